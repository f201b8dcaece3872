//! Generalized Newton–Raphson (§3.3): `X ← X − α C(X)⁺ g(X)`.
//!
//! The minimum-norm step `C⁺g = Cᵀ y` with `(C Cᵀ + εI) y = g` is solved by a matrix-free,
//! Jacobi-preconditioned conjugate gradient over the sparse rows of [`constraints::rows`]
//! (no dense matrix is ever formed; ε is a tiny Tikhonov term that keeps redundant rows
//! harmless). The step length α is found by backtracking on ½‖g‖² over the rows active at
//! the trial point, starting from the longest step that moves no vertex farther than a tenth
//! of the mean edge length. Deviation: the paper's interactive solver moves in small steps;
//! without this cap a full first step (for instance onto the ground plane of §6) can push
//! creases through vertex-adjacent faces, where the eq. 5–7 penalty (a necessary condition
//! that only works from an untangled state) then holds the solve in a tangled minimum. Convergence: every interior vertex developable within
//! [`SolveOptions::tolerance`] radians and every limit satisfied.

use glam::DVec3;

use super::TessError;
use super::constraints::{self, Family, Limits, Residuals, Row};
use super::model::TessMesh;
use super::vertex_penalty;

/// Solver settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SolveOptions {
    /// Fabrication limits.
    pub limits: Limits,
    /// Required developability residual, radians per vertex.
    pub tolerance: f64,
    /// Newton iteration cap.
    pub max_iterations: usize,
}

impl Default for SolveOptions {
    fn default() -> Self {
        SolveOptions {
            limits: Limits::default(),
            tolerance: 1e-12,
            max_iterations: 200,
        }
    }
}

/// One iteration's state, for progress messages.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Iteration {
    /// Iteration number (1-based).
    pub index: usize,
    /// Residuals after the step.
    pub residuals: Residuals,
    /// Active rows per family: developability, fold limit, fold sign, vertex angle, ground,
    /// boundary (eq. 2), vertex-adjacent penalty (eq. 5–7), flat diagonals.
    pub active: [usize; 8],
    /// Step length α taken.
    pub step: f64,
    /// Conjugate-gradient iterations used.
    pub cg_iterations: usize,
}

/// How the solve went.
#[derive(Clone, Debug, PartialEq)]
pub struct SolveReport {
    /// Whether every condition holds (see the module docs).
    pub converged: bool,
    /// Newton iterations done.
    pub iterations: usize,
    /// Residuals before solving.
    pub initial: Residuals,
    /// Residuals at the end.
    pub last: Residuals,
    /// The limits solved for.
    pub limits: Limits,
}

impl SolveReport {
    /// A short multi-line summary: residual per condition family and the limits.
    pub fn summary(&self) -> String {
        let deg = |r: f64| r.to_degrees();
        format!(
            "{} after {} iterations\n  developability (eq. 1): max |2pi - sum theta| = {:.3e} rad \
             (start {:.3e})\n  fold angles (eq. 3): max |rho| = {:.2} deg, limit {:.2} deg; \
             wrong-sign folds: {}\n  vertex angles: min theta = {:.2} deg, limit {:.2} deg\n  \
             flat diagonals: max |rho| = {:.1e} rad\n  \
             boundary (eq. 2): min turning of a boundary run + pi = {:.2} deg (>= 0)\n  \
             vertex-adjacent faces (eq. 5-7{}): illegal creases {} (start {}), max penalty {:.2e}",
            if self.converged {
                "converged"
            } else {
                "NOT converged"
            },
            self.iterations,
            self.last.developability,
            self.initial.developability,
            deg(self.last.max_fold),
            deg(self.limits.max_fold),
            if self.last.wrong_sign < 0.0 {
                format!("worst {:.2} deg", deg(self.last.wrong_sign))
            } else {
                "none".into()
            },
            deg(self.last.min_vertex_angle),
            deg(self.limits.min_vertex_angle),
            self.last.max_flat,
            deg(self.last.boundary_turn),
            if self.limits.vertex_penalty {
                ""
            } else {
                ", rows off"
            },
            self.last.illegal_creases,
            self.initial.illegal_creases,
            self.last.max_penalty,
        ) + &match self.limits.ground_z {
            Some(z) => format!(
                "\n  ground contact at z = {z:.3}: max boundary distance {:.2e}",
                self.last.ground
            ),
            None => String::new(),
        }
    }
}

