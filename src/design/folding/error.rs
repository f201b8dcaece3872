//! Why a fold step cannot be made. A failed step leaves the simulator's state untouched.

/// A fold, drag or undo that cannot be carried out.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FoldError {
    /// The sheet outline is unusable.
    #[error("the sheet {0}")]
    Sheet(String),
    /// A coordinate or angle is NaN, infinite or beyond ±1e9.
    #[error("{what} is not a finite number within ±1e9")]
    NotFinite {
        /// Which value.
        what: &'static str,
    },
    /// The two points of the fold line coincide.
    #[error("the two points of the fold line coincide")]
    DegenerateLine,
    /// The fold line (or drag) lies in no layer of the current state.
    #[error("the fold line does not lie in the plane of any layer of the paper")]
    NoLayer,
    /// The point naming the moving side lies on the fold line.
    #[error("the point naming the moving side lies on the fold line")]
    SideOnLine,
    /// Nothing or everything of the layer lies on the moving side.
    #[error("the fold line misses the sheet: {0}")]
    LineMissesSheet(&'static str),
    /// The fold angle is zero or beyond ±180°.
    #[error("fold angle {0}° is outside (0°, 180°] in magnitude")]
    BadAngle(f64),
    /// A tuck-in would carry faces of another plane along.
    #[error(
        "a tuck-in cannot carry faces of another plane: a moving face is attached beyond the \
         fold line to a face that does not lie in the layer plane"
    )]
    AttachedOutOfPlane,
    /// A face of another plane that the fold carries along is also joined to the stationary
    /// side (for example a standing flap whose hinge the fold line crosses).
    #[error(
        "a face in another plane would be carried by the fold but is also attached to the \
         stationary side of the fold line"
    )]
    CarriedFaceHeld,
    /// A tuck-in needs an even number of moving layers, mirrored pairwise.
    #[error("a tuck-in needs symmetric layers: {0}")]
    TuckAsymmetric(String),
    /// A stationary layer between the two halves of a tuck-in is in the way.
    #[error(
        "a tuck-in the layers do not allow: a stationary layer between the two moving halves \
         covers the place they fold to"
    )]
    TuckBlocked,
    /// No vertex lies near the point where a drag starts.
    #[error("no vertex of the paper lies within {tolerance} mm of the drag start")]
    NoVertexNear {
        /// The search radius, millimetres.
        tolerance: f64,
    },
    /// The drag does not define a fold (zero length, or straight along the layer normal).
    #[error("the drag does not define a fold: {0}")]
    BadDrag(&'static str),
    /// Undo to a step that does not exist.
    #[error("cannot undo to step {step}: the sequence has steps 0 to {last}")]
    NoSuchStep {
        /// The step asked for.
        step: usize,
        /// The last step.
        last: usize,
    },
    /// Undo on the flat sheet.
    #[error("nothing to undo: the sheet is flat")]
    NothingToUndo,
    /// Too many faces (a cap against runaway scripts).
    #[error("the fold would make more than {0} faces")]
    TooManyFaces(usize),
}
