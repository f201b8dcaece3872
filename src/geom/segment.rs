//! Straight segments: the [`Segment`] type and the segment–segment and point–segment
//! relations it is built on (also callable on bare end points).

use glam::DVec2;

use super::Rect;
use super::tolerance::ROUNDOFF;

/// The straight segment from `a` to `b`, in the caller's units. A zero-length segment (a
/// point) is allowed: it has length 0, meets nothing in [`Segment::intersect`], and its
/// closest point to anything is `a`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Segment {
    /// Start.
    pub a: DVec2,
    /// End.
    pub b: DVec2,
}

impl Segment {
    /// The segment from `a` to `b`.
    pub const fn new(a: DVec2, b: DVec2) -> Segment {
        Segment { a, b }
    }

    /// Its end points, `[a, b]`.
    pub fn ends(self) -> [DVec2; 2] {
        [self.a, self.b]
    }

    /// `b − a`.
    pub fn vector(self) -> DVec2 {
        self.b - self.a
    }

    /// Its length.
    pub fn length(self) -> f64 {
        self.a.distance(self.b)
    }

    /// The point at parameter `t` (0 at `a`, 1 at `b`; not clamped).
    pub fn at(self, t: f64) -> DVec2 {
        self.a.lerp(self.b, t)
    }

    /// The point halfway.
    pub fn midpoint(self) -> DVec2 {
        (self.a + self.b) * 0.5
    }

    /// The same segment from `b` to `a`.
    pub fn reversed(self) -> Segment {
        Segment::new(self.b, self.a)
    }

    /// Its bounding box.
    pub fn bounds(self) -> Rect {
        Rect::covering(self.ends())
    }

    /// Where it meets `other` (see [`intersect`] for `eps`, relative, and the parameters).
    ///
    /// ```
    /// use foldcam::geom::{Crossing, DVec2, Segment};
    /// let s = Segment::new(DVec2::ZERO, DVec2::new(2.0, 2.0));
    /// let t = Segment::new(DVec2::new(0.0, 2.0), DVec2::new(2.0, 0.0));
    /// assert_eq!(s.intersect(t, 1e-12), Crossing::Point { t: 0.5, u: 0.5 });
    /// ```
    pub fn intersect(self, other: Segment, eps: f64) -> Crossing {
        intersect(self.a, self.b, other.a, other.b, eps)
    }

    /// Parameter of its point closest to `p`, in [0, 1].
    pub fn project(self, p: DVec2) -> f64 {
        project(self.a, self.b, p)
    }

    /// Its point closest to `p`.
    pub fn closest_point(self, p: DVec2) -> DVec2 {
        self.at(self.project(p))
    }

    /// Distance from `p` to its closest point.
    pub fn distance_to_point(self, p: DVec2) -> f64 {
        distance_to_point(self.a, self.b, p)
    }

    /// Distance to `other` (0 when they meet).
    pub fn distance(self, other: Segment) -> f64 {
        segment_distance(self.a, self.b, other.a, other.b)
    }
}

impl From<(DVec2, DVec2)> for Segment {
    fn from((a, b): (DVec2, DVec2)) -> Segment {
        Segment::new(a, b)
    }
}

impl From<[DVec2; 2]> for Segment {
    fn from([a, b]: [DVec2; 2]) -> Segment {
        Segment::new(a, b)
    }
}

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

/// Distance between segments `a0–a1` and `b0–b1` (0 when they meet).
pub fn segment_distance(a0: DVec2, a1: DVec2, b0: DVec2, b1: DVec2) -> f64 {
    if intersect(a0, a1, b0, b1, ROUNDOFF) != Crossing::None {
        return 0.0;
    }
    distance_to_point(b0, b1, a0)
        .min(distance_to_point(b0, b1, a1))
        .min(distance_to_point(a0, a1, b0))
        .min(distance_to_point(a0, a1, b1))
}

/// The translations along x that bring two segments closer than `gap`: the open interval
/// `(lo, hi)` of every `t` for which segment `a0–a1` moved by `(t, 0)` comes within `gap`
/// (> 0) of segment `b0–b1`, or `None` when no such `t` exists.
///
/// It is exact: `t` is in it iff `(t, 0)` lies in the Minkowski difference `B − A` (a
/// parallelogram) dilated by `gap`, a convex set whose trace on the x axis is one interval,
/// bounded where the x axis crosses the capsules round the parallelogram's sides.
pub fn slide_interval(a0: DVec2, a1: DVec2, b0: DVec2, b1: DVec2, gap: f64) -> Option<(f64, f64)> {
    let corners = [b0 - a0, b0 - a1, b1 - a1, b1 - a0];
    let mut span: Option<(f64, f64)> = None;
    for k in 0..4 {
        if let Some((lo, hi)) = capsule_on_x_axis(corners[k], corners[(k + 1) % 4], gap) {
            span = Some(span.map_or((lo, hi), |(l, h)| (l.min(lo), h.max(hi))));
        }
    }
    span.filter(|(lo, hi)| hi > lo)
}