fn satisfied(r: &Residuals, opts: &SolveOptions) -> bool {
    r.developability <= opts.tolerance
        && r.max_fold <= opts.limits.max_fold
        && r.wrong_sign >= 0.0
        && r.min_vertex_angle >= opts.limits.min_vertex_angle
        && r.ground <= GROUND_TOLERANCE
        && r.boundary_turn >= 0.0
        && r.max_flat <= FLAT_TOLERANCE
        && (!opts.limits.vertex_penalty || r.max_penalty <= vertex_penalty::TOLERANCE)
}

/// Largest accepted fold of a flat diagonal, radians.
pub const FLAT_TOLERANCE: f64 = 1e-9;

/// Largest accepted distance of a boundary vertex from the ground plane, mesh units.
pub const GROUND_TOLERANCE: f64 = 1e-9;

/// Solves the constraints for `mesh.positions` in place (§3.3), calling `progress` after every
/// iteration. Errors only on bad options; not converging is reported, not an error.
pub fn solve(
    mesh: &mut TessMesh,
    opts: &SolveOptions,
    mut progress: impl FnMut(&Iteration),
) -> Result<SolveReport, TessError> {
    let l = opts.limits;
    let valid = opts.tolerance > 0.0
        && l.max_fold > 0.0
        && l.max_fold <= std::f64::consts::PI
        && l.min_vertex_angle >= 0.0
        && l.min_vertex_angle < std::f64::consts::FRAC_PI_3
        && l.margin >= 0.0;
    if !valid {
        return Err(TessError::BadParameter(format!(
            "limits out of range: fold angle must be in (0, 180] deg, vertex angle in [0, 60) deg, \
             got {:.2} and {:.2}",
            l.max_fold.to_degrees(),
            l.min_vertex_angle.to_degrees()
        )));
    }
    let initial = constraints::residuals(mesh, &mesh.positions, l.ground_z);
    let mut last = initial;
    let mut iterations = 0;
    let mut x = mesh.positions.clone();
    let mut rows = constraints::rows(mesh, &x, &l);
    let mut merit = merit_of(&rows);
    let cap = 0.1 * mean_edge(mesh, &x);
    while iterations < opts.max_iterations && !satisfied(&last, opts) {
        iterations += 1;
        let g: Vec<f64> = rows.iter().map(|r| r.value).collect();
        let (dx, cg_iterations) = min_norm(&rows, &g, x.len());
        let reach = dx.iter().fold(0.0f64, |m, d| m.max(d.length()));
        let mut step = if reach > 0.0 {
            (cap / reach).min(1.0)
        } else {
            1.0
        };
        let mut accepted = None;
        while step > 1e-6 {
            let trial: Vec<DVec3> = x.iter().zip(&dx).map(|(p, d)| *p - step * *d).collect();
            let trial_rows = constraints::rows(mesh, &trial, &l);
            let m = merit_of(&trial_rows);
            if m < merit || m == 0.0 {
                accepted = Some((trial, trial_rows, m));
                break;
            }
            step *= 0.5;
        }
        let Some((trial, trial_rows, m)) = accepted else {
            break;
        };
        x = trial;
        rows = trial_rows;
        merit = m;
        last = constraints::residuals(mesh, &x, l.ground_z);
        progress(&Iteration {
            index: iterations,
            residuals: last,
            active: active_counts(&rows),
            step,
            cg_iterations,
        });
    }
    mesh.positions = x;
    Ok(SolveReport {
        converged: satisfied(&last, opts),
        iterations,
        initial,
        last,
        limits: l,
    })
}

