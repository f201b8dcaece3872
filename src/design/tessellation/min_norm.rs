//! The minimum-norm step of Tachi (2014) §3.3: `C⁺ g = Cᵀ y` with `(C Cᵀ + εI) y = g`, solved by a
//! preconditioned conjugate gradient on a compressed copy of the sparse rows (ε is a tiny
//! Tikhonov term that keeps redundant rows harmless). The preconditioner is a sparse Cholesky
//! factor of `C Cᵀ` (faer; `C Cᵀ` is sparse: two rows meet only where they share a vertex),
//! so the CG ends in a few iterations; small systems, and systems whose factorization fails
//! (the penalty rows of eq. 5–7 at contact are nearly redundant), use the diagonal.

use std::cell::OnceCell;

use faer::Side;
use faer::linalg::solvers::Solve;
use faer::sparse::linalg::solvers::Llt;
use faer::sparse::{SparseColMat, SymbolicSparseColMat};
use glam::DVec3;

use super::constraints::Row;
use crate::geom::tolerance::{ROUNDOFF, TINY};

/// The rows' Jacobian in compressed sparse row form, one 3-vector block per (row, vertex).
pub(crate) struct Jacobian {
    offsets: Vec<usize>,
    vertices: Vec<u32>,
    blocks: Vec<DVec3>,
    n: usize,
    /// The preconditioner and the Tikhonov ε, built at the first solve and reused by later
    /// solves with the same rows.
    preconditioner: OnceCell<(Preconditioner, f64)>,
    /// The Cholesky preconditioner built when the diagonal one needed more than
    /// [`JACOBI_BUDGET`] CG iterations (`None` when that factorization failed too).
    fallback: OnceCell<Option<Preconditioner>>,
}

impl Jacobian {
    /// Copies `rows` over `n` vertices.
    pub(crate) fn new(rows: &[Row], n: usize) -> Self {
        let mut offsets = Vec::with_capacity(rows.len() + 1);
        let total = rows.iter().map(|r| r.entries.len()).sum();
        let (mut vertices, mut blocks) = (Vec::with_capacity(total), Vec::with_capacity(total));
        offsets.push(0);
        for r in rows {
            for &(v, b) in &r.entries {
                vertices.push(v);
                blocks.push(b);
            }
            offsets.push(vertices.len());
        }
        Jacobian {
            offsets,
            vertices,
            blocks,
            n,
            preconditioner: OnceCell::new(),
            fallback: OnceCell::new(),
        }
    }

    fn row(&self, r: usize) -> impl Iterator<Item = (usize, DVec3)> + '_ {
        let range = self.offsets[r]..self.offsets[r + 1];
        self.vertices[range.clone()]
            .iter()
            .zip(&self.blocks[range])
            .map(|(&v, &b)| (v as usize, b))
    }

    fn rows(&self) -> usize {
        self.offsets.len() - 1
    }

    /// `C dx`.
    pub(crate) fn times_vec(&self, dx: &[DVec3]) -> Vec<f64> {
        let mut out = vec![0.0; self.rows()];
        self.times(dx, &mut out);
        out
    }

    /// `C dx` into `out`.
    fn times(&self, dx: &[DVec3], out: &mut [f64]) {
        for (r, o) in out.iter_mut().enumerate().take(self.rows()) {
            *o = self.row(r).map(|(v, b)| b.dot(dx[v])).sum();
        }
    }

    /// `Cᵀ y` into `out` (overwritten).
    fn transpose_times(&self, y: &[f64], out: &mut [DVec3]) {
        out.fill(DVec3::ZERO);
        for (r, &yr) in y.iter().enumerate().take(self.rows()) {
            for (v, b) in self.row(r) {
                out[v] += yr * b;
            }
        }
    }
}

