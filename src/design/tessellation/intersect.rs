//! Face intersections of the folded form (the "no face intersections"; Tachi (2014) §3.2 calls
//! them type 1–3 collisions): exact triangle–triangle tests between every pair of faces whose
//! bounding boxes meet, found by a sweep along x.
//!
//! Two triangles intersect when they cross transversally over a segment longer than the
//! tolerance (mm): each has vertices farther than the tolerance on both sides of the other's
//! plane, the two cuts are intervals on the planes' common line, and the intervals overlap by
//! more than the tolerance. So faces that only touch do not count, and coplanar faces
//! (stacked layers, contact without penetration) do not either. The cuts are measured
//! exactly (a vertex lies on the other plane only within float noise): counting a vertex
//! within the tolerance as on the plane stretched the cut of a face meeting the other plane
//! at a shallow angle, and reported nearly closed tucks whose corners only touch (measured on
//! a remeshed 450-face cap, 20°, shrink 0.8: 15–24 of 174 pairs).
//!
//! Faces sharing a vertex are tested by the same rule, which then only looks at the part
//! that is not shared: a triangle whose opposite edge does not cross the other's plane meets
//! it in the shared vertex alone. Faces sharing an edge are not tested: from positions alone
//! they meet along that edge or lie in one plane, never cross (eq. 3 keeps their fold inside
//! (−180°, 180°)).

use std::ops::ControlFlow;

use glam::DVec3;

use super::TessError;
use crate::geom::tolerance::ROUNDOFF;
use crate::geom::{Box3, overlapping_boxes, triangle_box};
use crate::pattern::FoldedState;

/// A vertex this close (mm) to the other triangle's plane lies on it when the cut is measured:
/// the float noise of a shared vertex, far under any sheet thickness.
const ON_PLANE: f64 = 1e-9;

/// Pairs `(a, b)`, `a < b`, of triangles of `positions` that intersect by more than
/// `tolerance` (mm, ≥ 0). Degenerate (zero-area) triangles are skipped.
pub fn intersecting_triangles(
    positions: &[DVec3],
    triangles: &[[u32; 3]],
    tolerance: f64,
) -> Result<Vec<(usize, usize)>, TessError> {
    if !(tolerance >= 0.0 && tolerance.is_finite()) {
        return Err(TessError::BadParameter(format!(
            "intersection tolerance must be a finite length >= 0 mm, got {tolerance}"
        )));
    }
    if let Some((t, _)) = triangles
        .iter()
        .enumerate()
        .find(|(_, t)| t.iter().any(|&v| v as usize >= positions.len()))
    {
        return Err(TessError::BadParameter(format!(
            "triangle {t} names a vertex beyond the {} positions",
            positions.len()
        )));
    }
    let tris: Vec<[DVec3; 3]> = triangles
        .iter()
        .map(|t| t.map(|v| positions[v as usize]))
        .collect();
    if tris.iter().flatten().any(|p| !p.is_finite()) {
        return Err(TessError::BadParameter(
            "a vertex position is not finite".into(),
        ));
    }
    let boxes: Vec<Box3> = tris.iter().map(|t| triangle_box(t, 0.0)).collect();
    let mut out = Vec::new();
    overlapping_boxes(&boxes, |a, b| {
        let shared = triangles[a]
            .iter()
            .filter(|v| triangles[b].contains(v))
            .count();
        if shared < 2 && triangles_cross(&tris[a], &tris[b], tolerance) {
            out.push((a.min(b), a.max(b)));
        }
        ControlFlow::Continue(())
    });
    out.sort_unstable();
    Ok(out)
}

/// Pairs of faces of `folded` that intersect by more than `tolerance` (mm); see the module
/// docs. Errors: no faces, a face that is not a triangle, a bad index or tolerance.
pub fn folded_intersections(
    folded: &FoldedState,
    tolerance: f64,
) -> Result<Vec<(usize, usize)>, TessError> {
    let faces = folded
        .faces
        .as_ref()
        .ok_or_else(|| TessError::BadParameter("the folded state has no faces to test".into()))?;
    let mut triangles = Vec::with_capacity(faces.len());
    for (k, f) in faces.iter().enumerate() {
        let [a, b, c] = f.outer[..] else {
            return Err(TessError::BadParameter(format!(
                "face {k} has {} corners; the intersection test takes triangles",
                f.outer.len()
            )));
        };
        triangles.push([a, b, c].map(|v| v.index() as u32));
    }
    intersecting_triangles(&folded.positions, &triangles, tolerance)
}

