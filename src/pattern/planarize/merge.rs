//! Merging vertices closer than a tolerance.
//!
//! Vertices are sorted by the cell of a grid whose cells are much larger than the tolerance
//! (64 × `tol`, or coarser for huge coordinate ranges), so two vertices within `tol` share a
//! cell unless one lies within `tol` of a cell border, in which case the few neighbouring cells
//! it is that close to are searched too. Candidate pairs are found in parallel; a union–find
//! joins them. Merging is transitive (a chain of vertices each within `tol` of the next
//! collapses to one), and the survivor of each group is its lowest-numbered vertex, which keeps
//! its position: results do not depend on thread scheduling.

use glam::DVec2;
use rayon::prelude::*;

use crate::geom::DisjointSets;

/// Cell size over tolerance: large enough that few points sit near a border, small enough that
/// distinct vertices of a real drawing rarely share a cell.
const CELL_OVER_TOL: f64 = 64.0;

/// Maps every vertex to the representative of its group (`rep[i] <= i`). Returns the map and
/// the number of vertices merged into others.
pub(super) fn merge_close(points: &[DVec2], tol: f64) -> (Vec<u32>, usize) {
    if tol <= 0.0 || points.len() < 2 {
        return ((0..points.len() as u32).collect(), 0);
    }
    let grid = SortedCells::new(points, tol);
    let pairs: Vec<(u32, u32)> = grid
        .runs()
        .par_iter()
        .fold(Vec::new, |mut out, run| {
            grid.close_pairs(points, run.clone(), tol, &mut out);
            out
        })
        .reduce(Vec::new, |mut a, mut b| {
            a.append(&mut b);
            a
        });
    let mut groups = DisjointSets::new(points.len());
    for (a, b) in pairs {
        groups.union(a as usize, b as usize);
    }
    let rep: Vec<u32> = groups.roots().into_iter().map(|r| r as u32).collect();
    let merged = rep
        .iter()
        .enumerate()
        .filter(|&(i, &r)| r != i as u32)
        .count();
    (rep, merged)
}

/// Vertex indices sorted by cell.
struct SortedCells {
    origin: DVec2,
    cell: f64,
    /// `(cell key, vertex)`, sorted.
    keys: Vec<((i64, i64), u32)>,
}

