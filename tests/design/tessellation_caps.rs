//! Tessellations of spherical caps as modelling programs export them (a pole of valence n,
//! ring k with n·k vertices): the necessary condition on star points at a high-valence pole,
//! its truncation, and solves within the 0.5 mm stainless limits, each checked by
//! re-measurement, the unfolded pattern and the cut on the fiber laser.

use crate::cuts_clean;
#[allow(dead_code)]
use crate::support::tessellation_checks as checks;

use foldcam::design::tessellation::{measure::*, samples::*, steps::*, *};
use foldcam::mesh::HalfEdgeMesh;
use glam::DVec3;

use checks::*;
use cuts_clean::assert_cuts_clean_on;

/// Faces of the folded form closer than this (mm) touch (see `solved_cap`).
const CONTACT: f64 = 1e-4;

/// The key vertex of a p-pointed star has 2p angles summing to 360°: p ≤ 180°/δ.
#[test]
fn star_points_follow_from_the_vertex_angle_limit() {
    let limits = stainless_limits();
    // 30° plus the 0.25° margin: 6 points would need 12 · 30.25° = 363° > 360°.
    assert_eq!(max_star_points(limits.min_vertex_angle + limits.margin), 5);
    assert_eq!(max_star_points(30f64.to_radians()), 6);
    assert_eq!(max_star_points(20.5f64.to_radians()), 8);
}

/// Without the cap, the 12-valent pole's 6-pointed star (checkerboard layout) is found before
/// any solve: one input vertex, at the pole, 12 sectors; the other vertices' stars (3 points)
/// pass. With the default cap the pole is truncated and nothing is flagged.
#[test]
fn a_twelve_valent_pole_is_diagnosed_before_solving_and_truncated() {
    let mesh = spherical_cap(12, 3, 60.0, 100.0);
    let he = HalfEdgeMesh::new(&mesh, 1e-9).expect("manifold");
    let limits = stainless_limits();
    let floor = limits.min_vertex_angle + limits.margin;
    let uncapped = star_tucks(
        &he,
        &StarOptions {
            max_star_points: Some(usize::MAX),
            ..StarOptions::default()
        },
    )
    .expect("initial pattern");
    let found = before_solving(&uncapped.mesh, mesh.positions(), floor);
    assert_eq!(found.len(), 1, "{found:?}");
    assert_eq!(found[0].input_vertex, 0);
    assert_eq!(found[0].position, DVec3::ZERO);
    assert_eq!(found[0].condition, Condition::TooManySectors);
    assert_eq!(found[0].value, 12.0);
    assert!(found[0].describe().contains("(0.0, 0.0, 0.0)"));
    // The same count independently: the key vertex of the pole's tuck.
    let key = uncapped.mesh.key_of_input[0].expect("the pole has a key vertex");
    assert_eq!(sector_counts(&uncapped.mesh)[key as usize], 12);
    // tessellate() refuses it without solving.
    let mut opts = TessellateOptions::with_limits(limits);
    opts.star.max_star_points = Some(usize::MAX);
    let t = tessellate(&mesh, &opts, &mut ()).expect("valid options");
    assert_eq!(t.report.iterations, 0);
    assert!(t.problem().expect("refused").contains("input vertex 0"));

    let capped = star_tucks(
        &he,
        &StarOptions {
            max_star_points: Some(max_star_points(floor)),
            ..StarOptions::default()
        },
    )
    .expect("initial pattern");
    assert_eq!(capped.truncated, vec![0]);
    assert_eq!(capped.mesh.key_of_input[0], None);
    assert!(before_solving(&capped.mesh, mesh.positions(), floor).is_empty());
}

/// Solves `mesh` with the default shrinks and the stainless limits and checks the result by
/// re-measurement: developable, every fold within 165° of its assigned sign, every angle
/// between creases at least 30°, no crease through a vertex-adjacent face, no face through
/// another, and the unfolded pattern isometric without overlaps; every face corner stays
/// near the sphere of `radius` about (0, 0, −radius). `shrinks` are tried in turn.
fn solved_cap(
    name: &str,
    mesh: &foldcam::mesh::PolyMesh,
    kind: TuckKind,
    radius: f64,
    shrinks: &[f64],
) -> Tessellation {
    let schedule = Schedule::Ladder {
        shrinks: shrinks.to_vec(),
        remesh: Remesh::Never,
        remesh_faces: None,
    };
    solved_cap_scheduled(name, mesh, kind, radius, &schedule)
}

