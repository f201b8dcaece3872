//! Meshes of bodies of revolution (about the z axis) and of bodies with elliptic sections
//! along the x axis, for tests and the examples' reference shapes (a vase, a sphere, a
//! fish).

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
    let rings: Vec<(f64, f64, f64)> = profile.iter().map(|&(r, z)| (z, r, r)).collect();
    // (x, y, z) ↦ (y, z, x) is a rotation, so the elliptic body about x is the same surface.
    let mesh = swept_rings(&rings, segments, |x, y, z| DVec3::new(y, z, x));
    mesh.map_err(|e| bad(&e.to_string()))
}

/// The surface through elliptic sections `(x, half_width, half_height)` along the x axis
/// (the section at x is `(x, w cos a, h sin a)`), `segments` facets round, normals outward
/// when x increases along the list. A section with `w = h = 0` becomes one pole vertex, so
/// `(x0, 0, 0)` first and `(x1, 0, 0)` last close the ends with flat caps when the next
/// section has the same x. Refuses fewer than 2 sections or 3 segments, and negative or
/// non-finite values, or a section with only one of w, h zero.
pub fn elliptic_body(
    sections: &[(f64, f64, f64)],
    segments: usize,
) -> Result<PolyMesh, PapercraftError> {
    let bad = |what: &str| PapercraftError::BadParameter(what.to_string());
    if sections.len() < 2 || segments < 3 {
        return Err(bad("a body needs 2 sections and 3 segments"));
    }
    let ok = |&(x, w, h): &(f64, f64, f64)| {
        x.is_finite()
            && w.is_finite()
            && h.is_finite()
            && w >= 0.0
            && h >= 0.0
            && ((w == 0.0) == (h == 0.0))
    };
    if !sections.iter().all(ok) {
        return Err(bad(
            "section sizes must be finite, non-negative, and both zero or both positive",
        ));
    }
    swept_rings(sections, segments, DVec3::new).map_err(|e| bad(&e.to_string()))
}

/// Rings of points `place(x, w cos a, h sin a)` joined by quads (triangles at poles).
fn swept_rings(
    sections: &[(f64, f64, f64)],
    segments: usize,
    place: impl Fn(f64, f64, f64) -> DVec3,
) -> Result<PolyMesh, crate::mesh::MeshError> {
    let mut positions = Vec::new();
    let mut rings = Vec::new();
    for &(x, w, h) in sections {
        let start = positions.len() as u32;
        if w == 0.0 {
            positions.push(place(x, 0.0, 0.0));
            rings.push(vec![start; segments]);
        } else {
            positions.extend((0..segments).map(|k| {
                let a = TAU * k as f64 / segments as f64;
                place(x, w * a.cos(), h * a.sin())
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
    PolyMesh::new(positions, faces)
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
