//! A near-regular re-triangulation of a disk-like surface, for meshes whose own triangles make
//! the fabrication limits unreachable (the pole fans and long thin triangles of a modelling
//! program's sphere: a 12-valent pole and faces with 29° corners under a 30° crease-angle
//! limit). Tachi (2014) tessellates the mesh it is given; this is the remedy for
//! meshes that cannot carry the tucks.
//!
//! Method: the surface is mapped onto the unit disk (boundary by arc length onto the circle,
//! interior by Floater's (2003) mean-value coordinates, a linear system solved by sparse LU;
//! the map is one-to-one for any disk mesh); a lattice of equilateral triangles is laid over
//! the disk with its spacing chosen from the surface's area so the face count matches the
//! request; every lattice triangle whose corners all fall inside the mapped mesh is kept, and
//! its corners are carried back onto the input surface by the barycentric coordinates of the
//! mapped triangle they fall in. Interior vertices then have valence 6 (no pole fans); the
//! triangles are as near equilateral as the map is conformal, and the new boundary is the
//! lattice's, up to one lattice row inside the old one ([`RemeshReport::area_kept`] says how
//! much of the surface is covered).

use std::collections::{BTreeMap, HashMap};

use faer::linalg::solvers::Solve;
use faer::sparse::{SparseColMat, Triplet};
use glam::{DVec2, DVec3};

use super::TessError;
use super::pipeline::disk;
use crate::mesh::{HalfEdgeMesh, PolyMesh};

/// What [`remesh`] changed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RemeshReport {
    /// Faces before and after.
    pub faces: [usize; 2],
    /// Largest interior vertex valence before and after.
    pub max_valence: [usize; 2],
    /// Smallest face corner angle before and after, radians.
    pub min_corner_angle: [f64; 2],
    /// Area of the new mesh over the input's (the lattice stops up to one row short of the
    /// boundary).
    pub area_kept: f64,
}

impl RemeshReport {
    /// One line for the user.
    pub fn describe(&self) -> String {
        format!(
            "remeshed to a near-regular triangulation of the same surface: {} -> {} faces, \
             highest valence {} -> {}, sharpest face corner {:.1} -> {:.1} deg, {:.1}% of \
             the area kept",
            self.faces[0],
            self.faces[1],
            self.max_valence[0],
            self.max_valence[1],
            self.min_corner_angle[0].to_degrees(),
            self.min_corner_angle[1].to_degrees(),
            100.0 * self.area_kept
        )
    }
}

/// Fewest faces [`remesh`] accepts as a target.
pub const MIN_FACES: usize = crate::limits::REMESH_FACES.min as usize;

/// Most faces [`remesh`] accepts as a target ([`crate::limits::REMESH_FACES`]): the lattice
/// and the solve after it grow with the count, so the bound is checked before either is built.
pub const MAX_FACES: usize = crate::limits::REMESH_FACES.max as usize;

