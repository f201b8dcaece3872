//! Ready for the shop floor: plan's time against the simulated machine reading the written
//! file, LinuxCNC lasers without spindle words, one preamble and one end per job, plotter
//! layers with a pen-change pause, air assist, the firmware expectations in the header.

use std::path::PathBuf;

use foldcam::design::classic::{MiuraOri, SquareTwist, Waterbomb, Yoshimura};
use foldcam::fab::Operation;
use foldcam::fab::{FabPlan, PlanOptions, plan};
use foldcam::machine::{
    LaserOutput, MachineProfile, Material, load_machine, load_material, shipped_machines,
};
use foldcam::pattern::{Assignment, CreasePattern, PlanarizeOptions, planarize};
use foldcam::post;
use foldcam::sim;
use glam::DVec2;

/// Largest relative difference between plan's time and the simulated machine's.
const TIME_TOLERANCE: f64 = 0.02;

fn sized(mut cp: CreasePattern, size: f64) -> CreasePattern {
    let (lo, hi) = cp.bounds().expect("vertices");
    cp.scale_to_mm(size / (hi - lo).max_element());
    cp
}

/// A curved outline: a 120-gon blob (radius 40 ± 8 mm, three lobes) cut out, with a valley
/// and a mountain across it, so kerf offsets carry a round join at every outline vertex.
fn blob() -> CreasePattern {
    let n = 120;
    let mut cp = CreasePattern::new();
    let v: Vec<_> = (0..n)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / n as f64;
            let r = 40.0 + 8.0 * (3.0 * t).sin();
            cp.add_vertex(DVec2::new(60.0, 60.0) + DVec2::from_angle(t) * r)
        })
        .collect();
    for i in 0..n {
        cp.add_edge(v[i], v[(i + 1) % n], Assignment::Boundary);
    }
    cp.add_edge(v[0], v[n / 2], Assignment::Valley);
    cp.add_edge(v[n / 4], v[3 * n / 4], Assignment::Mountain);
    let mut cp = cp;
    planarize(&mut cp, &PlanarizeOptions::default()).expect("planarises");
    cp
}

/// The classic generators at their defaults, the bundled example patterns (sized 120 mm), a
/// curved outline ([`blob`]) and curved creases (Origami Simulator's `HexSpiralTess.svg`).
fn examples() -> Vec<(String, CreasePattern)> {
    let mut out: Vec<(String, CreasePattern)> = vec![
        ("miura".into(), MiuraOri::default().build().expect("miura")),
        (
            "twist".into(),
            SquareTwist::default().build().expect("twist"),
        ),
        (
            "waterbomb".into(),
            Waterbomb::default().build().expect("wb"),
        ),
        (
            "yoshimura".into(),
            Yoshimura::default().build().expect("yo"),
        ),
    ];
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/patterns");
    for name in ["flat-vertex.fold", "preliminary-base.cp"] {
        let mut cp = foldcam::formats::load(&root.join(name))
            .unwrap_or_else(|e| panic!("{e}"))
            .pattern;
        planarize(&mut cp, &PlanarizeOptions::default()).expect("planarises");
        out.push((name.into(), sized(cp, 120.0)));
    }
    out.push(("curved outline".into(), blob()));
    let svg = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/HexSpiralTess.svg");
    let mut cp = foldcam::formats::load(&svg)
        .unwrap_or_else(|e| panic!("{e}"))
        .pattern;
    planarize(&mut cp, &PlanarizeOptions::default()).expect("planarises");
    out.push(("HexSpiralTess.svg".into(), sized(cp, 120.0)));
    out
}

#[test]
fn kerf_offset_outlines_have_no_side_shorter_than_the_resolution() {
    // Before the offsets were cleaned, every vertex of a curved outline carried a round join
    // of about 1 µm: on the fiber laser 12 of 207 cut moves were a single 1 µm step.
    for name in shipped_machines() {
        let machine = load_machine(name).expect("shipped");
        if !machine.supports(Operation::Cut) {
            continue; // a plotter draws the outline: no kerf
        }
        for material in material_for(&machine) {
            let p = planned(&blob(), &machine, &material);
            let mut sides = 0;
            for path in p.jobs.iter().flat_map(|j| &j.paths) {
                if path.op != Operation::Cut {
                    continue;
                }
                for w in path.strokes.iter().flat_map(|s| s.windows(2)) {
                    let length = w[0].distance(w[1]);
                    assert!(
                        length >= machine.resolution_mm,
                        "{name}/{}: a {length} mm side",
                        material.name
                    );
                    sides += 1;
                }
            }
            assert!(sides > 100, "{name}: {sides} cut sides");
        }
    }
}

