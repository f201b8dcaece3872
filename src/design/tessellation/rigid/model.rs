//! The kinematic model of rigid origami (§5, after Tachi's "Simulation of rigid origami"):
//! crease loops around interior vertices with their loop-closure residuals and analytic
//! Jacobian, and the placement of faces in 3D from fold angles.

use std::collections::{HashMap, VecDeque};

use glam::{DMat3, DVec2, DVec3};

use super::{RigidError, bad};
use crate::pattern::CreasePattern;
use crate::pattern::faces::find_faces;

/// A face placed across a crease from its parent face; the crease line runs `a → b` with the
/// face on its left, so a valley (positive angle) is a positive rotation about `b − a`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Link {
    face: usize,
    parent: usize,
    crease: usize,
    a: DVec3,
    b: DVec3,
}

/// The kinematic model of a flat crease pattern.
#[derive(Clone, Debug)]
pub struct RigidModel {
    pub(super) flat: Vec<DVec3>,
    pub(super) faces: Vec<Vec<usize>>,
    /// Pattern edge index of every crease.
    pub(super) creases: Vec<usize>,
    /// Per interior vertex: (crease, unit axis from the vertex) counter-clockwise.
    pub(super) loops: Vec<Vec<(usize, DVec3)>>,
    /// Breadth-first face order; the first entry is the root face.
    pub(super) tree: Vec<Link>,
    pub(super) triangles: Vec<[usize; 3]>,
    pub(super) triangle_face: Vec<usize>,
    pub(super) scale: f64,
}

impl RigidModel {
    /// Builds the model of a flat pattern. Faces come from `cp.faces` (or are traced); every
    /// edge with two faces is a crease, every vertex whose edges all have two faces carries a
    /// loop-closure condition.
    pub fn new(cp: &CreasePattern) -> Result<Self, RigidError> {
        if let Some(i) = cp.vertices.iter().position(|p| !p.is_finite()) {
            return Err(bad(format!("vertex {i} has a non-finite coordinate")));
        }
        let faces: Vec<Vec<usize>> = match &cp.faces {
            Some(f) => f.clone(),
            None => find_faces(cp).faces,
        }
        .into_iter()
        .enumerate()
        .map(|(i, f)| {
            let ok = f.holes.is_empty()
                && f.outer.len() >= 3
                && f.outer.iter().all(|v| v.index() < cp.vertices.len());
            ok.then(|| f.outer.iter().map(|v| v.index()).collect())
                .ok_or(RigidError::BadFace(i))
        })
        .collect::<Result<_, _>>()?;
        if faces.is_empty() {
            return Err(RigidError::NoFaces);
        }
        let index: HashMap<(usize, usize), usize> = cp
            .edges
            .iter()
            .enumerate()
            .map(|(e, ed)| {
                let [a, b] = ed.vertices.map(|v| v.index());
                ((a.min(b), a.max(b)), e)
            })
            .collect();
        // Faces on each edge, with the side's direction in that face.
        let mut sides: Vec<Vec<(usize, usize, usize)>> = vec![Vec::new(); cp.edges.len()];
        for (f, face) in faces.iter().enumerate() {
            for k in 0..face.len() {
                let (a, b) = (face[k], face[(k + 1) % face.len()]);
                let problem = |problem| RigidError::BadSide {
                    face: f,
                    a,
                    b,
                    problem,
                };
                let e = *index
                    .get(&(a.min(b), a.max(b)))
                    .ok_or_else(|| problem("is not an edge of the pattern"))?;
                sides[e].push((f, a, b));
                if sides[e].len() > 2 {
                    return Err(problem("borders more than two faces"));
                }
            }
        }
        let flat: Vec<DVec3> = cp.vertices.iter().map(|p| p.extend(0.0)).collect();
        let creases: Vec<usize> = (0..cp.edges.len())
            .filter(|&e| sides[e].len() == 2)
            .collect();
        let crease_of: HashMap<usize, usize> =
            creases.iter().enumerate().map(|(c, &e)| (e, c)).collect();
        let loops = vertex_loops(cp, &sides, &crease_of, &flat);
        let tree = face_tree(&faces, &sides, &crease_of, &flat)?;
        let mut triangles = Vec::new();
        let mut triangle_face = Vec::new();
        for (f, face) in faces.iter().enumerate() {
            for k in 1..face.len() - 1 {
                triangles.push([face[0], face[k], face[k + 1]]);
                triangle_face.push(f);
            }
        }
        let (lo, hi) = cp.bounds().unwrap_or((DVec2::ZERO, DVec2::ONE));
        Ok(RigidModel {
            flat,
            faces,
            creases,
            loops,
            tree,
            triangles,
            triangle_face,
            scale: (hi - lo).max_element().max(f64::MIN_POSITIVE),
        })
    }

