//! Open polylines measured by arc length: total length and the piece between two distances.
//!
//! A polyline is a slice of points walked in order; distances are measured along it from its
//! first point, in the points' unit. Cost O(n) per call.

use glam::DVec2;

/// Length of the polyline through `points` (0 for fewer than two).
pub fn length(points: &[DVec2]) -> f64 {
    points.windows(2).map(|w| w[0].distance(w[1])).sum()
}

/// The piece of the polyline from distance `from` to distance `to` along it (clamped to
/// `[0, length]`, `from ≤ to`): the point at `from`, every vertex strictly between, and the
/// point at `to`. Empty for fewer than two points or `from > to`.
pub fn sub_path(points: &[DVec2], from: f64, to: f64) -> Vec<DVec2> {
    if points.len() < 2 || from > to {
        return Vec::new();
    }
    let mut out = Vec::new();
    let mut walked = 0.0;
    for w in points.windows(2) {
        let seg = w[0].distance(w[1]);
        let next = walked + seg;
        let at = |d: f64| {
            if seg > 0.0 {
                w[0].lerp(w[1], ((d - walked) / seg).clamp(0.0, 1.0))
            } else {
                w[0]
            }
        };
        if out.is_empty() && from <= next {
            out.push(at(from));
        }
        if !out.is_empty() {
            if to <= next {
                out.push(at(to));
                return out;
            }
            if next > from {
                out.push(w[1]);
            }
        }
        walked = next;
    }
    if out.is_empty() {
        out.push(points[points.len() - 1]);
    }
    if out.len() == 1 {
        out.push(points[points.len() - 1]);
    }
    out
}

/// `points` without the interior points where the polyline goes straight on: the sine of the
/// turn there is at most `max_sine` (relative to the two pieces' lengths), and the polyline
/// does not double back.
pub fn drop_straight_points(points: &[DVec2], max_sine: f64) -> Vec<DVec2> {
    let mut out: Vec<DVec2> = Vec::with_capacity(points.len());
    for (i, &p) in points.iter().enumerate() {
        if let (Some(&prev), Some(&next)) = (out.last(), points.get(i + 1))
            && i > 0
        {
            let (a, b) = (p - prev, next - p);
            let scale = a.length() * b.length();
            if scale > 0.0 && a.dot(b) > 0.0 && a.perp_dot(b).abs() <= max_sine * scale {
                continue;
            }
        }
        out.push(p);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square_path() -> Vec<DVec2> {
        vec![
            DVec2::new(0.0, 0.0),
            DVec2::new(2.0, 0.0),
            DVec2::new(2.0, 2.0),
            DVec2::new(0.0, 2.0),
        ]
    }

    #[test]
    fn straight_points_are_dropped_and_corners_kept() {
        let p = [
            DVec2::new(0.0, 0.0),
            DVec2::new(1.0, 0.0),
            DVec2::new(2.0, 0.0),
            DVec2::new(2.0, 1.0),
        ];
        assert_eq!(drop_straight_points(&p, 1e-9), vec![p[0], p[2], p[3]]);
    }

    #[test]
    fn length_sums_the_pieces() {
        assert_eq!(length(&square_path()), 6.0);
        assert_eq!(length(&square_path()[..1]), 0.0);
    }

    #[test]
    fn sub_path_keeps_the_corners_it_passes() {
        let p = sub_path(&square_path(), 1.0, 3.5);
        assert_eq!(
            p,
            vec![
                DVec2::new(1.0, 0.0),
                DVec2::new(2.0, 0.0),
                DVec2::new(2.0, 1.5)
            ]
        );
        assert!((length(&p) - 2.5).abs() < 1e-12);
        let inside = sub_path(&square_path(), 0.5, 1.5);
        assert_eq!(inside, vec![DVec2::new(0.5, 0.0), DVec2::new(1.5, 0.0)]);
        let whole = sub_path(&square_path(), 0.0, 6.0);
        assert_eq!(whole, square_path());
        assert!(sub_path(&square_path(), 2.0, 1.0).is_empty());
    }
}
