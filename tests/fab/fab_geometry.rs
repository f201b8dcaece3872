//! Fabrication geometry on whole patterns: contour classification and nesting, kerf offset
//! toward the scrap, slits, tabs, lead-ins, the operation mapping, coverage of every cut edge,
//! and a Miura-ori.

use crate::fab_common;

use fab_common::{
    area, assert_cut_edges_covered, bounds, is_closed, options, polygon, square, with_role,
};
use foldcam::design::classic::MiuraOri;
use foldcam::fab::{ContourRole, FabError, Operation, PlanOptions, Tabs, Toolpath};
use foldcam::fab::{toolpaths, toolpaths_with_warnings};
use foldcam::geom::contains_point;
use foldcam::pattern::{Assignment, CreasePattern, Units};
use glam::DVec2;

/// A 100 mm square sheet with a 20 mm square hole in the middle and a 20 mm slit near the
/// bottom left.
fn sheet_with_hole_and_slit() -> CreasePattern {
    let mut cp = CreasePattern::new();
    polygon(&mut cp, &square(0.0, 100.0), Assignment::Boundary);
    polygon(&mut cp, &square(40.0, 60.0), Assignment::Boundary);
    cp.add_segment(
        DVec2::new(10.0, 10.0),
        DVec2::new(30.0, 10.0),
        Assignment::Cut,
    );
    cp
}

#[test]
fn outer_hole_and_slit_are_classified() {
    let cp = sheet_with_hole_and_slit();
    let paths = toolpaths(&cp, &options()).unwrap();
    let outer = with_role(&paths, ContourRole::Outer);
    let holes = with_role(&paths, ContourRole::Hole);
    let slits = with_role(&paths, ContourRole::Slit);
    assert_eq!((outer.len(), holes.len(), slits.len()), (1, 1, 1));
    assert_eq!(paths.len(), 3);
    assert_eq!(outer[0].1.container, None);
    assert_eq!(holes[0].1.container, Some(outer[0].0));
    assert_eq!(outer[0].1.edges.len(), 4);
    assert_eq!(holes[0].1.edges.len(), 4);
    for (_, p) in outer.iter().chain(&holes) {
        assert_eq!(p.op, Operation::Cut);
        assert!(p.strokes.iter().all(|s| is_closed(s)));
    }
    assert_eq!(slits[0].1.strokes.len(), 1);
    assert!(!is_closed(&slits[0].1.strokes[0]));
}

#[test]
fn kerf_offset_moves_cuts_toward_the_scrap() {
    let cp = sheet_with_hole_and_slit();
    let mut opts = options();
    opts.kerf_mm = 0.3;
    opts.kerf_offset = true;
    let paths = toolpaths(&cp, &opts).unwrap();
    let k = opts.kerf_mm / 2.0;
    let outer = with_role(&paths, ContourRole::Outer)[0].1;
    let hole = with_role(&paths, ContourRole::Hole)[0].1;
    let slit = with_role(&paths, ContourRole::Slit)[0].1;
    let outer_area = area(&outer.strokes[0]).abs();
    let expected = 100.0 * 100.0 + 400.0 * k + std::f64::consts::PI * k * k;
    assert!(
        (outer_area - expected).abs() < 1e-2,
        "{outer_area} vs {expected}"
    );
    let (lo, hi) = bounds(outer.strokes[0].iter().copied());
    assert!((lo - DVec2::splat(-k)).abs().max_element() < 1e-6);
    assert!((hi - DVec2::splat(100.0 + k)).abs().max_element() < 1e-6);
    let hole_area = area(&hole.strokes[0]).abs();
    let side = 20.0 - 2.0 * k;
    assert!((hole_area - side * side).abs() < 1e-6, "{hole_area}");
    let (lo, hi) = bounds(hole.strokes[0].iter().copied());
    assert!((lo - DVec2::splat(40.0 + k)).abs().max_element() < 1e-6);
    assert!((hi - DVec2::splat(60.0 - k)).abs().max_element() < 1e-6);
    assert_eq!(
        slit.strokes[0],
        vec![DVec2::new(10.0, 10.0), DVec2::new(30.0, 10.0)]
    );
}