/// The minimum-norm solution `dx = Cᵀ y` of `C dx = g` (that is `C⁺ g`), with the CG
/// stopped at the relative residual `eta` (1e-12 for an exact step). Returns the step and the
/// CG iteration count.
///
/// A small system starts with the diagonal preconditioner; when its CG has not converged
/// after [`JACOBI_BUDGET`] iterations (nearly dependent rows), the step is solved again with
/// the Cholesky factor, which this Jacobian then keeps.
pub(crate) fn min_norm(c: &Jacobian, g: &[f64], eta: f64) -> (Vec<DVec3>, usize) {
    let (first, eps) = c.preconditioner.get_or_init(|| {
        let (diag, eps) = diagonal(c, ROUNDOFF);
        (Preconditioner::new(c, &diag, eps, 100.0 * eps), eps)
    });
    let full = full_cap(c.rows());
    // The factor, once a diagonal has run out of its budget on these rows (it stays on the
    // diagonal, with the full cap, when that factorization failed).
    let pre = c.fallback.get().and_then(Option::as_ref).unwrap_or(first);
    let on_budget = matches!(first, Preconditioner::Jacobi(_)) && c.fallback.get().is_none();
    let cap = if on_budget {
        JACOBI_BUDGET.min(full)
    } else {
        full
    };
    let ((dx, it), converged) = preconditioned_cg(c, g, eta, *eps, pre, cap);
    if converged || cap == full {
        return (dx, it);
    }
    let factored = c
        .fallback
        .get_or_init(|| factor(c, 100.0 * eps).map(Preconditioner::Cholesky));
    let ((dx, more), _) =
        preconditioned_cg(c, g, eta, *eps, factored.as_ref().unwrap_or(first), full);
    (dx, it + more)
}

/// CG iterations a diagonal preconditioner gets before [`min_norm`] factors `C Cᵀ` instead:
/// on the sample domes the diagonal needs some tens to a few hundred; on saddles and height
/// fields of 216 faces it ran into the thousands per step (95% of the solve's time), where a
/// factorization costs a few dozen.
const JACOBI_BUDGET: usize = 400;

/// The CG's iteration cap for `m` rows.
fn full_cap(m: usize) -> usize {
    10 * m + 100
}

/// The Levenberg–Marquardt step `Cᵀ (C Cᵀ + μI)⁻¹ g` (Levenberg 1944, Marquardt 1963), μ =
/// `relative` × the largest diagonal entry of `C Cᵀ` in place of [`min_norm`]'s tiny ε: it
/// turns from the minimum-norm Newton step (μ → 0) towards the steepest descent of ½‖g‖²
/// (μ → ∞), and stays short where rows are nearly dependent. Its preconditioner is built for
/// this μ and not kept. Returns the step and the CG iteration count.
pub(crate) fn damped_min_norm(
    c: &Jacobian,
    g: &[f64],
    relative: f64,
    eta: f64,
) -> (Vec<DVec3>, usize) {
    let (diag, mu) = diagonal(c, relative.max(ROUNDOFF));
    let pre = Preconditioner::new(c, &diag, mu, mu);
    preconditioned_cg(c, g, eta, mu, &pre, full_cap(c.rows())).0
}

/// The diagonal of `C Cᵀ` and the shift `relative` × its largest entry (the Tikhonov ε of
/// [`min_norm`] with [`ROUNDOFF`]).
fn diagonal(c: &Jacobian, relative: f64) -> (Vec<f64>, f64) {
    let diag: Vec<f64> = (0..c.rows())
        .map(|r| c.row(r).map(|(_, b)| b.length_squared()).sum())
        .collect();
    let eps = relative * diag.iter().fold(0.0f64, |a, &d| a.max(d)).max(TINY);
    (diag, eps)
}

/// CG on `(C Cᵀ + εI) y = g` preconditioned by `pre`, to the relative residual `eta` or `cap`
/// iterations: the step `Cᵀ y`, the iterations, and whether the residual reached `eta`.
fn preconditioned_cg(
    c: &Jacobian,
    g: &[f64],
    eta: f64,
    eps: f64,
    pre: &Preconditioner,
    cap: usize,
) -> ((Vec<DVec3>, usize), bool) {
    let m = c.rows();
    let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    let mut z_blocks = vec![DVec3::ZERO; c.n];
    let mut apply = |p: &[f64], out: &mut [f64]| {
        c.transpose_times(p, &mut z_blocks);
        c.times(&z_blocks, out);
        for (o, pr) in out.iter_mut().zip(p) {
            *o += eps * pr;
        }
    };
    let mut y = vec![0.0; m];
    let mut r = g.to_vec();
    let mut z = vec![0.0; m];
    pre.apply(&r, &mut z);
    let mut p = z.clone();
    let mut ap = vec![0.0; m];
    let mut rz = dot(&r, &z);
    let goal = eta * eta * dot(g, g);
    let mut it = 0;
    while it < cap && dot(&r, &r) > goal {
        it += 1;
        apply(&p, &mut ap);
        let pap = dot(&p, &ap);
        if pap.is_nan() || pap <= 0.0 {
            break;
        }
        let alpha = rz / pap;
        for k in 0..m {
            y[k] += alpha * p[k];
            r[k] -= alpha * ap[k];
        }
        pre.apply(&r, &mut z);
        let rz_new = dot(&r, &z);
        let beta = rz_new / rz;
        rz = rz_new;
        for k in 0..m {
            p[k] = z[k] + beta * p[k];
        }
    }
    let converged = dot(&r, &r) <= goal;
    let mut dx = vec![DVec3::ZERO; c.n];
    c.transpose_times(&y, &mut dx);
    ((dx, it), converged)
}

