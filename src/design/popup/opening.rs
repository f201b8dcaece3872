//! Opening and closing a pop-up card, shared by the voxel and the polygon models: eq. 6 of
//! Mitani, Suzuki & Uno (2003), which is eq. 7 of Mitani & Suzuki (2004).
//!
//! With θ the papers' parameter, a card point `(x, y, z)` moves to
//! `X = x, Y = y − z cos θ, Z = z sin θ`. θ = 90° is the card standing (identity), θ = 0° the
//! sheet opened flat (the pattern, with Y = −v), θ = 180° the card closed flat (back sheet on
//! the base). Every face of either model is vertical (spanned by x and z) or horizontal (x and
//! y), and the map keeps lengths along x, along y and along z, so it is an isometry of every
//! face.
//!
//! The functions here take the **opening angle** between the base and the back sheet,
//! `opening = 180° − θ`: 0° closed, 90° standing, 180° open flat.
//!
//! [`fold_faces`] builds the folded state of a card's crease pattern once each model has said
//! where a face's points stand: it splits pattern vertices that lie on cuts (a vertex gets one
//! 3D copy per distinct position of the faces around it; [`FoldedCard::source`] names the
//! pattern vertex of every copy), and joins copies by edges along the faces' boundaries that
//! keep the pattern edge's assignment and carry the fold angle of this opening.

use std::collections::{HashMap, HashSet};

use glam::{DVec2, DVec3};

use crate::pattern::{CreasePattern, Edge, Face, FoldedState, VertexId};

/// A folded card and where its vertices come from.
#[derive(Clone, Debug, PartialEq)]
pub struct FoldedCard {
    /// Positions in millimetres, x along the fold, z up (the base sheet stays in z = 0).
    pub state: FoldedState,
    /// The pattern vertex of every folded vertex.
    pub source: Vec<VertexId>,
}

/// The papers' transform at the opening angle `opening_deg` (clamped to 0..=180; NaN counts
/// as 90), for a card point in any unit.
pub fn open_transform(p: DVec3, opening_deg: f64) -> DVec3 {
    let theta = (180.0 - clamp_opening(opening_deg)).to_radians();
    DVec3::new(p.x, p.y - p.z * theta.cos(), p.z * theta.sin())
}

/// The opening angle clamped to 0..=180°, NaN read as 90°.
pub(crate) fn clamp_opening(opening_deg: f64) -> f64 {
    if opening_deg.is_nan() {
        90.0
    } else {
        opening_deg.clamp(0.0, 180.0)
    }
}

/// The folded card `state` (as the voxel and polygon `fold_card` make it, millimetres) as the
/// reader holds it, for pictures: reflected through the back sheet's plane, `(x, y, z) ↦ (x,
/// −y, z)`, with every face cycle reversed so that its Newell normal still points to the
/// paper's front side.
///
/// The papers' axes (Mitani, Suzuki & Uno 2003, eq. 6; Mitani & Suzuki 2004, eq. 7) put the
/// base in front of the back sheet at +y with z up, so a viewer in front of the card (at +y)
/// sees x run from right to left, while the pattern, the README and the cut sheet have x from
/// the card's left edge as seen from the front (the pattern's valleys fold towards the printed
/// side, which becomes the card's inside). The folded states are the mirror image of the card
/// in the reader's hands; this reflection gives the card itself, its front towards −y, the
/// front of the 3D previews' camera (`render::View3d`, azimuth 0), x from left to right. Lengths, edges and fold
/// angles are unchanged.
pub fn as_held(state: &FoldedState) -> FoldedState {
    let mut held = state.clone();
    for p in &mut held.positions {
        p.y = -p.y;
    }
    for face in held.faces.iter_mut().flatten() {
        face.outer.reverse();
        for hole in &mut face.holes {
            hole.reverse();
        }
    }
    held
}

/// How a model stands its pattern up: the card point (at 90°, in the model's unit) of every
/// pattern position on each face, and the sizes of that unit.
pub(crate) struct Standing<F> {
    /// The card point of a pattern position (mm) on the face with this plane.
    pub to_card: F,
    /// Millimetres per card unit (the folded positions are scaled by it).
    pub unit_mm: f64,
    /// Card points that agree after rounding to 1 / `keys_per_unit` of a unit are one copy.
    pub keys_per_unit: f64,
}

