//! Least-squares fitting of a degree-4 B-spline directrix to a point sequence (Ōgaki 2016, §3.5 Step 3:
//! the thesis approximates the swept real boundary "by least squares with a degree-4
//! B-spline, after ref. \[11\]", with any number of control points).
//!
//! The curve has the clamped uniform knots of [`BSpline::directrix`]. Each data point q_i
//! gets a parameter t_i (the caller's, mapped affinely onto the domain `[0, n − 4]`) and a
//! weight w_i > 0; the control points P minimise
//! `Σ w_i |Σ_j N_j(t_i) P_j − q_i|² + λ Σ_j |P_{j−1} − 2P_j + P_{j+1}|²`.
//! The small second-difference term (λ = 1e-9 times the mean diagonal of the normal matrix)
//! is our addition: it keeps the normal equations positive definite when a knot span holds
//! no data and changes a well-covered fit by far less than the tolerances used. The normal
//! equations are solved by Cholesky. Then, `corrections` times, each t_i moves to the
//! parameter of the curve point closest to q_i (Newton on `c'(t)·(c(t) − q_i) = 0`, the
//! usual parameter correction) and the control points are solved again.

use glam::DVec3;

use super::PapercraftError;
use super::bspline::{BSpline, DEGREE};

/// Weight of the second-difference smoothing term, relative to the mean diagonal of the normal
/// equations: enough to make them regular where data is sparse, too small to move a fit
/// the data determine.
const SMOOTHING: f64 = 1e-9;

/// A fitted directrix.
#[derive(Clone, Debug)]
pub struct Fit {
    /// The curve.
    pub curve: BSpline,
    /// Each data point's final parameter on the curve.
    pub params: Vec<f64>,
    /// Each data point's distance to the curve at its parameter (mesh units).
    pub distances: Vec<f64>,
}

/// Fits `count` control points (≥ 5, and at most the number of points) to `points` at the
/// initial parameters `params` (finite values with a positive range, in any order), point i
/// counting with `weights[i]` (finite, > 0).
pub fn fit_directrix(
    points: &[DVec3],
    params: &[f64],
    weights: &[f64],
    count: usize,
    corrections: usize,
) -> Result<Fit, PapercraftError> {
    let bad = |m: String| Err(PapercraftError::BadParameter(m));
    if weights.len() != points.len() || weights.iter().any(|w| !(w.is_finite() && *w > 0.0)) {
        return bad("every point to fit needs a finite positive weight".into());
    }
    if count <= DEGREE || count > points.len() || params.len() != points.len() {
        return bad(format!(
            "cannot fit {count} control points to {} points (need 5 ≤ control points ≤ points)",
            points.len()
        ));
    }
    let (lo, hi) = params
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &t| {
            (a.min(t), b.max(t))
        });
    if !(hi - lo).is_finite() || hi <= lo || points.iter().any(|p| !p.is_finite()) {
        return bad("the points to fit are not finite or all at one parameter".into());
    }
    let domain = (count - DEGREE) as f64;
    let mut t: Vec<f64> = params
        .iter()
        .map(|&x| domain * (x - lo) / (hi - lo))
        .collect();
    let mut curve = solve(points, &t, weights, count)?;
    for _ in 0..corrections {
        correct(&curve, points, &mut t);
        curve = solve(points, &t, weights, count)?;
    }
    let distances = points
        .iter()
        .zip(&t)
        .map(|(&q, &u)| curve.at(u).distance(q))
        .collect();
    Ok(Fit {
        curve,
        params: t,
        distances,
    })
}

/// Solves the regularised normal equations for the control points.
fn solve(
    points: &[DVec3],
    t: &[f64],
    weights: &[f64],
    count: usize,
) -> Result<BSpline, PapercraftError> {
    let template = BSpline::unknown(count);
    let mut a = vec![vec![0.0; count]; count];
    let mut b = vec![DVec3::ZERO; count];
    for ((&q, &u), &w) in points.iter().zip(t).zip(weights) {
        let (first, n) = template.basis(u);
        for (j, &nj) in n.iter().enumerate() {
            b[first + j] += w * nj * q;
            for (k, &nk) in n.iter().enumerate() {
                a[first + j][first + k] += w * nj * nk;
            }
        }
    }
    let lambda = SMOOTHING * (0..count).map(|i| a[i][i]).sum::<f64>() / count as f64;
    for j in 1..count - 1 {
        let stencil = [(j - 1, 1.0), (j, -2.0), (j + 1, 1.0)];
        for &(r, wr) in &stencil {
            for &(c, wc) in &stencil {
                a[r][c] += lambda * wr * wc;
            }
        }
    }
    let control = cholesky_solve(a, b).ok_or_else(|| {
        PapercraftError::BadParameter("the least-squares directrix fit is singular".into())
    })?;
    BSpline::directrix(control, "fitted directrix")
}

/// Moves each parameter to the closest curve point near it (4 Newton steps, clamped).
fn correct(curve: &BSpline, points: &[DVec3], t: &mut [f64]) {
    let d1 = curve.derivative();
    let d2 = d1.derivative();
    let max = curve.spans() as f64;
    for (u, &q) in t.iter_mut().zip(points) {
        for _ in 0..4 {
            let (c, c1, c2) = (curve.at(*u), d1.at(*u), d2.at(*u));
            let f = c1.dot(c - q);
            let df = c2.dot(c - q) + c1.length_squared();
            if df <= 0.0 || !df.is_finite() {
                break;
            }
            *u = (*u - f / df).clamp(0.0, max);
        }
    }
}

/// Solves `A x = b` for a symmetric positive definite `A` (row vectors), three right-hand
/// sides at once; `None` if `A` is not positive definite.
fn cholesky_solve(mut a: Vec<Vec<f64>>, mut b: Vec<DVec3>) -> Option<Vec<DVec3>> {
    let n = a.len();
    for j in 0..n {
        let d = a[j][j] - (0..j).map(|k| a[j][k] * a[j][k]).sum::<f64>();
        if d <= 0.0 || !d.is_finite() {
            return None;
        }
        let d = d.sqrt();
        a[j][j] = d;
        for i in j + 1..n {
            let s = a[i][j] - (0..j).map(|k| a[i][k] * a[j][k]).sum::<f64>();
            a[i][j] = s / d;
        }
    }
    for i in 0..n {
        let s = b[i] - (0..i).map(|k| a[i][k] * b[k]).sum::<DVec3>();
        b[i] = s / a[i][i];
    }
    for i in (0..n).rev() {
        let s = b[i] - (i + 1..n).map(|k| a[k][i] * b[k]).sum::<DVec3>();
        b[i] = s / a[i][i];
    }
    Some(b)
}
