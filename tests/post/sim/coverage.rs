//! Coverage: a hand-built 40 mm square with one perforated crease, planned as a job, written
//! as G-code by a tiny test writer, and checked for missing cuts, perforations and strays.

use super::*;

const CUT_S: f64 = 1000.0;
const PERF_S: f64 = 600.0;
const KERF: f64 = 0.2;

fn settings(power: f64) -> OperationSettings {
    OperationSettings {
        speed_mm_min: 1200.0,
        power,
        passes: 1,
    }
}

/// A 40 × 40 mm sheet (edges 0–3 the outline) with a valley (edge 4) across at y = 20.
fn pattern() -> CreasePattern {
    let mut cp = CreasePattern::new();
    let p = |x: f64, y: f64| DVec2::new(x, y);
    let v: Vec<_> = [p(0.0, 0.0), p(40.0, 0.0), p(40.0, 40.0), p(0.0, 40.0)]
        .into_iter()
        .map(|q| cp.add_vertex(q))
        .collect();
    for i in 0..4 {
        cp.add_edge(v[i], v[(i + 1) % 4], Assignment::Boundary);
    }
    let (a, b) = (cp.add_vertex(p(0.0, 20.0)), cp.add_vertex(p(40.0, 20.0)));
    cp.add_edge(a, b, Assignment::Valley);
    cp
}

/// The pattern placed at (10, 10): perforation dashes of 4 mm with 2 mm bridges (1 mm
/// clearance at the start, 60 % duty), then the outline offset by half the kerf.
fn job() -> Setup {
    let to_machine = DAffine2::from_translation(DVec2::new(10.0, 10.0));
    let dashes = (0..6)
        .map(|k| {
            let x = 11.0 + 6.0 * f64::from(k);
            vec![DVec2::new(x, 30.0), DVec2::new(x + 4.0, 30.0)]
        })
        .collect();
    let (lo, hi) = (10.0 - KERF / 2.0, 50.0 + KERF / 2.0);
    let outline = [(lo, lo), (hi, lo), (hi, hi), (lo, hi), (lo, lo)]
        .map(|(x, y)| DVec2::new(x, y))
        .to_vec();
    let path = |op, strokes, role, edges: Vec<u32>| Toolpath {
        op,
        strokes,
        role,
        container: None,
        edges: edges.into_iter().map(EdgeId).collect(),
    };
    Setup {
        name: "front".into(),
        side: Side::Front,
        to_machine,
        paths: vec![
            path(Operation::Perforate, dashes, ContourRole::None, vec![4]),
            path(
                Operation::Cut,
                vec![outline],
                ContourRole::Outer,
                vec![0, 1, 2, 3],
            ),
        ],
    }
}

fn plan(job: Setup) -> FabPlan {
    FabPlan {
        jobs: vec![job],
        settings: SettingsByOperation {
            cut: settings(1.0),
            perforate: settings(PERF_S / 1000.0),
            score: settings(0.3),
            mark: settings(0.1),
            plot: settings(0.0),
        },
        about: Default::default(),
        stats: PlanStats::default(),
        warnings: Vec::new(),
        // Nothing beyond the job's own toolpaths is expected.
        mapping: foldcam::machine::OperationMapping {
            mountain: None,
            valley: None,
            unassigned: None,
            flat: None,
            boundary: None,
        },
        overrides: Vec::new(),
    }
}

/// A minimal GRBL writer for the test: M4 once, each stroke as G0 then G1 with inline S.
fn gcode(job: &Setup) -> String {
    let mut out = vec!["G21 G90".to_string(), "M4 S0".to_string()];
    for tp in &job.paths {
        let s = if tp.op == Operation::Cut {
            CUT_S
        } else {
            PERF_S
        };
        for stroke in &tp.strokes {
            out.push(format!("G0 X{:.3} Y{:.3}", stroke[0].x, stroke[0].y));
            for p in &stroke[1..] {
                out.push(format!("G1 X{:.3} Y{:.3} F1200 S{s}", p.x, p.y));
            }
        }
    }
    out.extend(["M5".into(), "G0 X0 Y0".into(), "M2".into()]);
    out.join("\n")
}

fn check(written: &Setup) -> sim::CoverageReport {
    let report = run(&gcode(written), &laser(Dialect::Grbl));
    assert!(report.is_clean(), "{:?}", report.violations);
    sim::coverage(&report, &pattern(), &job(), &plan(job()))
}

