//! Generalized Newton–Raphson (§3.3): `X ← X − α C(X)⁺ g(X)`.
//!
//! The minimum-norm step `C⁺g = Cᵀ y` with `(C Cᵀ + εI) y = g` is solved by a conjugate
//! gradient over a compressed copy of the sparse rows of [`constraints::rows`], preconditioned
//! by a sparse Cholesky factor of `C Cᵀ` on large systems (`min_norm`). The CG stops at a
//! relative residual η = clamp(‖g‖, 1e-12, 1e-3) (an inexact Newton method: rough steps far
//! from the solution, exact ones near it). The step length α is found by backtracking on
//! ½‖g‖² over the rows active at the trial point, starting from the longest step that moves
//! no vertex farther than a tenth of the mean edge length. Deviation: the paper's interactive
//! solver moves in small steps; without this cap a full first step (for instance onto the
//! ground plane of §6) can push creases through vertex-adjacent faces, where the eq. 5–7
//! penalty (a necessary condition that only works from an untangled state) then holds the
//! solve in a tangled minimum. When neither the rough nor the exact step descends, one step is
//! taken with every inequality entering the active set continuously ([`Limits::hold`] = 1):
//! the hysteresis of the active set makes the merit jump where a row enters, which can block
//! every step near the limits (the twisted saddle stalled so at 1e-4 rad); the next iteration
//! returns to the hysteresis set, and two such steps never follow each other. With
//! [`SolveOptions::damped_fallback`], when that too finds no descent, Levenberg–Marquardt
//! steps `Cᵀ (C Cᵀ + μI)⁻¹ g` are tried with μ growing from 1e-8 to 1 of the largest diagonal
//! entry of `C Cᵀ` (Levenberg 1944, Marquardt 1963; a descent direction of ½‖g‖² for the
//! rows active now, shorter than the minimum-norm step where rows are nearly dependent).
//! Convergence:
//! every interior vertex developable within [`SolveOptions::tolerance`] radians, every flat
//! diagonal flat and every limit satisfied.

use std::cell::Cell;

use glam::DVec3;

use super::TessError;
use super::constraints::{self, Family, Limits, Residuals, Row};
use super::min_norm::{Jacobian, damped_min_norm, min_norm};
use super::model::TessMesh;
use super::pipeline::Watch;
use super::vertex_penalty;
use crate::clock::Deadline;

/// Solver settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SolveOptions {
    /// Fabrication limits.
    pub limits: Limits,
    /// Required developability residual, radians per vertex.
    pub tolerance: f64,
    /// Newton iteration cap.
    pub max_iterations: usize,
    /// When no step descends (rough, exact, or with continuous entry of the inequalities),
    /// try Levenberg–Marquardt steps `Cᵀ (C Cᵀ + μI)⁻¹ g` with growing damping μ before
    /// giving up (beyond the paper; see the module docs). Off by default; the pipeline
    /// turns it on for twisted stars.
    pub damped_fallback: bool,
}

