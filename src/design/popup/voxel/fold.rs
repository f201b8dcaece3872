//! Folding a voxel card: each pattern face stands on the plane of the unit cell under it, and
//! the card opens by eq. 6 of Mitani, Suzuki & Uno (2003), shared with polygon cards in
//! [`crate::design::popup::opening`] (which also splits vertices on cuts).

use glam::{DVec2, DVec3};

use super::VoxelCard;
use super::surface::{Plane, Surface};
pub use crate::design::popup::opening::{FoldedCard, open_transform};
use crate::design::popup::opening::{Standing, fold_faces};
use crate::pattern::{CreasePattern, Face};

/// Folds `cp` (the pattern of `card`, with faces, as [`super::crease_pattern`] makes it) to
/// the opening angle `opening_deg` (see [`open_transform`]). Faces the pattern does not list
/// are left out. Fold edges carry the angle they are folded by at this opening
/// (±(180° − opening)).
pub fn fold_card(card: &VoxelCard, cp: &CreasePattern, opening_deg: f64) -> FoldedCard {
    let surface = Surface::new(card);
    let s = card.cell_mm();
    let planes = cp
        .faces
        .iter()
        .flatten()
        .map(|face| face_plane(card, &surface, cp, face));
    let standing = Standing {
        to_card: |plane: &Plane, p: DVec2| {
            let p = p / s;
            DVec3::from(plane.to_card(p.x, p.y))
        },
        unit_mm: s,
        keys_per_unit: 1e6,
    };
    fold_faces(cp, planes, &standing, opening_deg)
}

/// The plane of a pattern face: the plane of the unit cell just inside its first edge.
fn face_plane(card: &VoxelCard, surface: &Surface, cp: &CreasePattern, face: &Face) -> Plane {
    let (a, b) = (cp.position(face.outer[0]), cp.position(face.outer[1]));
    let d = (b - a).normalize_or_zero();
    let inside = (a + b) * 0.5 + DVec2::new(-d.y, d.x) * (0.25 * card.cell_mm());
    // Out-of-grid cells are margins; clamping keeps the casts in range.
    let x = (inside.x / card.cell_mm())
        .floor()
        .clamp(-1.0, surface.nx as f64);
    let r = (inside.y / card.cell_mm() + card.ny() as f64).floor();
    let r = r.clamp(-1.0, surface.rows as f64);
    surface.plane(x as i64, r as i64)
}
