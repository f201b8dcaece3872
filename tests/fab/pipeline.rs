//! The whole path from pattern to machine: every shipped machine × material on the shared test
//! patterns, planned, written as G-code, read back by the simulated machine (no violations)
//! and checked against the pattern (every crease and cut covered as planned, nothing stray);
//! file-only machines get DXF and SVG. Property test: random patterns never produce
//! out-of-bed moves, lit travel, NaN or lost cut geometry.

use std::path::PathBuf;

use foldcam::design::classic::{MiuraOri, SquareTwist, Waterbomb, Yoshimura};
use foldcam::fab::{PlanOptions, plan};
use foldcam::machine::{
    MachineProfile, Material, load_machine, load_material, shipped_machines, shipped_materials,
};
use foldcam::pattern::{Assignment, CreasePattern, PlanarizeOptions, planarize};
use foldcam::post::{self, DxfVersion};
use foldcam::sim::{self, CoverageOptions, ViolationKind};
use glam::DVec2;
use proptest::prelude::*;

/// Scales a pattern so its longer side is `size` mm.
fn sized(mut cp: CreasePattern, size: f64) -> CreasePattern {
    let (lo, hi) = cp.bounds().expect("vertices");
    cp.scale_to_mm(size / (hi - lo).max_element());
    cp
}

/// The shared test patterns: the classic generators, the bundled samples and files from other
/// tools.
fn patterns() -> Vec<(String, CreasePattern)> {
    let mut out: Vec<(String, CreasePattern)> = vec![
        ("miura".into(), MiuraOri::default().build().expect("miura")),
        (
            "twist".into(),
            SquareTwist::default().build().expect("twist"),
        ),
        (
            "waterbomb".into(),
            Waterbomb::default().build().expect("waterbomb"),
        ),
        (
            "yoshimura".into(),
            Yoshimura::default().build().expect("yoshimura"),
        ),
    ];
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let mut files = vec![
        root.join("examples/patterns/flat-vertex.fold"),
        root.join("examples/patterns/preliminary-base.cp"),
    ];
    // Files from other tools (Origami Simulator, MIT: see tests/data/README.md), including
    // pop-up cards and a cube net with cuts.
    for name in [
        "popupSimple.svg",
        "cubeunwrapping.svg",
        "squareBase.svg",
        "mapfold.svg",
    ] {
        files.push(root.join("tests/data/svg").join(name));
    }
    for f in files {
        let mut cp = foldcam::formats::load(&f)
            .unwrap_or_else(|e| panic!("{e}"))
            .pattern;
        planarize(&mut cp, &PlanarizeOptions::default()).expect("planarises");
        out.push((
            f.file_name().expect("name").to_string_lossy().into_owned(),
            cp,
        ));
    }
    out.into_iter()
        .map(|(n, cp)| (n, sized(cp, 120.0)))
        .collect()
}

/// Read back with the `dxf` crate and roxmltree: one DXF entity per drawn stroke on its
/// operation's layer, every point on the bed, and as many SVG paths as strokes.
fn assert_file_outputs_hold_the_job(
    what: &str,
    job: &foldcam::fab::Setup,
    dxf: &[u8],
    svg: &[u8],
    machine: &MachineProfile,
) {
    let drawn = |s: &Vec<DVec2>| s.windows(2).any(|w| w[0].distance(w[1]) > 1e-3);
    let mut want = std::collections::BTreeMap::<String, usize>::new();
    for path in &job.paths {
        *want.entry(path.op.name().to_uppercase()).or_default() +=
            path.strokes.iter().filter(|s| drawn(s)).count();
    }
    want.retain(|_, n| *n > 0);
    let drawing = ::dxf::Drawing::load(&mut &dxf[..]).expect("readable DXF");
    let mut got = std::collections::BTreeMap::<String, usize>::new();
    let (w, h) = (machine.bed.width_mm, machine.bed.height_mm);
    for e in drawing.entities() {
        *got.entry(e.common.layer.clone()).or_default() += 1;
        if let ::dxf::entities::EntityType::LwPolyline(p) = &e.specific {
            for v in &p.vertices {
                assert!(
                    (-1e-6..=w + 1e-6).contains(&v.x) && (-1e-6..=h + 1e-6).contains(&v.y),
                    "{what}: DXF point ({}, {}) off the bed",
                    v.x,
                    v.y
                );
            }
        }
    }
    assert_eq!(got, want, "{what}: DXF entities per layer");
    let text = std::str::from_utf8(svg).expect("UTF-8 SVG");
    let doc = usvg::roxmltree::Document::parse(text).expect("well-formed SVG");
    let paths = doc
        .descendants()
        .filter(|n| n.has_tag_name("path") || n.has_tag_name("polyline"))
        .count();
    assert_eq!(paths, want.values().sum::<usize>(), "{what}: SVG paths");
}

