//! Segment–segment and point–segment relations.

use glam::DVec2;

/// Where two segments meet.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Crossing {
    /// They do not meet.
    None,
    /// They meet at one point, at parameters `t` on the first and `u` on the second (0..=1).
    Point {
        /// Parameter on the first segment.
        t: f64,
        /// Parameter on the second segment.
        u: f64,
    },
    /// They are collinear and overlap.
    Overlap,
}

/// Intersects segments `a0–a1` and `b0–b1`. `eps` is the tolerance on the cross product,
/// relative to the product of the lengths, below which segments count as parallel; collinear
/// segments that share less than `eps` of the first's length touch at a point.
pub fn intersect(a0: DVec2, a1: DVec2, b0: DVec2, b1: DVec2, eps: f64) -> Crossing {
    let r = a1 - a0;
    let s = b1 - b0;
    let denom = r.perp_dot(s);
    let qp = b0 - a0;
    let scale = r.length() * s.length();
    if scale == 0.0 {
        return Crossing::None;
    }
    if denom.abs() <= eps * scale {
        // Parallel: overlapping when collinear and their projections overlap.
        if qp.perp_dot(r).abs() > eps * r.length() * qp.length().max(s.length()) {
            return Crossing::None;
        }
        let rr = r.length_squared();
        let t0 = qp.dot(r) / rr;
        let t1 = (b1 - a0).dot(r) / rr;
        let (lo, hi) = if t0 < t1 { (t0, t1) } else { (t1, t0) };
        let (from, to) = (lo.max(0.0), hi.min(1.0));
        return if from > to {
            Crossing::None
        } else if to - from <= eps {
            // Collinear, touching end to end at one point.
            let u = (a0.lerp(a1, from) - b0).dot(s) / s.length_squared();
            Crossing::Point {
                t: from,
                u: u.clamp(0.0, 1.0),
            }
        } else {
            Crossing::Overlap
        };
    }
    let t = qp.perp_dot(s) / denom;
    let u = qp.perp_dot(r) / denom;
    if (0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&u) {
        Crossing::Point { t, u }
    } else {
        Crossing::None
    }
}

/// Parameter of the point on segment `a–b` closest to `p`, clamped to [0, 1].
pub fn project(a: DVec2, b: DVec2, p: DVec2) -> f64 {
    let d = b - a;
    let l2 = d.length_squared();
    if l2 == 0.0 {
        0.0
    } else {
        ((p - a).dot(d) / l2).clamp(0.0, 1.0)
    }
}

/// Distance from `p` to segment `a–b`.
pub fn distance_to_point(a: DVec2, b: DVec2, p: DVec2) -> f64 {
    let t = project(a, b, p);
    a.lerp(b, t).distance(p)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crossing_diagonals_meet_in_the_middle() {
        let c = intersect(
            DVec2::ZERO,
            DVec2::ONE,
            DVec2::new(0.0, 1.0),
            DVec2::new(1.0, 0.0),
            1e-12,
        );
        assert_eq!(c, Crossing::Point { t: 0.5, u: 0.5 });
    }

    #[test]
    fn collinear_overlap_and_disjoint() {
        let a = (DVec2::ZERO, DVec2::new(2.0, 0.0));
        let near = intersect(a.0, a.1, DVec2::new(1.0, 0.0), DVec2::new(3.0, 0.0), 1e-12);
        let far = intersect(a.0, a.1, DVec2::new(3.0, 0.0), DVec2::new(4.0, 0.0), 1e-12);
        assert_eq!(near, Crossing::Overlap);
        assert_eq!(far, Crossing::None);
        let end_to_end = intersect(a.0, a.1, a.1, DVec2::new(5.0, 0.0), 1e-12);
        assert_eq!(end_to_end, Crossing::Point { t: 1.0, u: 0.0 });
    }
}