fn material_for(machine: &MachineProfile) -> Vec<Material> {
    let names: &[&str] = if machine.dialect == foldcam::machine::Dialect::LinuxCnc {
        &["stainless-0.5"]
    } else {
        &["card-300gsm", "paper-160gsm"]
    };
    names
        .iter()
        .map(|n| load_material(n).expect("shipped"))
        .collect()
}

fn planned(cp: &CreasePattern, machine: &MachineProfile, material: &Material) -> FabPlan {
    let o = PlanOptions::for_machine(machine, material, &Default::default()).expect("adapts");
    plan(cp, machine, material, &o).expect("plans")
}

/// Every job of `p` written and run on the simulated machine: total seconds, and the texts.
fn simulated(p: &FabPlan, machine: &MachineProfile) -> (f64, Vec<String>) {
    let mut total = 0.0;
    let mut texts = Vec::new();
    for job in &p.jobs {
        let text = post::gcode(p, job, machine).expect("G-code");
        let run = sim::run(&text, machine).expect("readable");
        assert!(
            run.is_clean(),
            "{}: {:?}",
            machine.name,
            run.violations.first()
        );
        total += run.time_s;
        texts.push(text);
    }
    (total, texts)
}

#[test]
fn plan_time_is_within_two_percent_of_the_simulated_machine_everywhere() {
    let mut checked = 0;
    let mut worst = (0.0, String::new());
    for name in shipped_machines() {
        let machine = load_machine(name).expect("shipped");
        if !machine.emits_gcode() {
            continue;
        }
        for material in material_for(&machine) {
            for (pattern, cp) in examples() {
                let p = planned(&cp, &machine, &material);
                let (sim_s, _) = simulated(&p, &machine);
                let plan_s = p.stats.time_s;
                let diff = (plan_s - sim_s).abs() / sim_s;
                if diff > worst.0 {
                    worst = (diff, format!("{name}/{}/{pattern}", material.name));
                }
                assert!(
                    diff <= TIME_TOLERANCE,
                    "{name}/{}/{pattern}: plan {plan_s:.2} s, simulated {sim_s:.2} s",
                    material.name
                );
                checked += 1;
            }
        }
    }
    assert!(checked >= 3 * 2 * 8 + 8, "checked {checked}");
    eprintln!(
        "worst plan vs simulate difference: {:.4}% ({})",
        100.0 * worst.0,
        worst.1
    );
}

fn normalized(text: &str) -> Vec<String> {
    text.lines()
        .map(foldcam::post::gcode::normalize)
        .filter(|l| !l.is_empty())
        .collect()
}