/// Whether triangles `a` and `b` cross over a segment longer than `tol` (module docs).
pub fn triangles_cross(a: &[DVec3; 3], b: &[DVec3; 3], tol: f64) -> bool {
    let (na, nb) = (normal(a), normal(b));
    let (Some(na), Some(nb)) = (na, nb) else {
        return false;
    };
    let da = a.map(|p| nb.dot(p - b[0]));
    let db = b.map(|p| na.dot(p - a[0]));
    if !straddles(&da, tol) || !straddles(&db, tol) {
        return false;
    }
    let line = na.cross(nb);
    if line.length() < ROUNDOFF {
        return false; // parallel planes within the tolerance: contact, not penetration
    }
    let line = line.normalize();
    // The cuts themselves are exact (a vertex lies on the plane only within float noise):
    // counting a vertex within `tol` as on the plane would stretch a cut along a shallow
    // edge by tol / sin(its angle to the plane) and report faces that only touch.
    let on = tol.min(ON_PLANE);
    let (Some(ia), Some(ib)) = (cut(a, &da, line, on), cut(b, &db, line, on)) else {
        return false;
    };
    ia.1.min(ib.1) - ia.0.max(ib.0) > tol
}

fn normal(t: &[DVec3; 3]) -> Option<DVec3> {
    let n = (t[1] - t[0]).cross(t[2] - t[0]);
    (n.length() > 0.0).then(|| n.normalize())
}

/// Whether some signed distance is beyond `tol` on each side (a triangle that does not
/// straddle the other's plane at most touches it).
fn straddles(d: &[f64; 3], tol: f64) -> bool {
    d.iter().any(|&x| x > tol) && d.iter().any(|&x| x < -tol)
}

