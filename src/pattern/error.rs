//! Errors of the pattern model.

use super::{EdgeId, FaceId, VertexId};

/// A crease pattern that breaks a structural invariant (see
/// [`CreasePattern::validate`](super::CreasePattern::validate)).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PatternError {
    /// A coordinate is NaN or infinite.
    #[error("vertex {vertex} has a non-finite coordinate")]
    NonFiniteCoordinate {
        /// The vertex.
        vertex: VertexId,
    },
    /// A coordinate is beyond ±1e9.
    #[error("vertex {vertex} has a coordinate of {value:e}, beyond the limit of 1e9 mm")]
    CoordinateTooLarge {
        /// The vertex.
        vertex: VertexId,
        /// The offending magnitude.
        value: f64,
    },
    /// An edge refers to a vertex that does not exist.
    #[error("edge {edge} refers to vertex {vertex}, but there are only {count} vertices")]
    VertexOutOfRange {
        /// The edge.
        edge: EdgeId,
        /// The bad index.
        vertex: usize,
        /// Number of vertices.
        count: usize,
    },
    /// An edge starts and ends at the same vertex.
    #[error("edge {edge} joins a vertex to itself")]
    LoopEdge {
        /// The edge.
        edge: EdgeId,
    },
    /// A fold angle is outside [−180°, 180°] or not finite.
    #[error("edge {edge} has fold angle {degrees}°, outside [-180°, 180°]")]
    FoldAngleOutOfRange {
        /// The edge.
        edge: EdgeId,
        /// The angle given.
        degrees: f64,
    },
    /// A face has fewer than three corners (or a hole fewer than two).
    #[error("face {face} has fewer than 3 vertices")]
    DegenerateFace {
        /// The face.
        face: FaceId,
    },
    /// A face refers to a vertex that does not exist.
    #[error("face {face} refers to vertex {vertex}, but there are only {count} vertices")]
    FaceVertexOutOfRange {
        /// The face.
        face: FaceId,
        /// The bad index.
        vertex: usize,
        /// Number of vertices.
        count: usize,
    },
}
