//! Cut lines: chaining the edges cut through into closed contours and open slits, and
//! classifying the contours as outer boundaries or holes.
//!
//! # Algorithm
//! 1. The *cut graph* holds the edges whose operation is [`Operation::Cut`] (the outline and
//!    cut edges under the usual mapping; any crease mapped to cut as well).
//! 2. Its *bridges* — edges whose removal disconnects their component, found by Tarjan's
//!    low-link depth-first search (iterative, O(V + E)) — cannot lie on a closed contour:
//!    they are dangling slits or cuts joining two loops.
//! 3. The remaining edges are traced into faces ([`find_faces`]); the clockwise cycle around
//!    each connected component (its outline) is a closed contour. Without bridges, a face
//!    never lies on both sides of an edge, so every outline passes each edge once; it may
//!    pass a vertex twice (two loops touching at a corner), which is kept as one
//!    self-touching contour.
//! 4. Cut edges on no outline (bridges, and cuts inside a component, such as a line dividing
//!    a sheet or a loop joined to the outline by a cut) are chained into slits: the chain
//!    goes on through a vertex where exactly two such edges meet, at any angle; where three
//!    or more meet, edges that continue each other in a straight line are paired (two
//!    crossing cuts stay two strokes) and the others end there. Slits are cut on their centre
//!    line, never offset; a slit chain that closes is emitted as one closed stroke.
//! 5. Nesting by point in polygon: a contour's depth is the number of contours containing
//!    the midpoint of its first edge (contours share no edge, so the midpoint is never on
//!    another contour); its container is the smallest of them by area. Even depth is an
//!    outer boundary (a part, or an island inside a hole), odd depth a hole. Cost
//!    O(C² · k) for C contours of k vertices.
//!
//! Limit: regions separated only by a shared cut (a sheet cut in two) are one contour with a
//! slit: the shared cut cannot be offset toward both parts, so each loses `kerf/2` there.

use std::collections::HashMap;

use glam::DVec2;

use super::creases::{Chain, chain_edges_paired, straight_pairs};
use super::{ContourRole, Operation};
use crate::geom::polygon::{contains_point, signed_area};
use crate::pattern::faces::find_faces;
use crate::pattern::{CreasePattern, EdgeId, VertexId};

/// A traced ring of positions with the pattern edges it runs along.
type Ring = (Vec<DVec2>, Vec<EdgeId>);

/// A closed cut contour before kerf offset.
#[derive(Clone, Debug, PartialEq)]
pub struct Contour {
    /// The ring of positions, not repeating the first point, in the order traced.
    pub ring: Vec<DVec2>,
    /// The pattern edges, in ring order.
    pub edges: Vec<EdgeId>,
    /// Outer boundary or hole.
    pub role: ContourRole,
    /// Index (in the `contours` list) of the contour directly around it.
    pub container: Option<usize>,
}

/// The cut lines of a pattern.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CutLines {
    /// Closed contours, classified.
    pub contours: Vec<Contour>,
    /// Open (or interior closed) slit chains, cut on their centre lines.
    pub slits: Vec<Chain>,
}

/// Splits the edges of `cp` whose operation in `ops` is a cut into contours and slits.
pub fn cut_lines(cp: &CreasePattern, ops: &[Option<Operation>]) -> CutLines {
    let is_cut: Vec<bool> = ops.iter().map(|o| *o == Some(Operation::Cut)).collect();
    let bridge = bridges(cp, &is_cut);
    let on_loop: Vec<bool> = (0..cp.edges.len())
        .map(|i| is_cut[i] && !bridge[i])
        .collect();
    let (rings, on_outline) = outlines(cp, &on_loop);
    let slits = chain_edges_paired(
        cp,
        |e| is_cut[e.index()] && !on_outline[e.index()],
        |v, at| straight_pairs(cp, v, at),
    );
    CutLines {
        contours: classify(rings),
        slits,
    }
}

/// Marks the bridges of the subgraph of edges with `keep` set (iterative Tarjan).
fn bridges(cp: &CreasePattern, keep: &[bool]) -> Vec<bool> {
    const UNSEEN: usize = usize::MAX;
    let mut adj: Vec<Vec<(EdgeId, VertexId)>> = vec![Vec::new(); cp.vertices.len()];
    for e in cp.edge_ids().filter(|e| keep[e.index()]) {
        let [a, b] = cp.edges[e.index()].vertices;
        adj[a.index()].push((e, b));
        adj[b.index()].push((e, a));
    }
    let mut is_bridge = vec![false; cp.edges.len()];
    let (mut disc, mut low) = (vec![UNSEEN; adj.len()], vec![0; adj.len()]);
    let mut time = 0;
    for root in 0..adj.len() {
        if disc[root] != UNSEEN || adj[root].is_empty() {
            continue;
        }
        disc[root] = time;
        low[root] = time;
        time += 1;
        // (vertex, edge it was reached by, next adjacency slot)
        let mut stack: Vec<(usize, Option<EdgeId>, usize)> = vec![(root, None, 0)];
        while let Some(top) = stack.last_mut() {
            let (v, parent_edge, slot) = *top;
            if let Some(&(e, w)) = adj[v].get(slot) {
                top.2 += 1;
                if Some(e) == parent_edge {
                    continue;
                }
                let w = w.index();
                if disc[w] == UNSEEN {
                    disc[w] = time;
                    low[w] = time;
                    time += 1;
                    stack.push((w, Some(e), 0));
                } else {
                    low[v] = low[v].min(disc[w]);
                }
            } else {
                stack.pop();
                if let (Some(&(u, _, _)), Some(e)) = (stack.last(), parent_edge) {
                    low[u] = low[u].min(low[v]);
                    if low[v] > disc[u] {
                        is_bridge[e.index()] = true;
                    }
                }
            }
        }
    }
    is_bridge
}

