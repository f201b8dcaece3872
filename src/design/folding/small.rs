//! Short lists kept inline (smallvec): face polygons and neighbour lists have a few entries
//! each, so copying a state (one per step, for undo) and splitting faces need no heap
//! allocation.

use glam::DVec2;
use smallvec::SmallVec;

use super::state::Neighbour;

/// A face's edge-neighbours (see [`Neighbour`]).
pub type Neighbours = SmallVec<[Neighbour; 6]>;

/// A face polygon on the sheet, millimetres.
pub type Ring = SmallVec<[DVec2; 8]>;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Segment;

    fn n(face: usize) -> Neighbour {
        Neighbour {
            face,
            edge: Segment::new(DVec2::ZERO, DVec2::X * face as f64),
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
