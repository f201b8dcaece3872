//! A uniform grid over the edges: each edge is listed in every cell its tolerance-widened
//! segment passes through, so two edges that come within the tolerance of each other share at
//! least one cell.
//!
//! The cell size is the mean edge length (at least four tolerances), enlarged when that would
//! make more than about four cells per edge, which keeps cells short for drawings of evenly
//! sized creases. Patterns with a few very long edges among many short ones stay correct but
//! test more pairs; the grid refuses to grow past [`MAX_ENTRIES_PER_EDGE`] entries per edge.

use crate::geom::Segment;
use glam::DVec2;
use rayon::prelude::*;

/// Most grid entries per edge (on average) before the search gives up as too complex: an
/// edge crossing many cells is one much longer than the mean, and many of those make the
/// search quadratic.
pub(super) const MAX_ENTRIES_PER_EDGE: u64 = 64;

/// Edges bucketed by cell, as compressed rows.
pub(super) struct EdgeGrid {
    /// Start of each cell's run in `edges` (one more entry than there are cells).
    pub runs: Vec<u32>,
    /// Edge indices, grouped by cell.
    pub edges: Vec<u32>,
}

impl EdgeGrid {
    /// Builds the grid for segments `segs` (end positions), widened by `tol`; `None` when the
    /// grid would exceed [`MAX_ENTRIES_PER_EDGE`] entries per edge.
    pub fn new(segs: &[Segment], tol: f64) -> Option<Self> {
        let Some((lo, hi)) = bounds(segs) else {
            return Some(EdgeGrid {
                runs: vec![0],
                edges: Vec::new(),
            });
        };
        let size = (hi - lo).max(DVec2::splat(tol.max(f64::MIN_POSITIVE)));
        let n = segs.len().max(1) as f64;
        let mean = segs.iter().map(|s| s.length()).sum::<f64>() / n;
        let mut cell = mean.max(4.0 * tol).max(size.max_element() / (4.0 * n));
        let max_cells = 4.0 * n + 64.0;
        loop {
            let cells = (size.x / cell + 2.0) * (size.y / cell + 2.0);
            if cells <= max_cells {
                break;
            }
            cell *= (cells / max_cells).sqrt().max(1.01);
        }
        let cols = (size.x + 2.0 * tol) / cell;
        let rows = (size.y + 2.0 * tol) / cell;
        let spec = CellSpec {
            origin: lo - DVec2::splat(tol),
            inv: 1.0 / cell,
            cell,
            cols: cols.floor() as u64 + 1,
            rows: rows.floor() as u64 + 1,
            tol,
        };
        // Counting sort by cell: count, prefix sums, scatter (the cells are few and dense, so
        // this beats a comparison sort of (cell, edge) pairs).
        let mut runs = vec![0u32; (spec.cols * spec.rows) as usize + 1];
        let mut entries = 0u64;
        for s in segs {
            spec.cover(s.a, s.b, |key| {
                runs[key as usize + 1] += 1;
                entries += 1;
            });
        }
        if entries > MAX_ENTRIES_PER_EDGE * segs.len() as u64 + 1_000_000 {
            return None;
        }
        for i in 1..runs.len() {
            runs[i] += runs[i - 1];
        }
        let mut fill = runs.clone();
        let mut edges = vec![0u32; runs[runs.len() - 1] as usize];
        for (i, s) in segs.iter().enumerate() {
            spec.cover(s.a, s.b, |key| {
                let slot = &mut fill[key as usize];
                edges[*slot as usize] = i as u32;
                *slot += 1;
            });
        }
        Some(EdgeGrid { runs, edges })
    }

    /// Number of edge pairs that share a cell (the work of a crossing search).
    pub fn pair_count(&self) -> u64 {
        self.runs
            .windows(2)
            .map(|w| {
                let k = u64::from(w[1] - w[0]);
                k * k.saturating_sub(1) / 2
            })
            .sum()
    }

    /// The edge lists of the cells holding two or more edges.
    pub fn crowded_cells(&self) -> impl ParallelIterator<Item = &[u32]> {
        self.runs.par_windows(2).filter_map(|w| {
            let cell = &self.edges[w[0] as usize..w[1] as usize];
            (cell.len() >= 2).then_some(cell)
        })
    }
}

struct CellSpec {
    origin: DVec2,
    inv: f64,
    cell: f64,
    cols: u64,
    rows: u64,
    tol: f64,
}

impl CellSpec {
    fn col(&self, x: f64) -> u64 {
        (((x - self.origin.x) * self.inv).floor().max(0.0) as u64).min(self.cols - 1)
    }

    fn row(&self, y: f64) -> u64 {
        (((y - self.origin.y) * self.inv).floor().max(0.0) as u64).min(self.rows - 1)
    }

    /// Calls `visit` with the key of every cell the widened segment `a–b` touches: column by
    /// column, the rows spanned by the part of the segment over that column.
    fn cover(&self, a: DVec2, b: DVec2, mut visit: impl FnMut(u64)) {
        let t = self.tol;
        let (c0, c1) = (self.col(a.x.min(b.x) - t), self.col(a.x.max(b.x) + t));
        let d = b - a;
        for c in c0..=c1 {
            let x0 = self.origin.x + c as f64 * self.cell - t;
            let x1 = x0 + self.cell + 2.0 * t;
            let (ya, yb) = if d.x.abs() <= f64::EPSILON * (a.x.abs() + 1.0) {
                (a.y, b.y)
            } else {
                let ta = ((x0 - a.x) / d.x).clamp(0.0, 1.0);
                let tb = ((x1 - a.x) / d.x).clamp(0.0, 1.0);
                (a.y + d.y * ta, a.y + d.y * tb)
            };
            let (r0, r1) = (self.row(ya.min(yb) - t), self.row(ya.max(yb) + t));
            for r in r0..=r1 {
                visit(r * self.cols + c);
            }
        }
    }
}

fn bounds(segs: &[Segment]) -> Option<(DVec2, DVec2)> {
    crate::geom::Rect::of(segs.iter().flat_map(|s| s.ends())).map(crate::geom::Rect::corners)
}
