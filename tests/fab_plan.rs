//! The plan: placement on the bed, two-sided jobs, statistics, errors and warnings.

use foldcam::fab::placement::{bed_to_machine, bounds_of, place};
use foldcam::fab::plan::{design_limit_warnings, plan_toolpaths};
use foldcam::fab::sides::{mirror, registration_marks, split};
use foldcam::fab::stats::{moves, stroke_length};
use foldcam::fab::{ContourRole, FabError, Operation, PlanOptions, Side, Toolpath};
use foldcam::machine::motion::job_time;
use foldcam::machine::{
    Bed, Corner, DesignLimits, Dialect, DwellUnit, LaserMode, MachineKind, MachineProfile,
    Material, OperationMapping, OperationSettings, Perforation, PowerRange, SettingsByOperation,
};
use foldcam::pattern::{Assignment, CreasePattern, EdgeId, Units};
use glam::DVec2;

const CORNERS: [Corner; 4] = [
    Corner::BottomLeft,
    Corner::TopLeft,
    Corner::BottomRight,
    Corner::TopRight,
];

struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn bed(origin: Corner, y_flipped: bool) -> Bed {
    Bed {
        width_mm: 400.0,
        height_mm: 300.0,
        origin,
        y_flipped,
    }
}

fn machine(bed: Bed) -> MachineProfile {
    MachineProfile {
        name: "test".into(),
        description: "test laser".into(),
        kind: MachineKind::Laser,
        dialect: Dialect::Grbl,
        bed,
        max_feed_mm_min: 6000.0,
        travel_feed_mm_min: 6000.0,
        acceleration_mm_s2: 1000.0,
        junction_deviation_mm: 0.01,
        power: PowerRange {
            min: 0.0,
            max: 1000.0,
        },
        laser_mode: LaserMode::Dynamic,
        dwell_unit: DwellUnit::Seconds,
        resolution_mm: 0.001,
        pen_up: Vec::new(),
        pen_down: Vec::new(),
        pen_delay_s: 0.0,
        preamble: Vec::new(),
        postamble: Vec::new(),
    }
}

fn settings(speed_mm_min: f64, passes: u32) -> OperationSettings {
    OperationSettings {
        speed_mm_min,
        power: 0.5,
        passes,
    }
}

fn material() -> Material {
    Material {
        name: "card".into(),
        description: "test card".into(),
        thickness_mm: 0.3,
        kerf_mm: 0.1,
        settings: SettingsByOperation {
            cut: settings(600.0, 2),
            perforate: settings(1200.0, 1),
            score: settings(3000.0, 1),
            mark: settings(3000.0, 1),
            plot: settings(2000.0, 1),
        },
        perforation: Perforation {
            cut_mm: 2.0,
            bridge_mm: 1.0,
            min_dash_mm: 0.5,
            min_web_mm: 0.5,
            vertex_clearance_mm: 1.0,
        },
        mapping: OperationMapping {
            mountain: Some(Operation::Perforate),
            valley: Some(Operation::Score),
            unassigned: Some(Operation::Score),
            flat: None,
            boundary: Some(Operation::Cut),
        },
        limits: DesignLimits {
            min_vertex_angle_deg: 10.0,
            max_fold_angle_deg: 175.0,
        },
    }
}

/// A square sheet with a mountain and a valley crease and its outline, and the matching
/// toolpaths (what the geometry would produce, in pattern coordinates).
fn sheet(size: f64, at: DVec2) -> (CreasePattern, Vec<Toolpath>) {
    let mut cp = CreasePattern::new();
    let c = [DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y].map(|p| at + p * size);
    let v: Vec<_> = c.iter().map(|&p| cp.add_vertex(p)).collect();
    for i in 0..4 {
        cp.add_edge(v[i], v[(i + 1) % 4], Assignment::Boundary);
    }
    let m = cp.add_edge(v[0], v[2], Assignment::Mountain);
    let mid = [
        at + DVec2::new(0.0, size / 2.0),
        at + DVec2::new(size, size / 2.0),
    ];
    let ma = cp.add_vertex(mid[0]);
    let mb = cp.add_vertex(mid[1]);
    let val = cp.add_edge(ma, mb, Assignment::Valley);
    let crease = |op, a: DVec2, b: DVec2, e: EdgeId| Toolpath {
        op,
        strokes: vec![vec![a, b]],
        role: ContourRole::None,
        container: None,
        edges: vec![e],
    };
    let outline = Toolpath {
        op: Operation::Cut,
        strokes: vec![vec![c[0], c[1], c[2], c[3], c[0]]],
        role: ContourRole::Outer,
        container: None,
        edges: (0..4).map(EdgeId::new).collect(),
    };
    let paths = vec![
        crease(Operation::Perforate, c[0], c[2], m),
        crease(Operation::Score, mid[0], mid[1], val),
        outline,
    ];
    (cp, paths)
}

