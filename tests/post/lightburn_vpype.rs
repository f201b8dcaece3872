//! What other software makes of our files (issue 35): LightBurn burns the dashes foldcam
//! fitted, in both ways a `.lbrn2` project can carry them, and vpype keeps the layers of a
//! plotter SVG apart.
//!
//! The LightBurn tests rebuild LightBurn's dashes from the written project with their own
//! reader (roxmltree): a shape on a layer without perforation is burnt as drawn; on a layer
//! with LightBurn's perforation mode, cut (`perfLen`) and skip (`perfSkip`) alternate from the
//! path's start to its end, as LightBurn lays them. The rebuilt dashes are compared with the
//! dashes of the plan's perforation toolpaths. The vpype test runs `vpype read` (Python, `pip
//! install vpype`) and is ignored without it; `.ci/run` installs it and runs ignored tests.

use crate::post_common;

use std::path::Path;

use foldcam::fab::{FabPlan, Operation, PlanOptions, PlanOverrides, plan};
use foldcam::machine::{MachineProfile, load_machine, load_material};
use foldcam::pattern::{CreasePattern, PlanarizeOptions, planarize};
use foldcam::post::{self, LbrnPerforation};
use glam::DVec2;

/// Largest distance allowed between a dash end LightBurn burns and foldcam's (issue 35).
const DASH_TOLERANCE_MM: f64 = 0.05;

fn load_sized(relative: &str, size_mm: f64) -> CreasePattern {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(relative);
    let mut cp = foldcam::formats::load(&path)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        .pattern;
    planarize(&mut cp, &PlanarizeOptions::default()).expect("planarises");
    let (lo, hi) = cp.bounds().expect("vertices");
    cp.scale_to_mm(size_mm / (hi - lo).max_element());
    cp
}

/// The bird base (straight creases) and Origami Simulator's `HexSpiralTess.svg` (curved
/// creases between junctions, as polylines).
fn designs() -> Vec<(&'static str, CreasePattern)> {
    vec![
        (
            "bird base",
            load_sized("examples/patterns/bird-base.cp", 150.0),
        ),
        (
            "HexSpiralTess",
            load_sized("tests/data/HexSpiralTess.svg", 120.0),
        ),
    ]
}

fn planned(cp: &CreasePattern, machine: &MachineProfile, material: &str) -> FabPlan {
    let material = load_material(material).expect("shipped");
    let o =
        PlanOptions::for_machine(machine, &material, &PlanOverrides::default()).expect("adapts");
    plan(cp, machine, &material, &o).expect("plans")
}

/// The dashes of the plan's perforation toolpaths (first job), in drawing coordinates (the
/// project's: mm, y up from the bed's front-left corner).
fn foldcam_dashes(p: &FabPlan, machine: &MachineProfile) -> Vec<Vec<DVec2>> {
    let to_drawing = machine.bed.to_machine().inverse();
    p.jobs[0]
        .paths
        .iter()
        .filter(|t| t.op == Operation::Perforate)
        .flat_map(|t| &t.strokes)
        .map(|s| s.iter().map(|&q| to_drawing.transform_point2(q)).collect())
        .collect()
}

/// A `CutSetting` as read back.
#[derive(Debug)]
struct Setting {
    name: String,
    /// `(perfLen, perfSkip)` when LightBurn's perforation mode is on.
    perforation: Option<(f64, f64)>,
}

/// A `Path` shape as read back: its layer index and its polyline.
type Shape = (usize, Vec<DVec2>);

/// The project's settings by index and its `Path` shapes as (index, polyline).
fn read_project(xml: &str) -> (Vec<(usize, Setting)>, Vec<Shape>) {
    let doc = roxmltree::Document::parse(xml).expect("well-formed XML");
    let root = doc.root_element();
    assert_eq!(root.tag_name().name(), "LightBurnProject");
    let value = |n: roxmltree::Node, key: &str| -> Option<String> {
        n.children()
            .find(|c| c.has_tag_name(key))
            .and_then(|c| c.attribute("Value"))
            .map(str::to_string)
    };
    let num = |n: roxmltree::Node, key: &str| -> f64 {
        value(n, key)
            .unwrap_or_else(|| panic!("{key} missing"))
            .parse()
            .expect("a number")
    };
    let settings = root
        .children()
        .filter(|c| c.has_tag_name("CutSetting"))
        .map(|cs| {
            let on = value(cs, "perforate").as_deref() == Some("1");
            let setting = Setting {
                name: value(cs, "name").expect("name"),
                perforation: on.then(|| (num(cs, "perfLen"), num(cs, "perfSkip"))),
            };
            (num(cs, "index") as usize, setting)
        })
        .collect();
    let shapes = root
        .children()
        .filter(|c| c.has_tag_name("Shape"))
        .map(|s| {
            assert_eq!(s.attribute("Type"), Some("Path"));
            let index: usize = s.attribute("CutIndex").expect("CutIndex").parse().unwrap();
            let text = |tag: &str| {
                s.children()
                    .find(|c| c.has_tag_name(tag))
                    .and_then(|c| c.text())
                    .unwrap_or_else(|| panic!("{tag} missing"))
                    .to_string()
            };
            assert_eq!(text("XForm"), "1 0 0 1 0 0");
            (index, polyline(&text("VertList"), &text("PrimList")))
        })
        .collect();
    (settings, shapes)
}

