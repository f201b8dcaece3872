//! Origami tessellations (Tachi 2014) from a disk-like mesh: the tucks, the solve (trying
//! smaller face shrinks until one works, unless one is asked for), the report, and the
//! unfolded crease pattern with its folded form — what `foldcam tessellate` does before it
//! writes anything.

use std::ops::ControlFlow;
use std::path::Path;

use super::note::BuildNote;
use super::summary::{SummaryLine, text_lines};
use super::{DesignFile, DesignKind, Progress, SourceError};
use crate::design::tessellation::advice::curvature_advice;
use crate::design::tessellation::distance::{MIN_COVERED, SurfaceFit, fit_and_missing};
use crate::design::tessellation::estimate::ladder_estimate;
use crate::design::tessellation::steps::{
    FitOptions, SHRINK_LADDER, Triangulation, TuckShape, Unfolded,
};
use crate::design::tessellation::{
    Iteration, Limits, Remesh, Schedule, StarOptions, TessError, TessMesh, TessellateOptions,
    Tessellation, TuckKind, TuckLayout, Watch,
};
use crate::mesh::PolyMesh;

/// Most places shown of each condition a solve left unmet.
const UNMET_SHOWN: usize = 4;

/// Most Newton iterations a solve may be given.
pub const MAX_ITERATIONS: usize = 100_000;

/// Fold-angle limit when neither the options nor a material give one: Tachi's (2014)
/// stainless-steel example, degrees.
pub const DEFAULT_MAX_FOLD_DEG: f64 = 165.0;

/// Vertex-angle limit of the same example, degrees.
pub const DEFAULT_MIN_VERTEX_DEG: f64 = 30.0;

/// How a mesh becomes a tessellation; each default is `foldcam tessellate`'s.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TessellationOptions {
    /// Tuck structure (Tachi 2014, sections 2.1 and 2.2).
    pub tuck: TuckKind,
    /// Gap layout of the star tucks.
    pub layout: TuckLayout,
    /// Face shrink in (0, 1]; `None` tries [`SHRINK_LADDER`] in turn.
    pub shrink: Option<f64>,
    /// Truncated star and twist fold: initial size of the flat n-gon, fraction in (0, 1).
    pub truncation: f64,
    /// Twisted star and twist fold: initial twist about the vertex normal, degrees.
    pub twist_deg: f64,
    /// Largest fold angle, degrees (180 − δ_fold).
    pub max_fold_angle_deg: f64,
    /// Smallest angle between neighbouring creases, degrees (δ_corner).
    pub min_vertex_angle_deg: f64,
    /// Ground contact: every boundary vertex on the plane through the lowest one.
    pub ground: bool,
    /// Surface fit after solving, with this tangential weight in [0, 1].
    pub fit: Option<f64>,
    /// Newton iteration cap, 1 to [`MAX_ITERATIONS`].
    pub max_iterations: usize,
    /// Whether and when to re-triangulate the surface near-regularly first.
    pub remesh: Remesh,
    /// Faces of the re-triangulation; `None`: as many as the input has.
    pub remesh_faces: Option<usize>,
    /// Seconds the whole schedule may take (then the best attempt is reported, refused with
    /// the reason), [`DEFAULT_TIME_LIMIT_S`] by default; `None`: no limit.
    pub time_limit_s: Option<f64>,
}

/// The default [`TessellationOptions::time_limit_s`]: a run ends, solved or refused with its
/// reason, within a minute.
pub const DEFAULT_TIME_LIMIT_S: f64 = 60.0;

/// The largest [`TessellationOptions::time_limit_s`] accepted: a day.
pub const MAX_TIME_LIMIT_S: f64 = 86_400.0;

impl Default for TessellationOptions {
    fn default() -> Self {
        TessellationOptions {
            tuck: TuckKind::Star,
            layout: TuckLayout::Auto,
            shrink: None,
            truncation: 0.3,
            twist_deg: 15.0,
            max_fold_angle_deg: DEFAULT_MAX_FOLD_DEG,
            min_vertex_angle_deg: DEFAULT_MIN_VERTEX_DEG,
            ground: false,
            fit: None,
            max_iterations: 200,
            remesh: Remesh::Auto,
            remesh_faces: None,
            time_limit_s: Some(DEFAULT_TIME_LIMIT_S),
        }
    }
}

