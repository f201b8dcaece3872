//! The bar-and-hinge model of a crease pattern (Ghassaei, Demaine & Gershenfeld 2018, after
//! Schenk & Guest 2011 and Liu & Paulino 2017): every face triangulated, an axial bar on every
//! triangle side, a hinge on every side shared by two triangles.
//!
//! **Vertices.** The model has one vertex per pattern vertex (same index), plus a copy for
//! every extra side of a cut: around a vertex, the faces joined through non-cut edges share one
//! model vertex, and each further group separated by cut edges gets its own copy, so the two
//! sides of a cut move apart. [`BarHingeModel::source`] maps every model vertex back.
//!
//! **Hinges.** A side that is a pattern edge is a *crease hinge* when the edge folds (M, V, U)
//! and driven to `percent × target` ([`crease_target_deg`]: the edge's fold angle, or −180° for
//! a mountain and +180° for a valley without one; an unassigned edge without an angle hinges
//! freely); flat (F) and join (J) edges and the sides the triangulation adds inside a face are
//! *facet hinges* with target 0, which keep triangulated faces flat. Boundary and cut edges
//! have one triangle on each model side and no hinge.
//!
//! **Orientation.** A hinge's edge `[j, k]` runs along its first triangle counter-clockwise
//! (as seen from the sheet's front, +z), `wings[0]` is that triangle's third corner and
//! `wings[1]` the other triangle's. Its fold angle follows FOLD's sign: valley positive.

use std::collections::HashMap;

use glam::{DVec2, DVec3};

use crate::geom::DisjointSets;
use crate::geom::triangulate::{TriangulateError, triangulate_polygon};
use crate::pattern::{Assignment, CreasePattern, EdgeId, Face, FaceId, VertexId};

/// What a hinge does.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum HingeKind {
    /// A crease driven to `percent ×` this angle, radians (FOLD sign).
    Crease(f64),
    /// A crease without a target (unassigned, no angle): no stiffness.
    Free,
    /// Keeps two triangles coplanar (flat lines and triangulation sides): target 0.
    Facet,
}

/// A hinge between two triangles.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hinge {
    /// The shared side, counter-clockwise along the first triangle.
    pub edge: [u32; 2],
    /// The third corners of the first and the second triangle.
    pub wings: [u32; 2],
    /// Crease, free or facet.
    pub kind: HingeKind,
    /// The pattern edge on this side, if it is one.
    pub crease: Option<EdgeId>,
}

/// An axial bar (a triangle side) and its rest length.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bar {
    /// The two model vertices.
    pub ends: [u32; 2],
    /// Length in the flat sheet, in the pattern's unit.
    pub rest: f64,
}

/// The bar-and-hinge model of a crease pattern (see the module docs).
#[derive(Clone, Debug, PartialEq)]
pub struct BarHingeModel {
    /// Positions of the flat sheet (z = 0), one per model vertex.
    pub rest: Vec<DVec3>,
    /// The pattern vertex of each model vertex (the identity on the first pattern-many).
    pub source: Vec<VertexId>,
    /// Triangles, counter-clockwise seen from +z in the flat sheet.
    pub triangles: Vec<[u32; 3]>,
    /// The pattern face of each triangle.
    pub triangle_face: Vec<FaceId>,
    /// Axial bars.
    pub bars: Vec<Bar>,
    /// Hinges.
    pub hinges: Vec<Hinge>,
    /// The hinge on each pattern edge, where there is one.
    pub edge_hinge: Vec<Option<u32>>,
    /// The pattern's faces with corners renamed to model vertices.
    pub faces: Vec<Face>,
    /// The pattern's edges on model vertices: the first pattern-many in the pattern's order,
    /// then one copy for the second side of every cut that split its vertices.
    pub edges: Vec<crate::pattern::Edge>,
}

/// Why a pattern has no bar-and-hinge model.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ModelError {
    /// The pattern has no faces.
    #[error("the pattern has no faces: planarise it first (foldcam does so for files)")]
    NoFaces,
    /// A face could not be triangulated.
    #[error("face {face} could not be triangulated: {source}")]
    Triangulation {
        /// The face.
        face: FaceId,
        /// Why.
        source: TriangulateError,
    },
    /// A face names a vertex that does not exist.
    #[error("face {face} names vertex {vertex}, which does not exist")]
    BadFace {
        /// The face.
        face: FaceId,
        /// The vertex index.
        vertex: usize,
    },
    /// No face has area.
    #[error("no face of the pattern has an area to fold")]
    Empty,
}

