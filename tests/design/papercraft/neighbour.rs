//! Automatic neighbouring patches (§3.5) and the least-squares directrix fit.

use std::path::Path;

use foldcam::design::papercraft::BSpline;
use foldcam::design::papercraft::CylinderPatch;
use foldcam::design::papercraft::PapercraftError;
use foldcam::design::papercraft::Walls;
use foldcam::design::papercraft::boundary_gap;
use foldcam::design::papercraft::fit_directrix;
use foldcam::design::papercraft::{Design, Made, parse_design};
use foldcam::mesh::ReferenceMesh;
use foldcam::mesh::read_mesh;
use glam::DVec3;

use super::support::{
    Rng, assert_cuts_clean_on_paper, build_example, example_design, side_lengths,
};

fn auto_text() -> String {
    std::fs::read_to_string("examples/papercraft/vase_auto.craft.toml").unwrap()
}

fn vase_mesh() -> ReferenceMesh {
    ReferenceMesh::new(&read_mesh(Path::new("examples/papercraft/vase.obj")).unwrap()).unwrap()
}

/// The design's walls.
fn walls_of(design: &Design, mesh: &ReferenceMesh) -> Walls {
    design.network_and_walls(mesh).unwrap().1
}

/// Distance from `x` to the cylinder `patch` (closest section point, scan then refine).
fn distance_to_surface(patch: &CylinderPatch, x: DVec3) -> f64 {
    let d = patch.ruling();
    let off = |u: f64| {
        let r = x - patch.directrix().at(u);
        (r - r.dot(d) * d).length()
    };
    let steps = 400;
    let h = patch.u_max() / steps as f64;
    let k = (0..=steps)
        .min_by(|&a, &b| off(a as f64 * h).total_cmp(&off(b as f64 * h)))
        .unwrap();
    let (mut lo, mut hi) = ((k as f64 - 1.0) * h, (k as f64 + 1.0) * h);
    for _ in 0..100 {
        // Golden-section search on the bracket.
        let (a, b) = (hi - 0.618 * (hi - lo), lo + 0.618 * (hi - lo));
        if off(a) < off(b) { hi = b } else { lo = a }
    }
    off(0.5 * (lo + hi))
}

/// The gap along cut line `e` between the two parts glued there: the largest distance from
/// a point of either part's real boundary on `e` (mapped back onto its patch in 3D) to the
/// other patch's surface (mesh units).
fn gap_on(design: &Design, made: &Made, e: usize) -> f64 {
    let mut users: Vec<(usize, Vec<DVec3>)> = Vec::new();
    for part in &made.parts {
        let patch = &made.patches[part.patch];
        for s in part.sides.iter().filter(|s| s.half_edge / 2 == e) {
            let pts = (0..=s.len)
                .map(|k| patch.point_of_flat(part.point(s.start + k) / design.scale))
                .collect();
            users.push((part.patch, pts));
        }
    }
    assert_eq!(users.len(), 2, "cut line {e} joins two parts");
    [(0, 1), (1, 0)]
        .iter()
        .map(|&(me, other)| {
            users[me]
                .1
                .iter()
                .map(|&x| distance_to_surface(&made.patches[users[other].0], x))
                .fold(0.0, f64::max)
        })
        .fold(0.0, f64::max)
}

/// The two parts glued along cut line `e`: each one's real boundary there lies on the other
/// patch's surface within the tolerance (the boundary points are on the wall, so they are on
/// the other's real boundary), and the two glued sides have the same length (longer than
/// `at_least` mm).
fn assert_meets_without_gap(design: &Design, made: &Made, e: usize, at_least: f64) {
    let tol = design.tolerance;
    let gap = gap_on(design, made, e);
    assert!(gap < tol, "cut line {e}: gap {gap} mm ≥ tolerance {tol}");
    let lengths = side_lengths(made, e);
    assert!(lengths[0] > at_least, "cut line {e}: {lengths:?}");
    assert!(
        (lengths[0] - lengths[1]).abs() < tol,
        "cut line {e}: {lengths:?}"
    );
}

