//! DXF input: drawings written ezdxf/LibreCAD-style by the `dxf` crate (R12 and R2000, layers
//! named MOUNTAIN/VALLEY/…, or colours), ORIPA's DXF layout, units, curves, block inserts, and
//! foldcam's own machine DXF read back.

use crate::bin;
use crate::post_common;

use std::collections::HashMap;
use std::f64::consts::PI;
use std::path::PathBuf;

use dxf::entities::{Arc, Circle, Entity, EntityType, Insert, Line, LwPolyline, Polyline, Vertex};
use dxf::enums::{AcadVersion, Units as DxfUnits};
use dxf::tables::Layer;
use dxf::{Block, Color, Drawing, Point};
use foldcam::formats;
use foldcam::pattern::{Assignment, CreasePattern, Units};
use glam::DVec2;

fn n(cp: &CreasePattern, a: Assignment) -> usize {
    cp.edges.iter().filter(|e| e.assignment == a).count()
}

fn entity(layer: &str, colour: Option<u8>, specific: EntityType) -> Entity {
    let mut e = Entity::new(specific);
    e.common.layer = layer.to_string();
    if let Some(c) = colour {
        e.common.color = Color::from_index(c);
    }
    e
}

fn line(layer: &str, colour: Option<u8>, a: (f64, f64), b: (f64, f64)) -> Entity {
    entity(
        layer,
        colour,
        EntityType::Line(Line::new(
            Point::new(a.0, a.1, 0.0),
            Point::new(b.0, b.1, 0.0),
        )),
    )
}

fn text(drawing: &Drawing) -> String {
    let mut out = Vec::new();
    drawing.save(&mut out).unwrap_or_else(|e| panic!("{e}"));
    String::from_utf8(out).unwrap_or_else(|e| panic!("{e}"))
}

fn read(drawing: &Drawing) -> formats::Imported {
    formats::dxf::read_str(&text(drawing)).unwrap_or_else(|e| panic!("{e}"))
}

/// The 100 mm test sheet: a square outline, a mountain diagonal, a valley diagonal and a
/// horizontal valley through the centre, with the layer names or colours each style gives.
/// Counted by hand: the three creases cross at the centre (2 + 2 + 2 pieces) and the
/// horizontal splits the left and right sides (4 + 2 outline pieces).
fn sheet(drawing: &mut Drawing, by_layer: bool, outline: Entity) {
    let (m, v) = if by_layer {
        (("MOUNTAIN", None), ("VALLEY", None))
    } else {
        (("0", Some(1)), ("0", Some(5)))
    };
    drawing.add_entity(outline);
    drawing.add_entity(line(m.0, m.1, (0.0, 0.0), (100.0, 100.0)));
    drawing.add_entity(line(v.0, v.1, (0.0, 100.0), (100.0, 0.0)));
    drawing.add_entity(line(v.0, v.1, (0.0, 50.0), (100.0, 50.0)));
}

fn square_lwpolyline(layer: &str, colour: Option<u8>) -> Entity {
    let mut p = LwPolyline::default();
    for (x, y) in [(0.0, 0.0), (100.0, 0.0), (100.0, 100.0), (0.0, 100.0)] {
        p.vertices.push(dxf::LwPolylineVertex {
            x,
            y,
            ..Default::default()
        });
    }
    p.set_is_closed(true);
    entity(layer, colour, EntityType::LwPolyline(p))
}

fn square_polyline(layer: &str, colour: Option<u8>) -> Entity {
    let mut p = Polyline::default();
    for (x, y) in [(0.0, 0.0), (100.0, 0.0), (100.0, 100.0), (0.0, 100.0)] {
        p.add_vertex(&mut Drawing::new(), Vertex::new(Point::new(x, y, 0.0)));
    }
    p.set_is_closed(true);
    entity(layer, colour, EntityType::Polyline(p))
}

#[test]
fn r2000_layers_named_mountain_and_valley() {
    let mut d = Drawing::new();
    d.header.version = AcadVersion::R2000;
    d.header.default_drawing_units = DxfUnits::Millimeters;
    sheet(&mut d, true, square_lwpolyline("BOUNDARY", None));
    let imported = read(&d);
    let cp = &imported.pattern;
    assert_eq!(cp.units, Units::Millimetres);
    assert_eq!(n(cp, Assignment::Mountain), 2);
    assert_eq!(n(cp, Assignment::Valley), 4);
    assert_eq!(n(cp, Assignment::Boundary), 6);
    assert_eq!(cp.edges.len(), 12);
    assert!(
        imported.warnings().next().is_none(),
        "{:?}",
        imported.findings
    );
}

