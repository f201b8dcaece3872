//! A half-edge view of a [`super::PolyMesh`]: twins, vertex fans and the boundary,
//! for designers that walk a surface (tessellations, paper craft).
//!
//! [`HalfEdgeMesh::new`] accepts an oriented 2-manifold, with or without boundary, and refuses
//! with a [`HalfEdgeError`] naming the element: a face that repeats a corner or has zero area,
//! an edge used by more than two faces or twice in the same direction (inconsistent winding),
//! a vertex whose faces form more than one fan ("bow-tie"), a vertex used by no face is
//! ignored (it simply has no half-edges).
//!
//! Half-edge `h` of face `f` runs from corner `k` to corner `k + 1` of that face; its twin runs
//! the other way in the neighbouring face (none on the boundary).

use std::collections::HashMap;

use glam::DVec3;
use thiserror::Error;

use super::PolyMesh;

/// Why a mesh is not an oriented manifold.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum HalfEdgeError {
    /// A face visits the same vertex twice.
    #[error("face {face} uses vertex {vertex} twice")]
    RepeatedCorner {
        /// Face index (0-based).
        face: usize,
        /// The repeated vertex.
        vertex: usize,
    },
    /// A face has (nearly) zero area.
    #[error("face {face} is degenerate (zero area)")]
    ZeroArea {
        /// Face index (0-based).
        face: usize,
    },
    /// An edge is shared by more than two faces, or two faces run along it the same way.
    #[error(
        "edge {a}-{b} is non-manifold or its faces are inconsistently oriented \
         (two faces run along it from {a} to {b})"
    )]
    NonManifoldEdge {
        /// Start vertex (0-based).
        a: usize,
        /// End vertex (0-based).
        b: usize,
    },
    /// The faces around a vertex do not form one fan.
    #[error("vertex {vertex} is non-manifold (its faces form {fans} separate fans)")]
    NonManifoldVertex {
        /// Vertex index (0-based).
        vertex: usize,
        /// How many fans were found.
        fans: usize,
    },
}

/// One directed edge of a face.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HalfEdge {
    /// Start vertex.
    pub from: u32,
    /// End vertex.
    pub to: u32,
    /// The face it bounds (on its left).
    pub face: u32,
    /// The opposite half-edge, `None` on the boundary.
    pub twin: Option<u32>,
    /// The next half-edge of the same face.
    pub next: u32,
    /// The previous half-edge of the same face.
    pub prev: u32,
}

/// An oriented manifold polygon mesh with half-edge adjacency.
#[derive(Clone, Debug)]
pub struct HalfEdgeMesh {
    positions: Vec<DVec3>,
    faces: Vec<Vec<u32>>,
    half_edges: Vec<HalfEdge>,
    /// First half-edge of each face.
    face_start: Vec<u32>,
    /// Outgoing half-edges of each vertex, counter-clockwise about the face normals.
    fans: Vec<Vec<u32>>,
    boundary: Vec<bool>,
}

impl HalfEdgeMesh {
    /// Builds the adjacency, refusing non-manifold or degenerate input (see [`HalfEdgeError`]).
    /// `area_tolerance` is the smallest accepted face area, in squared mesh units.
    pub fn new(mesh: &PolyMesh, area_tolerance: f64) -> Result<Self, HalfEdgeError> {
        let positions = mesh.positions().to_vec();
        let faces = mesh.faces().to_vec();
        let mut half_edges = Vec::new();
        let mut face_start = Vec::with_capacity(faces.len());
        let mut by_ends: HashMap<(u32, u32), u32> = HashMap::new();
        for (fi, f) in faces.iter().enumerate() {
            check_face(&positions, fi, f, area_tolerance)?;
            let start = half_edges.len() as u32;
            face_start.push(start);
            let n = f.len() as u32;
            for k in 0..n {
                let (from, to) = (f[k as usize], f[((k + 1) % n) as usize]);
                let id = start + k;
                if by_ends.insert((from, to), id).is_some() {
                    return Err(non_manifold_edge(from, to));
                }
                half_edges.push(HalfEdge {
                    from,
                    to,
                    face: fi as u32,
                    twin: None,
                    next: start + (k + 1) % n,
                    prev: start + (k + n - 1) % n,
                });
            }
        }
        for h in &mut half_edges {
            h.twin = by_ends.get(&(h.to, h.from)).copied();
        }
        let (fans, boundary) = vertex_fans(positions.len(), &half_edges)?;
        Ok(HalfEdgeMesh {
            positions,
            faces,
            half_edges,
            face_start,
            fans,
            boundary,
        })
    }