#[test]
fn generated_gores_meet_their_neighbours_without_a_gap_and_close_the_vase() {
    let design = parse_design(&auto_text()).unwrap();
    assert_eq!((design.patches.len(), design.auto_patches.len()), (1, 7));
    let mesh = vase_mesh();
    let made = design.build(&mesh).unwrap();
    assert_eq!(made.parts.len(), 8);
    assert!(made.parts.iter().all(|p| p.dropped_tabs == 0));
    let tol = design.tolerance;
    // Every shared meridian, including meridian 0 where the last generated gore meets the
    // placed one.
    for e in 0..8 {
        assert_meets_without_gap(&design, &made, e, 100.0);
    }
    // The reports agree: every gap measured on the wall ribs is below the tolerance.
    assert_eq!(made.auto.len(), 7);
    assert_eq!(
        made.auto[6].gaps.len(),
        2,
        "gore 7 grows from gores 6 and 0"
    );
    for r in &made.auto {
        assert!(r.gaps.iter().all(|&(_, _, g)| g < tol), "{r:?}");
    }
    for (s, cp) in made.sheets.iter().enumerate() {
        assert_cuts_clean_on_paper(&format!("generated vase sheet {s}"), cp);
    }
}

#[test]
fn fitting_to_both_neighbours_closes_the_ring_better_than_to_one() {
    let mesh = vase_mesh();
    let both = parse_design(&auto_text()).unwrap();
    let one_text = auto_text().replacen(
        "from = [{ patch = 6, cut_line = 7 }, { patch = 0, cut_line = 0 }]",
        "from = [{ patch = 6, cut_line = 7 }]",
        1,
    );
    assert_ne!(one_text, auto_text());
    let one = parse_design(&one_text).unwrap();
    let walls = walls_of(&both, &mesh);
    let worst = |made: &Made| {
        [(6, 7), (0, 0)]
            .iter()
            .map(|&(q, e)| {
                boundary_gap(&mesh, &walls, e, &made.patches[q], &made.patches[7], 256).unwrap()
            })
            .fold(0.0, f64::max)
    };
    let (g_both, g_one) = (
        worst(&both.build(&mesh).unwrap()),
        worst(&one.build(&mesh).unwrap()),
    );
    assert!(g_both < g_one, "both {g_both}, one {g_one}");
    assert!(g_both < both.tolerance);
}

#[test]
fn a_generated_patch_too_short_for_its_walls_is_extended() {
    let mesh = vase_mesh();
    // Without extension gore 1 ends exactly at the corners of meridian 1 and misses the
    // rim or foot wall (the thesis's first limit, §5.2.1).
    let bare = auto_text().replace("\nfrom = [", "\nextend = 0.0\nfrom = [");
    let err = parse_design(&bare).unwrap().build(&mesh).unwrap_err();
    assert!(
        matches!(err, PapercraftError::MissesWall { patch: 1, .. }),
        "{err}"
    );
    assert!(err.to_string().contains("extend"), "{err}");
    assert!(parse_design(&auto_text()).unwrap().build(&mesh).is_ok());
}

#[test]
fn bad_automatic_patches_name_the_problem() {
    let mesh = vase_mesh();
    let build = |text: String| parse_design(&text).unwrap().build(&mesh).unwrap_err();
    let cases = [
        // Gore 1 growing across a meridian it does not share with gore 0.
        (
            "from = [{ patch = 0, cut_line = 1 }]",
            "from = [{ patch = 0, cut_line = 2 }]",
            "does not lie between patch 0",
        ),
        // Gore 1 growing from gore 2, which is built after it.
        (
            "from = [{ patch = 0, cut_line = 1 }]",
            "from = [{ patch = 2, cut_line = 2 }]",
            "must be built before",
        ),
        (
            "from = [{ patch = 0, cut_line = 1 }]",
            "from = []",
            "at least one",
        ),
        (
            "normal = [-0.9239, 0.3827, 0.0000]",
            "normal = [0.0, 0.0, 0.0]",
            "non-zero normal",
        ),
    ];
    for (from, to, message) in cases {
        let text = auto_text().replacen(from, to, 1);
        assert_ne!(text, auto_text(), "{from}");
        let err = build(text);
        assert!(
            matches!(&err, PapercraftError::BadLoop { patch: 1, message: m } if m.contains(message)),
            "{to}: {err}"
        );
    }
}

