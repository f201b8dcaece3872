//! A short list kept inline: face polygons and neighbour lists have a few entries each, so
//! copying a state (one per step, for undo) and splitting faces need no heap allocation.

use std::ops::Deref;

use glam::DVec2;

use super::state::Neighbour;

/// A face's edge-neighbours (see [`Neighbour`]).
pub type Neighbours = SmallList<Neighbour, 6>;

/// A face polygon on the sheet, millimetres.
pub type Ring = SmallList<DVec2, 8>;

/// A list of `T` in insertion order, the first `N` inline; derefs to a slice.
#[derive(Clone, Debug)]
pub struct SmallList<T: Copy + Default, const N: usize> {
    len: usize,
    inline: [T; N],
    /// All the entries once there are more than `N` (then `inline` is unused).
    heap: Vec<T>,
}

impl<T: Copy + Default, const N: usize> SmallList<T, N> {
    /// An empty list.
    pub fn new() -> Self {
        SmallList {
            len: 0,
            inline: [T::default(); N],
            heap: Vec::new(),
        }
    }

    /// Adds one at the end.
    pub fn push(&mut self, n: T) {
        if self.len < N {
            self.inline[self.len] = n;
        } else {
            if self.len == N {
                self.heap.extend_from_slice(&self.inline);
            }
            self.heap.push(n);
        }
        self.len += 1;
    }

    /// Keeps only those for which `keep` holds, in order.
    pub fn retain(&mut self, mut keep: impl FnMut(&T) -> bool) {
        if self.len > N {
            self.heap.retain(|n| keep(n));
            self.len = self.heap.len();
            if self.len <= N {
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

impl<T: Copy + Default, const N: usize> Default for SmallList<T, N> {
    fn default() -> Self {
        SmallList::new()
    }
}

impl<T: Copy + Default, const N: usize> Deref for SmallList<T, N> {
    type Target = [T];

    fn deref(&self) -> &[T] {
        if self.len > N {
            &self.heap
        } else {
            &self.inline[..self.len]
        }
    }
}

impl<T: Copy + Default + PartialEq, const N: usize> PartialEq for SmallList<T, N> {
    fn eq(&self, other: &Self) -> bool {
        **self == **other
    }
}

impl<'a, T: Copy + Default, const N: usize> IntoIterator for &'a SmallList<T, N> {
    type Item = &'a T;
    type IntoIter = std::slice::Iter<'a, T>;

    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

impl<T: Copy + Default, const N: usize> FromIterator<T> for SmallList<T, N> {
    fn from_iter<I: IntoIterator<Item = T>>(iter: I) -> Self {
        let mut out = SmallList::new();
        for x in iter {
            out.push(x);
        }
        out
    }
}

impl<T: Copy + Default, const N: usize> From<&[T]> for SmallList<T, N> {
    fn from(items: &[T]) -> Self {
        items.iter().copied().collect()
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
    fn a_long_ring_spills_to_the_heap_and_reads_the_same() {
        let points: Vec<DVec2> = (0..20).map(|i| DVec2::new(i as f64, 1.0)).collect();
        let ring: Ring = points.iter().copied().collect();
        assert_eq!(&ring[..], &points[..]);
        let short = Ring::from(&points[..3]);
        assert_eq!(short.len(), 3);
        assert_ne!(short, ring);
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