/// Where the x axis meets the capsule of radius `r` round segment `p–q`: `(lo, hi)` in x.
fn capsule_on_x_axis(p: DVec2, q: DVec2, r: f64) -> Option<(f64, f64)> {
    let disk = |c: DVec2| {
        (c.y.abs() < r).then(|| {
            let h = (r * r - c.y * c.y).sqrt();
            (c.x - h, c.x + h)
        })
    };
    let mut out: Option<(f64, f64)> = None;
    let mut take = |iv: Option<(f64, f64)>| {
        if let Some((lo, hi)) = iv {
            out = Some(out.map_or((lo, hi), |(l, h)| (l.min(lo), h.max(hi))));
        }
    };
    take(disk(p));
    take(disk(q));
    let d = q - p;
    let len = d.length();
    if len > 0.0 {
        let u = d / len;
        // For the point (t, 0): its position along the segment, (t − p.x) u.x − p.y u.y, in
        // [0, len], and its signed offset, u.x (−p.y) − u.y (t − p.x), in (−r, r).
        let along = linear_range(u.x, -p.x * u.x - p.y * u.y, 0.0, len);
        let across = linear_range(-u.y, p.y * -u.x + u.y * p.x, -r, r);
        if let (Some(a), Some(b)) = (along, across) {
            let (lo, hi) = (a.0.max(b.0), a.1.min(b.1));
            if lo <= hi {
                take(Some((lo, hi)));
            }
        }
    }
    out
}

/// The `t` with `lo ≤ alpha t + beta ≤ hi`, as `(from, to)`; unbounded ends are infinite.
fn linear_range(alpha: f64, beta: f64, lo: f64, hi: f64) -> Option<(f64, f64)> {
    if alpha == 0.0 {
        return (lo..=hi)
            .contains(&beta)
            .then_some((f64::NEG_INFINITY, f64::INFINITY));
    }
    let (x, y) = ((lo - beta) / alpha, (hi - beta) / alpha);
    Some((x.min(y), x.max(y)))
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

    #[test]
    fn segment_methods_agree_with_closed_forms() {
        // A 3-4-5 triangle's hypotenuse: length 5, foot of the origin at 9/25 of the way.
        let s = Segment::new(DVec2::new(3.0, 0.0), DVec2::new(0.0, 4.0));
        assert_eq!(s.length(), 5.0);
        assert_eq!(s.midpoint(), DVec2::new(1.5, 2.0));
        let t = s.project(DVec2::ZERO);
        assert!((t - 9.0 / 25.0).abs() < 1e-15, "{t}");
        // The distance from the origin is the triangle's height on the hypotenuse, 12/5.
        assert!((s.distance_to_point(DVec2::ZERO) - 2.4).abs() < 1e-12);
        assert!((s.closest_point(DVec2::ZERO).length() - 2.4).abs() < 1e-12);
        assert_eq!(s.reversed().reversed(), s);
        assert_eq!(s.bounds().size(), DVec2::new(3.0, 4.0));
        let far = Segment::new(DVec2::new(10.0, 0.0), DVec2::new(10.0, 1.0));
        assert_eq!(s.distance(far), 7.0);
        assert_eq!(s.intersect(far, 1e-12), Crossing::None);
        let point = Segment::new(DVec2::ONE, DVec2::ONE);
        assert_eq!(point.length(), 0.0);
        assert_eq!(point.closest_point(DVec2::ZERO), DVec2::ONE);
    }

    #[test]
    fn slide_interval_matches_the_distance_everywhere() {
        // A fixed-seed LCG for random segments; every t is checked against the distance.
        let mut rng = crate::test_rng::TestRng::new(7);
        let mut r = || rng.unit() * 10.0 - 5.0;
        for _ in 0..300 {
            let (a0, a1) = (DVec2::new(r(), r()), DVec2::new(r(), r()));
            let (b0, b1) = (DVec2::new(r(), r()), DVec2::new(r(), r()));
            let gap = 0.5 + r().abs() * 0.3;
            let iv = slide_interval(a0, a1, b0, b1, gap);
            for k in 0..400 {
                let t = -20.0 + 40.0 * k as f64 / 400.0;
                let shift = DVec2::new(t, 0.0);
                let d = segment_distance(a0 + shift, a1 + shift, b0, b1);
                let inside = iv.is_some_and(|(lo, hi)| t > lo && t < hi);
                if (d - gap).abs() > 1e-9 {
                    assert_eq!(inside, d < gap, "t {t}: distance {d}, interval {iv:?}");
                }
            }
        }
        // Horizontal segments on one line: touching at both ends of the interval.
        let iv = slide_interval(
            DVec2::ZERO,
            DVec2::X,
            DVec2::new(5.0, 0.0),
            DVec2::new(6.0, 0.0),
            1.0,
        )
        .unwrap();
        assert!(
            (iv.0 - 3.0).abs() < 1e-12 && (iv.1 - 7.0).abs() < 1e-12,
            "{iv:?}"
        );
    }
}
