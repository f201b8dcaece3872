//! The Origami Simulator SVG reader and writer: real files, colours, opacities, transforms,
//! shapes, errors, and a property-based write → read round trip.

use std::path::PathBuf;

use foldcam::formats::{FindingKind, svg};
use foldcam::pattern::{Assignment, CreasePattern, Units};
use glam::DVec2;
use proptest::prelude::*;

#[path = "svg_format/grid.rs"]
mod grid;

use grid::{build, grid_spec};

/// Millimetres per CSS pixel.
const MM_PER_PX: f64 = 25.4 / 96.0;

/// Origami Simulator's SVGs (MIT), copied into `tests/data/svg`.
fn testdata() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/svg")
}

fn read_file(name: &str) -> foldcam::formats::Imported {
    let path = testdata().join(name);
    let text = std::fs::read_to_string(&path).expect("test file is readable");
    svg::read_str(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// An SVG document 100 mm square with one user unit per millimetre.
fn doc(body: &str) -> String {
    format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100mm\" height=\"100mm\" \
         viewBox=\"0 0 100 100\">{body}</svg>"
    )
}

fn read(body: &str) -> foldcam::formats::Imported {
    svg::read_str(&doc(body)).unwrap_or_else(|e| panic!("{e}\n{body}"))
}

fn count(cp: &CreasePattern, a: Assignment) -> usize {
    cp.edges.iter().filter(|e| e.assignment == a).count()
}

fn angles(cp: &CreasePattern, a: Assignment) -> Vec<Option<f64>> {
    cp.edges
        .iter()
        .filter(|e| e.assignment == a)
        .map(|e| e.fold_angle)
        .collect()
}

fn close(p: DVec2, q: DVec2, tol: f64) -> bool {
    p.distance(q) <= tol
}

fn has_edge(cp: &CreasePattern, a: DVec2, b: DVec2, tol: f64) -> bool {
    cp.edge_ids().any(|e| {
        let (p, q) = cp.segment(e);
        (close(p, a, tol) && close(q, b, tol)) || (close(p, b, tol) && close(q, a, tol))
    })
}

#[test]
fn every_origami_simulator_file_imports() {
    let dir = testdata();
    let mut paths: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("testdata is listable")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "svg"))
        .collect();
    paths.sort();
    assert!(paths.len() >= 10, "expected the Origami Simulator set");
    for path in paths {
        let text = std::fs::read_to_string(&path).expect("readable");
        let imported = svg::read_str(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let cp = &imported.pattern;
        let name = path.display();
        cp.validate().unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(cp.units, Units::Millimetres, "{name}");
        assert!(count(cp, Assignment::Boundary) >= 3, "{name}: no outline");
        assert!(
            cp.edges.iter().any(|e| e.assignment.is_fold()),
            "{name}: no folds"
        );
        let (lo, hi) = cp.bounds().expect("has vertices");
        let size = lo.distance(hi);
        // Planarised: no edge shorter than the merge tolerance, no repeated vertex pair.
        let tol = svg::merge_tolerance(cp);
        assert!(cp.edge_ids().all(|e| cp.edge_length(e) > tol), "{name}");
        let mut pairs: Vec<_> = cp
            .edges
            .iter()
            .map(|e| {
                (
                    e.vertices[0].min(e.vertices[1]),
                    e.vertices[0].max(e.vertices[1]),
                )
            })
            .collect();
        pairs.sort();
        pairs.dedup();
        assert_eq!(pairs.len(), cp.edges.len(), "{name}: duplicate edges");
        assert!(size > 10.0 && size < 5000.0, "{name}: size {size} mm");
    }
}

#[test]
fn simple_vertex_has_the_hand_counted_edges() {
    // A square outline, a red line across and a red half line down to the centre, a blue half
    // line up from it: the outline splits where the four crease ends touch it.
    let imported = read_file("simpleVertex.svg");
    let cp = &imported.pattern;
    assert_eq!(count(cp, Assignment::Boundary), 8);
    assert_eq!(count(cp, Assignment::Mountain), 3);
    assert_eq!(count(cp, Assignment::Valley), 1);
    assert_eq!(cp.edges.len(), 12);
    assert_eq!(cp.vertices.len(), 9);
    let centre = DVec2::new(1519.471, -1335.882) * MM_PER_PX;
    let degree = cp
        .vertex_ids()
        .find(|&v| close(cp.position(v), centre, 1e-3))
        .map(|v| cp.vertex_edges()[v.index()].len());
    assert_eq!(degree, Some(4));
    assert_eq!(angles(cp, Assignment::Valley), vec![Some(180.0)]);
    assert!(
        angles(cp, Assignment::Mountain)
            .iter()
            .all(|a| *a == Some(-180.0))
    );
}

