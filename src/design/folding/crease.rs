//! The crease pattern cut from a fold sequence, and the folded state of every step on its
//! topology.
//!
//! **Pattern.** The faces of the final state, unfolded (each face's sheet polygon), are the
//! pattern's faces; corners closer than 100 × the simulator's tolerance merge, and a corner
//! lying on another face's edge splits that edge (T-junctions). An edge used by one face is the
//! boundary (B); an edge between faces `f` (on its left) and `g` gets the fold angle of the
//! final state, `atan2(−(n_f × n_g)·d, n_f·n_g)` with `d` the edge direction in space and `n`
//! the face normals (FOLD's sign: valley positive). A flat fold (±180°) takes its sign from the
//! face stack: valley when `g` lies above `f` on the side of `f`'s normal. Folds that ended at
//! 0° are flat creases (F).
//!
//! **Steps.** Every step's state is expressed on the final pattern's vertices and faces: each
//! pattern face lies inside one face of that step (its face-tree ancestor), whose transform
//! places it. `faceOrders` lists every pair of overlapping faces of one flat group.

use std::collections::HashMap;

use glam::{DVec2, DVec3};

use super::geometry::{overlaps, plane_basis};
use super::state::{CellId, Folding, State};
use crate::geom::HashGrid;
use crate::geom::tolerance::{ANGLE_DEG, RELATIVE};
use crate::pattern::{Assignment, CreasePattern, Edge, Face, FaceId, FoldedState, VertexId};

/// A crease pattern with, for each of its faces, the face-tree cell it unfolds.
#[derive(Clone, Debug, PartialEq)]
pub struct SheetPattern {
    /// The pattern, millimetres, faces counter-clockwise.
    pub pattern: CreasePattern,
    /// For each pattern face, its cell (a face of the final state).
    pub cells: Vec<CellId>,
    /// For each pattern face, its index in the final state's faces.
    pub faces: Vec<usize>,
}

/// The crease pattern of the current state (see the module docs).
pub fn crease_pattern(folding: &Folding) -> SheetPattern {
    let state = folding.current();
    let tol = folding.tol * 100.0;
    let mut vertices: Vec<DVec2> = Vec::new();
    let mut grid = HashGrid::new(tol);
    let corners: Vec<Vec<usize>> = state
        .faces
        .iter()
        .map(|f| {
            folding
                .polygon(f)
                .iter()
                .map(|&p| vertex_id(&mut vertices, &mut grid, p, tol))
                .collect()
        })
        .collect();
    let rings: Vec<Vec<usize>> = corners
        .iter()
        .map(|c| with_t_junctions(c, &vertices, tol))
        .collect();
    let mut edge_faces: HashMap<(usize, usize), Vec<(usize, bool)>> = HashMap::new();
    let mut order = Vec::new();
    for (f, ring) in rings.iter().enumerate() {
        for i in 0..ring.len() {
            let (a, b) = (ring[i], ring[(i + 1) % ring.len()]);
            let key = (a.min(b), a.max(b));
            let entry = edge_faces.entry(key).or_default();
            if entry.is_empty() {
                order.push(key);
            }
            entry.push((f, a < b));
        }
    }
    let mut cp = CreasePattern::new();
    cp.vertices = vertices.clone();
    for key in order {
        let faces = &edge_faces[&key];
        let edge = match faces.as_slice() {
            [(f, forward), (g, _)] => {
                let (left, right) = if *forward { (*f, *g) } else { (*g, *f) };
                let d = vertices[key.1] - vertices[key.0];
                crease_edge(state, left, right, d)
            }
            _ => Edge::new(VertexId(0), VertexId(0), Assignment::Boundary),
        };
        let mut edge = edge;
        edge.vertices = [VertexId(key.0 as u32), VertexId(key.1 as u32)];
        cp.edges.push(edge);
    }
    cp.faces = Some(
        rings
            .iter()
            .map(|r| Face::simple(r.iter().map(|&v| VertexId(v as u32)).collect()))
            .collect(),
    );
    SheetPattern {
        pattern: cp,
        cells: state.faces.iter().map(|f| f.cell).collect(),
        faces: (0..state.faces.len()).collect(),
    }
}

