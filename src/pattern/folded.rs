//! The folded state: a crease pattern's topology with 3D vertex positions.

use glam::DVec3;

use super::{Edge, Face, FaceId};

/// A 3D configuration of a sheet (a FOLD frame of class `foldedForm`): positions in the same
/// length unit as the pattern it folds. Read from FOLD, edges and faces are indexed like that
/// pattern's; a design module may instead split vertices along cuts (one copy per 3D
/// position) and say how copies map back (e.g. the voxel pop-up card's `FoldedCard::source`).
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
