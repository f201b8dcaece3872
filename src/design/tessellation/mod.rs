//! Freeform origami tessellations (Tachi 2014, Tachi, "Freeform 3D Origami Tessellations for
//! Fabrication"): from a disk-like polygon mesh to a developable, Resch-like tessellation that
//! respects the fabrication limits, unfolded into a [`CreasePattern`](crate::pattern::CreasePattern)
//! with its folded state.
//!
//! One entry point: [`tessellate`]`(mesh, &opts, &mut watch)`. [`TessellateOptions`] hold the
//! initial pattern ([`StarOptions`]: layout, tuck kind, face shrink), the solver and its
//! fabrication [`Limits`] ([`SolveOptions`]), ground contact, the surface fit and the
//! [`Schedule`]: one solve ([`Schedule::Once`], the default), one with a shrink per face
//! ([`Schedule::FaceShrinks`]) or a face-shrink ladder over re-triangulations
//! ([`Schedule::Ladder`], [`Remesh`]). [`TessellateOptions::plan`] builds the
//! [`Plan`] (the triangulations, in order) for a caller that shows it before
//! [`Plan::run`] solves it. A [`Watch`] hears every solver [`Iteration`] and every refused
//! result and can stop the work; `()` watches nothing. The result is a [`Tessellation`]
//! (the solved [`TessMesh`], the reports, the unfolded pattern).
//!
//! Four public submodules own the rest: [`steps`], the pipeline's individual steps (star
//! tucks, fold assignment, the solve, the re-triangulation, the unfolding, the
//! face-intersection check) for callers that run them one by one; [`measure`], what is
//! measured on a mesh or a result (residuals, fold angles, violations, rim crowding,
//! collision sites, the distance to the input surface); [`samples`], the sample surfaces
//! (caps, the face mask); and [`rigid`], the rigid-foldability simulation of §5.
//!
//! Pipeline: star tucks at every vertex (§2.1, §2.2: `star.rs`, `tuck.rs`); mountains and
//! valleys read off the half-open tucks; the solve moves every vertex by generalized
//! Newton–Raphson until the interior vertices are developable (eq. 1) and the fold-angle
//! (eq. 3, §5) and vertex-angle (§5) limits hold (`solver.rs`); the unfolding lays the
//! result flat triangle by triangle and checks it for overlaps (`unfold.rs`); the folded
//! form is checked for faces passing through each other (`intersect.rs`).
//!
//! Implemented: §2.1 (checkerboard and digon layouts), eq. 1, eq. 3 with the §5 fold limit,
//! the §5 vertex-angle limit, ground contact (§6), §3.3 with an analytic sparse Jacobian (eq. 8)
//! and a matrix-free conjugate gradient for the minimum-norm step, the surface fit of §3.4
//! (eq. 9, eq. 10 as a weighted sum of squares: `fit.rs`), the vertex-adjacent penalty
//! (eq. 5–7, `vertex_penalty.rs`) as solver rows, the §2.2 variations (truncated star,
//! twisted star, twist fold: `tuck.rs`) with their flat n-gons kept flat and the vertex-angle
//! limit measured between creases (`sectors.rs`). The rigid-foldability simulation of §5 is in
//! [`rigid`].
//! Beyond the paper (which leaves global collisions to the user's eye), the folded form is
//! checked exactly for intersecting faces (`intersect.rs`). Boundary non-overlap (eq. 2) is a
//! constraint (`boundary.rs`) and the unfolded pattern is also checked for overlaps directly.
//! Meshes whose own triangles make the limits unreachable (a modelling program's sphere: a
//! 12-valent pole, face corners sharper than the crease-angle limit) are re-triangulated
//! near-regularly (`remesh.rs`, Floater's (2003) mean-value map onto a disk), by
//! [`Schedule::ladder`] as `foldcam tessellate` does (on a coarser re-triangulation first
//! when the input is crowded at the rim, `crowding.rs`, `passes.rs`); `distance.rs` measures
//! how far the folded form lies from the input surface, with the closest-point structure
//! [`ReferenceMesh`](crate::mesh::ReferenceMesh) of `mesh`.

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
pub mod measure;
mod min_norm;
pub(crate) mod model;
pub(crate) mod passes;
pub(crate) mod pipeline;
pub(crate) mod remesh;
pub mod rigid;
pub mod samples;
pub(crate) mod sectors;
pub(crate) mod solver;
pub(crate) mod star;
pub mod steps;
pub(crate) mod tuck;
pub(crate) mod unfold;
pub(crate) mod vertex_penalty;

use thiserror::Error;

pub use constraints::Limits;
pub use model::TessMesh;
pub use pipeline::{Plan, Remesh, Schedule, TessellateOptions, Tessellation, Watch, tessellate};
pub use solver::{Iteration, SolveOptions};
pub use star::{StarOptions, TuckLayout};
pub use tuck::TuckKind;

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
