//! Geometry in space (millimetres): which axis-aligned boxes overlap, by a sweep along x, and
//! where a segment passes through a triangle. The broad and the exact phase of the
//! face-intersection tests of tessellations and of 3D folding.

use std::ops::ControlFlow;

use glam::DVec3;

/// An axis-aligned box in space: its lowest and its highest corner.
pub type Box3 = (DVec3, DVec3);

/// The bounding box of triangle `t`, grown by `margin` (≥ 0) on every side.
pub fn triangle_box(t: &[DVec3; 3], margin: f64) -> Box3 {
    (
        t[0].min(t[1]).min(t[2]) - DVec3::splat(margin),
        t[0].max(t[1]).max(t[2]) + DVec3::splat(margin),
    )
}

/// Calls `visit(a, b)` once for every pair of boxes that overlap (closed: boxes that touch
/// overlap), by sorting the boxes along x and sweeping: `O(n log n)` plus the pairs whose x
/// ranges overlap. Pairs come in sweep order (`a`'s lower x is at most `b`'s); the sweep stops
/// when `visit` breaks.
pub fn overlapping_boxes(boxes: &[Box3], mut visit: impl FnMut(usize, usize) -> ControlFlow<()>) {
    let mut order: Vec<usize> = (0..boxes.len()).collect();
    order.sort_by(|&a, &b| boxes[a].0.x.total_cmp(&boxes[b].0.x));
    for (n, &a) in order.iter().enumerate() {
        for &b in &order[n + 1..] {
            if boxes[b].0.x > boxes[a].1.x {
                break;
            }
            let apart = (boxes[a].0.cmpgt(boxes[b].1) | boxes[b].0.cmpgt(boxes[a].1)).any();
            if !apart && visit(a, b).is_break() {
                return;
            }
        }
    }
}

/// Below this `|det|` (mm³ for millimetre input) a segment counts as parallel to the
/// triangle's plane in [`segment_through_triangle`].
pub const PARALLEL_DETERMINANT: f64 = 1e-15;

/// Where segment `p`–`q` passes through the closed triangle `t`, if it does: Möller and
/// Trumbore's (1997) ray–triangle test restricted to the segment. A segment parallel to the
/// triangle's plane ([`PARALLEL_DETERMINANT`]) never passes through it.
pub fn segment_through_triangle(p: DVec3, q: DVec3, t: &[DVec3; 3]) -> Option<DVec3> {
    let d = q - p;
    let (e1, e2) = (t[1] - t[0], t[2] - t[0]);
    let h = d.cross(e2);
    let det = e1.dot(h);
    if det.abs() < PARALLEL_DETERMINANT {
        return None;
    }
    let s = p - t[0];
    let u = s.dot(h) / det;
    let qv = s.cross(e1);
    let v = d.dot(qv) / det;
    let w = e2.dot(qv) / det;
    ((0.0..=1.0).contains(&u) && v >= 0.0 && u + v <= 1.0 && (0.0..=1.0).contains(&w))
        .then(|| p + w * d)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_rng::TestRng;

    #[test]
    fn the_sweep_finds_exactly_the_pairs_a_full_comparison_finds() {
        let mut rng = TestRng::new(11);
        let boxes: Vec<Box3> = (0..300)
            .map(|_| {
                let lo = DVec3::new(rng.unit(), rng.unit(), rng.unit()) * 100.0;
                (
                    lo,
                    lo + DVec3::new(rng.unit(), rng.unit(), rng.unit()) * 12.0,
                )
            })
            .collect();
        let mut swept = Vec::new();
        overlapping_boxes(&boxes, |a, b| {
            swept.push((a.min(b), a.max(b)));
            ControlFlow::Continue(())
        });
        swept.sort_unstable();
        let mut all = Vec::new();
        for a in 0..boxes.len() {
            for b in a + 1..boxes.len() {
                let (p, q) = (boxes[a], boxes[b]);
                if p.0.cmple(q.1).all() && q.0.cmple(p.1).all() {
                    all.push((a, b));
                }
            }
        }
        assert!(!all.is_empty());
        assert_eq!(swept, all);
        // Breaking stops the sweep at the first pair.
        let mut seen = 0;
        overlapping_boxes(&boxes, |_, _| {
            seen += 1;
            ControlFlow::Break(())
        });
        assert_eq!(seen, 1);
    }

    #[test]
    fn a_segment_passes_through_a_triangle_where_it_meets_its_plane() {
        let t = [
            DVec3::ZERO,
            DVec3::new(4.0, 0.0, 0.0),
            DVec3::new(0.0, 4.0, 0.0),
        ];
        let hit =
            segment_through_triangle(DVec3::new(1.0, 1.0, -2.0), DVec3::new(1.0, 1.0, 6.0), &t);
        assert_eq!(hit, Some(DVec3::new(1.0, 1.0, 0.0)));
        // Ends short of the plane, outside the triangle, parallel to it.
        let p = DVec3::new(1.0, 1.0, 1.0);
        assert_eq!(
            segment_through_triangle(p, DVec3::new(1.0, 1.0, 3.0), &t),
            None
        );
        assert_eq!(
            segment_through_triangle(DVec3::new(3.0, 3.0, -1.0), DVec3::new(3.0, 3.0, 1.0), &t),
            None
        );
        assert_eq!(
            segment_through_triangle(p, DVec3::new(2.0, 1.0, 1.0), &t),
            None
        );
    }
}