/// The polyline of a `VertList` (corners `Vx yc0x1c1x1`) and a `PrimList` of lines (`La b`
/// running on from one to the next) or `LineClosed`.
fn polyline(verts: &str, prims: &str) -> Vec<DVec2> {
    let points: Vec<DVec2> = verts
        .split('V')
        .filter(|v| !v.is_empty())
        .map(|v| {
            let xy = v
                .strip_suffix("c0x1c1x1")
                .expect("a corner without handles");
            let n: Vec<f64> = xy
                .split(' ')
                .map(|t| t.parse().expect("a number"))
                .collect();
            assert_eq!(n.len(), 2, "{v}");
            DVec2::new(n[0], n[1])
        })
        .collect();
    if prims == "LineClosed" {
        let mut closed = points.clone();
        closed.push(points[0]);
        return closed;
    }
    let mut out = Vec::new();
    for (k, prim) in prims.split('L').filter(|p| !p.is_empty()).enumerate() {
        let ab: Vec<usize> = prim.split(' ').map(|t| t.parse().unwrap()).collect();
        assert_eq!(ab, vec![k, k + 1], "lines run on in order");
        if k == 0 {
            out.push(points[ab[0]]);
        }
        out.push(points[ab[1]]);
    }
    assert_eq!(out.len(), points.len(), "every vertex on the path");
    out
}

/// The point at arc length `s` along `line` and the index of the segment it lies on.
fn at(line: &[DVec2], s: f64) -> (DVec2, usize) {
    let mut left = s;
    for (i, w) in line.windows(2).enumerate() {
        let len = w[0].distance(w[1]);
        if left <= len {
            return (w[0].lerp(w[1], if len > 0.0 { left / len } else { 0.0 }), i);
        }
        left -= len;
    }
    (line[line.len() - 1], line.len() - 2)
}

/// The part of `line` from arc length `a` to `b`.
fn sub_path(line: &[DVec2], a: f64, b: f64) -> Vec<DVec2> {
    let ((p, i), (q, j)) = (at(line, a), at(line, b));
    let mut out = vec![p];
    out.extend_from_slice(&line[i + 1..=j]);
    out.push(q);
    out.dedup();
    out
}

fn length(line: &[DVec2]) -> f64 {
    line.windows(2).map(|w| w[0].distance(w[1])).sum()
}

/// The dashes LightBurn burns on the project's perforation layers (named `perforate…`), in
/// file order: a shape on a layer without perforation mode is one dash; on a layer with it,
/// cut `perfLen` and skip `perfSkip` alternate from the path's start, the last cut stopping
/// at the path's end.
fn lightburn_dashes(xml: &str) -> Vec<Vec<DVec2>> {
    let (settings, shapes) = read_project(xml);
    let mut out = Vec::new();
    for (index, line) in shapes {
        let (_, setting) = settings
            .iter()
            .find(|(i, _)| *i == index)
            .unwrap_or_else(|| panic!("shape on layer {index} without a CutSetting"));
        if !setting.name.starts_with("perforate") {
            continue;
        }
        let Some((cut, skip)) = setting.perforation else {
            out.push(line);
            continue;
        };
        assert!(cut > 0.0 && skip > 0.0, "{setting:?}");
        let total = length(&line);
        let mut s = 0.0;
        while s < total {
            out.push(sub_path(&line, s, (s + cut).min(total)));
            s += cut + skip;
        }
    }
    out
}