fn options(machine: &MachineProfile, material: &Material, two_sided: bool) -> PlanOptions {
    let overrides = foldcam::fab::PlanOverrides {
        two_sided,
        ..Default::default()
    };
    PlanOptions::for_machine(machine, material, &overrides)
        .expect("every shipped machine can do every shipped material")
}

#[test]
fn every_shipped_machine_and_material_runs_clean_on_the_shared_patterns() {
    use rayon::prelude::*;
    let patterns = patterns();
    let materials = shipped_materials();
    let combos: Vec<(&str, &str)> = shipped_machines()
        .into_iter()
        .flat_map(|m| materials.iter().map(move |x| (m, *x)))
        .collect();
    // Every machine × material × pattern in parallel; each returns its G-code job count.
    let jobs: usize = combos
        .par_iter()
        .map(|&(machine_name, material_name)| {
            let machine = load_machine(machine_name).expect("shipped machine");
            let material = load_material(material_name).expect("shipped material");
            patterns
                .par_iter()
                .map(|(name, cp)| run_pattern(name, cp, &machine, &material))
                .sum::<usize>()
        })
        .sum();
    assert_eq!(
        jobs,
        expected_gcode_jobs(&patterns),
        "every G-code machine ran every pattern"
    );
    assert!(jobs >= 4 * 5 * 6, "ran {jobs} G-code jobs");
}

/// Plans one pattern on one machine and material and checks every job; the number of G-code
/// jobs run.
fn run_pattern(
    name: &str,
    cp: &CreasePattern,
    machine: &MachineProfile,
    material: &Material,
) -> usize {
    let two_sided = name == "miura";
    let (machine_name, material_name) = (&machine.name, &material.name);
    let p = plan(
        cp,
        machine,
        material,
        &options(machine, material, two_sided),
    )
    .unwrap_or_else(|e| panic!("{name} on {machine_name}/{material_name}: {e}"));
    let mut jobs = 0;
    for job in &p.jobs {
        let what = format!("{name} ({}) on {machine_name}/{material_name}", job.name);
        if !machine.emits_gcode() {
            let dxf = post::dxf(&p, job, DxfVersion::R2000).expect("DXF");
            let svg = post::svg(&p, job, &machine.bed, false).expect("SVG");
            assert_file_outputs_hold_the_job(&what, job, &dxf, svg.as_bytes(), machine);
            continue;
        }
        let gcode = post::gcode(&p, job, machine).expect("G-code");
        let run = sim::run(&gcode, machine).expect("readable");
        assert!(run.is_clean(), "{what}: {:?}", run.violations.first());
        let cov = sim::coverage(&run, cp, job, &p);
        assert!(
            cov.passed(),
            "{what}: {:?}, stray {:?}",
            cov.failed_edges().next(),
            cov.stray.first()
        );
        jobs += 1;
    }
    jobs
}