fn mean_edge(mesh: &TessMesh, x: &[DVec3]) -> f64 {
    let total: f64 = mesh
        .edges
        .iter()
        .map(|e| x[e.vertices[0] as usize].distance(x[e.vertices[1] as usize]))
        .sum();
    total / mesh.edges.len().max(1) as f64
}

fn merit_of(rows: &[Row]) -> f64 {
    0.5 * rows.iter().map(|r| r.value * r.value).sum::<f64>()
}

fn active_counts(rows: &[Row]) -> [usize; 8] {
    let mut c = [0; 8];
    for r in rows {
        c[match r.family {
            Family::Developability => 0,
            Family::FoldLimit => 1,
            Family::FoldSign => 2,
            Family::VertexAngle => 3,
            Family::Ground => 4,
            Family::Boundary => 5,
            Family::VertexPenalty => 6,
            Family::Flat => 7,
        }] += 1;
    }
    c
}

/// `Cᵀ y` scattered into per-vertex blocks.
fn transpose_times(rows: &[Row], y: &[f64], n: usize) -> Vec<DVec3> {
    let mut out = vec![DVec3::ZERO; n];
    for (r, &yr) in rows.iter().zip(y) {
        for &(v, g) in &r.entries {
            out[v as usize] += yr * g;
        }
    }
    out
}

/// `C dx` for per-vertex blocks `dx`.
pub(crate) fn times(rows: &[Row], dx: &[DVec3]) -> Vec<f64> {
    rows.iter()
        .map(|r| r.entries.iter().map(|&(v, e)| e.dot(dx[v as usize])).sum())
        .collect()
}

/// The minimum-norm solution `dx = Cᵀ y` of `C dx = g` (that is `C⁺ g`), with
/// `(C Cᵀ + εI) y = g` solved by Jacobi-preconditioned conjugate gradient. Returns the step
/// and the CG iteration count.
pub(crate) fn min_norm(rows: &[Row], g: &[f64], n: usize) -> (Vec<DVec3>, usize) {
    let g = g.to_vec();
    let diag: Vec<f64> = rows
        .iter()
        .map(|r| {
            r.entries
                .iter()
                .map(|(_, e)| e.length_squared())
                .sum::<f64>()
        })
        .collect();
    let eps = 1e-12 * diag.iter().fold(0.0f64, |m, &d| m.max(d)).max(1e-300);
    let apply = |y: &[f64]| -> Vec<f64> {
        let z = transpose_times(rows, y, n);
        rows.iter()
            .zip(y)
            .map(|(r, &yr)| {
                r.entries
                    .iter()
                    .map(|&(v, e)| e.dot(z[v as usize]))
                    .sum::<f64>()
                    + eps * yr
            })
            .collect()
    };
    let precondition =
        |r: &[f64]| -> Vec<f64> { r.iter().zip(&diag).map(|(a, d)| a / (d + eps)).collect() };
    let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    let mut y = vec![0.0; g.len()];
    let mut r = g.clone();
    let mut z = precondition(&r);
    let mut p = z.clone();
    let mut rz = dot(&r, &z);
    let goal = 1e-24 * dot(&g, &g);
    let cap = 10 * g.len() + 100;
    let mut it = 0;
    while it < cap && dot(&r, &r) > goal {
        it += 1;
        let ap = apply(&p);
        let pap = dot(&p, &ap);
        if pap.is_nan() || pap <= 0.0 {
            break;
        }
        let alpha = rz / pap;
        for k in 0..y.len() {
            y[k] += alpha * p[k];
            r[k] -= alpha * ap[k];
        }
        z = precondition(&r);
        let rz_new = dot(&r, &z);
        let beta = rz_new / rz;
        rz = rz_new;
        for k in 0..p.len() {
            p[k] = z[k] + beta * p[k];
        }
    }
    (transpose_times(rows, &y, n), it)
}