    /// Vertex positions.
    pub fn positions(&self) -> &[DVec3] {
        &self.positions
    }

    /// Faces as corner cycles.
    pub fn faces(&self) -> &[Vec<u32>] {
        &self.faces
    }

    /// All half-edges.
    pub fn half_edges(&self) -> &[HalfEdge] {
        &self.half_edges
    }

    /// The half-edges of face `f`, in corner order.
    pub fn face_half_edges(&self, f: usize) -> std::ops::Range<u32> {
        let s = self.face_start[f];
        s..s + self.faces[f].len() as u32
    }

    /// Outgoing half-edges of vertex `v`, counter-clockwise about the normals; on the
    /// boundary the fan starts at the boundary half-edge leaving `v`.
    pub fn fan(&self, v: usize) -> &[u32] {
        &self.fans[v]
    }

    /// Whether `v` lies on the boundary (or is used by no face).
    pub fn is_boundary(&self, v: usize) -> bool {
        self.boundary[v]
    }

    /// Area-weighted unit normal of vertex `v` (zero for an unused vertex).
    pub fn vertex_normal(&self, v: usize) -> DVec3 {
        self.fans[v]
            .iter()
            .map(|&h| {
                let e = self.half_edges[h as usize];
                let p = self.half_edges[e.prev as usize].from;
                let o = self.positions[v];
                (self.positions[e.to as usize] - o).cross(self.positions[p as usize] - o)
            })
            .sum::<DVec3>()
            .normalize_or_zero()
    }

    /// Centroid of face `f` (mean of its corners).
    pub fn face_centroid(&self, f: usize) -> DVec3 {
        let c = &self.faces[f];
        c.iter().map(|&v| self.positions[v as usize]).sum::<DVec3>() / c.len() as f64
    }
}

fn non_manifold_edge(a: u32, b: u32) -> HalfEdgeError {
    HalfEdgeError::NonManifoldEdge {
        a: a as usize,
        b: b as usize,
    }
}

fn check_face(
    positions: &[DVec3],
    face: usize,
    f: &[u32],
    area_tolerance: f64,
) -> Result<(), HalfEdgeError> {
    let mut seen = f.to_vec();
    seen.sort_unstable();
    if let Some(w) = seen.windows(2).find(|w| w[0] == w[1]) {
        return Err(HalfEdgeError::RepeatedCorner {
            face,
            vertex: w[0] as usize,
        });
    }
    let n = f.len();
    let newell: DVec3 = (0..n)
        .map(|k| positions[f[k] as usize].cross(positions[f[(k + 1) % n] as usize]))
        .sum();
    if 0.5 * newell.length() <= area_tolerance {
        return Err(HalfEdgeError::ZeroArea { face });
    }
    Ok(())
}