/// G-code jobs the matrix must run: for every G-code machine and material, one job per pattern
/// (two for the two-sided Miura-ori).
fn expected_gcode_jobs(patterns: &[(String, CreasePattern)]) -> usize {
    let gcode_machines = shipped_machines()
        .iter()
        .filter(|m| load_machine(m).expect("shipped").emits_gcode())
        .count();
    let per_pair: usize = patterns
        .iter()
        .map(|(n, _)| if n == "miura" { 2 } else { 1 })
        .sum();
    gcode_machines * shipped_materials().len() * per_pair
}

/// A random planar pattern on a lattice: creases of every kind and cut lines, with the sheet
/// outline as boundary.
fn random_pattern(cols: usize, rows: usize, pitch: f64, kinds: &[u8]) -> CreasePattern {
    let mut cp = CreasePattern::new();
    let p = |i: usize, j: usize| DVec2::new(i as f64 * pitch, j as f64 * pitch);
    let kind = |k: u8| match k % 6 {
        0 => None,
        1 => Some(Assignment::Mountain),
        2 => Some(Assignment::Valley),
        3 => Some(Assignment::Flat),
        4 => Some(Assignment::Cut),
        _ => Some(Assignment::Unassigned),
    };
    let mut k = kinds.iter().copied().cycle();
    for j in 0..=rows {
        for i in 0..cols {
            let edge = j == 0 || j == rows;
            let a = if edge {
                Some(Assignment::Boundary)
            } else {
                kind(k.next().unwrap_or(0))
            };
            if let Some(a) = a {
                cp.add_segment(p(i, j), p(i + 1, j), a);
            }
        }
    }
    for j in 0..rows {
        for i in 0..=cols {
            let edge = i == 0 || i == cols;
            let a = if edge {
                Some(Assignment::Boundary)
            } else {
                kind(k.next().unwrap_or(0))
            };
            if let Some(a) = a {
                cp.add_segment(p(i, j), p(i, j + 1), a);
            }
        }
    }
    for j in 0..rows {
        for i in 0..cols {
            if let Some(a) = kind(k.next().unwrap_or(0)) {
                cp.add_segment(p(i, j), p(i + 1, j + 1), a);
            }
        }
    }
    planarize(&mut cp, &PlanarizeOptions::default()).expect("planarises");
    cp
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    #[test]
    fn random_patterns_never_break_the_machine(
        cols in 1usize..6,
        rows in 1usize..6,
        pitch in 4.0f64..30.0,
        kinds in proptest::collection::vec(any::<u8>(), 1..40),
        machine_index in 0usize..4,
        two_sided in any::<bool>(),
    ) {
        let machines = ["grbl-diode", "marlin-laser", "linuxcnc-fiber", "grbl-pen-plotter"];
        let machine = load_machine(machines[machine_index]).expect("shipped");
        let material = load_material("stainless-0.5").expect("shipped");
        let cp = random_pattern(cols, rows, pitch, &kinds);
        let p = plan(&cp, &machine, &material, &options(&machine, &material, two_sided))
            .expect("plans");
        for job in &p.jobs {
            let gcode = post::gcode(&p, job, &machine).expect("G-code");
            prop_assert!(!gcode.contains("NaN") && !gcode.contains("inf"));
            let run = sim::run(&gcode, &machine).expect("readable");
            for kind in [ViolationKind::OutOfBed, ViolationKind::LitTravel] {
                prop_assert_eq!(run.violations_of(kind).count(), 0, "{:?}", run.violations.first());
            }
            prop_assert!(run.is_clean(), "{:?}", run.violations.first());
            // No lost cut geometry: every cut or boundary edge this job realises is cut.
            let cov = sim::coverage_with(&run, &cp, job, &p, &CoverageOptions::default());
            for e in &cov.edges {
                let assignment = cp.edges[e.edge.index()].assignment;
                if assignment.is_boundary_like() {
                    prop_assert!(e.ok, "cut edge {} burned {:.2} of {:.2}", e.edge, e.burned, e.planned);
                }
            }
            prop_assert!(cov.passed(), "{:?} stray {:?}", cov.failed_edges().next(), cov.stray.first());
        }
    }
}