#[test]
fn a_hole_smaller_than_the_kerf_is_reported_not_mangled() {
    let mut cp = CreasePattern::new();
    polygon(&mut cp, &square(0.0, 100.0), Assignment::Boundary);
    polygon(&mut cp, &square(50.0, 50.2), Assignment::Cut);
    let mut opts = options();
    opts.kerf_mm = 0.3;
    opts.kerf_offset = true;
    let (paths, warnings) = toolpaths_with_warnings(&cp, &opts).unwrap();
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert_eq!(
        warnings[0].kind,
        foldcam::fab::PlanWarningKind::HoleBelowKerf
    );
    assert!(warnings[0].text.contains("smaller than the kerf"));
    // The hole's four sides, drawn after the outline's four.
    let mut about: Vec<usize> = warnings[0].edges.iter().map(|e| e.index()).collect();
    about.sort_unstable();
    assert_eq!(about, [4, 5, 6, 7]);
    let hole = with_role(&paths, ContourRole::Hole)[0].1;
    assert!((area(&hole.strokes[0]).abs() - 0.04).abs() < 1e-9);
}

#[test]
fn tabs_leave_gaps_of_the_given_width_on_outer_contours() {
    let cp = sheet_with_hole_and_slit();
    let mut opts = options();
    opts.kerf_offset = true;
    opts.tabs = Some(Tabs {
        width_mm: 2.0,
        spacing_mm: 100.0,
    });
    let paths = toolpaths(&cp, &opts).unwrap();
    let outer = with_role(&paths, ContourRole::Outer)[0].1;
    assert_eq!(outer.strokes.len(), 4);
    let k = opts.kerf_mm / 2.0;
    for (i, s) in outer.strokes.iter().enumerate() {
        assert!(!is_closed(s));
        let next = &outer.strokes[(i + 1) % outer.strokes.len()];
        let gap = s.last().unwrap().distance(next[0]);
        assert!((gap - 2.0).abs() < 1e-6, "gap {gap}");
        // Tabs sit on a straight side, away from the corners.
        let mid = s.last().unwrap().lerp(next[0], 0.5);
        let on_side = [mid.x, mid.y]
            .iter()
            .any(|&c| (c + k).abs() < 1e-6 || (c - 100.0 - k).abs() < 1e-6);
        assert!(on_side, "tab at {mid}");
        assert!(mid.x > 2.0 && mid.x < 98.0 || mid.y > 2.0 && mid.y < 98.0);
    }
    // Holes are not tabbed.
    let hole = with_role(&paths, ContourRole::Hole)[0].1;
    assert_eq!(hole.strokes.len(), 1);
    assert!(is_closed(&hole.strokes[0]));
}

#[test]
fn a_small_part_still_gets_one_tab() {
    let mut cp = CreasePattern::new();
    polygon(&mut cp, &square(0.0, 10.0), Assignment::Boundary);
    let mut opts = options();
    opts.tabs = Some(Tabs {
        width_mm: 1.0,
        spacing_mm: 500.0,
    });
    let paths = toolpaths(&cp, &opts).unwrap();
    assert_eq!(paths[0].strokes.len(), 1);
    let s = &paths[0].strokes[0];
    assert!((s.last().unwrap().distance(s[0]) - 1.0).abs() < 1e-9);
}

#[test]
fn lead_ins_start_in_the_scrap() {
    let cp = sheet_with_hole_and_slit();
    let mut opts = options();
    opts.kerf_offset = true;
    opts.lead_in_mm = Some(3.0);
    for tabs in [
        None,
        Some(Tabs {
            width_mm: 2.0,
            spacing_mm: 150.0,
        }),
    ] {
        opts.tabs = tabs;
        let paths = toolpaths(&cp, &opts).unwrap();
        let outer = with_role(&paths, ContourRole::Outer)[0].1;
        let hole = with_role(&paths, ContourRole::Hole)[0].1;
        let (o, h) = (&outer.strokes[0], &hole.strokes[0]);
        assert!(
            !contains_point(&square(0.0, 100.0), o[0]),
            "outer lead-in at {}",
            o[0]
        );
        assert!(
            contains_point(&square(40.0, 60.0), h[0]),
            "hole lead-in at {}",
            h[0]
        );
        for s in [o, h] {
            assert!((s[0].distance(s[1]) - 3.0).abs() < 1e-6);
            // Perpendicular to the contour where it starts.
            assert!((s[1] - s[0]).dot(s[2] - s[1]).abs() < 1e-6);
        }
        if tabs.is_none() {
            assert_eq!(o[1], *o.last().unwrap(), "the ring closes at its start");
        }
    }
}

