//! Opening and closing the card: eq. 7 of Mitani & Suzuki (2004) as a
//! [`FoldedState`](crate::pattern::FoldedState).
//!
//! Each face of the crease pattern is placed on the plane of the card face under it (eq. 2,
//! 3), then moved by eq. 7 (`X = x, Y = y − z cos θ, Z = z sin θ`, shared with the voxel
//! card: [`open_transform`](crate::design::popup::opening::open_transform)). As for the voxel
//! card, the angle given is the **opening angle** between base and back sheet, `180° − θ`: 0°
//! closed, 90° standing, 180° flat.
//!
//! Pattern vertices on cuts are split: a vertex gets one 3D copy per distinct position of the
//! faces around it ([`FoldedCard::source`] maps copies back); the placement and the split are
//! [`crate::design::popup::opening`]'s, shared with voxel cards. Fold edges carry the angle
//! they are folded by at this opening, ±(180° − opening).

use glam::{DVec2, DVec3};

use super::model::{Plane, PolygonCard};
use crate::design::popup::opening::{FoldedCard, Standing, fold_faces};
use crate::geom::polygon::contains_point;
use crate::pattern::{CreasePattern, Face, VertexId};

/// Distances (mm) from a face's side at which a probe point looks up the face's plane, tried
/// from the largest: 10 µm first, down to 0.3 of the card's 0.1 µm grid step for thin slivers.
const PROBE_OFFSETS_MM: [f64; 4] = [1e-2, 1e-3, 1e-4, 3e-5];

/// A folded polygon card and where its vertices come from (the same type as a folded voxel
/// card).
pub type FoldedPolygonCard = FoldedCard;

/// The plane of every face of `cp` (the pattern of `card`): the plane of the card face that
/// holds a point just inside the pattern face. A face no card face holds (only possible for
/// slivers thinner than the sampling offsets) is put on the base plane.
pub fn face_planes(card: &PolygonCard, cp: &CreasePattern) -> Vec<Plane> {
    cp.faces
        .iter()
        .flatten()
        .map(|f| face_plane(card, cp, f).unwrap_or(Plane::BASE))
        .collect()
}

/// Whether a face of `cp` is paper the card means to keep: it lies on a face of `card` and
/// has an edge parallel to the fold. Every fold of a polygon card runs parallel to the
/// central fold (x), so a face without such an edge can never be held by a fold: the design
/// cuts it out (Mitani & Suzuki 2004's slanted outlines; a diamond opening's paper falls out by design).
pub fn holds_paper(card: &PolygonCard, cp: &CreasePattern, face: &Face) -> bool {
    let ring = &face.outer;
    let along_x = (0..ring.len()).any(|i| {
        let (a, b) = (
            cp.position(ring[i]),
            cp.position(ring[(i + 1) % ring.len()]),
        );
        (a.y - b.y).abs() <= super::crease::PATTERN_TOLERANCE_MM && a.x != b.x
    });
    along_x && face_plane(card, cp, face).is_some()
}

fn face_plane(card: &PolygonCard, cp: &CreasePattern, face: &Face) -> Option<Plane> {
    let ring = |c: &Vec<VertexId>| c.iter().map(|&v| cp.position(v)).collect::<Vec<DVec2>>();
    let outer = ring(&face.outer);
    let holes: Vec<Vec<DVec2>> = face.holes.iter().map(ring).collect();
    let inside =
        |q: DVec2| contains_point(&outer, q) && !holes.iter().any(|h| contains_point(h, q));
    for eps in PROBE_OFFSETS_MM {
        for i in 0..outer.len() {
            let (a, b) = (outer[i], outer[(i + 1) % outer.len()]);
            let d = (b - a).normalize_or_zero();
            let q = (a + b) * 0.5 + DVec2::new(-d.y, d.x) * eps;
            if inside(q)
                && let Some(k) = card.face_at(q)
            {
                return Some(card.faces()[k].plane);
            }
        }
    }
    None
}

/// Folds `cp` (the pattern of `card`, with faces, as [`super::crease_pattern`] makes it) to the
/// opening angle `opening_deg` (clamped to 0..=180; NaN counts as 90).
pub fn fold_card(card: &PolygonCard, cp: &CreasePattern, opening_deg: f64) -> FoldedPolygonCard {
    let standing = Standing {
        to_card: |plane: &Plane, p: DVec2| plane.to_card(p),
        unit_mm: 1.0,
        keys_per_unit: 1e5,
    };
    fold_faces(cp, face_planes(card, cp), &standing, opening_deg)
}

/// The card point at 90° of every pattern vertex seen from each face around it (tests and
/// comparisons): `(pattern vertex, card point)` per face corner.
pub fn standing_corners(card: &PolygonCard, cp: &CreasePattern) -> Vec<(VertexId, DVec3)> {
    let planes = face_planes(card, cp);
    cp.faces
        .iter()
        .flatten()
        .zip(planes)
        .flat_map(|(f, plane)| {
            let ring = f.outer.iter().chain(f.holes.iter().flatten());
            ring.map(move |&v| (v, plane.to_card(cp.position(v))))
                .collect::<Vec<_>>()
        })
        .collect()
}
