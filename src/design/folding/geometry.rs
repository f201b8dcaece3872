//! Plane geometry of convex faces: a directed line and its sides, splitting a convex polygon by
//! a line (Miyazaki et al. 1992, §4.2, §4.3), positive-area overlap of two convex polygons (the overlap tests of the
//! moving-face search, §4.1), and rotations about a line in space.
//!
//! Every predicate takes an explicit tolerance in millimetres: points closer than `tol` to a
//! line count as on it, and overlaps thinner than `tol` count as touching, not overlapping.

use glam::{DAffine3, DVec2, DVec3};

use crate::geom::Segment;
use crate::geom::tolerance::TINY;

/// A directed line in a plane: a point and a unit direction. Its left side is positive.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Line2 {
    /// A point on the line.
    pub point: DVec2,
    /// Unit direction.
    pub dir: DVec2,
}

impl Line2 {
    /// The line through `a` and `b`, or `None` when they are closer than `tol`.
    pub fn through(a: DVec2, b: DVec2, tol: f64) -> Option<Line2> {
        let d = b - a;
        let len = d.length();
        (len > tol && len.is_finite()).then(|| Line2 {
            point: a,
            dir: d / len,
        })
    }

    /// Signed distance of `p` from the line: positive on the left.
    pub fn side(&self, p: DVec2) -> f64 {
        self.dir.perp_dot(p - self.point)
    }

    /// The mirror image of `p` across the line.
    pub fn reflect(&self, p: DVec2) -> DVec2 {
        p - 2.0 * self.side(p) * self.dir.perp()
    }
}

/// Twice the signed area of a polygon (positive when counter-clockwise).
pub fn double_area(poly: &[DVec2]) -> f64 {
    let n = poly.len();
    (0..n).map(|i| poly[i].perp_dot(poly[(i + 1) % n])).sum()
}

/// Both parts of a convex polygon: the one left of `line` appended to `left`, the one right
/// of it to `right`. Corners within `tol` of the line are snapped onto it; a part thinner
/// than `tol` appends nothing.
pub fn split_into(
    poly: &[DVec2],
    line: &Line2,
    tol: f64,
    left: &mut Vec<DVec2>,
    right: &mut Vec<DVec2>,
) {
    with_distances(poly, line, tol, |dist| {
        emit(poly, dist, line, 1.0, tol, left);
        emit(poly, dist, line, -1.0, tol, right);
    });
}

/// Calls `f` with the signed distances of the corners from the line, those within `tol`
/// set to 0 (on the stack for the small polygons folding makes).
fn with_distances(poly: &[DVec2], line: &Line2, tol: f64, f: impl FnOnce(&[f64])) {
    let d = |p: DVec2| {
        let s = line.side(p);
        if s.abs() <= tol { 0.0 } else { s }
    };
    let mut small = [0.0f64; 16];
    let mut large = Vec::new();
    let dist: &mut [f64] = if poly.len() <= small.len() {
        &mut small[..poly.len()]
    } else {
        large.resize(poly.len(), 0.0);
        &mut large
    };
    for (slot, &p) in dist.iter_mut().zip(poly) {
        *slot = d(p);
    }
    f(dist)
}

/// Appends the part of `poly` where `sign × dist` is not negative (see [`split_into`]).
fn emit(poly: &[DVec2], dist: &[f64], line: &Line2, sign: f64, tol: f64, out: &mut Vec<DVec2>) {
    if dist.iter().all(|&s| sign * s <= tol) {
        return;
    }
    let n = poly.len();
    let start = out.len();
    out.reserve(n + 1);
    let (mut p, mut sp) = (poly[n - 1], sign * dist[n - 1]);
    for (&q, &d) in poly.iter().zip(dist) {
        // The edge from the previous corner `p` to `q`: its start, then a crossing.
        let sq = sign * d;
        if (sp > 0.0 && sq < 0.0) || (sp < 0.0 && sq > 0.0) {
            out.push(p + (q - p) * (sp / (sp - sq)));
        }
        if sq >= 0.0 {
            out.push(if sq == 0.0 { onto(line, q) } else { q });
        }
        (p, sp) = (q, sq);
    }
    dedup_ring(out, start, tol);
    if out.len() - start < 3 {
        out.truncate(start);
    }
}

