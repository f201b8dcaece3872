//! Chaining edges into polylines before stroking.
//!
//! A crease line crossing many others is stored as many short edges; dashing each one alone
//! would restart the dash pattern at every vertex (short edges would all draw as solid
//! lines) and costs one contour per edge. So the edges of one assignment are joined through
//! every vertex where exactly two edges of that assignment meet in a straight line (directions
//! opposite within a relative 1e-9). Each edge ends up in exactly one polyline; a closed
//! straight chain cannot occur, but any cycle is still emitted once. Cost O(E), with two
//! arrays per vertex and one flag per edge.

use glam::DVec2;

use crate::geom::tolerance::RELATIVE;
use crate::pattern::{Assignment, CreasePattern};

const NONE: u32 = u32::MAX;

/// Vertex-to-edge incidence restricted to one assignment: the first two edges and a count.
struct Incidence {
    deg: Vec<u8>,
    edges: Vec<[u32; 2]>,
}

impl Incidence {
    fn new(cp: &CreasePattern, a: Assignment) -> Self {
        let n = cp.vertices.len();
        let mut inc = Incidence {
            deg: vec![0; n],
            edges: vec![[NONE; 2]; n],
        };
        for (i, e) in cp.edges.iter().enumerate() {
            if e.assignment != a || !drawable(cp, i) {
                continue;
            }
            for v in e.vertices {
                let v = v.index();
                let d = inc.deg[v];
                if let Some(slot) = inc.edges[v].get_mut(usize::from(d)) {
                    *slot = i as u32;
                }
                inc.deg[v] = d.saturating_add(1);
            }
        }
        inc
    }

    /// The vertex joins exactly two edges in a straight line.
    fn passes(&self, cp: &CreasePattern, v: usize) -> bool {
        if self.deg[v] != 2 {
            return false;
        }
        let [e1, e2] = self.edges[v];
        let p = cp.vertices[v];
        let d1 = far_end(cp, e1, v) - p;
        let d2 = far_end(cp, e2, v) - p;
        d1.dot(d2) < 0.0 && d1.perp_dot(d2).abs() <= RELATIVE * d1.length() * d2.length()
    }

    /// The other edge at a passing vertex.
    fn next(&self, v: usize, e: u32) -> u32 {
        let [a, b] = self.edges[v];
        if a == e { b } else { a }
    }
}

/// An edge whose two distinct vertices exist.
fn drawable(cp: &CreasePattern, i: usize) -> bool {
    let [a, b] = cp.edges[i].vertices;
    a != b && a.index() < cp.vertices.len() && b.index() < cp.vertices.len()
}

fn other_vertex(cp: &CreasePattern, e: u32, v: usize) -> usize {
    cp.edges[e as usize]
        .other(crate::pattern::VertexId::new(v))
        .index()
}

fn far_end(cp: &CreasePattern, e: u32, v: usize) -> DVec2 {
    cp.vertices[other_vertex(cp, e, v)]
}

/// Calls `emit` with the positions of every polyline of assignment `a` (at least two
/// points each).
pub(super) fn for_each_polyline(cp: &CreasePattern, a: Assignment, mut emit: impl FnMut(&[DVec2])) {
    let inc = Incidence::new(cp, a);
    let mut visited = vec![false; cp.edges.len()];
    let mut points = Vec::new();
    for (i, e) in cp.edges.iter().enumerate() {
        if e.assignment != a || visited[i] || !drawable(cp, i) {
            continue;
        }
        let (mut edge, mut v) = chain_start(cp, &inc, i as u32);
        points.clear();
        points.push(cp.vertices[v]);
        loop {
            visited[edge as usize] = true;
            v = other_vertex(cp, edge, v);
            points.push(cp.vertices[v]);
            if !inc.passes(cp, v) {
                break;
            }
            edge = inc.next(v, edge);
            if visited[edge as usize] {
                break;
            }
        }
        emit(&points);
    }
}

/// Walks back from edge `e` to the start of its chain: returns the first edge and the
/// vertex the chain starts at.
fn chain_start(cp: &CreasePattern, inc: &Incidence, e: u32) -> (u32, usize) {
    let mut edge = e;
    let mut v = cp.edges[e as usize].vertices[0].index();
    while inc.passes(cp, v) {
        let prev = inc.next(v, edge);
        if prev == e {
            break;
        }
        edge = prev;
        v = other_vertex(cp, edge, v);
    }
    (edge, v)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pattern::VertexId;

    #[test]
    fn straight_runs_join_and_corners_split() {
        let mut cp = CreasePattern::new();
        let p: Vec<VertexId> = [(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (2.0, 1.0)]
            .iter()
            .map(|&(x, y)| cp.add_vertex(DVec2::new(x, y)))
            .collect();
        // Stored out of order: 1–2, 0–1, 2–3 (a corner at vertex 2).
        cp.add_edge(p[1], p[2], Assignment::Valley);
        cp.add_edge(p[0], p[1], Assignment::Valley);
        cp.add_edge(p[2], p[3], Assignment::Valley);
        cp.add_edge(p[0], p[3], Assignment::Mountain);
        let mut lines = Vec::new();
        for_each_polyline(&cp, Assignment::Valley, |pts| lines.push(pts.len()));
        lines.sort();
        assert_eq!(lines, vec![2, 3]);
    }
}