#[test]
fn linuxcnc_perforations_run_on_synchronised_outputs_without_spindle_words() {
    let cp = MiuraOri::default().build().expect("miura");
    let analog = load_machine("linuxcnc-fiber").expect("shipped");
    assert_eq!(analog.control.laser_output, LaserOutput::Analog);
    let material = load_material("stainless-0.5").expect("shipped");
    let p = planned(&cp, &analog, &material);
    let (analog_s, texts) = simulated(&p, &analog);
    let lines = normalized(&texts[0]);
    let spindle_words = lines
        .iter()
        .filter(|l| l.starts_with("M3") || l.starts_with("M5"))
        .count();
    assert_eq!(spindle_words, 0);
    // One synchronised power-on per perforation dash and cut stroke (passes included).
    let strokes: usize = p.jobs[0]
        .paths
        .iter()
        .map(|t| t.strokes.len() * p.settings.get(t.op).passes as usize)
        .sum();
    let on = lines
        .iter()
        .filter(|l| l.starts_with("M67E0Q") && *l != "M67E0Q0")
        .count();
    assert_eq!(on, strokes);
    // No rapid between two burns of one pass of a toolpath: LinuxCNC would stop at both ends.
    // A G0 leads only to a toolpath or a pass; the dashes are linked by G1 at the travel feed.
    let passes: usize = p.jobs[0]
        .paths
        .iter()
        .map(|t| p.settings.get(t.op).passes as usize)
        .sum();
    let rapids = lines.iter().filter(|l| l.starts_with("G0")).count();
    assert!(rapids <= passes, "{rapids} rapids for {passes} passes");
    assert!(lines.contains(&"G64P0.01".to_string()));
    let links = lines.iter().filter(|l| l.ends_with("F30000")).count();
    assert!(links > strokes / 2, "{links} links for {strokes} burns");
    // The same job with a G0 between dashes (as foldcam wrote it before) stops at every
    // switch: the simulated machine times it as LinuxCNC 2.9 ran it, about twice as long.
    // (Every link sets F30000 and the burn after it sets its own feed again.)
    let old: String = texts[0]
        .lines()
        .map(|l| match l.strip_suffix(" F30000") {
            Some(link) if l.starts_with("G1") => link.replacen("G1", "G0", 1) + "\n",
            _ => format!("{l}\n"),
        })
        .collect();
    let old_run = sim::run(&old, &analog).expect("readable");
    assert!(old_run.is_clean(), "{:?}", old_run.violations.first());
    assert!(
        old_run.time_s > 1.5 * analog_s,
        "{} vs {analog_s}",
        old_run.time_s
    );
    // The same job switched through the spindle stops at every dash: the simulated machine
    // must take markedly longer (LinuxCNC 2.9 measured +43% on a Miura-ori).
    let spindle = MachineProfile {
        control: foldcam::machine::MachineControl {
            laser_output: LaserOutput::Spindle,
            ..analog.control.clone()
        },
        ..analog.clone()
    };
    let (spindle_s, spindle_texts) = simulated(&p, &spindle);
    assert!(normalized(&spindle_texts[0]).iter().any(|l| l == "M5"));
    assert!(spindle_s > 1.3 * analog_s, "{spindle_s} vs {analog_s}");
    // A digital gate burns the same lengths as the analog output.
    let digital = MachineProfile {
        control: foldcam::machine::MachineControl {
            laser_output: LaserOutput::Digital,
            ..analog.control.clone()
        },
        ..analog.clone()
    };
    let a = sim::run(&texts[0], &analog).expect("readable");
    let text = post::gcode(&p, &p.jobs[0], &digital).expect("G-code");
    assert!(normalized(&text).iter().any(|l| l == "M62P0"));
    let d = sim::run(&text, &digital).expect("readable");
    assert!(d.is_clean());
    assert_eq!(d.pierces, a.pierces);
    assert!((d.burn_length_mm - a.burn_length_mm).abs() < 1e-6);
    // Assist gas on for the cuts and perforations, off at the end.
    assert!(lines.contains(&"M8".to_string()));
    let m9 = lines.iter().rposition(|l| l == "M9").expect("air off");
    assert!(lines.iter().rposition(|l| l == "M8").expect("air on") < m9);
}

#[test]
fn every_job_has_one_preamble_and_one_end() {
    let cp = SquareTwist::default().build().expect("twist");
    for name in shipped_machines() {
        let machine = load_machine(name).expect("shipped");
        if !machine.emits_gcode() {
            continue;
        }
        let material = &material_for(&machine)[0];
        let p = planned(&cp, &machine, material);
        let (_, texts) = simulated(&p, &machine);
        let lines = normalized(&texts[0]);
        let count = |w: &str| lines.iter().filter(|l| *l == w).count();
        assert_eq!((count("G21"), count("G90")), (1, 1), "{name}");
        let end = machine.dialect != foldcam::machine::Dialect::Marlin;
        assert_eq!(count("M2"), usize::from(end), "{name}");
        if end {
            assert_eq!(lines.last().map(String::as_str), Some("M2"), "{name}");
        }
        let tail: Vec<_> = lines.iter().rev().take(4).collect();
        assert!(
            tail.windows(2).all(|w| w[0] != w[1]),
            "{name}: repeated lines at the end {tail:?}"
        );
    }
}

#[test]
fn headers_state_what_the_firmware_must_be_set_to() {
    let cp = SquareTwist::default().build().expect("twist");
    for (name, expect) in [("grbl-diode", "$32=1"), ("grbl-pen-plotter", "$32=0")] {
        let machine = load_machine(name).expect("shipped");
        let p = planned(
            &cp,
            &machine,
            &load_material("card-300gsm").expect("shipped"),
        );
        let (_, texts) = simulated(&p, &machine);
        let comment = texts[0]
            .lines()
            .take(3)
            .find(|l| l.starts_with(';') && l.contains(expect));
        assert!(comment.is_some(), "{name}: no {expect} in the header");
    }
}

