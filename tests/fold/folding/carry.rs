//! Faces of another plane joined beyond the fold line move along rigidly (§4.1: faces
//! edge-connected to moving faces move too): a standing flap is carried by a later fold, a
//! flap whose hinge the fold line crosses holds the paper and the fold is refused, and a flap
//! folds on about its own crease.

use foldcam::check::{CheckOptions, check};
use foldcam::design::folding::crease_pattern;
use foldcam::design::folding::layer_problems;
use foldcam::design::folding::{Fold, FoldError, Folding, Layers, Turn};
use foldcam::pattern::Assignment;
use glam::{DVec2, DVec3};

use super::{assert_every_step_isometric, square};

fn p(x: f64, y: f64) -> DVec3 {
    DVec3::new(x, y, 0.0)
}

/// Turns the part right of the vertical line `x` by `angle` degrees (towards +z if positive).
fn vertical(x: f64, angle: f64) -> Fold {
    Fold {
        line: [p(x, 0.0), p(x, 100.0)],
        moving: p(x + 5.0, 50.0),
        turn: Turn::Angle(angle),
        layers: Layers::All,
    }
}

/// A 100 mm square with the strip x ∈ [80, 100] turned up by 90° about x = 80.
fn with_flap() -> Folding {
    let mut f = square(100.0);
    f.fold(&vertical(80.0, 90.0), None).expect("flap up");
    f
}

/// The current face whose sheet polygon contains `at` (a point of the flat sheet).
fn face_at(f: &Folding, at: DVec2) -> usize {
    let faces = &f.current().faces;
    (0..faces.len())
        .find(|&i| {
            let poly = f.polygon(&faces[i]);
            let (lo, hi) = poly
                .iter()
                .fold((poly[0], poly[0]), |(lo, hi), q| (lo.min(*q), hi.max(*q)));
            at.cmpgt(lo).all() && at.cmplt(hi).all()
        })
        .expect("a face there")
}

/// The fold angle of the crease along x = `x` on the sheet.
fn crease_at(f: &Folding, x: f64) -> (Assignment, f64) {
    let cp = crease_pattern(f).pattern;
    let e = cp
        .edges
        .iter()
        .find(|e| {
            let [a, b] = e.vertices.map(|v| cp.vertices[v.0 as usize]);
            (a.x - x).abs() < 1e-6 && (b.x - x).abs() < 1e-6
        })
        .expect("crease");
    (e.assignment, e.fold_angle.unwrap_or(0.0))
}

#[test]
fn a_fold_up_carries_a_standing_flap_into_a_new_plane() {
    let mut f = with_flap();
    let report = f
        .fold(&vertical(40.0, 90.0), None)
        .expect("carries the flap");
    assert_eq!((report.moved, report.split), (2, 1));
    // The flap turned with the part it hangs on: from the vertical plane x = 80 to the
    // horizontal plane z = 40, over x ∈ [20, 40].
    let flap = face_at(&f, DVec2::new(90.0, 50.0));
    for c in f.corners(&f.current().faces[flap]) {
        assert!((c.z - 40.0).abs() < 1e-9 && (20.0 - 1e-9..=40.0 + 1e-9).contains(&c.x));
    }
    let groups = &f.current().groups;
    assert_eq!(groups.len(), 3);
    let top = groups
        .iter()
        .find(|g| g.stack.contains(&flap))
        .expect("the flap's group");
    assert_eq!(top.stack, vec![flap]);
    assert!(top.normal.z.abs() > 1.0 - 1e-12 && (top.origin.z - 40.0).abs() < 1e-9);
    assert_every_step_isometric(&f, "flap carried up");
    for x in [40.0, 80.0] {
        let (a, angle) = crease_at(&f, x);
        assert_eq!(a, Assignment::Valley);
        assert!((angle - 90.0).abs() < 1e-9, "x = {x}: {angle}");
    }
    let before = f.steps()[1].state.clone();
    f.undo().expect("undo");
    assert_eq!(f.current(), &before);
}

#[test]
fn a_bend_carries_a_standing_flap_over() {
    let mut f = with_flap();
    f.fold(&vertical(40.0, 180.0), None)
        .expect("carries the flap");
    // Bent over x = 40 onto the left half, the flap now hangs down from x = 0.
    let flap = face_at(&f, DVec2::new(90.0, 50.0));
    let corners = f.corners(&f.current().faces[flap]);
    assert!(corners.iter().all(|c| c.x.abs() < 1e-9));
    assert!(corners.iter().any(|c| (c.z + 20.0).abs() < 1e-9));
    assert!(layer_problems(&f, f.current()).is_empty());
    assert_every_step_isometric(&f, "flap bent over");
    let (a, angle) = crease_at(&f, 80.0);
    assert!(
        a == Assignment::Valley && (angle - 90.0).abs() < 1e-9,
        "{angle}"
    );
}

#[test]
fn a_flap_whose_hinge_the_fold_crosses_holds_the_paper() {
    let mut f = with_flap();
    let before = f.clone();
    let across = Fold {
        line: [p(0.0, 50.0), p(100.0, 50.0)],
        moving: p(50.0, 90.0),
        turn: Turn::Angle(180.0),
        layers: Layers::All,
    };
    assert_eq!(f.fold(&across, None), Err(FoldError::CarriedFaceHeld));
    assert_eq!(f, before);
    // A fold parallel to the hinge that leaves the flap on the stationary side is made.
    let left = Fold {
        moving: p(10.0, 50.0),
        ..vertical(40.0, 180.0)
    };
    f.fold(&left, None).expect("the flap stays");
    let flap = face_at(&f, DVec2::new(90.0, 50.0));
    assert_eq!(
        f.current().faces[flap].transform,
        before.current().faces[1].transform
    );
}

#[test]
fn a_flap_folds_on_about_its_own_crease_to_lie_flat() {
    let mut f = with_flap();
    // The fold line is the flap's hinge, in the flap's plane; the whole flap turns on.
    let on = Fold {
        line: [p(80.0, 0.0), p(80.0, 100.0)],
        moving: DVec3::new(80.0, 50.0, 10.0),
        turn: Turn::Angle(90.0),
        layers: Layers::All,
    };
    let report = f.fold(&on, None).expect("folds on");
    assert_eq!((report.moved, report.split), (1, 0));
    let state = f.current();
    assert_eq!(state.groups.len(), 1);
    let flap = face_at(&f, DVec2::new(90.0, 50.0));
    assert_eq!(state.groups[0].stack.last(), Some(&flap), "on top");
    assert!(
        f.corners(&state.faces[flap])
            .iter()
            .all(|c| c.z.abs() < 1e-9 && c.x > 60.0 - 1e-9)
    );
    assert!(layer_problems(&f, state).is_empty());
    assert!(check(&crease_pattern(&f).pattern, &CheckOptions::default()).passed());
    assert_eq!(crease_at(&f, 80.0).0, Assignment::Valley);
    // Folding the whole paper about a line it lies beside is still refused.
    let beside = Fold {
        line: [p(-10.0, 0.0), p(-10.0, 100.0)],
        moving: p(50.0, 50.0),
        turn: Turn::Angle(90.0),
        layers: Layers::All,
    };
    let before = f.clone();
    let err = f.fold(&beside, None).expect_err("nothing stays");
    assert!(matches!(err, FoldError::LineMissesSheet(_)), "{err}");
    assert_eq!(f, before);
}
