//! Projections for the rigid simulation: the minimum-norm solve `Jᵀ(JJᵀ + εI)⁻¹g` by
//! matrix-free conjugate gradient, the null-space projection of a fold increment and the
//! Newton correction back onto the loop-closure manifold.

use glam::DVec3;

use super::RigidModel;

/// The ε of `(JJᵀ + εI)`: a ridge far below any row's squared norm of a unit-scale model,
/// only there to keep the system positive definite when rows are dependent.
const REGULARISATION: f64 = 1e-14;

/// Conjugate gradient stops once the squared residual has fallen by this factor (10⁻¹⁴ in
/// the residual's norm).
const CG_REDUCTION: f64 = 1e-28;

/// Sparse Jacobian: per interior vertex, `(crease, ∂r/∂ρ_crease)`.
type Jacobian = [Vec<(usize, DVec3)>];

impl RigidModel {
    /// `J v` stacked as one 3-vector per vertex.
    pub(super) fn apply(jac: &Jacobian, v: &[f64]) -> Vec<DVec3> {
        jac.iter()
            .map(|row| row.iter().map(|&(c, g)| g * v[c]).sum())
            .collect()
    }

    /// `Jᵀ y`.
    pub(super) fn apply_t(jac: &Jacobian, y: &[DVec3], n: usize) -> Vec<f64> {
        let mut out = vec![0.0; n];
        for (row, yr) in jac.iter().zip(y) {
            for &(c, g) in row {
                out[c] += g.dot(*yr);
            }
        }
        out
    }

    /// The minimum-norm `x = Jᵀ y` with `(JJᵀ + εI) y = g`, by conjugate gradient.
    pub(super) fn min_norm(jac: &Jacobian, g: &[DVec3], n: usize) -> Vec<f64> {
        let dot = |a: &[DVec3], b: &[DVec3]| a.iter().zip(b).map(|(x, y)| x.dot(*y)).sum::<f64>();
        let eps = REGULARISATION;
        let op = |y: &[DVec3]| -> Vec<DVec3> {
            let z = Self::apply_t(jac, y, n);
            Self::apply(jac, &z)
                .into_iter()
                .zip(y)
                .map(|(a, b)| a + eps * *b)
                .collect()
        };
        let mut y = vec![DVec3::ZERO; g.len()];
        let mut r = g.to_vec();
        let mut p = r.clone();
        let mut rr = dot(&r, &r);
        let goal = CG_REDUCTION * rr.max(f64::MIN_POSITIVE);
        for _ in 0..(30 * g.len() + 100) {
            if rr <= goal {
                break;
            }
            let ap = op(&p);
            let pap = dot(&p, &ap);
            if pap.is_nan() || pap <= 0.0 {
                break;
            }
            let alpha = rr / pap;
            for k in 0..y.len() {
                y[k] += alpha * p[k];
                r[k] -= alpha * ap[k];
            }
            let rr_new = dot(&r, &r);
            let beta = rr_new / rr;
            rr = rr_new;
            for k in 0..p.len() {
                p[k] = r[k] + beta * p[k];
            }
        }
        Self::apply_t(jac, &y, n)
    }

    /// `d` projected onto the null space of the Jacobian at `rho`.
    pub(super) fn project(&self, rho: &[f64], d: &[f64]) -> Vec<f64> {
        let jac = self.jacobian(rho);
        let jd = Self::apply(&jac, d);
        let c = Self::min_norm(&jac, &jd, d.len());
        d.iter().zip(c).map(|(a, b)| a - b).collect()
    }

    /// Newton steps back onto the manifold; returns the skew residual reached.
    pub(super) fn correct(&self, rho: &mut [f64], tolerance: f64) -> f64 {
        let worst = |r: &[DVec3]| r.iter().map(|v| v.length()).fold(0.0, f64::max);
        let mut r = self.residuals(rho);
        for _ in 0..30 {
            if worst(&r) <= tolerance {
                break;
            }
            let dx = Self::min_norm(&self.jacobian(rho), &r, rho.len());
            for (x, d) in rho.iter_mut().zip(dx) {
                *x -= d;
            }
            r = self.residuals(rho);
        }
        worst(&r)
    }
}
