//! A static 2-d tree over points with deletion, for nearest-neighbour queries.
//!
//! The tree is implicit: the points are permuted so that the node of a range `lo..hi` is the
//! middle element `(lo + hi) / 2`, split on x at even depths and y at odd ones (median found by
//! `select_nth_unstable`, O(n log n) to build). Each node counts the live points of its
//! subtree; a deletion decrements the counts along the root path (O(log n)), and queries skip
//! subtrees without live points, so a nearest-neighbour tour that deletes as it goes stays
//! near O(log n) per query even when most points are gone.

use glam::DVec2;

/// Points with deletion and nearest-live-point queries.
pub(super) struct KdTree {
    /// Tree position → point id.
    order: Vec<u32>,
    /// Point id → tree position.
    position: Vec<u32>,
    /// Point coordinates by point id.
    points: Vec<DVec2>,
    /// Live points in the subtree rooted at each tree position.
    live: Vec<u32>,
    /// Deleted flag by tree position.
    dead: Vec<bool>,
}

impl KdTree {
    /// Builds the tree over `points` (ids are indices into it).
    pub(super) fn new(points: Vec<DVec2>) -> Self {
        let n = points.len();
        let mut order: Vec<u32> = (0..n as u32).collect();
        let mut live = vec![0; n];
        build(&mut order, &points, &mut live, 0, n, 0);
        let mut position = vec![0; n];
        for (tree_pos, &id) in order.iter().enumerate() {
            position[id as usize] = tree_pos as u32;
        }
        KdTree {
            order,
            position,
            points,
            live,
            dead: vec![false; n],
        }
    }

    /// The live point nearest to `q` (its id), `None` when every point is deleted.
    pub(super) fn nearest(&self, q: DVec2) -> Option<usize> {
        let mut best = (f64::INFINITY, None);
        self.search(q, 0, self.order.len(), 0, &mut best);
        best.1
    }

    /// Deletes point `id` (idempotent).
    pub(super) fn delete(&mut self, id: usize) {
        let target = self.position[id] as usize;
        if self.dead[target] {
            return;
        }
        self.dead[target] = true;
        let (mut lo, mut hi) = (0, self.order.len());
        while lo < hi {
            let mid = (lo + hi) / 2;
            self.live[mid] -= 1;
            if target == mid {
                break;
            }
            if target < mid {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
    }

    fn search(
        &self,
        q: DVec2,
        lo: usize,
        hi: usize,
        depth: usize,
        best: &mut (f64, Option<usize>),
    ) {
        if lo >= hi {
            return;
        }
        let mid = (lo + hi) / 2;
        if self.live[mid] == 0 {
            return;
        }
        let id = self.order[mid] as usize;
        let p = self.points[id];
        if !self.dead[mid] {
            let d = q.distance_squared(p);
            if d < best.0 {
                *best = (d, Some(id));
            }
        }
        let diff = if depth.is_multiple_of(2) {
            q.x - p.x
        } else {
            q.y - p.y
        };
        let (near, far) = if diff < 0.0 {
            ((lo, mid), (mid + 1, hi))
        } else {
            ((mid + 1, hi), (lo, mid))
        };
        self.search(q, near.0, near.1, depth + 1, best);
        if diff * diff < best.0 {
            self.search(q, far.0, far.1, depth + 1, best);
        }
    }
}

/// Arranges `order[lo..hi]` as the subtree of depth `depth` and fills its live counts.
fn build(
    order: &mut [u32],
    points: &[DVec2],
    live: &mut [u32],
    lo: usize,
    hi: usize,
    depth: usize,
) {
    if lo >= hi {
        return;
    }
    let mid = (lo + hi) / 2;
    let axis = |id: &u32| {
        let p = points[*id as usize];
        if depth.is_multiple_of(2) { p.x } else { p.y }
    };
    order[lo..hi].select_nth_unstable_by(mid - lo, |a, b| axis(a).total_cmp(&axis(b)));
    live[mid] = (hi - lo) as u32;
    build(order, points, live, lo, mid, depth + 1);
    build(order, points, live, mid + 1, hi, depth + 1);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_the_nearest_live_point_by_brute_force() {
        let mut rng = crate::test_rng::TestRng::new(7);
        let mut next = move || rng.unit() * 100.0;
        let pts: Vec<DVec2> = (0..300).map(|_| DVec2::new(next(), next())).collect();
        let mut tree = KdTree::new(pts.clone());
        let mut alive = vec![true; pts.len()];
        for step in 0..pts.len() {
            let q = DVec2::new(next(), next());
            let got = tree.nearest(q).map(|id| q.distance(pts[id]));
            let want = (0..pts.len())
                .filter(|&i| alive[i])
                .map(|i| q.distance(pts[i]))
                .min_by(f64::total_cmp);
            assert_eq!(got, want, "step {step}");
            let victim = (step * 37) % pts.len();
            tree.delete(victim);
            alive[victim] = false;
        }
    }
}