impl Default for SolveOptions {
    fn default() -> Self {
        SolveOptions {
            limits: Limits::default(),
            tolerance: 1e-12,
            max_iterations: 200,
            damped_fallback: false,
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
    /// Whether a boundary row (Tachi 2014, eq. 2) was among any rows the solve evaluated,
    /// at an iterate or a trial step. When none was, the solve is the same to the bit with
    /// either [`BoundaryRuns`](super::constraints::BoundaryRuns) form: a violated run implies a violated
    /// dominant run, so both forms have no boundary row at exactly the same points.
    pub boundary_rows: bool,
    /// Whether the solve stopped because its time limit ran out
    /// ([`TessellateOptions::time_limit`](super::TessellateOptions::time_limit)) before it
    /// converged or gave up.
    pub out_of_time: bool,
}

impl SolveReport {
    /// A short multi-line summary: residual per condition family and the limits.
    pub fn summary(&self) -> String {
        let deg = |r: f64| r.to_degrees();
        format!(
            "{} after {} iterations\n  developability: largest angle defect (2 pi minus the \
             face angles around a vertex) = {:.3e} rad (start {:.3e})\n  fold angles: largest \
             |fold angle| = {:.2} deg, limit {:.2} deg; folds of the wrong sign: {}\n  vertex \
             angles: smallest angle between neighbouring creases = {:.2} deg, limit {:.2} deg\n  \
             flat diagonals: largest fold of a diagonal meant to stay flat = {:.1e} rad\n  \
             boundary: smallest turn of a boundary run + pi = {:.2} deg (>= 0)\n  \
             vertex-adjacent faces (Tachi 2014 corner penalty{}): illegal creases {} (start {}), max penalty {:.2e}",
            if self.converged {
                "converged"
            } else if self.out_of_time {
                "NOT converged (the time limit ran out)"
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

/// Solves the constraints for `mesh.positions` in place (Tachi 2014, §3.3), calling
/// `watch` ([`Watch::iteration`]: `()` hears nothing, a closure over [`Iteration`] hears
/// every one) after every iteration; [`Break`](std::ops::ControlFlow::Break) from it stops
/// the solve at once with [`TessError::Cancelled`] (`mesh` is then left as it was). Errors
/// otherwise only on bad options; not converging is reported, not an error.
pub fn solve(
    mesh: &mut TessMesh,
    opts: &SolveOptions,
    watch: impl Watch,
) -> Result<SolveReport, TessError> {
    solve_until(mesh, opts, &Deadline::after(None), watch)
}

/// [`solve`], stopping before an iteration once `deadline` has passed: the positions
/// reached are kept and the report says [`SolveReport::out_of_time`].
///
/// # Errors
/// As [`solve`].
pub fn solve_until(
    mesh: &mut TessMesh,
    opts: &SolveOptions,
    deadline: &Deadline,
    mut watch: impl Watch,
) -> Result<SolveReport, TessError> {
    let l = opts.limits;
    let valid = opts.tolerance > 0.0
        && l.max_fold > 0.0
        && l.max_fold <= std::f64::consts::PI
        && l.min_vertex_angle >= 0.0
        && l.min_vertex_angle < std::f64::consts::FRAC_PI_3
        && l.margin >= 0.0
        && l.hold > 0.0
        && l.hold <= 1.0;
    if !valid {
        return Err(TessError::BadParameter(format!(
            "limits out of range: fold angle must be in (0, 180] deg, vertex angle in [0, 60) deg, \
             hold in (0, 1], got {:.2}, {:.2} and {}",
            l.max_fold.to_degrees(),
            l.min_vertex_angle.to_degrees(),
            l.hold
        )));
    }
    let initial = constraints::residuals(mesh, &mesh.positions, l.ground_z);
    let mut last = initial;
    let mut iterations = 0;
    let mut x = mesh.positions.clone();
    let eval = RowsAt {
        mesh,
        boundary: Cell::new(false),
    };
    let mut rows = eval.rows(&x, &l);
    let mut merit = merit_of(&rows);
    let cap = 0.1 * mean_edge(mesh, &x);
    let mut smoothed = false;
    let mut out_of_time = false;
    while iterations < opts.max_iterations && !satisfied(&last, opts) {
        if deadline.passed() {
            out_of_time = true;
            break;
        }
        iterations += 1;
        let g: Vec<f64> = rows.iter().map(|r| r.value).collect();
        // Inexact Newton: the CG's relative residual η shrinks with ‖g‖, so far from the
        // solution a rough step does and near it the step is exact (quadratic convergence).
        // When the rough step finds no descent, the exact one is tried.
        let norm = g.iter().map(|v| v * v).sum::<f64>().sqrt();
        let eta = norm.clamp(EXACT, 1e-3);
        let c = Jacobian::new(&rows, x.len());
        let (dx, mut cg_iterations) = min_norm(&c, &g, eta);
        let mut found = line_search(&eval, &l, &x, &dx, merit, cap);
        let mut smoothing = false;
        if found.is_none() && eta > EXACT {
            let (dx, more) = min_norm(&c, &g, EXACT);
            cg_iterations += more;
            found = line_search(&eval, &l, &x, &dx, merit, cap);
        }
        if found.is_none() && l.hold < 1.0 && !smoothed {
            // The active set's hysteresis makes the merit jump where a row enters it; step
            // with every row entering continuously (at its target), not twice in a row.
            smoothing = true;
            let smooth = Limits { hold: 1.0, ..l };
            let rows = eval.rows(&x, &smooth);
            let g: Vec<f64> = rows.iter().map(|r| r.value).collect();
            let c = Jacobian::new(&rows, x.len());
            let (dx, more) = min_norm(&c, &g, EXACT);
            cg_iterations += more;
            found = line_search(&eval, &smooth, &x, &dx, merit_of(&rows), cap).map(|f| Found {
                rows: eval.rows(&f.x, &l),
                ..f
            });
            if let Some(f) = found.as_mut() {
                f.merit = merit_of(&f.rows);
            }
        }
        if found.is_none() && opts.damped_fallback {
            // Levenberg–Marquardt: shorter steps that lean towards steepest descent, for
            // nearly dependent active rows whose minimum-norm step is long and finds no
            // descent within the line search's reach.
            for &relative in &DAMPING {
                let (dx, more) = damped_min_norm(&c, &g, relative, EXACT);
                cg_iterations += more;
                found = line_search(&eval, &l, &x, &dx, merit, cap);
                if found.is_some() {
                    smoothing = false;
                    break;
                }
            }
        }
        smoothed = found.is_some() && smoothing;
        let Some(Found {
            x: trial,
            rows: trial_rows,
            merit: m,
            step,
        }) = found
        else {
            break;
        };
        x = trial;
        rows = trial_rows;
        merit = m;
        last = constraints::residuals(mesh, &x, l.ground_z);
        let heard = watch.iteration(&Iteration {
            index: iterations,
            residuals: last,
            active: active_counts(&rows),
            step,
            cg_iterations,
        });
        if heard.is_break() {
            return Err(TessError::Cancelled);
        }
    }
    let boundary_rows = eval.boundary.get();
    mesh.positions = x;
    Ok(SolveReport {
        converged: satisfied(&last, opts),
        iterations,
        initial,
        last,
        limits: l,
        boundary_rows,
        out_of_time,
    })
}

/// The CG tolerance of an exact step.
const EXACT: f64 = 1e-12;

/// The Levenberg–Marquardt dampings of [`SolveOptions::damped_fallback`], relative to the
/// largest diagonal entry of `C Cᵀ`, smallest first.
const DAMPING: [f64; 5] = [1e-8, 1e-6, 1e-4, 1e-2, 1.0];

/// The rows of a mesh's conditions at given positions, noting whether a boundary row was
/// ever among them ([`SolveReport::boundary_rows`]).
struct RowsAt<'a> {
    mesh: &'a TessMesh,
    boundary: Cell<bool>,
}

impl RowsAt<'_> {
    fn rows(&self, x: &[DVec3], limits: &Limits) -> Vec<Row> {
        let rows = constraints::rows(self.mesh, x, limits);
        if rows.iter().any(|r| r.family == Family::Boundary) {
            self.boundary.set(true);
        }
        rows
    }
}

/// An accepted Newton step.
struct Found {
    x: Vec<DVec3>,
    rows: Vec<Row>,
    merit: f64,
    step: f64,
}

/// The step `−α dx`, with α by backtracking from the longest step that moves no vertex
/// farther than `cap`; `None` without descent of the merit.
fn line_search(
    eval: &RowsAt,
    limits: &Limits,
    x: &[DVec3],
    dx: &[DVec3],
    merit: f64,
    cap: f64,
) -> Option<Found> {
    let reach = dx.iter().fold(0.0f64, |m, d| m.max(d.length()));
    let mut step = if reach > 0.0 {
        (cap / reach).min(1.0)
    } else {
        1.0
    };
    while step > 1e-6 {
        let trial: Vec<DVec3> = x.iter().zip(dx).map(|(p, d)| *p - step * *d).collect();
        let trial_rows = eval.rows(&trial, limits);
        let m = merit_of(&trial_rows);
        if m < merit || m == 0.0 {
            return Some(Found {
                x: trial,
                rows: trial_rows,
                merit: m,
                step,
            });
        }
        step *= 0.5;
    }
    None
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
            Family::VertexPenalty | Family::Collision => 6,
            Family::Flat => 7,
        }] += 1;
    }
    c
}
