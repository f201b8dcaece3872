//! Unfolding the developed tessellation: triangles laid flat one by one in breadth-first
//! order, each placed isometrically against its already placed neighbour (the order and the
//! placement are [`crate::geom::unfold`]'s, shared with FOLD import); then the
//! [`CreasePattern`] (frame 0, millimetres) and the [`FoldedState`] (same vertices, edges and
//! faces in 3D) are written out, and the flat pattern is checked for overlapping triangles.
//!
//! A vertex takes the position of its first placement; a developable surface (eq. 1 of Tachi 2014 holds)
//! closes every vertex fan, so later placements agree up to the residual, which the
//! [`Unfolded::max_length_error`] reports.

use glam::DVec2;

use super::TessError;
use super::geometry::fold_angle;
use super::model::{EdgeRole, TessMesh};
use crate::geom::tolerance::RELATIVE;
use crate::geom::unfold::{apex, breadth_first};
use crate::pattern::{Assignment, CreasePattern, Edge, Face, FoldedState, VertexId};

/// The unfolded tessellation.
#[derive(Clone, Debug)]
pub struct Unfolded {
    /// The crease pattern in millimetres: triangles as faces (counter-clockwise), creases with
    /// assignments and target fold angles, the outline as boundary edges.
    pub pattern: CreasePattern,
    /// The folded form: the same vertices, edges and faces at their 3D positions.
    pub folded: FoldedState,
    /// Largest relative difference between an edge's flat and 3D lengths.
    pub max_length_error: f64,
}

/// Lays `mesh` flat and builds the pattern; fails with [`TessError::Overlap`] when two
/// triangles overlap in the plane (or one is flipped), and [`TessError::NotADisk`] when the
/// triangles are not all connected.
pub fn unfold(mesh: &TessMesh) -> Result<Unfolded, TessError> {
    let flat = develop(mesh)?;
    if let Some((a, b)) = first_overlap(mesh, &flat) {
        return Err(TessError::Overlap(a, b));
    }
    let x = &mesh.positions;
    let mut max_length_error = 0.0f64;
    let mut edges = Vec::with_capacity(mesh.edges.len());
    for e in &mesh.edges {
        let [i, j] = e.vertices;
        let l3 = x[i as usize].distance(x[j as usize]);
        let l2 = flat[i as usize].distance(flat[j as usize]);
        max_length_error = max_length_error.max((l3 - l2).abs() / l3.max(f64::MIN_POSITIVE));
        let ids = [VertexId::new(i as usize), VertexId::new(j as usize)];
        if !e.interior {
            edges.push(Edge::new(ids[0], ids[1], Assignment::Boundary));
            continue;
        }
        let [a, b, c, d] = mesh.hinge(e).map(|v| x[v as usize]);
        let rho = fold_angle(a, b, c, d).value.to_degrees();
        let assignment = match e.role {
            EdgeRole::Diagonal if rho.abs() < 0.5 => Assignment::Flat,
            EdgeRole::Diagonal if rho > 0.0 => Assignment::Valley,
            EdgeRole::Diagonal => Assignment::Mountain,
            // Left free by the solve (twist folds): the way it folds.
            _ if e.assignment == Assignment::Unassigned && rho >= 0.0 => Assignment::Valley,
            _ if e.assignment == Assignment::Unassigned => Assignment::Mountain,
            _ => e.assignment,
        };
        edges.push(Edge::new(ids[0], ids[1], assignment).with_angle(rho.clamp(-180.0, 180.0)));
    }
    let faces: Vec<Face> = mesh
        .triangles
        .iter()
        .map(|t| Face::simple(t.iter().map(|&v| VertexId::new(v as usize)).collect()))
        .collect();
    let lo = flat
        .iter()
        .fold(DVec2::splat(f64::INFINITY), |m, p| m.min(*p));
    let mut pattern = CreasePattern::new();
    pattern.vertices = flat.iter().map(|p| *p - lo).collect();
    pattern.edges = edges.clone();
    pattern.faces = Some(faces.clone());
    pattern.meta.creator = Some("foldcam tessellate".into());
    let folded = FoldedState {
        positions: x.clone(),
        edges,
        faces: Some(faces),
        face_orders: Vec::new(),
    };
    Ok(Unfolded {
        pattern,
        folded,
        max_length_error,
    })
}

