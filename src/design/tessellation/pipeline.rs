//! The whole design in one call: mesh → star tucks → solve → unfold → face-intersection check.
//!
//! The callbacks (`progress` per solver iteration, `attempt` per refused result) return
//! [`ControlFlow`]: [`ControlFlow::Break`] stops the work at once with
//! [`TessError::Cancelled`]; [`keep_going`] and [`keep_trying`] never stop it.

use std::ops::ControlFlow;

use super::collision_sites::CollisionSites;
use super::constraints::{BoundaryRuns, Limits, assign_folds, assign_free_folds};
use super::crowding::{CROWDING_LIMIT, RimCrowding, rim_crowding_of};
use super::diagnose::{self, Violation};
use super::fit::{FitOptions, FitReport, Target, fit_surface};
use super::intersect::intersecting_triangles;
use super::passes::{Pass, Triangulation, scheduled_passes};
use super::remesh::{RemeshReport, min_corner_angle};
use super::solver::{Iteration, SolveOptions, SolveReport, solve};
use super::star::{InitialPattern, StarOptions, max_star_points, star_tucks_shrunk};
use super::tuck::TuckKind;
use super::unfold::{Unfolded, unfold};
use super::{TessError, TessMesh};
use crate::mesh::{HalfEdgeMesh, PolyMesh};

/// Everything [`tessellate`] needs besides the mesh.
#[derive(Clone, Copy, Debug, PartialEq)]
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
}