/// [`solved_cap`] over a whole [`Schedule`] (face shrinks, re-triangulation).
fn solved_cap_scheduled(
    name: &str,
    mesh: &foldcam::mesh::PolyMesh,
    kind: TuckKind,
    radius: f64,
    schedule: &Schedule,
) -> Tessellation {
    let limits = stainless_limits();
    let mut opts = TessellateOptions::with_limits(limits);
    opts.star.tuck.kind = kind;
    opts.schedule = schedule.clone();
    let t = tessellate(mesh, &opts, &mut ()).unwrap();
    let r = &t.report;
    assert!(t.problem().is_none(), "{name}: {}", t.summary());
    assert!(r.converged, "{name}: {}", r.summary());
    for (v, d) in angle_defects(&t.mesh, &t.mesh.positions).iter().enumerate() {
        assert!(d.abs() < 1e-9, "{name}: vertex {v} defect {d:e}");
    }
    let again = residuals(&t.mesh, &t.mesh.positions, None);
    assert!(again.max_fold <= limits.max_fold, "{name}");
    assert!(again.wrong_sign >= 0.0, "{name}");
    assert!(again.min_vertex_angle >= limits.min_vertex_angle, "{name}");
    // Creases may touch a vertex-adjacent face (penalty within the solver's tolerance), never
    // pass through one; the face-intersection test below is the stricter check.
    assert!(again.max_penalty <= PENALTY_TOLERANCE, "{name}");
    // Face corners come to rest on neighbouring faces; within 0.1 µm (float noise of the
    // solve, 5,000 times under the sheet's 0.5 mm) that is contact, not a crossing.
    let crossing =
        intersecting_triangles(&t.mesh.positions, &t.mesh.triangles, CONTACT).expect("triangles");
    assert!(crossing.is_empty(), "{name}: {crossing:?}");
    check_unfolded_within(name, &t, CONTACT);
    // The folded form stays near the input surface: no face corner farther from the sphere
    // than a third of the radius (the tucks pull the faces in by about their depth).
    let centre = DVec3::new(0.0, 0.0, -radius);
    let off = t.mesh.positions[..t.mesh.corner_count]
        .iter()
        .fold(0.0f64, |m, p| m.max((p.distance(centre) - radius).abs()));
    assert!(off < radius / 3.0, "{name}: {off}");
    t
}

/// The cap: 12-valent pole, 60°, radius 100 mm, 432 faces, star tucks at the face
/// shrink the default ladder reaches (0.45; the larger ones are not solved here to keep the
/// debug-build test short).
#[test]
fn the_432_face_cap_with_a_twelve_valent_pole_tessellates_with_star_tucks() {
    let mesh = spherical_cap(12, 6, 60.0, 100.0);
    assert_eq!(mesh.faces().len(), 432);
    assert!(SHRINK_LADDER.contains(&0.45));
    let t = solved_cap("cap 432", &mesh, TuckKind::Star, 100.0, &[0.45]);
    assert_eq!(t.initial.truncated, vec![0]);
}

/// How many twist folds `t` has, after checking each is a mountain or a valley now (left
/// unassigned while solving; `check_unfolded` has checked each folds the way it says).
fn assigned_twist_folds(name: &str, t: &Tessellation) -> usize {
    let twist_folds: Vec<_> = t
        .mesh
        .edges
        .iter()
        .filter(|e| e.role == EdgeRole::TwistFold)
        .collect();
    assert!(
        twist_folds.iter().all(|e| e.assignment.is_fold()),
        "{name}: a twist fold left unassigned"
    );
    twist_folds.len()
}