impl TessellationOptions {
    /// The solver's options, with the schedule `foldcam tessellate` solves
    /// ([`Schedule::Ladder`]): the one shrink asked for, else every shrink of
    /// [`SHRINK_LADDER`], on the triangulations [`TessellationOptions::remesh`] asks for.
    ///
    /// # Errors
    /// [`SourceError::Option`] for an iteration cap, a limit angle (0° to 180°) or a fit
    /// weight out of range.
    pub fn to_solver(&self) -> Result<TessellateOptions, SourceError> {
        if self.max_iterations == 0 || self.max_iterations > MAX_ITERATIONS {
            return Err(SourceError::Option(format!(
                "--max-iterations must be between 1 and {MAX_ITERATIONS}"
            )));
        }
        // Too many faces is refused here, before anything is built; too few leaves the
        // re-triangulation out of the schedule (it cannot be built), as it always did.
        let limit = crate::limits::REMESH_FACES;
        if let Some(faces) = self.remesh_faces.filter(|&f| f as u64 > limit.max) {
            return Err(SourceError::Option(format!(
                "{} {faces}: expected {}",
                limit.name(),
                limit.expected()
            )));
        }
        for (option, v) in [
            ("--max-fold-angle", self.max_fold_angle_deg),
            ("--min-vertex-angle", self.min_vertex_angle_deg),
        ] {
            if !(v.is_finite() && (0.0..=180.0).contains(&v)) {
                return Err(SourceError::Option(format!(
                    "{option} {v}: must be an angle between 0 and 180 degrees"
                )));
            }
        }
        if let Some(t) = self
            .time_limit_s
            .filter(|t| !(t.is_finite() && *t > 0.0 && *t <= MAX_TIME_LIMIT_S))
        {
            return Err(SourceError::Option(format!(
                "--time-limit {t}: must be more than 0 and at most {MAX_TIME_LIMIT_S} seconds"
            )));
        }
        let limits = Limits::from_degrees(self.max_fold_angle_deg, self.min_vertex_angle_deg);
        let mut opts = TessellateOptions::with_limits(limits);
        opts.time_limit = self.time_limit_s.map(std::time::Duration::from_secs_f64);
        opts.star = StarOptions {
            shrink: self.shrink.unwrap_or(SHRINK_LADDER[0]),
            layout: self.layout,
            tuck: TuckShape {
                kind: self.tuck,
                truncation: self.truncation,
                twist: self.twist_deg.to_radians(),
            },
            max_star_points: None,
        };
        opts.solve.max_iterations = self.max_iterations;
        opts.ground = self.ground;
        opts.schedule = Schedule::Ladder {
            shrinks: self.shrink.map_or(SHRINK_LADDER.to_vec(), |s| vec![s]),
            remesh: self.remesh,
            remesh_faces: self.remesh_faces,
        };
        if let Some(weight) = self.fit {
            if !(0.0..=1.0).contains(&weight) {
                return Err(SourceError::Option(format!(
                    "--fit must be a weight between 0 and 1, got {weight}"
                )));
            }
            opts.fit = Some(FitOptions {
                weight,
                ..FitOptions::default()
            });
        }
        Ok(opts)
    }
}

/// The line `foldcam tessellate` prints for one solver iteration.
pub fn iteration_line(it: &Iteration) -> String {
    format!(
        "  iteration {:3}: developability {:.2e} rad, max fold {:.2} deg, min angle {:.2} deg, \
         active limits {}, corner penalties {}, step {}",
        it.index,
        it.residuals.developability,
        it.residuals.max_fold.to_degrees(),
        it.residuals.min_vertex_angle.to_degrees(),
        it.active[1] + it.active[2] + it.active[3],
        it.active[6],
        it.step
    )
}

/// A tessellation that converged, unfolded without overlaps and does not pass through itself.
#[derive(Clone, Debug)]
pub struct TessellationDesign {
    /// The crease pattern (mm) and the folded form.
    pub unfolded: Unfolded,
    /// What `foldcam tessellate` prints about the solve and the unfolding.
    pub summary: Vec<SummaryLine>,
    /// How well the folded form stands for the input (`None` for a degenerate surface); a
    /// partial one ([`SurfaceFit::partial`]) fails `foldcam tessellate` unless allowed.
    pub fit: Option<SurfaceFit>,
    /// The input triangles the folded form leaves mostly uncovered (empty when it covers
    /// [`MIN_COVERED`] of the area or more): what pictures mark as missing, mesh units.
    pub missing: Vec<[glam::DVec3; 3]>,
}

impl TessellationDesign {
    /// As one design, with its folded form.
    pub fn into_design(self) -> super::Design {
        super::Design {
            kind: DesignKind::Mesh,
            made: "origami tessellation (Tachi 2014)",
            pattern: self.unfolded.pattern,
            folded: Some(self.unfolded.folded),
            summary: self.summary,
            sheets: 1,
        }
    }
}

