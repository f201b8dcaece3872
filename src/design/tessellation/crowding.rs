//! Before solving: will the tucks near the sheet's edge run into each other? Tachi (2014,
//! Fig. 14) shows tucks growing towards the boundary of a strongly curved surface until they
//! cannot avoid each other, and cuts the surface to keep them apart. This module turns that
//! into one number read off the input mesh, the **crowding index**
//!
//! `ρ² / (R · l)`
//!
//! with `ρ` the farthest any vertex lies from the sheet's edge (along mesh edges, mm), `R`
//! the radius of curvature of the surface (`1/√κ`, `κ` the mean Gaussian curvature: the
//! interior angular defects over the interior vertices' area) and `l` the edge length (the
//! side of an equilateral triangle of the mean face area, so that a re-triangulation with as
//! many faces measures the same).
//! Two readings: `ρ/l` is how many tucks lie between the centre and the edge, `ρ/R` the angle
//! the surface turns over that distance; on a spherical cap of polar angle `φ` with `k`
//! rings it is about `φ · k` (the edge is about the radial edge `Rφ/k`).
//!
//! The limit [`CROWDING_LIMIT`] is measured, not derived (release build,
//! `examples/tessellation_collisions.rs`, truncated stars, shrink 0.45, stainless limits
//! 165°/30°, each cap re-triangulated near-regularly with about its own face count): these
//! caps of radius 100 mm (`spherical_cap(12, rings, φ, 100)`) tessellate without a face
//! intersection: 60°/6 rings (432 faces), 36.9°/8, 41.5°/9 and 30°/13 rings; these do not:
//! 46.2°/10 rings (72 pairs), 35°/13 (48), 40°/13 (378), 45°/13 (210), 50°/13 (675), 60°/9
//! (813) and 60°/13 (483 to 585). Every pair lay in the outermost band of polar angle
//! (for example 45°–60° on the 60° caps, 30°–35° on the 35° one). The 8-, 9- and 10-ring
//! caps share the edge length of the 13-ring 60° cap: pieces of that mesh reaching at most
//! 9 rings from their edge are clean, as [`RimCrowding::max_reach`] predicts (77 mm; 9 rings
//! reach 72.5 mm, 10 rings 80.5 mm), and the 60° cap is clean with 432 faces, not with 972,
//! as [`RimCrowding::faces_for_limit`] predicts (about 600): `foldcam tessellate` of the
//! 2,028-face cap with `--tuck truncated --remesh 603` (606 faces) wrote a clean result at
//! shrink 0.4 in 1.6 s. Every colliding cap above (index 10.4 to 18.3) also collided at
//! every other shrink of the default ladder, 0.8 to 0.4 (30 to 1,200 pairs each), which is
//! why [`Schedule::ladder`](super::Schedule::ladder) solves a crowded input on a
//! coarser re-triangulation with [`RimCrowding::faces_for_limit`] faces first (see
//! [`passes`](super::passes)) and, at the input's face count, stops at the first converged
//! result crowded at the rim.
//! The `tests` module checks that the index computed here separates exactly these two groups.
//!
//! So the index says what helps: a smaller piece (`ρ`, for instance cuts or slits from the
//! edge inwards, as Tachi does), fewer and larger faces (`l`; the index falls as `1/l`, the
//! face count as `l²`), or a flatter surface (`R`). A smaller face shrink did not help on the
//! 2,028-face 60° cap (0.5, 0.45, 0.4: 1,479, 585, 1,290 pairs), nor per-vertex tuck depths
//! (the tucks' own vertices moved 0.6 or 1.6 times as deep at the rim: the solve stalled at
//! 0.35 and 0.25 rad with 1,550 and 11,503 pairs), nor turning the surface over so that the
//! tucks lie on its convex side (7,309 pairs), nor ground contact (no convergence), nor
//! the collision rows of [`collision`](super::collision) switched on from a converged state
//! (the solve stalls at once; the crossings are several millimetres deep by then).

use std::cmp::Ordering;
use std::collections::BinaryHeap;

use super::TessError;
use super::advice::curvature_advice_of;
use super::pipeline::disk;
use crate::mesh::{HalfEdgeMesh, PolyMesh};

