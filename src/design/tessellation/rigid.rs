//! Rigid-foldability check (§5): Tachi's rigid origami simulation ("Simulation of rigid
//! origami", the paper's reference [11]) run from the flat sheet to the target fold angles.
//!
//! Unknowns are the fold angles ρ of all creases (FOLD sign: valley positive). Every interior
//! vertex with creases `l_1 … l_n` in counter-clockwise order (unit directions in the flat
//! pattern) gives the loop-closure condition `R(l_1, ρ_1) ⋯ R(l_n, ρ_n) = I`; its three
//! residuals are the skew part of the product, `vee((P − Pᵀ)/2)`. The Jacobian is analytic:
//! `∂P/∂ρ_k = A_k [l_k]× R_k B_k` with `A_k`, `B_k` the products before and after crease `k`
//! (at closure this is `[A_k l_k]×`, the crease axis in the folded frame).
//!
//! Simulation: in step `s` of `N` the desired increment `Δρ = (ρ_target − ρ)/(N − s + 1)` is
//! projected onto the null space of the Jacobian, `Δρ − Jᵀ(JJᵀ)⁻¹JΔρ`, then Newton steps
//! `−Jᵀ(JJᵀ)⁻¹r` bring ρ back onto the constraint manifold (both by conjugate gradient on
//! `JJᵀ`, matrix-free). After the N steps the same projected step towards the target is
//! repeated until it stops changing ρ. Faces are placed in 3D by composing rotations about
//! the crease lines from a root face (breadth-first), and every step checks all pairs of
//! triangles that share no vertex for intersection.
//!
//! Deviations and limits: the skew-part residual cannot see a loop that is off by a half-turn
//! (the reported closure error is `‖P − I‖`, which does); faces that share a vertex are not
//! checked for penetration here (the vertex-adjacent conditions eq. 5–7 are the solver's job);
//! the collision test is O(T²) per step with an x-sorted sweep.

use std::collections::{HashMap, VecDeque};

use glam::{DMat3, DVec2, DVec3};
use thiserror::Error;

use crate::pattern::CreasePattern;
use crate::pattern::faces::find_faces;

/// Why a pattern cannot be simulated.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum RigidError {
    /// The pattern has no usable faces.
    #[error("the crease pattern has no faces")]
    NoFaces,
    /// A face is not a simple polygon of at least three vertices.
    #[error("face {0} is not a simple polygon with at least three corners and no holes")]
    BadFace(usize),
    /// A face side is not an edge of the pattern, or an edge borders more than two faces.
    #[error("face {face}: side {a}-{b} {problem}")]
    BadSide {
        /// The face.
        face: usize,
        /// First vertex of the side.
        a: usize,
        /// Second vertex of the side.
        b: usize,
        /// What is wrong.
        problem: &'static str,
    },
    /// The faces do not form one connected sheet.
    #[error("face {0} is not connected to face 0 across creases")]
    Disconnected(usize),
    /// A coordinate or target angle is not finite, or the targets have the wrong length.
    #[error("{0}")]
    BadInput(String),
}

/// A face placed across a crease from its parent face; the crease line runs `a → b` with the
/// face on its left, so a valley (positive angle) is a positive rotation about `b − a`.
#[derive(Clone, Copy, Debug)]
struct Link {
    face: usize,
    parent: usize,
    crease: usize,
    a: DVec3,
    b: DVec3,
}

/// The kinematic model of a flat crease pattern.
#[derive(Clone, Debug)]
pub struct RigidModel {
    flat: Vec<DVec3>,
    faces: Vec<Vec<usize>>,
    /// Pattern edge index of every crease.
    creases: Vec<usize>,
    /// Per interior vertex: (crease, unit axis from the vertex) counter-clockwise.
    loops: Vec<Vec<(usize, DVec3)>>,
    /// Breadth-first face order; the first entry is the root face.
    tree: Vec<Link>,
    triangles: Vec<[usize; 3]>,
    triangle_face: Vec<usize>,
    scale: f64,
}

