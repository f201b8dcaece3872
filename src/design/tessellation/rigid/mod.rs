//! Rigid-foldability check (§5): Tachi's rigid origami simulation ("Simulation of rigid
//! origami", the paper's reference 11) run from the flat sheet to the target fold angles.
//!
//! Unknowns are the fold angles ρ of all creases (FOLD sign: valley positive). Every interior
//! vertex with creases `l_1 … l_n` in counter-clockwise order (unit directions in the flat
//! pattern) gives the loop-closure condition `R(l_1, ρ_1) ⋯ R(l_n, ρ_n) = I`; its three
//! residuals are the skew part of the product, `vee((P − Pᵀ)/2)`. The Jacobian is analytic:
//! `∂P/∂ρ_k = A_k [l_k]× R_k B_k` with `A_k`, `B_k` the products before and after crease `k`
//! (at closure this is `[A_k l_k]×`, the crease axis in the folded frame).
//!
//! Simulation: in step `s` of `N` the desired increment `Δρ = (ρ_target − ρ)/(N − s + 1)` is
//! projected onto the null space of the Jacobian, `Δρ − Jᵀ(JJᵀ)⁻¹JΔρ`, then Newton steps
//! `−Jᵀ(JJᵀ)⁻¹r` bring ρ back onto the constraint manifold (both by conjugate gradient on
//! `JJᵀ`, matrix-free). After the N steps the same projected step towards the target is
//! repeated until it stops changing ρ. Faces are placed in 3D by composing rotations about
//! the crease lines from a root face (breadth-first), and every step checks all pairs of
//! triangles that share no vertex for intersection.
//!
//! Deviations and limits: the skew-part residual cannot see a loop that is off by a half-turn
//! (the reported closure error is `‖P − I‖`, which does); faces that share a vertex are not
//! checked for penetration here (the vertex-adjacent conditions eq. 5–7 are the solver's job);
//! the collision test is O(T²) per step with an x-sorted sweep.
//!
//! Files: [`model`] builds the kinematic model (loops, Jacobian, face placement), `newton`
//! holds the projections, `collide` the triangle–triangle test.

mod collide;
pub mod model;
mod newton;

pub use model::RigidModel;

use glam::DVec3;
use thiserror::Error;

/// Why a pattern cannot be simulated.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum RigidError {
    /// The pattern has no usable faces.
    #[error("the crease pattern has no faces")]
    NoFaces,
    /// A face is not a simple polygon of at least three vertices.
    #[error("face {0} is not a simple polygon with at least three corners and no holes")]
    BadFace(usize),
    /// A face side is not an edge of the pattern, or an edge borders more than two faces.
    #[error("face {face}: side {a}-{b} {problem}")]
    BadSide {
        /// The face.
        face: usize,
        /// First vertex of the side.
        a: usize,
        /// Second vertex of the side.
        b: usize,
        /// What is wrong.
        problem: &'static str,
    },
    /// The faces do not form one connected sheet.
    #[error("face {0} is not connected to face 0 across creases")]
    Disconnected(usize),
    /// A coordinate or target angle is not finite, or the targets have the wrong length.
    #[error("{0}")]
    BadInput(String),
}

/// Simulation settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RigidOptions {
    /// Number of increments from flat to the target (≥ 1).
    pub steps: usize,
    /// Loop-closure tolerance of the Newton correction (‖skew part‖ per vertex).
    pub tolerance: f64,
    /// Largest fold-angle error, radians, that still counts as reaching the target.
    pub angle_tolerance: f64,
}

/// Default [`RigidOptions::tolerance`]: the loop-closure skew per vertex at which a Newton
/// correction stops (unit vectors' round-off, [`crate::geom::tolerance::ROUNDOFF`]).
pub const DEFAULT_TOLERANCE: f64 = 1e-12;

/// Default [`RigidOptions::angle_tolerance`], radians (about 6 × 10⁻⁵ degrees).
pub const DEFAULT_ANGLE_TOLERANCE: f64 = 1e-6;

impl Default for RigidOptions {
    fn default() -> Self {
        RigidOptions {
            steps: 100,
            tolerance: DEFAULT_TOLERANCE,
            angle_tolerance: DEFAULT_ANGLE_TOLERANCE,
        }
    }
}

/// Where and why the simulation stopped early.
#[derive(Clone, Debug, PartialEq)]
pub enum Stuck {
    /// The Newton correction did not return to the constraint manifold at this step.
    Closure {
        /// The step (1-based).
        step: usize,
        /// Largest closure error `‖P − I‖` left.
        residual: f64,
    },
    /// Two triangles (indices into the fan-triangulated faces) intersect at this step.
    Collision {
        /// The step (1-based).
        step: usize,
        /// The faces the two triangles belong to.
        faces: [usize; 2],
    },
}

/// The outcome of [`simulate`].
#[derive(Clone, Debug, PartialEq)]
pub struct RigidReport {
    /// Whether the target was reached within the angle tolerance, on the constraint manifold,
    /// without collisions.
    pub reached: bool,
    /// Largest `|ρ − ρ_target|` at the end, radians.
    pub angle_error: f64,
    /// Largest closure error `‖P − I‖` (Frobenius) over all vertices and steps.
    pub max_residual: f64,
    /// Largest closure error at the end.
    pub final_residual: f64,
    /// Steps completed (at most the steps asked for).
    pub steps: usize,
    /// Correction rounds after the last step, aimed at the target itself.
    pub polish_rounds: usize,
    /// Why the run stopped early, if it did.
    pub stuck: Option<Stuck>,
    /// Two faces that intersect in the target shape itself (faces placed by the target
    /// angles), if any: then no folding path can reach it without collision.
    pub target_collision: Option<[usize; 2]>,
    /// The fold angles at the end, per crease (see [`RigidModel::crease_edges`]), radians.
    pub angles: Vec<f64>,
    /// Vertex positions at the end (each vertex placed by the first face that holds it), mm.
    pub positions: Vec<DVec3>,
}

