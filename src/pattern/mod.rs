//! The crease-pattern model: vertices in millimetres, edges with FOLD assignments and fold
//! angles, faces; its folded state; and planarisation, which turns any line drawing into a
//! clean planar graph with faces.
//!
//! Invariants of a validated [`CreasePattern`] (see [`CreasePattern::validate`]): coordinates
//! are finite and within ±1e9, every edge joins two distinct existing vertices, fold angles lie
//! in [−180°, 180°]. After [`planarize()`], additionally: no two edges cross or overlap, no two
//! vertices are closer than the tolerance, no edge has zero length, and the faces are those of
//! the planar graph.

mod assignment;
mod crease_pattern;
pub mod edit;
mod error;
mod extent;
pub(crate) mod faces;
mod folded;
mod ids;
pub(crate) mod planarize;
mod scale;
pub mod snap;
pub(crate) mod vertex_fan;

pub use assignment::{Assignment, UnknownAssignment};
pub use crease_pattern::{
    CreasePattern, Edge, Face, MAX_COORDINATE, Metadata, UnitlessError, Units,
};
pub use error::PatternError;
pub use extent::Degenerate;
pub use faces::find_faces;
pub use folded::FoldedState;
pub use ids::{EdgeId, FaceId, VertexId};
pub use planarize::{PlanarizeError, PlanarizeOptions, PlanarizeReport, planarize};
pub use scale::{Scale, ScaleError, Scaled};
pub use vertex_fan::VertexFans;