/// How far LightBurn's dashes are from foldcam's: (foldcam's count, LightBurn's count, the
/// largest distance from a dash of either set to the closest dash of the other, as the larger
/// of the distances between their ends and the difference of their lengths, mm).
fn deviation(ours: &[Vec<DVec2>], theirs: &[Vec<DVec2>]) -> (usize, usize, f64) {
    let apart = |a: &[DVec2], b: &[DVec2]| {
        let (a0, a1, b0, b1) = (a[0], a[a.len() - 1], b[0], b[b.len() - 1]);
        let ends = a0
            .distance(b0)
            .max(a1.distance(b1))
            .min(a0.distance(b1).max(a1.distance(b0)));
        ends.max((length(a) - length(b)).abs())
    };
    let farthest = |from: &[Vec<DVec2>], to: &[Vec<DVec2>]| {
        from.iter()
            .map(|a| to.iter().map(|b| apart(a, b)).fold(f64::INFINITY, f64::min))
            .fold(0.0, f64::max)
    };
    let d = farthest(ours, theirs).max(farthest(theirs, ours));
    (ours.len(), theirs.len(), d)
}

/// Number of `CutSetting`s of a project with LightBurn's perforation mode on.
fn perforation_settings(xml: &str) -> usize {
    read_project(xml)
        .0
        .iter()
        .filter(|(_, s)| s.perforation.is_some())
        .count()
}

#[test]
fn lightburn_burns_foldcams_dashes_in_both_modes() {
    let machine = load_machine("lightburn").expect("shipped");
    for (name, cp) in designs() {
        let p = planned(&cp, &machine, "paper-160gsm");
        let ours = foldcam_dashes(&p, &machine);
        assert!(ours.len() > 50, "{name}: {} dashes", ours.len());
        for mode in [LbrnPerforation::Dashes, LbrnPerforation::LightBurn] {
            let xml = post::lbrn2(&p, &p.jobs[0], &machine, mode).expect("lbrn2");
            let (n_ours, n_theirs, d) = deviation(&ours, &lightburn_dashes(&xml));
            eprintln!(
                "{name} {mode:?}: {n_ours} dashes planned, {n_theirs} burnt, largest \
                 deviation {d:.4} mm, {} perforation CutSettings",
                perforation_settings(&xml)
            );
            assert_eq!(n_theirs, n_ours, "{name} {mode:?}: dash count");
            assert!(d <= DASH_TOLERANCE_MM, "{name} {mode:?}: {d} mm");
        }
    }
}

#[test]
fn lightburn_perforation_layers_carry_each_creases_own_dash_and_gap() {
    let machine = load_machine("lightburn").expect("shipped");
    let material = load_material("paper-160gsm").expect("shipped");
    let (asked, kerf) = (material.perforation, material.kerf_mm);
    for (name, cp) in designs() {
        let p = planned(&cp, &machine, "paper-160gsm");
        let xml = post::lbrn2(&p, &p.jobs[0], &machine, LbrnPerforation::LightBurn).unwrap();
        let (settings, shapes) = read_project(&xml);
        let pairs: Vec<(f64, f64)> = settings.iter().filter_map(|(_, s)| s.perforation).collect();
        // More than one pair (the creases are fitted one by one), each a distinct pair, each
        // within the layout's stretch of the material's toolpath dash and gap.
        assert!(pairs.len() > 1, "{name}: {pairs:?}");
        for (i, a) in pairs.iter().enumerate() {
            assert!(pairs[i + 1..].iter().all(|b| b != a), "{name}: {a:?} twice");
            let (dash, gap) = *a;
            assert!(
                (dash - (asked.cut_mm - kerf)).abs() < 0.35 * asked.cut_mm,
                "{dash}"
            );
            assert!(
                (gap - (asked.bridge_mm + kerf)).abs() < 0.35 * asked.bridge_mm,
                "{gap}"
            );
        }
        // Same speed and power on every perforation layer, and the layer indices are the
        // colour layers 0-29 in order.
        let indices: Vec<usize> = settings.iter().map(|(i, _)| *i).collect();
        assert_eq!(indices, (0..settings.len()).collect::<Vec<_>>());
        assert!(settings.len() <= 30);
        // One path per crease, each on a perforation layer, fewer than the dashes.
        let dashes = foldcam_dashes(&p, &machine).len();
        let on_perforation = shapes
            .iter()
            .filter(|(i, _)| settings[*i].1.perforation.is_some())
            .count();
        let creases = p.jobs[0]
            .paths
            .iter()
            .filter(|t| t.op == Operation::Perforate)
            .count();
        assert!(
            on_perforation >= creases && on_perforation < dashes,
            "{name}"
        );
    }
}