/// Re-triangulates the disk `mesh` with about `faces` near-equilateral triangles (see the
/// module docs). Errors: not a disk, fewer than [`MIN_FACES`] or more than [`MAX_FACES`]
/// faces asked for, or a lattice that does not come out as one disk.
pub fn remesh(mesh: &PolyMesh, faces: usize) -> Result<(PolyMesh, RemeshReport), TessError> {
    if faces < MIN_FACES {
        return Err(TessError::BadParameter(format!(
            "remeshing needs at least {MIN_FACES} faces, got {faces}"
        )));
    }
    if faces > MAX_FACES {
        return Err(TessError::BadParameter(format!(
            "remeshing to {faces} faces: at most {MAX_FACES} ({})",
            crate::limits::REMESH_FACES.name()
        )));
    }
    let he = disk(mesh)?;
    let triangles = fan_triangles(mesh);
    let uv = disk_map(&he, &triangles)?;
    let x = mesh.positions();
    let area3: f64 = triangles.iter().map(|t| tri_area3(x, t)).sum();
    let area2: f64 = triangles.iter().map(|t| tri_area2(&uv, t).abs()).sum();
    // Lattice spacing: `faces` equilateral triangles of side h on the mapped area, then once
    // more corrected by the count kept (the lattice stops short of the boundary).
    let mut h = (4.0 * area2 / (3f64.sqrt() * faces as f64)).sqrt();
    let mut built = lattice(&uv, &triangles, x, h);
    if !built.1.is_empty() {
        h *= (built.1.len() as f64 / faces as f64).sqrt();
        built = lattice(&uv, &triangles, x, h);
    }
    let (positions, out_faces) = built;
    let out_faces = largest_piece(&out_faces);
    let (positions, out_faces) = compact(&positions, &out_faces);
    let out = PolyMesh::new(positions, out_faces)
        .map_err(|e| TessError::BadParameter(format!("remeshed surface: {e}")))?;
    let he_out = disk(&out)?;
    let report = RemeshReport {
        faces: [mesh.faces().len(), out.faces().len()],
        max_valence: [max_valence(&he), max_valence(&he_out)],
        min_corner_angle: [min_corner_angle(mesh), min_corner_angle(&out)],
        area_kept: out.area() / area3,
    };
    Ok((out, report))
}

/// The lattice of spacing `h` over the mapped disk `uv`: its vertices carried back onto the
/// surface `x` and its triangles whose corners all fall inside the mapped mesh.
fn lattice(
    uv: &[DVec2],
    triangles: &[[u32; 3]],
    x: &[DVec3],
    h: f64,
) -> (Vec<DVec3>, Vec<Vec<u32>>) {
    let locate = Locator::new(uv, triangles, h);
    let reach = (1.0 / h).ceil() as i64 + 2;
    let mut index: HashMap<(i64, i64), Option<u32>> = HashMap::new();
    let mut positions = Vec::new();
    let mut vertex = |i: i64, j: i64| -> Option<u32> {
        *index.entry((i, j)).or_insert_with(|| {
            let p = DVec2::new(i as f64 + 0.5 * j as f64, 0.75f64.sqrt() * j as f64) * h;
            let (t, b) = locate.find(p)?;
            let [a, bb, c] = triangles[t].map(|v| x[v as usize]);
            positions.push(b[0] * a + b[1] * bb + b[2] * c);
            Some((positions.len() - 1) as u32)
        })
    };
    let mut faces = Vec::new();
    for j in -reach..=reach {
        for i in -reach..=reach {
            for tri in [
                [(i, j), (i + 1, j), (i, j + 1)],
                [(i + 1, j), (i + 1, j + 1), (i, j + 1)],
            ] {
                if let [Some(a), Some(b), Some(c)] = tri.map(|(a, b)| vertex(a, b)) {
                    faces.push(vec![a, b, c]);
                }
            }
        }
    }
    (positions, faces)
}

/// Faces fanned into triangles from their first corner.
fn fan_triangles(mesh: &PolyMesh) -> Vec<[u32; 3]> {
    mesh.faces()
        .iter()
        .flat_map(|f| (1..f.len() - 1).map(move |k| [f[0], f[k], f[k + 1]]))
        .collect()
}

fn tri_area3(x: &[DVec3], t: &[u32; 3]) -> f64 {
    let [a, b, c] = t.map(|v| x[v as usize]);
    0.5 * (b - a).cross(c - a).length()
}

fn tri_area2(uv: &[DVec2], t: &[u32; 3]) -> f64 {
    let [a, b, c] = t.map(|v| uv[v as usize]);
    0.5 * (b - a).perp_dot(c - a)
}