#[test]
fn waterbomb_base_reads_half_opacity_valleys() {
    // Red diagonals at full opacity, blue midlines at opacity 0.5, a 2016 px square outline.
    let imported = read_file("waterbombBase.svg");
    let cp = &imported.pattern;
    assert_eq!(count(cp, Assignment::Boundary), 8);
    assert_eq!(count(cp, Assignment::Mountain), 4);
    assert_eq!(count(cp, Assignment::Valley), 4);
    assert!(
        angles(cp, Assignment::Mountain)
            .iter()
            .all(|a| *a == Some(-180.0))
    );
    for a in angles(cp, Assignment::Valley) {
        assert!((a.unwrap_or(f64::NAN) - 90.0).abs() < 1e-4, "{a:?}");
    }
    let (lo, hi) = cp.bounds().expect("has vertices");
    let side = 2016.0 * MM_PER_PX;
    assert!(close(hi - lo, DVec2::splat(side), 1e-3));
    // y flipped: the file's top-left corner (432, 288) px is the pattern's top-left.
    assert!(close(
        DVec2::new(lo.x, hi.y),
        DVec2::new(432.0, -288.0) * MM_PER_PX,
        1e-3
    ));
    assert!(
        imported.warnings().next().is_none(),
        "{:?}",
        imported.findings
    );
}

#[test]
fn palette_colours_in_any_notation_are_exact() {
    let imported = read(
        "<line x1='0' y1='0' x2='10' y2='0' stroke='#f00'/>\
         <line x1='0' y1='10' x2='10' y2='10' stroke='rgb(0,0,255)'/>\
         <line x1='0' y1='20' x2='10' y2='20' stroke='black'/>\
         <line x1='0' y1='30' x2='10' y2='30' style='stroke: lime'/>\
         <line x1='0' y1='40' x2='10' y2='40' stroke='#FFFF00'/>\
         <line x1='0' y1='50' x2='10' y2='50' stroke='magenta'/>",
    );
    let cp = &imported.pattern;
    for a in [
        Assignment::Mountain,
        Assignment::Valley,
        Assignment::Boundary,
        Assignment::Cut,
        Assignment::Flat,
        Assignment::Unassigned,
    ] {
        assert_eq!(count(cp, a), 1, "{a:?}");
    }
    assert!(
        imported.warnings().next().is_none(),
        "{:?}",
        imported.findings
    );
}

#[test]
fn off_palette_colours_map_to_the_nearest_with_one_warning_each() {
    let imported = read(
        "<line id='a' x1='0' y1='0' x2='10' y2='0' stroke='#e01010'/>\
         <line id='b' x1='0' y1='10' x2='10' y2='10' stroke='#e01010'/>\
         <line x1='0' y1='20' x2='10' y2='20' stroke='#800080'/>\
         <line x1='0' y1='30' x2='10' y2='30' stroke='#202020'/>",
    );
    let cp = &imported.pattern;
    assert_eq!(count(cp, Assignment::Mountain), 2);
    assert_eq!(count(cp, Assignment::Unassigned), 1);
    assert_eq!(count(cp, Assignment::Boundary), 1);
    let w: Vec<&str> = imported.warnings().map(|f| f.text.as_str()).collect();
    assert!(
        imported
            .warnings()
            .all(|f| f.kind == FindingKind::OffPaletteColour),
        "{w:?}"
    );
    assert_eq!(w.len(), 3, "{w:?}");
    let red = w
        .iter()
        .find(|m| m.contains("#e01010"))
        .expect("warns #e01010");
    assert!(red.contains("2 element") && red.contains("\"a\"") && red.contains("\"b\""));
    assert!(red.contains("mountain") && red.contains("#ff0000"), "{red}");
    let purple = w
        .iter()
        .find(|m| m.contains("#800080"))
        .expect("warns #800080");
    assert!(
        purple.contains("unassigned") && purple.contains("no id"),
        "{purple}"
    );
}