/// The crowding index up to which the measured caps tessellated without intersections (see
/// the module docs): the clean caps measure 6.1–9.5 (60°/6 rings 8.5, 41.5°/9 rings 8.6,
/// 30°/13 rings 8.9 on the input mesh, 9.0 re-triangulated; the 60°/13-ring cap
/// re-triangulated to 564 faces 9.5, clean at shrink 0.5), the colliding ones 10.4 and more
/// (35°/13 rings 10.4, 46.2°/10 rings 10.6, 60°/13 rings 18.3).
pub const CROWDING_LIMIT: f64 = 10.0;

/// The quantities of the crowding index of one mesh, see the module docs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RimCrowding {
    /// Farthest distance of a vertex from the sheet's edge along mesh edges, mesh units.
    pub reach: f64,
    /// Radius of curvature `1/√κ` of the mean Gaussian curvature, mesh units (infinite on a
    /// developable surface).
    pub radius: f64,
    /// Edge length: the side of an equilateral triangle of the mesh's mean triangle area
    /// (polygons counted as the triangles of a fan), mesh units.
    pub edge: f64,
    /// Faces of the mesh.
    pub faces: usize,
}

impl RimCrowding {
    /// `ρ² / (R · l)`.
    pub fn index(&self) -> f64 {
        if !self.radius.is_finite() || self.radius <= 0.0 || self.edge <= 0.0 {
            return 0.0;
        }
        self.reach * self.reach / (self.radius * self.edge)
    }

    /// Whether the index exceeds [`CROWDING_LIMIT`].
    pub fn crowded(&self) -> bool {
        self.index() > CROWDING_LIMIT
    }

    /// The farthest a piece of this surface, at this edge length, may reach from its edge
    /// and stay within the limit: `√(limit · R · l)`, mesh units.
    pub fn max_reach(&self) -> f64 {
        (CROWDING_LIMIT * self.radius * self.edge).sqrt()
    }

    /// The most faces this whole surface may have and stay within the limit (the index
    /// falls as `1/l`, the face count as `1/l²`); at most the mesh's own count.
    pub fn faces_for_limit(&self) -> usize {
        let index = self.index();
        if index <= CROWDING_LIMIT {
            return self.faces;
        }
        (self.faces as f64 * (CROWDING_LIMIT / index).powi(2)).floor() as usize
    }

    /// Lines for the user: the index and, when crowded, where and what would fix it.
    pub fn describe(&self) -> Vec<String> {
        let index = self.index();
        let head = format!(
            "rim crowding: the sheet reaches {:.0} mm from its edge, on a surface curved with \
             a radius of about {:.0} mm, at {:.1} mm edges: reach^2 / (radius x edge) = {index:.1}",
            self.reach, self.radius, self.edge
        );
        if !self.crowded() {
            return vec![format!(
                "{head}, within the {CROWDING_LIMIT:.1} up to which spherical caps were measured \
                 free of intersections"
            )];
        }
        vec![
            format!(
                "{head}, over the {CROWDING_LIMIT:.1} up to which spherical caps were measured \
                 free of intersections: expect the tucks near the edge to run into each other \
                 (Tachi 2014, Fig. 14; a smaller face shrink did not help on such caps)"
            ),
            format!(
                "rim crowding: what would fix it: pieces reaching at most {:.0} mm from their \
                 edge (cut the surface, or slit it from the edge inwards as Tachi does), or \
                 about {} faces or fewer for the whole surface (--remesh {})",
                self.max_reach(),
                self.faces_for_limit(),
                self.faces_for_limit()
            ),
        ]
    }
}

/// The crowding index's quantities for `mesh` (a disk, see [`disk`]).
///
/// # Errors
/// When `mesh` is not an oriented manifold disk.
pub fn rim_crowding(mesh: &PolyMesh) -> Result<RimCrowding, TessError> {
    Ok(rim_crowding_of(mesh, &disk(mesh)?))
}

/// [`rim_crowding`] of `mesh` with its half-edge view `he` already built.
pub(crate) fn rim_crowding_of(mesh: &PolyMesh, he: &HalfEdgeMesh) -> RimCrowding {
    let advice = curvature_advice_of(mesh, he);
    let x = mesh.positions();
    // The edge of an equilateral triangle of the mean triangle area: unlike the mean edge
    // length, the same for a modelling program's cap and its near-regular re-triangulation.
    let triangles: usize = mesh.faces().iter().map(|f| f.len() - 2).sum();
    let edge = (4.0 * advice.area / (3f64.sqrt() * triangles.max(1) as f64)).sqrt();
    let kappa = if advice.interior_area > 0.0 {
        advice.total.abs() / advice.interior_area
    } else {
        0.0
    };
    let radius = if kappa > 0.0 {
        1.0 / kappa.sqrt()
    } else {
        f64::INFINITY
    };
    let reach = distances_from_boundary(he, |v, w| x[v].distance(x[w]))
        .into_iter()
        .filter(|d| d.is_finite())
        .fold(0.0, f64::max);
    RimCrowding {
        reach,
        radius,
        edge,
        faces: mesh.faces().len(),
    }
}