/// Tessellates `mesh`, read from `file` (named in messages).
///
/// # Errors
/// Bad options or a mesh the tucks cannot be built on; [`SourceError::NotMade`] with the
/// report when no shrink gave a usable result.
pub fn build(
    file: &DesignFile<'_>,
    mesh: &PolyMesh,
    options: &TessellationOptions,
    progress: &mut dyn Progress,
) -> Result<TessellationDesign, SourceError> {
    tessellate_mesh(file.name, mesh, options, progress)
}

/// [`build`] by name.
///
/// # Errors
/// As [`build`]; [`SourceError::Cancelled`] when `progress` asked to stop.
pub fn tessellate_mesh(
    name: &Path,
    mesh: &PolyMesh,
    options: &TessellationOptions,
    progress: &mut dyn Progress,
) -> Result<TessellationDesign, SourceError> {
    let outcome = tessellate_outcome(name, mesh, options, progress)?;
    outcome.design.map_err(|lines| SourceError::NotMade {
        lines: text_lines(&lines),
    })
}

/// A solve's result, usable or not: the surface it left (to show where it misses the limits,
/// see [`super::tess_limits`]) and either the design or the report of why it is refused.
#[derive(Clone, Debug)]
pub struct TessellationOutcome {
    /// The surface the solve left (of the first attempt when none was usable), in the
    /// mesh's units.
    pub surface: TessMesh,
    /// The limits it was solved for.
    pub limits: Limits,
    /// Its developability tolerance, radians per vertex.
    pub tolerance: f64,
    /// The design, or the lines `foldcam tessellate` prints before exiting with status 1.
    pub design: Result<TessellationDesign, Vec<SummaryLine>>,
}

/// [`ControlFlow::Break`] when `progress` asks to stop: the solver's callbacks then end the
/// work with [`TessError::Cancelled`].
fn go_on(progress: &dyn Progress) -> ControlFlow<()> {
    if progress.cancelled() {
        ControlFlow::Break(())
    } else {
        ControlFlow::Continue(())
    }
}

/// [`SourceError::Cancelled`] when `progress` asks to stop before the solve begins.
fn stop_if_cancelled_early(progress: &dyn Progress) -> Result<(), SourceError> {
    if progress.cancelled() {
        return Err(SourceError::Cancelled);
    }
    Ok(())
}

