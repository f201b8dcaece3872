//! The moving-face search of Miyazaki et al. (1992) §4.1 on one face group, in the group's plane coordinates.
//!
//! Starting from the seed faces (rule ①: the face of the picked vertex, or the faces a script
//! names), a face becomes moving when
//! - ② it shares an edge with a moving face on the moving side of the fold line,
//! - ③ (folding up, bending) its moving part overlaps a moving face's moving part and it lies
//!   on the side the faces rotate towards (above for a turn towards the group normal),
//! - ④ (tucking in) it lies between two moving faces in the stack and its moving part overlaps
//!   both of theirs;
//!
//! repeated until nothing changes; the rest stay (⑤). Overlap tests use bounding boxes first.
//!
//! Faces of other planes (other face groups) joined to a moving face by an edge beyond the
//! fold line are carried along rigidly, and so is every face joined to a carried one (rule ②
//! across planes: the fold line lies in one plane and cuts no other). A carried face joined
//! beyond the line to a face of the folded group makes that face move; one joined to the
//! stationary side holds the paper fast, and the fold is refused. Tuck-ins carry nothing.

use glam::{DVec2, DVec3};

use super::FoldError;
use super::geometry::{Line2, overlaps, split_into};
use super::state::{Folding, State};
use crate::geom::Segment;

/// How the moving faces turn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Turning {
    /// All towards +normal (`+1.0`) or −normal (`−1.0`) of the group.
    Towards(f64),
    /// Tucking in: the lower half turns up, the upper half down.
    Tuck,
}

/// One face group seen in its plane: positions, parts on either side of the fold line.
pub(super) struct Layer {
    /// Index of the group in [`State::groups`].
    pub group: usize,
    /// Face indices in stack order (bottom first).
    pub stack: Vec<usize>,
    /// Plane frame: origin and in-plane axes.
    pub origin: DVec3,
    pub u: DVec3,
    pub v: DVec3,
    pub normal: DVec3,
    /// The fold line in plane coordinates.
    pub line: Line2,
    /// +1 when the moving side is left of the line, −1 when right.
    pub side: f64,
    /// Every face's parts on the moving and the stationary side, one after the other.
    parts: Vec<DVec2>,
    /// Per stack position: the ranges of `parts` holding its moving and its stationary part.
    ranges: Vec<[(u32, u32); 2]>,
    boxes: Vec<(DVec2, DVec2)>,
}

impl Layer {
    /// Sets up group `group` of `state` for a fold along `line` (plane coordinates).
    pub fn new(
        folding: &Folding,
        state: &State,
        group: usize,
        frame: (DVec3, DVec3, DVec3),
        line: Line2,
        side: f64,
    ) -> Layer {
        let g = &state.groups[group];
        let (origin, u, v) = frame;
        let tol = folding.tol;
        let mut parts = Vec::with_capacity(g.stack.len() * 8);
        let mut ranges = Vec::with_capacity(g.stack.len());
        let mut boxes = Vec::with_capacity(g.stack.len());
        let mut poly: Vec<DVec2> = Vec::with_capacity(8);
        let mut right: Vec<DVec2> = Vec::with_capacity(8);
        for &f in &g.stack {
            let face = &state.faces[f];
            poly.clear();
            poly.extend(folding.polygon(face).iter().map(|p| {
                let q = face.transform.transform_point3(p.extend(0.0)) - origin;
                DVec2::new(q.dot(u), q.dot(v))
            }));
            let start = parts.len();
            split_into(&poly, &line, tol, &mut parts, &mut right);
            let middle = parts.len();
            parts.append(&mut right);
            let (left, right) = (
                (start as u32, middle as u32),
                (middle as u32, parts.len() as u32),
            );
            let (moving, fixed) = if side > 0.0 {
                (left, right)
            } else {
                (right, left)
            };
            boxes.push(bounds(&parts[moving.0 as usize..moving.1 as usize]));
            ranges.push([moving, fixed]);
        }
        Layer {
            group,
            stack: g.stack.clone(),
            origin,
            u,
            v,
            normal: g.normal,
            line,
            side,
            parts,
            ranges,
            boxes,
        }
    }

