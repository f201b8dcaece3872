//! The whole design in one call, [`tessellate`] (Tachi 2014): mesh → star tucks → solve →
//! unfold → face-intersection check, once or over a [`Schedule`] of face shrinks and
//! re-triangulations ([`Plan`]).
//!
//! A [`Watch`] hears every solver iteration and every refused result of a ladder; its
//! methods return [`ControlFlow`]: [`ControlFlow::Break`] stops the work at once with
//! [`TessError::Cancelled`]. `()` watches nothing.

use std::ops::ControlFlow;
use std::time::Duration;

use super::collision_sites::CollisionSites;
use super::constraints::{BoundaryRuns, Limits, assign_folds, assign_free_folds};
use super::crowding::{CROWDING_LIMIT, RimCrowding, rim_crowding_of};
use super::diagnose::{self, Violation};
use super::fit::{FitOptions, FitReport, Target, fit_surface};
use super::intersect::intersecting_triangles;
use super::passes::{Pass, Triangulation, scheduled_passes};
use super::remesh::{RemeshReport, min_corner_angle};
use super::solver::{Iteration, SolveOptions, SolveReport, solve_until};
use super::star::{InitialPattern, StarOptions, max_star_points, star_tucks_shrunk};
use super::tuck::TuckKind;
use super::unfold::{Unfolded, unfold};
use super::{TessError, TessMesh};
use crate::clock::Deadline;
use crate::mesh::{HalfEdgeMesh, PolyMesh};

/// Everything [`tessellate`] needs besides the mesh.
#[derive(Clone, Debug, PartialEq)]
pub struct TessellateOptions {
    /// Initial pattern (Tachi 2014, §2.1).
    pub star: StarOptions,
    /// Solver settings and fabrication limits (§3.3, §5).
    pub solve: SolveOptions,
    /// Ground contact (§6): put every boundary vertex on the horizontal plane through the
    /// lowest boundary vertex of the initial pattern (overrides `solve.limits.ground_z`).
    pub ground: bool,
    /// Surface fit (§3.4) after a converged solve, towards the initial face corners.
    pub fit: Option<FitOptions>,
    /// Faces of the folded form crossing each other by less than this (mm) only touch.
    pub intersection_tolerance: f64,
    /// What is solved, in order: one solve (the default), one with a shrink per face, or a
    /// face-shrink ladder over re-triangulations.
    pub schedule: Schedule,
    /// How long the whole schedule may take: once it has run out, the solve under way stops
    /// (keeping what it reached) and no further solve starts; the result then says
    /// [`Tessellation::out_of_time`]. `None` (the default): no limit.
    pub time_limit: Option<Duration>,
}

impl Default for TessellateOptions {
    fn default() -> Self {
        TessellateOptions {
            star: StarOptions::default(),
            solve: SolveOptions::default(),
            ground: false,
            fit: None,
            intersection_tolerance: 1e-3,
            schedule: Schedule::Once,
            time_limit: None,
        }
    }
}

impl TessellateOptions {
    /// Default options with the given fabrication limits.
    pub fn with_limits(limits: Limits) -> Self {
        let mut o = TessellateOptions::default();
        o.solve.limits = limits;
        o
    }

    /// The solver settings [`tessellate`] uses: [`TessellateOptions::solve`], for twisted
    /// stars ([`TuckKind::Twisted`]) with the Levenberg–Marquardt fallback
    /// ([`SolveOptions::damped_fallback`]) and [`TWISTED_ITERATIONS`] times the iteration cap.
    pub fn solve_options(&self) -> SolveOptions {
        let mut s = self.solve;
        if self.star.tuck.kind == TuckKind::Twisted {
            s.damped_fallback = true;
            s.max_iterations = s.max_iterations.saturating_mul(TWISTED_ITERATIONS);
        }
        s
    }

    /// The face shrinks each triangulation is solved at, in order: the ladder's, else the one
    /// of [`StarOptions::shrink`] (also for [`Schedule::FaceShrinks`], which overrides it per
    /// face).
    pub fn shrinks(&self) -> Vec<f64> {
        match &self.schedule {
            Schedule::Ladder { shrinks, .. } => shrinks.clone(),
            Schedule::Once | Schedule::FaceShrinks(_) => vec![self.star.shrink],
        }
    }

