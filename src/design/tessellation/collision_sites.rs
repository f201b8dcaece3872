//! Where the folded form passes through itself, in the input mesh's terms: which input
//! vertices own the colliding faces (a tuck belongs to its vertex, a shrunk face to its
//! corners), how deep the faces cross, and how far those vertices lie from the sheet's edge
//! in input edges — the rings of a spherical cap. Tachi (2014, Fig. 14) shows the typical
//! case: on a strongly curved surface the tucks grow towards the boundary until they cannot
//! avoid each other, and cutting the surface (or taking a smaller piece of it) is the cure;
//! these sites let a refusal say whether that is what happened.

use glam::DVec3;

use super::crowding::distances_from_boundary;
use super::model::TessMesh;
use crate::mesh::HalfEdgeMesh;

/// Most sites [`CollisionSites::describe`] names.
pub const SITES_SHOWN: usize = 3;

/// The input vertices owning colliding faces, see the module docs.
#[derive(Clone, Debug, PartialEq)]
pub struct CollisionSites {
    /// Intersecting face pairs.
    pub pairs: usize,
    /// Per owning input vertex, deepest first.
    pub sites: Vec<CollisionSite>,
    /// Pairs by the distance of their outermost owner from the sheet's edge, in input edges
    /// (index 0: an owner on the boundary).
    pub by_ring: Vec<usize>,
    /// The largest distance of any input vertex from the edge, input edges (the centre).
    pub rings: usize,
    /// The deepest crossing, mm: per pair the smaller of the two faces' reach through the
    /// other's plane on its shallower side.
    pub deepest: f64,
}

/// One input vertex whose tuck or faces collide.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CollisionSite {
    /// The input vertex.
    pub input_vertex: u32,
    /// Its position on the input mesh, mesh units.
    pub position: DVec3,
    /// Its distance from the sheet's edge, input edges.
    pub ring: usize,
    /// Colliding pairs with a face it owns.
    pub pairs: usize,
    /// The deepest of them, mm.
    pub depth: f64,
}

impl CollisionSites {
    /// Locates `pairs` (triangle indices of `mesh`, as
    /// [`intersecting_triangles`](super::intersect::intersecting_triangles) finds them on
    /// `mesh.positions`) on the input mesh `input`.
    pub fn locate(mesh: &TessMesh, input: &HalfEdgeMesh, pairs: &[(usize, usize)]) -> Self {
        let ring = rings_from_boundary(input);
        let rings = ring.iter().copied().filter(|&r| r != usize::MAX).max();
        let x = &mesh.positions;
        let mut sites: Vec<Option<CollisionSite>> = vec![None; input.positions().len()];
        let mut by_ring = vec![0; rings.unwrap_or(0) + 1];
        let mut deepest = 0.0f64;
        for &(a, b) in pairs {
            let (ta, tb) = (mesh.triangles[a], mesh.triangles[b]);
            let depth = crossing_depth(&ta.map(|v| x[v as usize]), &tb.map(|v| x[v as usize]));
            deepest = deepest.max(depth);
            let owners: Vec<u32> = owners(mesh, ta).chain(owners(mesh, tb)).collect();
            let outer = owners.iter().map(|&v| ring[v as usize]).min().unwrap_or(0);
            if let Some(slot) = by_ring.get_mut(outer) {
                *slot += 1;
            }
            for v in owners {
                let site = sites[v as usize].get_or_insert(CollisionSite {
                    input_vertex: v,
                    position: input.positions()[v as usize],
                    ring: ring[v as usize],
                    pairs: 0,
                    depth: 0.0,
                });
                site.pairs += 1;
                site.depth = site.depth.max(depth);
            }
        }
        let mut sites: Vec<CollisionSite> = sites.into_iter().flatten().collect();
        sites.sort_by(|p, q| q.depth.total_cmp(&p.depth));
        CollisionSites {
            pairs: pairs.len(),
            sites,
            by_ring,
            rings: rings.unwrap_or(0),
            deepest,
        }
    }

    /// Pairs whose outermost owner lies in the outer third of the distance from the edge to
    /// the centre (ring ≤ rings / 3), the region where Tachi's (2014, Fig. 14) tucks grow
    /// into each other.
    pub fn outer_third(&self) -> usize {
        let limit = self.rings / 3;
        self.by_ring.iter().take(limit + 1).sum()
    }

    /// Lines for the user: how many pairs, where by ring, the deepest sites.
    pub fn describe(&self) -> Vec<String> {
        let mut lines = vec![format!(
            "self-intersection: {} face pairs cross, the deepest by {:.2} mm, among the tucks \
             and faces of {} input vertices; {} of the pairs lie in the outer third (at most \
             {} input edges from the sheet's edge, of {} to the centre)",
            self.pairs,
            self.deepest,
            self.sites.len(),
            self.outer_third(),
            self.rings / 3,
            self.rings
        )];
        let rings: Vec<String> = self
            .by_ring
            .iter()
            .enumerate()
            .filter(|(_, n)| **n > 0)
            .map(|(r, n)| format!("{r}: {n}"))
            .collect();
        lines.push(format!(
            "self-intersection: pairs by input edges from the sheet's edge: {}",
            rings.join(", ")
        ));
        for s in self.sites.iter().take(SITES_SHOWN) {
            let p = s.position;
            lines.push(format!(
                "self-intersection: input vertex {} at ({:.1}, {:.1}, {:.1}), {} input edges \
                 from the edge: {} pairs, {:.2} mm deep",
                s.input_vertex, p.x, p.y, p.z, s.ring, s.pairs, s.depth
            ));
        }
        lines
    }
}

