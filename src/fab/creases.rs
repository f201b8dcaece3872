//! Chaining edges into lines: creases, score and mark polylines, slits.
//!
//! Planarisation splits every drawn line wherever another line touches it, so one drawn
//! crease may arrive as several edges. A *chain* is a maximal walk over a chosen set of edges
//! that passes through a vertex only where that vertex *joins* its two chosen edges; the
//! caller says which vertices join:
//!
//! - perforated creases ([`crease_joins`]): no line that weakens the sheet (a cut, score,
//!   perforation or the outline, see [`weakening_degrees`]) other than the two edges meets at
//!   the vertex, both edges have the same assignment and operation, and the crease turns
//!   there by at most [`CHAIN_MAX_TURN_DEG`]. A polyline or a flattened curve between two
//!   *real* vertices (another weakening line meets, or the crease turns sharper than that) is
//!   one crease: its dashes run along the whole chain, and vertex clearances sit only at its
//!   real ends. Lines the plan leaves alone or only draws (Origami Simulator's facet lines,
//!   marks) neither end a crease nor need a clearance: a curved crease drawn as a polyline
//!   between triangulated facets stays one crease;
//! - scores, marks and pen lines ([`polyline_joins`]): no other line the plan machines meets
//!   at the vertex ([`machined_degrees`]) and both edges have the same assignment and
//!   operation, at any angle — a drawn polyline is burnt in one stroke;
//! - slits: any vertex where exactly two slit edges meet.
//!
//! Cost O(V + E). A chain whose walk returns to its start is `closed` (its first vertex is
//! repeated at the end of `vertices`).

use glam::DVec2;

use super::Operation;
use super::operations::is_continuous_weakening;
use crate::pattern::{CreasePattern, EdgeId, VertexId};

/// Largest sine of the turn between two edges that still continue one straight crease:
/// 1e-4 rad absorbs the rounding of planarisation's split points and vertex merging.
pub const COLLINEAR_SINE: f64 = 1e-4;

/// Largest turn, degrees, between two edges of one perforated crease at a vertex where no
/// other line meets. A flattened curve turns by a few degrees per point (a circle cut into
/// 64 chords, by 5.6°), so every drawn curve stays one crease; a polyline that turns more
/// sharply than this ends there, and the corner gets vertex clearances like any other.
pub const CHAIN_MAX_TURN_DEG: f64 = 30.0;

/// A maximal walk over edges.
#[derive(Clone, Debug, PartialEq)]
pub struct Chain {
    /// Vertices in walk order, one more than the edges (first repeated last when closed).
    pub vertices: Vec<VertexId>,
    /// Edges in walk order.
    pub edges: Vec<EdgeId>,
    /// The walk returns to its start.
    pub closed: bool,
}

impl Chain {
    /// The vertex positions in walk order.
    pub fn points(&self, cp: &CreasePattern) -> Vec<DVec2> {
        self.vertices.iter().map(|&v| cp.position(v)).collect()
    }
}

/// Chains the edges for which `include` holds, passing through a vertex `v` with exactly two
/// included edges `a`, `b` only when `joins(v, a, b)`.
pub fn chain_edges(
    cp: &CreasePattern,
    include: impl Fn(EdgeId) -> bool,
    joins: impl Fn(VertexId, EdgeId, EdgeId) -> bool,
) -> Vec<Chain> {
    chain_edges_paired(cp, include, |v, at| match *at {
        [a, b] if joins(v, a, b) => vec![(a, b)],
        _ => Vec::new(),
    })
}

/// Chains the edges for which `include` holds; `pairs(v, edges)` says which of the included
/// edges at `v` continue each other (each edge in at most one pair).
pub fn chain_edges_paired(
    cp: &CreasePattern,
    include: impl Fn(EdgeId) -> bool,
    pairs: impl Fn(VertexId, &[EdgeId]) -> Vec<(EdgeId, EdgeId)>,
) -> Vec<Chain> {
    let mut incident: Vec<Vec<EdgeId>> = vec![Vec::new(); cp.vertices.len()];
    for e in cp.edge_ids().filter(|&e| include(e)) {
        for v in cp.edges[e.index()].vertices {
            incident[v.index()].push(e);
        }
    }
    let links: Vec<Vec<(EdgeId, EdgeId)>> = cp
        .vertex_ids()
        .map(|v| match incident[v.index()].len() {
            0 | 1 => Vec::new(),
            _ => pairs(v, &incident[v.index()]),
        })
        .collect();
    let mut used = vec![false; cp.edges.len()];
    let mut chains = Vec::new();
    for e in cp.edge_ids().filter(|&e| include(e)) {
        if !used[e.index()] {
            chains.push(walk(cp, e, &links, &mut used));
        }
    }
    chains
}

/// The edge paired with `from` at a vertex, if any.
fn partner(links: &[(EdgeId, EdgeId)], from: EdgeId) -> Option<EdgeId> {
    links.iter().find_map(|&(a, b)| {
        if a == from {
            Some(b)
        } else if b == from {
            Some(a)
        } else {
            None
        }
    })
}