    /// The [`Plan`] [`tessellate`] follows on `mesh`: the triangulations of the schedule in
    /// the order they are solved ([`Triangulation::Coarser`] first on a
    /// [`Schedule::Ladder`] with [`Remesh::Auto`] and no face count when the input is
    /// [`crowded`](RimCrowding::crowded), then the input's own triangles and the
    /// re-triangulation in the order [`Remesh`] says), each re-triangulation built (a few
    /// milliseconds per thousand faces); a re-triangulation that cannot be built is left
    /// out when another pass remains. [`Plan::run`] then solves it.
    ///
    /// # Errors
    /// When `mesh` is not a disk, or no pass can be built (the first re-triangulation's
    /// error).
    pub fn plan<'a>(&'a self, mesh: &'a PolyMesh) -> Result<Plan<'a>, TessError> {
        let (passes, crowding) = match &self.schedule {
            Schedule::Ladder {
                remesh,
                remesh_faces,
                ..
            } => scheduled_passes(mesh, &self.solve.limits, *remesh, *remesh_faces)?,
            Schedule::Once | Schedule::FaceShrinks(_) => {
                scheduled_passes(mesh, &self.solve.limits, Remesh::Never, None)?
            }
        };
        Ok(Plan {
            mesh,
            opts: self,
            passes,
            crowding,
        })
    }
}

/// How many times the iteration cap a twisted-star solve gets. Twisted stars (Tachi 2014,
/// §2.2) add a vertex and two creases to every star arm, and their solves near the limits
/// creep along many nearly dependent fold-limit and crease-angle rows: measured on the
/// issue's cap (`spherical_cap(12, 6, 60, 100)` re-triangulated to 450 faces, 0.5 mm
/// stainless limits, release build), shrink 0.8 converges after 501 iterations and shrink
/// 0.7 after 422, where star tucks need 162 (`examples/tessellation_modes.rs`).
pub const TWISTED_ITERATIONS: usize = 4;

/// A finished tessellation.
#[derive(Clone, Debug)]
pub struct Tessellation {
    /// The initial pattern before solving (its mesh holds the initial positions).
    pub initial: InitialPattern,
    /// The solved surface.
    pub mesh: TessMesh,
    /// How the solve went.
    pub report: SolveReport,
    /// How the surface fit went, when requested and the solve converged.
    pub fit: Option<FitReport>,
    /// The unfolded pattern and its folded state; `Err` when the flat pattern overlaps.
    pub unfolded: Result<Unfolded, TessError>,
    /// Pairs of triangles of the solved surface (the folded state's faces, same indices)
    /// that pass through each other, see [`intersect`](super::intersect).
    pub intersections: Vec<(usize, usize)>,
    /// The tolerance they were found with, mm.
    pub intersection_tolerance: f64,
    /// Where on the input mesh those pairs lie (`None` when there are none).
    pub collisions: Option<CollisionSites>,
    /// The input mesh's crowding index (Tachi 2014, Fig. 14: tucks running into each other
    /// near the edge), see [`crowding`](super::crowding).
    pub crowding: RimCrowding,
    /// Limits the initial pattern cannot meet whatever the solve does (then the solve is
    /// skipped), see [`diagnose::before_solving`].
    pub infeasible: Vec<Violation>,
    /// The conditions left unmet by a solve that did not converge, per input vertex, see
    /// [`diagnose::after_solving`].
    pub unmet: Vec<Violation>,
    /// When the input was re-triangulated before tessellating ([`Remesh`]), what changed;
    /// the input vertices named in `infeasible` and `unmet` are then the new mesh's.
    pub remeshed: Option<RemeshReport>,
    /// When that re-triangulation has fewer faces than the input because the input's rim
    /// crowding index is over the limit ([`Triangulation::Coarser`]): the input's crowding.
    pub coarsened: Option<RimCrowding>,
    /// [`TessellateOptions::time_limit`] when it ran out before the schedule ended (a solve
    /// cut short, or solves left untried).
    pub out_of_time: Option<Duration>,
}

impl Tessellation {
    /// The solver's summary with the face-intersection count of the folded form (its
    /// `Display` is what `foldcam tessellate` prints).
    pub fn summary(&self) -> SolveSummary {
        SolveSummary {
            report: self.report.clone(),
            intersections: self.intersections.len(),
            first_intersection: self.intersections.first().copied(),
            intersection_tolerance: self.intersection_tolerance,
            remeshed: self.remeshed,
            coarsened: self.coarsened,
        }
    }
}