    /// The part of the face at stack position `i` on the moving side (empty if none), in
    /// plane coordinates, with the orientation the face has in the plane.
    pub fn moving_part(&self, i: usize) -> &[DVec2] {
        let (a, b) = self.ranges[i][0];
        &self.parts[a as usize..b as usize]
    }

    /// The part of the face at stack position `i` on the stationary side (empty if none).
    pub fn fixed_part(&self, i: usize) -> &[DVec2] {
        let (a, b) = self.ranges[i][1];
        &self.parts[a as usize..b as usize]
    }

    /// A point of space in plane coordinates.
    pub fn to_plane(&self, p: DVec3) -> DVec2 {
        DVec2::new((p - self.origin).dot(self.u), (p - self.origin).dot(self.v))
    }

    /// Whether the moving parts at stack positions `a` and `b` overlap.
    fn moving_overlap(&self, a: usize, b: usize, tol: f64) -> bool {
        let (la, ha) = self.boxes[a];
        let (lb, hb) = self.boxes[b];
        if la.x > hb.x || lb.x > ha.x || la.y > hb.y || lb.y > ha.y {
            return false;
        }
        overlaps(self.moving_part(a), self.moving_part(b), tol)
    }

    /// The smallest and largest signed distance, positive on the moving side, of the ends of
    /// `edge` (a sheet segment of face `face`) from the fold line, once placed in the plane.
    fn edge_sides(&self, state: &State, face: usize, edge: Segment) -> (f64, f64) {
        let t = &state.faces[face].transform;
        let side = |s: DVec2| {
            self.side
                * self
                    .line
                    .side(self.to_plane(t.transform_point3(s.extend(0.0))))
        };
        let (p, q) = (side(edge.a), side(edge.b));
        (p.min(q), p.max(q))
    }
}

/// Bounding box of a polygon (inverted for an empty one).
fn bounds(poly: &[DVec2]) -> (DVec2, DVec2) {
    crate::geom::Rect::covering(poly.iter().copied()).corners()
}

/// The result of the search: who moves.
pub(super) struct Moving {
    /// Per stack position of the folded group: whether the face (its moving part) turns.
    pub in_layer: Vec<bool>,
    /// Faces of other groups carried along rigidly (indices into [`State::faces`]).
    pub carried: Vec<usize>,
}

