//! Compliant 3D fold simulation: the bar-and-hinge model of Origami Simulator (Ghassaei,
//! Demaine & Gershenfeld, "Fast, Interactive Origami Simulation using GPU Computation", 2018),
//! run on the CPU.
//!
//! **Model** ([`model`]). Every face of the pattern is triangulated (spade's constrained
//! Delaunay triangulation, [`crate::geom::triangulate`]); every triangle side is an axial bar
//! (in-plane stiffness, Schenk & Guest 2011), every side shared by two triangles a hinge:
//! crease hinges are driven to `percent × target` (the edge's fold angle; a mountain without
//! one counts as −180°, a valley as +180°), facet hinges (flat lines and the triangulation's
//! own sides) to 0, which keeps faces flat. Cuts split the sheet.
//!
//! **Dynamics** ([`solver`]). Explicit damped dynamics (Ghassaei et al. 2018, section 3) run
//! as dynamic relaxation: masses scaled so that a unit time step is stable at every vertex,
//! kinetic damping (Barnes 1999), a linear ramp of the target, then holding until the
//! residual force falls below [`FoldOptions::tolerance`], or [`FoldOptions::max_steps`] or
//! [`FoldOptions::max_time`] stop it ([`Stop`]).
//!
//! **Static solve** ([`newton`], [`FoldOptions::implicit`], the default). The same
//! equilibrium found directly: load steps of sparse Levenberg–Marquardt iterations on the
//! model's energy, the explicit run taking over when it does not settle on the assignment
//! ([`FoldReport::static_solve`], [`FoldReport::produced`]). Each load step can be a frame,
//! handed over as soon as it is solved ([`fold_streamed`]).
//!
//! **Report** ([`FoldReport`]). Bar strain `(|d| − L)/L` per face (the largest over the bars
//! of its triangles) and where it is largest; the reached fold angle of every crease and the
//! largest error against its target; whether triangles pass through each other
//! ([`intersect`]). A pattern that cannot fold to its targets (Kawasaki violated at a vertex)
//! still settles, with its strain concentrated around that vertex, which the report names.
//!
//! **Limits.** No contact: layers may pass through each other (reported, not prevented).
//! The compliant model folds a rigid-foldable pattern up to bar strains of the order of
//! `crease stiffness × angle error / axial stiffness`; stiffer bars fold more exactly but need
//! a little more steps. The defaults (axial 3000, facet 200, crease 0.7: facets and bars
//! three to four orders stiffer than creases, where Origami Simulator's interactive defaults
//! are softer) fold a Miura-ori within 0.3 % of its rigid kinematics.

pub(crate) mod dihedral;
pub(crate) mod intersect;
pub(crate) mod model;
pub(crate) mod newton;
pub(crate) mod solver;

use std::time::Duration;

use crate::clock::Stopwatch;

use glam::{DVec2, DVec3};
use serde::Serialize;

use crate::pattern::{CreasePattern, EdgeId, FaceId, FoldedState};
pub use model::{BarHingeModel, HingeKind, ModelError, crease_target_deg};
pub use newton::START_STEPS as STATIC_START_STEPS;
pub use solver::Solver;

/// Most triangle pairs listed as crossing.
pub const MAX_CROSSINGS_LISTED: usize = 1000;

/// Tolerance of the crossing test, as a fraction of the mean bar length.
pub const CROSSING_TOLERANCE: f64 = 1e-3;

/// Largest number of frames recorded for an animation.
pub const MAX_FRAMES: usize = 200;