#[test]
fn lightburn_shapes_are_written_as_lightburn_saves_them() {
    let machine = load_machine("lightburn").expect("shipped");
    let p = planned(&designs().remove(0).1, &machine, "paper-160gsm");
    for mode in [LbrnPerforation::Dashes, LbrnPerforation::LightBurn] {
        let xml = post::lbrn2(&p, &p.jobs[0], &machine, mode).unwrap();
        let doc = roxmltree::Document::parse(&xml).unwrap();
        let shapes: Vec<_> = doc
            .root_element()
            .children()
            .filter(|c| c.has_tag_name("Shape"))
            .collect();
        // Every shape names its own vertex and primitive lists.
        let mut ids: Vec<&str> = shapes
            .iter()
            .map(|s| s.attribute("VertID").unwrap())
            .collect();
        let prim: Vec<&str> = shapes
            .iter()
            .map(|s| s.attribute("PrimID").unwrap())
            .collect();
        assert_eq!(ids, prim);
        ids.sort();
        ids.dedup();
        assert_eq!(ids.len(), shapes.len(), "{mode:?}: one id per shape");
        // The outline is cut as one closed path (LineClosed), the dashes open.
        let closed = shapes
            .iter()
            .filter(|s| {
                s.children()
                    .any(|c| c.has_tag_name("PrimList") && c.text() == Some("LineClosed"))
            })
            .count();
        assert!(closed >= 1, "{mode:?}");
        // Read back by the corner form (`read_project` refuses any other vertex form).
        read_project(&xml);
    }
}

#[test]
fn too_many_dash_patterns_for_lightburn_are_refused_with_a_way_out() {
    // 40 parallel valleys of 40 lengths: 40 dash/gap pairs, more than 30 colour layers.
    let mut cp = CreasePattern::new();
    for k in 0..40 {
        let y = 5.0 * k as f64;
        let len = 60.0 + 1.37 * k as f64;
        cp.add_segment(
            DVec2::new(0.0, y),
            DVec2::new(len, y),
            foldcam::pattern::Assignment::Valley,
        );
    }
    let machine = load_machine("lightburn").expect("shipped");
    let p = planned(&cp, &machine, "paper-160gsm");
    let err = post::lbrn2(&p, &p.jobs[0], &machine, LbrnPerforation::LightBurn)
        .expect_err("too many pairs");
    assert!(
        matches!(err, post::PostError::TooManyDashPatterns { limit: 30, .. }),
        "{err}"
    );
    assert!(err.to_string().contains("--lightburn-perforation"), "{err}");
    // The default (dash shapes) has no such limit.
    let xml = post::lbrn2(&p, &p.jobs[0], &machine, LbrnPerforation::Dashes).expect("dashes");
    let (n, m, d) = deviation(&foldcam_dashes(&p, &machine), &lightburn_dashes(&xml));
    assert!(n == m && d < 1e-3, "{n} {m} {d}");
}

/// The layer groups of an SVG at the root: (id, label, number of drawn elements).
fn svg_layers(svg: &str) -> Vec<(String, String, usize)> {
    const INKSCAPE: &str = "http://www.inkscape.org/namespaces/inkscape";
    let doc = roxmltree::Document::parse(svg).expect("well-formed SVG");
    doc.root_element()
        .children()
        .filter(|n| n.attribute((INKSCAPE, "groupmode")) == Some("layer"))
        .map(|g| {
            let drawn = g
                .children()
                .filter(|c| ["path", "line", "polyline", "polygon"].contains(&c.tag_name().name()))
                .count();
            (
                g.attribute("id").unwrap_or_default().to_string(),
                g.attribute((INKSCAPE, "label"))
                    .unwrap_or_default()
                    .to_string(),
                drawn,
            )
        })
        .collect()
}

/// The layers vpype makes of `svg`: `vpype read FILE write OUT` and OUT's layer groups (vpype
/// writes layer N as `id="layerN"` with the name it read as label, one element per line).
fn vpype_layers(svg: &str) -> Vec<(String, String, usize)> {
    let dir = tempfile::tempdir().expect("temporary folder");
    let (input, output) = (dir.path().join("job.svg"), dir.path().join("vpype.svg"));
    std::fs::write(&input, svg).expect("written");
    let run = std::process::Command::new("vpype")
        .arg("read")
        .arg(&input)
        .arg("write")
        .arg(&output)
        .output()
        .expect("vpype on PATH (python3 -m pip install vpype)");
    assert!(
        run.status.success(),
        "vpype read: {}",
        String::from_utf8_lossy(&run.stderr)
    );
    svg_layers(&std::fs::read_to_string(&output).expect("vpype's SVG"))
}