/// [`tessellate_mesh`], keeping the surface of a refused result.
///
/// # Errors
/// Bad options or a mesh the tucks cannot be built on; [`SourceError::Cancelled`] when
/// `progress` asked to stop (asked after every solver iteration and between solves).
pub fn tessellate_outcome(
    name: &Path,
    mesh: &PolyMesh,
    options: &TessellationOptions,
    progress: &mut dyn Progress,
) -> Result<TessellationOutcome, SourceError> {
    let opts = options.to_solver()?;
    let limits = opts.solve.limits;
    progress.note(BuildNote::Solving {
        file: name.display().to_string(),
        faces: mesh.faces().len(),
        max_fold_deg: limits.max_fold.to_degrees(),
        min_vertex_angle_deg: limits.min_vertex_angle.to_degrees(),
    });
    // Every triangulation the schedule solves on, built once for the notes and the solves.
    let plan = opts.plan(mesh).map_err(|e| SourceError::input(name, e))?;
    let (passes, crowding, shrinks) = (plan.passes(), *plan.crowding(), plan.shrinks());
    // The faces of the first triangulation solved: the one the history's times are per.
    let first_faces = match passes.first().map(|p| p.triangulation) {
        Some(Triangulation::Coarser { faces } | Triangulation::Remeshed { faces }) => faces,
        _ => mesh.faces().len(),
    };
    progress.note(BuildNote::SolveEstimate {
        shrinks: shrinks.len(),
        passes: passes.len(),
        estimate: ladder_estimate(opts.star.tuck.kind, first_faces),
        time_limit: opts.time_limit,
    });
    // What the curvature asks of the tucks (a mesh that is not a disk is refused below).
    let advice = curvature_advice(mesh).ok();
    if let Some(advice) = advice {
        progress.note(BuildNote::Curvature(advice));
    }
    // Up front, when the tucks near the edge are expected to run into each other.
    if crowding.crowded() {
        progress.note(BuildNote::Crowding(crowding));
        if let Triangulation::Coarser { faces } = passes[0].triangulation {
            progress.note(BuildNote::CoarserFirst {
                faces,
                input_faces: mesh.faces().len(),
            });
        }
    }
    let asked = options.shrink.is_some();
    stop_if_cancelled_early(progress)?;
    progress.busy("solving");
    let t = plan.run(&mut Reporter {
        progress: &mut *progress,
        asked,
    });
    progress.idle();
    if matches!(t, Err(TessError::Cancelled)) {
        return Err(SourceError::Cancelled);
    }
    let t = t.map_err(|e| SourceError::input(name, e))?;
    let mut lines = vec![
        SummaryLine::Tessellated {
            file: name.display().to_string(),
            layout: t.initial.layout,
            tuck: opts.star.tuck.kind,
            shrink: t.initial.shrink,
            vertices: t.mesh.positions.len(),
            triangles: t.mesh.triangles.len(),
            interior_vertices: t.mesh.interior_count(),
        },
        SummaryLine::Solve(Box::new(t.summary())),
    ];
    lines.extend(t.infeasible.iter().map(|&v| SummaryLine::CannotMeet(v)));
    // The worst few places of each unmet condition (the list is sorted by condition).
    for group in t.unmet.chunk_by(|a, b| a.condition == b.condition) {
        lines.extend(
            group
                .iter()
                .take(UNMET_SHOWN)
                .map(|&v| SummaryLine::Unmet(v)),
        );
        if group.len() > UNMET_SHOWN {
            lines.push(SummaryLine::MoreUnmet(group.len() - UNMET_SHOWN));
        }
    }
    if let Some(sites) = &t.collisions {
        lines.push(SummaryLine::Collisions(Box::new(sites.clone())));
        lines.push(SummaryLine::Crowding(t.crowding));
        if t.crowded_at_rim() {
            lines.push(SummaryLine::CrowdedAtRim {
                shrink: t.initial.shrink,
            });
        }
    }
    if let Some(fit) = t.fit {
        lines.push(SummaryLine::FitRounds(fit));
    }
    let problem = t.problem();
    let design = match (problem, t.unfolded) {
        (None, Ok(mut unfolded)) => {
            super::title_from(&mut unfolded.pattern, name);
            lines.push(SummaryLine::Unfolded {
                max_length_error: unfolded.max_length_error,
            });
            // One sampling gives the fit and the region a partial form leaves uncovered.
            let (fit, uncovered) = fit_and_missing(mesh, &t.mesh).unzip();
            if let Some(fit) = fit {
                lines.push(SummaryLine::SurfaceFit(fit));
            }
            let missing = match &fit {
                Some(f) if f.covered < MIN_COVERED => uncovered.unwrap_or_default(),
                _ => Vec::new(),
            };
            Ok(TessellationDesign {
                unfolded,
                summary: lines,
                fit,
                missing,
            })
        }
        (problem, unfolded) => {
            let why = problem.or(unfolded.err().map(|e| e.to_string()));
            lines.extend(advice.map(SummaryLine::Curvature));
            lines.push(SummaryLine::NothingWritten {
                reason: why.unwrap_or_default(),
            });
            Err(lines)
        }
    };
    Ok(TessellationOutcome {
        surface: t.mesh,
        limits,
        tolerance: opts.solve.tolerance,
        design,
    })
}

/// What a solve tells `progress`: every iteration, and every refused shrink (in words
/// unless the one shrink was asked for) before the next solve.
struct Reporter<'a> {
    progress: &'a mut dyn Progress,
    /// Whether one shrink was asked for (then a refusal is not followed by another).
    asked: bool,
}

impl Watch for Reporter<'_> {
    fn iteration(&mut self, it: &Iteration) -> ControlFlow<()> {
        self.progress.iteration(it);
        go_on(&*self.progress)
    }

    fn refused(&mut self, s: f64, t: &Tessellation) -> ControlFlow<()> {
        if !self.asked {
            self.progress.note(BuildNote::ShrinkRefused {
                shrink: s,
                problem: t.problem().unwrap_or_default(),
                last: s <= SHRINK_LADDER[SHRINK_LADDER.len() - 1],
            });
        }
        self.progress.next_solve();
        go_on(&*self.progress)
    }
}

/// One solve of a [`SolvePlan`]: the face shrink and the triangles it runs on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlannedSolve {
    /// Face shrink.
    pub shrink: f64,
    /// The input's own triangles or which re-triangulation.
    pub triangulation: Triangulation,
}

/// What a tessellation will try, in order: the [`Plan`](crate::design::tessellation::Plan) of
/// its [`Schedule::Ladder`] (which stops at the first usable result), with each solve's
/// iteration cap and tolerance.
#[derive(Clone, Debug, PartialEq)]
pub struct SolvePlan {
    /// The solves, in the order they are tried.
    pub solves: Vec<PlannedSolve>,
    /// Newton iteration cap of each solve.
    pub max_iterations: usize,
    /// Developability the solve stops at, radians.
    pub tolerance: f64,
}