fn all_points(paths: &[Toolpath]) -> Vec<DVec2> {
    paths
        .iter()
        .flat_map(|p| &p.strokes)
        .flatten()
        .copied()
        .collect()
}

fn inside_bed(p: DVec2, bed: &Bed) -> bool {
    let eps = 1e-9;
    p.x >= -eps && p.y >= -eps && p.x <= bed.width_mm + eps && p.y <= bed.height_mm + eps
}

#[test]
fn placement_keeps_random_extents_on_the_bed_for_every_origin() {
    let mut rng = Lcg(42);
    for _ in 0..200 {
        let lo = DVec2::new(rng.next() * 2000.0 - 1000.0, rng.next() * 2000.0 - 1000.0);
        let hi = lo + DVec2::new(rng.next() * 390.0, rng.next() * 290.0);
        for origin in CORNERS {
            for flip in [false, true] {
                let b = bed(origin, flip);
                let t = place((lo, hi), &b, 5.0);
                let Ok(t) = t else {
                    let need = hi - lo + 10.0;
                    assert!(need.x > 400.0 || need.y > 300.0, "{lo} {hi} rejected");
                    continue;
                };
                for p in [lo, hi, DVec2::new(lo.x, hi.y), DVec2::new(hi.x, lo.y)] {
                    let m = t.transform_point2(p);
                    assert!(
                        inside_bed(m, &b),
                        "{p} → {m} off the bed ({origin:?}, {flip})"
                    );
                }
                // A rigid placement: lengths are kept.
                let d = t.transform_point2(hi).distance(t.transform_point2(lo));
                assert!((d - lo.distance(hi)).abs() < 1e-9);
            }
        }
    }
}

#[test]
fn placement_sits_in_the_origin_corner_with_the_margin() {
    let extent = (DVec2::new(-20.0, 7.0), DVec2::new(80.0, 57.0));
    for origin in CORNERS {
        for flip in [false, true] {
            let b = bed(origin, flip);
            let to_bed = bed_to_machine(&b).inverse() * place(extent, &b, 5.0).unwrap();
            let lo = to_bed.transform_point2(extent.0);
            let hi = to_bed.transform_point2(extent.1);
            let right = matches!(origin, Corner::BottomRight | Corner::TopRight);
            let top = matches!(origin, Corner::TopLeft | Corner::TopRight);
            let gap_x = if right { 400.0 - hi.x } else { lo.x };
            let gap_y = if top { 300.0 - hi.y } else { lo.y };
            assert!(
                (gap_x - 5.0).abs() < 1e-9 && (gap_y - 5.0).abs() < 1e-9,
                "{origin:?}"
            );
            // The drawing keeps its orientation in the bed view.
            assert!(hi.x > lo.x && hi.y > lo.y);
        }
    }
}

#[test]
fn machine_frame_flips_follow_the_profile() {
    let p = DVec2::new(10.0, 20.0);
    let at = |origin, flip| bed_to_machine(&bed(origin, flip)).transform_point2(p);
    assert_eq!(at(Corner::BottomLeft, false), p);
    assert_eq!(at(Corner::TopLeft, true), DVec2::new(10.0, 280.0));
    assert_eq!(at(Corner::BottomRight, false), DVec2::new(390.0, 20.0));
    assert_eq!(at(Corner::TopRight, true), DVec2::new(390.0, 280.0));
}

#[test]
fn too_large_patterns_do_not_fit() {
    let b = bed(Corner::BottomLeft, false);
    let err = place((DVec2::ZERO, DVec2::new(395.0, 100.0)), &b, 5.0).unwrap_err();
    assert_eq!(
        err,
        FabError::DoesNotFit {
            width: 405.0,
            height: 110.0,
            bed_width: 400.0,
            bed_height: 300.0
        }
    );
    assert!(place((DVec2::ZERO, DVec2::new(390.0, 290.0)), &b, 5.0).is_ok());
    let (cp, paths) = sheet(500.0, DVec2::ZERO);
    let opts = PlanOptions::from_material(&material());
    let r = plan_toolpaths(&cp, paths, &machine(b), &material(), &opts);
    assert!(matches!(r, Err(FabError::DoesNotFit { .. })));
}