/// The target fold angle of an edge at 100 %, degrees (FOLD sign), or `None` when the edge
/// does not fold toward a target: the edge's fold angle for M, V and U; −180° for a mountain
/// and +180° for a valley without one; `None` for an unassigned edge without one and for every
/// other assignment.
pub fn crease_target_deg(edge: &crate::pattern::Edge) -> Option<f64> {
    match edge.assignment {
        Assignment::Mountain => Some(edge.fold_angle.unwrap_or(-180.0)),
        Assignment::Valley => Some(edge.fold_angle.unwrap_or(180.0)),
        Assignment::Unassigned => edge.fold_angle,
        _ => None,
    }
}

fn pair(a: VertexId, b: VertexId) -> (u32, u32) {
    let (a, b) = (a.index() as u32, b.index() as u32);
    (a.min(b), a.max(b))
}

/// The cycles of a face: outer first, then holes.
fn cycles(face: &Face) -> impl Iterator<Item = &Vec<VertexId>> {
    std::iter::once(&face.outer).chain(&face.holes)
}

impl BarHingeModel {
    /// Builds the model of a validated pattern with faces (see the module docs).
    pub fn build(cp: &CreasePattern) -> Result<Self, ModelError> {
        let faces = cp.faces.as_deref().ok_or(ModelError::NoFaces)?;
        let n = cp.vertices.len();
        for (f, face) in faces.iter().enumerate() {
            if let Some(v) = cycles(face).flatten().find(|v| v.index() >= n) {
                return Err(ModelError::BadFace {
                    face: FaceId::new(f),
                    vertex: v.index(),
                });
            }
        }
        let edge_of: HashMap<(u32, u32), usize> = cp
            .edges
            .iter()
            .enumerate()
            .map(|(i, e)| (pair(e.vertices[0], e.vertices[1]), i))
            .collect();
        // Corners: one per (face, vertex).
        let mut corner_of: HashMap<(u32, u32), u32> = HashMap::new();
        let mut corner_vertex = Vec::new();
        let mut sides: HashMap<(u32, u32), Vec<u32>> = HashMap::new();
        for (f, face) in faces.iter().enumerate() {
            for ring in cycles(face) {
                for (k, &v) in ring.iter().enumerate() {
                    corner_of
                        .entry((f as u32, v.index() as u32))
                        .or_insert_with(|| {
                            corner_vertex.push(v);
                            (corner_vertex.len() - 1) as u32
                        });
                    let w = ring[(k + 1) % ring.len()];
                    if w != v {
                        sides.entry(pair(v, w)).or_default().push(f as u32);
                    }
                }
            }
        }
        let mut uf = DisjointSets::new(corner_vertex.len());
        let cut = |key: &(u32, u32)| {
            edge_of
                .get(key)
                .is_some_and(|&e| cp.edges[e].assignment == Assignment::Cut)
        };
        for (key, fs) in &sides {
            if cut(key) {
                continue;
            }
            for w in fs.windows(2) {
                for v in [key.0, key.1] {
                    uf.union(
                        corner_of[&(w[0], v)] as usize,
                        corner_of[&(w[1], v)] as usize,
                    );
                }
            }
        }
        // Model vertices: the first class of each pattern vertex keeps its index.
        let mut source: Vec<VertexId> = (0..n).map(VertexId::new).collect();
        let mut class_vertex: HashMap<u32, u32> = HashMap::new();
        let mut taken = vec![false; n];
        for c in 0..corner_vertex.len() as u32 {
            let root = uf.find(c as usize) as u32;
            if class_vertex.contains_key(&root) {
                continue;
            }
            let v = corner_vertex[root as usize];
            let id = if taken[v.index()] {
                source.push(v);
                (source.len() - 1) as u32
            } else {
                taken[v.index()] = true;
                v.index() as u32
            };
            class_vertex.insert(root, id);
        }
        let mut model_of = |f: usize, v: VertexId| -> u32 {
            let c = corner_of[&(f as u32, v.index() as u32)];
            class_vertex[&(uf.find(c as usize) as u32)]
        };
        let rest: Vec<DVec3> = source
            .iter()
            .map(|v| cp.vertices[v.index()].extend(0.0))
            .collect();
        let mut triangles = Vec::new();
        let mut triangle_face = Vec::new();
        let mut model_faces = Vec::with_capacity(faces.len());
        for (f, face) in faces.iter().enumerate() {
            let ring_points = |r: &Vec<VertexId>| -> Vec<DVec2> {
                r.iter().map(|v| cp.vertices[v.index()]).collect()
            };
            let outer = ring_points(&face.outer);
            let holes: Vec<Vec<DVec2>> = face.holes.iter().map(ring_points).collect();
            let tris = triangulate_polygon(&outer, &holes).map_err(|source| {
                ModelError::Triangulation {
                    face: FaceId::new(f),
                    source,
                }
            })?;
            let flat: Vec<VertexId> = cycles(face).flatten().copied().collect();
            for t in tris {
                triangles.push(t.map(|i| model_of(f, flat[i])));
                triangle_face.push(FaceId::new(f));
            }
            let rename = |r: &Vec<VertexId>, m: &mut dyn FnMut(usize, VertexId) -> u32| {
                r.iter()
                    .map(|&v| VertexId::new(m(f, v) as usize))
                    .collect::<Vec<_>>()
            };
            model_faces.push(Face {
                outer: rename(&face.outer, &mut model_of),
                holes: face
                    .holes
                    .iter()
                    .map(|h| rename(h, &mut model_of))
                    .collect(),
            });
        }
        if triangles.is_empty() {
            return Err(ModelError::Empty);
        }
        let edges = model_edges(cp, &sides, &mut model_of);
        let (bars, hinges) = bars_and_hinges(cp, &rest, &source, &triangles, &edge_of);
        let mut edge_hinge = vec![None; cp.edges.len()];
        for (h, hinge) in hinges.iter().enumerate() {
            if let Some(e) = hinge.crease {
                edge_hinge[e.index()] = Some(h as u32);
            }
        }
        Ok(BarHingeModel {
            rest,
            source,
            triangles,
            triangle_face,
            bars,
            hinges,
            edge_hinge,
            faces: model_faces,
            edges,
        })
    }

