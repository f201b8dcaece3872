//! Mesh builders shared by the tessellation tests: regular tilings (Fig. 5) and the example
//! surfaces (dome, saddle, bell).

use std::collections::HashMap;

use foldcam::mesh::PolyMesh;
use glam::DVec3;

/// Polygons given by corner positions, with equal positions merged into one vertex.
pub fn welded(polygons: &[Vec<DVec3>]) -> PolyMesh {
    let mut index: HashMap<(i64, i64, i64), u32> = HashMap::new();
    let mut positions = Vec::new();
    let mut faces = Vec::new();
    for poly in polygons {
        let face = poly
            .iter()
            .map(|p| {
                let key = (
                    (p.x * 1e6).round() as i64,
                    (p.y * 1e6).round() as i64,
                    (p.z * 1e6).round() as i64,
                );
                *index.entry(key).or_insert_with(|| {
                    positions.push(*p);
                    positions.len() as u32 - 1
                })
            })
            .collect();
        faces.push(face);
    }
    PolyMesh::new(positions, faces).expect("valid mesh")
}

/// Equilateral triangles of side `l` on a `cols × rows` rhombic patch (interior valence 6).
pub fn triangle_tiling(cols: usize, rows: usize, l: f64) -> PolyMesh {
    let p = |i: usize, j: usize| {
        DVec3::new(
            l * (i as f64 + 0.5 * j as f64),
            l * 0.75f64.sqrt() * j as f64,
            0.0,
        )
    };
    let mut polys = Vec::new();
    for j in 0..rows {
        for i in 0..cols {
            polys.push(vec![p(i, j), p(i + 1, j), p(i, j + 1)]);
            polys.push(vec![p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)]);
        }
    }
    welded(&polys)
}

/// Squares of side `l` (interior valence 4).
pub fn square_tiling(cols: usize, rows: usize, l: f64) -> PolyMesh {
    let p = |i: usize, j: usize| DVec3::new(l * i as f64, l * j as f64, 0.0);
    let mut polys = Vec::new();
    for j in 0..rows {
        for i in 0..cols {
            polys.push(vec![p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)]);
        }
    }
    welded(&polys)
}

/// Regular hexagons of side `l` (interior valence 3).
pub fn hexagon_tiling(cols: usize, rows: usize, l: f64) -> PolyMesh {
    let mut polys = Vec::new();
    for j in 0..rows {
        for i in 0..cols {
            let c = DVec3::new(
                l * 3f64.sqrt() * (i as f64 + 0.5 * (j % 2) as f64),
                1.5 * l * j as f64,
                0.0,
            );
            polys.push(
                (0..6)
                    .map(|k| {
                        let a = std::f64::consts::PI / 6.0 + k as f64 * std::f64::consts::PI / 3.0;
                        c + l * DVec3::new(a.cos(), a.sin(), 0.0)
                    })
                    .collect(),
            );
        }
    }
    welded(&polys)
}