/// The foot of `p` on the line.
fn onto(line: &Line2, p: DVec2) -> DVec2 {
    line.point + line.dir * line.dir.dot(p - line.point)
}

/// Removes consecutive vertices closer than `tol` (cyclically) from the ring `ring[start..]`.
fn dedup_ring(ring: &mut Vec<DVec2>, start: usize, tol: f64) {
    let tol2 = tol * tol;
    let mut kept = start;
    for i in start..ring.len() {
        if kept == start || ring[kept - 1].distance_squared(ring[i]) > tol2 {
            ring[kept] = ring[i];
            kept += 1;
        }
    }
    ring.truncate(kept);
    while ring.len() > start + 1 && ring[start].distance_squared(ring[ring.len() - 1]) <= tol2 {
        ring.pop();
    }
}

/// Whether two convex polygons overlap in an area wider than `tol` in every direction
/// (separating-axis test over both polygons' edge normals).
pub fn overlaps(a: &[DVec2], b: &[DVec2], tol: f64) -> bool {
    !(separated_by_edges_of(a, b, tol) || separated_by_edges_of(b, a, tol))
}

fn separated_by_edges_of(a: &[DVec2], b: &[DVec2], tol: f64) -> bool {
    let n = a.len();
    (0..n).any(|i| {
        let axis = (a[(i + 1) % n] - a[i]).perp().normalize_or_zero();
        if axis == DVec2::ZERO {
            return false;
        }
        let (lo_a, hi_a) = project(a, axis);
        let (lo_b, hi_b) = project(b, axis);
        hi_a.min(hi_b) - lo_a.max(lo_b) <= tol
    })
}

fn project(poly: &[DVec2], axis: DVec2) -> (f64, f64) {
    poly.iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            let t = p.dot(axis);
            (lo.min(t), hi.max(t))
        })
}

/// Whether the open segment `p`–`q` runs through the interior of the convex polygon `poly`
/// (counter-clockwise) over a length longer than `tol`, staying farther than `tol` from its
/// boundary somewhere.
pub fn segment_crosses_interior(p: DVec2, q: DVec2, poly: &[DVec2], tol: f64) -> bool {
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    let d = q - p;
    let len = d.length();
    if len <= tol {
        return false;
    }
    let n = poly.len();
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        let Some(edge) = Line2::through(a, b, 0.0) else {
            continue;
        };
        // Inside means left of every edge by more than tol.
        let s0 = edge.side(p) - tol;
        let ds = edge.dir.perp_dot(d);
        if ds.abs() < TINY {
            if s0 <= 0.0 {
                return false;
            }
            continue;
        }
        let t = -s0 / ds;
        if ds > 0.0 {
            t0 = t0.max(t);
        } else {
            t1 = t1.min(t);
        }
    }
    (t1 - t0) * len > tol
}

/// Whether `p` lies inside the convex polygon `poly` of either orientation, or within `tol`.
pub fn contains_either(poly: &[DVec2], p: DVec2, tol: f64) -> bool {
    let sign = if double_area(poly) >= 0.0 { 1.0 } else { -1.0 };
    contains_oriented(poly, p, tol, sign)
}

/// [`contains_either`] with the ring's orientation given: `sign` is +1 for counter-clockwise
/// (or degenerate), −1 for clockwise.
pub(super) fn contains_oriented(poly: &[DVec2], p: DVec2, tol: f64, sign: f64) -> bool {
    let n = poly.len();
    (0..n).all(|i| match Line2::through(poly[i], poly[(i + 1) % n], 0.0) {
        Some(edge) => sign * edge.side(p) >= -tol,
        None => true,
    })
}

