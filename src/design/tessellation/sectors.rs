//! Sectors: the angles between neighbouring creases at a vertex, which the Tachi (2014) §5 vertex-angle
//! limit bounds. A triangle corner is a sector of its own unless an edge beside it is a flat
//! diagonal (a polygon face or a truncated star's n-gon fanned into triangles): corners on
//! either side of a flat diagonal at the same vertex form one sector, whose angle is their sum.

use glam::DVec3;

use super::geometry::corner_angle;
use super::model::{EdgeRole, TessEdge, TessMesh};

/// Sector id of every triangle corner `3·t + k` (corner `k` of triangle `t`); ids index
/// [`Sectors::count`] sectors.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Sectors {
    /// Sector of each corner.
    pub of_corner: Vec<u32>,
    /// Number of sectors.
    pub count: usize,
}

impl Sectors {
    /// Groups the corners of `triangles` across the flat diagonals among `edges`.
    pub fn new(triangles: &[[u32; 3]], edges: &[TessEdge]) -> Self {
        let n = 3 * triangles.len();
        let mut parent: Vec<u32> = (0..n as u32).collect();
        let corner = |t: u32, v: u32| -> usize {
            let tri = triangles[t as usize];
            3 * t as usize + tri.iter().position(|&w| w == v).unwrap_or(0)
        };
        for e in edges
            .iter()
            .filter(|e| e.interior && e.role == EdgeRole::Diagonal)
        {
            let [p, q] = e.triangles;
            for v in e.vertices {
                let (a, b) = (
                    find(&mut parent, corner(p, v)),
                    find(&mut parent, corner(q, v)),
                );
                parent[a] = b as u32;
            }
        }
        let mut id = vec![u32::MAX; n];
        let mut count = 0;
        let of_corner = (0..n)
            .map(|c| {
                let r = find(&mut parent, c);
                if id[r] == u32::MAX {
                    id[r] = count as u32;
                    count += 1;
                }
                id[r]
            })
            .collect();
        Sectors { of_corner, count }
    }

    /// The angle of every sector at `x`, radians.
    pub fn angles(&self, mesh: &TessMesh, x: &[DVec3]) -> Vec<f64> {
        let mut out = vec![0.0; self.count];
        for (t, tri) in mesh.triangles.iter().enumerate() {
            for k in 0..3 {
                let [o, a, b] = [tri[k], tri[(k + 1) % 3], tri[(k + 2) % 3]].map(|v| x[v as usize]);
                out[self.of_corner[3 * t + k] as usize] += corner_angle(o, a, b).value;
            }
        }
        out
    }
}

fn find(parent: &mut [u32], mut x: usize) -> usize {
    while parent[x] as usize != x {
        parent[x] = parent[parent[x] as usize];
        x = parent[x] as usize;
    }
    x
}