/// How to fold.
#[derive(Clone, Debug, PartialEq)]
pub struct FoldOptions {
    /// How far to fold, percent of every crease's target (0 to 100).
    pub percent: f64,
    /// Axial stiffness `EA` of the bars (a force; a bar's spring constant is `EA/L`).
    pub axial_stiffness: f64,
    /// Stiffness of crease hinges per unit crease length (a force).
    pub crease_stiffness: f64,
    /// Stiffness of facet hinges per unit length (a force).
    pub facet_stiffness: f64,
    /// Damping ratio ζ of the bars (0.45 in Origami Simulator).
    pub damping_ratio: f64,
    /// Steps over which the target rises from 0 to `percent`.
    pub ramp_steps: usize,
    /// Most steps in all.
    pub max_steps: usize,
    /// Longest run.
    pub max_time: Duration,
    /// Residual force (over `EA`) below which the fold has settled.
    pub tolerance: f64,
    /// Adaptive ramp (off by default): the target rises up to [`RAMP_SPEEDUP`] times faster
    /// than over [`Self::ramp_steps`] while the largest force on a vertex stays below
    /// [`RAMP_FORCE`] (the sheet keeps up with it), and falls back towards the linear rate when
    /// it does not; never slower than the linear ramp. It settles a rigid-foldable sheet such
    /// as a Miura-ori in about half the steps, to the same tolerance; a sheet that is not
    /// rigid-foldable from flat (a tessellation of a curved surface) can settle on another
    /// branch than with the slow ramp (the saddle example lands 2.2 % of its diagonal off its
    /// solved form instead of 1.7 %), so it is not the default.
    pub adaptive_ramp: bool,
    /// States recorded on the way for an animation (0: none; at most [`MAX_FRAMES`]): the
    /// explicit run takes them while its target rises; the static solve folds in at least this
    /// many load steps and records the end of each, settled at its target.
    pub frames: usize,
    /// Solve for static equilibrium by load steps and Levenberg–Marquardt iterations
    /// ([`newton`]; the default) instead of the explicit dynamics, which take over when it
    /// does not settle on the assignment ([`FoldReport::static_solve`]). False: the explicit
    /// dynamics alone (with [`Self::ramp_steps`], [`Self::adaptive_ramp`]).
    pub implicit: bool,
}

/// Default [`FoldOptions::tolerance`]: the residual force, relative to the bars' axial
/// stiffness `EA`, below which the fold has settled (10⁻⁵: strains under about 0.001 %).
pub const SETTLED_RESIDUAL: f64 = 1e-5;

impl Default for FoldOptions {
    fn default() -> Self {
        FoldOptions {
            percent: 100.0,
            axial_stiffness: 3000.0,
            crease_stiffness: 0.7,
            facet_stiffness: 200.0,
            damping_ratio: 0.45,
            ramp_steps: 6000,
            adaptive_ramp: false,
            max_steps: 200_000,
            max_time: Duration::from_secs(60),
            tolerance: SETTLED_RESIDUAL,
            frames: 0,
            implicit: true,
        }
    }
}

/// Why the options cannot be used.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FoldError {
    /// An option is out of range.
    #[error("{name} = {value}: expected {expected}")]
    Option {
        /// The option.
        name: &'static str,
        /// Its value.
        value: String,
        /// What it must be.
        expected: &'static str,
    },
    /// The pattern has no model.
    #[error(transparent)]
    Model(#[from] ModelError),
}

impl FoldOptions {
    /// Checks every option.
    pub fn validate(&self) -> Result<(), FoldError> {
        let bad = |name, value: f64, expected| FoldError::Option {
            name,
            value: value.to_string(),
            expected,
        };
        if !(0.0..=100.0).contains(&self.percent) {
            return Err(bad("percent", self.percent, "0 to 100"));
        }
        for (name, v) in [
            ("axial_stiffness", self.axial_stiffness),
            ("crease_stiffness", self.crease_stiffness),
            ("facet_stiffness", self.facet_stiffness),
            ("tolerance", self.tolerance),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Err(bad(name, v, "a finite number above 0"));
            }
        }
        if !(self.damping_ratio.is_finite() && (0.0..=1.0).contains(&self.damping_ratio)) {
            return Err(bad("damping_ratio", self.damping_ratio, "0 to 1"));
        }
        if self.max_steps == 0 {
            return Err(bad("max_steps", 0.0, "at least 1 step"));
        }
        if self.frames > MAX_FRAMES {
            return Err(bad("frames", self.frames as f64, "at most 200"));
        }
        Ok(())
    }
}

/// Why the simulation stopped.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Stop {
    /// The residual force fell below the tolerance.
    Settled,
    /// [`FoldOptions::max_steps`] ran out.
    StepCap,
    /// [`FoldOptions::max_time`] ran out.
    TimeCap,
    /// A position stopped being finite or left ±[`crate::limits::MAX_COORDINATE`] (the last
    /// state within them is kept).
    Diverged,
}