#[test]
fn many_off_palette_colours_share_one_warning_beyond_a_dozen() {
    let body: String = (0..20)
        .map(|i| {
            format!(
                "<line x1='0' y1='{i}' x2='10' y2='{i}' stroke='rgb({},0,0)'/>",
                200 + i
            )
        })
        .collect();
    let imported = read(&body);
    assert_eq!(imported.pattern.edges.len(), 20);
    let w: Vec<&str> = imported.warnings().map(|f| f.text.as_str()).collect();
    assert_eq!(w.len(), 13, "{w:?}");
    assert!(
        w[12].contains("8 more off-palette stroke colours on 8 element"),
        "{w:?}"
    );
}

#[test]
fn opacity_sets_the_fold_angle() {
    let imported = read(
        "<line x1='0' y1='0' x2='10' y2='0' stroke='blue' stroke-opacity='0.25'/>\
         <g opacity='0.5'><line x1='0' y1='10' x2='10' y2='10' stroke='red' \
            stroke-opacity='0.5'/></g>\
         <line x1='0' y1='20' x2='10' y2='20' stroke='red' opacity='0.5'/>\
         <line x1='0' y1='30' x2='10' y2='30' stroke='blue' style='stroke-opacity:0.75'/>\
         <line x1='0' y1='40' x2='10' y2='40' stroke='rgba(0,0,255,0.5)'/>\
         <line x1='0' y1='50' x2='10' y2='50' stroke='yellow' opacity='0.3'/>\
         <line x1='0' y1='60' x2='10' y2='60' stroke='black' opacity='0.3'/>\
         <line x1='0' y1='70' x2='10' y2='70' stroke='magenta' opacity='0.3'/>",
    );
    let cp = &imported.pattern;
    let angle_at = |y: f64| {
        cp.edges
            .iter()
            .find(|e| (cp.position(e.vertices[0]).y + y).abs() < 1e-3)
            .and_then(|e| e.fold_angle)
    };
    let expect = [
        (0.0, 45.0),
        (10.0, -45.0),
        (20.0, -90.0),
        (30.0, 135.0),
        (40.0, 90.0),
        (50.0, 0.0),
    ];
    for (y, want) in expect {
        let got = angle_at(y).unwrap_or(f64::NAN);
        assert!((got - want).abs() < 0.5, "line at y={y}: {got} vs {want}");
    }
    // rgba alpha is 8-bit: 0.5 becomes 128/255; the others are exact to f32.
    for (y, want) in expect.iter().filter(|(y, _)| *y != 40.0) {
        let got = angle_at(*y).unwrap_or(f64::NAN);
        assert!((got - want).abs() < 1e-4, "line at y={y}: {got} vs {want}");
    }
    assert_eq!(angle_at(60.0), None);
    assert_eq!(angle_at(70.0), None);
}

#[test]
fn transforms_are_applied() {
    let imported = read(
        "<g transform='translate(10,20)'><g transform='rotate(90) scale(2)'>\
           <line x1='0' y1='0' x2='5' y2='0' stroke='red'/></g></g>\
         <line x1='0' y1='0' x2='1' y2='0' stroke='blue' transform='matrix(0 1 -1 0 50 50)'/>",
    );
    let cp = &imported.pattern;
    // (5, 0) → scale 2 → (10, 0) → rotate 90° → (0, 10) → translate → (10, 30); y flipped.
    assert!(has_edge(
        cp,
        DVec2::new(10.0, -20.0),
        DVec2::new(10.0, -30.0),
        1e-4
    ));
    // matrix maps (1, 0) to (50, 51).
    assert!(has_edge(
        cp,
        DVec2::new(50.0, -50.0),
        DVec2::new(50.0, -51.0),
        1e-4
    ));
}

