//! What is measured on a tessellation's mesh or result (Tachi 2014), for reports and tests:
//! the residuals of the conditions (eq. 1, eq. 3, the §5 limits: [`residuals`],
//! [`angle_defects`], [`fold_angle`] with its gradient, [`Graded`]); the places a limit
//! cannot be met before solving or is left unmet ([`before_solving`], [`Violation`],
//! [`Condition`], [`sector_counts`]); the rim crowding index (Fig. 14: [`rim_crowding`],
//! [`CROWDING_LIMIT`]) and where face collisions lie ([`CollisionSites`]); how far the folded
//! form lies from the input surface ([`corner_distance`], [`surface_fit`], mm) and the input
//! triangles it leaves uncovered ([`uncovered_triangles`]).

pub use super::advice::CurvatureAdvice;
pub use super::collision_sites::{CollisionSite, CollisionSites};
pub use super::constraints::{Residuals, angle_defects, residuals};
pub use super::crowding::{CROWDING_LIMIT, RimCrowding, rim_crowding};
pub use super::diagnose::{Condition, Violation, before_solving, sector_counts};
pub use super::distance::{
    SurfaceDistance, SurfaceFit, corner_distance, surface_fit, uncovered_triangles,
};
pub use super::estimate::LadderEstimate;
pub use super::geometry::{Graded, fold_angle};
pub use super::pipeline::SolveSummary;