/// Orders every vertex's outgoing half-edges counter-clockwise (turning from `h` to the twin
/// of its face's previous half-edge) and marks boundary vertices.
fn vertex_fans(
    count: usize,
    half_edges: &[HalfEdge],
) -> Result<(Vec<Vec<u32>>, Vec<bool>), HalfEdgeError> {
    let mut outgoing = vec![Vec::new(); count];
    for (i, h) in half_edges.iter().enumerate() {
        outgoing[h.from as usize].push(i as u32);
    }
    let mut fans = Vec::with_capacity(count);
    let mut boundary = vec![true; count];
    for (v, out) in outgoing.into_iter().enumerate() {
        if out.is_empty() {
            fans.push(out);
            continue;
        }
        // Start at a half-edge with no clockwise neighbour (its twin is missing) if any.
        let start = out
            .iter()
            .copied()
            .find(|&h| half_edges[h as usize].twin.is_none())
            .unwrap_or(out[0]);
        let mut fan = vec![start];
        let mut h = start;
        loop {
            let prev = half_edges[half_edges[h as usize].prev as usize];
            match prev.twin {
                Some(t) if t == start => {
                    boundary[v] = false;
                    break;
                }
                Some(t) => {
                    if fan.len() > out.len() {
                        break;
                    }
                    fan.push(t);
                    h = t;
                }
                None => break,
            }
        }
        if fan.len() != out.len() {
            let open_ends = out
                .iter()
                .filter(|&&h| {
                    half_edges[half_edges[h as usize].prev as usize]
                        .twin
                        .is_none()
                })
                .count();
            return Err(HalfEdgeError::NonManifoldVertex {
                vertex: v,
                fans: open_ends.max(2),
            });
        }
        fans.push(fan);
    }
    Ok((fans, boundary))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid() -> PolyMesh {
        // 3 x 3 vertices, 4 quads.
        let mut p = Vec::new();
        for j in 0..3 {
            for i in 0..3 {
                p.push(DVec3::new(i as f64, j as f64, 0.0));
            }
        }
        let q = |i: u32, j: u32| vec![j * 3 + i, j * 3 + i + 1, j * 3 + i + 4, j * 3 + i + 3];
        PolyMesh::new(p, vec![q(0, 0), q(1, 0), q(0, 1), q(1, 1)]).unwrap()
    }

    #[test]
    fn grid_centre_is_interior_with_a_ccw_fan() {
        let m = HalfEdgeMesh::new(&grid(), 1e-12).unwrap();
        assert!(!m.is_boundary(4));
        assert!(m.is_boundary(0) && m.is_boundary(1));
        let ends: Vec<u32> = m
            .fan(4)
            .iter()
            .map(|&h| m.half_edges()[h as usize].to)
            .collect();
        assert_eq!(ends.len(), 4);
        // Counter-clockwise about +z: each next end is the previous one turned by +90°.
        for k in 0..4 {
            let a = m.positions()[ends[k] as usize] - m.positions()[4];
            let b = m.positions()[ends[(k + 1) % 4] as usize] - m.positions()[4];
            assert!(a.cross(b).z > 0.0, "{ends:?}");
        }
        assert!((m.vertex_normal(4) - DVec3::Z).length() < 1e-12);
    }

    #[test]
    fn bad_meshes_are_named() {
        let p = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::new(1.0, 1.0, 0.0)];
        let flipped = PolyMesh::new(p.clone(), vec![vec![0, 1, 2], vec![1, 2, 3]]).unwrap();
        assert!(matches!(
            HalfEdgeMesh::new(&flipped, 1e-12),
            Err(HalfEdgeError::NonManifoldEdge { a: 1, b: 2 })
        ));
        let flat = PolyMesh::new(p.clone(), vec![vec![0, 1, 1]]).unwrap();
        assert!(matches!(
            HalfEdgeMesh::new(&flat, 1e-12),
            Err(HalfEdgeError::RepeatedCorner { .. })
        ));
        let line = PolyMesh::new(
            vec![DVec3::ZERO, DVec3::X, 2.0 * DVec3::X],
            vec![vec![0, 1, 2]],
        );
        assert!(matches!(
            HalfEdgeMesh::new(&line.unwrap(), 1e-12),
            Err(HalfEdgeError::ZeroArea { face: 0 })
        ));
        let mut q = p;
        q.extend([DVec3::new(-1.0, 0.0, 0.0), DVec3::new(0.0, -1.0, 0.0)]);
        let bowtie = PolyMesh::new(q, vec![vec![0, 1, 3], vec![0, 4, 5]]).unwrap();
        assert!(matches!(
            HalfEdgeMesh::new(&bowtie, 1e-12),
            Err(HalfEdgeError::NonManifoldVertex { vertex: 0, .. })
        ));
    }
}
