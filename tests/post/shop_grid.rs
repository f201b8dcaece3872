//! Shop tools: the calibration grid on every shipped machine (G-code read back by the simulated
//! machine, LightBurn, DXF and SVG layers per cell), framing jobs, LightBurn perforations along
//! curved creases, and plotter statistics agreeing with what the plotter draws.

use crate::post_common;

use foldcam::design::classic::MiuraOri;
use foldcam::fab::testgrid::{TestGrid, TestGridOptions, test_grid};
use foldcam::fab::{FabPlan, Operation, PlanOptions, plan};
use foldcam::machine::{
    Dialect, MachineKind, MachineProfile, Material, load_machine, load_material, shipped_machines,
};
use foldcam::pattern::{Assignment, CreasePattern};
use foldcam::post::{self, DxfVersion};
use foldcam::sim;
use glam::DVec2;

/// Largest relative difference between plan's time and the simulated machine's.
const TIME_TOLERANCE: f64 = 0.02;
/// Distance within which a simulated burn counts as lying on a crease, mm (coordinates are
/// rounded to at most 0.01 mm).
const ON_LINE_MM: f64 = 0.02;

fn material_for(machine: &MachineProfile) -> Material {
    let name = if machine.dialect == Dialect::LinuxCnc {
        "stainless-0.5"
    } else {
        "card-300gsm"
    };
    load_material(name).expect("shipped")
}

fn grid_for(machine: &MachineProfile, material: &Material) -> TestGrid {
    let opts = TestGridOptions::around(material, machine);
    test_grid(machine, material, &opts).unwrap_or_else(|e| panic!("{}: {e}", machine.name))
}

/// Whether LinuxCNC's own interpreter (`rs274 -g`, Debian linuxcnc-uspace) reads `text` to its
/// end without an error; panics when `rs274` cannot run.
fn rs274_accepts(text: &str) -> bool {
    let dir = tempfile::tempdir().expect("temp dir");
    let file = dir.path().join("job.ngc");
    std::fs::write(&file, text).expect("write");
    let out = std::process::Command::new("rs274")
        .arg("-g")
        .arg(&file)
        .output()
        .expect("rs274 (Debian linuxcnc-uspace) runs");
    let canon = String::from_utf8_lossy(&out.stdout);
    out.status.success() && canon.contains("PROGRAM_END()")
}