/// What the simulation reached.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FoldReport {
    /// Steps taken.
    pub steps: usize,
    /// Why it stopped.
    pub stop: Stop,
    /// Residual force over `EA` at the end.
    pub residual: f64,
    /// The percentage folded to.
    pub percent: f64,
    /// Largest |bar strain| of each face's triangles.
    pub face_strain: Vec<f64>,
    /// The largest |bar strain| and the face where it is (`None` for a sheet without bars).
    pub max_strain: f64,
    /// The face with the largest strain.
    pub max_strain_face: Option<FaceId>,
    /// Where that face is in the flat pattern (its corners' mean).
    pub max_strain_at: Option<DVec2>,
    /// Reached fold angle of every pattern edge with a hinge, degrees (FOLD sign).
    pub fold_angles: Vec<Option<f64>>,
    /// Target of every crease at this percentage, degrees.
    pub targets: Vec<Option<f64>>,
    /// Largest |reached − target| over the creases, degrees, the difference taken as a turn
    /// (wrapped to [0, 180]: a hinge 10° past flat on the other side is 10° off, not 350°).
    pub max_angle_error_deg: f64,
    /// The crease with that error.
    pub max_angle_error_edge: Option<EdgeId>,
    /// Creases whose reached angle has the opposite sign of their target (by more than
    /// [`SIGN_TOLERANCE_DEG`]).
    pub wrong_sign: Vec<EdgeId>,
    /// Creases folded past flat (the solver's angle beyond ±180° by more than
    /// [`PAST_FLAT_TOLERANCE_DEG`]): their two faces pass through each other along the crease.
    /// Their [`Self::fold_angles`] are clamped to ±180°.
    pub past_flat: Vec<EdgeId>,
    /// Pairs of faces whose triangles pass through each other (at most
    /// [`MAX_CROSSINGS_LISTED`] triangle pairs examined).
    pub crossing_faces: Vec<(FaceId, FaceId)>,
    /// Wall time, seconds.
    pub seconds: f64,
    /// Triangles of the model.
    pub triangles: usize,
    /// Runs given up for creases settled against their assignment, each followed by a run
    /// with a slower ramp (see [`fold_with`]); [`Self::steps`] counts their steps too.
    pub slower_ramps: Vec<SlowerRamp>,
    /// The static solve, when [`FoldOptions::implicit`] asked for it ([`Self::steps`]
    /// counts its explicit start, and the explicit run after it when it was not used).
    pub static_solve: Option<StaticSolve>,
}

/// Which method produced a report's result, and its work.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Produced {
    /// The static solve ([`newton`]).
    StaticSolve {
        /// Linear solves made.
        linear_solves: usize,
    },
    /// The explicit dynamics (after a static solve that was not used, if any).
    Explicit {
        /// Steps taken in all.
        steps: usize,
    },
}

impl std::fmt::Display for Produced {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Produced::StaticSolve { linear_solves } => {
                write!(f, "static solve, {linear_solves} linear solves")
            }
            Produced::Explicit { steps } => write!(f, "explicit run, {steps} steps"),
        }
    }
}

impl FoldReport {
    /// Which method produced the result ([`Self::static_solve`] says whether it was used).
    pub fn produced(&self) -> Produced {
        match self.static_solve {
            Some(s) if s.used => Produced::StaticSolve {
                linear_solves: s.linear_solves,
            },
            _ => Produced::Explicit { steps: self.steps },
        }
    }
}

/// How the static solve ([`newton`]) went.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct StaticSolve {
    /// Linear solves made.
    pub linear_solves: usize,
    /// Sparse factorizations made.
    pub factorizations: usize,
    /// Whether its result is the report's: it settled within the tolerance, or the time cap
    /// stopped it ([`Stop::TimeCap`]), with every crease on its assignment's side; otherwise
    /// the explicit dynamics ran from flat after it.
    pub used: bool,
}

/// A reached angle this close to 0 has no sign, degrees.
pub const SIGN_TOLERANCE_DEG: f64 = 0.5;

/// How far past ±180° a hinge may fold before its faces count as passing through each other,
/// degrees (the solver's settling noise on a folded-flat crease stays far below).
pub const PAST_FLAT_TOLERANCE_DEG: f64 = 0.05;

/// The turn between two fold angles, degrees, in [0, 180].
pub fn angle_difference_deg(a: f64, b: f64) -> f64 {
    ((a - b + 180.0).rem_euclid(360.0) - 180.0).abs()
}