#[test]
fn r12_colours_and_inch_units() {
    let mut d = Drawing::new();
    d.header.version = AcadVersion::R12;
    sheet(&mut d, false, square_polyline("0", Some(7)));
    let cp = read(&d).pattern;
    // R12 has no $INSUNITS: the drawing is unitless, with its numbers kept.
    assert_eq!(cp.units, Units::Unitless);
    assert_eq!(
        (n(&cp, Assignment::Mountain), n(&cp, Assignment::Valley)),
        (2, 4)
    );
    assert_eq!(n(&cp, Assignment::Boundary), 6);
    // The same drawing in R2000 with inches comes back 25.4 times larger, in millimetres.
    let mut d = Drawing::new();
    d.header.version = AcadVersion::R2000;
    d.header.default_drawing_units = DxfUnits::Inches;
    sheet(&mut d, false, square_lwpolyline("0", Some(7)));
    let cp = read(&d).pattern;
    assert_eq!(cp.units, Units::Millimetres);
    let (lo, hi) = cp.bounds().unwrap_or_default();
    assert!((hi - lo - DVec2::splat(2540.0)).abs().max_element() < 1e-9);
}

#[test]
fn bylayer_colours_true_colours_and_layer_names_take_precedence() {
    let mut d = Drawing::new();
    d.header.version = AcadVersion::R2018;
    d.header.default_drawing_units = DxfUnits::Millimeters;
    d.add_layer(Layer {
        name: "RED INK".into(),
        color: Color::from_index(1),
        ..Default::default()
    });
    d.add_entity(square_lwpolyline("OUTLINE", Some(1)));
    // BYLAYER on a red layer: mountain.
    d.add_entity(line("RED INK", None, (0.0, 0.0), (100.0, 100.0)));
    // True colour blue on an unnamed layer: valley.
    let mut blue = line("0", Some(3), (0.0, 100.0), (100.0, 0.0));
    blue.common.color_24_bit = 0x0000ff;
    d.add_entity(blue);
    let imported = read(&d);
    let cp = &imported.pattern;
    // OUTLINE is a boundary by name although drawn red.
    assert_eq!(n(cp, Assignment::Boundary), 4);
    assert_eq!(n(cp, Assignment::Mountain), 2);
    assert_eq!(n(cp, Assignment::Valley), 2);
    assert!(
        imported.found(formats::FindingKind::DxfLayersByColour),
        "{:?}",
        imported.findings
    );
}

#[test]
fn arcs_circles_bulges_and_inserted_blocks() {
    let mut d = Drawing::new();
    d.header.version = AcadVersion::R2000;
    d.header.default_drawing_units = DxfUnits::Millimeters;
    sheet(&mut d, true, square_lwpolyline("BOUNDARY", None));
    // A block holding one 10 mm line on layer 0, inserted on MOUNTAIN at (25, 0), turned
    // 90° and scaled 2: a mountain from (25, 0) to (25, 20).
    let mut block = Block {
        name: "FLAP".into(),
        ..Default::default()
    };
    block
        .entities
        .push(line("0", None, (0.0, 0.0), (10.0, 0.0)));
    d.add_block(block);
    let mut insert = Insert {
        name: "FLAP".into(),
        location: Point::new(25.0, 0.0, 0.0),
        x_scale_factor: 2.0,
        y_scale_factor: 2.0,
        rotation: 90.0,
        ..Default::default()
    };
    insert.column_count = 1;
    insert.row_count = 1;
    d.add_entity(entity("MOUNTAIN", None, EntityType::Insert(insert)));
    // A cut circle of radius 5 at (75, 35), clear of every crease.
    d.add_entity(entity(
        "CUT",
        None,
        EntityType::Circle(Circle::new(Point::new(75.0, 35.0, 0.0), 5.0)),
    ));
    // A flat quarter arc of radius 10 round (20, 60), from 0° to 90°.
    d.add_entity(entity(
        "FLAT",
        None,
        EntityType::Arc(Arc::new(Point::new(20.0, 60.0, 0.0), 10.0, 0.0, 90.0)),
    ));
    let cp = read(&d).pattern;
    let has = |p: DVec2| cp.vertices.iter().any(|q| q.distance(p) < 1e-9);
    assert!(has(DVec2::new(25.0, 20.0)) && has(DVec2::new(25.0, 0.0)));
    let ms: Vec<_> = cp
        .edge_ids()
        .filter(|&e| cp.edges[e.index()].assignment == Assignment::Mountain)
        .map(|e| cp.segment(e))
        .collect();
    assert_eq!(n(&cp, Assignment::Mountain), 3, "{ms:?}");
    // The insert splits the bottom side once more.
    assert_eq!(n(&cp, Assignment::Boundary), 7);
    // Chords within 0.01 mm: the sagitta r (1 − cos(θ/2)) ≤ tol gives the count.
    let chords = |r: f64, sweep: f64| (sweep / (2.0 * (1.0 - 0.01 / r).acos())).ceil() as usize;
    assert_eq!(n(&cp, Assignment::Cut), chords(5.0, 2.0 * PI));
    assert_eq!(n(&cp, Assignment::Flat), chords(10.0, PI / 2.0));
    for v in cp
        .vertices
        .iter()
        .filter(|p| p.distance(DVec2::new(75.0, 35.0)) < 6.0)
    {
        assert!((v.distance(DVec2::new(75.0, 35.0)) - 5.0).abs() < 1e-9);
    }
}

