//! Curvature read off the input mesh before solving, and what finer faces or a smaller face
//! shrink can do about it (issue: "how many faces, or what sheet size, would bring tucks
//! within the limits").
//!
//! Two relations, both from the discrete Gaussian curvature, the angular defect
//! `K_v = 2π − Σθ` of an interior vertex `v` (Descartes; `θ` its face corners):
//!
//! 1. **Per vertex.** By the discrete Gauss–Bonnet theorem the defects of a disk add up to
//!    `2π − Σ_boundary (π − Σθ)`, a property of the surface, not of its triangulation: `k`
//!    times as many faces (about `k` times as many vertices, Euler) divide the defect one
//!    tuck takes up by about `k`. So `F · K_max / K` faces bring the largest defect down to
//!    `K` ([`CurvatureAdvice::faces_for`]).
//! 2. **Accumulated towards the rim** (Tachi 2014, Fig. 14: tucks grow towards the boundary
//!    of strongly curved surfaces). The crease pattern is flat, so the tucks on a ring at
//!    geodesic distance `ρ` from a point take up the difference between the flat
//!    circumference `2πρ` and the surface's, `2π sin(√κ ρ)/√κ` at Gaussian curvature `κ`:
//!    `πκρ³/3` to third order. Shared by the `2πρ/l` tucks of that ring (edge length `l`),
//!    each tuck takes up `κρ²/6` of an edge length more than one at the centre — a number
//!    without `l`, so finer faces do not change it. With `κρ² ≈ ΣK_v / π` over a patch of
//!    area `A = πρ²` ([`CurvatureAdvice::rim_demand`] `= ΣK_v / 6π`), it is the share of an
//!    edge that the rim's tucks must open further than the centre's (1/6 for a 60° spherical cap); the face shrink `s`
//!    leaves gaps of about `1 − s` of an edge for the tucks, so a smaller shrink, or a
//!    smaller piece of the surface (cut it into several sheets), is what helps.
//!
//! Measured (release build, stainless limits, star tucks, `foldcam tessellate` defaults on
//! spherical caps of 6 to 96 faces and 60° to 170°, and on the face mask): neither number
//! decides a solve. Caps with up to 186° at one vertex solved at shrink 0.8; a 330° pole did
//! not. The rim demand is 1/6 for a 60° cap and 1/2 for a 120° one, yet 54-face 120° caps
//! solved at 0.8 while finer 60° and 90° caps needed 0.7; the mask (0.10) needed 0.6. So the
//! advice states both numbers and the remedy each calls for, as a guide, not a promise.

use std::f64::consts::PI;

use glam::DVec3;

use super::TessError;
use super::pipeline::disk;
use crate::mesh::{HalfEdgeMesh, PolyMesh};

/// The curvature of an input mesh, see the module docs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurvatureAdvice {
    /// Faces of the mesh.
    pub faces: usize,
    /// Interior vertices.
    pub interior: usize,
    /// Sum of the interior vertices' defects, radians (the total Gaussian curvature).
    pub total: f64,
    /// Largest defect magnitude of one interior vertex, radians.
    pub max_defect: f64,
    /// Where that vertex is, mesh units.
    pub max_at: DVec3,
    /// Area of the mesh, square mesh units.
    pub area: f64,
    /// The interior vertices' share of it (a third of every face at each of its corners).
    pub interior_area: f64,
}

impl CurvatureAdvice {
    /// Faces that bring the largest per-vertex defect down to `defect` radians (relation 1 of
    /// the module docs); at least the mesh's own count.
    pub fn faces_for(&self, defect: f64) -> usize {
        if defect <= 0.0 {
            return usize::MAX;
        }
        let k = (self.max_defect / defect).max(1.0);
        (self.faces as f64 * k).ceil() as usize
    }

    /// How much further, in edge lengths, the tucks at the rim must open than those at the
    /// centre: `κρ²/6` of relation 2 (module docs), with the mean curvature
    /// `κ = |ΣK_v| / A_interior` over the whole area `A = πρ²` (the interior vertices' own
    /// area, so that a coarse mesh whose boundary vertices carry much of the curvature is
    /// not under-read).
    pub fn rim_demand(&self) -> f64 {
        if self.interior_area <= 0.0 {
            return 0.0;
        }
        let kappa = self.total.abs() / self.interior_area;
        kappa * self.area / (6.0 * PI)
    }

    /// The face shrink under which the gaps between faces (about `1 − s` of an edge) cover
    /// [`rim_demand`](Self::rim_demand), in (0, 1]; a first-order guide, not a guarantee.
    pub fn shrink_for_rim(&self) -> f64 {
        (1.0 - self.rim_demand()).clamp(0.05, 1.0)
    }

    /// Lines for the user: the two numbers and what each calls for.
    pub fn describe(&self) -> Vec<String> {
        let deg = f64::to_degrees;
        let p = self.max_at;
        let refine = if self.max_defect > DEFECT_SEEN_SOLVED {
            format!(
                "more than the {:.0} deg seen solved; about {} faces would bring it there",
                deg(DEFECT_SEEN_SOLVED),
                self.faces_for(DEFECT_SEEN_SOLVED)
            )
        } else {
            format!(
                "within the {:.0} deg seen solved, so finer faces are not needed for it",
                deg(DEFECT_SEEN_SOLVED)
            )
        };
        vec![
            format!(
                "curvature: {:.0} deg in total over {} interior vertices, at most {:.1} deg at \
                 one, at ({:.1}, {:.1}, {:.1}): {refine} (a tuck takes up less with more faces)",
                deg(self.total),
                self.interior,
                deg(self.max_defect),
                p.x,
                p.y,
                p.z,
            ),
            format!(
                "curvature: the tucks at the rim must open about {:.2} of an edge further than \
                 at the centre (Tachi 2014, Fig. 14), whatever the face count; to first order a \
                 face shrink of {:.2} or less leaves room for that (a rough guide: the solve \
                 decides), or cut the surface into smaller pieces",
                self.rim_demand(),
                self.shrink_for_rim()
            ),
        ]
    }
}