/// Twisted stars on a cap of five rings round a 6-valent pole (`spherical_cap(6, 5, 20, 300)`,
/// 150 faces; the 300 mm radius keeps every crease long enough for a perforation dash on
/// stainless) at shrink 0.8, on its own triangles: with each twist fold's direction read off
/// the initial pattern the solve stalled (measured, release: not converged after 112
/// iterations, largest fold 167.5°, smallest crease angle 26.9°); with the direction left to
/// the solve it converges (158 iterations) within the stainless limits, checked as above,
/// each twist fold ends a mountain or valley as it folds, and the pattern cuts clean on the
/// fiber laser.
#[test]
fn twisted_stars_solve_a_five_ring_cap_and_cut_clean() {
    let mesh = spherical_cap(6, 5, 20.0, 300.0);
    assert_eq!(mesh.faces().len(), 150);
    let t = solved_cap("cap 6/5 twisted", &mesh, TuckKind::Twisted, 300.0, &[0.8]);
    assert_eq!(assigned_twist_folds("cap 6/5 twisted", &t), 420);
    let cp = &t.unfolded.as_ref().expect("unfolds").pattern;
    assert_cuts_clean_on("cap 6/5 twisted", cp, "linuxcnc-fiber", "stainless-0.5");
}

/// The small 12-valent cap goes through the fabrication pipeline on the fiber laser with
/// 0.5 mm stainless steel without violations and with every crease covered.
#[test]
fn the_small_twelve_valent_cap_cuts_clean_on_stainless() {
    let mesh = spherical_cap(12, 3, 60.0, 100.0);
    let t = solved_cap("cap 12/3", &mesh, TuckKind::Star, 100.0, &SHRINK_LADDER);
    let cp = &t.unfolded.as_ref().expect("unfolds").pattern;
    assert_cuts_clean_on("cap 12/3", cp, "linuxcnc-fiber", "stainless-0.5");
}

/// A small 12-valent cap with star tucks, and a small 8-valent cap (45°, radius 60 mm) in
/// every mode.
#[test]
fn small_caps_tessellate_in_every_mode() {
    let twelve = spherical_cap(12, 3, 60.0, 100.0);
    solved_cap(
        "cap 12/3 star",
        &twelve,
        TuckKind::Star,
        100.0,
        &SHRINK_LADDER,
    );
    let eight = spherical_cap(8, 3, 45.0, 60.0);
    for kind in [
        TuckKind::Star,
        TuckKind::Truncated,
        TuckKind::Twisted,
        TuckKind::TwistFold,
    ] {
        solved_cap(
            &format!("cap 8/3 {kind}"),
            &eight,
            kind,
            60.0,
            &SHRINK_LADDER,
        );
    }
}

/// The cap again, by the default schedule's order: its face corners (23.7°) are
/// sharper than the 30° crease-angle limit, so the near-regular re-triangulation is tried
/// first; truncated stars and twist folds then meet the stainless limits (the shrinks are
/// the ones the default ladder reaches, given alone to keep the test short), checked as
/// above, and the truncated stars cut clean on the fiber laser.
#[test]
fn the_432_face_cap_tessellates_remeshed_with_truncated_stars_and_twist_folds() {
    let mesh = spherical_cap(12, 6, 60.0, 100.0);
    assert_eq!(
        Schedule::ladder(),
        Schedule::Ladder {
            shrinks: SHRINK_LADDER.to_vec(),
            remesh: Remesh::Auto,
            remesh_faces: None
        }
    );
    for (kind, shrink) in [(TuckKind::Truncated, 0.5), (TuckKind::TwistFold, 0.7)] {
        assert!(SHRINK_LADDER.contains(&shrink));
        let only = Schedule::Ladder {
            shrinks: vec![shrink],
            remesh: Remesh::Auto,
            remesh_faces: None,
        };
        let name = format!("cap 432 {kind}");
        let t = solved_cap_scheduled(&name, &mesh, kind, 100.0, &only);
        let r = t.remeshed.expect("re-triangulated first");
        assert_eq!(r.max_valence, [12, 6]);
        if kind == TuckKind::Truncated {
            let cp = &t.unfolded.as_ref().expect("unfolds").pattern;
            assert_cuts_clean_on(&name, cp, "linuxcnc-fiber", "stainless-0.5");
        }
    }
}

