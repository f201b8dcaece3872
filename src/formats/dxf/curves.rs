//! Flattening DXF curves into chords within a chordal tolerance: circular arcs (ARC, CIRCLE,
//! polyline bulges), elliptical arcs, and NURBS splines.
//!
//! - A circular arc of radius `r` cut into `n` equal chords deviates from the arc by the
//!   sagitta `r (1 − cos(θ / 2n))` for a sweep θ; `n` is the smallest count keeping that
//!   within the tolerance.
//! - A polyline bulge `b` is `tan(θ/4)` of the arc's sweep θ, positive counter-clockwise
//!   (AutoCAD's definition), so the radius is `chord (1 + b²) / 4|b|`.
//! - A spline is evaluated with de Boor's algorithm (rational with weights when given) and
//!   subdivided recursively until the curve's point halfway between two samples lies within
//!   the tolerance of their chord (to at most [`MAX_DEPTH`] halvings per knot span).
//!
//! Every curve gives at most [`MAX_CHORDS`] chords.

use std::f64::consts::TAU;

use glam::DVec2;

use crate::geom::segment::distance_to_point;

/// Smallest minor-to-major axis ratio used to tighten an ellipse's chord tolerance: flatter
/// ellipses are chorded as if this flat, which bounds their chord count.
const MIN_AXIS_RATIO: f64 = 1e-3;

/// Most chords made from one curve.
pub const MAX_CHORDS: usize = 4096;

/// Most halvings of a spline's knot span.
pub const MAX_DEPTH: u32 = 12;

/// Chords needed for an arc of `radius` sweeping `sweep` radians within `tol`.
fn arc_chords(radius: f64, sweep: f64, tol: f64) -> usize {
    let sweep = sweep.abs();
    if radius <= tol || sweep == 0.0 {
        return 1;
    }
    let half_step = (1.0 - tol / radius).clamp(-1.0, 1.0).acos();
    let n = (sweep / (2.0 * half_step)).ceil();
    if n.is_finite() {
        (n as usize).clamp(1, MAX_CHORDS)
    } else {
        MAX_CHORDS
    }
}

/// Points along a circular arc from angle `start` sweeping `sweep` radians (negative:
/// clockwise), the start point included.
pub fn arc(centre: DVec2, radius: f64, start: f64, sweep: f64, tol: f64) -> Vec<DVec2> {
    let n = arc_chords(radius, sweep, tol);
    (0..=n)
        .map(|i| {
            let a = start + sweep * i as f64 / n as f64;
            centre + radius * DVec2::new(a.cos(), a.sin())
        })
        .collect()
}

/// The counter-clockwise sweep from `start` to `end` (radians), in (0, 2π].
pub fn ccw_sweep(start: f64, end: f64) -> f64 {
    let s = (end - start).rem_euclid(TAU);
    if s == 0.0 { TAU } else { s }
}

/// Points from `a` to `b` along the arc of bulge `bulge` (both ends included); a straight
/// pair when the bulge is 0.
pub fn bulge(a: DVec2, b: DVec2, bulge: f64, tol: f64) -> Vec<DVec2> {
    let chord = b - a;
    let len = chord.length();
    if bulge == 0.0 || !bulge.is_finite() || len == 0.0 {
        return vec![a, b];
    }
    let sweep = 4.0 * bulge.atan();
    let radius = len * (1.0 + bulge * bulge) / (4.0 * bulge.abs());
    // The centre lies on the chord's perpendicular bisector, left of a→b for a
    // counter-clockwise arc shorter than a half turn.
    let sagitta_to_centre = radius - len * bulge.abs() / 2.0;
    let left = DVec2::new(-chord.y, chord.x) / len;
    let centre = (a + b) / 2.0 + left * sagitta_to_centre * bulge.signum();
    let start = (a - centre).to_angle();
    let mut points = arc(centre, radius, start, sweep, tol);
    // Land exactly on the given ends.
    points[0] = a;
    if let Some(last) = points.last_mut() {
        *last = b;
    }
    points
}

/// Points along an elliptical arc: `centre`, semi-major axis vector `major`, the minor axis
/// `ratio` times as long, parameters from `start` to `end` (radians, counter-clockwise).
pub fn ellipse(
    centre: DVec2,
    major: DVec2,
    ratio: f64,
    start: f64,
    end: f64,
    tol: f64,
) -> Vec<DVec2> {
    let minor = DVec2::new(-major.y, major.x) * ratio;
    let sweep = ccw_sweep(start, end);
    // The major radius bounds the curvature radius from above for the chord count.
    let n = arc_chords(
        major.length(),
        sweep,
        tol * ratio.clamp(MIN_AXIS_RATIO, 1.0),
    );
    (0..=n)
        .map(|i| {
            let t = start + sweep * i as f64 / n as f64;
            centre + major * t.cos() + minor * t.sin()
        })
        .collect()
}

/// A NURBS curve: degree, knots, control points and weights (empty: all 1).
pub struct Nurbs<'a> {
    /// The degree (≥ 1).
    pub degree: usize,
    /// The knot vector (`control.len() + degree + 1` values, non-decreasing).
    pub knots: &'a [f64],
    /// The control points.
    pub control: &'a [DVec2],
    /// The weights, one per control point, or empty.
    pub weights: &'a [f64],
}

