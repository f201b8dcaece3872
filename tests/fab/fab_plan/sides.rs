//! Two-sided jobs: mirroring, registration marks, the split.

use super::*;

#[test]
fn mirror_is_an_involution() {
    let m = mirror(37.5);
    let mut rng = Lcg(3);
    for _ in 0..100 {
        let p = DVec2::new(rng.unit() * 500.0 - 250.0, rng.unit() * 500.0);
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
fn hole_containers_point_at_their_contour_in_every_job() {
    let (cp, mut paths) = sheet(100.0, DVec2::ZERO);
    let ring = [
        (40.0, 40.0),
        (60.0, 40.0),
        (60.0, 60.0),
        (40.0, 60.0),
        (40.0, 40.0),
    ];
    paths.insert(
        0,
        Toolpath {
            op: Operation::Cut,
            strokes: vec![ring.iter().map(|&(x, y)| DVec2::new(x, y)).collect()],
            role: ContourRole::Hole,
            container: Some(3), // the outline, after this insertion
            edges: Vec::new(),
        },
    );
    for two_sided in [false, true] {
        let mut opts = PlanOptions::from_material(&material());
        opts.two_sided = two_sided;
        let m = machine(bed(Corner::TopRight, true));
        let plan = plan_toolpaths(&cp, paths.clone(), &m, &material(), &opts).unwrap();
        let job = plan.jobs.last().unwrap();
        let hole = job
            .paths
            .iter()
            .position(|p| p.role == ContourRole::Hole)
            .unwrap();
        let c = job.paths[hole].container.unwrap();
        assert_eq!(job.paths[c].role, ContourRole::Outer);
        assert!(hole < c);
    }
}