/// The plan `tessellate_outcome` follows for `mesh` with `options`: the passes of
/// [`TessellateOptions::plan`] (a coarser re-triangulation first when the input is crowded at the
/// rim; the re-triangulation first when the input has a face corner sharper than the
/// vertex-angle limit, as [`Remesh::Auto`] decides; a re-triangulation that cannot be built
/// left out, as the pipeline leaves it out), each with every shrink. Builds the
/// re-triangulations to know which can be built (a few milliseconds per thousand faces).
/// On a mesh the pipeline will refuse (not a disk) the plan is the input's shrinks.
///
/// # Errors
/// As [`TessellationOptions::to_solver`].
pub fn solve_plan(
    mesh: &PolyMesh,
    options: &TessellationOptions,
) -> Result<SolvePlan, SourceError> {
    let opts = options.to_solver()?;
    let passes = opts
        .plan(mesh)
        .map(|plan| plan.passes().iter().map(|p| p.triangulation).collect())
        .unwrap_or_else(|_| vec![Triangulation::Input]);
    let shrinks = &opts.shrinks();
    Ok(SolvePlan {
        solves: passes
            .iter()
            .flat_map(|&triangulation| {
                shrinks.iter().map(move |&shrink| PlannedSolve {
                    shrink,
                    triangulation,
                })
            })
            .collect(),
        max_iterations: opts.solve_options().max_iterations,
        tolerance: opts.solve.tolerance,
    })
}

/// Iterations of the developability residual's recent history a [`SolveTracker`] reads its
/// rate of decrease from.
pub const RATE_WINDOW: usize = 5;

/// Where a running tessellation stands, for a progress display: which solve of the
/// [`SolvePlan`] runs (the next begins when [`SolveTracker::next_solve`] says the running one
/// ended, as [`Progress::next_solve`] is told by the pipeline's `attempt` callback), its
/// residual, and the time it has left.
///
/// The time left in the running solve is its observed seconds per iteration times the
/// iterations left, read off the developability residual `r`: Newton–Raphson steps cut it
/// by a roughly constant factor `q < 1` per iteration while far from the solution (the
/// geometric mean over the last [`RATE_WINDOW`] iterations), so reaching the tolerance `τ`
/// takes `ln(r/τ) / ln(1/q)` more, at most the iteration cap. Until two iterations of the
/// running solve are seen nothing is known, and nothing is said: the up-front estimate of
/// [`ladder_estimate`] is from the solver's measured history on other meshes, printed as such
/// before the work starts, never as the time left. Times are passed in, so nothing
/// here reads a clock. A solve that makes no iteration (refused before solving) is still
/// counted; a re-triangulation that cannot be built is not in the plan (see [`solve_plan`]).
#[derive(Clone, Debug)]
pub struct SolveTracker {
    plan: SolvePlan,
    /// Index into `plan.solves` of the running solve.
    solve: usize,
    /// Seconds since the start when the running solve began.
    started: f64,
    /// Seconds since the start at the last iteration.
    now: f64,
    /// Iteration number of the last iteration (1-based; 0 before the first).
    index: usize,
    /// Developability residuals of the running solve, latest last (at most RATE_WINDOW + 1).
    residuals: Vec<f64>,
}

impl SolveTracker {
    /// A tracker at the start of `plan`.
    pub fn new(plan: SolvePlan) -> SolveTracker {
        SolveTracker {
            plan,
            solve: 0,
            started: 0.0,
            now: 0.0,
            index: 0,
            residuals: Vec::new(),
        }
    }

    /// Hears that the running solve ended, `seconds` after the tessellation started: the
    /// next of the plan begins (the last one stays named when there is none).
    pub fn next_solve(&mut self, seconds: f64) {
        self.solve = (self.solve + 1).min(self.plan.solves.len().saturating_sub(1));
        self.started = seconds;
        self.now = seconds;
        self.index = 0;
        self.residuals.clear();
    }

    /// Hears one solver iteration, `seconds` after the tessellation started.
    pub fn iteration(&mut self, it: &Iteration, seconds: f64) {
        self.index = it.index;
        self.now = seconds;
        self.residuals.push(it.residuals.developability);
        if self.residuals.len() > RATE_WINDOW + 1 {
            self.residuals.remove(0);
        }
    }

    /// The running solve of the plan (0-based) and how many there are at most.
    pub fn solve(&self) -> (usize, usize) {
        (self.solve, self.plan.solves.len())
    }

