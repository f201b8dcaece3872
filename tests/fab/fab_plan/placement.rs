//! Placement on the bed, errors, one-sided plans.

use super::*;

#[test]
fn placement_keeps_random_extents_on_the_bed_for_every_origin() {
    let mut rng = Lcg(42);
    for _ in 0..200 {
        let lo = DVec2::new(rng.unit() * 2000.0 - 1000.0, rng.unit() * 2000.0 - 1000.0);
        let hi = lo + DVec2::new(rng.unit() * 390.0, rng.unit() * 290.0);
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