    /// The pattern edge index of every crease, in the order of the angle vectors.
    pub fn crease_edges(&self) -> &[usize] {
        &self.creases
    }

    /// Number of interior vertices (loop-closure conditions).
    pub fn loop_count(&self) -> usize {
        self.loops.len()
    }

    /// Target angles per crease from the pattern's edge fold angles (degrees, FOLD sign);
    /// a crease without an angle gets 0.
    pub fn targets_from(&self, cp: &CreasePattern) -> Vec<f64> {
        self.creases
            .iter()
            .map(|&e| cp.edges[e].fold_angle.unwrap_or(0.0).to_radians())
            .collect()
    }

    /// The loop product `P = R(l_1, ρ_1) ⋯ R(l_n, ρ_n)` of every interior vertex.
    fn products<'a>(&'a self, rho: &'a [f64]) -> impl Iterator<Item = DMat3> + 'a {
        self.loops.iter().map(move |lp| {
            lp.iter().fold(DMat3::IDENTITY, |p, &(c, l)| {
                p * DMat3::from_axis_angle(l, rho[c])
            })
        })
    }

    /// Loop-closure residuals `vee((P − Pᵀ)/2)` per interior vertex.
    pub fn residuals(&self, rho: &[f64]) -> Vec<DVec3> {
        self.products(rho).map(|p| vee_skew(&p)).collect()
    }

    /// Largest closure error `‖P − I‖` (Frobenius) over the interior vertices.
    pub fn closure_error(&self, rho: &[f64]) -> f64 {
        self.products(rho)
            .map(|p| {
                let d = p - DMat3::IDENTITY;
                (d.x_axis.length_squared() + d.y_axis.length_squared() + d.z_axis.length_squared())
                    .sqrt()
            })
            .fold(0.0, f64::max)
    }

    /// Analytic Jacobian of [`RigidModel::residuals`]: per vertex, `(crease, ∂r/∂ρ_crease)`.
    pub fn jacobian(&self, rho: &[f64]) -> Vec<Vec<(usize, DVec3)>> {
        self.loops
            .iter()
            .map(|lp| {
                let rots: Vec<DMat3> = lp
                    .iter()
                    .map(|&(c, l)| DMat3::from_axis_angle(l, rho[c]))
                    .collect();
                let mut after = vec![DMat3::IDENTITY; lp.len() + 1];
                for k in (0..lp.len()).rev() {
                    after[k] = rots[k] * after[k + 1];
                }
                let mut before = DMat3::IDENTITY;
                lp.iter()
                    .enumerate()
                    .map(|(k, &(c, l))| {
                        let d = before * skew(l) * after[k];
                        before *= rots[k];
                        (c, vee_skew(&d))
                    })
                    .collect()
            })
            .collect()
    }

    /// 3D vertex positions for the fold angles `rho` and the rigid transform of every face.
    pub fn positions(&self, rho: &[f64]) -> (Vec<DVec3>, Vec<(DMat3, DVec3)>) {
        let mut frames = vec![(DMat3::IDENTITY, DVec3::ZERO); self.faces.len()];
        for l in &self.tree[1..] {
            let (m, t) = frames[l.parent];
            let r = DMat3::from_axis_angle((l.b - l.a).normalize(), rho[l.crease]);
            frames[l.face] = (m * r, m * (l.a - r * l.a) + t);
        }
        let mut pos = vec![DVec3::NAN; self.flat.len()];
        for l in self.tree.iter().rev() {
            let (m, t) = frames[l.face];
            for &v in &self.faces[l.face] {
                pos[v] = m * self.flat[v] + t;
            }
        }
        (pos, frames)
    }
}