/// The interval along `line` where triangle `t` (signed distances `d` to the other plane)
/// meets that plane: its vertices within `tol` of it and its edges crossing it.
fn cut(t: &[DVec3; 3], d: &[f64; 3], line: DVec3, tol: f64) -> Option<(f64, f64)> {
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    let mut take = |p: DVec3| {
        let s = p.dot(line);
        lo = lo.min(s);
        hi = hi.max(s);
    };
    for k in 0..3 {
        let (i, j) = (k, (k + 1) % 3);
        if d[i].abs() <= tol {
            take(t[i]);
        }
        if (d[i] > tol && d[j] < -tol) || (d[i] < -tol && d[j] > tol) {
            take(t[i] + (t[j] - t[i]) * (d[i] / (d[i] - d[j])));
        }
    }
    (lo <= hi).then_some((lo, hi))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::segment_through_triangle;

    const T: [DVec3; 3] = [
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(10.0, 0.0, 0.0),
        DVec3::new(0.0, 10.0, 0.0),
    ];

    #[test]
    fn a_triangle_through_another_is_found() {
        let through = [
            DVec3::new(2.0, 2.0, -3.0),
            DVec3::new(2.0, 2.0, 3.0),
            DVec3::new(8.0, 8.0, 0.5),
        ];
        assert!(triangles_cross(&T, &through, 1e-6));
        assert!(triangles_cross(&through, &T, 1e-6));
        // The same triangle lifted above the plane: apart.
        let above = through.map(|p| p + DVec3::new(0.0, 0.0, 3.5));
        assert!(!triangles_cross(&T, &above, 1e-6));
        // Beside the triangle (past its hypotenuse): the cuts do not overlap.
        let beside = through.map(|p| p + DVec3::new(6.0, 6.0, 0.0));
        assert!(!triangles_cross(&T, &beside, 1e-6));
        // Touching the plane at one vertex only: contact, not intersection.
        let touch = [
            DVec3::new(2.0, 2.0, 0.0),
            DVec3::new(2.0, 5.0, 3.0),
            DVec3::new(5.0, 2.0, 3.0),
        ];
        assert!(!triangles_cross(&T, &touch, 1e-6));
        // Coplanar overlap is stacking, not penetration.
        let stacked = T.map(|p| p + DVec3::new(1.0, 1.0, 0.0));
        assert!(!triangles_cross(&T, &stacked, 1e-6));
    }

    #[test]
    fn penetration_under_the_tolerance_is_contact() {
        // A triangle dipping 0.01 mm through the plane, over a 0.1 mm-long cut.
        let dip = [
            DVec3::new(2.0, 2.0, -0.01),
            DVec3::new(2.0, 2.0, 3.0),
            DVec3::new(2.1, 2.0, -0.01),
        ];
        assert!(triangles_cross(&T, &dip, 1e-3));
        assert!(!triangles_cross(&T, &dip, 0.02));
    }

    #[test]
    fn faces_sharing_a_vertex_are_tested_on_their_free_parts() {
        // Shares vertex 0 with T; its opposite edge pierces T.
        let p = vec![
            T[0],
            T[1],
            T[2],
            DVec3::new(5.0, 1.0, -2.0),
            DVec3::new(1.0, 5.0, 2.0),
        ];
        let crossing = intersecting_triangles(&p, &[[0, 1, 2], [0, 3, 4]], 1e-6).unwrap();
        assert_eq!(crossing, vec![(0, 1)]);
        // Folded up out of the plane through the shared vertex only: no intersection.
        let q = vec![
            T[0],
            T[1],
            T[2],
            DVec3::new(-5.0, 1.0, 2.0),
            DVec3::new(1.0, 5.0, 2.0),
        ];
        assert!(
            intersecting_triangles(&q, &[[0, 1, 2], [0, 3, 4]], 1e-6)
                .unwrap()
                .is_empty()
        );
        // Sharing an edge (a fold): never reported.
        let hinge = intersecting_triangles(&p, &[[0, 1, 2], [1, 0, 3]], 1e-6).unwrap();
        assert!(hinge.is_empty());
    }

    /// Length of the segment two triangles share: the span of the points where an edge of
    /// one pierces the other (two non-coplanar triangles meet in a segment whose ends lie on
    /// their edges).
    fn cut_length(a: &[DVec3; 3], b: &[DVec3; 3]) -> f64 {
        let mut pts = Vec::new();
        for (s, t) in [(a, b), (b, a)] {
            for k in 0..3 {
                pts.extend(segment_through_triangle(s[k], s[(k + 1) % 3], t));
            }
        }
        let mut best = 0.0f64;
        for i in 0..pts.len() {
            for j in i + 1..pts.len() {
                best = best.max(pts[i].distance(pts[j]));
            }
        }
        best
    }

    /// Random triangle pairs in a small box, some sharing a vertex: the verdict at tolerance
    /// `tol` agrees with the independent segment length wherever that length is clearly
    /// above or below `tol` (no false positives for pairs sharing a vertex either).
    #[test]
    fn crossings_agree_with_an_independent_segment_test() {
        let mut rng = crate::test_rng::TestRng::new(20);
        let mut point =
            || DVec3::new(rng.unit(), rng.unit(), rng.unit()) * 10.0 - DVec3::splat(5.0);
        let tol = 1e-3;
        let (mut crossing, mut shared_crossing, mut apart) = (0, 0, 0);
        for case in 0..4000 {
            let a = [point(), point(), point()];
            let mut b = [point(), point(), point()];
            let share = case % 2 == 1;
            if share {
                b[0] = a[0];
            }
            let positions = [a[0], a[1], a[2], b[0], b[1], b[2]];
            let tris = if share {
                [[0, 1, 2], [0, 4, 5]]
            } else {
                [[0, 1, 2], [3, 4, 5]]
            };
            let found = !intersecting_triangles(&positions, &tris, tol)
                .unwrap()
                .is_empty();
            let len = cut_length(&a, &b);
            if len > 10.0 * tol {
                assert!(found, "case {case}: cut {len} mm not found");
                if share {
                    shared_crossing += 1;
                } else {
                    crossing += 1;
                }
            } else if len < 0.1 * tol {
                assert!(!found, "case {case}: cut {len} mm reported");
                apart += 1;
            }
        }
        // Every kind of case occurred.
        assert!(crossing > 50 && shared_crossing > 50 && apart > 500);
    }

    /// A face and a tuck triangle of a solved cap (remeshed 450 faces, 20°, truncated stars,
    /// shrink 0.8) whose corners, 0.03 mm apart, only touch: the tuck's corner lies 0.0003 mm
    /// from the face's plane and its edge leaves that plane at under 1°. The independent
    /// segment test finds no cut longer than the tolerance, and neither does the check.
    #[test]
    fn corners_that_only_touch_at_a_shallow_angle_are_not_a_crossing() {
        let face = [
            DVec3::new(10.30411321470706, -25.04556661611415, -4.041720447718484),
            DVec3::new(12.487831749730612, -21.598232144744944, -3.61047849516975),
            DVec3::new(8.401076013910714, -21.635382150523505, -3.0812260190040575),
        ];
        let tuck = [
            DVec3::new(13.39746413540628, -21.051702123409683, -5.430267781393094),
            DVec3::new(12.460701986447607, -21.613895685747817, -3.6104779624885968),
            DVec3::new(14.53625257615459, -18.093236302870825, -3.081226005540167),
        ];
        let tol = 1e-3;
        assert!(cut_length(&face, &tuck) < tol);
        assert!(!triangles_cross(&face, &tuck, tol));
        assert!(!triangles_cross(&tuck, &face, tol));
        // Moved 1 mm along −x and −y, the tuck crosses the face over about 1.2 mm.
        let through = tuck.map(|p| p + DVec3::new(-1.0, -1.0, 0.0));
        assert!(cut_length(&face, &through) > tol);
        assert!(triangles_cross(&face, &through, tol));
    }

    #[test]
    fn bad_input_is_refused() {
        assert!(intersecting_triangles(&T, &[[0, 1, 5]], 1e-6).is_err());
        assert!(intersecting_triangles(&T, &[[0, 1, 2]], f64::NAN).is_err());
        assert!(intersecting_triangles(&[DVec3::NAN; 3], &[[0, 1, 2]], 1e-6).is_err());
    }
}