/// Simulation settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RigidOptions {
    /// Number of increments from flat to the target (≥ 1).
    pub steps: usize,
    /// Loop-closure tolerance of the Newton correction (‖skew part‖ per vertex).
    pub tolerance: f64,
    /// Largest fold-angle error, radians, that still counts as reaching the target.
    pub angle_tolerance: f64,
}

impl Default for RigidOptions {
    fn default() -> Self {
        RigidOptions {
            steps: 100,
            tolerance: 1e-12,
            angle_tolerance: 1e-6,
        }
    }
}

/// Where and why the simulation stopped early.
#[derive(Clone, Debug, PartialEq)]
pub enum Stuck {
    /// The Newton correction did not return to the constraint manifold at this step.
    Closure {
        /// The step (1-based).
        step: usize,
        /// Largest closure error `‖P − I‖` left.
        residual: f64,
    },
    /// Two triangles (indices into the fan-triangulated faces) intersect at this step.
    Collision {
        /// The step (1-based).
        step: usize,
        /// The faces the two triangles belong to.
        faces: [usize; 2],
    },
}

/// The outcome of [`simulate`].
#[derive(Clone, Debug, PartialEq)]
pub struct RigidReport {
    /// Whether the target was reached within the angle tolerance, on the constraint manifold,
    /// without collisions.
    pub reached: bool,
    /// Largest `|ρ − ρ_target|` at the end, radians.
    pub angle_error: f64,
    /// Largest closure error `‖P − I‖` (Frobenius) over all vertices and steps.
    pub max_residual: f64,
    /// Largest closure error at the end.
    pub final_residual: f64,
    /// Steps completed.
    pub steps: usize,
    /// Why the run stopped early, if it did.
    pub stuck: Option<Stuck>,
    /// The fold angles at the end, per crease (see [`RigidModel::crease_edges`]), radians.
    pub angles: Vec<f64>,
    /// Vertex positions at the end (each vertex placed by the first face that holds it), mm.
    pub positions: Vec<DVec3>,
}

impl RigidReport {
    /// A one-paragraph summary for the command line.
    pub fn summary(&self) -> String {
        let verdict = if self.reached {
            "reached the target".to_string()
        } else {
            match &self.stuck {
                Some(Stuck::Closure { step, residual }) => {
                    format!("stuck at step {step}: loop closure not restored ({residual:.2e})")
                }
                Some(Stuck::Collision { step, faces }) => {
                    format!(
                        "stuck at step {step}: faces {} and {} collide",
                        faces[0], faces[1]
                    )
                }
                None => "did not reach the target".into(),
            }
        };
        format!(
            "rigid folding (§5): {verdict} after {} steps; final angle error {:.3e} deg, \
             max loop-closure residual {:.2e} (final {:.2e})",
            self.steps,
            self.angle_error.to_degrees(),
            self.max_residual,
            self.final_residual
        )
    }
}