/// Flat positions by breadth-first placement over triangles.
fn develop(mesh: &TessMesh) -> Result<Vec<DVec2>, TessError> {
    let x = &mesh.positions;
    let n = x.len();
    let mut flat = vec![DVec2::NAN; n];
    let mut placed = vec![false; n];
    // Triangle adjacency through the edges.
    let mut across: Vec<[Option<u32>; 3]> = vec![[None; 3]; mesh.triangles.len()];
    for e in mesh.edges.iter().filter(|e| e.interior) {
        let [p, q] = e.triangles;
        for (t, other) in [(p, q), (q, p)] {
            let tri = mesh.triangles[t as usize];
            if let Some(k) = (0..3).find(|&k| {
                let (a, b) = (tri[k], tri[(k + 1) % 3]);
                (a == e.vertices[0] && b == e.vertices[1])
                    || (a == e.vertices[1] && b == e.vertices[0])
            }) {
                across[t as usize][k] = Some(other);
            }
        }
    }
    let Some(first) = mesh.triangles.first() else {
        return Err(TessError::NotADisk("no triangles".into()));
    };
    let [i, j, a] = first.map(|v| v as usize);
    flat[i] = DVec2::ZERO;
    flat[j] = DVec2::new(x[i].distance(x[j]), 0.0);
    flat[a] = apex(x[i], x[j], x[a], flat[i], flat[j]);
    for v in [i, j, a] {
        placed[v] = true;
    }
    let mut seen = vec![false; mesh.triangles.len()];
    let order = breadth_first(0, &mut seen, |t, out| {
        let tri = mesh.triangles[t];
        // The triangle across side k runs along (tri[k+1], tri[k]).
        out.extend(
            (0..3).filter_map(|k| across[t][k].map(|q| (q as usize, (tri[(k + 1) % 3], tri[k])))),
        );
    });
    for step in order {
        let Some((_, (s, e))) = step.across else {
            continue;
        };
        // Its apex lies left of the direction s → e.
        let b = mesh.apex(step.face as u32, s, e) as usize;
        let (s, e) = (s as usize, e as usize);
        if !placed[b] {
            flat[b] = apex(x[s], x[e], x[b], flat[s], flat[e]);
            placed[b] = true;
        }
    }
    if let Some(t) = seen.iter().position(|s| !s) {
        return Err(TessError::NotADisk(format!(
            "triangle {t} is not connected to the others"
        )));
    }
    Ok(flat)
}

/// First pair of triangles whose flat interiors overlap (separating-axis test with a
/// tolerance relative to the pattern size), or a flipped triangle paired with itself.
fn first_overlap(mesh: &TessMesh, flat: &[DVec2]) -> Option<(usize, usize)> {
    let tris: Vec<[DVec2; 3]> = mesh
        .triangles
        .iter()
        .map(|t| t.map(|v| flat[v as usize]))
        .collect();
    let (lo, hi) = flat.iter().fold(
        (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
        |(l, h), p| (l.min(*p), h.max(*p)),
    );
    let tol = RELATIVE * (hi - lo).max_element();
    for (k, t) in tris.iter().enumerate() {
        if (t[1] - t[0]).perp_dot(t[2] - t[0]) <= 0.0 {
            return Some((k, k));
        }
    }
    let mut order: Vec<usize> = (0..tris.len()).collect();
    let min_x = |t: &[DVec2; 3]| t.iter().map(|p| p.x).fold(f64::INFINITY, f64::min);
    let max_x = |t: &[DVec2; 3]| t.iter().map(|p| p.x).fold(f64::NEG_INFINITY, f64::max);
    order.sort_by(|&a, &b| min_x(&tris[a]).total_cmp(&min_x(&tris[b])));
    for (n, &a) in order.iter().enumerate() {
        let right = max_x(&tris[a]);
        for &b in &order[n + 1..] {
            if min_x(&tris[b]) > right - tol {
                break;
            }
            if interiors_overlap(&tris[a], &tris[b], tol) {
                return Some((a.min(b), a.max(b)));
            }
        }
    }
    None
}

/// Whether two counter-clockwise triangles overlap by more than `tol` along every axis.
fn interiors_overlap(a: &[DVec2; 3], b: &[DVec2; 3], tol: f64) -> bool {
    for tri in [a, b] {
        for k in 0..3 {
            let axis = (tri[(k + 1) % 3] - tri[k]).perp().normalize_or_zero();
            let span = |t: &[DVec2; 3]| {
                t.iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p| {
                        let d = p.dot(axis);
                        (l.min(d), h.max(d))
                    })
            };
            let ((l1, h1), (l2, h2)) = (span(a), span(b));
            if h1.min(h2) - l1.max(l2) <= tol {
                return false;
            }
        }
    }
    true
}
