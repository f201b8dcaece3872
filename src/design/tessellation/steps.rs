//! The pipeline's individual steps (Tachi 2014), for callers that run them one by one
//! (benchmarks, experiments) instead of [`tessellate`](super::tessellate), in the order the
//! pipeline runs them, with what they return:
//!
//! 1. [`disk`]: the input as a half-edge mesh, refused unless an oriented manifold disk;
//!    [`remesh`]: a near-regular re-triangulation (Floater's (2003) mean-value map onto a
//!    disk), and the [`Pass`]es of a [`Plan`](super::Plan) on the [`Triangulation`]s it
//!    builds;
//! 2. [`star_tucks`]: the initial pattern (§2.1, §2.2) with at most [`max_star_points`]
//!    points per star, tucks shaped by [`TuckShape`];
//! 3. [`assign_folds`]: mountains and valleys read off the half-open tucks;
//! 4. [`solve`]: generalized Newton–Raphson (§3.3) to developability (eq. 1) within the
//!    limits (eq. 3, §5), the eq. 2 boundary rows as [`BoundaryRuns`] says, the vertex
//!    penalties (eq. 5–7) active within [`PENALTY_TOLERANCE`] radians;
//! 5. the surface fit (§3.4, [`FitOptions`], [`FitReport`]);
//! 6. [`unfold`]: the flat pattern and its folded state ([`Unfolded`]);
//! 7. [`intersecting_triangles`], [`folded_intersections`]: faces of the folded form passing
//!    through each other (beyond the paper).
//!
//! [`SHRINK_LADDER`] is the ladder's face shrinks, [`TWISTED_ITERATIONS`] the iteration cap's
//! factor for twisted stars.

pub use super::constraints::{BoundaryRuns, assign_folds};
pub use super::fit::{FitOptions, FitReport};
pub use super::intersect::{folded_intersections, intersecting_triangles};
pub use super::model::{EdgeRole, TessEdge};
pub use super::passes::{Pass, Triangulation};
pub use super::pipeline::{SHRINK_LADDER, TWISTED_ITERATIONS, disk};
pub use super::remesh::{RemeshReport, remesh};
pub use super::solver::{SolveReport, solve};
pub use super::star::{InitialPattern, max_star_points, star_tucks};
pub use super::tuck::TuckShape;
pub use super::unfold::{Unfolded, unfold};
pub use super::vertex_penalty::TOLERANCE as PENALTY_TOLERANCE;