#[test]
fn plotters_draw_mountains_and_valleys_on_separate_layers_with_a_pause() {
    let cp = MiuraOri::default().build().expect("miura");
    let machine = load_machine("grbl-pen-plotter").expect("shipped");
    let p = planned(
        &cp,
        &machine,
        &load_material("card-300gsm").expect("shipped"),
    );
    assert!(p.warnings.iter().any(|w| {
        w.kind == foldcam::fab::PlanWarningKind::AdaptedToMachine && w.text.contains("is a plotter")
    }));
    let svg = post::svg(&p, &p.jobs[0], &machine.bed, false).expect("SVG");
    let layers = svg.matches("inkscape:groupmode=\"layer\"").count();
    assert_eq!(layers, 2);
    let (_, texts) = simulated(&p, &machine);
    let lines = normalized(&texts[0]);
    let groups = texts[0]
        .lines()
        .filter(|l| matches!(*l, "; plot" | "; mark"))
        .count();
    assert_eq!(groups, 2);
    assert_eq!(lines.iter().filter(|l| *l == "M0").count(), groups - 1);
    // Asked-for dashed valleys stay dashes on a plotter (pen down per dash).
    let material = load_material("card-300gsm").expect("shipped");
    let overrides = foldcam::fab::PlanOverrides {
        valley: Some(Some(foldcam::fab::Operation::Perforate)),
        ..Default::default()
    };
    let o = PlanOptions::for_machine(&machine, &material, &overrides).expect("adapts");
    let dashed = plan(&cp, &machine, &material, &o).expect("plans");
    let svg = post::svg(&dashed, &dashed.jobs[0], &machine.bed, true).expect("SVG");
    assert!(svg.contains("inkscape:label=\"perforate\"") && svg.contains("stroke-dasharray"));
    let (_, texts) = simulated(&dashed, &machine);
    let run = sim::run(&texts[0], &machine).expect("readable");
    let perforate_strokes: usize = dashed.jobs[0]
        .paths
        .iter()
        .filter(|t| t.op == foldcam::fab::Operation::Perforate)
        .map(|t| t.strokes.len())
        .sum();
    assert!(perforate_strokes > 0 && run.pierces > perforate_strokes);
}

#[test]
fn perforation_bridges_are_the_material_left_after_the_kerf() {
    use foldcam::fab::{Operation, toolpaths};
    use foldcam::pattern::Assignment;
    use glam::DVec2;
    let mut cp = CreasePattern::new();
    cp.add_segment(DVec2::ZERO, DVec2::new(200.0, 0.0), Assignment::Valley);
    let material = load_material("paper-160gsm").expect("shipped");
    let mut o = PlanOptions::from_material(&material);
    o.mapping.valley = Some(Operation::Perforate);
    let asked = o.perforation;
    let kerf = o.kerf_mm;
    assert!(kerf > 0.05);
    // Mean gap between the toolpath dashes, mm.
    let mean_gap = |o: &PlanOptions| {
        let paths = toolpaths(&cp, o).expect("toolpaths");
        let dashes = &paths[0].strokes;
        let gaps: Vec<f64> = dashes
            .windows(2)
            .map(|w| w[0][1].distance(w[1][0]))
            .collect();
        gaps.iter().sum::<f64>() / gaps.len() as f64
    };
    // The layout stretches the period a little to fit whole dashes on the crease.
    let slack = 0.05 * asked.bridge_mm;
    let web = mean_gap(&o) - kerf;
    assert!((web - asked.bridge_mm).abs() < slack, "web {web}");
    o.kerf_offset = false;
    let raw = mean_gap(&o);
    assert!((raw - asked.bridge_mm).abs() < slack, "gap {raw}");
}