fn distance_to_segment(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let ab = b - a;
    let t = ((p - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0);
    p.distance(a + ab * t)
}

#[test]
fn testgrid_runs_clean_on_every_shipped_machine_with_each_cells_power_and_speed() {
    let mut checked = 0;
    for name in shipped_machines() {
        let machine = load_machine(name).expect("shipped");
        if !machine.emits_gcode() {
            continue; // file-only: see the LightBurn, DXF and SVG tests
        }
        let material = material_for(&machine);
        let grid = grid_for(&machine, &material);
        let opts = TestGridOptions::around(&material, &machine);
        let want_cells =
            opts.dash_mm.len() * opts.bridge_mm.len() * opts.power.len() * opts.speed_mm_min.len();
        assert_eq!(grid.cells.len(), want_cells, "{name}");
        assert_eq!(grid.plan.jobs.len(), 1);
        let job = &grid.plan.jobs[0];
        let text = post::gcode(&grid.plan, job, &machine).expect("G-code");
        let run = sim::run(&text, &machine).expect("readable");
        assert!(run.is_clean(), "{name}: {:?}", run.violations);
        let plotter = machine.kind == MachineKind::Plotter;
        for cell in &grid.cells {
            let (a, b) = grid.pattern.segment(cell.crease);
            let (a, b) = (
                job.to_machine.transform_point2(a),
                job.to_machine.transform_point2(b),
            );
            let on: Vec<_> = run
                .burns
                .iter()
                .filter(|burn| {
                    distance_to_segment(burn.from, a, b) < ON_LINE_MM
                        && distance_to_segment(burn.to, a, b) < ON_LINE_MM
                })
                .collect();
            let length: f64 = on.iter().map(|b| b.length()).sum();
            // The cut share of the crease: toolpath dashes one kerf shorter than asked, the
            // period dash + bridge; the end clearances and the stretch to whole dashes take
            // some of the crease, never more than half.
            let duty = (cell.dash_mm - material.kerf_mm) / (cell.dash_mm + cell.bridge_mm);
            let most = duty * a.distance(b);
            assert!(
                length > 0.5 * most && length < 1.2 * most,
                "{name} cell {}: {length} mm burned on the crease, about {most} mm expected",
                cell.number
            );
            let feed = cell.speed_mm_min.min(machine.max_feed_mm_min);
            for burn in on {
                assert!((burn.feed_mm_min - feed).abs() < 1e-6, "{name} feed");
                if !plotter {
                    let f = run.power_fraction(burn.power);
                    assert!(
                        (f - cell.power).abs() < 1e-6,
                        "{name} cell {} power {f}",
                        cell.number
                    );
                }
            }
            // The labels name the values.
            assert_eq!(
                cell.label[0],
                format!(
                    "{} {}",
                    foldcam::fab::testgrid::short_number(cell.dash_mm),
                    foldcam::fab::testgrid::short_number(cell.bridge_mm)
                )
            );
        }
        // Labels marked: burns at the material's mark power (a pen draws them all at once).
        if !plotter {
            let mark = run
                .burns
                .iter()
                .filter(|b| {
                    (run.power_fraction(b.power) - material.settings.mark.power).abs() < 1e-6
                })
                .count();
            assert!(mark > grid.cells.len(), "{name}: {mark} label strokes");
        }
        let rel = (grid.plan.stats.time_s - run.time_s).abs() / run.time_s;
        assert!(
            rel < TIME_TOLERANCE,
            "{name}: plan {} s, simulated {} s",
            grid.plan.stats.time_s,
            run.time_s
        );
        checked += 1;
    }
    assert_eq!(checked, 4, "the four G-code machines");
}

/// `Value` of the child `key` of a LightBurn element.
fn value(n: roxmltree::Node, key: &str) -> String {
    n.children()
        .find(|c| c.has_tag_name(key))
        .and_then(|c| c.attribute("Value"))
        .unwrap_or_else(|| panic!("{key} missing"))
        .to_string()
}

fn num(n: roxmltree::Node, key: &str) -> f64 {
    value(n, key).parse().expect("number")
}

#[test]
fn testgrid_lightburn_project_has_one_cut_setting_per_cell_with_its_values() {
    for name in ["lightburn", "grbl-diode"] {
        let machine = load_machine(name).expect("shipped");
        let material = load_material("paper-160gsm").expect("shipped");
        let grid = grid_for(&machine, &material);
        let perf = post::LbrnPerforation::LightBurn;
        let xml = post::lbrn2(&grid.plan, &grid.plan.jobs[0], &machine, perf).expect("lbrn2");
        let doc = roxmltree::Document::parse(&xml).expect("well-formed XML");
        let settings: Vec<_> = doc
            .root_element()
            .children()
            .filter(|c| c.has_tag_name("CutSetting"))
            .collect();
        // One per cell, and the outlines' cut and the labels' mark.
        assert_eq!(settings.len(), grid.cells.len() + 2, "{name}");
        let kerf = material.kerf_mm;
        for cell in &grid.cells {
            let layer = format!("perforate-cell-{}", cell.number);
            let cs = settings
                .iter()
                .find(|c| value(**c, "name") == layer)
                .unwrap_or_else(|| panic!("{layer} missing"));
            let speed = cell.speed_mm_min.min(machine.max_feed_mm_min) / 60.0;
            assert!((num(*cs, "speed") - speed).abs() < 1e-3);
            assert!((num(*cs, "maxPower") - 100.0 * cell.power).abs() < 1e-3);
            assert_eq!(value(*cs, "perforate"), "1");
            // The layer's own dash and gap: the asked values, kerf taken into account, within
            // the layout's stretch to whole dashes.
            let (dash, gap) = (num(*cs, "perfLen"), num(*cs, "perfSkip"));
            assert!(
                (dash - (cell.dash_mm - kerf)).abs() < 0.1 * cell.dash_mm,
                "{dash}"
            );
            assert!(
                (gap - (cell.bridge_mm + kerf)).abs() < 0.15 * cell.bridge_mm + 0.05,
                "{gap}"
            );
            let index = value(*cs, "index");
            let shapes = doc
                .root_element()
                .children()
                .filter(|c| c.has_tag_name("Shape") && c.attribute("CutIndex") == Some(&index))
                .count();
            assert_eq!(shapes, 1, "{layer}: one perforated crease");
        }
        // A grid with more cells than LightBurn has colour layers is refused, not truncated.
        let mut many = TestGridOptions::around(&material, &machine);
        many.dash_mm = vec![1.0, 1.5, 2.0, 2.5];
        many.bridge_mm = vec![0.4, 0.5, 0.6, 0.7];
        many.power = vec![0.6, 0.7];
        let big = test_grid(&machine, &material, &many).expect("32 cells");
        let err = post::lbrn2(&big.plan, &big.plan.jobs[0], &machine, perf).expect_err("too many");
        assert!(
            matches!(err, post::PostError::TooManyLayers { layers: 34, .. }),
            "{err}"
        );
        for op in ["cut", "mark"] {
            let cs = settings
                .iter()
                .find(|c| value(**c, "name") == op)
                .unwrap_or_else(|| panic!("{op} missing"));
            let s = material.settings.get(Operation::from_name(op).expect("op"));
            assert!((num(*cs, "maxPower") - 100.0 * s.power).abs() < 1e-3);
        }
    }
}

#[test]
fn testgrid_dxf_and_svg_give_every_cell_a_layer_with_unique_handles() {
    let machine = load_machine("lightburn").expect("shipped");
    let material = load_material("stainless-0.3").expect("shipped");
    let grid = grid_for(&machine, &material);
    let job = &grid.plan.jobs[0];
    let n = grid.cells.len();
    assert!(n > 16, "more layers than the fixed handle block holds");
    for version in [DxfVersion::R2000, DxfVersion::R12] {
        let text =
            String::from_utf8(post::dxf(&grid.plan, job, version).expect("dxf")).expect("text");
        let lines: Vec<&str> = text.lines().map(str::trim).collect();
        let pairs: Vec<(&str, &str)> = lines.chunks(2).map(|c| (c[0], c[1])).collect();
        let layer_records = pairs.iter().filter(|p| **p == ("0", "LAYER")).count();
        // Layer 0, the outlines' cut, the labels' mark and one per cell.
        assert_eq!(layer_records, n + 3, "{version:?}");
        for cell in &grid.cells {
            let layer = format!("PERFORATE-CELL-{}", cell.number);
            assert!(
                pairs.contains(&("2", layer.as_str())),
                "{version:?}: {layer}"
            );
            assert!(
                pairs.contains(&("8", layer.as_str())),
                "{version:?}: {layer} unused"
            );
        }
        if version == DxfVersion::R2000 {
            let mut handles: Vec<&str> = pairs.iter().filter(|p| p.0 == "5").map(|p| p.1).collect();
            let all = handles.len();
            handles.sort();
            handles.dedup();
            assert_eq!(handles.len(), all, "every handle once");
        }
    }
    let svg = post::svg(&grid.plan, job, &machine.bed, false).expect("svg");
    let doc = roxmltree::Document::parse(&svg).expect("well-formed SVG");
    let labels: Vec<&str> = doc
        .descendants()
        .filter_map(|g| g.attribute(("http://www.inkscape.org/namespaces/inkscape", "label")))
        .filter(|l| l.contains(" perforate-cell-"))
        .collect();
    assert_eq!(labels.len(), n);
}

fn planned(cp: &CreasePattern, machine: &MachineProfile, material: &Material) -> FabPlan {
    let mut o = PlanOptions::from_material(material);
    o.adapt_to_machine(machine).expect("adapts");
    plan(cp, machine, material, &o).expect("plans")
}

/// The box of every burn of a simulated run.
fn burned_box(run: &sim::SimReport) -> (DVec2, DVec2) {
    let b = run.burn_bounds.expect("burns");
    (b.min, b.max)
}

#[test]
fn frames_trace_exactly_the_jobs_bounds_with_the_tool_off_or_at_the_frame_power() {
    let cp = MiuraOri::default().build().expect("miura");
    for name in shipped_machines() {
        let machine = load_machine(name).expect("shipped");
        if !machine.emits_gcode() {
            continue;
        }
        let material = material_for(&machine);
        let p = planned(&cp, &machine, &material);
        let job = &p.jobs[0];
        let tol = machine.resolution_mm;
        // The job's extent as the simulated machine burns it.
        let real = sim::run(&post::gcode(&p, job, &machine).expect("job"), &machine).expect("sim");
        let (lo, hi) = burned_box(&real);
        let corners = [lo, DVec2::new(hi.x, lo.y), hi, DVec2::new(lo.x, hi.y), lo];
        let dark_text = post::gcode::frame(&p, job, &machine, 0.0).expect("frame");
        let dark = sim::run(&dark_text, &machine).expect("sim");
        assert!(dark.is_clean(), "{name}: {:?}", dark.violations);
        assert!(dark.burns.is_empty(), "{name}: the frame burned");
        let visited: Vec<DVec2> = dark.travels.iter().map(|t| t.to).collect();
        let traced = visited
            .windows(5)
            .any(|w| w.iter().zip(&corners).all(|(a, b)| a.distance(*b) <= tol));
        assert!(traced, "{name}: {visited:?} does not trace {corners:?}");
        if machine.kind == MachineKind::Plotter {
            continue;
        }
        let lit = sim::run(
            &post::gcode::frame(&p, job, &machine, 0.05).expect("frame"),
            &machine,
        )
        .expect("sim");
        assert!(lit.is_clean(), "{name}: {:?}", lit.violations);
        let (llo, lhi) = burned_box(&lit);
        assert!(llo.distance(lo) <= tol && lhi.distance(hi) <= tol, "{name}");
        let perimeter = 2.0 * ((hi.x - lo.x) + (hi.y - lo.y));
        assert!(
            (lit.burn_length_mm - perimeter).abs() <= 4.0 * tol,
            "{name}"
        );
        for b in &lit.burns {
            assert!((lit.power_fraction(b.power) - 0.05).abs() < 1e-6, "{name}");
        }
    }
}

#[test]
fn lightburn_perforations_follow_a_curved_crease() {
    // A half circle of radius 40 mm as 64 short valley edges between two real vertices.
    let r = 40.0;
    let mut cp = CreasePattern::new();
    let n = 64;
    let ids: Vec<_> = (0..=n)
        .map(|k| {
            let t = std::f64::consts::PI * k as f64 / n as f64;
            cp.add_vertex(DVec2::new(50.0 + r * t.cos(), 10.0 + r * t.sin()))
        })
        .collect();
    for w in ids.windows(2) {
        cp.add_edge(w[0], w[1], Assignment::Valley);
    }
    let machine = load_machine("lightburn").expect("shipped");
    let material = load_material("paper-160gsm").expect("shipped");
    let p = planned(&cp, &machine, &material);
    let perf = post::LbrnPerforation::LightBurn;
    let xml = post::lbrn2(&p, &p.jobs[0], &machine, perf).expect("lbrn2");
    let doc = roxmltree::Document::parse(&xml).expect("XML");
    let shape = doc
        .root_element()
        .children()
        .find(|c| c.has_tag_name("Shape"))
        .expect("a shape");
    let verts: Vec<DVec2> = shape
        .children()
        .find(|c| c.has_tag_name("VertList"))
        .and_then(|c| c.text())
        .expect("VertList")
        .split('V')
        .filter(|v| !v.is_empty())
        .map(|v| {
            let v = v
                .strip_suffix("c0x1c1x1")
                .expect("LightBurn's corner flags");
            let xy: Vec<f64> = v.split(' ').map(|t| t.parse().expect("number")).collect();
            DVec2::new(xy[0], xy[1])
        })
        .collect();
    // Every written vertex lies on the circle (the crease), and the path runs along it: its
    // length is the half circle less the two end clearances, up to the chords of the bridges.
    // The pattern's lower-left corner (10, 10) goes to the margin's corner (5, 5).
    let margin = PlanOptions::from_material(&material).margin_mm;
    let centre = DVec2::new(50.0, 10.0) - DVec2::new(10.0, 10.0) + DVec2::splat(margin);
    for v in &verts {
        assert!((v.distance(centre) - r).abs() < 0.05, "{v} off the circle");
    }
    let length: f64 = verts.windows(2).map(|w| w[0].distance(w[1])).sum();
    let arc = std::f64::consts::PI * r;
    let clearance = material.perforation.vertex_clearance_mm;
    assert!(
        length > arc - 2.0 * clearance - 2.0 * material.perforation.cut_mm,
        "{length}"
    );
    assert!(length < arc, "{length}");
}

#[test]
fn plotter_statistics_count_what_the_plotter_draws() {
    let machine = load_machine("grbl-pen-plotter").expect("shipped");
    let mut material = load_material("card-300gsm").expect("shipped");
    // A plotter draws every layer at the plot settings: other passes must not count.
    material.settings.mark.passes = 3;
    material.settings.score.passes = 2;
    material.settings.plot.passes = 1;
    let cp = MiuraOri::default().build().expect("miura");
    let p = planned(&cp, &machine, &material);
    let text = post::gcode(&p, &p.jobs[0], &machine).expect("G-code");
    let run = sim::run(&text, &machine).expect("sim");
    assert!(run.is_clean());
    let planned_length: f64 = p.stats.length_mm.iter().map(|(_, mm)| mm).sum();
    assert!(
        (planned_length - run.burn_length_mm).abs() < 1e-6 * run.burn_length_mm + 0.05,
        "plan {planned_length} mm, drawn {} mm",
        run.burn_length_mm
    );
    assert_eq!(p.stats.pierces, run.pierces);
}

#[test]
#[ignore = "needs rs274 (Debian linuxcnc-uspace)"]
fn linuxcnc_reads_every_test_grid_and_frame_to_its_end() {
    let _alone = post_common::external_tools_alone();
    let cp = MiuraOri::default().build().expect("miura");
    let mut read = 0;
    for name in shipped_machines() {
        let machine = load_machine(name).expect("shipped");
        if machine.dialect != Dialect::LinuxCnc {
            continue;
        }
        let material = material_for(&machine);
        let grid = grid_for(&machine, &material);
        let text = post::gcode(&grid.plan, &grid.plan.jobs[0], &machine).expect("G-code");
        assert!(rs274_accepts(&text), "{name}: rs274 refused the grid");
        let p = planned(&cp, &machine, &material);
        for power in [0.0, 0.05] {
            let frame = post::gcode::frame(&p, &p.jobs[0], &machine, power).expect("frame");
            assert!(
                rs274_accepts(&frame),
                "{name}: rs274 refused the frame at {power}"
            );
        }
        assert!(!rs274_accepts("G1 X1 F\n"), "rs274 accepted a broken line");
        read += 1;
    }
    assert!(read >= 1, "no shipped LinuxCNC machine");
}
