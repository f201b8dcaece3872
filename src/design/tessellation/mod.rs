//! Freeform origami tessellations (Tachi 2014, Tachi, "Freeform 3D Origami Tessellations for
//! Fabrication"): from a disk-like polygon mesh to a developable, Resch-like tessellation that
//! respects the fabrication limits, unfolded into a [`CreasePattern`](crate::pattern::CreasePattern)
//! with its folded state.
//!
//! Pipeline: [`star_tucks`] inserts a tuck at every vertex (§2.1, §2.2: [`star`], [`tuck`]);
//! [`assign_folds`] reads mountains and valleys off the half-open tucks; [`solve`] moves every
//! vertex by generalized Newton–Raphson until the interior vertices are developable (eq. 1)
//! and the fold-angle (eq. 3, §5) and vertex-angle (§5) limits hold ([`solver`]);
//! [`unfold`](mod@unfold) lays the result flat triangle by triangle and checks it for overlaps;
//! [`intersect`] checks the folded form for faces passing through each other.
//!
//! Implemented: §2.1 (checkerboard and digon layouts), eq. 1, eq. 3 with the §5 fold limit,
//! the §5 vertex-angle limit, ground contact (§6), §3.3 with an analytic sparse Jacobian (eq. 8)
//! and a matrix-free conjugate gradient for the minimum-norm step, the surface fit of §3.4
//! (eq. 9, eq. 10 as a weighted sum of squares: see [`fit`]), the vertex-adjacent penalty
//! (eq. 5–7, [`vertex_penalty`]) as solver rows, the §2.2 variations (truncated star,
//! twisted star, twist fold: [`tuck`]) with their flat n-gons kept flat and the vertex-angle
//! limit measured between creases ([`sectors`]). The rigid-foldability simulation of §5 is in
//! `rigid`.
//! Beyond the paper (which leaves global collisions to the user's eye), the folded form is
//! checked exactly for intersecting faces ([`intersect`]). Boundary non-overlap (eq. 2) is a
//! constraint ([`boundary`]) and the unfolded pattern is also checked for overlaps directly.
//! Meshes whose own triangles make the limits unreachable (a modelling program's sphere: a
//! 12-valent pole, face corners sharper than the crease-angle limit) are re-triangulated
//! near-regularly ([`remesh`](mod@remesh), Floater's (2003) mean-value map onto a disk), by
//! [`tessellate_scheduled`] as the default does (on a coarser re-triangulation first when the
//! input is crowded at the rim, [`crowding`], [`passes`]); [`distance`] measures how far the
//! folded form lies from the input surface.

pub(crate) mod advice;
pub(crate) mod boundary;
pub(crate) mod collision;
pub(crate) mod collision_sites;
pub(crate) mod constraints;
pub(crate) mod crowding;
pub(crate) mod diagnose;
pub(crate) mod distance;
pub(crate) mod estimate;
pub(crate) mod fit;
pub(crate) mod geometry;
pub(crate) mod intersect;
mod min_norm;
pub(crate) mod model;
pub(crate) mod passes;
pub(crate) mod pipeline;
pub(crate) mod remesh;
pub mod rigid;
pub(crate) mod samples;
pub(crate) mod sectors;
pub(crate) mod solver;
pub(crate) mod star;
pub(crate) mod tuck;
pub(crate) mod unfold;
pub(crate) mod vertex_penalty;

use thiserror::Error;

pub use advice::{CurvatureAdvice, curvature_advice};
pub use collision_sites::{CollisionSite, CollisionSites};
pub use constraints::{
    BoundaryRuns, Limits, Residuals, angle_defects, assign_folds, assign_free_folds, residuals,
};
pub use crowding::{CROWDING_LIMIT, RimCrowding, rim_crowding};
pub use diagnose::{Condition, Violation, after_solving, before_solving, sector_counts};
pub use distance::{
    MIN_COVERED, PARTIAL_REACH, SurfaceDistance, SurfaceFit, corner_distance, fit_and_missing,
    surface_fit, uncovered_triangles,
};
pub use fit::{FitOptions, FitReport, Target, fit_surface};
pub use geometry::{Graded, fold_angle};
pub use intersect::{folded_intersections, intersecting_triangles};
pub use model::{EdgeRole, TessEdge, TessMesh};
pub use passes::{Pass, Triangulation, scheduled_passes};
pub use pipeline::{
    Remesh, SHRINK_LADDER, Schedule, TWISTED_ITERATIONS, TessellateOptions, Tessellation,
    default_schedule, disk, keep_going, keep_trying, tessellate, tessellate_passes,
    tessellate_scheduled, tessellate_shrinking, tessellate_with_face_shrink,
};
pub use remesh::{RemeshReport, remesh};
pub use samples::{MASK_SIZE_MM, SampleSurface, face_mask, sample_surface, spherical_cap};
pub use solver::{Iteration, SolveOptions, SolveReport, solve};
pub use star::{
    InitialPattern, StarOptions, TuckLayout, max_star_points, star_tucks, star_tucks_shrunk,
};
pub use tuck::{TuckKind, TuckShape};
pub use unfold::{Unfolded, unfold};
pub use vertex_penalty::TOLERANCE as PENALTY_TOLERANCE;

use crate::mesh::HalfEdgeError;

/// Why a tessellation cannot be made.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum TessError {
    /// The input mesh is not an oriented manifold.
    #[error("input mesh: {0}")]
    Mesh(#[from] HalfEdgeError),
    /// A parameter is out of range.
    #[error("{0}")]
    BadParameter(String),
    /// The input mesh is not a disk (one boundary loop, Euler characteristic 1).
    #[error("the mesh must be a disk with one boundary: {0}")]
    NotADisk(String),
    /// The developed pattern overlaps itself.
    #[error("the unfolded pattern overlaps itself (triangles {0} and {1})")]
    Overlap(usize, usize),
    /// A callback asked to stop (the solve was cancelled, not refused).
    #[error("cancelled")]
    Cancelled,
}