/// How a tessellation's solve went, as [`Tessellation::summary`] reports it: the solver's
/// residuals and limits, the re-triangulation if any, and the crossing face pairs.
#[derive(Clone, Debug, PartialEq)]
pub struct SolveSummary {
    /// The solver's report.
    pub report: SolveReport,
    /// Pairs of folded-form triangles that pass through each other.
    pub intersections: usize,
    /// The first such pair.
    pub first_intersection: Option<(usize, usize)>,
    /// The tolerance they were found with, mm.
    pub intersection_tolerance: f64,
    /// What the re-triangulation changed, if the input was re-triangulated.
    pub remeshed: Option<RemeshReport>,
    /// The input's crowding, when a coarser re-triangulation was solved because of it.
    pub coarsened: Option<RimCrowding>,
}

impl std::fmt::Display for SolveSummary {
    /// Several lines: the re-triangulation, the solver's summary, the crossings.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if let (Some(c), Some(r)) = (&self.coarsened, &self.remeshed) {
            writeln!(f, "{}", Tessellation::coarsened_line(c, r))?;
        }
        if let Some(r) = &self.remeshed {
            writeln!(f, "{}", r.describe())?;
        }
        let found = match self.first_intersection {
            None => "none".to_string(),
            Some((a, b)) => format!(
                "{} pairs (first: triangles {a} and {b})",
                self.intersections
            ),
        };
        write!(
            f,
            "{}\n  face intersections (folded form, tolerance {:.0e} mm): {found}",
            self.report.summary(),
            self.intersection_tolerance
        )
    }
}

impl Tessellation {
    /// Why the face count changed, for the user: the input's crowding index over the limit.
    fn coarsened_line(c: &RimCrowding, r: &RemeshReport) -> String {
        format!(
            "face count changed from {} to {}: the input's rim crowding index {:.1} is over \
             the {CROWDING_LIMIT:.1} above which the tucks near the edge of the measured caps \
             collided (Tachi 2014, Fig. 14), so a coarser re-triangulation was solved first \
             (about {} faces, as --remesh {} asks)",
            r.faces[0],
            r.faces[1],
            c.index(),
            c.faces_for_limit(),
            c.faces_for_limit()
        )
    }

    /// Whether this is the crowding [`crowding`](super::crowding) predicts: the solve
    /// converged within every limit, the input mesh is crowded, and most intersecting pairs
    /// lie in the outer third of the surface. On the caps measured a smaller face shrink did
    /// not remove such intersections, so the schedules stop at the first such result.
    pub fn crowded_at_rim(&self) -> bool {
        self.report.converged
            && self.crowding.crowded()
            && self
                .collisions
                .as_ref()
                .is_some_and(|c| 2 * c.outer_third() > c.pairs)
    }

    /// Why the result cannot be used (not converged, a self-intersecting folded form, an
    /// overlapping pattern), or `None` when it can.
    pub fn problem(&self) -> Option<String> {
        if let Some(v) = self.infeasible.first() {
            return Some(format!(
                "the limits cannot be met at {} input vertices, not solved (first: {})",
                self.infeasible.len(),
                v.describe()
            ));
        }
        if let Some(limit) = self.out_of_time {
            let problem = self
                .problem_within_time()
                .unwrap_or_else(|| "no usable result".into());
            return Some(format!(
                "{problem}; the time limit of {limit:?} ran out before every face shrink and \
                 triangulation was tried"
            ));
        }
        self.problem_within_time()
    }

    /// [`Tessellation::problem`] without the time limit.
    fn problem_within_time(&self) -> Option<String> {
        if !self.report.converged {
            return Some("the solver did not reach every condition".into());
        }
        if let Some((a, b)) = self.intersections.first() {
            let sites = self.collisions.as_ref().map_or(String::new(), |c| {
                format!(
                    ", {} of them within {} input edges of the sheet's edge, the deepest \
                     {:.2} mm",
                    c.outer_third(),
                    c.rings / 3,
                    c.deepest
                )
            });
            return Some(format!(
                "the folded form intersects itself ({} face pairs, first: faces {a} and {b}{sites})",
                self.intersections.len()
            ));
        }
        self.unfolded.as_ref().err().map(|e| e.to_string())
    }
}

