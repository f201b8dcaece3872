//! A face's list of edge-neighbours, kept inline for the few a face usually has, so that
//! copying a state (one per step, for undo) and splitting faces allocate little.

use std::ops::Deref;

use glam::DVec2;

use super::state::Neighbour;

/// How many neighbours are stored without a heap allocation.
const INLINE: usize = 6;

const NONE: Neighbour = Neighbour {
    face: usize::MAX,
    edge: (DVec2::ZERO, DVec2::ZERO),
};

/// The neighbours of a face, in insertion order; derefs to a slice.
#[derive(Clone, Debug)]
pub struct Neighbours {
    len: usize,
    inline: [Neighbour; INLINE],
    /// All the neighbours once there are more than `INLINE` (then `inline` is unused).
    heap: Vec<Neighbour>,
}

impl Neighbours {
    /// No neighbours.
    pub fn new() -> Neighbours {
        Neighbours {
            len: 0,
            inline: [NONE; INLINE],
            heap: Vec::new(),
        }
    }

    /// Adds one at the end.
    pub fn push(&mut self, n: Neighbour) {
        if self.len < INLINE {
            self.inline[self.len] = n;
        } else {
            if self.len == INLINE {
                self.heap.extend_from_slice(&self.inline);
            }
            self.heap.push(n);
        }
        self.len += 1;
    }

    /// Keeps only those for which `keep` holds, in order.
    pub fn retain(&mut self, mut keep: impl FnMut(&Neighbour) -> bool) {
        if self.len > INLINE {
            self.heap.retain(|n| keep(n));
            self.len = self.heap.len();
            if self.len <= INLINE {
                self.inline[..self.len].copy_from_slice(&self.heap);
                self.heap.clear();
            }
            return;
        }
        let mut kept = 0;
        for i in 0..self.len {
            if keep(&self.inline[i]) {
                self.inline[kept] = self.inline[i];
                kept += 1;
            }
        }
        self.len = kept;
    }
}

impl Default for Neighbours {
    fn default() -> Self {
        Neighbours::new()
    }
}

impl Deref for Neighbours {
    type Target = [Neighbour];

    fn deref(&self) -> &[Neighbour] {
        if self.len > INLINE {
            &self.heap
        } else {
            &self.inline[..self.len]
        }
    }
}

impl PartialEq for Neighbours {
    fn eq(&self, other: &Self) -> bool {
        **self == **other
    }
}

impl<'a> IntoIterator for &'a Neighbours {
    type Item = &'a Neighbour;
    type IntoIter = std::slice::Iter<'a, Neighbour>;

    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn n(face: usize) -> Neighbour {
        Neighbour {
            face,
            edge: (DVec2::ZERO, DVec2::X * face as f64),
        }
    }

    #[test]
    fn push_and_retain_across_the_inline_limit_keep_order() {
        let mut list = Neighbours::new();
        for i in 0..9 {
            list.push(n(i));
        }
        assert_eq!(
            list.iter().map(|m| m.face).collect::<Vec<_>>(),
            (0..9).collect::<Vec<_>>()
        );
        list.retain(|m| m.face % 3 != 0);
        assert_eq!(
            list.iter().map(|m| m.face).collect::<Vec<_>>(),
            vec![1, 2, 4, 5, 7, 8]
        );
        list.retain(|m| m.face != 4);
        list.push(n(10));
        assert_eq!(
            list.iter().map(|m| m.face).collect::<Vec<_>>(),
            vec![1, 2, 5, 7, 8, 10]
        );
        let copy = list.clone();
        assert_eq!(copy, list);
        list.retain(|m| m.face != 10);
        assert_ne!(copy, list);
    }
}