/// The input vertices a triangle of the tessellation belongs to: a tuck triangle (one with
/// a tuck vertex) to its tuck's vertex, a shrunk face's triangle to the face's corners.
fn owners(mesh: &TessMesh, tri: [u32; 3]) -> impl Iterator<Item = u32> + '_ {
    let tuck = tri
        .iter()
        .find(|&&v| v as usize >= mesh.corner_count)
        .map(|&v| mesh.input_vertex[v as usize]);
    let corners = tri.map(|v| mesh.input_vertex[v as usize]);
    let list: Vec<u32> = match tuck {
        Some(v) => vec![v],
        None => {
            let mut c = corners.to_vec();
            c.sort_unstable();
            c.dedup();
            c
        }
    };
    list.into_iter()
}

/// Distance of every input vertex from the boundary, in edges
/// ([`distances_from_boundary`] with unit edges); `usize::MAX` for a vertex no face uses.
pub fn rings_from_boundary(mesh: &HalfEdgeMesh) -> Vec<usize> {
    distances_from_boundary(mesh, |_, _| 1.0)
        .into_iter()
        .map(|d| {
            if d.is_finite() {
                d as usize
            } else {
                usize::MAX
            }
        })
        .collect()
}

/// How deep triangles `a` and `b` cross, mm: for each, its reach through the other's plane
/// on its shallower side (the smaller of the largest distances on either side); the smaller
/// of the two. Zero for a degenerate triangle.
pub fn crossing_depth(a: &[DVec3; 3], b: &[DVec3; 3]) -> f64 {
    let straddle = |p: &[DVec3; 3], q: &[DVec3; 3]| {
        let n = (q[1] - q[0]).cross(q[2] - q[0]);
        if n.length() == 0.0 {
            return 0.0;
        }
        let n = n.normalize();
        let d = p.map(|v| n.dot(v - q[0]));
        let hi = d.iter().copied().fold(f64::MIN, f64::max);
        let lo = d.iter().copied().fold(f64::MAX, f64::min);
        hi.min(-lo).max(0.0)
    };
    straddle(a, b).min(straddle(b, a))
}

#[cfg(test)]
mod tests {
    use std::collections::HashMap;

    use super::*;
    use crate::design::tessellation::intersect::intersecting_triangles;
    use crate::design::tessellation::samples::spherical_cap;

    /// On a spherical cap every vertex of ring `k` is `rings − k` edges from the rim (the
    /// rings are concentric and each step inwards crosses one ring).
    #[test]
    fn rings_count_edges_from_the_rim() {
        let rings = 4;
        let cap = spherical_cap(6, rings, 50.0, 80.0);
        let he = HalfEdgeMesh::new(&cap, 1e-9).expect("manifold");
        let found = rings_from_boundary(&he);
        // Ring k has 6k vertices, stored after the pole in ring order.
        let mut expected = vec![rings];
        for k in 1..=rings {
            expected.extend(std::iter::repeat_n(rings - k, 6 * k));
        }
        assert_eq!(found, expected);
    }

    /// A face triangle in the plane z = 0 whose corners come from the pole and the first ring
    /// of a two-ring cap, pierced 0.3 mm deep by a vertical tuck triangle of a rim vertex:
    /// one pair, in ring 0 (its outermost owner is on the rim), 0.3 mm deep (the tuck
    /// reaches 0.3 below the face's plane; the face reaches 7.07 to either side of the
    /// tuck's), and all four owners named.
    #[test]
    fn a_pierced_face_is_placed_on_its_owners_and_ring() {
        let cap = spherical_cap(6, 2, 40.0, 50.0);
        let he = HalfEdgeMesh::new(&cap, 1e-9).expect("manifold");
        let positions = vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(10.0, 0.0, 0.0),
            DVec3::new(0.0, 10.0, 0.0),
            DVec3::new(2.0, 2.0, -0.3),
            DVec3::new(2.0, 2.0, 4.0),
            DVec3::new(3.0, 3.0, 4.0),
        ];
        let triangles = vec![[0, 1, 2], [3, 4, 5]];
        // Vertices 0..3 are face corners of input vertices 0 (pole), 1 and 2 (first ring);
        // 3..6 belong to the tuck of rim vertex 7 (4, 5 stand for its tips).
        let mesh = TessMesh::from_triangles(
            positions.clone(),
            triangles.clone(),
            &HashMap::new(),
            vec![None; cap.positions().len()],
            vec![0, 1, 2, 7, 7, 7],
            3,
        );
        let pairs = intersecting_triangles(&positions, &triangles, 1e-3).unwrap();
        assert_eq!(pairs, vec![(0, 1)]);
        let sites = CollisionSites::locate(&mesh, &he, &pairs);
        assert_eq!(sites.pairs, 1);
        assert_eq!(sites.rings, 2);
        assert_eq!(sites.by_ring, vec![1, 0, 0]);
        assert_eq!(sites.outer_third(), 1);
        assert!((sites.deepest - 0.3).abs() < 1e-12, "{}", sites.deepest);
        let mut owners: Vec<(u32, usize)> = sites
            .sites
            .iter()
            .map(|s| (s.input_vertex, s.ring))
            .collect();
        owners.sort_unstable();
        assert_eq!(owners, vec![(0, 2), (1, 1), (2, 1), (7, 0)]);
        assert_eq!(
            sites.sites[0].position,
            cap.positions()[sites.sites[0].input_vertex as usize]
        );
        let text = sites.describe().join("\n");
        assert!(
            text.contains("1 face pairs cross, the deepest by 0.30 mm"),
            "{text}"
        );
        assert!(text.contains("edge: 0: 1"), "{text}");
    }
}