/// The chain through `start`: extends forwards from its second vertex, then, unless the walk
/// closed, backwards from its first.
fn walk(
    cp: &CreasePattern,
    start: EdgeId,
    links: &[Vec<(EdgeId, EdgeId)>],
    used: &mut [bool],
) -> Chain {
    used[start.index()] = true;
    let [a, b] = cp.edges[start.index()].vertices;
    let (fwd_v, fwd_e) = extend(cp, b, start, links, used);
    // Closed when the walk came back to `a` along the edge that continues into `start`.
    let closed = fwd_v.last() == Some(&a)
        && fwd_e
            .last()
            .is_some_and(|&x| partner(&links[a.index()], x) == Some(start));
    let (back_v, back_e) = if closed {
        (Vec::new(), Vec::new())
    } else {
        extend(cp, a, start, links, used)
    };
    let mut vertices: Vec<VertexId> = back_v.into_iter().rev().collect();
    vertices.push(a);
    vertices.push(b);
    vertices.extend(fwd_v);
    let mut edges: Vec<EdgeId> = back_e.into_iter().rev().collect();
    edges.push(start);
    edges.extend(fwd_e);
    Chain {
        vertices,
        edges,
        closed,
    }
}

/// Walks on from `v`, having arrived along `from`, while `from` continues into an unused edge.
fn extend(
    cp: &CreasePattern,
    mut v: VertexId,
    mut from: EdgeId,
    links: &[Vec<(EdgeId, EdgeId)>],
    used: &mut [bool],
) -> (Vec<VertexId>, Vec<EdgeId>) {
    let (mut vs, mut es) = (Vec::new(), Vec::new());
    while let Some(next) = partner(&links[v.index()], from) {
        if used[next.index()] {
            break;
        }
        used[next.index()] = true;
        v = cp.edges[next.index()].other(v);
        vs.push(v);
        es.push(next);
        from = next;
    }
    (vs, es)
}

/// Pairs of edges at `v` that continue each other: all of them when there are two, otherwise
/// the pairs that go on straight (see [`straight_through`]), so that crossing or branching
/// cuts stay as long strokes and the rest end at `v`.
pub fn straight_pairs(cp: &CreasePattern, v: VertexId, at: &[EdgeId]) -> Vec<(EdgeId, EdgeId)> {
    if let [a, b] = *at {
        return vec![(a, b)];
    }
    let mut taken = vec![false; at.len()];
    let mut out = Vec::new();
    for i in 0..at.len() {
        for j in i + 1..at.len() {
            if !taken[i] && !taken[j] && straight_through(cp, v, at[i], at[j]) {
                taken[i] = true;
                taken[j] = true;
                out.push((at[i], at[j]));
            }
        }
    }
    out
}

/// Whether edges `a` and `b`, both at `v`, continue each other in a straight line.
pub fn straight_through(cp: &CreasePattern, v: VertexId, a: EdgeId, b: EdgeId) -> bool {
    let p = cp.position(v);
    let da = cp.position(cp.edges[a.index()].other(v)) - p;
    let db = cp.position(cp.edges[b.index()].other(v)) - p;
    let scale = da.length() * db.length();
    scale > 0.0 && da.dot(db) < 0.0 && da.perp_dot(db).abs() <= COLLINEAR_SINE * scale
}

/// The joining rule of score, mark and pen polylines (see the module docs); `degree` counts
/// the lines that matter at each vertex ([`machined_degrees`] or [`weakening_degrees`]).
pub fn polyline_joins(
    cp: &CreasePattern,
    degree: &[usize],
    v: VertexId,
    a: EdgeId,
    b: EdgeId,
) -> bool {
    let (ea, eb) = (&cp.edges[a.index()], &cp.edges[b.index()]);
    degree[v.index()] == 2 && ea.assignment == eb.assignment
}

/// Whether edges `a` and `b`, both at `v`, continue each other with a turn of at most
/// `max_turn_deg` degrees (0 for straight on, 180 for doubling back).
pub fn turns_at_most(
    cp: &CreasePattern,
    v: VertexId,
    a: EdgeId,
    b: EdgeId,
    max_turn_deg: f64,
) -> bool {
    let p = cp.position(v);
    let da = cp.position(cp.edges[a.index()].other(v)) - p;
    let db = cp.position(cp.edges[b.index()].other(v)) - p;
    let scale = da.length() * db.length();
    if scale <= 0.0 {
        return false;
    }
    // The turn is π minus the angle between the two rays leaving `v`.
    let between = da.perp_dot(db).abs().atan2(da.dot(db));
    (std::f64::consts::PI - between).to_degrees() <= max_turn_deg
}

/// The joining rule of perforated creases (see the module docs); `degree` is
/// [`weakening_degrees`].
pub fn crease_joins(
    cp: &CreasePattern,
    degree: &[usize],
    v: VertexId,
    a: EdgeId,
    b: EdgeId,
) -> bool {
    polyline_joins(cp, degree, v, a, b)
        && (straight_through(cp, v, a, b) || turns_at_most(cp, v, a, b, CHAIN_MAX_TURN_DEG))
}