/// The outline cycle of every component of the edges with `keep` set, with their edges, and
/// which edges lie on some outline.
fn outlines(cp: &CreasePattern, keep: &[bool]) -> (Vec<Ring>, Vec<bool>) {
    let mut sub = CreasePattern::new();
    sub.vertices = cp.vertices.clone();
    let mut edge_of: HashMap<(VertexId, VertexId), EdgeId> = HashMap::new();
    for e in cp.edge_ids().filter(|e| keep[e.index()]) {
        let [a, b] = cp.edges[e.index()].vertices;
        sub.edges.push(cp.edges[e.index()].clone());
        edge_of.insert((a.min(b), a.max(b)), e);
    }
    let faces = find_faces(&sub);
    let cycles = faces
        .outer
        .iter()
        .chain(faces.faces.iter().flat_map(|f| f.holes.iter()));
    let mut on_outline = vec![false; cp.edges.len()];
    let mut rings = Vec::new();
    for cycle in cycles {
        let n = cycle.len();
        let edges: Vec<EdgeId> = (0..n)
            .filter_map(|i| {
                let (a, b) = (cycle[i], cycle[(i + 1) % n]);
                edge_of.get(&(a.min(b), a.max(b))).copied()
            })
            .collect();
        if n < 3 || edges.len() != n {
            continue; // cannot happen without bridges; such edges stay slits
        }
        for e in &edges {
            on_outline[e.index()] = true;
        }
        rings.push((cycle.iter().map(|&v| cp.position(v)).collect(), edges));
    }
    (rings, on_outline)
}

/// Depth, role and container of every ring (see the module docs).
fn classify(rings: Vec<Ring>) -> Vec<Contour> {
    let areas: Vec<f64> = rings
        .iter()
        .map(|(r, _)| signed_area(r.iter().copied()).abs())
        .collect();
    let mut contours = Vec::with_capacity(rings.len());
    for (i, (ring, _)) in rings.iter().enumerate() {
        let probe = ring[0].lerp(ring[1], 0.5);
        let around: Vec<usize> = (0..rings.len())
            .filter(|&j| j != i && contains_point(&rings[j].0, probe))
            .collect();
        let container = around
            .iter()
            .copied()
            .min_by(|&a, &b| areas[a].total_cmp(&areas[b]));
        let role = if around.len().is_multiple_of(2) {
            ContourRole::Outer
        } else {
            ContourRole::Hole
        };
        contours.push((role, container));
    }
    rings
        .into_iter()
        .zip(contours)
        .map(|((ring, edges), (role, container))| Contour {
            ring,
            edges,
            role,
            container,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pattern::Assignment;

    fn square(cp: &mut CreasePattern, lo: f64, hi: f64) -> Vec<VertexId> {
        let corners = [(lo, lo), (hi, lo), (hi, hi), (lo, hi)];
        let v: Vec<VertexId> = corners
            .into_iter()
            .map(|(x, y)| cp.add_vertex(DVec2::new(x, y)))
            .collect();
        for i in 0..4 {
            cp.add_edge(v[i], v[(i + 1) % 4], Assignment::Boundary);
        }
        v
    }

    #[test]
    fn dumbbell_gives_two_contours_and_a_slit() {
        let mut cp = CreasePattern::new();
        let a = square(&mut cp, 0.0, 1.0);
        let b = square(&mut cp, 3.0, 4.0);
        cp.add_edge(a[2], b[0], Assignment::Cut);
        let ops = vec![Some(Operation::Cut); cp.edges.len()];
        let lines = cut_lines(&cp, &ops);
        assert_eq!(lines.contours.len(), 2);
        assert!(lines.contours.iter().all(|c| c.role == ContourRole::Outer));
        assert_eq!(lines.slits.len(), 1);
        assert_eq!(lines.slits[0].edges, vec![EdgeId(8)]);
    }

    #[test]
    fn nested_squares_alternate_roles() {
        let mut cp = CreasePattern::new();
        square(&mut cp, 0.0, 10.0);
        square(&mut cp, 2.0, 8.0);
        square(&mut cp, 4.0, 6.0);
        let ops = vec![Some(Operation::Cut); cp.edges.len()];
        let lines = cut_lines(&cp, &ops);
        let mut seen: Vec<(i64, ContourRole, Option<i64>)> = lines
            .contours
            .iter()
            .map(|c| {
                let size = |k: usize| {
                    signed_area(lines.contours[k].ring.iter().copied())
                        .abs()
                        .round() as i64
                };
                let me = signed_area(c.ring.iter().copied()).abs().round() as i64;
                (me, c.role, c.container.map(size))
            })
            .collect();
        seen.sort_by_key(|s| s.0);
        assert_eq!(
            seen,
            vec![
                (4, ContourRole::Outer, Some(36)),
                (36, ContourRole::Hole, Some(100)),
                (100, ContourRole::Outer, None)
            ]
        );
    }
}
