//! Degree-4 B-spline curves, the directrices of the thesis's patches (Ōgaki 2016, §3.2 Step 2: the
//! thesis replaces the cubic Bézier of Hosoda's method by a degree-4 B-spline).
//!
//! The knot vector is clamped and uniform: with n control points (n ≥ 5) it is
//! `0,0,0,0,0, 1, 2, …, n−5, n−4,n−4,n−4,n−4,n−4`, so the curve starts at the first control
//! point, ends at the last, and the parameter runs over `[0, n − 4]` (one unit per knot span).
//! Evaluation is de Boor's algorithm; the derivative is the degree-3 B-spline of the scaled
//! control-point differences `4 (P_{i+1} − P_i) / (t_{i+5} − t_{i+1})`.

use glam::DVec3;

use super::PapercraftError;

/// The degree of every directrix.
pub const DEGREE: usize = 4;

/// A clamped uniform B-spline of any degree (the directrix uses [`DEGREE`]).
#[derive(Clone, Debug, PartialEq)]
pub struct BSpline {
    degree: usize,
    control: Vec<DVec3>,
    knots: Vec<f64>,
}

impl BSpline {
    /// A degree-4 directrix through `control` (at least 5 finite points); `what` names it in
    /// errors.
    pub fn directrix(control: Vec<DVec3>, what: &str) -> Result<Self, PapercraftError> {
        if control.len() <= DEGREE {
            return Err(PapercraftError::BadParameter(format!(
                "{what}: a degree-{DEGREE} B-spline needs at least {} control points, got {}",
                DEGREE + 1,
                control.len()
            )));
        }
        if control.iter().any(|p| !p.is_finite()) {
            return Err(PapercraftError::NonFinite { what: what.into() });
        }
        Ok(Self::clamped(DEGREE, control))
    }

    fn clamped(degree: usize, control: Vec<DVec3>) -> Self {
        let spans = control.len() - degree;
        let mut knots = vec![0.0; degree + 1];
        knots.extend((1..spans).map(|k| k as f64));
        knots.extend(std::iter::repeat_n(spans as f64, degree + 1));
        BSpline {
            degree,
            control,
            knots,
        }
    }

    /// Control points.
    pub fn control(&self) -> &[DVec3] {
        &self.control
    }

    /// Number of knot spans; the parameter domain is `[0, spans]`.
    pub fn spans(&self) -> usize {
        self.control.len() - self.degree
    }

    /// `u` clamped to the domain, and the knot span holding it (as a knot index).
    fn span(&self, u: f64) -> (f64, usize) {
        let u = u.clamp(0.0, self.spans() as f64);
        (u, (u.floor() as usize).min(self.spans() - 1) + self.degree)
    }

    /// The curve at `u` (clamped to the domain).
    pub fn at(&self, u: f64) -> DVec3 {
        let p = self.degree;
        let (u, span) = self.span(u);
        let mut d: Vec<DVec3> = (0..=p).map(|j| self.control[span - p + j]).collect();
        for r in 1..=p {
            for j in (r..=p).rev() {
                let i = span - p + j;
                let (k0, k1) = (self.knots[i], self.knots[i + p + 1 - r]);
                let a = if k1 > k0 { (u - k0) / (k1 - k0) } else { 0.0 };
                d[j] = d[j - 1].lerp(d[j], a);
            }
        }
        d[p]
    }

    /// The zero-length directrix of `count` control points (all at the origin), whose
    /// [`Self::basis`] the least-squares fit uses before the control points are known.
    pub(crate) fn unknown(count: usize) -> Self {
        Self::clamped(DEGREE, vec![DVec3::ZERO; count.max(DEGREE + 1)])
    }

    /// The non-zero basis functions at `u` (clamped to the domain): `(first, values)` with
    /// `values[j] = N_{first + j}(u)`, `degree + 1` of them, summing to 1 (Cox–de Boor).
    pub fn basis(&self, u: f64) -> (usize, Vec<f64>) {
        let p = self.degree;
        let (u, span) = self.span(u);
        let mut n = vec![0.0; p + 1];
        let (mut left, mut right) = (vec![0.0; p + 1], vec![0.0; p + 1]);
        n[0] = 1.0;
        for j in 1..=p {
            left[j] = u - self.knots[span + 1 - j];
            right[j] = self.knots[span + j] - u;
            let mut saved = 0.0;
            for r in 0..j {
                let temp = n[r] / (right[r + 1] + left[j - r]);
                n[r] = saved + right[r + 1] * temp;
                saved = left[j - r] * temp;
            }
            n[j] = saved;
        }
        (span - p, n)
    }

    /// The derivative curve (degree one less; a degree-0 curve is refused by construction
    /// since directrices have degree 4).
    pub fn derivative(&self) -> BSpline {
        let p = self.degree;
        let control = self
            .control
            .windows(2)
            .enumerate()
            .map(|(i, w)| {
                let dt = self.knots[i + p + 1] - self.knots[i + 1];
                if dt > 0.0 {
                    (w[1] - w[0]) * (p as f64 / dt)
                } else {
                    DVec3::ZERO
                }
            })
            .collect();
        BSpline {
            degree: p - 1,
            control,
            knots: self.knots[1..self.knots.len() - 1].to_vec(),
        }
    }
}
