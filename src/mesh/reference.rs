//! A triangulated mesh with closest-point projection and the surface normal there: the
//! reference mesh of Ōgaki (2016) (§3.1), the shape paper craft's user traces cut lines and
//! directrices on, and the surface a tessellation's distance to its input is measured on.
//!
//! Faces are split into fan triangles; a [`TriangleGrid`] finds candidates near the query.
//! The normal at a projected point interpolates area-weighted vertex normals with the point's
//! barycentric coordinates (smooth across edges); the thesis only says "the normal of the
//! closest mesh point", so this smoothing is our choice. Normals follow the file's winding
//! (counter-clockwise seen from outside gives outward normals).

use glam::DVec3;

use super::triangle_grid::TriangleGrid;
use super::{MeshError, PolyMesh};
use crate::geom::tolerance::ROUNDOFF_SQUARED;

/// The closest point of the reference mesh to a query point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Projection {
    /// The closest point on the mesh (mesh units).
    pub point: DVec3,
    /// Unit normal there (interpolated vertex normals).
    pub normal: DVec3,
    /// Index of the fan triangle holding the point.
    pub triangle: usize,
    /// Distance from the query to `point`.
    pub distance: f64,
}

/// A triangulated reference mesh with a search grid.
#[derive(Clone, Debug)]
pub struct ReferenceMesh {
    positions: Vec<DVec3>,
    triangles: Vec<[u32; 3]>,
    vertex_normals: Vec<DVec3>,
    grid: TriangleGrid,
}

impl ReferenceMesh {
    /// Triangulates `mesh` (fans), drops zero-area triangles and builds the search grid.
    /// Refuses a mesh with no triangle of positive area ([`MeshError::Degenerate`]).
    pub fn new(mesh: &PolyMesh) -> Result<Self, MeshError> {
        let positions = mesh.positions().to_vec();
        let scale = {
            let (lo, hi) = mesh.bounds();
            (hi - lo).length()
        };
        let triangles: Vec<[u32; 3]> = mesh
            .faces()
            .iter()
            .flat_map(|f| (1..f.len() - 1).map(move |k| [f[0], f[k], f[k + 1]]))
            .filter(|t| tri_cross(&positions, t).length() > ROUNDOFF_SQUARED * scale * scale)
            .collect();
        if triangles.is_empty() {
            return Err(MeshError::Degenerate);
        }
        let mut vertex_normals = vec![DVec3::ZERO; positions.len()];
        for t in &triangles {
            let n = tri_cross(&positions, t);
            t.iter().for_each(|&v| vertex_normals[v as usize] += n);
        }
        vertex_normals
            .iter_mut()
            .for_each(|n| *n = n.normalize_or_zero());
        let boxes: Vec<(DVec3, DVec3)> = triangles
            .iter()
            .map(|t| {
                let [a, b, c] = corners(&positions, t);
                (a.min(b).min(c), a.max(b).max(c))
            })
            .collect();
        let grid = TriangleGrid::new(boxes);
        Ok(ReferenceMesh {
            positions,
            triangles,
            vertex_normals,
            grid,
        })
    }

    /// Number of (non-degenerate) fan triangles.
    pub fn triangle_count(&self) -> usize {
        self.triangles.len()
    }

    /// Corners of fan triangle `t`.
    pub fn triangle(&self, t: usize) -> [DVec3; 3] {
        corners(&self.positions, &self.triangles[t])
    }

    /// The closest point of the mesh to `p` and the normal there. `p` must be finite.
    pub fn project(&self, p: DVec3) -> Projection {
        let mut best = (f64::INFINITY, 0usize, DVec3::ZERO, [1.0, 0.0, 0.0]);
        self.grid.nearest(p, |t| {
            let (q, bary) = closest_on_triangle(p, self.triangle(t as usize));
            let d = (q - p).length();
            if d < best.0 {
                best = (d, t as usize, q, bary);
            }
            d
        });
        let (distance, triangle, point, bary) = best;
        let t = &self.triangles[triangle];
        let blended: DVec3 = (0..3)
            .map(|i| bary[i] * self.vertex_normals[t[i] as usize])
            .sum();
        let normal = blended
            .try_normalize()
            .unwrap_or_else(|| tri_cross(&self.positions, t).normalize());
        Projection {
            point,
            normal,
            triangle,
            distance,
        }
    }
}

fn corners(positions: &[DVec3], t: &[u32; 3]) -> [DVec3; 3] {
    t.map(|v| positions[v as usize])
}

fn tri_cross(positions: &[DVec3], t: &[u32; 3]) -> DVec3 {
    let [a, b, c] = corners(positions, t);
    (b - a).cross(c - a)
}

/// Closest point of triangle `[a, b, c]` to `p` and its barycentric coordinates, by the
/// Voronoi regions of the corners, edges and face.
pub fn closest_on_triangle(p: DVec3, [a, b, c]: [DVec3; 3]) -> (DVec3, [f64; 3]) {
    let (ab, ac, ap) = (b - a, c - a, p - a);
    let (d1, d2) = (ab.dot(ap), ac.dot(ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return (a, [1.0, 0.0, 0.0]);
    }
    let bp = p - b;
    let (d3, d4) = (ab.dot(bp), ac.dot(bp));
    if d3 >= 0.0 && d4 <= d3 {
        return (b, [0.0, 1.0, 0.0]);
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        let v = d1 / (d1 - d3);
        return (a + v * ab, [1.0 - v, v, 0.0]);
    }
    let cp = p - c;
    let (d5, d6) = (ab.dot(cp), ac.dot(cp));
    if d6 >= 0.0 && d5 <= d6 {
        return (c, [0.0, 0.0, 1.0]);
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        let w = d2 / (d2 - d6);
        return (a + w * ac, [1.0 - w, 0.0, w]);
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        let w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return (b + w * (c - b), [0.0, 1.0 - w, w]);
    }
    let denom = 1.0 / (va + vb + vc);
    let (v, w) = (vb * denom, vc * denom);
    (a + ab * v + ac * w, [1.0 - v - w, v, w])
}