impl RigidReport {
    /// A one-paragraph summary for the command line.
    pub fn summary(&self) -> String {
        let verdict = if self.reached {
            "reached the target".to_string()
        } else {
            match &self.stuck {
                Some(Stuck::Closure { step, residual }) => {
                    format!("stuck at step {step}: loop closure not restored ({residual:.2e})")
                }
                Some(Stuck::Collision { step, faces }) => {
                    format!(
                        "stuck at step {step}: faces {} and {} collide",
                        faces[0], faces[1]
                    )
                }
                None => "did not reach the target".into(),
            }
        };
        let target = match self.target_collision {
            Some([a, b]) => format!("; faces {a} and {b} intersect in the target shape itself"),
            None => "; the target shape has no face intersections".into(),
        };
        format!(
            "rigid folding: {verdict} after {} steps{}; final angle error {:.3e} deg, \
             max loop-closure residual {:.2e} (final {:.2e}){target}",
            self.steps,
            match self.polish_rounds {
                0 => String::new(),
                1 => " and 1 correction round".into(),
                n => format!(" and {n} correction rounds"),
            },
            self.angle_error.to_degrees(),
            self.max_residual,
            self.final_residual
        )
    }
}

/// A loop-closure residual (or correction skew) above this means the fold left the
/// constraint manifold: the run is stuck.
const STALL_RESIDUAL: f64 = 1e-3;
/// The correction skew allowed per unit of [`RigidOptions::tolerance`] (capped by
/// [`STALL_RESIDUAL`]).
const SKEW_PER_TOLERANCE: f64 = 1e6;
/// Correction rounds stop once no angle moves more than this share of
/// [`RigidOptions::angle_tolerance`].
const SETTLED_SHARE: f64 = 1e-3;

pub(super) fn bad(msg: String) -> RigidError {
    RigidError::BadInput(msg)
}

/// Simulates folding from flat to `target` (radians per crease, in the order of
/// [`RigidModel::crease_edges`]) and reports how far it got (see the module docs).
/// `progress` hears each of the `opts.steps` steps (step number from 1, loop-closure
/// residual), not the correction rounds after them.
pub fn simulate(
    model: &RigidModel,
    target: &[f64],
    opts: &RigidOptions,
    mut progress: impl FnMut(usize, f64),
) -> Result<RigidReport, RigidError> {
    let n = model.creases.len();
    if target.len() != n {
        return Err(bad(format!(
            "{} target angles for {n} creases",
            target.len()
        )));
    }
    if let Some(c) = target.iter().position(|t| !t.is_finite()) {
        return Err(bad(format!("the target angle of crease {c} is not finite")));
    }
    if opts.steps == 0 || opts.steps > 1_000_000 {
        return Err(bad(format!(
            "steps must be in 1..=1000000, got {}",
            opts.steps
        )));
    }
    let mut rho = vec![0.0; n];
    let mut max_residual = 0.0f64;
    let mut stuck = None;
    let mut steps = 0;
    let mut polish_rounds = 0;
    let stall = STALL_RESIDUAL;
    // Up to `steps` increments, then a few polishing rounds aimed at the target itself.
    for s in 1..=opts.steps + 50 {
        let remaining = opts.steps.saturating_sub(s - 1).max(1) as f64;
        let d: Vec<f64> = target
            .iter()
            .zip(&rho)
            .map(|(t, r)| (t - r) / remaining)
            .collect();
        let dp = model.project(&rho, &d);
        let moved = dp.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        for (x, dx) in rho.iter_mut().zip(dp) {
            *x += dx;
        }
        let skew = model.correct(&mut rho, opts.tolerance);
        let residual = model.closure_error(&rho);
        max_residual = max_residual.max(residual);
        steps = s.min(opts.steps);
        if s <= opts.steps {
            progress(s, residual);
        } else {
            polish_rounds = s - opts.steps;
        }
        if skew > stall.min(SKEW_PER_TOLERANCE * opts.tolerance) || residual > stall {
            stuck = Some(Stuck::Closure { step: s, residual });
            break;
        }
        let (_, frames) = model.positions(&rho);
        if let Some(faces) = model.collision(&frames) {
            stuck = Some(Stuck::Collision { step: s, faces });
            break;
        }
        if s >= opts.steps && moved <= SETTLED_SHARE * opts.angle_tolerance {
            break;
        }
    }
    let angle_error = target
        .iter()
        .zip(&rho)
        .fold(0.0f64, |m, (t, r)| m.max((t - r).abs()));
    let final_residual = model.closure_error(&rho);
    let target_collision = model.collision(&model.positions(target).1);
    Ok(RigidReport {
        reached: stuck.is_none() && angle_error <= opts.angle_tolerance,
        angle_error,
        max_residual,
        final_residual,
        steps,
        polish_rounds,
        stuck,
        target_collision,
        positions: model.positions(&rho).0,
        angles: rho,
    })
}
