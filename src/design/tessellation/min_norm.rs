//! The minimum-norm step of §3.3: `C⁺ g = Cᵀ y` with `(C Cᵀ + εI) y = g`, solved by a
//! Jacobi-preconditioned conjugate gradient on a compressed copy of the sparse rows (no dense
//! matrix is ever formed; ε is a tiny Tikhonov term that keeps redundant rows harmless).

use glam::DVec3;

use super::constraints::Row;

/// The rows' Jacobian in compressed sparse row form, one 3-vector block per (row, vertex).
pub(crate) struct Jacobian {
    offsets: Vec<usize>,
    vertices: Vec<u32>,
    blocks: Vec<DVec3>,
    n: usize,
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
pub(crate) fn min_norm(c: &Jacobian, g: &[f64], eta: f64) -> (Vec<DVec3>, usize) {
    let m = c.rows();
    let diag: Vec<f64> = (0..m)
        .map(|r| c.row(r).map(|(_, b)| b.length_squared()).sum())
        .collect();
    let eps = 1e-12 * diag.iter().fold(0.0f64, |a, &d| a.max(d)).max(1e-300);
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
    let mut z: Vec<f64> = r.iter().zip(&diag).map(|(a, d)| a / (d + eps)).collect();
    let mut p = z.clone();
    let mut ap = vec![0.0; m];
    let mut rz = dot(&r, &z);
    let goal = eta * eta * dot(g, g);
    let cap = 10 * m + 100;
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
            z[k] = r[k] / (diag[k] + eps);
        }
        let rz_new = dot(&r, &z);
        let beta = rz_new / rz;
        rz = rz_new;
        for k in 0..m {
            p[k] = z[k] + beta * p[k];
        }
    }
    let mut dx = vec![DVec3::ZERO; c.n];
    c.transpose_times(&y, &mut dx);
    (dx, it)
}
