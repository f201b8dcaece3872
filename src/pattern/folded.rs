//! The folded state: a crease pattern's topology with 3D vertex positions.

use glam::DVec3;

use super::{Edge, Face, FaceId};

/// A 3D configuration of a sheet (a FOLD frame of class `foldedForm`): positions in the same
/// length unit as the pattern it folds, edges and faces indexed like that pattern's.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct FoldedState {
    /// 3D vertex positions.
    pub positions: Vec<DVec3>,
    /// Edges (same order and meaning as the crease pattern's).
    pub edges: Vec<Edge>,
    /// Faces, when known.
    pub faces: Option<Vec<Face>>,
    /// Face stacking order (`faceOrders`).
    pub face_orders: Vec<(FaceId, FaceId, i8)>,
}