/// A 12-valent cap of 108 faces, whose own triangles fail with truncated stars (face
/// collisions or a stalled solve at shrinks 0.8, 0.6 and 0.45, measured), tessellates
/// re-triangulated in every mode within the stainless limits by the default schedule.
#[test]
fn a_small_remeshed_twelve_valent_cap_tessellates_in_every_mode() {
    let mesh = spherical_cap(12, 3, 60.0, 100.0);
    // By default: the input's 24° face corners are under the 30° limit, so the
    // re-triangulation comes first.
    let schedule = Schedule::ladder();
    for kind in [
        TuckKind::Star,
        TuckKind::Truncated,
        TuckKind::Twisted,
        TuckKind::TwistFold,
    ] {
        let t = solved_cap_scheduled(&format!("cap 108 {kind}"), &mesh, kind, 100.0, &schedule);
        assert_eq!(t.remeshed.expect("re-triangulated").max_valence, [12, 6]);
    }
}

/// The cap with twisted stars by the default schedule's first attempt (the
/// re-triangulation at shrink 0.8, the ladder's first shrink): the twisted-star solve gets
/// the Levenberg–Marquardt fallback and a longer iteration cap by default (see
/// `TWISTED_ITERATIONS`; without them it stalled short of the limits, largest fold 166.8°,
/// smallest crease angle 29.6°, measured), meets the stainless limits, checked as above,
/// leaves every twist fold a mountain or a valley, and cuts clean on the fiber laser.
#[test]
fn the_432_face_cap_tessellates_remeshed_with_twisted_stars_and_cuts_clean() {
    let mesh = spherical_cap(12, 6, 60.0, 100.0);
    let only = Schedule::Ladder {
        shrinks: vec![SHRINK_LADDER[0]],
        remesh: Remesh::Auto,
        remesh_faces: None,
    };
    let name = "cap 432 twisted-star";
    let t = solved_cap_scheduled(name, &mesh, TuckKind::Twisted, 100.0, &only);
    assert_eq!(
        t.remeshed.expect("re-triangulated first").max_valence,
        [12, 6]
    );
    assert!(assigned_twist_folds(name, &t) > 0, "{name}");
    let cp = &t.unfolded.as_ref().expect("unfolds").pattern;
    assert_cuts_clean_on(name, cp, "linuxcnc-fiber", "stainless-0.5");
}

/// A cap crowded at the rim (60°, 9 rings, 972 faces: its rim crowding index is over the
/// limit, and truncated stars on it collided at every shrink, see `crowding`) is solved by
/// the default schedule on the coarser re-triangulation the crowding index allows, and the
/// result says so. Twist folds there end clean at the first shrink (0.8, release build:
/// 42 iterations, 0.7 s); every check of `solved_cap_scheduled` re-measures the result.
#[test]
fn a_cap_crowded_at_the_rim_is_solved_coarser_and_says_so() {
    let mesh = spherical_cap(12, 9, 60.0, 100.0);
    let input = rim_crowding(&mesh).unwrap();
    assert!(input.crowded(), "{}", input.index());
    let t = solved_cap_scheduled(
        "cap 972 twist fold",
        &mesh,
        TuckKind::TwistFold,
        100.0,
        &Schedule::ladder(),
    );
    assert_eq!(t.coarsened, Some(input));
    let r = t.remeshed.expect("re-triangulated");
    assert!(r.faces[0] == 972 && r.faces[1] < 972, "{:?}", r.faces);
    // The re-triangulation has about the face count the crowding advice names (the lattice
    // comes out within a few per cent of the count asked for).
    let asked = input.faces_for_limit() as f64;
    assert!(
        (r.faces[1] as f64 / asked - 1.0).abs() < 0.05,
        "{asked} {r:?}"
    );
    // The solved mesh's own index is the coarser one's: under the input's, near the limit.
    assert!(t.crowding.index() < input.index());
    assert!(
        t.crowding.index() < 1.05 * CROWDING_LIMIT,
        "{}",
        t.crowding.index()
    );
    let summary = t.summary().to_string();
    assert!(
        summary.contains(&format!("face count changed from 972 to {}", r.faces[1])),
        "{summary}"
    );
    assert!(summary.contains("rim crowding index"), "{summary}");
}