/// Floater's (2003) mean-value map of the disk `he` onto the unit disk, counter-clockwise
/// (the input's face orientation kept). Vertices on no face map to the origin.
fn disk_map(he: &HalfEdgeMesh, triangles: &[[u32; 3]]) -> Result<Vec<DVec2>, TessError> {
    let x = he.positions();
    let n = x.len();
    let hes = he.half_edges();
    // The boundary loop, in the direction of its half-edges (interior on the left).
    let next: HashMap<u32, u32> = hes
        .iter()
        .filter(|h| h.twin.is_none())
        .map(|h| (h.from, h.to))
        .collect();
    let start = *next
        .keys()
        .min()
        .ok_or_else(|| TessError::NotADisk("no boundary".into()))?;
    let mut lp = vec![start];
    while let Some(&v) = next.get(lp.last().expect("non-empty")) {
        if v == start {
            break;
        }
        if lp.len() > next.len() {
            return Err(TessError::NotADisk("the boundary does not close".into()));
        }
        lp.push(v);
    }
    let length: f64 = (0..lp.len())
        .map(|k| x[lp[k] as usize].distance(x[lp[(k + 1) % lp.len()] as usize]))
        .sum();
    let mut uv = vec![DVec2::ZERO; n];
    let mut on_boundary = vec![false; n];
    let mut run = 0.0;
    for k in 0..lp.len() {
        let a = std::f64::consts::TAU * run / length;
        uv[lp[k] as usize] = DVec2::new(a.cos(), a.sin());
        on_boundary[lp[k] as usize] = true;
        run += x[lp[k] as usize].distance(x[lp[(k + 1) % lp.len()] as usize]);
    }
    // Mean-value weights w_ij = (tan(α/2) + tan(β/2)) / |x_j − x_i|, α and β the angles at i
    // of the two triangles on edge ij, gathered triangle by triangle. In key order, so the
    // diagonal and right-hand sums below add up the same way on every run (a hash map's
    // order would vary the result in its last bits, and the solve after it).
    let mut weights: BTreeMap<(u32, u32), f64> = BTreeMap::new();
    for t in triangles {
        for k in 0..3 {
            let (i, j, l) = (t[k], t[(k + 1) % 3], t[(k + 2) % 3]);
            let (pi, pj, pl) = (x[i as usize], x[j as usize], x[l as usize]);
            let angle = (pj - pi).angle_between(pl - pi);
            let half = (0.5 * angle).tan();
            for (a, b) in [(i, j), (i, l)] {
                let d = x[a as usize].distance(x[b as usize]).max(f64::MIN_POSITIVE);
                *weights.entry((a, b)).or_insert(0.0) += half / d;
            }
        }
    }
    // Unknowns: interior vertices; rows Σ_j w_ij (u_i − u_j) = 0.
    let mut slot = vec![usize::MAX; n];
    let mut m = 0;
    for v in 0..n {
        if !on_boundary[v] && !he.fan(v).is_empty() {
            slot[v] = m;
            m += 1;
        }
    }
    if m == 0 {
        return Ok(uv);
    }
    let mut entries = Vec::new();
    let mut rhs = vec![DVec2::ZERO; m];
    for (&(i, j), &w) in &weights {
        let si = slot[i as usize];
        if si == usize::MAX {
            continue;
        }
        entries.push(Triplet::new(si, si, w));
        match slot[j as usize] {
            usize::MAX => rhs[si] += w * uv[j as usize],
            sj => entries.push(Triplet::new(si, sj, -w)),
        }
    }
    let a = SparseColMat::<usize, f64>::try_new_from_triplets(m, m, &entries)
        .map_err(|e| TessError::BadParameter(format!("disk map: {e:?}")))?;
    let lu = a
        .sp_lu()
        .map_err(|e| TessError::BadParameter(format!("disk map: {e:?}")))?;
    let mut b = faer::Mat::<f64>::zeros(m, 2);
    for (k, r) in rhs.iter().enumerate() {
        b[(k, 0)] = r.x;
        b[(k, 1)] = r.y;
    }
    lu.solve_in_place(b.as_mut());
    for v in 0..n {
        if slot[v] != usize::MAX {
            uv[v] = DVec2::new(b[(slot[v], 0)], b[(slot[v], 1)]);
        }
    }
    if uv.iter().any(|p| !p.is_finite()) {
        return Err(TessError::BadParameter(
            "disk map: the linear solve failed".into(),
        ));
    }
    Ok(uv)
}