#[test]
fn the_fit_reproduces_a_b_spline_and_converges_on_a_circle() {
    let mut rng = Rng::new(11);
    let control: Vec<DVec3> = (0..8)
        .map(|i| DVec3::new(5.0 * i as f64, 0.0, 0.0) + rng.cube(3.0))
        .collect();
    let curve = BSpline::directrix(control, "truth").unwrap();
    let params: Vec<f64> = (0..=200).map(|k| 4.0 * k as f64 / 200.0).collect();
    let points: Vec<DVec3> = params.iter().map(|&u| curve.at(u)).collect();
    let fit = fit_directrix(&points, &params, &vec![1.0; points.len()], 8, 2).unwrap();
    for (a, b) in fit.curve.control().iter().zip(curve.control()) {
        assert!(a.distance(*b) < 1e-6, "{a} vs {b}");
    }
    // Exact up to the tiny second-difference regularisation.
    assert!(
        fit.distances.iter().all(|&d| d < 1e-6),
        "{:?}",
        fit.distances.iter().fold(0.0, |a: f64, &d| a.max(d))
    );
    // A half circle of radius 10 is not a B-spline: more control points fit it better.
    let arc: Vec<DVec3> = (0..=300)
        .map(|k| {
            let a = std::f64::consts::PI * k as f64 / 300.0;
            DVec3::new(10.0 * a.cos(), 10.0 * a.sin(), 0.0)
        })
        .collect();
    let t: Vec<f64> = (0..=300).map(|k| k as f64).collect();
    let residual = |n: usize| {
        let f = fit_directrix(&arc, &t, &vec![1.0; arc.len()], n, 4).unwrap();
        f.distances.iter().fold(0.0, |a: f64, &d| a.max(d))
    };
    let (r5, r10, r20) = (residual(5), residual(10), residual(20));
    assert!(r5 > r10 && r10 > r20, "{r5} {r10} {r20}");
    assert!(r20 < 1e-4, "{r20}");
    // Too many control points, and zero weights, are refused.
    assert!(fit_directrix(&points[..6], &params[..6], &[1.0; 6], 7, 0).is_err());
    assert!(fit_directrix(&points[..6], &params[..6], &[0.0; 6], 5, 0).is_err());
}

#[test]
fn the_fish_example_builds_its_generated_gores_meet_and_it_cuts_clean() {
    let design = example_design("fish");
    assert_eq!((design.patches.len(), design.auto_patches.len()), (3, 5));
    let made = build_example("fish");
    assert_eq!(made.parts.len(), 8);
    assert!(made.parts.iter().all(|p| p.dropped_tabs == 0));
    // Six meridians between the gores (the body is 98 mm long between the caps): the sections
    // are ellipses, so the gores are not mirror images and only §3.5 makes them meet.
    for e in 0..6 {
        assert_meets_without_gap(&design, &made, e, 98.0);
    }
    for (s, cp) in made.sheets.iter().enumerate() {
        assert_cuts_clean_on_paper(&format!("fish sheet {s}"), cp);
    }
}

#[test]
fn the_fish_caps_meet_the_gores_within_the_tolerance() {
    // The snout (cut lines 6–11) and tail-root (12–17) caps are flat and placed by hand; the
    // gores contain their end chords, so gores and caps cross the end walls together.
    let design = example_design("fish");
    let made = build_example("fish");
    let gaps: Vec<f64> = (6..18).map(|e| gap_on(&design, &made, e)).collect();
    let worst = gaps.iter().fold(0.0, |a: f64, &g| a.max(g));
    println!("fish caps to gores, cut lines 6–17: gaps {gaps:.4?} mm, largest {worst:.4} mm");
    assert!(
        worst < design.tolerance,
        "largest cap gap {worst} mm ≥ tolerance {}",
        design.tolerance
    );
    for e in 6..18 {
        let lengths = side_lengths(&made, e);
        assert!(
            (lengths[0] - lengths[1]).abs() < design.tolerance,
            "cut line {e}: {lengths:?}"
        );
    }
}