/// What a caller hears while [`tessellate`] works, and how it stops the work: each method
/// returns [`ControlFlow::Break`] to stop at once with [`TessError::Cancelled`]. Every method
/// has a default that lets the work go on, so `()` watches nothing and a closure over
/// [`Iteration`] hears only the solver.
pub trait Watch {
    /// After every iteration of a solve (Tachi 2014, §3.3), with the residuals then.
    fn iteration(&mut self, _it: &Iteration) -> ControlFlow<()> {
        ControlFlow::Continue(())
    }

    /// After every result of a [`Schedule::Ladder`] that has a [`Tessellation::problem`]
    /// (its solve has ended), with the face shrink it was solved at, before the next solve.
    fn refused(&mut self, _shrink: f64, _t: &Tessellation) -> ControlFlow<()> {
        ControlFlow::Continue(())
    }
}

/// Watches nothing: the work always goes on.
impl Watch for () {}

/// A closure hears every solver iteration and nothing else.
impl<F: FnMut(&Iteration) -> ControlFlow<()>> Watch for F {
    fn iteration(&mut self, it: &Iteration) -> ControlFlow<()> {
        self(it)
    }
}

/// The face shrinks [`Schedule::ladder`] tries, largest first.
pub const SHRINK_LADDER: [f64; 6] = [0.8, 0.7, 0.6, 0.5, 0.45, 0.4];

/// Each face shrink of `shrinks` in turn (overriding `opts.star.shrink`) on `mesh`
/// until a result has no [`Tessellation::problem`]; `watch` hears every result that has one
/// (its solve has ended) before the next shrink is tried. A shrink whose solve converges with
/// [`BoundaryRuns::Dominant`] rows but intersects itself is solved once more with
/// [`BoundaryRuns::EveryStart`] when a boundary row entered the first solve
/// ([`SolveReport::boundary_rows`]; else the second would repeat it to the bit). That is the
/// stiffer outline, as one attempt: `watch` hears the
/// second result only, and its iterations count on from the
/// first's). Returns the first usable result, else the first one (the result of the shrink
/// asked for first); stops early at a result
/// [`crowded at the rim`](Tessellation::crowded_at_rim) and returns that one.
/// This stands in for the paper's user (Tachi 2014), who avoids global face collisions
/// (type 3, §3.2) by adjusting the design: a smaller shrink opens the tucks wider.
fn tessellate_shrinking(
    mesh: &PolyMesh,
    opts: &TessellateOptions,
    shrinks: &[f64],
    deadline: &Deadline,
    watch: &mut impl Watch,
) -> Result<Tessellation, TessError> {
    let mut first: Option<Tessellation> = None;
    for &shrink in shrinks {
        if let Some(t) = first.as_mut().filter(|_| deadline.passed()) {
            t.out_of_time = deadline.limit();
            break;
        }
        let mut o = opts.clone();
        o.star.shrink = shrink;
        let mut t = tessellate_shrunk(mesh, &o, None, deadline, |it: &Iteration| {
            watch.iteration(it)
        })?;
        if t.report.converged
            && !t.intersections.is_empty()
            && o.solve.limits.boundary_runs == BoundaryRuns::Dominant
            && t.report.boundary_rows
            && !deadline.passed()
        {
            // The same shrink again with the stiffer outline (see `BoundaryRuns`); its
            // iterations continue the count, so progress displays see one solve per shrink.
            // Not when no boundary row ever entered: that solve would be the same one
            // (`SolveReport::boundary_rows`).
            o.solve.limits.boundary_runs = BoundaryRuns::EveryStart;
            let before = t.report.iterations;
            t = tessellate_shrunk(mesh, &o, None, deadline, |it: &Iteration| {
                watch.iteration(&Iteration {
                    index: before + it.index,
                    ..*it
                })
            })?;
        }
        if t.problem().is_none() || t.crowded_at_rim() {
            return Ok(t);
        }
        if watch.refused(shrink, &t).is_break() {
            return Err(TessError::Cancelled);
        }
        let cut_short = t.out_of_time.is_some();
        let kept = first.get_or_insert(t);
        if cut_short {
            kept.out_of_time = deadline.limit();
            break;
        }
    }
    first.ok_or_else(|| TessError::BadParameter("no face shrink to try".into()))
}

