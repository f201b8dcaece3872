//! Sample surfaces for examples, tests and benchmarks: a hexagonal patch of equilateral
//! triangles (edge `l`, `6·rings²` faces) lifted vertically onto a dome, a saddle or a bell,
//! the doubly curved shapes of Fig. 13.

use glam::DVec3;

use crate::mesh::PolyMesh;

/// The shape a sample patch is lifted onto.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SampleSurface {
    /// A spherical cap (positive Gaussian curvature), sphere radius 1.5 × patch radius.
    Dome,
    /// A hyperbolic paraboloid `z = (x² − y²) / (3 ρ)` (negative curvature), ρ the patch radius.
    Saddle,
    /// A Gaussian bell `z = 0.4 ρ exp(−r² / (2 (ρ/2.5)²))` (positive top, negative rim).
    Bell,
}

/// A hexagonal patch of `6·rings²` triangles of edge `edge` (mesh units) lifted onto
/// `surface`; every interior vertex has valence 6. Faces are counter-clockwise seen from +z.
/// `rings` is clamped to 1..=64.
pub fn sample_surface(surface: SampleSurface, rings: usize, edge: f64) -> PolyMesh {
    let r = rings.clamp(1, 64) as i64;
    let radius = r as f64 * edge;
    let lift = |x: f64, y: f64| -> f64 {
        let rr = x * x + y * y;
        match surface {
            SampleSurface::Dome => {
                let s = 1.5 * radius;
                (s * s - rr).max(0.0).sqrt() - s
            }
            SampleSurface::Saddle => (x * x - y * y) / (3.0 * radius),
            SampleSurface::Bell => {
                let sigma = radius / 2.5;
                0.4 * radius * (-rr / (2.0 * sigma * sigma)).exp()
            }
        }
    };
    let inside = |i: i64, j: i64| i.abs().max(j.abs()).max((i + j).abs()) <= r;
    let mut index = std::collections::HashMap::new();
    let mut positions = Vec::new();
    for j in -r..=r {
        for i in -r..=r {
            if inside(i, j) {
                let x = edge * (i as f64 + 0.5 * j as f64);
                let y = edge * 0.75f64.sqrt() * j as f64;
                index.insert((i, j), positions.len() as u32);
                positions.push(DVec3::new(x, y, lift(x, y)));
            }
        }
    }
    let mut faces = Vec::new();
    for j in -r..=r {
        for i in -r..=r {
            let corners = [
                [(i, j), (i + 1, j), (i, j + 1)],
                [(i + 1, j), (i + 1, j + 1), (i, j + 1)],
            ];
            for tri in corners {
                if tri.iter().all(|&(a, b)| inside(a, b)) {
                    faces.push(tri.iter().map(|k| index[k]).collect());
                }
            }
        }
    }
    PolyMesh::new(positions, faces).expect("a sample patch is a valid mesh")
}
