//! The tessellated surface: a triangle mesh whose edges know their role in the tuck structure
//! and their mountain/valley assignment.

use std::collections::HashMap;

use glam::DVec3;

use super::sectors::Sectors;
use super::vertex_penalty::{self, Fan};
use crate::pattern::Assignment;

/// What an edge of the tessellation is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EdgeRole {
    /// An edge of a (shrunk) input face, between the face and a tuck triangle.
    FaceRim,
    /// A diagonal added to triangulate a polygon input face.
    Diagonal,
    /// The zero-area digon of an input edge, collapsed to one crease between two tucks.
    Digon,
    /// A tuck crease from the key vertex to a star tip (a corner of a neighbouring face).
    KeyTip,
    /// A tuck crease from the key vertex to a corner of a face around the tuck's vertex.
    KeyCorner,
    /// An edge of the flat n-gon of a truncated star or twist fold (Tachi 2014, §2.2).
    TruncationRim,
    /// A fold added to a star triangle by the twist (§2.2), from the twist vertex to a face
    /// corner.
    TwistFold,
    /// An edge on the sheet boundary.
    Boundary,
}

/// One undirected edge of the triangle mesh.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TessEdge {
    /// End vertices `[i, j]`, oriented as in its first triangle `p = (i, j, a)`.
    pub vertices: [u32; 2],
    /// `p` (containing `i → j`) and, for an interior edge, `q` (containing `j → i`).
    pub triangles: [u32; 2],
    /// Whether `q` exists.
    pub interior: bool,
    /// Its role.
    pub role: EdgeRole,
    /// Mountain, valley, flat (diagonals) or boundary.
    pub assignment: Assignment,
}

/// A triangle mesh of the tessellated surface, in the input mesh's units (millimetres).
#[derive(Clone, Debug)]
pub struct TessMesh {
    /// Vertex positions.
    pub positions: Vec<DVec3>,
    /// Triangles, counter-clockwise about the front normal.
    pub triangles: Vec<[u32; 3]>,
    /// Undirected edges.
    pub edges: Vec<TessEdge>,
    /// Whether each vertex is interior (closed fan), i.e. carries a developability condition.
    pub interior: Vec<bool>,
    /// For every vertex of the input mesh, the key vertex of its tuck (if it has one).
    pub key_of_input: Vec<Option<u32>>,
    /// For every tessellation vertex, the input vertex it comes from (a face corner or a
    /// vertex of its tuck).
    pub input_vertex: Vec<u32>,
    /// Vertices `0..corner_count` are corners of the (shrunk) input faces; the rest belong
    /// to the tucks.
    pub corner_count: usize,
    /// The corners grouped into the angles between neighbouring creases (topology only).
    pub sectors: Sectors,
    /// The ordered fans checked by the vertex-adjacent penalty, eq. 5–7 (topology only).
    pub fans: Vec<Fan>,
}

impl TessMesh {
    /// Builds edges and interior flags from triangles. `role` names each directed edge
    /// `(a, b)` of a triangle; the first triangle that lists an edge decides its role.
    pub(crate) fn from_triangles(
        positions: Vec<DVec3>,
        triangles: Vec<[u32; 3]>,
        roles: &HashMap<(u32, u32), EdgeRole>,
        key_of_input: Vec<Option<u32>>,
        input_vertex: Vec<u32>,
        corner_count: usize,
    ) -> Self {
        let mut index: HashMap<(u32, u32), usize> = HashMap::new();
        let mut edges: Vec<TessEdge> = Vec::new();
        for (t, tri) in triangles.iter().enumerate() {
            for k in 0..3 {
                let (a, b) = (tri[k], tri[(k + 1) % 3]);
                if let Some(&e) = index.get(&(b, a)) {
                    edges[e].triangles[1] = t as u32;
                    edges[e].interior = true;
                    continue;
                }
                let role = roles.get(&(a, b)).or(roles.get(&(b, a)));
                index.insert((a, b), edges.len());
                edges.push(TessEdge {
                    vertices: [a, b],
                    triangles: [t as u32, u32::MAX],
                    interior: false,
                    role: role.copied().unwrap_or(EdgeRole::FaceRim),
                    assignment: Assignment::Unassigned,
                });
            }
        }
        let mut interior = vec![true; positions.len()];
        for e in edges.iter_mut().filter(|e| !e.interior) {
            e.role = EdgeRole::Boundary;
            e.assignment = Assignment::Boundary;
            interior[e.vertices[0] as usize] = false;
            interior[e.vertices[1] as usize] = false;
        }
        let sectors = Sectors::new(&triangles, &edges);
        let fans = vertex_penalty::fans(&triangles, &interior);
        TessMesh {
            positions,
            triangles,
            edges,
            interior,
            key_of_input,
            input_vertex,
            corner_count,
            sectors,
            fans,
        }
    }

    /// The third vertex of triangle `t` (the one not on edge `{i, j}`).
    pub fn apex(&self, t: u32, i: u32, j: u32) -> u32 {
        let tri = self.triangles[t as usize];
        tri.into_iter()
            .find(|&v| v != i && v != j)
            .unwrap_or(tri[0])
    }

    /// For an interior edge: `[i, j, a, b]` with `p = (i, j, a)` and `q = (j, i, b)`.
    pub fn hinge(&self, e: &TessEdge) -> [u32; 4] {
        let [i, j] = e.vertices;
        [
            i,
            j,
            self.apex(e.triangles[0], i, j),
            self.apex(e.triangles[1], i, j),
        ]
    }

    /// Number of interior vertices.
    pub fn interior_count(&self) -> usize {
        self.interior.iter().filter(|&&b| b).count()
    }
}
