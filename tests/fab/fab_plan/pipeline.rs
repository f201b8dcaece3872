//! `plan_toolpaths` on a real pattern (the Miura-ori) with simple hand-built toolpaths: one
//! straight toolpath per edge, as the geometry would give without perforation or kerf.

use super::*;
use foldcam::design::classic::MiuraOri;
use foldcam::fab::FabPlan;

/// One toolpath per edge with the material's operation; boundary segments are cut slits.
fn edge_toolpaths(cp: &CreasePattern, mapping: &OperationMapping) -> Vec<Toolpath> {
    cp.edge_ids()
        .filter_map(|e| {
            let (a, b) = cp.segment(e);
            let (op, role) = match cp.edges[e.index()].assignment {
                Assignment::Mountain => (mapping.mountain?, ContourRole::None),
                Assignment::Valley => (mapping.valley?, ContourRole::None),
                Assignment::Boundary | Assignment::Cut => (mapping.boundary?, ContourRole::Slit),
                _ => return None,
            };
            Some(Toolpath {
                op,
                strokes: vec![vec![a, b]],
                role,
                container: None,
                edges: vec![e],
            })
        })
        .collect()
}

fn miura_plan(two_sided: bool, origin: Corner, flip: bool) -> (CreasePattern, FabPlan) {
    let cp = MiuraOri::default().build().unwrap();
    let mat = material();
    let mut opts = PlanOptions::from_material(&mat);
    opts.two_sided = two_sided;
    let paths = edge_toolpaths(&cp, &mat.mapping);
    let m = machine(bed(origin, flip));
    let plan = plan_toolpaths(&cp, paths, &m, &mat, &opts).unwrap();
    (cp, plan)
}

/// Every edge that maps to an operation appears exactly once over all jobs.
fn assert_edges_covered_once(cp: &CreasePattern, plan: &FabPlan) {
    let mut seen = vec![0; cp.edges.len()];
    for e in plan
        .jobs
        .iter()
        .flat_map(|j| &j.paths)
        .flat_map(|p| &p.edges)
    {
        seen[e.index()] += 1;
    }
    assert!(seen.iter().all(|&c| c == 1), "{seen:?}");
}

#[test]
fn miura_plans_on_every_bed_one_and_two_sided() {
    for two_sided in [false, true] {
        for origin in CORNERS {
            for flip in [false, true] {
                let (cp, plan) = miura_plan(two_sided, origin, flip);
                assert_eq!(plan.jobs.len(), if two_sided { 2 } else { 1 });
                assert_edges_covered_once(&cp, &plan);
                let b = bed(origin, flip);
                for job in &plan.jobs {
                    assert!(all_points(&job.paths).iter().all(|&p| inside_bed(p, &b)));
                }
                let s = &plan.stats;
                assert!(s.travel_mm < s.naive_travel_mm, "{s:?}");
                assert!(s.time_s > 0.0);
                // The Miura-ori's creases carry the generators' 170°, within the card's 180°:
                // no design limit is exceeded.
                assert!(
                    cp.edges
                        .iter()
                        .filter(|e| e.assignment.is_fold())
                        .all(|e| e.fold_angle.is_some_and(|a| a.abs() <= 175.0))
                );
                assert!(plan.warnings.is_empty(), "{:?}", plan.warnings);
            }
        }
    }
}

#[test]
fn miura_two_sided_puts_valleys_on_the_back() {
    let (cp, plan) = miura_plan(true, Corner::BottomLeft, false);
    let assignment = |e: &EdgeId| cp.edges[e.index()].assignment;
    let front = &plan.jobs[0];
    let back = &plan.jobs[1];
    assert!(
        front
            .paths
            .iter()
            .flat_map(|p| &p.edges)
            .all(|e| assignment(e) == Assignment::Mountain)
    );
    assert!(
        back.paths
            .iter()
            .flat_map(|p| &p.edges)
            .all(|e| assignment(e) != Assignment::Mountain)
    );
    // Cuts come last: the sheet holds the part until the end.
    let first_cut = back
        .paths
        .iter()
        .position(|p| p.op == Operation::Cut)
        .unwrap();
    assert!(
        back.paths[first_cut..]
            .iter()
            .all(|p| p.op == Operation::Cut)
    );
    // Each back point, turned over with the sheet, lies on its pattern edge.
    for p in back.paths.iter().filter(|p| p.op != Operation::Mark) {
        for q in p.strokes.iter().flatten() {
            let at = back.to_machine.inverse().transform_point2(*q);
            let on_edge = p.edges.iter().any(|&e| {
                let (a, b) = cp.segment(e);
                (a.distance(at) + at.distance(b) - a.distance(b)).abs() < 1e-6
            });
            assert!(on_edge, "{q} is not on its edge");
        }
    }
}

#[test]
fn miura_outline_is_joined_into_few_strokes() {
    let (cp, plan) = miura_plan(false, Corner::BottomLeft, false);
    let boundary = cp
        .edges
        .iter()
        .filter(|e| e.assignment == Assignment::Boundary)
        .count();
    let cut_strokes: usize = plan.jobs[0]
        .paths
        .iter()
        .filter(|p| p.op == Operation::Cut)
        .map(|p| p.strokes.len())
        .sum();
    assert!(
        cut_strokes * 4 <= boundary,
        "{cut_strokes} strokes for {boundary} edges"
    );
    // Pierces count strokes × passes (cuts take two passes here).
    let expected: usize = plan.jobs[0]
        .paths
        .iter()
        .map(|p| p.strokes.len() * if p.op == Operation::Cut { 2 } else { 1 })
        .sum();
    assert_eq!(plan.stats.pierces, expected);
}