/// The id of the vertex at `p`, merging with one within `tol`.
fn vertex_id(vertices: &mut Vec<DVec2>, grid: &mut HashGrid, p: DVec2, tol: f64) -> usize {
    if let Some(id) = grid.near(p).find(|&i| vertices[i].distance(p) <= tol) {
        return id;
    }
    vertices.push(p);
    grid.insert(p, vertices.len() - 1);
    vertices.len() - 1
}

/// A face's corner ring with the other vertices lying on its edges inserted in order.
fn with_t_junctions(corners: &[usize], vertices: &[DVec2], tol: f64) -> Vec<usize> {
    let n = corners.len();
    let mut ring = Vec::with_capacity(n);
    for i in 0..n {
        let (a, b) = (corners[i], corners[(i + 1) % n]);
        ring.push(a);
        let (pa, pb) = (vertices[a], vertices[b]);
        let d = pb - pa;
        let len2 = d.length_squared();
        let mut on: Vec<(f64, usize)> = (0..vertices.len())
            .filter(|&v| v != a && v != b)
            .filter_map(|v| {
                let t = (vertices[v] - pa).dot(d) / len2;
                let off = (pa + d * t).distance(vertices[v]);
                (t > 0.0 && t < 1.0 && off <= tol).then_some((t, v))
            })
            .collect();
        on.sort_by(|x, y| x.0.total_cmp(&y.0));
        ring.extend(on.into_iter().map(|(_, v)| v));
    }
    ring
}

/// The crease between faces `left` and `right` of `state` along sheet direction `d`.
fn crease_edge(state: &State, left: usize, right: usize, d: DVec2) -> Edge {
    let angle = fold_angle(state, left, right, d);
    let assignment = if angle.abs() < ANGLE_DEG {
        Assignment::Flat
    } else if angle > 0.0 {
        Assignment::Valley
    } else {
        Assignment::Mountain
    };
    Edge::new(VertexId(0), VertexId(0), assignment).with_angle(if angle.abs() < ANGLE_DEG {
        0.0
    } else {
        angle
    })
}

/// Fold angle in degrees (valley positive) between face `left` and face `right` of `state`,
/// joined along the sheet direction `d` (with `left` on its left).
pub fn fold_angle(state: &State, left: usize, right: usize, d: DVec2) -> f64 {
    let (nf, ng) = (state.face_normal(left), state.face_normal(right));
    let d3 = (state.faces[left].transform.matrix3 * d.extend(0.0)).normalize();
    let s = -nf.cross(ng).dot(d3);
    let c = nf.dot(ng);
    if c < 0.0 && s.abs() < RELATIVE {
        return if above_along(state, right, left, nf) {
            180.0
        } else {
            -180.0
        };
    }
    s.atan2(c).to_degrees()
}

/// Whether face `a` lies above face `b` on the side of `direction` (same group assumed).
fn above_along(state: &State, a: usize, b: usize, direction: DVec3) -> bool {
    let layers = state.layers();
    let (ga, pa) = layers[a];
    let (gb, pb) = layers[b];
    if ga != gb {
        return true;
    }
    (pa > pb) == (direction.dot(state.groups[ga].normal) > 0.0)
}

/// The folded state of every step (0 = the flat sheet) on the topology of `sheet`: vertex
/// positions, the fold angle of every edge at that step, and `faceOrders` for flat layers.
pub fn step_states(folding: &Folding, sheet: &SheetPattern) -> Vec<FoldedState> {
    folding
        .steps()
        .iter()
        .map(|step| state_on_pattern(folding, &step.state, sheet))
        .collect()
}

