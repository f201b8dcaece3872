//! Drawing lines that meet as few strokes as possible: Euler paths through a group of pen,
//! mark and score lines.
//!
//! A drawing of many short lines meeting at vertices (a triangulated grid, a tessellation's
//! creases) is a graph whose edges are the toolpaths. Each pen-up is a jump between two
//! strokes, and a connected graph with `2k` odd-degree vertices cannot be drawn in fewer than
//! `k` strokes (Euler; none fewer than one). This step reaches that bound: odd vertices are
//! paired by proximity with a virtual *jump* edge each, so every vertex has even degree; an
//! Euler circuit of each connected piece (Hierholzer's algorithm, O(E)) is cut at its jumps
//! into strokes. The strokes are then ordered like any toolpaths (nearest neighbour, local
//! improvement); consecutive toolpaths of a stroke continue each other, so the joining step
//! makes each stroke one toolpath, with one pen-down.
//!
//! Vertices are the toolpaths' end points compared bit for bit: ends made from one pattern
//! vertex by one placement are identical.

use std::collections::HashMap;

use glam::DVec2;

use super::kdtree::KdTree;
use super::visit::{Freedom, Orient, Visit, ends, freedom};
use crate::fab::{ContourRole, Operation, Toolpath};

/// Whether the step applies to `p`: one open or closed stroke of a line that may be drawn
/// through a vertex without stopping (pen, mark, score), not a contour or part of one.
fn drawable(p: &Toolpath) -> bool {
    matches!(p.op, Operation::Plot | Operation::Mark | Operation::Score)
        && p.role == ContourRole::None
        && p.container.is_none()
        && p.strokes.len() == 1
        && p.strokes[0].len() >= 2
        && freedom(p) == Freedom::Reversible
}

/// The strokes through `items` (indices into `paths`), each a run of visits that continue
/// one another, when every item is a line the step applies to; `None` otherwise (the caller
/// orders the items one by one).
pub(super) fn strokes(paths: &[Toolpath], items: &[usize]) -> Option<Vec<Vec<Visit>>> {
    if items.len() < 2 || !items.iter().all(|&i| drawable(&paths[i])) {
        return None;
    }
    let graph = Graph::new(paths, items)?;
    Some(graph.strokes(paths, items))
}

/// The lines as a multigraph: vertices are distinct end points, edges the items (and, once
/// paired, the jumps between odd vertices).
struct Graph {
    /// Vertex positions.
    points: Vec<DVec2>,
    /// End vertices of each edge; edges `items.len()..` are jumps.
    ends: Vec<[usize; 2]>,
    /// Incident edges of each vertex.
    incident: Vec<Vec<usize>>,
}

impl Graph {
    fn new(paths: &[Toolpath], items: &[usize]) -> Option<Graph> {
        let mut index: HashMap<[u64; 2], usize> = HashMap::with_capacity(items.len());
        let mut points = Vec::new();
        let mut vertex = |p: DVec2| {
            *index
                .entry([p.x.to_bits(), p.y.to_bits()])
                .or_insert_with(|| {
                    points.push(p);
                    points.len() - 1
                })
        };
        let mut edge_ends = Vec::with_capacity(items.len());
        for &i in items {
            let (a, b) = ends(&paths[i])?;
            edge_ends.push([vertex(a), vertex(b)]);
        }
        let mut incident = vec![Vec::new(); points.len()];
        for (e, &[a, b]) in edge_ends.iter().enumerate() {
            incident[a].push(e);
            incident[b].push(e);
        }
        let mut graph = Graph {
            points,
            ends: edge_ends,
            incident,
        };
        graph.pair_odd_vertices();
        Some(graph)
    }

    /// Joins the odd vertices in pairs, each with its nearest unpaired odd vertex (greedy,
    /// in vertex order), by a jump edge.
    fn pair_odd_vertices(&mut self) {
        let odd: Vec<usize> = (0..self.points.len())
            .filter(|&v| self.incident[v].len() % 2 == 1)
            .collect();
        let mut tree = KdTree::new(odd.iter().map(|&v| self.points[v]).collect());
        let mut paired = vec![false; odd.len()];
        for k in 0..odd.len() {
            if paired[k] {
                continue;
            }
            paired[k] = true;
            tree.delete(k);
            let Some(m) = tree.nearest(self.points[odd[k]]) else {
                break;
            };
            paired[m] = true;
            tree.delete(m);
            let e = self.ends.len();
            self.ends.push([odd[k], odd[m]]);
            self.incident[odd[k]].push(e);
            self.incident[odd[m]].push(e);
        }
    }

