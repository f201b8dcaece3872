//! Triangles of a folded sheet that pass through each other.
//!
//! Broad phase: sweep and prune on x over the triangles' bounding boxes grown by the
//! tolerance. Narrow phase: two triangles that share no side cross when a side of one
//! pierces the other, i.e. its ends lie on opposite sides of the other's plane, each farther
//! than the tolerance, and the piercing point lies inside the other triangle by more than the
//! tolerance. Triangles in one plane (stacked layers of a flat fold) touch but do not cross
//! and are not reported; nor are triangles that meet within the tolerance.

use std::ops::ControlFlow;

use glam::DVec3;

use crate::geom::{Box3, overlapping_boxes, triangle_box};

/// Pairs of triangles (indices, lower first) that pass through each other, at most `limit` of
/// them, with `tolerance` in the unit of the positions.
pub fn crossing_triangles(
    positions: &[DVec3],
    triangles: &[[u32; 3]],
    tolerance: f64,
    limit: usize,
) -> Vec<(u32, u32)> {
    let corners = |t: usize| triangles[t].map(|v| positions[v as usize]);
    let boxes: Vec<Box3> = (0..triangles.len())
        .map(|t| triangle_box(&corners(t), tolerance))
        .collect();
    let mut found = Vec::new();
    overlapping_boxes(&boxes, |a, b| {
        // Triangles sharing a side (a hinge) cross only by folding past flat, which the
        // hinge's angle tells; a shared corner alone does not stop the far side of one from
        // piercing the other (the sides from the shared corner start in the other's plane and
        // are never counted).
        if triangles[a]
            .iter()
            .filter(|v| triangles[b].contains(v))
            .count()
            >= 2
        {
            return ControlFlow::Continue(());
        }
        let (ta, tb) = (corners(a), corners(b));
        if pierces(&ta, &tb, tolerance) || pierces(&tb, &ta, tolerance) {
            found.push((a.min(b) as u32, a.max(b) as u32));
            if found.len() >= limit {
                return ControlFlow::Break(());
            }
        }
        ControlFlow::Continue(())
    });
    found
}

/// Whether a side of `t` pierces the interior of `u`.
fn pierces(t: &[DVec3; 3], u: &[DVec3; 3], tol: f64) -> bool {
    let normal = (u[1] - u[0]).cross(u[2] - u[0]);
    let len = normal.length();
    if len <= 0.0 {
        return false;
    }
    let n = normal / len;
    (0..3).any(|s| {
        let (p, q) = (t[s], t[(s + 1) % 3]);
        let (dp, dq) = ((p - u[0]).dot(n), (q - u[0]).dot(n));
        if !((dp > tol && dq < -tol) || (dp < -tol && dq > tol)) {
            return false;
        }
        let hit = p + (q - p) * (dp / (dp - dq));
        (0..3).all(|e| {
            let (a, b) = (u[e], u[(e + 1) % 3]);
            let inward = n.cross(b - a).normalize_or_zero();
            (hit - a).dot(inward) > tol
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_triangle_through_another_is_found_and_a_touching_one_is_not() {
        let p = vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::new(0.0, 2.0, 0.0),
            // Through the first: a vertical triangle crossing z = 0 inside it.
            DVec3::new(0.5, 0.5, -1.0),
            DVec3::new(0.5, 0.5, 1.0),
            DVec3::new(0.6, 0.2, 1.0),
            // Stacked in the plane z = 0 (a flat layer).
            DVec3::new(1.0, 0.1, 0.0),
            DVec3::new(1.8, 0.1, 0.0),
            DVec3::new(1.0, 0.9, 0.0),
        ];
        let tris = [[0, 1, 2], [3, 4, 5], [6, 7, 8]];
        assert_eq!(crossing_triangles(&p, &tris, 1e-9, 10), vec![(0, 1)]);
    }

    #[test]
    fn a_shared_corner_does_not_hide_a_crossing_but_a_shared_side_does() {
        let p = vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::new(0.0, 2.0, 0.0),
            // From the shared corner 0, its far side pierces the first triangle.
            DVec3::new(1.0, 0.4, -1.0),
            DVec3::new(0.4, 1.0, 1.0),
        ];
        assert_eq!(
            crossing_triangles(&p, &[[0, 1, 2], [0, 3, 4]], 1e-9, 10),
            vec![(0, 1)]
        );
        // Sharing the side 0–1 (a hinge), the wings are left to the hinge's angle.
        assert!(crossing_triangles(&p, &[[0, 1, 2], [0, 1, 4]], 1e-9, 10).is_empty());
    }
}
