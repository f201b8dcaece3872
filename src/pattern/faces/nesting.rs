//! Which face holds each component: a ray cast straight down from the component's lowest
//! vertex (lowest y, then lowest x) meets first the edge just below it; the cycle on that
//! edge's upper side is either a face (the container) or the outline of another component,
//! in which case the answer is that component's container. No edge of the component itself
//! lies strictly below its lowest vertex, so the ray never meets its own component.
//!
//! Edges count on the half-open x-range `[left, right)`, so at a shared vertex only the edges
//! leaving it rightwards are seen, as if the ray were cast just right of the vertex; among
//! edges at the same height there, the steepest is the lowest boundary of what lies above.

use glam::DVec2;

use super::super::vertex_fan::VertexFans;
use super::super::{CreasePattern, EdgeId, VertexId};
use super::trace::Traced;

/// For each outline cycle (indices into `traced.cycles`), the face that contains it, or `None`
/// when it is on the unbounded face.
pub(super) fn containing_faces(
    cp: &CreasePattern,
    fans: &VertexFans,
    traced: &Traced,
    face_of_cycle: &[Option<usize>],
    outlines: &[usize],
) -> Vec<Option<usize>> {
    if outlines.len() <= 1 {
        return vec![None; outlines.len()];
    }
    let index = ColumnIndex::new(cp);
    let below: Vec<Option<usize>> = outlines
        .iter()
        .map(|&c| {
            let lowest = lowest_vertex(cp, &traced.cycles[c]);
            let edge = index.edge_below(cp, cp.position(lowest))?;
            Some(traced.cycle_of[upper_half_edge(cp, fans, edge)] as usize)
        })
        .collect();
    let slot_of_outline: std::collections::HashMap<usize, usize> =
        outlines.iter().enumerate().map(|(i, &c)| (c, i)).collect();
    (0..outlines.len())
        .map(|mut i| {
            // Follow outline → outline until a face or nothing; outlines nest as a forest, so
            // the walk ends (bounded by the count anyway).
            for _ in 0..=outlines.len() {
                match below[i] {
                    None => return None,
                    Some(c) => match face_of_cycle[c] {
                        Some(f) => return Some(f),
                        None => i = *slot_of_outline.get(&c)?,
                    },
                }
            }
            None
        })
        .collect()
}

fn lowest_vertex(cp: &CreasePattern, cycle: &[VertexId]) -> VertexId {
    let key = |v: &&VertexId| {
        let p = cp.position(**v);
        (p.y, p.x)
    };
    *cycle
        .iter()
        .min_by(|a, b| {
            key(a)
                .partial_cmp(&key(b))
                .unwrap_or(std::cmp::Ordering::Equal)
        })
        .unwrap_or(&cycle[0])
}

/// The half-edge of `edge` that runs left to right: the face on its left is above the edge.
fn upper_half_edge(cp: &CreasePattern, fans: &VertexFans, edge: EdgeId) -> usize {
    let [a, b] = cp.edges[edge.index()].vertices;
    let from = if cp.position(a).x <= cp.position(b).x {
        a
    } else {
        b
    };
    let row = fans.offsets[from.index()] as usize;
    let k = fans
        .of(from)
        .iter()
        .position(|s| s.edge == edge)
        .unwrap_or(0);
    row + k
}

/// Non-vertical edges bucketed by the x-columns they span.
struct ColumnIndex {
    x0: f64,
    inv: f64,
    columns: usize,
    runs: Vec<u32>,
    edges: Vec<u32>,
}

impl ColumnIndex {
    fn new(cp: &CreasePattern) -> Self {
        let (lo, hi) = cp.bounds().unwrap_or((DVec2::ZERO, DVec2::ONE));
        let width = (hi.x - lo.x).max(f64::MIN_POSITIVE);
        let total_span: f64 = cp.edge_ids().map(|e| span(cp, e).1 - span(cp, e).0).sum();
        let n = cp.edges.len().max(1) as f64;
        // About √E columns, fewer when long edges would make the index much larger than 4E.
        let by_size = n.sqrt().ceil();
        let by_memory = (4.0 * n * width / total_span.max(f64::MIN_POSITIVE)).floor();
        let columns = by_size.min(by_memory).max(1.0) as usize;
        let mut index = ColumnIndex {
            x0: lo.x,
            inv: columns as f64 / width,
            columns,
            runs: vec![0; columns + 1],
            edges: Vec::new(),
        };
        for e in cp.edge_ids() {
            if let Some((c0, c1)) = index.columns_of(cp, e) {
                for c in c0..=c1 {
                    index.runs[c + 1] += 1;
                }
            }
        }
        for c in 0..columns {
            index.runs[c + 1] += index.runs[c];
        }
        let mut fill = index.runs.clone();
        index.edges = vec![0; index.runs[columns] as usize];
        for e in cp.edge_ids() {
            if let Some((c0, c1)) = index.columns_of(cp, e) {
                for slot in &mut fill[c0..=c1] {
                    index.edges[*slot as usize] = e.0;
                    *slot += 1;
                }
            }
        }
        index
    }

    fn column(&self, x: f64) -> usize {
        (((x - self.x0) * self.inv).floor().max(0.0) as usize).min(self.columns - 1)
    }

    fn columns_of(&self, cp: &CreasePattern, e: EdgeId) -> Option<(usize, usize)> {
        let (l, r) = span(cp, e);
        (r > l).then(|| (self.column(l), self.column(r)))
    }

    /// The edge met first by a ray cast down from `p`, if any.
    fn edge_below(&self, cp: &CreasePattern, p: DVec2) -> Option<EdgeId> {
        let c = self.column(p.x);
        let cell = &self.edges[self.runs[c] as usize..self.runs[c + 1] as usize];
        let mut best: Option<(f64, f64, EdgeId)> = None;
        for &e in cell {
            let e = EdgeId(e);
            let (a, b) = cp.segment(e);
            let (l, r) = if a.x <= b.x { (a, b) } else { (b, a) };
            if !(l.x <= p.x && p.x < r.x) {
                continue;
            }
            let slope = (r.y - l.y) / (r.x - l.x);
            let y = l.y + slope * (p.x - l.x);
            if y >= p.y {
                continue;
            }
            let better = match best {
                None => true,
                Some((by, bs, _)) => y > by || (y == by && slope > bs),
            };
            if better {
                best = Some((y, slope, e));
            }
        }
        best.map(|(_, _, e)| e)
    }
}

/// The x-range of an edge.
fn span(cp: &CreasePattern, e: EdgeId) -> (f64, f64) {
    let (a, b) = cp.segment(e);
    (a.x.min(b.x), a.x.max(b.x))
}