/// The moving faces from the seed positions (§4.1 ①–⑤), and the faces of other planes they
/// carry along. Errors: a carried face is also joined to the stationary side
/// ([`FoldError::CarriedFaceHeld`]), or a tuck-in would carry one
/// ([`FoldError::AttachedOutOfPlane`]).
pub(super) fn moving_faces(
    folding: &Folding,
    state: &State,
    layer: &Layer,
    seeds: &[usize],
    turning: Turning,
) -> Result<Moving, FoldError> {
    let n = layer.stack.len();
    let tol = folding.tol;
    let mut pos = vec![usize::MAX; state.faces.len()];
    for (i, &f) in layer.stack.iter().enumerate() {
        pos[f] = i;
    }
    let mut moving = vec![false; n];
    let mut queue: Vec<usize> = Vec::new();
    for &s in seeds {
        if !layer.moving_part(s).is_empty() && !moving[s] {
            moving[s] = true;
            queue.push(s);
        }
    }
    let every_candidate_moves = (0..n).all(|i| moving[i] || layer.moving_part(i).is_empty());
    let mut unmoved = Unmoved::new(n);
    for (i, &m) in moving.iter().enumerate() {
        if m || layer.moving_part(i).is_empty() {
            unmoved.remove(i);
        }
    }
    let mut is_carried = vec![false; state.faces.len()];
    let mut carried: Vec<usize> = Vec::new();
    let mut next_carried = 0;
    loop {
        loop {
            while let Some(a) = queue.pop() {
                let fa = layer.stack[a];
                // ② edge-connected on the moving side.
                for n in &state.faces[fa].neighbours {
                    let b = pos[n.face];
                    if b == usize::MAX {
                        if !is_carried[n.face] && layer.edge_sides(state, fa, n.edge).1 > tol {
                            is_carried[n.face] = true;
                            carried.push(n.face);
                        }
                        continue;
                    }
                    if every_candidate_moves {
                        continue;
                    }
                    if !moving[b] && layer.edge_sides(state, fa, n.edge).1 > tol {
                        moving[b] = true;
                        unmoved.remove(b);
                        queue.push(b);
                    }
                }
                // ③ overlapping on the rotation side: the still unmoved candidates beyond `a`
                // on the turning side.
                if let Turning::Towards(sign) = turning {
                    if every_candidate_moves {
                        continue;
                    }
                    let mut b = unmoved.next(a, sign);
                    while let Some(c) = b {
                        if layer.moving_overlap(a, c, tol) {
                            moving[c] = true;
                            unmoved.remove(c);
                            queue.push(c);
                        }
                        b = unmoved.next(c, sign);
                    }
                }
            }
            // Faces of other planes: carried with their neighbours.
            let Some(&c) = carried.get(next_carried) else {
                break;
            };
            next_carried += 1;
            for n in &state.faces[c].neighbours {
                let b = pos[n.face];
                if b == usize::MAX {
                    if !is_carried[n.face] {
                        is_carried[n.face] = true;
                        carried.push(n.face);
                    }
                    continue;
                }
                let (lo, hi) = layer.edge_sides(state, n.face, n.edge);
                if lo < -tol {
                    return Err(FoldError::CarriedFaceHeld);
                }
                if hi > tol && !moving[b] {
                    moving[b] = true;
                    unmoved.remove(b);
                    queue.push(b);
                }
            }
        }
        // ④ between two moving faces (tucking in).
        if turning != Turning::Tuck {
            break;
        }
        let added = between_moving(layer, &mut moving, tol);
        if added.is_empty() {
            break;
        }
        queue = added;
    }
    if turning == Turning::Tuck && !carried.is_empty() {
        return Err(FoldError::AttachedOutOfPlane);
    }
    Ok(Moving {
        in_layer: moving,
        carried,
    })
}

/// The stack positions not (yet) moving, as two skip lists with path compression, so that
/// rule ③ walks only over candidates (amortised near-constant time per step).
struct Unmoved {
    /// `up[i]`: a position ≥ `i` that may be unmoved (`n` = none).
    up: Vec<usize>,
    /// `down[i + 1]`: a position ≤ `i` that may be unmoved, plus one (`0` = none).
    down: Vec<usize>,
}

impl Unmoved {
    fn new(n: usize) -> Unmoved {
        Unmoved {
            up: (0..=n).collect(),
            down: (0..=n).collect(),
        }
    }

    fn remove(&mut self, i: usize) {
        self.up[i] = i + 1;
        self.down[i + 1] = i;
    }

    /// The nearest unmoved position above `a` (`sign` > 0) or below it.
    fn next(&mut self, a: usize, sign: f64) -> Option<usize> {
        if sign > 0.0 {
            let b = find(&mut self.up, a + 1);
            (b + 1 < self.up.len()).then_some(b)
        } else {
            find(&mut self.down, a).checked_sub(1)
        }
    }
}

/// The root of `i` in the forest `parent` (a root is its own parent), compressing the path.
fn find(parent: &mut [usize], i: usize) -> usize {
    let mut root = i;
    while parent[root] != root {
        root = parent[root];
    }
    let mut j = i;
    while parent[j] != root {
        let next = parent[j];
        parent[j] = root;
        j = next;
    }
    root
}

/// Rule ④: faces between two moving ones whose moving part overlaps both; returns those added.
fn between_moving(layer: &Layer, moving: &mut [bool], tol: f64) -> Vec<usize> {
    let n = moving.len();
    let mut added = Vec::new();
    for b in 0..n {
        if moving[b] || layer.moving_part(b).is_empty() {
            continue;
        }
        let below = (0..b).any(|a| moving[a] && layer.moving_overlap(a, b, tol));
        let above = (b + 1..n).any(|c| moving[c] && layer.moving_overlap(c, b, tol));
        if below && above {
            added.push(b);
        }
    }
    for &b in &added {
        moving[b] = true;
    }
    added
}