fn bad(msg: String) -> RigidError {
    RigidError::BadInput(msg)
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

    /// First pair of triangles sharing no vertex that intersect, as face indices.
    fn collision(&self, frames: &[(DMat3, DVec3)]) -> Option<[usize; 2]> {
        let tris: Vec<[DVec3; 3]> = self
            .triangles
            .iter()
            .zip(&self.triangle_face)
            .map(|(t, &f)| t.map(|v| frames[f].0 * self.flat[v] + frames[f].1))
            .collect();
        let tol = 1e-9 * self.scale;
        let lo = |t: &[DVec3; 3]| t.iter().map(|p| p.x).fold(f64::INFINITY, f64::min);
        let hi = |t: &[DVec3; 3]| t.iter().map(|p| p.x).fold(f64::NEG_INFINITY, f64::max);
        let mut order: Vec<usize> = (0..tris.len()).collect();
        order.sort_by(|&a, &b| lo(&tris[a]).total_cmp(&lo(&tris[b])));
        for (n, &a) in order.iter().enumerate() {
            for &b in &order[n + 1..] {
                if lo(&tris[b]) > hi(&tris[a]) + tol {
                    break;
                }
                let shared = self.triangles[a]
                    .iter()
                    .any(|v| self.triangles[b].contains(v));
                if !shared && triangles_intersect(&tris[a], &tris[b], tol) {
                    let (fa, fb) = (self.triangle_face[a], self.triangle_face[b]);
                    return Some([fa.min(fb), fa.max(fb)]);
                }
            }
        }
        None
    }

    /// `J v` stacked as one 3-vector per vertex.
    fn apply(jac: &[Vec<(usize, DVec3)>], v: &[f64]) -> Vec<DVec3> {
        jac.iter()
            .map(|row| row.iter().map(|&(c, g)| g * v[c]).sum())
            .collect()
    }

    /// `Jᵀ y`.
    fn apply_t(jac: &[Vec<(usize, DVec3)>], y: &[DVec3], n: usize) -> Vec<f64> {
        let mut out = vec![0.0; n];
        for (row, yr) in jac.iter().zip(y) {
            for &(c, g) in row {
                out[c] += g.dot(*yr);
            }
        }
        out
    }

    /// The minimum-norm `x = Jᵀ y` with `(JJᵀ + εI) y = g`, by conjugate gradient.
    fn min_norm(jac: &[Vec<(usize, DVec3)>], g: &[DVec3], n: usize) -> Vec<f64> {
        let dot = |a: &[DVec3], b: &[DVec3]| a.iter().zip(b).map(|(x, y)| x.dot(*y)).sum::<f64>();
        let eps = 1e-14;
        let op = |y: &[DVec3]| -> Vec<DVec3> {
            let z = Self::apply_t(jac, y, n);
            Self::apply(jac, &z)
                .into_iter()
                .zip(y)
                .map(|(a, b)| a + eps * *b)
                .collect()
        };
        let mut y = vec![DVec3::ZERO; g.len()];
        let mut r = g.to_vec();
        let mut p = r.clone();
        let mut rr = dot(&r, &r);
        let goal = 1e-28 * rr.max(f64::MIN_POSITIVE);
        for _ in 0..(30 * g.len() + 100) {
            if rr <= goal {
                break;
            }
            let ap = op(&p);
            let pap = dot(&p, &ap);
            if pap.is_nan() || pap <= 0.0 {
                break;
            }
            let alpha = rr / pap;
            for k in 0..y.len() {
                y[k] += alpha * p[k];
                r[k] -= alpha * ap[k];
            }
            let rr_new = dot(&r, &r);
            let beta = rr_new / rr;
            rr = rr_new;
            for k in 0..p.len() {
                p[k] = r[k] + beta * p[k];
            }
        }
        Self::apply_t(jac, &y, n)
    }

    /// `d` projected onto the null space of the Jacobian at `rho`.
    fn project(&self, rho: &[f64], d: &[f64]) -> Vec<f64> {
        let jac = self.jacobian(rho);
        let jd = Self::apply(&jac, d);
        let c = Self::min_norm(&jac, &jd, d.len());
        d.iter().zip(c).map(|(a, b)| a - b).collect()
    }

    /// Newton steps back onto the manifold; returns the skew residual reached.
    fn correct(&self, rho: &mut [f64], tolerance: f64) -> f64 {
        let worst = |r: &[DVec3]| r.iter().map(|v| v.length()).fold(0.0, f64::max);
        let mut r = self.residuals(rho);
        for _ in 0..30 {
            if worst(&r) <= tolerance {
                break;
            }
            let dx = Self::min_norm(&self.jacobian(rho), &r, rho.len());
            for (x, d) in rho.iter_mut().zip(dx) {
                *x -= d;
            }
            r = self.residuals(rho);
        }
        worst(&r)
    }
}