#[test]
fn lightburn_projects_parse_back_with_one_layer_per_operation_and_the_material_values() {
    use foldcam::fab::Operation;
    let cp = MiuraOri::default().build().expect("miura");
    for machine_name in ["lightburn", "grbl-diode"] {
        let machine = load_machine(machine_name).expect("shipped");
        let material = load_material("paper-160gsm").expect("shipped");
        let p = planned(&cp, &machine, &material);
        let job = &p.jobs[0];
        let xml = post::lbrn2(&p, job, &machine, post::LbrnPerforation::Dashes).expect("lbrn2");
        let doc = roxmltree::Document::parse(&xml).expect("well-formed XML");
        let root = doc.root_element();
        assert_eq!(root.tag_name().name(), "LightBurnProject");
        let value = |n: roxmltree::Node, key: &str| -> String {
            n.children()
                .find(|c| c.has_tag_name(key))
                .and_then(|c| c.attribute("Value"))
                .unwrap_or_else(|| panic!("{key} missing"))
                .to_string()
        };
        let num = |n: roxmltree::Node, key: &str| -> f64 { value(n, key).parse().expect("number") };
        let settings: Vec<_> = root
            .children()
            .filter(|c| c.has_tag_name("CutSetting"))
            .collect();
        let mut ops: Vec<Operation> = job.paths.iter().map(|t| t.op).collect();
        ops.sort();
        ops.dedup();
        assert_eq!(settings.len(), ops.len(), "{machine_name}");
        for cs in &settings {
            let op = Operation::from_name(&value(*cs, "name")).expect("an operation");
            assert!(ops.contains(&op));
            let s = material.settings.get(op);
            let speed = s.speed_mm_min.min(machine.max_feed_mm_min) / 60.0;
            assert!((num(*cs, "speed") - speed).abs() < 1e-3, "{op:?} speed");
            assert!((num(*cs, "maxPower") - 100.0 * s.power).abs() < 1e-3);
            assert_eq!(num(*cs, "numPasses"), f64::from(s.passes));
            let index = value(*cs, "index");
            let shapes = root
                .children()
                .filter(|c| c.has_tag_name("Shape") && c.attribute("CutIndex") == Some(&index))
                .count();
            // Every stroke is a shape, each perforation dash too (LightBurn's perforation
            // mode stays off; tests/post/lightburn_vpype.rs covers it).
            let paths = job.paths.iter().filter(|t| t.op == op);
            let want: usize = paths.map(|t| t.strokes.len()).sum();
            assert_eq!(shapes, want, "{op:?} shapes");
            assert!(cs.children().all(|c| !c.has_tag_name("perforate")));
        }
        // Every vertex lies on the bed.
        for shape in root.children().filter(|c| c.has_tag_name("Shape")) {
            let verts = shape
                .children()
                .find(|c| c.has_tag_name("VertList"))
                .and_then(|c| c.text())
                .expect("VertList");
            for v in verts.split('V').filter(|v| !v.is_empty()) {
                let v = v
                    .strip_suffix("c0x1c1x1")
                    .expect("LightBurn's corner flags");
                let xy: Vec<f64> = v.split(' ').map(|t| t.parse().expect("number")).collect();
                assert!(xy[0] >= 0.0 && xy[0] <= machine.bed.width_mm);
                assert!(xy[1] >= 0.0 && xy[1] <= machine.bed.height_mm);
            }
        }
    }
}

#[test]
fn origin_centre_and_offset_move_the_job_on_the_bed() {
    use foldcam::fab::Placement;
    use glam::DVec2;
    let cp = SquareTwist::default().build().expect("twist");
    let machine = load_machine("grbl-diode").expect("shipped");
    let material = load_material("card-300gsm").expect("shipped");
    let bounds = |p: &FabPlan| {
        let pts = p.jobs[0].paths.iter().flat_map(|t| &t.strokes).flatten();
        pts.fold(
            (DVec2::splat(f64::MAX), DVec2::splat(f64::MIN)),
            |(lo, hi), &q| (lo.min(q), hi.max(q)),
        )
    };
    let with = |placement: Placement| {
        let mut o = PlanOptions::from_material(&material);
        o.placement = placement;
        plan(&cp, &machine, &material, &o)
    };
    let corner = bounds(&with(Placement::default()).expect("plans"));
    let centred = bounds(
        &with(Placement {
            centre: true,
            offset_mm: DVec2::ZERO,
        })
        .expect("plans"),
    );
    let middle = (centred.0 + centred.1) / 2.0;
    let bed = DVec2::new(machine.bed.width_mm, machine.bed.height_mm);
    assert!((middle - bed / 2.0).length() < 1e-6, "{middle}");
    assert!(((centred.1 - centred.0) - (corner.1 - corner.0)).length() < 1e-9);
    let shift = DVec2::new(12.5, 30.0);
    let shifted = bounds(
        &with(Placement {
            centre: false,
            offset_mm: shift,
        })
        .expect("plans"),
    );
    assert!((shifted.0 - corner.0 - shift).length() < 1e-9);
    let off = with(Placement {
        centre: false,
        offset_mm: DVec2::new(-50.0, 0.0),
    });
    assert!(off.is_err());
}