#[test]
fn the_planned_job_covers_the_pattern() {
    let c = check(&job());
    assert!(c.passed(), "{:?}", c);
    assert!(
        (c.kerf_mm - KERF).abs() < 1e-9,
        "kerf estimated from the contour"
    );
    assert_eq!(c.edges.len(), 5);
    let crease = c.edges.iter().find(|e| e.edge == EdgeId(4)).unwrap();
    assert!((crease.planned - 0.6).abs() < 1e-9 && (crease.burned - 0.6).abs() < 1e-9);
    assert!(
        c.edges
            .iter()
            .filter(|e| e.op == Operation::Cut)
            .all(|e| e.burned > 0.999)
    );
}

#[test]
fn a_missing_cut_is_found() {
    let mut j = job();
    // Cut only three sides of the outline.
    j.paths[1].strokes[0].pop();
    let c = check(&j);
    let failed: Vec<EdgeId> = c.failed_edges().map(|e| e.edge).collect();
    assert_eq!(failed, vec![EdgeId(3)]);
    assert!(c.stray.is_empty());
}

#[test]
fn a_short_cut_is_found() {
    let mut j = job();
    // Stop the last side 2 mm early: 95 % of that edge.
    j.paths[1].strokes[0][4].y += 2.0;
    let c = check(&j);
    let failed: Vec<EdgeId> = c.failed_edges().map(|e| e.edge).collect();
    assert_eq!(failed, vec![EdgeId(3)]);
}

#[test]
fn a_missing_perforation_is_found() {
    let mut j = job();
    j.paths[0].strokes.truncate(3);
    let c = check(&j);
    let failed: Vec<(EdgeId, Operation)> = c.failed_edges().map(|e| (e.edge, e.op)).collect();
    assert_eq!(failed, vec![(EdgeId(4), Operation::Perforate)]);
}

#[test]
fn a_stray_burn_is_found() {
    let mut j = job();
    j.paths.push(Toolpath {
        op: Operation::Cut,
        strokes: vec![vec![DVec2::new(20.0, 20.0), DVec2::new(40.0, 20.0)]],
        role: ContourRole::Slit,
        container: None,
        edges: Vec::new(),
    });
    let c = check(&j);
    assert!(c.edges.iter().all(|e| e.ok));
    assert_eq!(c.stray.len(), 1);
    assert!(
        (c.stray_length_mm - 20.0).abs() < 0.5,
        "{}",
        c.stray_length_mm
    );
}

#[test]
fn a_crease_burned_at_cut_power_is_wrong() {
    let mut j = job();
    j.paths[0].op = Operation::Cut; // the writer now burns the dashes at cut power
    let c = check(&j);
    assert!(!c.passed());
    assert!(c.failed_edges().any(|e| e.edge == EdgeId(4)));
    assert!(
        !c.stray.is_empty(),
        "the dashes are not where any cut edge is"
    );
}

#[test]
fn burns_map_back_to_operations() {
    let report = run(&gcode(&job()), &laser(Dialect::Grbl));
    let by_op = report.burn_by_operation(&plan(job()).settings, 0.02);
    assert_eq!(by_op.len(), 2);
    assert_eq!(by_op[0].0, Some(Operation::Perforate));
    assert!((by_op[0].1 - 24.0).abs() < 1e-9);
    assert_eq!(by_op[1].0, Some(Operation::Cut));
    assert!((by_op[1].1 - 4.0 * (40.0 + KERF)).abs() < 1e-9);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// Any burns: shares stay within 0..=1 and the stray length within the burn length.
    #[test]
    fn coverage_of_random_burns_is_bounded(
        segs in prop::collection::vec((0.0..300.0f64, 0.0..200.0f64, 0.0..1000.0f64), 1..40)
    ) {
        let mut text = String::from("M4 S0\nG1 F1200\n");
        for (x, y, s) in &segs {
            text.push_str(&format!("G1 X{x:.3} Y{y:.3} S{s:.0}\n"));
        }
        text.push_str("M5\nM2\n");
        let report = run(&text, &laser(Dialect::Grbl));
        let c = sim::coverage(&report, &pattern(), &job(), &plan(job()));
        for e in &c.edges {
            prop_assert!((0.0..=1.0).contains(&e.burned) && (0.0..=1.0).contains(&e.planned));
        }
        prop_assert!(c.stray_length_mm <= report.burn_length_mm + 1e-9);
    }
}