fn ops_of(paths: &[Toolpath], cp: &CreasePattern, kind: Assignment) -> Vec<Operation> {
    let mut ops: Vec<Operation> = paths
        .iter()
        .filter(|p| {
            p.edges
                .iter()
                .any(|e| cp.edges[e.index()].assignment == kind)
        })
        .map(|p| p.op)
        .collect();
    ops.dedup();
    ops
}

#[test]
fn the_mapping_decides_each_operation() {
    let mut cp = CreasePattern::new();
    polygon(&mut cp, &square(0.0, 100.0), Assignment::Boundary);
    cp.add_segment(
        DVec2::new(20.0, 20.0),
        DVec2::new(80.0, 20.0),
        Assignment::Mountain,
    );
    cp.add_segment(
        DVec2::new(20.0, 50.0),
        DVec2::new(80.0, 50.0),
        Assignment::Valley,
    );
    cp.add_segment(
        DVec2::new(20.0, 80.0),
        DVec2::new(80.0, 80.0),
        Assignment::Flat,
    );
    cp.add_segment(
        DVec2::new(10.0, 30.0),
        DVec2::new(10.0, 70.0),
        Assignment::Join,
    );
    let mut opts: PlanOptions = options();
    let paths = toolpaths(&cp, &opts).unwrap();
    assert_eq!(
        ops_of(&paths, &cp, Assignment::Mountain),
        [Operation::Perforate]
    );
    assert_eq!(
        ops_of(&paths, &cp, Assignment::Valley),
        [Operation::Perforate]
    );
    assert!(ops_of(&paths, &cp, Assignment::Flat).is_empty());
    assert!(ops_of(&paths, &cp, Assignment::Join).is_empty());
    opts.mapping.mountain = Some(Operation::Score);
    opts.mapping.flat = Some(Operation::Mark);
    let paths = toolpaths(&cp, &opts).unwrap();
    assert_eq!(
        ops_of(&paths, &cp, Assignment::Mountain),
        [Operation::Score]
    );
    assert_eq!(ops_of(&paths, &cp, Assignment::Flat), [Operation::Mark]);
    let score = paths.iter().find(|p| p.op == Operation::Score).unwrap();
    assert_eq!(
        score.strokes,
        vec![vec![DVec2::new(20.0, 20.0), DVec2::new(80.0, 20.0)]]
    );
    assert!(ops_of(&paths, &cp, Assignment::Join).is_empty());
}

#[test]
fn polylines_join_drawn_segments_at_plain_corners() {
    let mut cp = CreasePattern::new();
    let pts = [(10.0, 10.0), (20.0, 10.0), (25.0, 20.0), (30.0, 10.0)];
    let v: Vec<_> = pts
        .iter()
        .map(|&(x, y)| cp.add_vertex(DVec2::new(x, y)))
        .collect();
    for w in v.windows(2) {
        cp.add_edge(w[0], w[1], Assignment::Valley);
    }
    let mut opts = options();
    opts.mapping.valley = Some(Operation::Plot);
    let paths = toolpaths(&cp, &opts).unwrap();
    assert_eq!(paths.len(), 1);
    assert_eq!(paths[0].strokes[0].len(), 4);
    assert_eq!(paths[0].edges.len(), 3);
}

#[test]
fn no_cut_geometry_is_lost() {
    let mut cp = sheet_with_hole_and_slit();
    // A self-touching pair of holes and a cut from the outline inwards.
    polygon(
        &mut cp,
        &[
            DVec2::new(70.0, 70.0),
            DVec2::new(80.0, 70.0),
            DVec2::new(80.0, 80.0),
        ],
        Assignment::Cut,
    );
    polygon(
        &mut cp,
        &[
            DVec2::new(80.0, 80.0),
            DVec2::new(90.0, 80.0),
            DVec2::new(90.0, 90.0),
        ],
        Assignment::Cut,
    );
    cp.add_segment(
        DVec2::new(0.0, 30.0),
        DVec2::new(20.0, 30.0),
        Assignment::Cut,
    );
    foldcam::pattern::planarize(&mut cp, &Default::default()).expect("planarises");
    let mut opts = options();
    let paths = toolpaths(&cp, &opts).unwrap();
    assert_cut_edges_covered(&cp, &paths, &[0.0, 0.25, 0.5, 0.75, 1.0], 1e-9);
    assert_eq!(with_role(&paths, ContourRole::Hole).len(), 2);
    opts.kerf_offset = true;
    let paths = toolpaths(&cp, &opts).unwrap();
    // Offset: away from corners (where the offset path rounds or cuts them), every edge is
    // followed at half the kerf.
    assert_cut_edges_covered(&cp, &paths, &[0.25, 0.5, 0.75], opts.kerf_mm / 2.0 + 1e-6);
}