/// Point location in the mapped triangles through a uniform grid of buckets.
struct Locator<'a> {
    uv: &'a [DVec2],
    triangles: &'a [[u32; 3]],
    cell: f64,
    buckets: HashMap<(i64, i64), Vec<u32>>,
}

/// Barycentric coordinates down to this count a point as inside (a point on a shared edge
/// is found in one of the two triangles).
const INSIDE: f64 = -1e-9;

impl<'a> Locator<'a> {
    fn new(uv: &'a [DVec2], triangles: &'a [[u32; 3]], cell: f64) -> Self {
        let mut buckets: HashMap<(i64, i64), Vec<u32>> = HashMap::new();
        for (t, tri) in triangles.iter().enumerate() {
            let [a, b, c] = tri.map(|v| uv[v as usize]);
            let (lo, hi) = (a.min(b).min(c), a.max(b).max(c));
            for i in (lo.x / cell).floor() as i64..=(hi.x / cell).floor() as i64 {
                for j in (lo.y / cell).floor() as i64..=(hi.y / cell).floor() as i64 {
                    buckets.entry((i, j)).or_default().push(t as u32);
                }
            }
        }
        Locator {
            uv,
            triangles,
            cell,
            buckets,
        }
    }

    /// The triangle containing `p` and `p`'s barycentric coordinates in it.
    fn find(&self, p: DVec2) -> Option<(usize, [f64; 3])> {
        let key = (
            (p.x / self.cell).floor() as i64,
            (p.y / self.cell).floor() as i64,
        );
        for &t in self.buckets.get(&key)? {
            let [a, b, c] = self.triangles[t as usize].map(|v| self.uv[v as usize]);
            let area = (b - a).perp_dot(c - a);
            if area.abs() < f64::MIN_POSITIVE {
                continue;
            }
            let l1 = (c - b).perp_dot(p - b) / area;
            let l2 = (a - c).perp_dot(p - c) / area;
            let l3 = 1.0 - l1 - l2;
            if l1 >= INSIDE && l2 >= INSIDE && l3 >= INSIDE {
                return Some((t as usize, [l1, l2, l3]));
            }
        }
        None
    }
}

/// The faces of the largest edge-connected piece of `faces`.
fn largest_piece(faces: &[Vec<u32>]) -> Vec<Vec<u32>> {
    let mut by_edge: HashMap<(u32, u32), Vec<usize>> = HashMap::new();
    for (f, face) in faces.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (face[k], face[(k + 1) % 3]);
            by_edge.entry((a.min(b), a.max(b))).or_default().push(f);
        }
    }
    let mut piece = vec![usize::MAX; faces.len()];
    let mut sizes = Vec::new();
    for seed in 0..faces.len() {
        if piece[seed] != usize::MAX {
            continue;
        }
        let id = sizes.len();
        let mut count = 0;
        let mut stack = vec![seed];
        piece[seed] = id;
        while let Some(f) = stack.pop() {
            count += 1;
            for k in 0..3 {
                let (a, b) = (faces[f][k], faces[f][(k + 1) % 3]);
                for &g in &by_edge[&(a.min(b), a.max(b))] {
                    if piece[g] == usize::MAX {
                        piece[g] = id;
                        stack.push(g);
                    }
                }
            }
        }
        sizes.push(count);
    }
    let best = (0..sizes.len()).max_by_key(|&i| sizes[i]).unwrap_or(0);
    faces
        .iter()
        .zip(&piece)
        .filter(|(_, p)| **p == best)
        .map(|(f, _)| f.clone())
        .collect()
}