/// The result of a simulation.
#[derive(Clone, Debug, PartialEq)]
pub struct Fold {
    /// The model that was folded.
    pub model: BarHingeModel,
    /// The folded form: model vertices at their 3D positions, the pattern's faces and edges
    /// on them (edges with the reached fold angles).
    pub folded: FoldedState,
    /// States recorded on the way (see [`FoldOptions::frames`]), from the least folded; the
    /// last is the end ([`Self::folded`]'s positions, at [`FoldReport::percent`]).
    pub frames: Vec<Frame>,
    /// What was reached.
    pub report: FoldReport,
}

/// A state of the fold on its way to the end.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    /// The target at this state, percent of every crease's fold angle.
    pub percent: f64,
    /// Solved to equilibrium at [`Self::percent`]: the static solve's load steps, and an end
    /// that settled; false for the explicit run's frames, taken while its target rises, and
    /// for an end a cap stopped.
    pub settled: bool,
    /// Every model vertex, in the pattern's unit.
    pub positions: Vec<DVec3>,
}

impl Fold {
    /// The folded state with other positions (e.g. a recorded frame, or the flat sheet
    /// [`BarHingeModel::rest`]).
    pub fn state_at(&self, positions: &[DVec3]) -> FoldedState {
        FoldedState {
            positions: positions.to_vec(),
            ..self.folded.clone()
        }
    }
}

/// Folds a validated pattern with faces (see the module docs).
pub fn fold(cp: &CreasePattern, opts: &FoldOptions) -> Result<Fold, FoldError> {
    fold_with(cp, opts, |_, _| {})
}

/// [`fold`], calling `observe` with the model and the positions after every step.
///
/// **Slower ramps.** A sheet that is not rigid-foldable from flat (a tessellation of a curved
/// surface) can pick the other branch where its faces bend through, and settle with creases
/// folded against their assignment when the target rises too fast for it. When a settled run
/// ends with such creases, the fold starts again from flat with a ramp
/// [`SLOWER_RAMP_FACTOR`] times longer, at most [`SLOWER_RAMPS`] times, within the step and
/// time caps ([`FoldReport::slower_ramps`] lists the runs given up). A continuation that
/// shortens its load step on failure; a pattern whose assignment cannot be reached keeps its
/// wrong signs after the last run, and the report names them.
pub fn fold_with(
    cp: &CreasePattern,
    opts: &FoldOptions,
    mut observe: impl FnMut(&BarHingeModel, &[DVec3]),
) -> Result<Fold, FoldError> {
    fold_observed(cp, opts, &mut observe, &mut |_| {})
}

/// [`fold`], handing every frame to `on_frame` as soon as it is recorded (see
/// [`FoldOptions::frames`]; the end is not handed, it is the result's), so that a viewer can
/// show the fold while it runs. When the static solve is not used, the explicit run's frames
/// follow its load steps' and start again from flat; the result's [`Fold::frames`] are those
/// of the run that produced it.
pub fn fold_streamed(
    cp: &CreasePattern,
    opts: &FoldOptions,
    mut on_frame: impl FnMut(&Frame),
) -> Result<Fold, FoldError> {
    fold_observed(cp, opts, &mut |_, _| {}, &mut on_frame)
}