/// vpype keeps every layer of `svg` apart, numbered in order, with every element a line of
/// its own; returns the layers.
fn assert_vpype_keeps_layers_apart(what: &str, svg: &str) -> Vec<(String, String, usize)> {
    let ours = svg_layers(svg);
    let theirs = vpype_layers(svg);
    eprintln!(
        "{what}: {} layers written, vpype reads {}: {:?}",
        ours.len(),
        theirs.len(),
        theirs.iter().map(|l| &l.1).collect::<Vec<_>>()
    );
    let numbered: Vec<(String, String, usize)> = ours
        .iter()
        .enumerate()
        .map(|(i, (_, label, n))| (format!("layer{}", i + 1), label.clone(), *n))
        .collect();
    assert_eq!(theirs, numbered, "{what}");
    ours
}

#[test]
#[ignore = "needs vpype (pip)"]
fn vpype_reads_one_layer_per_assignment_in_order() {
    let _alone = post_common::external_tools_alone();
    let machine = load_machine("grbl-pen-plotter").expect("shipped");
    let material = load_material("card-300gsm").expect("shipped");
    let bird = designs().remove(0).1;
    // Mountains plotted, valleys marked: two pens.
    let p = planned(&bird, &machine, "card-300gsm");
    let svg = post::svg(&p, &p.jobs[0], &machine.bed, false).expect("svg");
    let layers = assert_vpype_keeps_layers_apart("bird base, plotter", &svg);
    let labels: Vec<&str> = layers.iter().map(|l| l.1.as_str()).collect();
    assert_eq!(labels, ["mark", "plot"]);
    // Dashed valleys: every dash is a line of vpype's perforate layer.
    let overrides = PlanOverrides {
        valley: Some(Some(Operation::Perforate)),
        ..Default::default()
    };
    let o = PlanOptions::for_machine(&machine, &material, &overrides).expect("adapts");
    let dashed = plan(&bird, &machine, &material, &o).expect("plans");
    let svg = post::svg(&dashed, &dashed.jobs[0], &machine.bed, false).expect("svg");
    let layers = assert_vpype_keeps_layers_apart("bird base, dashed valleys", &svg);
    let dashes = foldcam_dashes(&dashed, &machine).len();
    let perforate = layers
        .iter()
        .find(|l| l.1 == "perforate")
        .expect("perforate");
    assert!(
        dashes > 50 && perforate.2 == dashes,
        "{dashes} {perforate:?}"
    );
    // A calibration grid: 27 cells of their own, whose names hold digits, between the mark
    // and the cut layers.
    let laser = load_machine("grbl-diode").expect("shipped");
    let paper = load_material("paper-160gsm").expect("shipped");
    let opts = foldcam::fab::testgrid::TestGridOptions::around(&paper, &laser);
    let grid = foldcam::fab::testgrid::test_grid(&laser, &paper, &opts).expect("grid");
    let svg = post::svg(&grid.plan, &grid.plan.jobs[0], &laser.bed, false).expect("svg");
    let layers = assert_vpype_keeps_layers_apart("calibration grid", &svg);
    assert_eq!(layers.len(), grid.cells.len() + 2);
    assert_eq!(layers[0].1, "mark");
    assert_eq!(layers[1].1, "2 perforate-cell-1");
}

#[test]
fn svg_layers_carry_their_number_first_where_vpype_looks_for_it() {
    // What vpype 1.15 reads (`read_multilayer_svg`): the first digits of the label, else of
    // the id, else the group's position. Without a vpype, the numbers it would read.
    let first_digits = |s: &str| -> Option<usize> {
        let digits: String = s
            .chars()
            .skip_while(|c| !c.is_ascii_digit())
            .take_while(|c| c.is_ascii_digit())
            .collect();
        digits.parse().ok()
    };
    let laser = load_machine("grbl-diode").expect("shipped");
    let paper = load_material("paper-160gsm").expect("shipped");
    let opts = foldcam::fab::testgrid::TestGridOptions::around(&paper, &laser);
    let grid = foldcam::fab::testgrid::test_grid(&laser, &paper, &opts).expect("grid");
    let svg = post::svg(&grid.plan, &grid.plan.jobs[0], &laser.bed, false).expect("svg");
    let layers = svg_layers(&svg);
    assert_eq!(layers.len(), grid.cells.len() + 2);
    for (i, (id, label, _)) in layers.iter().enumerate() {
        let read = first_digits(label)
            .or_else(|| first_digits(id))
            .unwrap_or(i + 1);
        assert_eq!(read, i + 1, "{id} {label}");
    }
}

