//! Polygon meshes read from OBJ and STL: the input of the mesh-driven designers (voxel pop-ups
//! from buildings, tessellations over a surface, paper craft over a reference shape).
//!
//! [`PolyMesh`] keeps faces as the file gives them (triangles, quads, n-gons) over shared
//! positions, in the file's own units and axes; each designer decides how to place it.
//! [`read_mesh`] picks the reader from the extension, [`parse_obj`] and [`parse_stl`] read
//! bytes, and every reader validates with [`PolyMesh::new`]: no empty mesh, no non-finite
//! coordinate, no face with fewer than three corners or an index out of range.
//! [`PolyMesh::to_obj`] writes the mesh back (the examples' meshes are made that way).
//! [`ReferenceMesh`] triangulates a mesh for closest-point queries ([`ReferenceMesh::project`]:
//! the closest point and the normal there, found through a uniform grid over the triangles'
//! boxes), used by paper craft (Ōgaki 2016, §3.1) and by the tessellation's distance to its
//! input surface.
//!
//! ```
//! use foldcam::mesh::parse_obj;
//!
//! let square = parse_obj(b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n")?;
//! assert_eq!(square.faces().len(), 1);
//! assert_eq!(square.triangles().count(), 2);
//! assert!((square.area() - 1.0).abs() < 1e-12);
//! # Ok::<(), foldcam::mesh::MeshError>(())
//! ```

pub(crate) mod half_edge;
mod read;
pub(crate) mod reference;
mod triangle_grid;

pub use half_edge::{HalfEdgeError, HalfEdgeMesh};
pub use read::{parse_obj, parse_stl, read_mesh};
pub use reference::{Projection, ReferenceMesh, closest_on_triangle};

use glam::DVec3;
use thiserror::Error;

/// Why a mesh cannot be used.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum MeshError {
    /// The file could not be read.
    #[error("cannot read: {0}")]
    Io(String),
    /// The file is not a mesh this reader understands.
    #[error("not a valid {format} file: {message}")]
    Syntax {
        /// "OBJ" or "STL".
        format: &'static str,
        /// The parser's message.
        message: String,
    },
    /// The extension names no mesh format.
    #[error("unknown mesh format (use .obj or .stl)")]
    UnknownFormat,
    /// The mesh has no faces.
    #[error("the mesh has no faces")]
    Empty,
    /// A coordinate is NaN or infinite.
    #[error("vertex {vertex} has a non-finite coordinate")]
    NonFinite {
        /// Vertex index (0-based).
        vertex: usize,
    },
    /// A face has fewer than three corners.
    #[error("face {face} has {corners} corners (at least 3 needed)")]
    ShortFace {
        /// Face index (0-based).
        face: usize,
        /// Its corner count.
        corners: usize,
    },
    /// A face names a vertex that does not exist.
    #[error("face {face} uses vertex {vertex}, but the mesh has {count} vertices")]
    BadIndex {
        /// Face index (0-based).
        face: usize,
        /// The index used (0-based).
        vertex: usize,
        /// Number of vertices.
        count: usize,
    },
    /// No triangle of the mesh has positive area (a [`ReferenceMesh`] needs one).
    #[error("the reference mesh has no triangle of positive area")]
    Degenerate,
}

/// A polygon mesh: positions and faces given as corner cycles (indices into the positions).
/// Faces keep the file's winding; no orientation or manifold property is assumed.
#[derive(Clone, Debug, PartialEq)]
pub struct PolyMesh {
    positions: Vec<DVec3>,
    faces: Vec<Vec<u32>>,
}

impl PolyMesh {
    /// A validated mesh (see [`MeshError`] for what is refused).
    pub fn new(positions: Vec<DVec3>, faces: Vec<Vec<u32>>) -> Result<Self, MeshError> {
        if faces.is_empty() {
            return Err(MeshError::Empty);
        }
        if let Some(vertex) = positions.iter().position(|p| !p.is_finite()) {
            return Err(MeshError::NonFinite { vertex });
        }
        for (face, corners) in faces.iter().enumerate() {
            if corners.len() < 3 {
                return Err(MeshError::ShortFace {
                    face,
                    corners: corners.len(),
                });
            }
            if let Some(&v) = corners.iter().find(|&&v| v as usize >= positions.len()) {
                return Err(MeshError::BadIndex {
                    face,
                    vertex: v as usize,
                    count: positions.len(),
                });
            }
        }
        Ok(PolyMesh { positions, faces })
    }

    /// Vertex positions, in the file's units.
    pub fn positions(&self) -> &[DVec3] {
        &self.positions
    }

    /// Faces as corner cycles.
    pub fn faces(&self) -> &[Vec<u32>] {
        &self.faces
    }

    /// Fan triangles of every face, as position triples (a convex or star-shaped face from
    /// its first corner is split exactly; others are approximated).
    pub fn triangles(&self) -> impl Iterator<Item = [DVec3; 3]> + '_ {
        self.faces.iter().flat_map(move |f| {
            let p = |i: usize| self.positions[f[i] as usize];
            (1..f.len() - 1).map(move |k| [p(0), p(k), p(k + 1)])
        })
    }

    /// Axis-aligned bounds `(min, max)` of the vertices used by faces.
    pub fn bounds(&self) -> (DVec3, DVec3) {
        let mut lo = DVec3::splat(f64::INFINITY);
        let mut hi = DVec3::splat(f64::NEG_INFINITY);
        for &v in self.faces.iter().flatten() {
            let p = self.positions[v as usize];
            lo = lo.min(p);
            hi = hi.max(p);
        }
        (lo, hi)
    }

    /// Total surface area (sum of the fan triangles' areas).
    pub fn area(&self) -> f64 {
        self.triangles()
            .map(|[a, b, c]| 0.5 * (b - a).cross(c - a).length())
            .sum()
    }

    /// The mesh with every position mapped by `f` (same faces).
    pub fn map_positions(&self, f: impl Fn(DVec3) -> DVec3) -> Result<Self, MeshError> {
        PolyMesh::new(
            self.positions.iter().map(|&p| f(p)).collect(),
            self.faces.clone(),
        )
    }

    /// The mesh as OBJ text (`v` and `f` lines, 1-based indices, shortest round-trip numbers).
    pub fn to_obj(&self) -> String {
        use std::fmt::Write;
        let mut out = String::from("# written by foldcam\n");
        for p in &self.positions {
            let _ = writeln!(out, "v {} {} {}", p.x, p.y, p.z);
        }
        for f in &self.faces {
            out.push('f');
            for v in f {
                let _ = write!(out, " {}", v + 1);
            }
            out.push('\n');
        }
        out
    }
}