#[test]
fn unitless_patterns_and_empty_work_are_errors() {
    let (mut cp, paths) = sheet(100.0, DVec2::ZERO);
    let m = machine(bed(Corner::BottomLeft, false));
    let opts = PlanOptions::from_material(&material());
    let r = plan_toolpaths(&cp, Vec::new(), &m, &material(), &opts);
    assert_eq!(r.unwrap_err(), FabError::NothingToDo);
    cp.units = Units::Unitless;
    let r = plan_toolpaths(&cp, paths, &m, &material(), &opts);
    assert!(matches!(r, Err(FabError::Unitless(_))));
    let r = foldcam::fab::plan(&cp, &m, &material(), &opts);
    assert!(matches!(r, Err(FabError::Unitless(_))));
}

#[test]
fn one_sided_plans_stay_on_the_bed_for_every_origin() {
    let (cp, paths) = sheet(120.0, DVec2::new(-300.0, 40.0));
    let opts = PlanOptions::from_material(&material());
    for origin in CORNERS {
        for flip in [false, true] {
            let m = machine(bed(origin, flip));
            let plan = plan_toolpaths(&cp, paths.clone(), &m, &material(), &opts).unwrap();
            assert_eq!(plan.jobs.len(), 1);
            let job = &plan.jobs[0];
            assert_eq!((job.name.as_str(), job.side), ("front", Side::Front));
            assert!(
                all_points(&job.paths)
                    .iter()
                    .all(|&p| inside_bed(p, &m.bed))
            );
            // Every stroke point is the transform of a pattern point.
            let inv = job.to_machine.inverse();
            let pattern_pts = all_points(&paths);
            for q in all_points(&job.paths) {
                let back = inv.transform_point2(q);
                assert!(pattern_pts.iter().any(|p| p.distance(back) < 1e-9));
            }
            assert_eq!(job.paths.last().unwrap().role, ContourRole::Outer);
        }
    }
}

#[test]
fn mirror_is_an_involution() {
    let m = mirror(37.5);
    let mut rng = Lcg(3);
    for _ in 0..100 {
        let p = DVec2::new(rng.next() * 500.0 - 250.0, rng.next() * 500.0);
        assert!((m * m).transform_point2(p).distance(p) < 1e-9);
        assert_eq!(m.transform_point2(p).y, p.y);
    }
    assert_eq!(
        m.transform_point2(DVec2::new(37.5, 1.0)),
        DVec2::new(37.5, 1.0)
    );
}

#[test]
fn registration_marks_are_outside_and_asymmetric() {
    let extent = (DVec2::ZERO, DVec2::new(100.0, 60.0));
    let marks = registration_marks(extent);
    assert_eq!(marks.len(), 3);
    for p in all_points(&marks) {
        let inside = p.x > 0.0 && p.x < 100.0 && p.y > 0.0 && p.y < 60.0;
        assert!(!inside);
    }
    // Flipping about the vertical centre line does not map the set onto itself…
    let m = mirror(50.0);
    let centres: Vec<DVec2> = marks
        .iter()
        .map(|t| (t.strokes[0][0] + t.strokes[0][1]) / 2.0)
        .collect();
    let mirrored: Vec<DVec2> = centres.iter().map(|&c| m.transform_point2(c)).collect();
    assert!(
        mirrored
            .iter()
            .any(|c| !centres.iter().any(|d| d.distance(*c) < 1e-9))
    );
    // …nor does a flip about the horizontal one.
    let flipped: Vec<DVec2> = centres
        .iter()
        .map(|c| DVec2::new(c.x, 60.0 - c.y))
        .collect();
    assert!(
        flipped
            .iter()
            .any(|c| !centres.iter().any(|d| d.distance(*c) < 1e-9))
    );
}

#[test]
fn split_puts_valleys_and_cuts_on_the_back() {
    let (cp, paths) = sheet(100.0, DVec2::ZERO);
    let (front, back) = split(&cp, paths);
    assert_eq!(
        front.iter().map(|p| p.op).collect::<Vec<_>>(),
        [Operation::Perforate]
    );
    assert_eq!(
        back.iter().map(|p| p.op).collect::<Vec<_>>(),
        [Operation::Score, Operation::Cut]
    );
}