fn state_on_pattern(folding: &Folding, state: &State, sheet: &SheetPattern) -> FoldedState {
    let cp = &sheet.pattern;
    let mut live = vec![usize::MAX; folding.cells().len()];
    for (i, f) in state.faces.iter().enumerate() {
        live[f.cell.index()] = i;
    }
    let owner: Vec<usize> = sheet
        .cells
        .iter()
        .map(|&c| {
            let ancestry = folding.ancestry(c);
            ancestry
                .iter()
                .map(|a| live[a.index()])
                .find(|&i| i != usize::MAX)
                .unwrap_or(0)
        })
        .collect();
    let faces = cp.faces.clone().unwrap_or_default();
    let mut positions = vec![DVec3::ZERO; cp.vertices.len()];
    for (j, face) in faces.iter().enumerate() {
        let t = state.faces[owner[j]].transform;
        for v in &face.outer {
            positions[v.index()] = t.transform_point3(cp.vertices[v.index()].extend(0.0));
        }
    }
    let edges = step_edges(state, cp, &faces, &owner);
    let face_orders = face_orders(folding, state, cp, &faces, &owner);
    FoldedState {
        positions,
        edges,
        faces: Some(faces),
        face_orders,
    }
}

/// The pattern's edges with the fold angles of `state`.
fn step_edges(state: &State, cp: &CreasePattern, faces: &[Face], owner: &[usize]) -> Vec<Edge> {
    let mut left_of: HashMap<(u32, u32), usize> = HashMap::new();
    for (j, face) in faces.iter().enumerate() {
        let n = face.outer.len();
        for i in 0..n {
            left_of.insert((face.outer[i].0, face.outer[(i + 1) % n].0), j);
        }
    }
    cp.edges
        .iter()
        .map(|e| {
            let [a, b] = e.vertices;
            match (left_of.get(&(a.0, b.0)), left_of.get(&(b.0, a.0))) {
                (Some(&f), Some(&g)) if owner[f] != owner[g] => {
                    let d = cp.vertices[b.index()] - cp.vertices[a.index()];
                    let mut edge = crease_edge(state, owner[f], owner[g], d);
                    edge.vertices = e.vertices;
                    edge
                }
                (Some(_), Some(_)) => Edge::new(a, b, Assignment::Flat).with_angle(0.0),
                _ => e.clone(),
            }
        })
        .collect()
}

/// `faceOrders` of `state`: `[f, g, s]` for overlapping pattern faces of one group, `s = +1`
/// when `f` lies above `g` on the side of `g`'s normal.
fn face_orders(
    folding: &Folding,
    state: &State,
    cp: &CreasePattern,
    faces: &[Face],
    owner: &[usize],
) -> Vec<(FaceId, FaceId, i8)> {
    let layers = state.layers();
    let mut out = Vec::new();
    let polys: Vec<Vec<DVec2>> = faces
        .iter()
        .enumerate()
        .map(|(j, face)| {
            let f = owner[j];
            let g = &state.groups[layers[f].0];
            let (u, v) = plane_basis(g.normal);
            face.outer
                .iter()
                .map(|&id| {
                    let p = state.faces[f]
                        .transform
                        .transform_point3(cp.vertices[id.index()].extend(0.0));
                    DVec2::new((p - g.origin).dot(u), (p - g.origin).dot(v))
                })
                .collect()
        })
        .collect();
    for a in 0..faces.len() {
        for b in a + 1..faces.len() {
            let (fa, fb) = (owner[a], owner[b]);
            let ((ga, pa), (gb, pb)) = (layers[fa], layers[fb]);
            if fa == fb || ga != gb || !overlaps(&polys[a], &polys[b], folding.tol * 100.0) {
                continue;
            }
            let up = state.groups[ga].normal;
            let b_up = state.face_normal(fb).dot(up) > 0.0;
            let a_above_b = (pa > pb) == b_up;
            out.push((
                FaceId(a as u32),
                FaceId(b as u32),
                if a_above_b { 1 } else { -1 },
            ));
        }
    }
    out
}