/// Systems with fewer rows are preconditioned by their diagonal alone: the CG then needs only
/// some hundred iterations, cheaper than a factorization (measured on the sample domes: a
/// 96-face dome's 400 rows solve faster by Jacobi, a 486-face dome's 2,000 by Cholesky).
const FACTOR_ROWS: usize = 1500;

/// `M⁻¹ r` for the CG: a sparse Cholesky factor of `C Cᵀ + δI` (near-exact, so the CG ends in a
/// few iterations), or the diagonal when the factorization fails.
enum Preconditioner {
    Cholesky(Llt<usize, f64>),
    Jacobi(Vec<f64>),
}

impl Preconditioner {
    /// The Cholesky factor of `C Cᵀ + shift·I` for systems of at least [`FACTOR_ROWS`] rows
    /// ([`min_norm`] shifts by 100ε so that near-redundant rows still factor), else or on
    /// failure the diagonal `diag + ε`.
    fn new(c: &Jacobian, diag: &[f64], eps: f64, shift: f64) -> Self {
        let factored = if c.rows() >= FACTOR_ROWS {
            factor(c, shift)
        } else {
            None
        };
        match factored {
            Some(llt) => Preconditioner::Cholesky(llt),
            None => Preconditioner::Jacobi(diag.iter().map(|d| d + eps).collect()),
        }
    }

    fn apply(&self, r: &[f64], z: &mut [f64]) {
        match self {
            Preconditioner::Cholesky(llt) => {
                z.copy_from_slice(r);
                let n = z.len();
                llt.solve_in_place(faer::MatMut::from_column_major_slice_mut(z, n, 1));
            }
            Preconditioner::Jacobi(d) => {
                for ((zk, rk), dk) in z.iter_mut().zip(r).zip(d) {
                    *zk = rk / dk;
                }
            }
        }
    }
}

