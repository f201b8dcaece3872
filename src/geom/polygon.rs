//! Simple polygons given as rings of points.

use glam::DVec2;

use super::segment::{Crossing, intersect};
use super::tolerance::ROUNDOFF;

/// Signed area of a closed ring (shoelace formula): positive when counter-clockwise.
pub fn signed_area(ring: impl IntoIterator<Item = DVec2>) -> f64 {
    let mut iter = ring.into_iter();
    let Some(first) = iter.next() else {
        return 0.0;
    };
    let mut prev = first;
    let mut twice = 0.0;
    for p in iter {
        twice += prev.perp_dot(p);
        prev = p;
    }
    twice += prev.perp_dot(first);
    0.5 * twice
}

/// Whether `p` lies inside the closed ring (even–odd rule; points on the boundary may go
/// either way).
pub fn contains_point(ring: &[DVec2], p: DVec2) -> bool {
    let mut inside = false;
    let n = ring.len();
    for i in 0..n {
        let a = ring[i];
        let b = ring[(i + 1) % n];
        if (a.y > p.y) != (b.y > p.y) {
            let x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
            if p.x < x {
                inside = !inside;
            }
        }
    }
    inside
}

/// Whether the segment `a b` meets any edge of the closed ring (touching counts).
pub fn segment_crosses_ring(ring: &[DVec2], a: DVec2, b: DVec2) -> bool {
    let n = ring.len();
    (0..n).any(|i| intersect(a, b, ring[i], ring[(i + 1) % n], ROUNDOFF) != Crossing::None)
}

/// The closed ring `ring` (first point not repeated) without sides shorter than `min_len` and
/// without bevels: a side whose neighbours' lines meet within `tolerance` of it, no farther
/// from either of its ends than its length (a short round join of an offset is such a bevel).
/// Either becomes one point: where the neighbours' lines meet when that point is a bevel's
/// corner, else (a side shorter than `min_len` that is no bevel) the side's midpoint. So one
/// merge moves the path by at most `tolerance` at a bevel and under `min_len` elsewhere, and the
/// sides left are at least `min_len` long. A ring that would keep fewer than three points is
/// returned as it was. Cost O(n log n) for typical rings (each pass merges every other side
/// it can), O(n²) at worst.
pub fn merge_short_sides(ring: &[DVec2], min_len: f64, tolerance: f64) -> Vec<DVec2> {
    let mut pts = ring.to_vec();
    loop {
        let n = pts.len();
        if n <= 3 {
            break;
        }
        let mut merged: Vec<Option<DVec2>> = vec![None; n];
        let mut removed = vec![false; n];
        let mut any = false;
        let mut i = 0;
        while i < n {
            let j = (i + 1) % n;
            let untouched =
                !removed[i] && !removed[j] && merged[i].is_none() && merged[j].is_none();
            let before = pts[(i + n - 1) % n];
            let after = pts[(j + 1) % n];
            let point = untouched
                .then(|| joint(before, pts[i], pts[j], after, min_len, tolerance))
                .flatten();
            if let Some(q) = point {
                merged[i] = Some(q);
                removed[j] = true;
                any = true;
                i += 2;
            } else {
                i += 1;
            }
        }
        if !any {
            break;
        }
        pts = (0..n)
            .filter(|&k| !removed[k])
            .map(|k| merged[k].unwrap_or(pts[k]))
            .collect();
    }
    if pts.len() < 3 { ring.to_vec() } else { pts }
}

/// The one point replacing side `b c` between sides `a b` and `c d`, if it goes (see
/// [`merge_short_sides`]).
fn joint(a: DVec2, b: DVec2, c: DVec2, d: DVec2, min_len: f64, tolerance: f64) -> Option<DVec2> {
    let (u, v, side) = (b - a, d - c, c - b);
    let len = side.length();
    let denom = u.perp_dot(v);
    if denom.abs() > ROUNDOFF * u.length() * v.length() {
        let q = b + u * (side.perp_dot(v) / denom);
        let off_side = if len > 0.0 {
            (q - b).perp_dot(side).abs() / len
        } else {
            q.distance(b)
        };
        let bevel = q.distance(b) <= len && q.distance(c) <= len && off_side <= tolerance;
        if q.is_finite() && bevel {
            return Some(q);
        }
    }
    (len < min_len).then(|| (b + c) / 2.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_sides_merge_into_the_corner_of_their_neighbours() {
        // A square with its corner (10, 0) cut by a 0.7 µm chamfer, and its top side in three
        // collinear pieces, the middle one 0.4 µm: both come out as the plain square (a point
        // on a straight side is a bevel of no deviation).
        let ring = [
            DVec2::new(0.0, 0.0),
            DVec2::new(10.0 - 0.0005, 0.0),
            DVec2::new(10.0, 0.0005),
            DVec2::new(10.0, 10.0),
            DVec2::new(5.0002, 10.0),
            DVec2::new(4.9998, 10.0),
            DVec2::new(0.0, 10.0),
        ];
        let out = merge_short_sides(&ring, 0.001, 0.0005);
        let square = [(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)];
        assert_eq!(out.len(), 4, "{out:?}");
        for (p, (x, y)) in out.iter().zip(square) {
            assert!(p.distance(DVec2::new(x, y)) < 1e-9, "{out:?}");
        }
        let n = out.len();
        assert!((0..n).all(|k| out[k].distance(out[(k + 1) % n]) >= 0.001));
        // A ring of sides all long enough is kept; a tiny triangle is kept whole.
        assert_eq!(merge_short_sides(&out, 0.001, 0.0005), out);
        let tiny = [DVec2::ZERO, DVec2::new(1e-4, 0.0), DVec2::new(0.0, 1e-4)];
        assert_eq!(merge_short_sides(&tiny, 0.001, 0.0005), tiny.to_vec());
        // A 5 µm bevel across a 3° turn is merged into its corner (0.07 µm away); a 0.3 mm
        // chord across the same turn is geometry (its corner is 4 µm away) and stays.
        let turn = 3f64.to_radians();
        let bevel = |len: f64| {
            let c = DVec2::new(10.0, 0.0) + DVec2::from_angle(turn) * len / 2.0;
            let b = DVec2::new(10.0, 0.0) - DVec2::X * len / 2.0;
            vec![
                DVec2::ZERO,
                b,
                c,
                c + DVec2::from_angle(turn) * 10.0,
                DVec2::new(0.0, 10.0),
            ]
        };
        assert_eq!(merge_short_sides(&bevel(0.005), 0.001, 0.0005).len(), 4);
        assert_eq!(merge_short_sides(&bevel(0.3), 0.001, 0.0005).len(), 5);
    }

    #[test]
    fn unit_square_area_and_orientation() {
        let sq = [
            DVec2::new(0.0, 0.0),
            DVec2::new(1.0, 0.0),
            DVec2::new(1.0, 1.0),
            DVec2::new(0.0, 1.0),
        ];
        assert_eq!(signed_area(sq), 1.0);
        assert_eq!(signed_area(sq.iter().rev().copied()), -1.0);
        assert!(contains_point(&sq, DVec2::new(0.5, 0.5)));
        assert!(!contains_point(&sq, DVec2::new(1.5, 0.5)));
    }
}