    /// Number of model vertices.
    pub fn vertex_count(&self) -> usize {
        self.rest.len()
    }
}

/// The pattern's edges on model vertices (see [`BarHingeModel::edges`]).
fn model_edges(
    cp: &CreasePattern,
    sides: &HashMap<(u32, u32), Vec<u32>>,
    model_of: &mut impl FnMut(usize, VertexId) -> u32,
) -> Vec<crate::pattern::Edge> {
    let mut edges = cp.edges.clone();
    let mut extra = Vec::new();
    for (e, edge) in cp.edges.iter().enumerate() {
        let [a, b] = edge.vertices;
        let Some(fs) = sides.get(&pair(a, b)) else {
            continue;
        };
        let ends = |f: u32, m: &mut dyn FnMut(usize, VertexId) -> u32| {
            [a, b].map(|v| VertexId::new(m(f as usize, v) as usize))
        };
        edges[e].vertices = ends(fs[0], model_of);
        for &g in &fs[1..] {
            let other = ends(g, model_of);
            if other != edges[e].vertices {
                let mut copy = edge.clone();
                copy.vertices = other;
                extra.push(copy);
            }
        }
    }
    edges.extend(extra);
    edges
}

/// Bars on every triangle side, hinges on every side two triangles share.
fn bars_and_hinges(
    cp: &CreasePattern,
    rest: &[DVec3],
    source: &[VertexId],
    triangles: &[[u32; 3]],
    edge_of: &HashMap<(u32, u32), usize>,
) -> (Vec<Bar>, Vec<Hinge>) {
    // Side (model vertices, sorted) → (triangle, side index) for each triangle using it.
    let mut side_tris: HashMap<(u32, u32), Vec<(u32, usize)>> = HashMap::new();
    for (t, tri) in triangles.iter().enumerate() {
        for s in 0..3 {
            let (a, b) = (tri[s], tri[(s + 1) % 3]);
            side_tris
                .entry((a.min(b), a.max(b)))
                .or_default()
                .push((t as u32, s));
        }
    }
    let mut keys: Vec<(u32, u32)> = side_tris.keys().copied().collect();
    keys.sort_unstable();
    let mut bars = Vec::with_capacity(keys.len());
    let mut hinges = Vec::new();
    for key in keys {
        let (a, b) = key;
        bars.push(Bar {
            ends: [a, b],
            rest: rest[a as usize].distance(rest[b as usize]),
        });
        let uses = &side_tris[&key];
        if uses.len() != 2 {
            continue;
        }
        let (t0, s0) = uses[0];
        let (t1, s1) = uses[1];
        let tri0 = triangles[t0 as usize];
        let tri1 = triangles[t1 as usize];
        let crease = edge_of
            .get(&pair(source[a as usize], source[b as usize]))
            .map(|&e| EdgeId::new(e));
        let kind = match crease.map(|e| &cp.edges[e.index()]) {
            Some(edge) => match edge.assignment {
                Assignment::Mountain | Assignment::Valley | Assignment::Unassigned => {
                    crease_target_deg(edge)
                        .map_or(HingeKind::Free, |d| HingeKind::Crease(d.to_radians()))
                }
                _ => HingeKind::Facet,
            },
            None => HingeKind::Facet,
        };
        hinges.push(Hinge {
            edge: [tri0[s0], tri0[(s0 + 1) % 3]],
            wings: [tri0[(s0 + 2) % 3], tri1[(s1 + 2) % 3]],
            kind,
            crease,
        });
    }
    (bars, hinges)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pattern::{PlanarizeOptions, planarize};

    /// A 2 × 1 rectangle split by a valley at x = 1 into two unit squares.
    fn two_squares() -> CreasePattern {
        let mut cp = CreasePattern::new();
        let p = [(0., 0.), (1., 0.), (2., 0.), (2., 1.), (1., 1.), (0., 1.)]
            .map(|(x, y)| cp.add_vertex(DVec2::new(x, y)));
        for k in 0..6 {
            cp.add_edge(p[k], p[(k + 1) % 6], Assignment::Boundary);
        }
        cp.add_edge(p[1], p[4], Assignment::Valley);
        let opts = PlanarizeOptions {
            faces: true,
            ..PlanarizeOptions::default()
        };
        planarize(&mut cp, &opts).unwrap();
        cp
    }

    #[test]
    fn squares_become_four_triangles_with_one_crease_and_two_facet_hinges() {
        let cp = two_squares();
        let m = BarHingeModel::build(&cp).unwrap();
        assert_eq!(m.triangles.len(), 4);
        // Euler: 6 vertices, 4 triangles → 9 sides, 3 of them shared.
        assert_eq!(m.bars.len(), 9);
        assert_eq!(m.hinges.len(), 3);
        let creases: Vec<_> = m
            .hinges
            .iter()
            .filter(|h| matches!(h.kind, HingeKind::Crease(_)))
            .collect();
        assert_eq!(creases.len(), 1);
        assert_eq!(creases[0].kind, HingeKind::Crease(std::f64::consts::PI));
        assert_eq!(m.vertex_count(), cp.vertices.len());
        // Every triangle counter-clockwise in the flat sheet.
        for t in &m.triangles {
            let [a, b, c] = t.map(|v| m.rest[v as usize].truncate());
            assert!((b - a).perp_dot(c - a) > 0.0);
        }
    }

    #[test]
    fn targets_follow_assignments_and_angles() {
        let e = |a, angle| crate::pattern::Edge {
            vertices: [VertexId::new(0), VertexId::new(1)],
            assignment: a,
            fold_angle: angle,
        };
        assert_eq!(
            crease_target_deg(&e(Assignment::Mountain, None)),
            Some(-180.0)
        );
        assert_eq!(crease_target_deg(&e(Assignment::Valley, None)), Some(180.0));
        assert_eq!(
            crease_target_deg(&e(Assignment::Valley, Some(40.0))),
            Some(40.0)
        );
        assert_eq!(crease_target_deg(&e(Assignment::Unassigned, None)), None);
        assert_eq!(crease_target_deg(&e(Assignment::Flat, Some(10.0))), None);
        assert_eq!(crease_target_deg(&e(Assignment::Boundary, None)), None);
    }
}