/// [`fold_with`] and [`fold_streamed`] in one.
fn fold_observed(
    cp: &CreasePattern,
    opts: &FoldOptions,
    observe: &mut dyn FnMut(&BarHingeModel, &[DVec3]),
    on_frame: &mut dyn FnMut(&Frame),
) -> Result<Fold, FoldError> {
    opts.validate()?;
    let start = Stopwatch::start();
    let model = BarHingeModel::build(cp)?;
    let fraction = opts.percent / 100.0;
    let mut ramp = opts.ramp_steps.min(opts.max_steps);
    let mut slower_ramps = Vec::new();
    let mut total_steps = 0;
    // The static solve first when asked; the explicit dynamics when it is not asked, or
    // when it does not settle or settles with creases against their assignment.
    let mut static_solve = None;
    let mut load_frames = Vec::new();
    let implicit = if opts.implicit {
        let mut solver = Solver::new(&model, opts);
        let late = || start.elapsed() > opts.max_time;
        let mut at_load = |reached: f64, x: &[DVec3]| {
            observe(&model, x);
            if opts.frames > 0 {
                let frame = Frame {
                    percent: 100.0 * reached,
                    settled: true,
                    positions: x.to_vec(),
                };
                on_frame(&frame);
                load_frames.push(frame);
            }
        };
        let settled = newton::settle(
            &mut solver,
            fraction,
            opts.frames,
            opts.tolerance,
            &late,
            &mut at_load,
        );
        let wrong = wrong_signs(&model, &solver.angles(), fraction);
        let converged = settled.is_some_and(|s| s.converged);
        // Stopped by the time cap on the assignment's side: its state stands, as the
        // explicit run's would at the cap (that run would start from flat with no time left).
        let out_of_time = settled.is_some() && !converged && late();
        let used = (converged || out_of_time) && wrong == 0 && solver.finite();
        static_solve = Some(StaticSolve {
            linear_solves: settled.map_or(0, |s| s.iterations),
            factorizations: settled.map_or(0, |s| s.factorizations),
            used,
        });
        total_steps = newton::START_STEPS;
        let stop = if converged {
            Stop::Settled
        } else {
            Stop::TimeCap
        };
        used.then_some((solver, stop))
    } else {
        None
    };
    let (mut solver, stop, frames) = if let Some((solver, stop)) = implicit {
        observe(&model, &solver.positions);
        (solver, stop, load_frames)
    } else {
        loop {
            let budget = Budget {
                steps: opts.max_steps - total_steps,
                start: &start,
            };
            let (solver, steps, stop, frames) = run(&model, opts, ramp, &budget, observe, on_frame);
            total_steps += steps;
            let wrong = wrong_signs(&model, &solver.angles(), fraction);
            let room = opts.max_steps - total_steps > ramp * SLOWER_RAMP_FACTOR
                && start.elapsed() < opts.max_time;
            let retry = wrong > 0 && stop == Stop::Settled && ramp > 0 && room;
            if !retry || slower_ramps.len() == SLOWER_RAMPS {
                break (solver, stop, frames);
            }
            slower_ramps.push(SlowerRamp {
                ramp_steps: ramp,
                steps,
                wrong_sign: wrong,
            });
            ramp *= SLOWER_RAMP_FACTOR;
        }
    };
    let mut frames = frames;
    let residual = solver.residual();
    let angles = solver.angles();
    let positions = std::mem::take(&mut solver.positions);
    let mut report = report(
        cp,
        &model,
        &positions,
        &angles,
        Run {
            steps: total_steps,
            stop,
            residual,
            percent: opts.percent,
            seconds: start.elapsed().as_secs_f64(),
        },
    );
    report.slower_ramps = slower_ramps;
    report.static_solve = static_solve;
    frames.push(Frame {
        percent: opts.percent,
        settled: stop == Stop::Settled,
        positions: positions.clone(),
    });
    let mut edges = model.edges.clone();
    for (e, a) in report.fold_angles.iter().enumerate() {
        if let Some(a) = a {
            edges[e].fold_angle = Some(*a);
        }
    }
    let folded = FoldedState {
        positions,
        edges,
        faces: Some(model.faces.clone()),
        face_orders: Vec::new(),
    };
    Ok(Fold {
        model,
        folded,
        frames,
        report,
    })
}

/// Times a run given up for creases folded against their assignment is retried with a slower
/// ramp (see [`fold_with`]).
pub const SLOWER_RAMPS: usize = 2;

/// How many times longer each slower ramp is.
pub const SLOWER_RAMP_FACTOR: usize = 3;

/// A run given up because creases settled against their assignment.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct SlowerRamp {
    /// Its ramp, steps.
    pub ramp_steps: usize,
    /// Steps it took.
    pub steps: usize,
    /// Creases it left folded against their assignment.
    pub wrong_sign: usize,
}

/// What is left of the caps for one run.
struct Budget<'a> {
    steps: usize,
    start: &'a Stopwatch,
}