/// The overlap, longer than `tol`, of segment `a0`–`a1` with the collinear segment `b0`–`b1`
/// (both within `tol` of one line), or `None`.
pub fn shared_segment(a0: DVec2, a1: DVec2, b0: DVec2, b1: DVec2, tol: f64) -> Option<Segment> {
    // Collinearity first, without a square root (most pairs fail here).
    let d = a1 - a0;
    let limit = tol * tol * d.length_squared();
    let off = |p: DVec2| {
        let c = d.perp_dot(p - a0);
        c * c > limit
    };
    if off(b0) || off(b1) {
        return None;
    }
    let line = Line2::through(a0, a1, tol)?;
    let t = |p: DVec2| line.dir.dot(p - a0);
    let (tb0, tb1) = (t(b0), t(b1));
    let lo = tb0.min(tb1).max(0.0);
    let hi = tb0.max(tb1).min(t(a1));
    (hi - lo > tol).then(|| Segment::new(a0 + line.dir * lo, a0 + line.dir * hi))
}

/// The rigid motion turning space by `angle` radians about the axis through `point` along the
/// unit vector `axis` (right-handed).
pub fn rotation_about(point: DVec3, axis: DVec3, angle: f64) -> DAffine3 {
    DAffine3::from_translation(point)
        * DAffine3::from_axis_angle(axis, angle)
        * DAffine3::from_translation(-point)
}

/// An orthonormal in-plane basis `(u, v)` with `u × v = normal`.
pub fn plane_basis(normal: DVec3) -> (DVec3, DVec3) {
    let u = normal.any_orthonormal_vector();
    (u, normal.cross(u))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square() -> Vec<DVec2> {
        vec![
            DVec2::new(0.0, 0.0),
            DVec2::new(1.0, 0.0),
            DVec2::new(1.0, 1.0),
            DVec2::new(0.0, 1.0),
        ]
    }

    /// The parts of `poly` left and right of `line`.
    fn halves(poly: &[DVec2], line: &Line2) -> (Vec<DVec2>, Vec<DVec2>) {
        let (mut left, mut right) = (Vec::new(), Vec::new());
        split_into(poly, line, 1e-9, &mut left, &mut right);
        (left, right)
    }

    #[test]
    fn a_diagonal_splits_the_square_into_two_halves() {
        let line = Line2::through(DVec2::ZERO, DVec2::ONE, 1e-12).unwrap();
        let (left, right) = halves(&square(), &line);
        assert_eq!((left.len(), right.len()), (3, 3));
        assert!((double_area(&left) - 1.0).abs() < 1e-12);
        assert!((double_area(&right) - 1.0).abs() < 1e-12);
        // An edge of the square: nothing on its outer side.
        let edge = Line2::through(DVec2::ZERO, DVec2::X, 1e-12).unwrap();
        assert!(halves(&square(), &edge).1.is_empty());
        assert_eq!(halves(&square(), &edge).0.len(), 4);
    }

    #[test]
    fn touching_squares_do_not_overlap() {
        let moved: Vec<DVec2> = square().iter().map(|p| *p + DVec2::X).collect();
        assert!(!overlaps(&square(), &moved, 1e-9));
        let half: Vec<DVec2> = square().iter().map(|p| *p + DVec2::X * 0.5).collect();
        assert!(overlaps(&square(), &half, 1e-9));
    }

    #[test]
    fn segments_through_and_along_a_square() {
        let sq = square();
        assert!(segment_crosses_interior(
            DVec2::new(-1.0, 0.5),
            DVec2::new(2.0, 0.5),
            &sq,
            1e-9
        ));
        assert!(!segment_crosses_interior(
            DVec2::new(-1.0, 0.0),
            DVec2::new(2.0, 0.0),
            &sq,
            1e-9
        ));
        let s = shared_segment(
            DVec2::ZERO,
            DVec2::X,
            DVec2::new(0.5, 0.0),
            DVec2::new(3.0, 0.0),
            1e-9,
        );
        assert_eq!(s, Some(Segment::new(DVec2::new(0.5, 0.0), DVec2::X)));
    }
}