impl Default for TessellateOptions {
    fn default() -> Self {
        TessellateOptions {
            star: StarOptions::default(),
            solve: SolveOptions::default(),
            ground: false,
            fit: None,
            intersection_tolerance: 1e-3,
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
}

impl Tessellation {
    /// The solver's summary with the face-intersection count of the folded form.
    pub fn summary(&self) -> String {
        let found = match self.intersections.first() {
            None => "none".to_string(),
            Some((a, b)) => format!(
                "{} pairs (first: triangles {a} and {b})",
                self.intersections.len()
            ),
        };
        let mut remeshed = self
            .remeshed
            .map_or(String::new(), |r| format!("{}\n", r.describe()));
        if let (Some(c), Some(r)) = (self.coarsened, self.remeshed) {
            remeshed = format!("{}\n{remeshed}", Self::coarsened_line(&c, &r));
        }
        format!(
            "{remeshed}{}\n  face intersections (folded form, tolerance {:.0e} mm): {found}",
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

/// A `progress` callback that only lets the solve go on.
pub fn keep_going(_: &Iteration) -> ControlFlow<()> {
    ControlFlow::Continue(())
}

/// An `attempt` callback that only lets the next attempt begin.
pub fn keep_trying(_: f64, _: &Tessellation) -> ControlFlow<()> {
    ControlFlow::Continue(())
}

/// The face shrinks [`tessellate_shrinking`] tries by default, largest first.
pub const SHRINK_LADDER: [f64; 6] = [0.8, 0.7, 0.6, 0.5, 0.45, 0.4];

/// [`tessellate`] with each face shrink of `shrinks` in turn (overriding `opts.star.shrink`)
/// until a result has no [`Tessellation::problem`]; `attempt` hears every result that has one
/// (its solve has ended) before the next shrink is tried. A shrink whose solve converges with
/// [`BoundaryRuns::Dominant`] rows but intersects itself is solved once more with
/// [`BoundaryRuns::EveryStart`] when a boundary row entered the first solve
/// ([`SolveReport::boundary_rows`]; else the second would repeat it to the bit). That is the
/// stiffer outline, as one attempt: `attempt` hears the
/// second result only, and `progress` counts the second solve's iterations on from the
/// first's). Returns the first usable result, else the first one (the result of the shrink
/// asked for first); stops early at a result
/// [`crowded at the rim`](Tessellation::crowded_at_rim) and returns that one.
/// This stands in for the paper's user, who avoids global face collisions (type 3, §3.2) by
/// adjusting the design: a smaller shrink opens the tucks wider.
pub fn tessellate_shrinking(
    mesh: &PolyMesh,
    opts: &TessellateOptions,
    shrinks: &[f64],
    mut attempt: impl FnMut(f64, &Tessellation) -> ControlFlow<()>,
    mut progress: impl FnMut(&Iteration) -> ControlFlow<()>,
) -> Result<Tessellation, TessError> {
    let mut first = None;
    for &shrink in shrinks {
        let mut o = *opts;
        o.star.shrink = shrink;
        let mut t = tessellate(mesh, &o, &mut progress)?;
        if t.report.converged
            && !t.intersections.is_empty()
            && o.solve.limits.boundary_runs == BoundaryRuns::Dominant
            && t.report.boundary_rows
        {
            // The same shrink again with the stiffer outline (see `BoundaryRuns`); its
            // iterations continue the count, so progress displays see one solve per shrink.
            // Not when no boundary row ever entered: that solve would be the same one
            // (`SolveReport::boundary_rows`).
            o.solve.limits.boundary_runs = BoundaryRuns::EveryStart;
            let before = t.report.iterations;
            t = tessellate(mesh, &o, |it: &Iteration| {
                progress(&Iteration {
                    index: before + it.index,
                    ..*it
                })
            })?;
        }
        if t.problem().is_none() || t.crowded_at_rim() {
            return Ok(t);
        }
        if attempt(shrink, &t).is_break() {
            return Err(TessError::Cancelled);
        }
        first.get_or_insert(t);
    }
    first.ok_or_else(|| TessError::BadParameter("no face shrink to try".into()))
}

/// Whether [`tessellate_scheduled`] re-triangulates the input ([`remesh`](fn@super::remesh)).
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

/// What [`tessellate_scheduled`] tries, in order.
#[derive(Clone, Debug, PartialEq)]
pub struct Schedule {
    /// Face shrinks, largest first (each a full solve).
    pub shrinks: Vec<f64>,
    /// Whether and when to re-triangulate the input.
    pub remesh: Remesh,
    /// Faces of the re-triangulation; `None`: as many as the input has.
    pub remesh_faces: Option<usize>,
}

impl Schedule {
    /// Whether each pass of the schedule runs on the re-triangulation (`true`) or on the
    /// input's own triangles, in order: [`Remesh::Auto`] re-triangulates first when `mesh`
    /// has a face corner sharper than the vertex-angle limit of `limits`.
    pub fn remesh_order(&self, mesh: &PolyMesh, limits: &Limits) -> &'static [bool] {
        let sharp = min_corner_angle(mesh) < limits.min_vertex_angle;
        match self.remesh {
            Remesh::Never => &[false],
            Remesh::Only => &[true],
            Remesh::Auto if sharp => &[true, false],
            Remesh::Auto => &[false, true],
        }
    }
}

/// The default schedule: every shrink of [`SHRINK_LADDER`], on the input's own triangles and
/// on a near-regular re-triangulation of the same surface with as many faces
/// ([`Remesh::Auto`]; first on a coarser one when the input is crowded at the rim).
pub fn default_schedule() -> Schedule {
    Schedule {
        shrinks: SHRINK_LADDER.to_vec(),
        remesh: Remesh::Auto,
        remesh_faces: None,
    }
}

/// [`tessellate_shrinking`] over `schedule`: the shrinks on each of its
/// [`passes`](super::passes::scheduled_passes) in turn (a coarser re-triangulation first when
/// the input is crowded at the rim, then the input mesh and its re-triangulation in the
/// order [`Schedule::remesh`] says) until a result has no [`Tessellation::problem`].
/// `attempt` hears every result that has one. Returns the first usable result; else the
/// first result at the input's face count (the coarser pass's when there is none); stops
/// early, returning it, at a result [`crowded at the rim`](Tessellation::crowded_at_rim) on
/// a pass at the input's face count (the other triangulation has the same surface and about
/// the same edge length, so the same crowding). A re-triangulation that cannot be built (for
/// instance on a mesh too small for it) is left out when another pass remains, an error
/// otherwise.
pub fn tessellate_scheduled(
    mesh: &PolyMesh,
    opts: &TessellateOptions,
    schedule: &Schedule,
    attempt: impl FnMut(f64, &Tessellation) -> ControlFlow<()>,
    progress: impl FnMut(&Iteration) -> ControlFlow<()>,
) -> Result<Tessellation, TessError> {
    let (passes, crowding) = scheduled_passes(mesh, &opts.solve.limits, schedule)?;
    tessellate_passes(
        mesh,
        opts,
        &schedule.shrinks,
        &passes,
        &crowding,
        attempt,
        progress,
    )
}

/// [`tessellate_scheduled`] over passes already built by
/// [`super::passes::scheduled_passes`] (with the input's `crowding` it
/// returned), so that a caller that shows the plan builds each re-triangulation once.
pub fn tessellate_passes(
    mesh: &PolyMesh,
    opts: &TessellateOptions,
    shrinks: &[f64],
    passes: &[Pass],
    crowding: &RimCrowding,
    mut attempt: impl FnMut(f64, &Tessellation) -> ControlFlow<()>,
    mut progress: impl FnMut(&Iteration) -> ControlFlow<()>,
) -> Result<Tessellation, TessError> {
    let mut first: Option<Tessellation> = None;
    let mut coarser: Option<Tessellation> = None;
    for pass in passes {
        // tessellate_shrinking tells `attempt` about every failed shrink.
        let coarsened = matches!(pass.triangulation, Triangulation::Coarser { .. });
        let t = match &pass.mesh {
            Some((m, report)) => {
                let mut t = tessellate_shrinking(m, opts, shrinks, &mut attempt, &mut progress)?;
                t.remeshed = Some(*report);
                t.coarsened = coarsened.then_some(*crowding);
                t
            }
            None => tessellate_shrinking(mesh, opts, shrinks, &mut attempt, &mut progress)?,
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

/// Tessellates `mesh`: star tucks (§2.1), mountain/valley by role, the solve (§3.3) with
/// `progress` called per iteration, the unfolding and the face-intersection check.
pub fn tessellate(
    mesh: &PolyMesh,
    opts: &TessellateOptions,
    progress: impl FnMut(&Iteration) -> ControlFlow<()>,
) -> Result<Tessellation, TessError> {
    tessellate_shrunk(mesh, opts, None, progress)
}

/// [`tessellate`] with a face shrink per input face (`face_shrink[f]` in (0, 1], overriding
/// `opts.star.shrink`; see [`super::star::star_tucks_shrunk`]).
/// Errors as [`tessellate`], and when `face_shrink` does not have one entry per face.
pub fn tessellate_with_face_shrink(
    mesh: &PolyMesh,
    opts: &TessellateOptions,
    face_shrink: &[f64],
    progress: impl FnMut(&Iteration) -> ControlFlow<()>,
) -> Result<Tessellation, TessError> {
    tessellate_shrunk(mesh, opts, Some(face_shrink), progress)
}

fn tessellate_shrunk(
    mesh: &PolyMesh,
    opts: &TessellateOptions,
    face_shrink: Option<&[f64]>,
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
    let report = solve(&mut solved, &solve_opts, progress)?;
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