/// Shortest distance of every vertex from the sheet's edge along the mesh edges, each edge
/// `(v, w)` costing `length(v, w)` (Dijkstra from every boundary vertex; a unit length counts
/// edges); infinite for a vertex no face uses.
pub(crate) fn distances_from_boundary(
    he: &HalfEdgeMesh,
    length: impl Fn(usize, usize) -> f64,
) -> Vec<f64> {
    let hes = he.half_edges();
    let mut dist = vec![f64::INFINITY; he.positions().len()];
    let mut heap = BinaryHeap::new();
    for (v, d) in dist.iter_mut().enumerate() {
        if !he.fan(v).is_empty() && he.is_boundary(v) {
            *d = 0.0;
            heap.push(Near(0.0, v));
        }
    }
    while let Some(Near(d, v)) = heap.pop() {
        if d > dist[v] {
            continue;
        }
        for &h in he.fan(v) {
            let e = hes[h as usize];
            // The outgoing edge's end and the face's incoming edge's start.
            for w in [e.to, hes[e.prev as usize].from] {
                let w = w as usize;
                let nd = d + length(v, w);
                if nd < dist[w] {
                    dist[w] = nd;
                    heap.push(Near(nd, w));
                }
            }
        }
    }
    dist
}

/// A heap entry, nearest first.
#[derive(PartialEq)]
struct Near(f64, usize);

impl Eq for Near {}

impl PartialOrd for Near {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Near {
    fn cmp(&self, other: &Self) -> Ordering {
        other.0.total_cmp(&self.0).then(other.1.cmp(&self.1))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::design::tessellation::samples::spherical_cap;

    /// The index computed here separates the caps measured clean from those measured with
    /// intersecting faces (module docs) at the limit.
    #[test]
    fn the_limit_separates_the_measured_caps() {
        let clean = [(6, 60.0), (8, 36.92), (9, 41.54), (13, 30.0)];
        let colliding = [
            (10, 46.15),
            (13, 35.0),
            (13, 40.0),
            (13, 45.0),
            (13, 50.0),
            (9, 60.0),
            (13, 60.0),
        ];
        let index = |(rings, deg): (usize, f64)| {
            rim_crowding(&spherical_cap(12, rings, deg, 100.0))
                .unwrap()
                .index()
        };
        for c in clean {
            assert!(index(c) < CROWDING_LIMIT, "{c:?}: {}", index(c));
        }
        for c in colliding {
            assert!(index(c) > CROWDING_LIMIT, "{c:?}: {}", index(c));
        }
    }

    /// Closed forms on a spherical cap of radius R and polar angle φ with k rings: the reach
    /// is the pole's distance along a meridian, k chords of 2R·sin(φ/2k); the curvature radius
    /// tends to R; the index scales with k at fixed φ (as 1/l), and `faces_for_limit`
    /// follows from it.
    #[test]
    fn reach_and_radius_match_the_sphere() {
        let (k, deg, r) = (8, 50.0f64, 100.0);
        let phi = deg.to_radians();
        let c = rim_crowding(&spherical_cap(12, k, deg, r)).unwrap();
        let chords = k as f64 * 2.0 * r * (phi / (2.0 * k as f64)).sin();
        assert!((c.reach - chords).abs() < 1e-9, "{} vs {chords}", c.reach);
        assert!((c.radius / r - 1.0).abs() < 0.1, "{}", c.radius);
        let finer = rim_crowding(&spherical_cap(12, 2 * k, deg, r)).unwrap();
        let ratio = finer.index() / c.index();
        assert!((ratio - 2.0).abs() < 0.15, "{ratio}");
        assert!(finer.crowded());
        let f = finer.faces_for_limit();
        let expected = finer.faces as f64 * (CROWDING_LIMIT / finer.index()).powi(2);
        assert_eq!(f, expected.floor() as usize);
        assert!(f < finer.faces);
        // A flat disk is never crowded.
        let flat = rim_crowding(&spherical_cap(12, 4, 1e-3, r)).unwrap();
        assert!(!flat.crowded(), "{}", flat.index());
    }
}