#[test]
fn two_sided_jobs_line_up_after_turning_the_sheet() {
    let (cp, paths) = sheet(100.0, DVec2::new(10.0, 10.0));
    let mut opts = PlanOptions::from_material(&material());
    opts.two_sided = true;
    for origin in CORNERS {
        for flip in [false, true] {
            let m = machine(bed(origin, flip));
            let plan = plan_toolpaths(&cp, paths.clone(), &m, &material(), &opts).unwrap();
            let [front, back] = &plan.jobs[..] else {
                panic!("two jobs expected")
            };
            assert_eq!((front.side, back.side), (Side::Front, Side::Back));
            for job in [front, back] {
                assert!(
                    all_points(&job.paths)
                        .iter()
                        .all(|&p| inside_bed(p, &m.bed))
                );
                assert_eq!(
                    job.paths.iter().filter(|p| p.op == Operation::Mark).count(),
                    3
                );
            }
            assert!(back.paths.iter().any(|p| p.op == Operation::Cut));
            assert!(front.paths.iter().all(|p| p.op != Operation::Cut));
            // Turning the sheet over is the reflection about the sheet's vertical centre
            // line; in machine coordinates it is back ∘ front⁻¹. A back mark must then land
            // on a front mark.
            let turn = |q: DVec2| {
                let flip = back.to_machine * front.to_machine.inverse();
                flip.transform_point2(q)
            };
            let front_marks: Vec<DVec2> = front
                .paths
                .iter()
                .filter(|p| p.op == Operation::Mark)
                .flat_map(|p| p.strokes.iter().flatten().copied())
                .collect();
            for q in back
                .paths
                .iter()
                .filter(|p| p.op == Operation::Mark)
                .flat_map(|p| p.strokes.iter().flatten())
            {
                let physical = turn(*q);
                assert!(
                    front_marks.iter().any(|f| f.distance(physical) < 1e-9),
                    "{q} off the marks"
                );
            }
            let pattern_pts = all_points(&paths);
            for q in all_points(&back.paths) {
                let p = back.to_machine.inverse().transform_point2(q);
                let on_pattern = pattern_pts.iter().any(|x| x.distance(p) < 1e-9);
                let on_marks = bounds_of(&paths)
                    .is_some_and(|(lo, hi)| p.x < lo.x || p.y < lo.y || p.x > hi.x || p.y > hi.y);
                assert!(on_pattern || on_marks);
            }
            // The back job is a mirror image: its transform reverses orientation relative to
            // the front's.
            let det = |a: glam::DAffine2| a.matrix2.determinant();
            assert!((det(front.to_machine) * det(back.to_machine) + 1.0).abs() < 1e-12);
        }
    }
}

#[test]
fn physical_flip_maps_back_marks_onto_front_marks() {
    // The same check in machine terms: x ↦ 2·c − x about the sheet centre's machine x.
    let (cp, paths) = sheet(80.0, DVec2::ZERO);
    let mut opts = PlanOptions::from_material(&material());
    opts.two_sided = true;
    let m = machine(bed(Corner::BottomLeft, false));
    let plan = plan_toolpaths(&cp, paths, &m, &material(), &opts).unwrap();
    let marks = |i: usize| -> Vec<DVec2> {
        plan.jobs[i]
            .paths
            .iter()
            .filter(|p| p.op == Operation::Mark)
            .flat_map(|p| p.strokes.iter().flatten().copied())
            .collect()
    };
    let (f, b) = (marks(0), marks(1));
    let (lo, hi) = f
        .iter()
        .fold((f[0], f[0]), |(l, h), &p| (l.min(p), h.max(p)));
    let c = (lo.x + hi.x) / 2.0;
    for q in &b {
        let turned = DVec2::new(2.0 * c - q.x, q.y);
        assert!(f.iter().any(|p| p.distance(turned) < 1e-9));
    }
    assert_ne!(f, b, "marks must not be symmetric");
}

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
    // Burn time alone: every length at its speed, passes included.
    let burn: f64 = 100.0 / 3000.0 * 60.0 + diag / 1200.0 * 60.0 + 800.0 / 600.0 * 60.0;
    assert!(t > burn && t < burn + travel / 6000.0 * 60.0 + 1e-9);
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
    cp.add_edge(o, a, Assignment::Mountain);
    cp.add_edge(o, b, Assignment::Valley);
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
        w[1].starts_with("1 edges") && w[1].contains("175°"),
        "{w:?}"
    );
    let (clean, _) = sheet(100.0, DVec2::ZERO);
    assert!(design_limit_warnings(&clean, &material()).is_empty());
}
