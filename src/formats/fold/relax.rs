//! Small corrections of 2D positions so that given edges get given lengths.
//!
//! Folded states written with few digits (FOLD's `squaretwist.fold` has six) are not exactly
//! developable: faces are slightly non-planar and angles around vertices miss 360° by about
//! 1e-6, so a face-by-face unfolding leaves edge lengths off by that much. When the errors
//! are that small, Gauss–Newton on the residuals `r_k = |P_a − P_b| − L_k` removes them: each
//! step is the least-squares solution of minimum norm of `J Δ = −r`, found by CGLS (conjugate
//! gradients on the normal equations, started at zero, so rigid motions — the null space of
//! `J` — never enter). When a 2D placement with exactly these lengths exists (the usual case:
//! a crease pattern has more coordinates than edges) the residuals fall to rounding level;
//! otherwise they end as a least-squares compromise, and the caller reports what is left.

use glam::DVec2;

/// An edge whose length is prescribed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Rod {
    /// One end (an index into the positions).
    pub a: usize,
    /// The other end.
    pub b: usize,
    /// Prescribed length (positive).
    pub length: f64,
}

/// Outer (Gauss–Newton) iterations at most.
const MAX_STEPS: usize = 10;

/// Stop when every relative residual is below this.
const TARGET: f64 = 1e-14;

/// The conjugate-gradient inner solve stops once its squared residual has fallen by this
/// factor (10⁻¹⁵ in the residual's norm: as far as f64 goes).
const CG_REDUCTION: f64 = 1e-30;

/// The largest relative length error `|len − L| / L` over the rods.
pub(super) fn worst_error(points: &[DVec2], rods: &[Rod]) -> f64 {
    rods.iter()
        .map(|r| (points[r.a].distance(points[r.b]) - r.length).abs() / r.length)
        .fold(0.0, f64::max)
}

/// Moves `points` so the rods get their lengths, as far as possible; returns the remaining
/// largest relative error. Rods must have positive lengths and indices within `points`.
pub(super) fn fit_lengths(points: &mut [DVec2], rods: &[Rod]) -> f64 {
    let mut error = worst_error(points, rods);
    for _ in 0..MAX_STEPS {
        if error <= TARGET {
            break;
        }
        let step = gauss_newton_step(points, rods);
        let before: Vec<DVec2> = points.to_vec();
        for (p, d) in points.iter_mut().zip(&step) {
            *p += *d;
        }
        let after = worst_error(points, rods);
        if after.is_nan() || after >= error {
            points.copy_from_slice(&before);
            break;
        }
        error = after;
    }
    error
}

/// The minimum-norm least-squares solution of `J Δ = −r` (CGLS).
fn gauss_newton_step(points: &[DVec2], rods: &[Rod]) -> Vec<DVec2> {
    let dirs: Vec<DVec2> = rods
        .iter()
        .map(|r| (points[r.a] - points[r.b]).normalize_or_zero())
        .collect();
    let j = |x: &[DVec2]| -> Vec<f64> {
        rods.iter()
            .zip(&dirs)
            .map(|(r, d)| d.dot(x[r.a] - x[r.b]))
            .collect()
    };
    let jt = |y: &[f64]| -> Vec<DVec2> {
        let mut out = vec![DVec2::ZERO; points.len()];
        for ((r, d), &v) in rods.iter().zip(&dirs).zip(y) {
            out[r.a] += *d * v;
            out[r.b] -= *d * v;
        }
        out
    };
    let mut rhs: Vec<f64> = rods
        .iter()
        .map(|r| r.length - points[r.a].distance(points[r.b]))
        .collect();
    let mut x = vec![DVec2::ZERO; points.len()];
    let mut s = jt(&rhs);
    let mut p = s.clone();
    let mut gamma = norm2(&s);
    let start = gamma;
    for _ in 0..(4 * points.len()).clamp(50, 1000) {
        if gamma <= CG_REDUCTION * start || gamma == 0.0 {
            break;
        }
        let q = j(&p);
        let qq: f64 = q.iter().map(|v| v * v).sum();
        if qq == 0.0 {
            break;
        }
        let alpha = gamma / qq;
        for (xi, pi) in x.iter_mut().zip(&p) {
            *xi += *pi * alpha;
        }
        for (ri, qi) in rhs.iter_mut().zip(&q) {
            *ri -= alpha * qi;
        }
        s = jt(&rhs);
        let next = norm2(&s);
        let beta = next / gamma;
        for (pi, si) in p.iter_mut().zip(&s) {
            *pi = *si + *pi * beta;
        }
        gamma = next;
    }
    x
}

fn norm2(v: &[DVec2]) -> f64 {
    v.iter().map(|d| d.length_squared()).sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn perturbed_quad_gets_its_lengths_back() {
        // A unit square with a diagonal, lengths prescribed, positions disturbed by 1e-6.
        let mut pts = vec![
            DVec2::new(0.0, 0.0),
            DVec2::new(1.0 + 1e-6, 0.0),
            DVec2::new(1.0, 1.0 - 1e-6),
            DVec2::new(1e-6, 1.0),
        ];
        let rod = |a, b, length| Rod { a, b, length };
        let rods = [
            rod(0, 1, 1.0),
            rod(1, 2, 1.0),
            rod(2, 3, 1.0),
            rod(3, 0, 1.0),
            rod(0, 2, 2f64.sqrt()),
        ];
        assert!(worst_error(&pts, &rods) > 1e-7);
        let err = fit_lengths(&mut pts, &rods);
        assert!(err < 1e-13, "{err}");
        assert!(pts[0].distance(DVec2::ZERO) < 1e-5);
    }
}