impl SortedCells {
    fn new(points: &[DVec2], tol: f64) -> Self {
        let (lo, hi) = points.iter().fold(
            (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
            |(lo, hi), &p| (lo.min(p), hi.max(p)),
        );
        // Keep cell indices far inside i64 even for a 1e9 range at a tiny tolerance.
        let cell = (CELL_OVER_TOL * tol).max((hi - lo).max_element() / (1u64 << 40) as f64);
        let mut grid = SortedCells {
            origin: lo,
            cell,
            keys: Vec::new(),
        };
        let mut keys: Vec<((i64, i64), u32)> = points
            .par_iter()
            .enumerate()
            .map(|(i, &p)| (grid.key(p), i as u32))
            .collect();
        keys.par_sort_unstable();
        grid.keys = keys;
        grid
    }

    fn key(&self, p: DVec2) -> (i64, i64) {
        let c = ((p - self.origin) / self.cell).floor();
        (c.x as i64, c.y as i64)
    }

    /// The ranges of `keys` that share a cell.
    fn runs(&self) -> Vec<std::ops::Range<usize>> {
        let mut runs = Vec::new();
        let mut start = 0;
        for i in 1..=self.keys.len() {
            if i == self.keys.len() || self.keys[i].0 != self.keys[start].0 {
                runs.push(start..i);
                start = i;
            }
        }
        runs
    }

    /// Pushes every pair within `tol` that has a member in `run` (one cell): pairs inside the
    /// cell, and pairs with the neighbouring cells that a member is within `tol` of.
    fn close_pairs(
        &self,
        points: &[DVec2],
        run: std::ops::Range<usize>,
        tol: f64,
        out: &mut Vec<(u32, u32)>,
    ) {
        if run.len() == 1 {
            self.border_pairs(points, self.keys[run.start].1, tol, out);
            return;
        }
        let tol2 = tol * tol;
        // Identical positions first (a pile of copies costs a sort, not a square), then the
        // distinct positions pairwise; only pairs that join two groups are emitted.
        let mut cell: Vec<u32> = self.keys[run].iter().map(|k| k.1).collect();
        let bits = |i: &u32| {
            let p = points[*i as usize];
            (p.x.to_bits(), p.y.to_bits())
        };
        cell.sort_unstable_by_key(bits);
        let mut distinct: Vec<u32> = Vec::with_capacity(cell.len());
        for &i in &cell {
            match distinct.last() {
                Some(&d) if bits(&d) == bits(&i) => out.push((i, d)),
                _ => distinct.push(i),
            }
        }
        let mut local = DisjointSets::new(distinct.len());
        for (k, &i) in distinct.iter().enumerate() {
            let p = points[i as usize];
            for (l, &j) in distinct.iter().enumerate().skip(k + 1) {
                if points[j as usize].distance_squared(p) <= tol2 && local.union(k, l) {
                    out.push((i, j));
                }
            }
            self.border_pairs(points, i, tol, out);
        }
    }

    /// Pairs of point `i` with points in the neighbouring cells it is within `tol` of (if
    /// any); each pair is taken from the side of the smaller cell key only, so it is found
    /// once.
    fn border_pairs(&self, points: &[DVec2], i: u32, tol: f64, out: &mut Vec<(u32, u32)>) {
        let p = points[i as usize];
        let (c, lo, hi) = (self.key(p), self.key(p - tol), self.key(p + tol));
        if lo == c && hi == c {
            return;
        }
        for x in lo.0..=hi.0 {
            for y in lo.1..=hi.1 {
                if (x, y) <= c {
                    continue;
                }
                let start = self.keys.partition_point(|k| k.0 < (x, y));
                for &(key, j) in &self.keys[start..] {
                    if key != (x, y) {
                        break;
                    }
                    if points[j as usize].distance_squared(p) <= tol * tol {
                        out.push((i, j));
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chain_within_tolerance_collapses_to_lowest_index() {
        let pts = [
            DVec2::new(0.3, 0.0),
            DVec2::new(5.0, 5.0),
            DVec2::new(0.0, 0.0),
            DVec2::new(0.15, 0.0),
        ];
        let (rep, merged) = merge_close(&pts, 0.2);
        assert_eq!(rep, vec![0, 1, 0, 0]);
        assert_eq!(merged, 2);
    }

    /// Brute force: the same grouping from all pairs within `tol`.
    fn brute(points: &[DVec2], tol: f64) -> Vec<u32> {
        let mut groups = DisjointSets::new(points.len());
        for i in 0..points.len() {
            for j in 0..i {
                if points[i].distance(points[j]) <= tol {
                    groups.union(i, j);
                }
            }
        }
        groups.roots().into_iter().map(|r| r as u32).collect()
    }

    #[test]
    fn agrees_with_brute_force_across_cell_borders() {
        // Points jittered around lattice positions that are multiples of the cell size, so
        // many pairs straddle borders; a fixed LCG keeps the case reproducible.
        let tol = 0.01;
        let mut rng = crate::test_rng::TestRng::new(0x2545_f491_4f6c_dd1d);
        let mut rand = || rng.unit();
        let mut pts = Vec::new();
        for _ in 0..600 {
            let base = DVec2::new((rand() * 6.0).floor(), (rand() * 6.0).floor()) * 0.64;
            let jitter = DVec2::new(rand() - 0.5, rand() - 0.5) * 0.03;
            pts.push(base + jitter);
        }
        let (rep, merged) = merge_close(&pts, tol);
        let want = brute(&pts, tol);
        assert_eq!(rep, want);
        assert_eq!(
            merged,
            rep.iter()
                .enumerate()
                .filter(|(i, r)| **r != *i as u32)
                .count()
        );
        assert!(merged > 0 && merged < pts.len() - 36);
    }
}