#[test]
fn units_and_view_box_offsets_are_honoured() {
    let inches = "<svg xmlns='http://www.w3.org/2000/svg' width='4in' height='4in' \
                  viewBox='0 0 4 4'><line x1='1' y1='1' x2='3' y2='1' stroke='red'/></svg>";
    let cp = svg::read_str(inches).expect("reads").pattern;
    assert!(has_edge(
        &cp,
        DVec2::new(25.4, -25.4),
        DVec2::new(76.2, -25.4),
        1e-4
    ));
    // The user-space origin stays the pattern origin whatever the viewBox offset.
    let offset = "<svg xmlns='http://www.w3.org/2000/svg' width='100mm' height='100mm' \
                  viewBox='-50 -50 100 100'><line x1='-10' y1='5' x2='10' y2='5' \
                  stroke='blue'/></svg>";
    let cp = svg::read_str(offset).expect("reads").pattern;
    assert!(has_edge(
        &cp,
        DVec2::new(-10.0, -5.0),
        DVec2::new(10.0, -5.0),
        1e-4
    ));
    // No size at all: user units are CSS pixels.
    let bare = "<svg xmlns='http://www.w3.org/2000/svg'>\
                <line x1='0' y1='0' x2='96' y2='0' stroke='red'/></svg>";
    let cp = svg::read_str(bare).expect("reads").pattern;
    assert!(has_edge(&cp, DVec2::ZERO, DVec2::new(25.4, 0.0), 1e-4));
}

#[test]
fn rects_polygons_and_polylines_become_edges() {
    let rect = read("<rect x='10' y='10' width='20' height='30' stroke='black' fill='white'/>");
    let cp = &rect.pattern;
    assert_eq!(count(cp, Assignment::Boundary), 4);
    assert!(has_edge(
        cp,
        DVec2::new(10.0, -10.0),
        DVec2::new(30.0, -10.0),
        1e-4
    ));
    assert!(has_edge(
        cp,
        DVec2::new(30.0, -40.0),
        DVec2::new(10.0, -40.0),
        1e-4
    ));

    let polygon = read("<polygon points='0,0 10,0 0,10' stroke='blue' fill='none'/>");
    assert_eq!(count(&polygon.pattern, Assignment::Valley), 3);
    assert!(has_edge(
        &polygon.pattern,
        DVec2::new(0.0, -10.0),
        DVec2::ZERO,
        1e-4
    ));

    let polyline = read("<polyline points='0,0 10,0 10,10' stroke='red' fill='none'/>");
    assert_eq!(count(&polyline.pattern, Assignment::Mountain), 2);
    assert_eq!(polyline.pattern.vertices.len(), 3);

    let path = read("<path d='M0 0 L10 0 l0 10 H0 Z M50 50 h10' stroke='green' fill='none'/>");
    assert_eq!(count(&path.pattern, Assignment::Cut), 5);
}

#[test]
fn curves_are_flattened_with_a_warning() {
    let imported = read("<circle cx='50' cy='50' r='20' stroke='black' fill='none'/>");
    let cp = &imported.pattern;
    assert!(cp.edges.len() >= 16, "{} chords", cp.edges.len());
    for p in &cp.vertices {
        let r = p.distance(DVec2::new(50.0, -50.0));
        assert!((r - 20.0).abs() < 0.02, "radius {r}");
    }
    // Chord midpoints stay within the flattening tolerance of the circle.
    for e in cp.edge_ids() {
        let (a, b) = cp.segment(e);
        let r = ((a + b) / 2.0).distance(DVec2::new(50.0, -50.0));
        assert!(
            20.0 - r <= svg::CURVE_TOLERANCE_MM + 1e-3,
            "sagitta {}",
            20.0 - r
        );
    }
    assert!(
        imported.found(FindingKind::CurvesFlattened),
        "{:?}",
        imported.findings
    );
}

#[test]
fn unstroked_elements_and_text_are_ignored_with_a_warning() {
    let imported = read(
        "<rect x='0' y='0' width='10' height='10' fill='red'/>\
         <text x='5' y='5' stroke='red'>label</text>\
         <line x1='0' y1='0' x2='10' y2='0' stroke='red'/>",
    );
    assert_eq!(imported.pattern.edges.len(), 1);
    let w: Vec<_> = imported.warnings().collect();
    let of = |kind| w.iter().find(|f| f.kind == kind).map(|f| f.text.as_str());
    assert!(
        of(FindingKind::Unstroked).is_some_and(|t| t.contains("1 element(s) without a stroke")),
        "{w:?}"
    );
    assert!(
        of(FindingKind::Text).is_some_and(|t| t.contains("1 text element(s)")),
        "{w:?}"
    );
}