#[test]
fn miura_ori_perforates_only_folds_inside_one_outline() {
    let cp = MiuraOri::default().build().unwrap();
    let mut opts = options();
    opts.kerf_offset = true;
    let (paths, warnings) = toolpaths_with_warnings(&cp, &opts).unwrap();
    assert!(warnings.is_empty(), "{warnings:?}");
    assert_eq!(with_role(&paths, ContourRole::Outer).len(), 1);
    assert!(with_role(&paths, ContourRole::Hole).is_empty());
    assert!(with_role(&paths, ContourRole::Slit).is_empty());
    let mut perforated = vec![false; cp.edges.len()];
    for p in paths.iter().filter(|p| p.op == Operation::Perforate) {
        assert!(!p.strokes.is_empty());
        for e in &p.edges {
            assert!(cp.edges[e.index()].assignment.is_fold());
            perforated[e.index()] = true;
        }
    }
    for e in cp.edge_ids() {
        assert_eq!(
            perforated[e.index()],
            cp.edges[e.index()].assignment.is_fold(),
            "{e}"
        );
    }
    assert!(
        paths
            .iter()
            .all(|p| matches!(p.op, Operation::Perforate | Operation::Cut))
    );
    // Every interior Miura vertex has degree 4, so each crease is one edge.
    let creases = paths
        .iter()
        .filter(|p| p.op == Operation::Perforate)
        .count();
    assert_eq!(creases, perforated.iter().filter(|&&p| p).count());
}

#[test]
fn bad_inputs_are_errors() {
    let mut cp = sheet_with_hole_and_slit();
    let mut opts = options();
    opts.mapping.boundary = None;
    assert_eq!(toolpaths(&cp, &opts), Err(FabError::NothingToDo));
    let mut opts = options();
    opts.perforation.cut_mm = 0.0;
    assert!(matches!(
        toolpaths(&cp, &opts),
        Err(FabError::Geometry { .. })
    ));
    opts = options();
    opts.kerf_mm = f64::NAN;
    assert!(matches!(
        toolpaths(&cp, &opts),
        Err(FabError::Geometry { .. })
    ));
    cp.units = Units::Unitless;
    assert!(matches!(
        toolpaths(&cp, &options()),
        Err(FabError::Unitless(_))
    ));
}

#[test]
fn touching_and_collinear_contours() {
    let mut cp = CreasePattern::new();
    // Two parts touching at a corner, one with extra collinear vertices on its sides.
    polygon(
        &mut cp,
        &[
            DVec2::new(0.0, 0.0),
            DVec2::new(5.0, 0.0),
            DVec2::new(10.0, 0.0),
            DVec2::new(10.0, 10.0),
            DVec2::new(0.0, 10.0),
            DVec2::new(0.0, 5.0),
        ],
        Assignment::Boundary,
    );
    polygon(&mut cp, &square(10.0, 20.0), Assignment::Boundary);
    foldcam::pattern::planarize(&mut cp, &Default::default()).expect("planarises");
    let mut opts = options();
    opts.kerf_offset = true;
    opts.lead_in_mm = Some(1.0);
    let paths = toolpaths(&cp, &opts).unwrap();
    let outer = with_role(&paths, ContourRole::Outer);
    assert_eq!(outer.len(), 1, "the touching parts share one outline");
    assert!(with_role(&paths, ContourRole::Hole).is_empty());
    assert_cut_edges_covered(&cp, &paths, &[0.25, 0.5, 0.75], 1e-6 + opts.kerf_mm / 2.0);
    opts.tabs = Some(Tabs {
        width_mm: 1.0,
        spacing_mm: 20.0,
    });
    let paths = toolpaths(&cp, &opts).unwrap();
    let outer = with_role(&paths, ContourRole::Outer)[0].1;
    assert!(outer.strokes.len() >= 3);
    assert!(outer.strokes.iter().flatten().all(|q| q.is_finite()));
}

