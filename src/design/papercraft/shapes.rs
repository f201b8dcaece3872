//! Meshes of bodies of revolution (about the z axis), for tests and the examples' reference
//! shapes (a vase, a sphere, a cylinder).

use std::f64::consts::TAU;

use glam::DVec3;

use super::PapercraftError;
use crate::mesh::PolyMesh;

/// The surface swept by the profile `(radius, z)` around the z axis with `segments` facets,
/// normals outward when z increases along the profile. An end with radius 0 becomes one pole
/// vertex; other ends stay open. Refuses fewer than 2 profile points or 3 segments, and
/// negative or non-finite values.
pub fn revolution(profile: &[(f64, f64)], segments: usize) -> Result<PolyMesh, PapercraftError> {
    let bad = |what: &str| PapercraftError::BadParameter(what.to_string());
    if profile.len() < 2 || segments < 3 {
        return Err(bad(
            "a body of revolution needs 2 profile points and 3 segments",
        ));
    }
    if profile
        .iter()
        .any(|&(r, z)| !(r.is_finite() && z.is_finite() && r >= 0.0))
    {
        return Err(bad("profile radii must be finite and non-negative"));
    }
    let mut positions = Vec::new();
    let mut rings = Vec::new();
    for &(r, z) in profile {
        let start = positions.len() as u32;
        if r == 0.0 {
            positions.push(DVec3::new(0.0, 0.0, z));
            rings.push(vec![start; segments]);
        } else {
            positions.extend((0..segments).map(|k| {
                let a = TAU * k as f64 / segments as f64;
                DVec3::new(r * a.cos(), r * a.sin(), z)
            }));
            rings.push((start..start + segments as u32).collect());
        }
    }
    let mut faces = Vec::new();
    for pair in rings.windows(2) {
        let (lo, hi) = (&pair[0], &pair[1]);
        for k in 0..segments {
            let k1 = (k + 1) % segments;
            let mut face = vec![lo[k], lo[k1], hi[k1], hi[k]];
            face.dedup();
            if face.first() == face.last() {
                face.pop();
            }
            if face.len() >= 3 {
                faces.push(face);
            }
        }
    }
    PolyMesh::new(positions, faces).map_err(|e| bad(&e.to_string()))
}

/// A sphere of `radius` about the origin with `rings` latitude bands and `segments` facets
/// around.
pub fn sphere(radius: f64, rings: usize, segments: usize) -> Result<PolyMesh, PapercraftError> {
    let profile: Vec<(f64, f64)> = (0..=rings.max(2))
        .map(|i| {
            let t = std::f64::consts::PI * (1.0 - i as f64 / rings.max(2) as f64);
            let (s, c) = t.sin_cos();
            (
                if i == 0 || i == rings.max(2) {
                    0.0
                } else {
                    radius * s
                },
                radius * c,
            )
        })
        .collect();
    revolution(&profile, segments)
}