/// Whether a [`Schedule::Ladder`] re-triangulates the input ([`remesh`](fn@super::remesh::remesh)).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Remesh {
    /// Never: the input's own triangles only.
    Never,
    /// Both, the more promising first (the default): the re-triangulation first when the
    /// input has a face corner sharper than the vertex-angle limit (every face corner is an
    /// angle between two creases of the initial pattern, Tachi 2014 §2.1, so such a face
    /// must be distorted before the limit can hold), else the input's own triangles first.
    /// Before both, when no face count is asked for and the input is crowded at the rim
    /// ([`crowding`](super::crowding)), a coarser re-triangulation (see
    /// [`passes`](super::passes)).
    #[default]
    Auto,
    /// The re-triangulation only.
    Only,
}

/// What [`tessellate`] solves, in order: [`TessellateOptions::schedule`].
#[derive(Clone, Debug, PartialEq, Default)]
pub enum Schedule {
    /// One solve at [`StarOptions::shrink`] on the input's own triangles (the default).
    #[default]
    Once,
    /// One solve with a face shrink per input face (`FaceShrinks(s)`: `s[f]` in (0, 1] for
    /// face `f`, overriding [`StarOptions::shrink`]; see [`star_tucks_shrunk`]). Refused
    /// unless `s` has one entry per face.
    FaceShrinks(Vec<f64>),
    /// A face-shrink ladder over the triangulations of the [`Plan`]: every shrink of
    /// `shrinks` (largest first, each a full solve) on each triangulation in turn until a
    /// result has no [`Tessellation::problem`] (see [`Plan::run`]).
    Ladder {
        /// Face shrinks, largest first (each a full solve).
        shrinks: Vec<f64>,
        /// Whether and when to re-triangulate the input.
        remesh: Remesh,
        /// Faces of the re-triangulation; `None`: as many as the input has.
        remesh_faces: Option<usize>,
    },
}

impl Schedule {
    /// The ladder `foldcam tessellate` solves by default: every shrink of [`SHRINK_LADDER`],
    /// on the input's own triangles and on a near-regular re-triangulation of the same
    /// surface with as many faces ([`Remesh::Auto`]; first on a coarser one when the input is
    /// crowded at the rim).
    pub fn ladder() -> Schedule {
        Schedule::Ladder {
            shrinks: SHRINK_LADDER.to_vec(),
            remesh: Remesh::Auto,
            remesh_faces: None,
        }
    }
}

/// Whether each pass of a ladder runs on the re-triangulation (`true`) or on the input's own
/// triangles, in order: [`Remesh::Auto`] re-triangulates first when `mesh` has a face corner
/// sharper than the vertex-angle limit of `limits`.
pub(crate) fn remesh_order(remesh: Remesh, mesh: &PolyMesh, limits: &Limits) -> &'static [bool] {
    let sharp = min_corner_angle(mesh) < limits.min_vertex_angle;
    match remesh {
        Remesh::Never => &[false],
        Remesh::Only => &[true],
        Remesh::Auto if sharp => &[true, false],
        Remesh::Auto => &[false, true],
    }
}

/// What [`tessellate`] will solve on `mesh`, built before the first solve
/// ([`TessellateOptions::plan`]): the triangulations of the schedule, each re-triangulation
/// built once, so that a caller can show the plan and then [`run`](Plan::run) it.
#[derive(Clone, Debug)]
pub struct Plan<'a> {
    mesh: &'a PolyMesh,
    opts: &'a TessellateOptions,
    passes: Vec<Pass>,
    crowding: RimCrowding,
}