#[test]
fn errors_name_the_problem() {
    let not_xml = svg::read_str("<svg xmlns='http://www.w3.org/2000/svg'>\n<line </svg>")
        .expect_err("not XML");
    assert!(not_xml.place.starts_with("line 2"), "{not_xml}");
    assert!(not_xml.message.contains("XML"), "{not_xml}");

    let html = svg::read_str("<html><body/></html>").expect_err("not SVG");
    assert!(html.message.contains("not <svg>"), "{html}");

    let empty = svg::read_str("  \n").expect_err("empty");
    assert!(empty.message.contains("empty"), "{empty}");

    let no_creases = svg::read_str(&doc("<rect width='10' height='10' fill='blue'/>"))
        .expect_err("nothing stroked");
    assert!(
        no_creases.message.contains("no stroked lines"),
        "{no_creases}"
    );

    let no_size = svg::read_str(
        "<svg xmlns='http://www.w3.org/2000/svg' width='0' height='10'>\
         <line x1='0' y1='0' x2='1' y2='1' stroke='red'/></svg>",
    )
    .expect_err("zero width");
    assert!(no_size.message.contains("size"), "{no_size}");

    let mut deep = String::new();
    (0..2000).for_each(|_| deep.push_str("<g>"));
    deep.push_str("<line x1='0' y1='0' x2='5' y2='5' stroke='red'/>");
    (0..2000).for_each(|_| deep.push_str("</g>"));
    let too_deep = svg::read_str(&doc(&deep)).expect_err("nested too deeply");
    assert!(too_deep.message.contains("nested"), "{too_deep}");

    let huge = svg::read_str(&doc(
        "<line x1='0' y1='0' x2='1e30' y2='0' stroke='red' id='far'/>",
    ))
    .expect_err("beyond the coordinate limit");
    assert!(
        huge.place.contains("line 1") && huge.place.contains("<line>"),
        "{huge}"
    );
    assert!(huge.message.contains("1e30"), "{huge}");
}

fn sample_pattern(units: Units) -> CreasePattern {
    let mut cp = CreasePattern {
        units,
        ..CreasePattern::default()
    };
    let p = [
        DVec2::new(-10.0, -5.0),
        DVec2::new(30.0, -5.0),
        DVec2::new(30.0, 15.0),
        DVec2::new(-10.0, 15.0),
    ];
    let v: Vec<_> = p.iter().map(|&q| cp.add_vertex(q)).collect();
    for i in 0..4 {
        cp.add_edge(v[i], v[(i + 1) % 4], Assignment::Boundary);
    }
    let m = cp.add_edge(v[0], v[2], Assignment::Mountain);
    cp.edges[m.index()].fold_angle = Some(-90.0);
    cp.meta.title = Some("Fish & <chips> \"quoted\"".to_string());
    cp
}

#[test]
fn written_svg_uses_the_palette_and_millimetres() {
    let text = svg::write_string(&sample_pattern(Units::Millimetres));
    let xml = usvg::roxmltree::Document::parse(&text).expect("the writer writes XML");
    let root = xml.root_element();
    assert_eq!(root.attribute("width"), Some("40mm"));
    assert_eq!(root.attribute("height"), Some("20mm"));
    assert_eq!(root.attribute("viewBox"), Some("-10 -15 40 20"));
    let lines: Vec<_> = xml
        .descendants()
        .filter(|n| n.has_tag_name("line"))
        .collect();
    assert_eq!(lines.len(), 5);
    let strokes: Vec<_> = lines.iter().filter_map(|n| n.attribute("stroke")).collect();
    assert_eq!(strokes.iter().filter(|s| **s == "#000000").count(), 4);
    assert_eq!(strokes.iter().filter(|s| **s == "#ff0000").count(), 1);
    let mountain = lines
        .iter()
        .find(|n| n.attribute("stroke") == Some("#ff0000"))
        .expect("one mountain");
    assert_eq!(mountain.attribute("stroke-opacity"), Some("0.5"));
    // Origami Simulator reads only the root's children: no groups, lines sorted by kind.
    assert!(lines.iter().all(|n| n.parent() == Some(root)));
    let classes: Vec<_> = lines.iter().filter_map(|n| n.attribute("class")).collect();
    assert_eq!(
        classes,
        vec!["boundary", "boundary", "boundary", "boundary", "mountain"]
    );
    let title = xml.descendants().find(|n| n.has_tag_name("title"));
    assert_eq!(
        title.and_then(|t| t.text()),
        Some("Fish & <chips> \"quoted\"")
    );

    let unitless = svg::write_string(&sample_pattern(Units::Unitless));
    let xml = usvg::roxmltree::Document::parse(&unitless).expect("XML");
    assert_eq!(xml.root_element().attribute("width"), Some("40"));
}

