//! Finding where edges cross or touch, and splitting them there.
//!
//! For every pair of edges that share a grid cell:
//! - an end vertex of one edge lying within `tol` of the other's interior splits the other at
//!   that vertex (T-junctions; collinear overlaps become identical pieces that the duplicate
//!   pass then removes);
//! - interiors crossing at a point farther than `tol` from all four ends split both at a new
//!   vertex there.

use glam::DVec2;
use std::sync::atomic::{AtomicUsize, Ordering};

use rayon::prelude::*;

use super::grid::EdgeGrid;
use crate::geom::Segment;
use crate::geom::segment::{Crossing, distance_to_point, intersect, project};
use crate::geom::tolerance::ROUNDOFF;

/// An edge reduced to what the crossing search needs.
#[derive(Clone, Copy)]
pub(super) struct Seg {
    pub v: [u32; 2],
    pub p: [DVec2; 2],
}

/// Splits found in one pass: edge `e` must be split at vertex `v`.
#[derive(Default)]
pub(super) struct Splits {
    /// Existing vertices on other edges' interiors: `(edge, vertex)`.
    pub touches: Vec<(u32, u32)>,
    /// Proper crossings: `(edge, edge, point)` with the first edge the smaller.
    pub crossings: Vec<(u32, u32, DVec2)>,
}

impl Splits {
    fn append(mut self, mut other: Splits) -> Splits {
        self.touches.append(&mut other.touches);
        self.crossings.append(&mut other.crossings);
        self
    }
}

/// Most edge pairs tested in one pass before the search gives up: beyond this the drawing
/// has so many edges on top of each other that splitting them all would take minutes.
pub const MAX_PAIR_TESTS: u64 = 400_000_000;

/// Finds every touch and crossing among `segs`; `None` when the work would exceed the limits
/// ([`MAX_PAIR_TESTS`], the grid's entry limit, or more than `max_splits` splits: the search
/// stops early once that many are found).
pub(super) fn find_splits(segs: &[Seg], tol: f64, max_splits: usize) -> Option<Splits> {
    let ends: Vec<Segment> = segs.iter().map(|s| Segment::from(s.p)).collect();
    let grid = EdgeGrid::new(&ends, tol)?;
    if grid.pair_count() > MAX_PAIR_TESTS {
        return None;
    }
    let found = AtomicUsize::new(0);
    let over = || found.load(Ordering::Relaxed) > max_splits;
    let mut splits = grid
        .crowded_cells()
        .fold(Splits::default, |mut out, cell| {
            for (k, &i) in cell.iter().enumerate() {
                let before = out.touches.len() + 2 * out.crossings.len();
                if over() {
                    break;
                }
                for &j in &cell[k + 1..] {
                    test_pair(segs, i, j, tol, &mut out);
                }
                let after = out.touches.len() + 2 * out.crossings.len();
                found.fetch_add(after - before, Ordering::Relaxed);
            }
            out
        })
        .reduce(Splits::default, Splits::append);
    if over() {
        return None;
    }
    splits.touches.par_sort_unstable();
    splits.touches.dedup();
    splits
        .crossings
        .par_sort_unstable_by(|a, b| (a.0, a.1).cmp(&(b.0, b.1)));
    splits.crossings.dedup_by(|a, b| (a.0, a.1) == (b.0, b.1));
    Some(splits)
}

fn test_pair(segs: &[Seg], i: u32, j: u32, tol: f64, out: &mut Splits) {
    let (a, b) = (&segs[i as usize], &segs[j as usize]);
    if !boxes_meet(a, b, tol) {
        return;
    }
    let shares_vertex = a.v.iter().any(|v| b.v.contains(v));
    touch(a, i, b, tol, out);
    touch(b, j, a, tol, out);
    if shares_vertex {
        return;
    }
    if let Crossing::Point { t, .. } = intersect(a.p[0], a.p[1], b.p[0], b.p[1], ROUNDOFF) {
        let x = a.p[0].lerp(a.p[1], t);
        let clear = a.p.iter().chain(&b.p).all(|q| q.distance(x) > tol);
        if clear {
            let (lo, hi) = if i < j { (i, j) } else { (j, i) };
            out.crossings.push((lo, hi, x));
        }
    }
}

/// Records the ends of `other` that lie on the interior of `seg` (edge `e`).
fn touch(seg: &Seg, e: u32, other: &Seg, tol: f64, out: &mut Splits) {
    for k in 0..2 {
        let (v, q) = (other.v[k], other.p[k]);
        if seg.v.contains(&v) {
            continue;
        }
        if seg.p[0].distance(q) <= tol || seg.p[1].distance(q) <= tol {
            continue;
        }
        if distance_to_point(seg.p[0], seg.p[1], q) <= tol {
            out.touches.push((e, v));
        }
    }
}

fn boxes_meet(a: &Seg, b: &Seg, tol: f64) -> bool {
    let (alo, ahi) = (a.p[0].min(a.p[1]), a.p[0].max(a.p[1]));
    let (blo, bhi) = (b.p[0].min(b.p[1]), b.p[0].max(b.p[1]));
    (alo - tol).cmple(bhi).all() && (blo - tol).cmple(ahi).all()
}

/// The pieces of an edge split at `cuts` (vertex ids with positions): the ends and cuts in
/// order along the edge, as consecutive vertex pairs.
pub(super) fn pieces(seg: &Seg, cuts: &mut [(u32, DVec2)]) -> Vec<[u32; 2]> {
    cuts.sort_unstable_by(|x, y| {
        let tx = project(seg.p[0], seg.p[1], x.1);
        let ty = project(seg.p[0], seg.p[1], y.1);
        tx.total_cmp(&ty)
    });
    let mut chain = Vec::with_capacity(cuts.len() + 2);
    chain.push(seg.v[0]);
    chain.extend(cuts.iter().map(|c| c.0));
    chain.push(seg.v[1]);
    chain.windows(2).map(|w| [w[0], w[1]]).collect()
}