    /// Every edge once, as circuits cut at their jumps into strokes of visits.
    fn strokes(&self, paths: &[Toolpath], items: &[usize]) -> Vec<Vec<Visit>> {
        let real = items.len();
        let mut used = vec![false; self.ends.len()];
        let mut next = vec![0usize; self.points.len()];
        let mut out = Vec::new();
        // Pieces with jumps first (from a jump's end), then those without (closed circuits).
        let starts = (real..self.ends.len())
            .map(|e| self.ends[e][0])
            .chain((0..real).map(|e| self.ends[e][0]));
        for start in starts {
            if self.incident[start].iter().all(|&e| used[e]) {
                continue;
            }
            let mut circuit = self.circuit(start, &mut used, &mut next);
            // A circuit is closed: begun just after a jump, cutting at the jumps leaves whole
            // strokes (none split across the circuit's start).
            if let Some(k) = circuit.iter().position(|&(e, _)| e >= real) {
                circuit.rotate_left(k + 1);
            }
            let mut stroke = Vec::new();
            for (e, from) in circuit {
                if e >= real {
                    if !stroke.is_empty() {
                        out.push(std::mem::take(&mut stroke));
                    }
                    continue;
                }
                let item = items[e];
                let forward = self.ends[e][0] == from;
                let (a, b) = ends(&paths[item]).unwrap_or_default();
                stroke.push(Visit {
                    item,
                    orient: if forward {
                        Orient::Forward
                    } else {
                        Orient::Reversed
                    },
                    entry: if forward { a } else { b },
                    exit: if forward { b } else { a },
                    turnable: true,
                });
            }
            if !stroke.is_empty() {
                out.push(stroke);
            }
        }
        out
    }

    /// An Euler circuit from `start` over the unused edges of its piece (Hierholzer's
    /// algorithm, iterative): each edge with the vertex it is left from, in walk order.
    fn circuit(&self, start: usize, used: &mut [bool], next: &mut [usize]) -> Vec<(usize, usize)> {
        // (vertex reached, edge taken to reach it, vertex it was taken from)
        let mut stack: Vec<(usize, Option<(usize, usize)>)> = vec![(start, None)];
        let mut circuit = Vec::new();
        while let Some(&(v, came)) = stack.last() {
            let mut step = None;
            while next[v] < self.incident[v].len() {
                let e = self.incident[v][next[v]];
                next[v] += 1;
                if !used[e] {
                    used[e] = true;
                    let [a, b] = self.ends[e];
                    step = Some((if a == v { b } else { a }, e));
                    break;
                }
            }
            match step {
                Some((w, e)) => stack.push((w, Some((e, v)))),
                None => {
                    stack.pop();
                    if let Some(taken) = came {
                        circuit.push(taken);
                    }
                }
            }
        }
        circuit.reverse();
        circuit
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pattern::EdgeId;

    fn line(a: (f64, f64), b: (f64, f64)) -> Toolpath {
        Toolpath {
            op: Operation::Plot,
            strokes: vec![vec![DVec2::new(a.0, a.1), DVec2::new(b.0, b.1)]],
            role: ContourRole::None,
            container: None,
            edges: vec![EdgeId(0)],
        }
    }

    /// Every stroke's visits continue one another; every item is visited once.
    fn assert_strokes(paths: &[Toolpath], strokes: &[Vec<Visit>]) {
        let mut seen: Vec<usize> = strokes.iter().flatten().map(|v| v.item).collect();
        seen.sort_unstable();
        assert!(seen.iter().copied().eq(0..paths.len()), "{seen:?}");
        for s in strokes {
            for w in s.windows(2) {
                assert_eq!(w[0].exit, w[1].entry, "{s:?}");
            }
        }
    }

    #[test]
    fn a_grid_is_drawn_in_as_few_strokes_as_its_odd_vertices_allow() {
        // A 4 × 4 grid of unit squares: 40 unit lines, shuffled. Its odd vertices are the
        // 3 × 4 non-corner ones on the rim (degree 3): 12, so 6 strokes at least.
        let mut paths = Vec::new();
        for i in 0..=4 {
            for j in 0..4 {
                let (x, y) = (f64::from(i), f64::from(j));
                paths.push(line((x, y), (x, y + 1.0)));
                paths.push(line((y, x), (y + 1.0, x)));
            }
        }
        let mut rng = crate::test_rng::TestRng::new(5);
        for k in (1..paths.len()).rev() {
            let m = (rng.unit() * (k + 1) as f64) as usize % (k + 1);
            paths.swap(k, m);
        }
        let items: Vec<usize> = (0..paths.len()).collect();
        let strokes = strokes(&paths, &items).expect("all lines");
        assert_strokes(&paths, &strokes);
        assert_eq!(strokes.len(), 6);
    }

    #[test]
    fn a_closed_figure_is_one_stroke_and_contours_are_left_alone() {
        let square = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (0.0, 0.0)];
        let paths: Vec<Toolpath> = square.windows(2).map(|w| line(w[0], w[1])).collect();
        let items: Vec<usize> = (0..paths.len()).collect();
        let strokes = strokes(&paths, &items).expect("all lines");
        assert_strokes(&paths, &strokes);
        assert_eq!(strokes.len(), 1);
        let mut cut = paths.clone();
        cut[0].op = Operation::Cut;
        assert!(super::strokes(&cut, &items).is_none());
    }
}
