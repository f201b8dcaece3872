//! Disjoint sets (union–find) over `0..n`: the grouping step behind merging close points,
//! joining collinear segments, flooding faces into pieces and gluing face corners.

/// A partition of `0..n` into groups. Every group is named by its smallest member, so the
/// result does not depend on the order of [`union`](Self::union) calls; paths are halved on
/// every [`find`](Self::find).
#[derive(Clone, Debug)]
pub struct DisjointSets {
    parent: Vec<u32>,
}

impl DisjointSets {
    /// `n` groups of one (`n` must fit in `u32`).
    pub fn new(n: usize) -> Self {
        debug_assert!(u32::try_from(n).is_ok(), "{n} elements do not fit in u32");
        DisjointSets {
            parent: (0..n as u32).collect(),
        }
    }

    /// How many elements the partition covers.
    pub fn len(&self) -> usize {
        self.parent.len()
    }

    /// Whether the partition covers no element.
    pub fn is_empty(&self) -> bool {
        self.parent.is_empty()
    }

    /// The smallest member of `x`'s group.
    ///
    /// # Panics
    /// When `x >= self.len()`.
    pub fn find(&mut self, x: usize) -> usize {
        let mut x = x as u32;
        while self.parent[x as usize] != x {
            let up = self.parent[self.parent[x as usize] as usize];
            self.parent[x as usize] = up;
            x = up;
        }
        x as usize
    }

    /// Joins the groups of `a` and `b`; returns whether they were apart.
    pub fn union(&mut self, a: usize, b: usize) -> bool {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra == rb {
            return false;
        }
        self.parent[ra.max(rb)] = ra.min(rb) as u32;
        true
    }

    /// Whether `a` and `b` are in one group.
    pub fn same(&mut self, a: usize, b: usize) -> bool {
        self.find(a) == self.find(b)
    }

    /// For every element, the smallest member of its group.
    pub fn roots(&mut self) -> Vec<usize> {
        (0..self.len()).map(|x| self.find(x)).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn groups_are_named_by_their_smallest_member_in_any_order() {
        let pairs = [(4, 2), (7, 4), (1, 3), (3, 5), (6, 6)];
        let mut forward = DisjointSets::new(8);
        let mut backward = DisjointSets::new(8);
        for &(a, b) in &pairs {
            forward.union(a, b);
        }
        for &(a, b) in pairs.iter().rev() {
            backward.union(b, a);
        }
        // Worked out by hand: {0}, {1,3,5}, {2,4,7}, {6}.
        let expected = vec![0, 1, 2, 1, 2, 1, 6, 2];
        assert_eq!(forward.roots(), expected);
        assert_eq!(backward.roots(), expected);
    }

    #[test]
    fn union_reports_whether_it_joined() {
        let mut sets = DisjointSets::new(3);
        assert!(sets.union(0, 2));
        assert!(!sets.union(2, 0));
        assert!(sets.same(0, 2));
        assert!(!sets.same(0, 1));
    }

    #[test]
    fn a_long_chain_is_flattened_and_keeps_its_root() {
        let n = 10_000;
        let mut sets = DisjointSets::new(n);
        for i in (1..n).rev() {
            sets.union(i, i - 1);
        }
        assert!(sets.roots().iter().all(|&r| r == 0));
    }
}