    /// Seconds the running solve has left, see the type's docs; `None` until two of its
    /// iterations are measured.
    pub fn seconds_left(&self) -> Option<f64> {
        if self.index < 2 || self.residuals.len() < 2 {
            return None;
        }
        let spent = self.now - self.started;
        let cap_left = self.plan.max_iterations.saturating_sub(self.index) as f64;
        let per_iteration = spent / self.index as f64;
        let (first, last) = (self.residuals[0], self.residuals[self.residuals.len() - 1]);
        let steps = (self.residuals.len() - 1) as f64;
        let tolerance = self.plan.tolerance.max(f64::MIN_POSITIVE);
        let left = if last <= tolerance {
            0.0
        } else if first > last && last > 0.0 {
            // ln(1/q) per iteration, from the geometric mean of the recent decrease.
            let rate = (first / last).ln() / steps;
            ((last / tolerance).ln() / rate).min(cap_left)
        } else {
            cap_left
        };
        Some(per_iteration * left)
    }

    /// The whole progress line, as `foldcam tessellate`'s bar shows it: the iteration of the
    /// running solve out of the cap, the time since the start, then [`SolveTracker::status`].
    pub fn line(&self) -> String {
        format!(
            "iteration {}/{} {}: {}",
            self.index,
            self.plan.max_iterations,
            seconds_text(self.now),
            self.status()
        )
    }

    /// The iteration cap of each solve.
    pub fn max_iterations(&self) -> usize {
        self.plan.max_iterations
    }

    /// One line for a progress bar: the solve of the plan, the residual, the time left.
    pub fn status(&self) -> String {
        let (k, n) = self.solve();
        let solve = self.plan.solves.get(k);
        let what = solve.map_or(String::new(), |s| {
            format!("shrink {} on {} ", s.shrink, s.triangulation.describe())
        });
        let residual = self
            .residuals
            .last()
            .map_or(String::new(), |r| format!(", developability {r:.1e} rad"));
        let left = self.seconds_left().map_or_else(
            || "time left measured after two iterations".to_string(),
            |s| format!("about {} left in this solve", seconds_text(s)),
        );
        format!("{what}(solve {} of at most {n}){residual}, {left}", k + 1)
    }
}