/// Simulates folding from flat to `target` (radians per crease, in the order of
/// [`RigidModel::crease_edges`]) and reports how far it got (see the module docs).
pub fn simulate(
    model: &RigidModel,
    target: &[f64],
    opts: &RigidOptions,
    mut progress: impl FnMut(usize, f64),
) -> Result<RigidReport, RigidError> {
    let n = model.creases.len();
    if target.len() != n {
        return Err(bad(format!(
            "{} target angles for {n} creases",
            target.len()
        )));
    }
    if let Some(c) = target.iter().position(|t| !t.is_finite()) {
        return Err(bad(format!("the target angle of crease {c} is not finite")));
    }
    if opts.steps == 0 || opts.steps > 1_000_000 {
        return Err(bad(format!(
            "steps must be in 1..=1000000, got {}",
            opts.steps
        )));
    }
    let mut rho = vec![0.0; n];
    let mut max_residual = 0.0f64;
    let mut stuck = None;
    let mut steps = 0;
    let stall = 1e-3f64;
    // Up to `steps` increments, then a few polishing rounds aimed at the target itself.
    for s in 1..=opts.steps + 50 {
        let remaining = opts.steps.saturating_sub(s - 1).max(1) as f64;
        let d: Vec<f64> = target
            .iter()
            .zip(&rho)
            .map(|(t, r)| (t - r) / remaining)
            .collect();
        let dp = model.project(&rho, &d);
        let moved = dp.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        for (x, dx) in rho.iter_mut().zip(dp) {
            *x += dx;
        }
        let skew = model.correct(&mut rho, opts.tolerance);
        let residual = model.closure_error(&rho);
        max_residual = max_residual.max(residual);
        steps = s.min(opts.steps);
        progress(s, residual);
        if skew > stall.min(1e6 * opts.tolerance) || residual > stall {
            stuck = Some(Stuck::Closure { step: s, residual });
            break;
        }
        let (_, frames) = model.positions(&rho);
        if let Some(faces) = model.collision(&frames) {
            stuck = Some(Stuck::Collision { step: s, faces });
            break;
        }
        if s >= opts.steps && moved <= 1e-3 * opts.angle_tolerance {
            break;
        }
    }
    let angle_error = target
        .iter()
        .zip(&rho)
        .fold(0.0f64, |m, (t, r)| m.max((t - r).abs()));
    let final_residual = model.closure_error(&rho);
    Ok(RigidReport {
        reached: stuck.is_none() && angle_error <= opts.angle_tolerance,
        angle_error,
        max_residual,
        final_residual,
        steps,
        stuck,
        positions: model.positions(&rho).0,
        angles: rho,
    })
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

/// Whether two triangles intersect by more than `tol`: an edge of one crosses the interior
/// of the other (coplanar contact is not counted).
fn triangles_intersect(a: &[DVec3; 3], b: &[DVec3; 3], tol: f64) -> bool {
    (0..3).any(|k| segment_hits(a[k], a[(k + 1) % 3], b, tol))
        || (0..3).any(|k| segment_hits(b[k], b[(k + 1) % 3], a, tol))
}

fn segment_hits(p: DVec3, q: DVec3, t: &[DVec3; 3], tol: f64) -> bool {
    let n = (t[1] - t[0]).cross(t[2] - t[0]);
    let len = n.length();
    if len == 0.0 {
        return false;
    }
    let n = n / len;
    let (dp, dq) = ((p - t[0]).dot(n), (q - t[0]).dot(n));
    if dp.abs() <= tol || dq.abs() <= tol || (dp > 0.0) == (dq > 0.0) {
        return false;
    }
    let x = p + (q - p) * (dp / (dp - dq));
    (0..3).all(|k| {
        let (a, b) = (t[k], t[(k + 1) % 3]);
        let out = (b - a).cross(x - a).dot(n) / (b - a).length().max(f64::MIN_POSITIVE);
        out > tol
    })
}
