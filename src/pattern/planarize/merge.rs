//! Merging vertices closer than a tolerance.
//!
//! Vertices are bucketed in a hash grid of cell size `tol`, so two vertices within `tol` of each
//! other are in the same or neighbouring cells; a union–find joins them. Merging is transitive
//! (a chain of vertices each within `tol` of the next collapses to one), and the survivor of
//! each group is its lowest-numbered vertex, which keeps its position: results do not depend
//! on hash order.

use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

use glam::DVec2;

/// Maps every vertex to the representative of its group (`rep[i] <= i`). Returns the map and
/// the number of vertices merged into others.
pub(super) fn merge_close(points: &[DVec2], tol: f64) -> (Vec<u32>, usize) {
    let mut parent: Vec<u32> = (0..points.len() as u32).collect();
    if tol <= 0.0 || points.len() < 2 {
        return (parent, 0);
    }
    let inv = 1.0 / tol;
    let cell_of = |p: DVec2| ((p.x * inv).floor() as i64, (p.y * inv).floor() as i64);
    let mut cells: HashMap<(i64, i64), u32, BuildHasherDefault<CellHasher>> =
        HashMap::with_capacity_and_hasher(points.len(), Default::default());
    // Each cell holds the head of a linked list of its vertices (next[] chains them).
    let mut next = vec![u32::MAX; points.len()];
    for (i, &p) in points.iter().enumerate() {
        let slot = cells.entry(cell_of(p)).or_insert(u32::MAX);
        next[i] = *slot;
        *slot = i as u32;
    }
    let tol2 = tol * tol;
    for (i, &p) in points.iter().enumerate() {
        let (cx, cy) = cell_of(p);
        for dx in -1..=1 {
            for dy in -1..=1 {
                let Some(&head) = cells.get(&(cx + dx, cy + dy)) else {
                    continue;
                };
                let mut j = head;
                while j != u32::MAX {
                    if (j as usize) < i && points[j as usize].distance_squared(p) <= tol2 {
                        union(&mut parent, i as u32, j);
                    }
                    j = next[j as usize];
                }
            }
        }
    }
    let mut merged = 0;
    for i in 0..parent.len() {
        let r = find(&mut parent, i as u32);
        parent[i] = r;
        if r != i as u32 {
            merged += 1;
        }
    }
    (parent, merged)
}

fn find(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        let p = parent[x as usize];
        parent[x as usize] = parent[p as usize];
        x = p;
    }
    x
}

/// Joins two groups, keeping the smaller index as the root.
fn union(parent: &mut [u32], a: u32, b: u32) {
    let ra = find(parent, a);
    let rb = find(parent, b);
    if ra != rb {
        let (lo, hi) = if ra < rb { (ra, rb) } else { (rb, ra) };
        parent[hi as usize] = lo;
    }
}

/// A fast multiplicative hasher for integer cell keys (no protection against adversarial
/// collisions is needed: keys come from coordinates already validated and bounded).
#[derive(Default)]
pub(super) struct CellHasher(u64);

impl Hasher for CellHasher {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(b as u64);
        }
    }
    fn write_i64(&mut self, n: i64) {
        self.write_u64(n as u64);
    }
    fn write_u64(&mut self, n: u64) {
        self.0 = (self.0.rotate_left(5) ^ n).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
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
}
