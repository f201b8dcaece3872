//! Flattening of quadratic and cubic Bézier curves into chords.
//!
//! A curve `B(t)` is cut into `n` chords of equal parameter step. The distance between a curve
//! and its chord over a parameter interval of length `h` is at most `h² / 8 · max |B''|`, and
//! `|B''|` is bounded by the control polygon's second differences: `2 |P0 − 2P1 + P2|` for a
//! quadratic, `6 max(|P0 − 2P1 + P2|, |P1 − 2P2 + P3|)` for a cubic. Solving for `n` gives the
//! fewest chords that keep within `tolerance` (in the units of the points), capped at
//! [`MAX_CHORDS`] per curve so a huge curve cannot exhaust memory.

use glam::DVec2;

/// Most chords made from one curve.
pub const MAX_CHORDS: usize = 256;

/// Chords needed for a curve with second-difference bound `m` (already including the curve's
/// derivative factor) to stay within `tolerance`.
fn chord_count(m: f64, tolerance: f64) -> usize {
    let n = (m / (8.0 * tolerance)).sqrt().ceil();
    if n.is_finite() {
        (n as usize).clamp(1, MAX_CHORDS)
    } else {
        MAX_CHORDS
    }
}

/// Points along a quadratic from `p0` (excluded) to `p2` (included).
pub fn quad(p0: DVec2, p1: DVec2, p2: DVec2, tolerance: f64) -> Vec<DVec2> {
    let m = 2.0 * (p0 - 2.0 * p1 + p2).length();
    let n = chord_count(m, tolerance);
    (1..=n)
        .map(|i| {
            let t = i as f64 / n as f64;
            let u = 1.0 - t;
            u * u * p0 + 2.0 * u * t * p1 + t * t * p2
        })
        .collect()
}

/// Points along a cubic from `p0` (excluded) to `p3` (included).
pub fn cubic(p0: DVec2, p1: DVec2, p2: DVec2, p3: DVec2, tolerance: f64) -> Vec<DVec2> {
    let d1 = (p0 - 2.0 * p1 + p2).length();
    let d2 = (p1 - 2.0 * p2 + p3).length();
    let n = chord_count(6.0 * d1.max(d2), tolerance);
    (1..=n)
        .map(|i| {
            let t = i as f64 / n as f64;
            let u = 1.0 - t;
            u * u * u * p0 + 3.0 * u * u * t * p1 + 3.0 * u * t * t * p2 + t * t * t * p3
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn max_error(points: &[DVec2], start: DVec2, curve: impl Fn(f64) -> DVec2) -> f64 {
        // Sample the curve densely; each sample's distance to the nearest chord.
        let mut poly = vec![start];
        poly.extend_from_slice(points);
        (0..=1000)
            .map(|i| {
                let p = curve(i as f64 / 1000.0);
                poly.windows(2)
                    .map(|w| crate::geom::segment::distance_to_point(w[0], w[1], p))
                    .fold(f64::INFINITY, f64::min)
            })
            .fold(0.0, f64::max)
    }

    #[test]
    fn a_straight_quad_is_one_chord() {
        let pts = quad(
            DVec2::ZERO,
            DVec2::new(1.0, 1.0),
            DVec2::new(2.0, 2.0),
            0.01,
        );
        assert_eq!(pts, vec![DVec2::new(2.0, 2.0)]);
    }

    #[test]
    fn a_quarter_circle_cubic_stays_within_tolerance() {
        let k = 0.552_284_75 * 100.0;
        let (p0, p1, p2, p3) = (
            DVec2::new(100.0, 0.0),
            DVec2::new(100.0, k),
            DVec2::new(k, 100.0),
            DVec2::new(0.0, 100.0),
        );
        let tol = 0.05;
        let pts = cubic(p0, p1, p2, p3, tol);
        assert!(pts.len() > 4 && pts.len() < MAX_CHORDS, "{}", pts.len());
        assert_eq!(pts.last().copied(), Some(p3));
        let err = max_error(&pts, p0, |t| {
            let u = 1.0 - t;
            u * u * u * p0 + 3.0 * u * u * t * p1 + 3.0 * u * t * t * p2 + t * t * t * p3
        });
        assert!(err <= tol, "error {err}");
    }

    #[test]
    fn huge_curves_are_capped() {
        let pts = quad(
            DVec2::ZERO,
            DVec2::new(1e9, 1e9),
            DVec2::new(2e9, 0.0),
            1e-9,
        );
        assert_eq!(pts.len(), MAX_CHORDS);
    }
}