/// Drops unused vertices and renumbers.
fn compact(positions: &[DVec3], faces: &[Vec<u32>]) -> (Vec<DVec3>, Vec<Vec<u32>>) {
    let mut new = vec![u32::MAX; positions.len()];
    let mut kept = Vec::new();
    let faces = faces
        .iter()
        .map(|f| {
            f.iter()
                .map(|&v| {
                    if new[v as usize] == u32::MAX {
                        new[v as usize] = kept.len() as u32;
                        kept.push(positions[v as usize]);
                    }
                    new[v as usize]
                })
                .collect()
        })
        .collect();
    (kept, faces)
}

/// Largest valence of an interior vertex.
pub fn max_valence(he: &HalfEdgeMesh) -> usize {
    (0..he.positions().len())
        .filter(|&v| !he.is_boundary(v))
        .map(|v| he.fan(v).len())
        .max()
        .unwrap_or(0)
}

/// Smallest corner angle of any face (polygons fanned from their first corner), radians.
pub fn min_corner_angle(mesh: &PolyMesh) -> f64 {
    mesh.triangles()
        .flat_map(|[a, b, c]| {
            [
                (b - a).angle_between(c - a),
                (c - b).angle_between(a - b),
                (a - c).angle_between(b - c),
            ]
        })
        .fold(std::f64::consts::PI, f64::min)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::design::tessellation::samples::spherical_cap;

    /// The cap (12-valent pole, faces with 29° corners) becomes a mesh of valence 6
    /// whose vertices all lie on the sphere's chordal mesh, with close to the asked face
    /// count and nearly all of the area.
    #[test]
    fn a_cap_with_a_pole_fan_remeshes_to_valence_six_on_the_same_surface() {
        let cap = spherical_cap(12, 6, 60.0, 100.0);
        let (out, report) = remesh(&cap, 432).expect("remeshes");
        assert_eq!(report.faces[0], 432);
        assert_eq!(report.max_valence, [12, 6]);
        let faces = out.faces().len();
        assert!((400..=470).contains(&faces), "{faces}");
        assert!(report.min_corner_angle[0] < 30f64.to_radians());
        assert!(
            report.min_corner_angle[1] > 40f64.to_radians(),
            "{report:?}"
        );
        assert!(
            report.area_kept > 0.85 && report.area_kept <= 1.0 + 1e-9,
            "{report:?}"
        );
        // On the input surface: inside the sphere, by no more than the largest sag of an
        // input face below it (R − √(R² − ρ²), ρ the face's circumradius).
        let sag = cap
            .triangles()
            .map(|[a, b, c]| {
                let rho = a.distance(b) * b.distance(c) * c.distance(a)
                    / (2.0 * (b - a).cross(c - a).length());
                100.0 - (100.0f64 * 100.0 - rho * rho).sqrt()
            })
            .fold(0.0f64, f64::max);
        let centre = DVec3::new(0.0, 0.0, -100.0);
        let surface = crate::mesh::ReferenceMesh::new(&cap).expect("the cap");
        for p in out.positions() {
            let d = p.distance(centre) - 100.0;
            assert!(d <= 1e-9 && d >= -sag - 1e-9, "{p} {d} (sag {sag})");
            assert!(surface.project(*p).distance < 1e-9);
        }
    }

    /// The same input gives the same re-triangulation to the last bit, every time (each map
    /// in a process iterates in its own order; the solve that follows amplifies last-bit
    /// differences into different results).
    #[test]
    fn remeshing_is_reproducible_to_the_bit() {
        let cap = spherical_cap(12, 6, 60.0, 100.0);
        let (first, _) = remesh(&cap, 450).expect("remeshes");
        for _ in 0..4 {
            let (again, _) = remesh(&cap, 450).expect("remeshes");
            assert_eq!(first.faces(), again.faces());
            for (p, q) in first.positions().iter().zip(again.positions()) {
                assert_eq!(
                    p.to_array().map(f64::to_bits),
                    q.to_array().map(f64::to_bits)
                );
            }
        }
    }
}
