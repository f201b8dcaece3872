//! Statistics and warnings.

use super::*;

#[test]
fn stats_sum_lengths_pierces_and_time_exactly() {
    let (cp, paths) = sheet(100.0, DVec2::ZERO);
    let mut opts = PlanOptions::from_material(&material());
    opts.margin_mm = 0.0;
    let mat = material();
    let m = machine(bed(Corner::BottomLeft, false));
    let plan = plan_toolpaths(&cp, paths, &m, &mat, &opts).unwrap();
    let s = &plan.stats;
    let diag = 100.0 * 2f64.sqrt();
    let want = [
        (Operation::Score, 100.0),
        (Operation::Perforate, diag),
        (Operation::Cut, 400.0 * 2.0),
    ];
    assert_eq!(s.length_mm.len(), 3);
    for (op, len) in want {
        let got = s.length_mm.iter().find(|(o, _)| *o == op).unwrap().1;
        assert!((got - len).abs() < 1e-9, "{op:?}: {got} vs {len}");
    }
    assert_eq!(s.pierces, 1 + 1 + 2);
    let job = &plan.jobs[0];
    let travel = foldcam::fab::order::travel_mm(&job.paths, DVec2::ZERO);
    assert!((s.travel_mm - travel).abs() < 1e-9);
    assert!(s.travel_mm <= s.naive_travel_mm + 1e-9);
    let t = job_time(DVec2::ZERO, &moves(&job.paths, &mat.settings), &m);
    assert!((s.time_s - t).abs() < 1e-9 && t > 0.0);
    // Every length at its speed, passes included, plus travel at the travel feed, is a lower
    // bound whatever the motion model adds (acceleration, cornering, pierce delays).
    let burn: f64 = 100.0 / 3000.0 * 60.0 + diag / 1200.0 * 60.0 + 800.0 / 600.0 * 60.0;
    assert!(t >= burn + travel / 6000.0 * 60.0 - 1e-9, "{t} < {burn}");
}

#[test]
fn open_strokes_repeat_backwards_without_travel() {
    let mut mat = material();
    mat.settings.score.passes = 3;
    let p = Toolpath {
        op: Operation::Score,
        strokes: vec![vec![
            DVec2::new(0.0, 0.0),
            DVec2::new(10.0, 0.0),
            DVec2::new(10.0, 5.0),
        ]],
        role: ContourRole::None,
        container: None,
        edges: Vec::new(),
    };
    let mv = moves(std::slice::from_ref(&p), &mat.settings);
    assert_eq!(mv.iter().filter(|m| m.rapid).count(), 1);
    let burned: f64 = mv.windows(2).map(|w| w[0].to.distance(w[1].to)).sum();
    assert!((burned - 3.0 * stroke_length(&p.strokes[0])).abs() < 1e-9);
}

#[test]
fn design_limits_are_warned_about() {
    let mut cp = CreasePattern::new();
    let o = cp.add_vertex(DVec2::ZERO);
    let a = cp.add_vertex(DVec2::new(10.0, 0.0));
    let b = cp.add_vertex(DVec2::new(10.0, 0.5)); // about 2.9° from the first crease
    let m = cp.add_edge(o, a, Assignment::Mountain);
    cp.edges[m.index()].fold_angle = Some(-90.0);
    cp.add_edge(o, b, Assignment::Valley); // no stored angle: folded flat
    let c = cp.add_vertex(DVec2::new(0.0, 10.0));
    let e = cp.add_edge(o, c, Assignment::Valley);
    cp.edges[e.index()].fold_angle = Some(179.0);
    let w = design_limit_warnings(&cp, &material());
    assert_eq!(w.len(), 2, "{w:?}");
    assert!(
        w[0].starts_with("1 vertices") && w[0].contains("10°"),
        "{w:?}"
    );
    assert!(
        w[1].starts_with("2 edges") && w[1].contains("175°") && w[1].contains("1 of them"),
        "{w:?}"
    );
    let (clean, _) = sheet(100.0, DVec2::ZERO);
    let mut flat_folding = material();
    flat_folding.limits.max_fold_angle_deg = 180.0;
    assert!(design_limit_warnings(&clean, &flat_folding).is_empty());
}
