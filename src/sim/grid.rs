//! Segment geometry for the coverage check: a uniform grid of segments for neighbour queries
//! (on [`HashGrid`]), the part of one segment lying within a band around another, and
//! interval unions.

use glam::DVec2;

use crate::geom::HashGrid;
use crate::geom::grid::CellKey;

use crate::geom::tolerance::ROUNDOFF;

/// Most cells a segment is walked through (bounds the work for any input).
const MAX_STEPS: f64 = 4096.0;

/// A uniform grid holding segment ids in every cell within one cell of the segment.
pub(crate) struct SegmentGrid {
    grid: HashGrid<u32>,
}

impl SegmentGrid {
    /// An empty grid with square cells of side `cell` (> 0), which must be at least twice the
    /// query distance so that a point's own cell and its neighbours hold every segment within
    /// that distance.
    pub fn new(cell: f64) -> Self {
        SegmentGrid {
            grid: HashGrid::new(cell),
        }
    }

    /// The cells along `a`→`b`, one step per half cell.
    fn walk(&self, a: DVec2, b: DVec2) -> Vec<CellKey> {
        let steps = (a.distance(b) / (self.grid.cell_size() / 2.0))
            .ceil()
            .clamp(1.0, MAX_STEPS) as usize;
        let mut keys: Vec<CellKey> = (0..=steps)
            .map(|i| self.grid.key(a.lerp(b, i as f64 / steps as f64)))
            .collect();
        keys.dedup();
        keys
    }

    /// Adds segment `id` from `a` to `b`.
    pub fn insert(&mut self, id: u32, a: DVec2, b: DVec2) {
        let mut cells: Vec<CellKey> = Vec::new();
        for (x, y) in self.walk(a, b) {
            for dx in -1..=1 {
                for dy in -1..=1 {
                    cells.push((x + dx, y + dy));
                }
            }
        }
        cells.sort_unstable();
        cells.dedup();
        for c in cells {
            self.grid.insert_at(c, id);
        }
    }

    /// Ids of segments that may lie within half a cell of `p`.
    pub fn near_point(&self, p: DVec2) -> &[u32] {
        self.grid.at(self.grid.key(p))
    }

    /// Ids of segments that may lie within half a cell of segment `a`→`b`, each once.
    pub fn near_segment(&self, a: DVec2, b: DVec2) -> Vec<u32> {
        let mut ids: Vec<u32> = self
            .walk(a, b)
            .into_iter()
            .flat_map(|k| self.grid.at(k).iter().copied())
            .collect();
        ids.sort_unstable();
        ids.dedup();
        ids
    }
}

/// The stretch of segment `a`→`b` (as distances along it from `a`, within `[0, |ab|]`) covered
/// by the part of segment `p`→`q` lying within `band` of the line through `a` and `b`.
pub(crate) fn covered_interval(
    a: DVec2,
    b: DVec2,
    p: DVec2,
    q: DVec2,
    band: f64,
) -> Option<(f64, f64)> {
    let len = a.distance(b);
    if len <= 0.0 {
        return None;
    }
    let u = (b - a) / len;
    let n = u.perp();
    let (d0, dd) = (n.dot(p - a), n.dot(q - p));
    let (t0, t1) = if dd.abs() < ROUNDOFF {
        if d0.abs() > band {
            return None;
        }
        (0.0, 1.0)
    } else {
        let (x, y) = ((-band - d0) / dd, (band - d0) / dd);
        (x.min(y).max(0.0), x.max(y).min(1.0))
    };
    if t0 > t1 {
        return None;
    }
    let (s0, ds) = (u.dot(p - a), u.dot(q - p));
    let (x, y) = (s0 + t0 * ds, s0 + t1 * ds);
    let (lo, hi) = (x.min(y).max(0.0), x.max(y).min(len));
    (lo < hi).then_some((lo, hi))
}

/// Total length of a union of intervals.
pub(crate) fn union_length(mut intervals: Vec<(f64, f64)>) -> f64 {
    intervals.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut total = 0.0;
    let mut current: Option<(f64, f64)> = None;
    for (lo, hi) in intervals {
        current = match current {
            Some((cl, ch)) if lo <= ch => Some((cl, ch.max(hi))),
            Some((cl, ch)) => {
                total += ch - cl;
                Some((lo, hi))
            }
            None => Some((lo, hi)),
        };
    }
    total + current.map_or(0.0, |(l, h)| h - l)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64) -> DVec2 {
        DVec2::new(x, y)
    }

    #[test]
    fn intervals_clip_to_band_and_edge() {
        let (a, b) = (v(0.0, 0.0), v(10.0, 0.0));
        assert_eq!(
            covered_interval(a, b, v(-5.0, 0.1), v(4.0, 0.1), 0.2),
            Some((0.0, 4.0))
        );
        assert_eq!(covered_interval(a, b, v(2.0, 1.0), v(3.0, 1.0), 0.2), None);
        let slanted = covered_interval(a, b, v(0.0, -1.0), v(10.0, 1.0), 0.2).unwrap();
        assert!((slanted.0 - 4.0).abs() < 1e-9 && (slanted.1 - 6.0).abs() < 1e-9);
    }

    #[test]
    fn union_merges_overlaps() {
        assert_eq!(union_length(vec![(0.0, 2.0), (5.0, 6.0), (1.0, 3.0)]), 4.0);
        assert_eq!(union_length(Vec::new()), 0.0);
    }

    #[test]
    fn grid_finds_neighbours() {
        let mut g = SegmentGrid::new(1.0);
        g.insert(7, v(0.0, 0.0), v(10.0, 0.0));
        assert!(g.near_point(v(5.0, 0.3)).contains(&7));
        assert!(g.near_point(v(5.0, 5.0)).is_empty());
        assert_eq!(g.near_segment(v(3.0, 0.2), v(4.0, 0.2)), vec![7]);
    }
}