/// One run from flat: the target rises over `ramp` steps, then holds until the residual
/// settles or the budget ends. Returns the solver, its steps, why it stopped and the frames.
fn run<'m>(
    model: &'m BarHingeModel,
    opts: &FoldOptions,
    ramp: usize,
    budget: &Budget<'_>,
    observe: &mut dyn FnMut(&BarHingeModel, &[DVec3]),
    on_frame: &mut dyn FnMut(&Frame),
) -> (Solver<'m>, usize, Stop, Vec<Frame>) {
    let fraction = opts.percent / 100.0;
    let mut solver = Solver::new(model, opts);
    let mut frames = Vec::new();
    // Frame k (from 1) is taken when the target reaches k·every/ramp of the fold, as the
    // linear ramp reached it at step k·every; the adaptive ramp lands on those fractions.
    let frame_every = ramp
        .checked_div(opts.frames)
        .map_or(usize::MAX, |every| every.max(1));
    let frame_at = |k: usize| (k.saturating_mul(frame_every)) as f64 / ramp.max(1) as f64;
    let (slowest, fastest) = if ramp == 0 {
        (1.0, 1.0)
    } else {
        (1.0 / ramp as f64, RAMP_SPEEDUP / ramp as f64)
    };
    let mut rate = slowest;
    let mut progress: f64 = 0.0;
    let mut last_good = solver.positions.clone();
    let mut steps = 0;
    let stop = loop {
        if steps >= budget.steps {
            break Stop::StepCap;
        }
        let ramping = progress < 1.0;
        if ramping {
            let mut next = if opts.adaptive_ramp {
                (progress + rate).min(1.0)
            } else {
                // The linear ramp, exactly as a step count.
                ((steps + 1) as f64 / ramp.max(1) as f64).min(1.0)
            };
            if ramp > 0 && frames.len() < opts.frames {
                next = next.min(frame_at(frames.len() + 1));
            }
            progress = next;
        }
        solver.set_fraction(fraction * progress);
        solver.step();
        steps += 1;
        observe(model, &solver.positions);
        if ramping {
            if ramp > 0 && frames.len() < opts.frames && progress >= frame_at(frames.len() + 1) {
                let frame = Frame {
                    percent: opts.percent * progress,
                    settled: false,
                    positions: solver.positions.clone(),
                };
                on_frame(&frame);
                frames.push(frame);
            }
            // Faster while the sheet keeps up with the target, slower when it lags.
            rate = if solver.step_force() < RAMP_FORCE {
                rate * RAMP_GROW
            } else {
                rate * RAMP_SHRINK
            }
            .clamp(slowest, fastest);
        }
        if steps % CHECK_EVERY == 0 {
            if !solver.finite() {
                break Stop::Diverged;
            }
            last_good.clone_from(&solver.positions);
            if progress >= 1.0 && solver.residual() < opts.tolerance {
                break Stop::Settled;
            }
            if budget.start.elapsed() > opts.max_time {
                break Stop::TimeCap;
            }
        }
    };
    if !solver.finite() {
        solver.positions = last_good;
    }
    (solver, steps, stop, frames)
}

/// Crease hinges whose angle has the opposite sign of their target at `fraction` (by more
/// than [`SIGN_TOLERANCE_DEG`]).
fn wrong_signs(model: &BarHingeModel, angles: &[f64], fraction: f64) -> usize {
    let tolerance = SIGN_TOLERANCE_DEG.to_radians();
    (model.hinges.iter().zip(angles))
        .filter(|(h, a)| match h.kind {
            HingeKind::Crease(full) => full * fraction * **a < 0.0 && a.abs() > tolerance,
            _ => false,
        })
        .count()
}

/// Adaptive ramp: the largest force on a vertex in a step ([`Solver::step_force`], over
/// `EA`) below which the target advances faster.
pub const RAMP_FORCE: f64 = 4e-4;

/// Adaptive ramp: how many times faster than the linear ramp of
/// [`FoldOptions::ramp_steps`] the target may rise at most (it never rises slower).
pub const RAMP_SPEEDUP: f64 = 20.0;

/// Adaptive ramp: factor on the rate after a step within [`RAMP_FORCE`].
pub const RAMP_GROW: f64 = 1.01;

/// Adaptive ramp: factor on the rate after a step beyond [`RAMP_FORCE`].
pub const RAMP_SHRINK: f64 = 0.7;

/// Steps between checks of divergence, residual and time.
const CHECK_EVERY: usize = 32;

/// How the run went, for the report.
struct Run {
    steps: usize,
    stop: Stop,
    residual: f64,
    percent: f64,
    seconds: f64,
}