impl Nurbs<'_> {
    /// Checks the sizes and values; the reason when they do not fit together.
    pub fn check(&self) -> Result<(), String> {
        let n = self.control.len();
        if self.degree < 1 || n <= self.degree {
            return Err(format!(
                "degree {} needs more than {} control points, it has {n}",
                self.degree, self.degree
            ));
        }
        if self.knots.len() != n + self.degree + 1 {
            return Err(format!(
                "{} knots for {n} control points of degree {} (expected {})",
                self.knots.len(),
                self.degree,
                n + self.degree + 1
            ));
        }
        if self.knots.iter().any(|k| !k.is_finite()) || self.knots.windows(2).any(|w| w[0] > w[1]) {
            return Err("the knots are not non-decreasing numbers".into());
        }
        if !self.weights.is_empty()
            && (self.weights.len() != n || self.weights.iter().any(|w| w.is_nan() || *w <= 0.0))
        {
            return Err("the weights are not one positive number per control point".into());
        }
        Ok(())
    }

    /// The point at parameter `u` (de Boor's algorithm, in homogeneous coordinates).
    fn point(&self, u: f64) -> DVec2 {
        let p = self.degree;
        let n = self.control.len();
        let k = (p..n)
            .rev()
            .find(|&k| self.knots[k] <= u)
            .unwrap_or(p)
            .min(n - 1);
        let weight = |i: usize| self.weights.get(i).copied().unwrap_or(1.0);
        let mut d: Vec<(DVec2, f64)> = (0..=p)
            .map(|j| {
                let i = j + k - p;
                (self.control[i] * weight(i), weight(i))
            })
            .collect();
        for r in 1..=p {
            for j in (r..=p).rev() {
                let i = j + k - p;
                let denom = self.knots[i + p + 1 - r] - self.knots[i];
                let alpha = if denom > 0.0 {
                    (u - self.knots[i]) / denom
                } else {
                    0.0
                };
                d[j] = (
                    d[j - 1].0 * (1.0 - alpha) + d[j].0 * alpha,
                    d[j - 1].1 * (1.0 - alpha) + d[j].1 * alpha,
                );
            }
        }
        d[p].0 / d[p].1
    }

    /// Points along the curve within `tol` of it, both ends included.
    pub fn flatten(&self, tol: f64) -> Vec<DVec2> {
        let p = self.degree;
        let n = self.control.len();
        let mut spans: Vec<f64> = self.knots[p..=n].to_vec();
        spans.dedup();
        let mut out = vec![self.point(spans[0])];
        for w in spans.windows(2) {
            self.subdivide(w[0], w[1], tol, 0, &mut out);
            if out.len() > MAX_CHORDS {
                break;
            }
        }
        out
    }

    fn subdivide(&self, u0: f64, u1: f64, tol: f64, depth: u32, out: &mut Vec<DVec2>) {
        let a = self.point(u0);
        let b = self.point(u1);
        let mid = (u0 + u1) / 2.0;
        let m = self.point(mid);
        let quarter = self.point((u0 + mid) / 2.0);
        let three = self.point((mid + u1) / 2.0);
        let flat = [m, quarter, three]
            .iter()
            .all(|&q| distance_to_point(a, b, q) <= tol);
        if depth >= MAX_DEPTH || out.len() > MAX_CHORDS || flat {
            out.push(b);
            return;
        }
        self.subdivide(u0, mid, tol, depth + 1, out);
        self.subdivide(mid, u1, tol, depth + 1, out);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn max_radius_error(points: &[DVec2], centre: DVec2, r: f64) -> f64 {
        points
            .windows(2)
            .map(|w| (r - centre.distance((w[0] + w[1]) / 2.0)).abs())
            .fold(0.0, f64::max)
    }

    #[test]
    fn arcs_stay_within_the_tolerance() {
        let pts = arc(DVec2::ZERO, 50.0, 0.0, TAU, 0.01);
        assert!(pts.len() > 20);
        assert!(max_radius_error(&pts, DVec2::ZERO, 50.0) <= 0.01 + 1e-12);
        assert!(pts[0].distance(pts[pts.len() - 1]) < 1e-9);
    }

    #[test]
    fn a_bulge_of_one_is_a_half_circle() {
        let (a, b) = (DVec2::new(0.0, 0.0), DVec2::new(10.0, 0.0));
        let pts = bulge(a, b, 1.0, 0.001);
        // Counter-clockwise from a to b: the arc passes below the chord, through (5, −5).
        let lowest = pts.iter().map(|p| p.y).fold(f64::INFINITY, f64::min);
        assert!((lowest + 5.0).abs() < 1e-3, "{lowest}");
        assert!(max_radius_error(&pts, DVec2::new(5.0, 0.0), 5.0) <= 0.001 + 1e-12);
        assert_eq!((pts[0], pts[pts.len() - 1]), (a, b));
    }

    #[test]
    fn a_rational_quadratic_spline_draws_a_quarter_circle() {
        let control = [
            DVec2::new(1.0, 0.0),
            DVec2::new(1.0, 1.0),
            DVec2::new(0.0, 1.0),
        ];
        let w = std::f64::consts::FRAC_1_SQRT_2;
        let curve = Nurbs {
            degree: 2,
            knots: &[0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
            control: &control,
            weights: &[1.0, w, 1.0],
        };
        assert!(curve.check().is_ok());
        let pts = curve.flatten(1e-4);
        for p in &pts {
            assert!((p.length() - 1.0).abs() < 1e-12, "{p}");
        }
        assert!(max_radius_error(&pts, DVec2::ZERO, 1.0) <= 1e-4 + 1e-12);
        assert_eq!(pts[pts.len() - 1], control[2]);
    }

    #[test]
    fn malformed_splines_are_refused() {
        let control = [DVec2::ZERO, DVec2::ONE];
        let curve = Nurbs {
            degree: 3,
            knots: &[0.0, 1.0],
            control: &control,
            weights: &[],
        };
        assert!(curve.check().is_err());
    }
}
