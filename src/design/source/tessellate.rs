//! Origami tessellations (Tachi 2014) from a disk-like mesh: the tucks, the solve (trying
//! smaller face shrinks until one works, unless one is asked for), the report, and the
//! unfolded crease pattern with its folded form — what `foldcam tessellate` does before it
//! writes anything.

use std::path::Path;

use super::{DesignFile, DesignKind, Progress, SourceError};
use crate::design::tessellation::estimate::solve_estimate;
use crate::design::tessellation::{
    FitOptions, Iteration, Limits, Remesh, SHRINK_LADDER, Schedule, StarOptions, TessMesh,
    TessellateOptions, Tessellation, TuckKind, TuckLayout, TuckShape, Unfolded,
    tessellate_scheduled,
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
}

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
        }
    }
}

impl TessellationOptions {
    /// The solver's options.
    ///
    /// # Errors
    /// [`SourceError::Option`] for an iteration cap or fit weight out of range.
    pub fn to_solver(&self) -> Result<TessellateOptions, SourceError> {
        if self.max_iterations == 0 || self.max_iterations > MAX_ITERATIONS {
            return Err(SourceError::Option(format!(
                "--max-iterations must be between 1 and {MAX_ITERATIONS}"
            )));
        }
        let limits = Limits::from_degrees(self.max_fold_angle_deg, self.min_vertex_angle_deg);
        let mut opts = TessellateOptions::with_limits(limits);
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
    pub summary: Vec<String>,
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
    outcome
        .design
        .map_err(|lines| SourceError::NotMade { lines })
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
    pub design: Result<TessellationDesign, Vec<String>>,
}

/// Raised through the solver to stop it when [`Progress::cancelled`] says so, and caught in
/// [`tessellate_outcome`]; the solver's callbacks have no other way out.
struct Cancelled;

/// Stops the solve when `progress` asks for it: unwinds with [`Cancelled`] (without the panic
/// hook, so nothing is printed).
fn stop_if_cancelled(progress: &dyn Progress) {
    if progress.cancelled() {
        std::panic::resume_unwind(Box::new(Cancelled));
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
/// `progress` asked to stop (checked before every solver iteration and between attempts).
pub fn tessellate_outcome(
    name: &Path,
    mesh: &PolyMesh,
    options: &TessellationOptions,
    progress: &mut dyn Progress,
) -> Result<TessellationOutcome, SourceError> {
    let opts = options.to_solver()?;
    let limits = opts.solve.limits;
    progress.note(format!(
        "{}: {} faces; solving (fold <= {fold:.1} deg, vertex angle >= {corner:.1} deg)",
        name.display(),
        mesh.faces().len(),
        fold = limits.max_fold.to_degrees(),
        corner = limits.min_vertex_angle.to_degrees(),
    ));
    let shrinks = options.shrink.map_or(SHRINK_LADDER.to_vec(), |s| vec![s]);
    progress.note(format!(
        "estimate: {} per solve, up to {} solve(s) (one per face shrink tried, twice if the \
         surface is re-triangulated)",
        solve_estimate(mesh.faces().len()),
        shrinks.len()
    ));
    let asked = options.shrink.is_some();
    stop_if_cancelled_early(progress)?;
    progress.busy("solving");
    // Both callbacks speak through `progress`, one at a time.
    let shared = std::cell::RefCell::new(&mut *progress);
    let schedule = Schedule {
        shrinks,
        remesh: options.remesh,
        remesh_faces: options.remesh_faces,
    };
    let run = || {
        tessellate_scheduled(
            mesh,
            &opts,
            &schedule,
            |s: f64, t: &Tessellation| {
                if !asked {
                    let next = if s > SHRINK_LADDER[SHRINK_LADDER.len() - 1] {
                        "trying a smaller shrink"
                    } else {
                        "no shrink worked on these triangles"
                    };
                    shared.borrow_mut().note(format!(
                        "shrink {s}: {}; {next}",
                        t.problem().unwrap_or_default()
                    ));
                }
                stop_if_cancelled(&**shared.borrow());
            },
            |it: &Iteration| {
                shared.borrow_mut().iteration(it);
                stop_if_cancelled(&**shared.borrow());
            },
        )
    };
    // Unwind safety: on cancellation everything the solve built is dropped unseen; `progress`
    // only ever sees whole calls.
    let t = match std::panic::catch_unwind(std::panic::AssertUnwindSafe(run)) {
        Ok(t) => t,
        Err(payload) if payload.is::<Cancelled>() => {
            progress.idle();
            return Err(SourceError::Cancelled);
        }
        Err(payload) => std::panic::resume_unwind(payload),
    };
    progress.idle();
    let t = t.map_err(|e| SourceError::input(name, e))?;
    let mut lines = vec![
        format!(
            "{}: {} layout, {} tucks, shrink {}, {} vertices, {} triangles, {} interior vertices",
            name.display(),
            t.initial.layout,
            opts.star.tuck.kind,
            t.initial.shrink,
            t.mesh.positions.len(),
            t.mesh.triangles.len(),
            t.mesh.interior_count()
        ),
        t.summary(),
    ];
    for v in &t.infeasible {
        lines.push(format!("  cannot meet the limits: {}", v.describe()));
    }
    // The worst few places of each unmet condition (the list is sorted by condition).
    for group in t.unmet.chunk_by(|a, b| a.condition == b.condition) {
        for v in group.iter().take(UNMET_SHOWN) {
            lines.push(format!("  unmet: {}", v.describe()));
        }
        if group.len() > UNMET_SHOWN {
            lines.push(format!(
                "  ... and {} more input vertices",
                group.len() - UNMET_SHOWN
            ));
        }
    }
    if let Some(fit) = &t.fit {
        lines.push(format!(
            "surface fit: distance {:.4e} -> {:.4e} in {} rounds",
            fit.initial, fit.last, fit.accepted
        ));
    }
    let problem = t.problem();
    let design = match (problem, t.unfolded) {
        (None, Ok(unfolded)) => {
            lines.push(format!(
                "unfolded: no overlaps, edge lengths match 3D within {:.1e} (relative)",
                unfolded.max_length_error
            ));
            Ok(TessellationDesign {
                unfolded,
                summary: lines,
            })
        }
        (problem, unfolded) => {
            let why = problem.or(unfolded.err().map(|e| e.to_string()));
            lines.push(format!("nothing written: {}", why.unwrap_or_default()));
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