/// The sparse Cholesky factor of `C Cᵀ + shift·I`, `None` when it is not positive definite.
/// The lower triangle is assembled vertex by vertex: `C Cᵀ = Σ_v C_v C_vᵀ` over the 3-column
/// blocks `C_v`, so a pair of rows costs one product per vertex they share (long rows, such
/// as eq. 2's boundary runs, would otherwise cost their whole length per row they meet).
fn factor(c: &Jacobian, shift: f64) -> Option<Llt<usize, f64>> {
    let m = c.rows();
    // The blocks touching every vertex, by increasing row.
    let mut start = vec![0usize; c.n + 1];
    for &v in &c.vertices {
        start[v as usize + 1] += 1;
    }
    for v in 0..c.n {
        start[v + 1] += start[v];
    }
    let mut fill = start.clone();
    let mut by_vertex = vec![(0u32, DVec3::ZERO); c.vertices.len()];
    for r in 0..m {
        for k in c.offsets[r]..c.offsets[r + 1] {
            let v = c.vertices[k] as usize;
            by_vertex[fill[v]] = (r as u32, c.blocks[k]);
            fill[v] += 1;
        }
    }
    // Row r's lower entries (q ≤ r): every vertex of r, every earlier row at that vertex.
    let mut acc = vec![0.0; m];
    let mut seen = vec![u32::MAX; m];
    let mut met: Vec<u32> = Vec::new();
    // Row r's lower entries are column r of the upper triangle, stored directly.
    let mut col_ptr = Vec::with_capacity(m + 1);
    col_ptr.push(0usize);
    let (mut row_idx, mut values) = (Vec::new(), Vec::new());
    for r in 0..m {
        met.clear();
        for k in c.offsets[r]..c.offsets[r + 1] {
            let (v, b) = (c.vertices[k] as usize, c.blocks[k]);
            for &(q, bq) in &by_vertex[start[v]..start[v + 1]] {
                if q as usize > r {
                    break;
                }
                if seen[q as usize] != r as u32 {
                    seen[q as usize] = r as u32;
                    acc[q as usize] = 0.0;
                    met.push(q);
                }
                acc[q as usize] += b.dot(bq);
            }
        }
        met.sort_unstable();
        for &q in &met {
            let q = q as usize;
            row_idx.push(q);
            values.push(if q == r { acc[q] + shift } else { acc[q] });
        }
        col_ptr.push(row_idx.len());
    }
    let pattern = SymbolicSparseColMat::new_checked(m, m, col_ptr, None, row_idx);
    SparseColMat::<usize, f64>::new(pattern, values)
        .sp_cholesky(Side::Upper)
        .ok()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::design::tessellation::constraints::Family;

    /// `m` rows over `n` vertices, each touching 2–5 vertices chosen by a fixed LCG, plus
    /// one long row touching every tenth vertex (like eq. 2's boundary runs).
    fn rows(m: usize, n: usize) -> Vec<Row> {
        let mut rng = crate::test_rng::TestRng::new(0x9e37_79b9_7f4a_7c15);
        let mut next = || rng.unit();
        let mut out = Vec::new();
        for _ in 0..m {
            let k = 2 + (next() * 4.0) as usize;
            let mut entries: Vec<(u32, DVec3)> = Vec::new();
            for _ in 0..k {
                let v = ((next() * n as f64) as u32).min(n as u32 - 1);
                if entries.iter().all(|(w, _)| *w != v) {
                    entries.push((v, DVec3::new(next() - 0.5, next() - 0.5, next() - 0.5)));
                }
            }
            out.push(Row {
                family: Family::Developability,
                value: next() - 0.5,
                entries,
            });
        }
        out.push(Row {
            family: Family::Boundary,
            value: 0.3,
            entries: (0..n as u32)
                .step_by(10)
                .map(|v| (v, DVec3::new(0.2, -0.1, 0.4)))
                .collect(),
        });
        out
    }

    /// max |C dx − g|.
    fn max_residual(c: &Jacobian, dx: &[DVec3], g: &[f64]) -> f64 {
        c.times_vec(dx)
            .iter()
            .zip(g)
            .fold(0.0f64, |a, (x, y)| a.max((x - y).abs()))
    }

    #[test]
    fn cholesky_and_jacobi_give_the_same_minimum_norm_step() {
        let (m, n) = (FACTOR_ROWS + 100, 1200);
        let rows = rows(m, n);
        let g: Vec<f64> = rows.iter().map(|r| r.value).collect();
        let c = Jacobian::new(&rows, n);
        let (dx, iterations) = min_norm(&c, &g, 1e-12);
        assert!(matches!(
            c.preconditioner.get(),
            Some((Preconditioner::Cholesky(_), _))
        ));
        // A near-exact preconditioner: a handful of CG iterations, not hundreds.
        assert!(iterations <= 5, "{iterations}");
        let residual = max_residual(&c, &dx, &g);
        assert!(residual < 1e-8, "{residual}");
        let (diag, eps) = diagonal(&c, ROUNDOFF);
        let jacobi = Preconditioner::Jacobi(diag.iter().map(|d| d + eps).collect());
        let ((reference, slow), _) =
            preconditioned_cg(&c, &g, 1e-12, eps, &jacobi, full_cap(c.rows()));
        assert!(slow > 10 * iterations, "{slow} vs {iterations}");
        let diff = dx
            .iter()
            .zip(&reference)
            .fold(0.0f64, |a, (p, q)| a.max(p.distance(*q)));
        assert!(diff < 1e-7, "{diff}");
    }

    /// A small but ill-conditioned system: a chain of 1,000 rows, each the difference of two
    /// neighbouring vertices (its `C Cᵀ` is the path Laplacian, condition number about
    /// 4m²/π²): the diagonal preconditioner runs out of its budget, the step is solved with
    /// the Cholesky factor, which the Jacobian keeps, and it solves `C dx = g`.
    #[test]
    fn a_small_ill_conditioned_system_falls_back_to_the_cholesky_factor() {
        let m = 1000;
        let chain: Vec<Row> = (0..m as u32)
            .map(|k| Row {
                family: Family::Developability,
                value: ((k as f64) * 0.37).sin(),
                entries: vec![(k, DVec3::X), (k + 1, -DVec3::X)],
            })
            .collect();
        assert!(chain.len() < FACTOR_ROWS);
        let g: Vec<f64> = chain.iter().map(|r| r.value).collect();
        let c = Jacobian::new(&chain, m + 1);
        let (dx, iterations) = min_norm(&c, &g, 1e-12);
        assert!(matches!(
            c.preconditioner.get(),
            Some((Preconditioner::Jacobi(_), _))
        ));
        assert!(matches!(
            c.fallback.get(),
            Some(Some(Preconditioner::Cholesky(_)))
        ));
        assert!(iterations > JACOBI_BUDGET, "{iterations}");
        let residual = max_residual(&c, &dx, &g);
        assert!(residual < 1e-6, "{residual}");
        // A second step on the same rows goes straight to the factor.
        let (again, more) = min_norm(&c, &g, 1e-12);
        assert!(more < 50, "{more}");
        let diff = dx
            .iter()
            .zip(&again)
            .fold(0.0f64, |a, (p, q)| a.max(p.distance(*q)));
        assert!(diff < 1e-9, "{diff}");
    }

    /// The damped step minimizes ‖C dx − g‖² + μ‖dx‖² (Levenberg 1944), so it solves the
    /// normal equations `(CᵀC + μI) dx = Cᵀ g`, checked here on the other side of the
    /// identity `Cᵀ (C Cᵀ + μI)⁻¹ = (CᵀC + μI)⁻¹ Cᵀ`; it shortens as μ grows and descends
    /// ½‖g‖² (`gᵀ C dx > 0`). Both preconditioners.
    #[test]
    fn damped_steps_solve_the_levenberg_marquardt_normal_equations() {
        for (m, n) in [(40, 100), (FACTOR_ROWS + 100, 1200)] {
            let rows = rows(m, n);
            let g: Vec<f64> = rows.iter().map(|r| r.value).collect();
            let c = Jacobian::new(&rows, n);
            let largest = diagonal(&c, ROUNDOFF)
                .0
                .iter()
                .fold(0.0f64, |a, &d| a.max(d));
            let mut last = f64::INFINITY;
            for relative in [1e-6, 1e-3, 1e-1, 1.0, 10.0] {
                let (dx, _) = damped_min_norm(&c, &g, relative, 1e-12);
                let mu = relative * largest;
                let cdx = c.times_vec(&dx);
                let miss: Vec<f64> = cdx.iter().zip(&g).map(|(a, b)| a - b).collect();
                let mut normal = vec![DVec3::ZERO; n];
                c.transpose_times(&miss, &mut normal);
                let worst = normal
                    .iter()
                    .zip(&dx)
                    .fold(0.0f64, |a, (r, d)| a.max((*r + mu * *d).length()));
                let scale = dx.iter().fold(0.0f64, |a, d| a.max(d.length())) * largest;
                assert!(
                    worst < 1e-8 * scale.max(1.0),
                    "{m} rows, μ {relative}: {worst:e}"
                );
                let length = dx.iter().map(|d| d.length_squared()).sum::<f64>().sqrt();
                assert!(
                    length < last,
                    "{m} rows, μ {relative}: {length} after {last}"
                );
                last = length;
                let descent: f64 = g.iter().zip(&cdx).map(|(a, b)| a * b).sum();
                assert!(descent > 0.0, "{m} rows, μ {relative}: {descent}");
            }
        }
    }

    #[test]
    fn small_systems_use_the_diagonal() {
        let rows = rows(40, 100);
        let g: Vec<f64> = rows.iter().map(|r| r.value).collect();
        let c = Jacobian::new(&rows, 100);
        let (dx, _) = min_norm(&c, &g, 1e-12);
        assert!(matches!(
            c.preconditioner.get(),
            Some((Preconditioner::Jacobi(_), _))
        ));
        let residual = max_residual(&c, &dx, &g);
        assert!(residual < 1e-8, "{residual}");
    }
}
