//! Opening and closing the card: eq. 6 of Mitani, Suzuki & Uno (2003) (eq. 7 of Mitani & Suzuki (2004)).
//!
//! With θ the paper's parameter, a card point `(x, y, z)` moves to
//! `X = x, Y = y − z cos θ, Z = z sin θ`. θ = 90° is the card standing (identity), θ = 0° the
//! sheet opened flat (the pattern, with Y = −v), θ = 180° the card closed flat (back sheet on the
//! base). Each face is vertical (spanned by x and z) or horizontal (x and y), and the map keeps
//! lengths along x, along y and along z, so it is an isometry of every face.
//!
//! This module takes the **opening angle** between the base and the back sheet,
//! `opening = 180° − θ`: 0° closed, 90° standing, 180° open flat.
//!
//! The folded state splits pattern vertices that lie on cuts: a vertex gets one 3D copy per
//! distinct position of the faces around it. [`FoldedCard::source`] names the pattern vertex of
//! every copy; edges join copies along the faces' boundaries and keep the pattern edge's
//! assignment and fold angle.

use std::collections::{HashMap, HashSet};

use glam::{DVec2, DVec3};

use super::VoxelCard;
use super::surface::{Plane, Surface};
use crate::pattern::{CreasePattern, Edge, Face, FoldedState, VertexId};

/// A folded voxel card and where its vertices come from.
#[derive(Clone, Debug, PartialEq)]
pub struct FoldedCard {
    /// Positions in millimetres, x along the fold, z up (the base sheet stays in z = 0).
    pub state: FoldedState,
    /// The pattern vertex of every folded vertex.
    pub source: Vec<VertexId>,
}

/// Eq. 6 at the opening angle `opening_deg` (clamped to 0..=180; NaN counts as 90).
pub fn open_transform(p: DVec3, opening_deg: f64) -> DVec3 {
    let theta = (180.0 - clamp_opening(opening_deg)).to_radians();
    DVec3::new(p.x, p.y - p.z * theta.cos(), p.z * theta.sin())
}

/// The opening angle clamped to 0..=180°, NaN read as 90°.
fn clamp_opening(opening_deg: f64) -> f64 {
    if opening_deg.is_nan() {
        90.0
    } else {
        opening_deg.clamp(0.0, 180.0)
    }
}

/// Folds `cp` (the pattern of `card`, with faces, as [`super::crease_pattern`] makes it) to
/// the opening angle `opening_deg`. Faces the pattern does not list are left out. Fold edges
/// carry the angle they are folded by at this opening (±(180° − opening)).
pub fn fold_card(card: &VoxelCard, cp: &CreasePattern, opening_deg: f64) -> FoldedCard {
    let surface = Surface::new(card);
    let s = card.cell_mm();
    let mut copies: HashMap<(VertexId, [i64; 3]), VertexId> = HashMap::new();
    let mut out = FoldedCard {
        state: FoldedState::default(),
        source: Vec::new(),
    };
    let mut faces = Vec::new();
    for face in cp.faces.iter().flatten() {
        let plane = face_plane(card, &surface, cp, face);
        let mut place = |v: VertexId| {
            let p = cp.position(v) / s;
            let q = DVec3::from(plane.to_card(p.x, p.y));
            let key = (v, (q * 1e6).round().as_i64vec3().to_array());
            *copies.entry(key).or_insert_with(|| {
                out.state.positions.push(open_transform(q, opening_deg) * s);
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

/// One folded edge per distinct pair of folded vertices along the faces' cycles, with the
/// pattern edge's assignment; folds carry the current fold angle `theta_deg` (eq. 6's θ:
/// every crease of the card turns by the same angle, valleys +θ, mountains −θ).
pub(crate) fn folded_edges(
    cp: &CreasePattern,
    faces: &[(Face, Face)],
    theta_deg: f64,
) -> Vec<Edge> {
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