#[test]
fn title_and_geometry_survive_a_round_trip() {
    let original = sample_pattern(Units::Millimetres);
    let back = svg::read_str(&svg::write_string(&original))
        .expect("reads its own output")
        .pattern;
    assert_eq!(back.meta.title, original.meta.title);
    assert_eq!(back.units, Units::Millimetres);
    assert_eq!(back.edges.len(), 5);
    assert!(has_edge(
        &back,
        DVec2::new(-10.0, -5.0),
        DVec2::new(30.0, 15.0),
        1e-5
    ));
    let m = back
        .edges
        .iter()
        .find(|e| e.assignment == Assignment::Mountain);
    let angle = m.and_then(|e| e.fold_angle).unwrap_or(f64::NAN);
    assert!((angle + 90.0).abs() < 2e-5, "{angle}");
}

/// The fold angle the SVG convention gives back for an edge.
fn expected_angle(assignment: Assignment, angle: Option<f64>) -> Option<f64> {
    match assignment {
        Assignment::Mountain | Assignment::Valley => {
            Some(angle.unwrap_or(assignment.flat_folded_angle().unwrap_or(0.0)))
        }
        Assignment::Flat => Some(0.0),
        _ => None,
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    #[test]
    fn write_then_read_gives_the_same_pattern(spec in grid_spec()) {
        let original = build(&spec);
        let text = svg::write_string(&original);
        let back = svg::read_str(&text).map_err(|e| TestCaseError::fail(e.to_string()))?.pattern;
        let (lo, hi) = original.bounds().expect("vertices");
        let magnitude = lo.abs().max(hi.abs()).max_element().max(lo.distance(hi));
        // usvg holds coordinates in f32: about 6e-8 of their magnitude.
        let tol = 1e-6 * magnitude;
        prop_assert_eq!(back.vertices.len(), original.vertices.len());
        prop_assert_eq!(back.edges.len(), original.edges.len());
        for e in &original.edges {
            let [a, b] = e.vertices.map(|v| original.position(v));
            let found = back.edges.iter().find(|f| {
                let [p, q] = f.vertices.map(|v| back.position(v));
                (close(p, a, tol) && close(q, b, tol)) || (close(p, b, tol) && close(q, a, tol))
            });
            let Some(f) = found else {
                return Err(TestCaseError::fail(format!("edge {a}–{b} lost")));
            };
            prop_assert_eq!(f.assignment, e.assignment);
            let want = expected_angle(e.assignment, e.fold_angle);
            match (want, f.fold_angle) {
                (None, None) => {}
                // usvg holds opacities in f32: 180 × 6e-8 degrees.
                (Some(w), Some(g)) => prop_assert!((w - g).abs() < 2e-5, "{} vs {}", w, g),
                (w, g) => return Err(TestCaseError::fail(format!("angle {w:?} vs {g:?}"))),
            }
        }
    }

    #[test]
    fn arbitrary_text_never_panics(text in "[<>/a-z =\"'0-9.#-]{0,120}") {
        for source in [text.clone(), doc(&text)] {
            // Whatever is accepted is a valid pattern.
            if let Ok(imported) = svg::read_str(&source) {
                prop_assert!(imported.pattern.validate().is_ok());
            }
        }
    }
}