/// A duration for a progress line: "12 s", "3 min", "2 h".
pub fn seconds_text(seconds: f64) -> String {
    if seconds < 90.0 {
        format!("{:.0} s", seconds.max(0.0))
    } else if seconds < 5400.0 {
        format!("{:.0} min", seconds / 60.0)
    } else {
        format!("{:.1} h", seconds / 3600.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::design::tessellation::measure::Residuals;
    use crate::design::tessellation::pipeline::remesh_order;
    use crate::design::tessellation::samples::{SampleSurface, sample_surface, spherical_cap};
    use crate::design::tessellation::tessellate;

    /// Two closures as a [`Watch`]: the refused results, then the iterations.
    struct Both<R, I>(R, I);

    impl<R, I> Watch for Both<R, I>
    where
        R: FnMut(f64, &Tessellation) -> ControlFlow<()>,
        I: FnMut(&Iteration) -> ControlFlow<()>,
    {
        fn iteration(&mut self, it: &Iteration) -> ControlFlow<()> {
            (self.1)(it)
        }

        fn refused(&mut self, s: f64, t: &Tessellation) -> ControlFlow<()> {
            (self.0)(s, t)
        }
    }

    fn plan() -> SolvePlan {
        SolvePlan {
            solves: vec![
                PlannedSolve {
                    shrink: 0.8,
                    triangulation: Triangulation::Input,
                },
                PlannedSolve {
                    shrink: 0.7,
                    triangulation: Triangulation::Remeshed { faces: 100 },
                },
            ],
            max_iterations: 200,
            tolerance: 1e-10,
        }
    }

    fn it(index: usize, developability: f64) -> Iteration {
        Iteration {
            index,
            residuals: Residuals {
                developability,
                ..Residuals::default()
            },
            active: [0; 8],
            step: 1.0,
            cg_iterations: 0,
        }
    }

    /// A residual falling tenfold per iteration, one iteration a second: from 1e-2 it takes
    /// 8 more iterations to reach 1e-10, so 8 s (closed form of the geometric decrease).
    #[test]
    fn limit_angles_out_of_range_are_refused_by_name() {
        for (max, min, named) in [
            (200.0, 30.0, "--max-fold-angle 200"),
            (165.0, f64::NAN, "--min-vertex-angle NaN"),
        ] {
            let o = TessellationOptions {
                max_fold_angle_deg: max,
                min_vertex_angle_deg: min,
                ..TessellationOptions::default()
            };
            match o.to_solver() {
                Err(SourceError::Option(m)) => assert!(m.starts_with(named), "{m}"),
                other => panic!("not refused: {other:?}"),
            }
        }
        assert!(TessellationOptions::default().to_solver().is_ok());
    }

    #[test]
    fn time_left_follows_the_residual_decrease_and_the_iteration_rate() {
        let mut t = SolveTracker::new(plan());
        // Before two iterations nothing is measured, and nothing is said.
        t.iteration(&it(1, 1.0), 1.0);
        assert_eq!(t.seconds_left(), None);
        for k in 2..=3 {
            t.iteration(&it(k, 10f64.powi(1 - k as i32)), k as f64);
        }
        let left = t.seconds_left().expect("measured");
        assert!((left - 8.0).abs() < 1e-9, "{left}");
        // A residual that does not fall: the iterations up to the cap.
        let mut flat = SolveTracker::new(plan());
        for k in 1..=4 {
            flat.iteration(&it(k, 0.5), 0.5 * k as f64);
        }
        let left = flat.seconds_left().expect("measured");
        assert!((left - 0.5 * 196.0).abs() < 1e-9, "{left}");
        // Reached: nothing left.
        t.iteration(&it(4, 1e-12), 4.0);
        assert_eq!(t.seconds_left(), Some(0.0));
    }

    /// The next solve of the plan begins when told, timed from its own start.
    #[test]
    fn a_new_solve_is_recognised_and_named() {
        let mut t = SolveTracker::new(plan());
        t.iteration(&it(1, 1.0), 1.0);
        t.iteration(&it(2, 0.1), 2.0);
        assert_eq!(t.solve(), (0, 2));
        assert!(
            t.status()
                .starts_with("shrink 0.8 on the input's triangles (solve 1 of at most 2)")
        );
        assert!(t.line().starts_with("iteration 2/200 2 s: shrink 0.8"));
        t.next_solve(4.0);
        t.iteration(&it(1, 1.0), 5.0);
        assert_eq!(t.solve(), (1, 2));
        assert!(
            t.status()
                .contains("shrink 0.7 on the re-triangulation (solve 2 of at most 2)")
        );
        // One iteration into the second solve: its time is not measured yet (the first
        // solve's rate belongs to another triangulation).
        assert_eq!(t.seconds_left(), None);
        assert!(
            t.status().contains("developability 1.0e0 rad"),
            "{}",
            t.status()
        );
        assert!(
            t.status()
                .ends_with("time left measured after two iterations"),
            "{}",
            t.status()
        );
        t.iteration(&it(2, 0.1), 5.5);
        assert!(
            t.status().ends_with("about 7 s left in this solve"),
            "{}",
            t.status()
        );
        // There is no third solve: the last stays named.
        t.next_solve(6.0);
        assert_eq!(t.solve(), (1, 2));
    }

    /// A solve that makes no iteration still counts. A nearly flat cap whose 12-valent pole,
    /// made a 12-pointed star (the star-point cap off), has 24 crease angles of at most
    /// 15 deg, under the 29.8 deg limit: refused before solving at every shrink on its own
    /// triangles, which come first (their sharpest corner, about 29.9 deg, is above the
    /// limit). Every iteration must carry the label of the solve the pipeline is in, counted
    /// from the pipeline's own `attempt` calls.
    #[test]
    fn solves_without_iterations_are_counted() {
        let cap = spherical_cap(12, 1, 10.0, 100.0);
        let options = TessellationOptions {
            min_vertex_angle_deg: 29.8,
            remesh_faces: Some(48),
            ..TessellationOptions::default()
        };
        let plan = solve_plan(&cap, &options).unwrap();
        let input_solves = SHRINK_LADDER.len();
        assert_eq!(plan.solves[0].triangulation, Triangulation::Input);
        assert_eq!(
            plan.solves[input_solves].triangulation,
            Triangulation::Remeshed { faces: 48 }
        );
        let mut opts = options.to_solver().unwrap();
        opts.star.max_star_points = Some(usize::MAX);
        let tracker = std::cell::RefCell::new(SolveTracker::new(plan.clone()));
        // Per attempt the pipeline reports: its shrink and its iterations.
        let attempts = std::cell::RefCell::new(Vec::new());
        let mut labelled = 0;
        let t = tessellate(
            &cap,
            &opts,
            &mut Both(
                |s, t: &Tessellation| {
                    attempts.borrow_mut().push((s, t.report.iterations));
                    tracker.borrow_mut().next_solve(0.0);
                    ControlFlow::Continue(())
                },
                |it: &Iteration| {
                    let mut tracker = tracker.borrow_mut();
                    tracker.iteration(it, 0.0);
                    assert_eq!(tracker.solve().0, attempts.borrow().len(), "{it:?}");
                    labelled += 1;
                    ControlFlow::Continue(())
                },
            ),
        )
        .unwrap();
        let attempts = attempts.into_inner();
        // The scenario: the input's solves made no iteration, the re-triangulation's did.
        assert!(attempts.len() >= input_solves, "{attempts:?}");
        assert!(attempts[..input_solves].iter().all(|a| a.1 == 0));
        assert!(labelled > 0 && t.remeshed.is_some() && t.problem().is_none());
        // The plan names each refused attempt's shrink, and the usable one's.
        for (k, a) in attempts.iter().enumerate() {
            assert_eq!(plan.solves[k].shrink, a.0, "{attempts:?}");
        }
        let last = plan.solves[attempts.len()];
        assert_eq!(
            (last.shrink, last.triangulation),
            (t.initial.shrink, Triangulation::Remeshed { faces: 48 })
        );
        assert!(tracker.borrow().status().starts_with(&format!(
            "shrink {} on the re-triangulation (solve {} of",
            t.initial.shrink,
            attempts.len() + 1
        )));
    }

    /// A re-triangulation that cannot be built is not in the plan, so every iteration of the
    /// input's solves that follow is labelled with the input's triangles and its shrink. The
    /// 48-face cap's 12-valent pole has face corners sharper than 30 deg (the re-triangulation
    /// is scheduled first), and 23 faces are fewer than a re-triangulation accepts (it
    /// cannot be built). Each iteration's label is checked against the shrink the pipeline
    /// itself reports for that solve when it ends.
    #[test]
    fn a_re_triangulation_that_cannot_be_built_does_not_shift_the_labels() {
        let cap = spherical_cap(12, 2, 30.0, 100.0);
        let options = TessellationOptions {
            remesh_faces: Some(crate::design::tessellation::remesh::MIN_FACES - 1),
            max_iterations: 20,
            ..TessellationOptions::default()
        };
        let opts = options.to_solver().unwrap();
        let order = remesh_order(options.remesh, &cap, &opts.solve.limits);
        assert_eq!(
            order,
            [true, false],
            "the re-triangulation is scheduled first"
        );
        let plan = solve_plan(&cap, &options).unwrap();
        let tracker = std::cell::RefCell::new(SolveTracker::new(plan));
        // The label of every iteration of the running solve; checked when it ends.
        let labels = std::cell::RefCell::new(Vec::new());
        let labelled = std::cell::Cell::new(0);
        let check = |shrink: f64, labels: &mut Vec<String>| {
            let want = format!("shrink {shrink} on the input's triangles (solve ");
            for l in labels.drain(..) {
                assert!(l.starts_with(&want), "{l}");
            }
        };
        let t = tessellate(
            &cap,
            &opts,
            &mut Both(
                |s, _: &Tessellation| {
                    check(s, &mut labels.borrow_mut());
                    tracker.borrow_mut().next_solve(0.0);
                    ControlFlow::Continue(())
                },
                |it: &Iteration| {
                    let mut tracker = tracker.borrow_mut();
                    tracker.iteration(it, 0.0);
                    labels.borrow_mut().push(tracker.status());
                    labelled.set(labelled.get() + 1);
                    ControlFlow::Continue(())
                },
            ),
        )
        .unwrap();
        assert!(t.remeshed.is_none());
        check(t.initial.shrink, &mut labels.borrow_mut());
        assert!(labelled.get() > 0, "no iteration to label");
    }

    #[test]
    fn durations_read_in_seconds_minutes_or_hours() {
        assert_eq!(seconds_text(12.4), "12 s");
        assert_eq!(seconds_text(600.0), "10 min");
        assert_eq!(seconds_text(7200.0), "2.0 h");
    }

    /// The plan follows the schedule: a sharp input is re-triangulated first.
    #[test]
    fn the_plan_is_the_schedule() {
        let cap = spherical_cap(12, 3, 60.0, 100.0);
        let p = solve_plan(&cap, &TessellationOptions::default()).unwrap();
        assert_eq!(p.solves.len(), 2 * SHRINK_LADDER.len());
        // The 12-valent pole's face corners are 30 deg minus the curvature: sharper than 30.
        assert_ne!(p.solves[0].triangulation, Triangulation::Input);
        assert_eq!(
            p.solves[SHRINK_LADDER.len()].triangulation,
            Triangulation::Input
        );
        let flat = sample_surface(SampleSurface::Saddle, 2, 20.0);
        let one = TessellationOptions {
            shrink: Some(0.5),
            remesh: Remesh::Never,
            ..TessellationOptions::default()
        };
        let p = solve_plan(&flat, &one).unwrap();
        assert_eq!(
            p.solves,
            vec![PlannedSolve {
                shrink: 0.5,
                triangulation: Triangulation::Input
            }]
        );
    }
}
