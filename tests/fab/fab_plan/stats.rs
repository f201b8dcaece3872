//! Statistics and warnings.

use super::*;

/// Seconds to run `length` mm from rest to rest at `speed` mm/s with acceleration `accel`
/// mm/s²: a trapezoid (L/v + v/a) when the cruise speed is reached (L ≥ v²/a), else a
/// triangle (2 √(L/a)).
fn rest_to_rest(length: f64, speed: f64, accel: f64) -> f64 {
    if length >= speed * speed / accel {
        length / speed + speed / accel
    } else {
        2.0 * (length / accel).sqrt()
    }
}

#[test]
fn stats_match_lengths_pierces_travel_and_time_computed_by_hand() {
    // A 50 mm square cut twice around an L-shaped score: 30 mm right, then 30 mm up.
    let mut cp = CreasePattern::new();
    let c = [(0.0, 0.0), (50.0, 0.0), (50.0, 50.0), (0.0, 50.0)].map(|(x, y)| DVec2::new(x, y));
    let v: Vec<_> = c.iter().map(|&p| cp.add_vertex(p)).collect();
    for i in 0..4 {
        cp.add_edge(v[i], v[(i + 1) % 4], Assignment::Boundary);
    }
    let l = [(10.0, 10.0), (40.0, 10.0), (40.0, 40.0)].map(|(x, y)| DVec2::new(x, y));
    let lv: Vec<_> = l.iter().map(|&p| cp.add_vertex(p)).collect();
    let e1 = cp.add_edge(lv[0], lv[1], Assignment::Valley);
    let e2 = cp.add_edge(lv[1], lv[2], Assignment::Valley);
    let paths = vec![
        Toolpath {
            op: Operation::Score,
            strokes: vec![l.to_vec()],
            role: ContourRole::None,
            container: None,
            edges: vec![e1, e2],
        },
        Toolpath {
            op: Operation::Cut,
            strokes: vec![vec![c[0], c[1], c[2], c[3], c[0]]],
            role: ContourRole::Outer,
            container: None,
            edges: (0..4).map(EdgeId::new).collect(),
        },
    ];
    let mut mat = material();
    mat.settings.score = settings(600.0, 1); // 10 mm/s, once
    mat.settings.cut = settings(300.0, 2); // 5 mm/s, twice
    let mut opts = PlanOptions::from_material(&mat);
    opts.margin_mm = 0.0;
    // No junction deviation: the machine stops at every corner, so each move is a trapezoid
    // from rest to rest.
    let m = MachineProfile {
        acceleration_mm_s2: 100.0,
        junction_deviation_mm: 0.0,
        travel_feed_mm_min: 6000.0,
        ..machine(bed(Corner::BottomLeft, false))
    };
    let plan = plan_toolpaths(&cp, paths, &m, &mat, &opts).unwrap();
    let job = &plan.jobs[0];
    // The pattern sits in the bed's corner as drawn; the score comes first (cuts last) from
    // its end nearest the origin.
    assert_eq!(job.paths[0].strokes[0], l.to_vec());
    let cut = &job.paths[1].strokes[0];
    let cut_start = cut[0];
    assert!(c.contains(&cut_start) && cut.len() == 5, "{cut:?}");
    let s = &plan.stats;
    assert_eq!(
        s.length_mm,
        vec![(Operation::Score, 60.0), (Operation::Cut, 400.0)]
    );
    assert_eq!(s.pierces, 1 + 2);
    let to_score = 200f64.sqrt(); // (0, 0) to (10, 10)
    let to_cut = (l[2] - cut_start).length();
    assert!(
        (s.travel_mm - (to_score + to_cut)).abs() < 1e-9,
        "{}",
        s.travel_mm
    );
    let a = 100.0;
    // GRBL limits each axis: a travel along unit vector u runs and accelerates
    // 1 / max(|uₓ|, |u_y|) times faster (√2 on the diagonal to the score).
    let axis = |v: DVec2| {
        let u = v.normalize();
        1.0 / u.x.abs().max(u.y.abs())
    };
    let (k_score, k_cut) = (axis(DVec2::new(10.0, 10.0)), axis(l[2] - cut_start));
    let time = rest_to_rest(to_score, 100.0 * k_score, a * k_score)
        + 2.0 * rest_to_rest(30.0, 10.0, a)
        + rest_to_rest(to_cut, 100.0 * k_cut, a * k_cut)
        + 8.0 * rest_to_rest(50.0, 5.0, a);
    // By the numbers: 0.7521 + 2 × 3.1 + travel + 8 × 10.05 s.
    assert!((s.time_s - time).abs() < 1e-9, "{} vs {time}", s.time_s);
}

#[test]
fn design_limits_are_warned_about() {
    let mut cp = CreasePattern::new();
    let o = cp.add_vertex(DVec2::ZERO);
    let a = cp.add_vertex(DVec2::new(10.0, 0.0));
    let b = cp.add_vertex(DVec2::new(10.0, 0.5)); // about 2.9° from the first crease
    let m = cp.add_edge(o, a, Assignment::Mountain);
    cp.edges[m.index()].fold_angle = Some(-90.0);
    let flat = cp.add_edge(o, b, Assignment::Valley); // no stored angle: folded flat
    let c = cp.add_vertex(DVec2::new(0.0, 10.0));
    let e = cp.add_edge(o, c, Assignment::Valley);
    cp.edges[e.index()].fold_angle = Some(179.0);
    let w = design_limit_warnings(&cp, &material());
    assert_eq!(w.len(), 2, "{w:?}");
    assert!(
        w[0].text.starts_with("1 vertices") && w[0].text.contains("10°"),
        "{w:?}"
    );
    assert!(
        w[1].text.starts_with("2 edges")
            && w[1].text.contains("175°")
            && w[1].text.contains("1 of them"),
        "{w:?}"
    );
    // Typed, with the edges to ring: a crease of the narrow sector, the two far-folding ones.
    use foldcam::fab::PlanWarningKind::{FoldAngleLimit, VertexAngleLimit};
    assert_eq!((w[0].kind, w[1].kind), (VertexAngleLimit, FoldAngleLimit));
    assert!(
        w[0].edges.len() == 1 && [m, flat].contains(&w[0].edges[0]),
        "{w:?}"
    );
    let mut far = w[1].edges.clone();
    far.sort();
    assert_eq!(far, [flat, e]);
    let (clean, _) = sheet(100.0, DVec2::ZERO);
    let mut flat_folding = material();
    flat_folding.limits.max_fold_angle_deg = 180.0;
    assert!(design_limit_warnings(&clean, &flat_folding).is_empty());
}