/// vpype's pen-up length of `svg` after the commands `then` (`["linesort"]`, or none to take
/// the file's order): `vpype read FILE … stat`, the last "Pen-up length" it prints (all
/// layers), in vpype's pixels (1/96 in).
fn vpype_pen_up(svg: &Path, then: &[&str]) -> f64 {
    let run = std::process::Command::new("vpype")
        .arg("read")
        .arg(svg)
        .args(then)
        .arg("stat")
        .output()
        .expect("vpype on PATH (python3 -m pip install vpype)");
    assert!(
        run.status.success(),
        "vpype stat: {}",
        String::from_utf8_lossy(&run.stderr)
    );
    let out = String::from_utf8_lossy(&run.stdout);
    out.lines()
        .rev()
        .filter_map(|l| l.trim().strip_prefix("Pen-up length:"))
        .find_map(|v| v.trim().parse::<f64>().ok())
        .unwrap_or_else(|| panic!("no pen-up length in: {out}"))
}

/// A drawing of `n` × `n` cells of `cell` mm, each with one diagonal (all the same way, or
/// alternating like a checkerboard), as one SVG `<line>` per segment in a shuffled order (a
/// fixed LCG), in millimetres.
fn shuffled_grid_svg(n: usize, cell: f64, alternate: bool) -> String {
    let mut segments = Vec::new();
    let at = |i: usize| 5.0 + i as f64 * cell;
    for i in 0..=n {
        for j in 0..n {
            segments.push([at(i), at(j), at(i), at(j + 1)]);
            segments.push([at(j), at(i), at(j + 1), at(i)]);
        }
    }
    for i in 0..n {
        for j in 0..n {
            if alternate && (i + j) % 2 == 1 {
                segments.push([at(i), at(j + 1), at(i + 1), at(j)]);
            } else {
                segments.push([at(i), at(j), at(i + 1), at(j + 1)]);
            }
        }
    }
    let mut state = 12345u64;
    for k in (1..segments.len()).rev() {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        segments.swap(k, (state >> 33) as usize % (k + 1));
    }
    let side = at(n) + 5.0;
    let mut svg = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{side}mm\" height=\"{side}mm\" \
         viewBox=\"0 0 {side} {side}\">\n"
    );
    for [a, b, c, d] in segments {
        svg.push_str(&format!(
            "<line x1=\"{a}\" y1=\"{b}\" x2=\"{c}\" y2=\"{d}\" stroke=\"#ff0000\"/>\n"
        ));
    }
    svg + "</svg>\n"
}

#[test]
#[ignore = "needs vpype (pip)"]
fn pen_lines_travel_no_further_than_after_vpype_linesort() {
    let _alone = post_common::external_tools_alone();
    let dir = tempfile::tempdir().expect("temporary folder");
    // The shuffled triangulated grid of the plotting benchmark, smaller (40 × 40 cells of
    // 2.2 mm: 4,880 segments; two vertices of odd degree), and one with alternating diagonals
    // (many odd vertices along the rim, so several strokes and jumps).
    for (name, alternate) in [("grid", false), ("alternating grid", true)] {
        let input = dir.path().join(format!("{name}.svg"));
        std::fs::write(&input, shuffled_grid_svg(40, 2.2, alternate)).expect("written");
        // Ours: the plotter SVG in machine millimetres, read back by vpype in our order.
        let ours = dir.path().join(format!("{name}.plot.svg"));
        let out = crate::bin::foldcam(
            &[
                "cut",
                input.to_str().unwrap(),
                "-m",
                "grbl-pen-plotter",
                "-x",
                "card-300gsm",
                "--mountain",
                "plot",
                "-o",
                ours.to_str().unwrap(),
            ],
            dir.path(),
        );
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        // Theirs: the same lines as vpype's linesort orders them.
        let (mine, theirs) = (
            vpype_pen_up(&ours, &[]),
            vpype_pen_up(&input, &["linesort"]),
        );
        eprintln!(
            "{name}: pen-up {:.1} mm in foldcam's order, {:.1} mm after vpype's linesort",
            mine * 25.4 / 96.0,
            theirs * 25.4 / 96.0
        );
        assert!(mine <= theirs, "{name}: {mine} px > {theirs} px");
    }
}