/// The largest angular defect at one vertex seen solved at the stainless limits (165°, 30°)
/// with star tucks at shrink 0.8 on the input's own triangles, radians: 111.5° at the pole of
/// a 6-face 90° spherical cap (`spherical_cap(6, 1, 90, 100)`, release build,
/// `foldcam tessellate --shrink 0.8`); a 6-face 150° cap, 271° at its pole, was not.
pub const DEFECT_SEEN_SOLVED: f64 = 111.5 * PI / 180.0;

/// The curvature of `mesh` (a disk, see [`disk`]); polygon corners are measured between the
/// corner's two neighbours.
///
/// # Errors
/// When `mesh` is not an oriented manifold disk.
pub fn curvature_advice(mesh: &PolyMesh) -> Result<CurvatureAdvice, TessError> {
    Ok(curvature_advice_of(mesh, &disk(mesh)?))
}

/// [`curvature_advice`] of `mesh` with its half-edge view `he` already built.
pub(crate) fn curvature_advice_of(mesh: &PolyMesh, he: &HalfEdgeMesh) -> CurvatureAdvice {
    let x = mesh.positions();
    let mut sums = vec![0.0; x.len()];
    let mut areas = vec![0.0; x.len()];
    for f in mesh.faces() {
        let n = f.len();
        let area: f64 = (1..n - 1)
            .map(|k| {
                let [a, b, c] = [f[0], f[k], f[k + 1]].map(|v| x[v as usize]);
                0.5 * (b - a).cross(c - a).length()
            })
            .sum();
        for k in 0..n {
            areas[f[k] as usize] += area / n as f64;
            let (o, a, b) = (f[k], f[(k + 1) % n], f[(k + n - 1) % n]);
            let (u, v) = (x[a as usize] - x[o as usize], x[b as usize] - x[o as usize]);
            sums[o as usize] += u.angle_between(v);
        }
    }
    let mut advice = CurvatureAdvice {
        faces: mesh.faces().len(),
        interior: 0,
        total: 0.0,
        max_defect: 0.0,
        max_at: DVec3::ZERO,
        area: areas.iter().sum(),
        interior_area: 0.0,
    };
    for (v, s) in sums.iter().enumerate() {
        if he.fan(v).is_empty() || he.is_boundary(v) {
            continue;
        }
        let defect = 2.0 * PI - s;
        advice.interior += 1;
        advice.total += defect;
        advice.interior_area += areas[v];
        if defect.abs() > advice.max_defect {
            advice.max_defect = defect.abs();
            advice.max_at = x[v];
        }
    }
    advice
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::design::tessellation::samples::{face_mask, spherical_cap};

    /// Discrete Gauss–Bonnet: on a disk the interior defects and the boundary's turning
    /// `π − Σθ` add up to exactly 2π, whatever the triangulation.
    #[test]
    fn defects_and_boundary_turning_add_up_to_two_pi() {
        for mesh in [spherical_cap(6, 3, 60.0, 100.0), face_mask(5)] {
            let a = curvature_advice(&mesh).unwrap();
            let he = disk(&mesh).unwrap();
            let x = mesh.positions();
            let mut turning = 0.0;
            for v in 0..x.len() {
                if !he.is_boundary(v) {
                    continue;
                }
                let mut s = 0.0;
                for f in mesh.faces() {
                    if let Some(k) = f.iter().position(|&w| w as usize == v) {
                        let n = f.len();
                        let (a, b) = (f[(k + 1) % n], f[(k + n - 1) % n]);
                        s += (x[a as usize] - x[v]).angle_between(x[b as usize] - x[v]);
                    }
                }
                turning += PI - s;
            }
            assert!(
                (a.total + turning - 2.0 * PI).abs() < 1e-9,
                "{}",
                a.total + turning
            );
        }
    }

    /// Relation 1: four times the faces (twice the rings) divide the largest defect of a
    /// spherical cap by about four, and `faces_for` says so. The total tends to the smooth
    /// cap's `2π(1 − cos φ)` (π for 60°) less the rim's geodesic curvature share.
    #[test]
    fn finer_faces_divide_the_defect_per_vertex() {
        let coarse = curvature_advice(&spherical_cap(6, 3, 60.0, 100.0)).unwrap();
        let fine = curvature_advice(&spherical_cap(6, 6, 60.0, 100.0)).unwrap();
        let ratio = coarse.max_defect / fine.max_defect;
        assert!((3.0..5.0).contains(&ratio), "{ratio}");
        let predicted = coarse.faces_for(fine.max_defect);
        assert!(
            (predicted as f64 / 216.0 - 1.0).abs() < 0.3,
            "{predicted} faces predicted, 216 have it"
        );
        // The rim demand does not depend on the face count (relation 2).
        assert!(
            (coarse.rim_demand() / fine.rim_demand() - 1.0).abs() < 0.25,
            "{} vs {}",
            coarse.rim_demand(),
            fine.rim_demand()
        );
        // The smooth 60° cap: κρ² = (1/R²)·2πR²(1 − cos φ)/π = 1, so 1/6.
        assert!(
            (fine.rim_demand() - 1.0 / 6.0).abs() < 0.03,
            "{}",
            fine.rim_demand()
        );
        assert_eq!(coarse.faces_for(coarse.max_defect), 54);
        assert!(fine.total > 0.5 * PI && fine.total < PI, "{}", fine.total);
    }
}