/// Number of edges for which `include` holds at every vertex of `cp`.
pub fn degrees_where(cp: &CreasePattern, include: impl Fn(EdgeId) -> bool) -> Vec<usize> {
    let mut d = vec![0; cp.vertices.len()];
    for e in cp.edge_ids().filter(|&e| include(e)) {
        let [a, b] = cp.edges[e.index()].vertices;
        d[a.index()] += 1;
        d[b.index()] += 1;
    }
    d
}

/// Number of lines at every vertex that the plan machines (any operation in `ops`, indexed by
/// [`EdgeId::index`]) or that are the sheet's outline: skipped lines (facet lines mapped to
/// no operation) are not counted.
pub fn machined_degrees(cp: &CreasePattern, ops: &[Option<Operation>]) -> Vec<usize> {
    degrees_where(cp, |e| {
        ops[e.index()].is_some() || cp.edges[e.index()].assignment.is_boundary_like()
    })
}

/// Number of lines at every vertex that weaken the sheet: cut, scored or perforated lines
/// and the outline. Marks, pen lines and skipped lines leave the material whole, so a
/// perforated crease runs on through a vertex where only such lines meet it.
pub fn weakening_degrees(cp: &CreasePattern, ops: &[Option<Operation>]) -> Vec<usize> {
    degrees_where(cp, |e| {
        is_continuous_weakening(cp, ops, e) || ops[e.index()] == Some(Operation::Perforate)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pattern::Assignment;

    #[test]
    fn collinear_run_chains_and_ends_at_a_junction() {
        let mut cp = CreasePattern::new();
        let v: Vec<VertexId> = [(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (3.0, 0.0), (2.0, 1.0)]
            .into_iter()
            .map(|(x, y)| cp.add_vertex(DVec2::new(x, y)))
            .collect();
        cp.add_edge(v[0], v[1], Assignment::Mountain);
        cp.add_edge(v[1], v[2], Assignment::Mountain);
        cp.add_edge(v[2], v[3], Assignment::Mountain);
        cp.add_edge(v[2], v[4], Assignment::Valley);
        let deg = degrees_where(&cp, |_| true);
        let chains = chain_edges(
            &cp,
            |e| cp.edges[e.index()].assignment == Assignment::Mountain,
            |v, a, b| crease_joins(&cp, &deg, v, a, b),
        );
        let mut lens: Vec<usize> = chains.iter().map(|c| c.edges.len()).collect();
        lens.sort();
        assert_eq!(lens, vec![1, 2]);
        assert!(chains.iter().all(|c| !c.closed));
    }

    #[test]
    fn a_gentle_polyline_is_one_crease_and_a_sharp_corner_ends_it() {
        // A quarter circle in 8 chords (turns of 11.25°), then a 90° corner and a straight
        // leg: the arc is one chain, the leg another.
        let mut cp = CreasePattern::new();
        let mut v: Vec<VertexId> = (0..=8)
            .map(|i| {
                let t = std::f64::consts::FRAC_PI_2 * f64::from(i) / 8.0;
                cp.add_vertex(DVec2::new(t.cos(), t.sin()) * 10.0)
            })
            .collect();
        v.push(cp.add_vertex(DVec2::new(0.0, 20.0)));
        for w in v.windows(2) {
            cp.add_edge(w[0], w[1], Assignment::Valley);
        }
        let deg = degrees_where(&cp, |_| true);
        let chains = chain_edges(&cp, |_| true, |v, a, b| crease_joins(&cp, &deg, v, a, b));
        let mut lens: Vec<usize> = chains.iter().map(|c| c.edges.len()).collect();
        lens.sort();
        assert_eq!(lens, vec![1, 8]);
    }

    #[test]
    fn crossing_cuts_pair_straight_through() {
        let mut cp = CreasePattern::new();
        let c = cp.add_vertex(DVec2::ZERO);
        for (x, y) in [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0), (1.0, 1.0)] {
            let v = cp.add_vertex(DVec2::new(x, y));
            cp.add_edge(c, v, Assignment::Cut);
        }
        let chains = chain_edges_paired(&cp, |_| true, |v, at| straight_pairs(&cp, v, at));
        let mut lens: Vec<usize> = chains.iter().map(|c| c.edges.len()).collect();
        lens.sort();
        assert_eq!(lens, vec![1, 2, 2]);
    }

    #[test]
    fn a_loop_of_degree_two_vertices_is_closed() {
        let mut cp = CreasePattern::new();
        let v: Vec<VertexId> = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)]
            .into_iter()
            .map(|(x, y)| cp.add_vertex(DVec2::new(x, y)))
            .collect();
        for i in 0..3 {
            cp.add_edge(v[i], v[(i + 1) % 3], Assignment::Cut);
        }
        let chains = chain_edges(&cp, |_| true, |_, _, _| true);
        assert_eq!(chains.len(), 1);
        assert!(chains[0].closed);
        assert_eq!(chains[0].vertices.len(), 4);
        assert_eq!(chains[0].vertices[0], chains[0].vertices[3]);
    }
}