impl Plan<'_> {
    /// The triangulations solved on, in order (one [`Triangulation::Input`] pass for
    /// [`Schedule::Once`] and [`Schedule::FaceShrinks`]).
    pub fn passes(&self) -> &[Pass] {
        &self.passes
    }

    /// The input mesh's rim crowding index (Tachi 2014, Fig. 14).
    pub fn crowding(&self) -> &RimCrowding {
        &self.crowding
    }

    /// The face shrinks solved on each pass, in order: the ladder's, else the one of
    /// [`StarOptions::shrink`] (also for [`Schedule::FaceShrinks`], which overrides it per
    /// face).
    pub fn shrinks(&self) -> Vec<f64> {
        self.opts.shrinks()
    }

    /// Solves the plan, as [`tessellate`] does. On a [`Schedule::Ladder`]: the shrinks on
    /// each pass in turn (a coarser re-triangulation first when the input is crowded at the
    /// rim, then the input mesh and its re-triangulation in the order [`Remesh`] says) until
    /// a result has no [`Tessellation::problem`]; `watch` hears every result that has one.
    /// Returns the first usable result; else the first result at the input's face count
    /// (the coarser pass's when there is none); stops early, returning it, at a result
    /// [`crowded at the rim`](Tessellation::crowded_at_rim) on a pass at the input's face
    /// count (the other triangulation has the same surface and about the same edge length,
    /// so the same crowding).
    ///
    /// # Errors
    /// As [`tessellate`].
    pub fn run(&self, watch: &mut impl Watch) -> Result<Tessellation, TessError> {
        if let Some(result) = single_solve(self.mesh, self.opts, watch) {
            return result;
        }
        let shrinks = self.shrinks();
        let (mesh, opts) = (self.mesh, self.opts);
        let deadline = Deadline::after(opts.time_limit);
        let mut first: Option<Tessellation> = None;
        let mut coarser: Option<Tessellation> = None;
        for pass in &self.passes {
            if deadline.passed() && (first.is_some() || coarser.is_some()) {
                // Passes left untried: the result returned says so.
                for t in [&mut first, &mut coarser].into_iter().flatten() {
                    t.out_of_time = deadline.limit();
                }
                break;
            }
            // tessellate_shrinking tells `watch` about every failed shrink.
            let coarsened = matches!(pass.triangulation, Triangulation::Coarser { .. });
            let t = match &pass.mesh {
                Some((m, report)) => {
                    let mut t = tessellate_shrinking(m, opts, &shrinks, &deadline, watch)?;
                    t.remeshed = Some(*report);
                    t.coarsened = coarsened.then_some(self.crowding);
                    t
                }
                None => tessellate_shrinking(mesh, opts, &shrinks, &deadline, watch)?,
            };
            if t.problem().is_none() {
                return Ok(t);
            }
            if coarsened {
                coarser.get_or_insert(t);
                continue;
            }
            if t.crowded_at_rim() {
                return Ok(t);
            }
            first.get_or_insert(t);
        }
        first
            .or(coarser)
            .ok_or_else(|| TessError::BadParameter("nothing to try".into()))
    }
}

/// Checks that `mesh` is an oriented manifold disk: connected, one boundary, Euler
/// characteristic 1.
pub fn disk(mesh: &PolyMesh) -> Result<HalfEdgeMesh, TessError> {
    let (lo, hi) = mesh.bounds();
    let scale = (hi - lo).max_element().max(f64::MIN_POSITIVE);
    let he = HalfEdgeMesh::new(mesh, 1e-12 * scale * scale)?;
    let used = (0..mesh.positions().len())
        .filter(|&v| !he.fan(v).is_empty())
        .count();
    let hes = he.half_edges();
    let edges = hes
        .iter()
        .filter(|h| h.twin.is_none() || h.from < h.to)
        .count();
    let euler = used as i64 - edges as i64 + mesh.faces().len() as i64;
    let mut seen = vec![false; mesh.faces().len()];
    let mut stack = vec![0usize];
    seen[0] = true;
    while let Some(f) = stack.pop() {
        for h in he.face_half_edges(f) {
            if let Some(t) = hes[h as usize].twin {
                let g = hes[t as usize].face as usize;
                if !seen[g] {
                    seen[g] = true;
                    stack.push(g);
                }
            }
        }
    }
    if seen.iter().any(|s| !s) {
        return Err(TessError::NotADisk(
            "the faces form more than one piece".into(),
        ));
    }
    if euler != 1 {
        return Err(TessError::NotADisk(format!(
            "Euler characteristic {euler} (a closed surface is 2, an annulus 0): cut it open"
        )));
    }
    Ok(he)
}