mod random_patterns {
    use super::*;
    use proptest::prelude::*;
    use proptest::test_runner::{Config, RngSeed};

    fn assignment() -> impl Strategy<Value = Assignment> {
        prop::sample::select(Assignment::ALL.to_vec())
    }

    proptest! {
        #![proptest_config(Config { cases: 64, rng_seed: RngSeed::Fixed(0x00fa_b9e0), ..Config::default() })]

        /// Random line drawings inside a sheet, planarised: no panic, no NaN, every cut edge
        /// covered when offsetting is off.
        #[test]
        fn random_drawings_give_finite_toolpaths(
            lines in prop::collection::vec(
                ((0.0f64..100.0, 0.0f64..100.0), (0.0f64..100.0, 0.0f64..100.0), assignment()),
                1..12,
            ),
            kerf_offset in any::<bool>(),
            tabs in any::<bool>(),
        ) {
            let mut cp = CreasePattern::new();
            polygon(&mut cp, &square(0.0, 100.0), Assignment::Boundary);
            for ((ax, ay), (bx, by), kind) in lines {
                if (ax - bx).abs() + (ay - by).abs() > 1e-3 {
                    cp.add_segment(DVec2::new(ax, ay), DVec2::new(bx, by), kind);
                }
            }
            foldcam::pattern::planarize(&mut cp, &Default::default()).expect("planarises");
            let mut opts = options();
            opts.mapping.flat = Some(Operation::Mark);
            opts.mapping.valley = Some(Operation::Score);
            opts.kerf_offset = kerf_offset;
            opts.lead_in_mm = Some(2.0);
            opts.tabs = tabs.then_some(Tabs { width_mm: 1.5, spacing_mm: 40.0 });
            let (paths, _) = toolpaths_with_warnings(&cp, &opts).unwrap();
            for p in &paths {
                prop_assert!(p.strokes.iter().flatten().all(|q| q.is_finite()));
                prop_assert!(p.strokes.iter().all(|s| s.len() >= 2));
                if let Some(c) = p.container {
                    prop_assert!(c < paths.len());
                }
            }
            if !kerf_offset {
                assert_cut_edges_covered(&cp, &paths, &[0.25, 0.5, 0.75], 1e-6);
            }
        }
    }
}

#[test]
fn a_pocket_closed_by_the_kerf_gets_its_lead_in_inside() {
    // A part with a keyhole: a 0.1 mm mouth (narrower than the kerf) into a 4 mm chamber.
    let keyhole = [
        (0.0, 0.0),
        (20.0, 0.0),
        (20.0, 20.0),
        (10.05, 20.0),
        (10.05, 14.0),
        (12.0, 14.0),
        (12.0, 10.0),
        (8.0, 10.0),
        (8.0, 14.0),
        (9.95, 14.0),
        (9.95, 20.0),
        (0.0, 20.0),
    ];
    let mut cp = CreasePattern::new();
    let pts: Vec<DVec2> = keyhole.iter().map(|&(x, y)| DVec2::new(x, y)).collect();
    polygon(&mut cp, &pts, Assignment::Boundary);
    let mut opts = options();
    opts.kerf_mm = 0.3;
    opts.kerf_offset = true;
    opts.lead_in_mm = Some(1.0);
    let paths = toolpaths(&cp, &opts).unwrap();
    assert_eq!(paths.len(), 1);
    assert_eq!(paths[0].strokes.len(), 2, "outline and chamber");
    let chamber = [
        DVec2::new(8.0, 10.0),
        DVec2::new(12.0, 10.0),
        DVec2::new(12.0, 14.0),
        DVec2::new(8.0, 14.0),
    ];
    let inside: Vec<bool> = paths[0]
        .strokes
        .iter()
        .map(|s| contains_point(&chamber, s[0]))
        .collect();
    assert_eq!(inside.iter().filter(|&&b| b).count(), 1, "{inside:?}");
    let outline = paths[0]
        .strokes
        .iter()
        .find(|s| !contains_point(&chamber, s[1]))
        .unwrap();
    assert!(!contains_point(&pts, outline[0]));
}
