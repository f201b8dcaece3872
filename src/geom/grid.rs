//! A sparse uniform grid of square cells for neighbour queries in the plane.
//!
//! Cell `(i, j)` holds the points with `⌊x / cell⌋ = i` and `⌊y / cell⌋ = j`; only cells
//! holding something are stored (a hash map), so the grid needs no bounds and costs memory
//! in proportion to what it holds. With a cell side of at least the query distance `d`,
//! every item within `d` of a point lies in the 3 × 3 block of cells around the point's
//! cell ([`HashGrid::near`]); the caller then filters by the exact distance.
//!
//! Items are small copyable ids (vertex or segment indices); a cell lists them in insertion
//! order, and [`HashGrid::near`] visits the block column by column (x outer, y inner), so
//! results are deterministic.

use std::collections::HashMap;

use glam::DVec2;

/// The key of a cell: its column and row.
pub type CellKey = (i64, i64);

/// Ids binned by the square cell of side `cell` they were inserted at.
#[derive(Clone, Debug)]
pub struct HashGrid<T = usize> {
    cell: f64,
    map: HashMap<CellKey, Vec<T>>,
}

impl<T: Copy> HashGrid<T> {
    /// An empty grid with square cells of side `cell` (> 0 and finite, in the points' units).
    pub fn new(cell: f64) -> Self {
        HashGrid {
            cell,
            map: HashMap::new(),
        }
    }

    /// The side of a cell.
    pub fn cell_size(&self) -> f64 {
        self.cell
    }

    /// The cell holding `p`: `(⌊p.x / cell⌋, ⌊p.y / cell⌋)` (saturating at `i64`'s range).
    pub fn key(&self, p: DVec2) -> CellKey {
        let k = (p / self.cell).floor();
        (k.x as i64, k.y as i64)
    }

    /// Adds `id` to the cell holding `p`.
    pub fn insert(&mut self, p: DVec2, id: T) {
        self.insert_at(self.key(p), id);
    }

    /// Adds `id` to cell `key`.
    pub fn insert_at(&mut self, key: CellKey, id: T) {
        self.map.entry(key).or_default().push(id);
    }

    /// The ids in cell `key`, in insertion order.
    pub fn at(&self, key: CellKey) -> &[T] {
        self.map.get(&key).map_or(&[], Vec::as_slice)
    }

    /// The ids in the 3 × 3 block of cells around the cell of `p` (x outer, y inner; each
    /// cell in insertion order): every id inserted within one cell side of `p`, and others.
    pub fn near(&self, p: DVec2) -> impl Iterator<Item = T> + '_ {
        let (x, y) = self.key(p);
        (-1..=1).flat_map(move |dx| {
            (-1..=1).flat_map(move |dy| self.at((x + dx, y + dy)).iter().copied())
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn near_finds_every_point_within_a_cell_side() {
        // Points on a fixed pseudo-random scatter; brute force is the reference.
        let mut rng = crate::test_rng::TestRng::new(11);
        let pts: Vec<DVec2> = (0..400)
            .map(|_| DVec2::new(rng.unit() * 20.0 - 10.0, rng.unit() * 20.0 - 10.0))
            .collect();
        let mut grid = HashGrid::new(1.5);
        for (i, &p) in pts.iter().enumerate() {
            grid.insert(p, i);
        }
        for &q in pts.iter().take(50) {
            let mut found: Vec<usize> = grid
                .near(q)
                .filter(|&i| pts[i].distance(q) <= 1.5)
                .collect();
            found.sort_unstable();
            let expected: Vec<usize> = (0..pts.len())
                .filter(|&i| pts[i].distance(q) <= 1.5)
                .collect();
            assert_eq!(found, expected);
        }
    }

    #[test]
    fn keys_floor_towards_minus_infinity() {
        let grid: HashGrid = HashGrid::new(2.0);
        assert_eq!(grid.key(DVec2::new(-0.5, 3.9)), (-1, 1));
        assert_eq!(grid.key(DVec2::new(4.0, -4.0)), (2, -2));
        assert!(grid.at((0, 0)).is_empty());
    }
}