/// Tessellates `mesh` (Tachi 2014) as `opts.schedule` says: star tucks (§2.1), mountain and
/// valley by role, the solve (§3.3) with `watch` hearing every iteration, the unfolding and
/// the face-intersection check; on a [`Schedule::Ladder`] over every shrink and
/// triangulation of its [`Plan`] until a result can be used (see [`Plan::run`]).
///
/// # Errors
/// [`TessError::NotADisk`] or [`TessError::Mesh`] for an input that is not an oriented
/// manifold disk; [`TessError::BadParameter`] for options out of range (a face-shrink list
/// without one entry per face, an empty ladder, a re-triangulation that cannot be built when
/// it is all the ladder asks for); [`TessError::Cancelled`] when `watch` asked to stop.
pub fn tessellate(
    mesh: &PolyMesh,
    opts: &TessellateOptions,
    watch: &mut impl Watch,
) -> Result<Tessellation, TessError> {
    match single_solve(mesh, opts, watch) {
        Some(result) => result,
        None => opts.plan(mesh)?.run(watch),
    }
}

/// The one solve of [`Schedule::Once`] and [`Schedule::FaceShrinks`]; `None` on a ladder.
fn single_solve(
    mesh: &PolyMesh,
    opts: &TessellateOptions,
    watch: &mut impl Watch,
) -> Option<Result<Tessellation, TessError>> {
    let face_shrink = match &opts.schedule {
        Schedule::Once => None,
        Schedule::FaceShrinks(s) => Some(s.as_slice()),
        Schedule::Ladder { .. } => return None,
    };
    Some(tessellate_shrunk(
        mesh,
        opts,
        face_shrink,
        &Deadline::after(opts.time_limit),
        |it: &Iteration| watch.iteration(it),
    ))
}

fn tessellate_shrunk(
    mesh: &PolyMesh,
    opts: &TessellateOptions,
    face_shrink: Option<&[f64]>,
    deadline: &Deadline,
    progress: impl FnMut(&Iteration) -> ControlFlow<()>,
) -> Result<Tessellation, TessError> {
    let he = disk(mesh)?;
    let mut star = opts.star;
    let l = opts.solve.limits;
    star.max_star_points = star
        .max_star_points
        .or(Some(max_star_points(l.min_vertex_angle + l.margin)));
    let mut initial = star_tucks_shrunk(&he, &star, face_shrink)?;
    assign_folds(&mut initial.mesh);
    let mut solved = initial.mesh.clone();
    let mut solve_opts = opts.solve_options();
    if opts.ground {
        solve_opts.limits.ground_z = solved
            .positions
            .iter()
            .zip(&solved.interior)
            .filter(|(_, inside)| !**inside)
            .map(|(p, _)| p.z)
            .reduce(f64::min);
    }
    let infeasible = diagnose::before_solving(
        &initial.mesh,
        mesh.positions(),
        l.min_vertex_angle + l.margin,
    );
    if !infeasible.is_empty() {
        solve_opts.max_iterations = 0;
    }
    let report = solve_until(&mut solved, &solve_opts, deadline, progress)?;
    let unmet = if report.converged {
        Vec::new()
    } else {
        diagnose::after_solving(
            &solved,
            mesh.positions(),
            &solved.positions,
            &solve_opts.limits,
            solve_opts.tolerance,
        )
    };
    let fit = match opts.fit {
        Some(fit) if report.converged => {
            let targets = corner_targets(&initial.mesh, &he);
            Some(fit_surface(&mut solved, &targets, &fit, &solve_opts)?)
        }
        _ => None,
    };
    assign_free_folds(&mut solved);
    let unfolded = unfold(&solved);
    let intersections = intersecting_triangles(
        &solved.positions,
        &solved.triangles,
        opts.intersection_tolerance,
    )?;
    let collisions =
        (!intersections.is_empty()).then(|| CollisionSites::locate(&solved, &he, &intersections));
    let crowding = rim_crowding_of(mesh, &he);
    let out_of_time = report.out_of_time.then_some(deadline.limit()).flatten();
    Ok(Tessellation {
        initial,
        mesh: solved,
        report,
        fit,
        unfolded,
        intersections,
        intersection_tolerance: opts.intersection_tolerance,
        collisions,
        crowding,
        infeasible,
        unmet,
        remeshed: None,
        coarsened: None,
        out_of_time,
    })
}

/// Every face corner of the initial pattern, at its initial place, with its input vertex's
/// normal (the tucks' vertices get no target).
fn corner_targets(initial: &TessMesh, he: &HalfEdgeMesh) -> Vec<Target> {
    (0..initial.corner_count)
        .map(|v| {
            let input = initial.input_vertex[v] as usize;
            Target {
                vertex: v as u32,
                point: initial.positions[v],
                normal: he.vertex_normal(input),
            }
        })
        .collect()
}