/// The report of a folded model (see [`FoldReport`]).
fn report(
    cp: &CreasePattern,
    model: &BarHingeModel,
    x: &[DVec3],
    angles: &[f64],
    run: Run,
) -> FoldReport {
    let face_count = model.faces.len();
    let mut face_strain = vec![0.0f64; face_count];
    let strain: std::collections::HashMap<(u32, u32), f64> = model
        .bars
        .iter()
        .map(|b| {
            let [p, q] = b.ends;
            let len = x[p as usize].distance(x[q as usize]);
            ((p, q), ((len - b.rest) / b.rest).abs())
        })
        .collect();
    for (t, tri) in model.triangles.iter().enumerate() {
        let f = model.triangle_face[t].index();
        for s in 0..3 {
            let (a, b) = (tri[s], tri[(s + 1) % 3]);
            let e = strain[&(a.min(b), a.max(b))];
            face_strain[f] = face_strain[f].max(e);
        }
    }
    let worst = (0..face_count).max_by(|&a, &b| face_strain[a].total_cmp(&face_strain[b]));
    let max_strain = worst.map_or(0.0, |f| face_strain[f]);
    let max_strain_at = worst.map(|f| {
        let outer = &cp.faces.as_deref().unwrap_or_default()[f].outer;
        outer.iter().map(|v| cp.vertices[v.index()]).sum::<DVec2>() / outer.len().max(1) as f64
    });
    let fraction = run.percent / 100.0;
    // The solver's angles are unwrapped: beyond ±180° a hinge's wings have passed through
    // each other. The reached angle is kept within FOLD's [−180, 180] (the nearest folded-flat
    // state) and such a hinge is reported apart.
    let unwrapped: Vec<Option<f64>> = model
        .edge_hinge
        .iter()
        .map(|h| h.map(|h| angles[h as usize].to_degrees()))
        .collect();
    let past_flat: Vec<EdgeId> = unwrapped
        .iter()
        .enumerate()
        .filter(|(_, a)| a.is_some_and(|a| a.abs() > 180.0 + PAST_FLAT_TOLERANCE_DEG))
        .map(|(e, _)| EdgeId::new(e))
        .collect();
    let fold_angles: Vec<Option<f64>> = unwrapped
        .iter()
        .map(|a| a.map(|a| a.clamp(-180.0, 180.0)))
        .collect();
    let targets: Vec<Option<f64>> = cp
        .edges
        .iter()
        .map(|e| crease_target_deg(e).map(|t| t * fraction))
        .collect();
    let mut max_err = 0.0;
    let mut max_edge = None;
    let mut wrong_sign = Vec::new();
    for (e, (reached, target)) in unwrapped.iter().zip(&targets).enumerate() {
        let (Some(r), Some(t)) = (reached, target) else {
            continue;
        };
        let err = angle_difference_deg(*r, *t);
        if err > max_err {
            max_err = err;
            max_edge = Some(EdgeId::new(e));
        }
        if t.abs() > SIGN_TOLERANCE_DEG && r * t.signum() < -SIGN_TOLERANCE_DEG {
            wrong_sign.push(EdgeId::new(e));
        }
    }
    let mean_bar = model.bars.iter().map(|b| b.rest).sum::<f64>() / model.bars.len().max(1) as f64;
    let pairs = intersect::crossing_triangles(
        x,
        &model.triangles,
        CROSSING_TOLERANCE * mean_bar,
        MAX_CROSSINGS_LISTED,
    );
    let mut crossing_faces: Vec<(FaceId, FaceId)> = pairs
        .iter()
        .map(|&(a, b)| {
            let (fa, fb) = (
                model.triangle_face[a as usize],
                model.triangle_face[b as usize],
            );
            (fa.min(fb), fa.max(fb))
        })
        .filter(|(a, b)| a != b)
        .collect();
    crossing_faces.sort_unstable();
    crossing_faces.dedup();
    FoldReport {
        steps: run.steps,
        stop: run.stop,
        residual: run.residual,
        percent: run.percent,
        face_strain,
        max_strain,
        max_strain_face: worst.map(FaceId::new),
        max_strain_at,
        fold_angles,
        targets,
        max_angle_error_deg: max_err,
        max_angle_error_edge: max_edge,
        wrong_sign,
        past_flat,
        crossing_faces,
        seconds: run.seconds,
        triangles: model.triangles.len(),
        slower_ramps: Vec::new(),
        static_solve: None,
    }
}