/// Folds the faces of `cp` to the opening angle `opening_deg`: face `k` of `cp.faces` stands
/// on `planes[k]` (faces beyond `planes` are left out), each of its vertices goes to
/// `standing.to_card(plane, position)`, then through [`open_transform`], then to millimetres.
/// Fold edges carry the angle they are folded by at this opening (±(180° − opening)).
pub(crate) fn fold_faces<P>(
    cp: &CreasePattern,
    planes: impl IntoIterator<Item = P>,
    standing: &Standing<impl Fn(&P, DVec2) -> DVec3>,
    opening_deg: f64,
) -> FoldedCard {
    let mut copies: HashMap<(VertexId, [i64; 3]), VertexId> = HashMap::new();
    let mut out = FoldedCard {
        state: FoldedState::default(),
        source: Vec::new(),
    };
    let mut faces = Vec::new();
    for (face, plane) in cp.faces.iter().flatten().zip(planes) {
        let mut place = |v: VertexId| {
            let q = (standing.to_card)(&plane, cp.position(v));
            let key = (
                v,
                (q * standing.keys_per_unit).round().as_i64vec3().to_array(),
            );
            *copies.entry(key).or_insert_with(|| {
                out.state
                    .positions
                    .push(open_transform(q, opening_deg) * standing.unit_mm);
                out.source.push(v);
                VertexId::new(out.source.len() - 1)
            })
        };
        let outer: Vec<VertexId> = face.outer.iter().map(|&v| place(v)).collect();
        let holes = face
            .holes
            .iter()
            .map(|h| h.iter().map(|&v| place(v)).collect())
            .collect();
        faces.push((face.clone(), Face { outer, holes }));
    }
    let theta = 180.0 - clamp_opening(opening_deg);
    out.state.edges = folded_edges(cp, &faces, theta);
    out.state.faces = Some(faces.into_iter().map(|(_, f)| f).collect());
    out
}

/// One folded edge per distinct pair of folded vertices along the faces' cycles, with the
/// pattern edge's assignment; folds carry the current fold angle `theta_deg` (the papers' θ:
/// every crease of the card turns by the same angle, valleys +θ, mountains −θ).
fn folded_edges(cp: &CreasePattern, faces: &[(Face, Face)], theta_deg: f64) -> Vec<Edge> {
    let mut pattern_edge = HashMap::new();
    for e in &cp.edges {
        let [a, b] = e.vertices;
        pattern_edge.insert((a.min(b), a.max(b)), e);
    }
    let mut seen = HashSet::new();
    let mut edges = Vec::new();
    for (src, dst) in faces {
        let cycles =
            std::iter::once((&src.outer, &dst.outer)).chain(src.holes.iter().zip(&dst.holes));
        for (sc, dc) in cycles {
            for i in 0..sc.len() {
                let j = (i + 1) % sc.len();
                let key = (dc[i].min(dc[j]), dc[i].max(dc[j]));
                let Some(e) = pattern_edge.get(&(sc[i].min(sc[j]), sc[i].max(sc[j]))) else {
                    continue;
                };
                if seen.insert(key) {
                    let mut edge = Edge::new(dc[i], dc[j], e.assignment);
                    edge.fold_angle = e.fold_angle.map(|a| a.signum() * theta_deg);
                    edges.push(edge);
                }
            }
        }
    }
    edges
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_transform_stands_at_90_and_lies_flat_at_0_and_180() {
        let p = DVec3::new(1.0, 2.0, 3.0);
        assert!((open_transform(p, 90.0) - p).length() < 1e-12);
        assert!((open_transform(p, f64::NAN) - p).length() < 1e-12);
        // Closed: the back sheet folds down onto the base, y grows by z.
        assert!((open_transform(p, 0.0) - DVec3::new(1.0, 5.0, 0.0)).length() < 1e-12);
        // Open flat: the pattern, y − z.
        assert!((open_transform(p, 180.0) - DVec3::new(1.0, -1.0, 0.0)).length() < 1e-12);
        assert_eq!(open_transform(p, 270.0), open_transform(p, 180.0));
    }
}