fn skew(l: DVec3) -> DMat3 {
    DMat3::from_cols(
        DVec3::new(0.0, l.z, -l.y),
        DVec3::new(-l.z, 0.0, l.x),
        DVec3::new(l.y, -l.x, 0.0),
    )
}

/// `vee((M − Mᵀ)/2)`: the axial vector of the skew part.
fn vee_skew(m: &DMat3) -> DVec3 {
    0.5 * DVec3::new(
        m.y_axis.z - m.z_axis.y,
        m.z_axis.x - m.x_axis.z,
        m.x_axis.y - m.y_axis.x,
    )
}

/// Counter-clockwise crease directions around every vertex whose edges all have two faces.
fn vertex_loops(
    cp: &CreasePattern,
    sides: &[Vec<(usize, usize, usize)>],
    crease_of: &HashMap<usize, usize>,
    flat: &[DVec3],
) -> Vec<Vec<(usize, DVec3)>> {
    let mut around: Vec<Vec<usize>> = vec![Vec::new(); flat.len()];
    let mut open = vec![false; flat.len()];
    for (e, s) in sides.iter().enumerate() {
        if s.is_empty() {
            continue;
        }
        for v in cp.edges[e].vertices.map(|v| v.index()) {
            around[v].push(e);
            open[v] |= s.len() < 2;
        }
    }
    let mut loops = Vec::new();
    for (v, edges) in around.iter().enumerate() {
        if open[v] || edges.len() < 3 {
            continue;
        }
        let mut lp: Vec<(usize, DVec3)> = edges
            .iter()
            .map(|&e| {
                let w = cp.edges[e].other(crate::pattern::VertexId::new(v)).index();
                (crease_of[&e], (flat[w] - flat[v]).normalize())
            })
            .collect();
        lp.sort_by(|a, b| a.1.y.atan2(a.1.x).total_cmp(&b.1.y.atan2(b.1.x)));
        loops.push(lp);
    }
    loops
}

/// Breadth-first spanning tree of the faces across creases. Each entry carries the crease
/// line directed so that the child face lies on its left (valley = positive rotation).
fn face_tree(
    faces: &[Vec<usize>],
    sides: &[Vec<(usize, usize, usize)>],
    crease_of: &HashMap<usize, usize>,
    flat: &[DVec3],
) -> Result<Vec<Link>, RigidError> {
    let mut across: Vec<Vec<(usize, usize, usize, usize)>> = vec![Vec::new(); faces.len()];
    for (e, s) in sides.iter().enumerate() {
        if let [(f, ..), (g, ga, gb)] = s[..] {
            let (fa, fb) = (s[0].1, s[0].2);
            across[f].push((g, crease_of[&e], ga, gb));
            across[g].push((f, crease_of[&e], fa, fb));
        }
    }
    let mut seen = vec![false; faces.len()];
    seen[0] = true;
    let mut tree = vec![Link {
        face: 0,
        parent: 0,
        crease: 0,
        a: DVec3::ZERO,
        b: DVec3::X,
    }];
    let mut queue = VecDeque::from([0]);
    while let Some(f) = queue.pop_front() {
        for &(g, c, a, b) in &across[f] {
            if !seen[g] {
                seen[g] = true;
                // g traverses a → b counter-clockwise, so g lies left of a → b.
                tree.push(Link {
                    face: g,
                    parent: f,
                    crease: c,
                    a: flat[a],
                    b: flat[b],
                });
                queue.push_back(g);
            }
        }
    }
    match seen.iter().position(|s| !s) {
        Some(f) => Err(RigidError::Disconnected(f)),
        None => Ok(tree),
    }
}