#[test]
fn oripa_style_file_reads_by_its_layer_names() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/oripa-style.dxf");
    let imported = formats::load(&path).unwrap_or_else(|e| panic!("{e}"));
    let cp = &imported.pattern;
    assert_eq!(cp.units, Units::Unitless);
    // Outline split at the four side middles; diagonals and book folds split at the centre.
    let counts: HashMap<Assignment, usize> = Assignment::ALL
        .iter()
        .map(|&a| (a, n(cp, a)))
        .filter(|(_, c)| *c > 0)
        .collect();
    assert_eq!(
        counts,
        HashMap::from([
            (Assignment::Boundary, 8),
            (Assignment::Valley, 4),
            (Assignment::Mountain, 4)
        ])
    );
}

#[test]
fn bad_input_names_the_file_and_entity() {
    let mut d = Drawing::new();
    d.header.version = AcadVersion::R2000;
    d.add_entity(entity(
        "CUT",
        None,
        EntityType::Circle(Circle::new(Point::new(0.0, 0.0, 0.0), -1.0)),
    ));
    let err = formats::dxf::read_str(&text(&d))
        .err()
        .map(|e| e.to_string());
    let err = err.unwrap_or_default();
    assert!(
        err.contains("CIRCLE") && err.contains("CUT") && err.contains("radius"),
        "{err}"
    );
    let err = formats::dxf::read_str("0\nSECTION\n2\nENTITIES\n0\nENDSEC\n0\nEOF\n")
        .err()
        .map(|e| e.to_string())
        .unwrap_or_default();
    assert!(err.contains("draws no lines"), "{err}");
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let path = dir.path().join("garbage.dxf");
    std::fs::write(&path, "this is not a drawing\n").unwrap_or_else(|e| panic!("{e}"));
    let err = formats::load(&path)
        .err()
        .map(|e| e.to_string())
        .unwrap_or_default();
    assert!(err.contains("garbage.dxf"), "{err}");
}

/// foldcam's own DXF writer (src/post/dxf): the fixture job has a mark, a two-segment score,
/// three perforation dashes and a square cut; read back they are 1 flat, 5 unassigned folds
/// and 4 cut edges, in millimetres (R2000 writes $INSUNITS 4).
#[test]
fn our_machine_dxf_reads_back() {
    let plan = post_common::plan(post_common::job());
    for version in [
        foldcam::post::DxfVersion::R2000,
        foldcam::post::DxfVersion::R12,
    ] {
        let bytes =
            foldcam::post::dxf(&plan, &plan.jobs[0], version).unwrap_or_else(|e| panic!("{e}"));
        let text = String::from_utf8(bytes).unwrap_or_else(|e| panic!("{e}"));
        let cp = formats::dxf::read_str(&text)
            .unwrap_or_else(|e| panic!("{e}"))
            .pattern;
        assert_eq!(n(&cp, Assignment::Cut), 4, "{version:?}");
        assert_eq!(n(&cp, Assignment::Unassigned), 5, "{version:?}");
        assert_eq!(n(&cp, Assignment::Flat), 1, "{version:?}");
        let expected_units = match version {
            foldcam::post::DxfVersion::R2000 => Units::Millimetres,
            _ => Units::Unitless,
        };
        assert_eq!(cp.units, expected_units);
    }
}

/// The layer-named (R2000, LWPOLYLINE outline) and coloured (R12, POLYLINE outline) sheets
/// converted by the binary, as a user would: `foldcam convert sheet.dxf sheet.fold` writes
/// the counts drawn (2 mountain, 4 valley, 6 outline pieces; see [`sheet`]), read back from
/// the FOLD file, and `foldcam check` passes both.
#[test]
fn layer_named_and_coloured_files_convert_with_their_counts() {
    let dir = tempfile::tempdir().unwrap();
    for (by_layer, version) in [(true, AcadVersion::R2000), (false, AcadVersion::R12)] {
        let mut d = Drawing::new();
        d.header.version = version;
        let outline = if by_layer {
            square_lwpolyline("BOUNDARY", None)
        } else {
            square_polyline("0", Some(7))
        };
        sheet(&mut d, by_layer, outline);
        let name = if by_layer { "layers" } else { "colours" };
        let (dxf, fold) = (format!("{name}.dxf"), format!("{name}.fold"));
        std::fs::write(dir.path().join(&dxf), text(&d)).unwrap();
        let o = bin::foldcam(&["convert", &dxf, &fold], dir.path());
        assert!(
            o.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        let cp = formats::load(&dir.path().join(&fold)).unwrap().pattern;
        let counts = (
            n(&cp, Assignment::Mountain),
            n(&cp, Assignment::Valley),
            n(&cp, Assignment::Boundary),
            cp.edges.len(),
        );
        assert_eq!(counts, (2, 4, 6, 12), "{name}");
        let o = bin::foldcam(&["check", &dxf], dir.path());
        assert_eq!(
            o.status.code(),
            Some(0),
            "{name}: {}",
            String::from_utf8_lossy(&o.stdout)
        );
    }
}
