//! Simple polygons given as rings of points.

use glam::DVec2;

use super::segment::{Crossing, intersect};
use super::tolerance::ROUNDOFF;

/// Signed area of a closed ring (shoelace formula): positive when counter-clockwise.
pub fn signed_area(ring: impl IntoIterator<Item = DVec2>) -> f64 {
    let mut iter = ring.into_iter();
    let Some(first) = iter.next() else {
        return 0.0;
    };
    let mut prev = first;
    let mut twice = 0.0;
    for p in iter {
        twice += prev.perp_dot(p);
        prev = p;
    }
    twice += prev.perp_dot(first);
    0.5 * twice
}

/// Whether `p` lies inside the closed ring (even–odd rule; points on the boundary may go
/// either way).
pub fn contains_point(ring: &[DVec2], p: DVec2) -> bool {
    let mut inside = false;
    let n = ring.len();
    for i in 0..n {
        let a = ring[i];
        let b = ring[(i + 1) % n];
        if (a.y > p.y) != (b.y > p.y) {
            let x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
            if p.x < x {
                inside = !inside;
            }
        }
    }
    inside
}

/// Whether the segment `a b` meets any edge of the closed ring (touching counts).
pub fn segment_crosses_ring(ring: &[DVec2], a: DVec2, b: DVec2) -> bool {
    let n = ring.len();
    (0..n).any(|i| intersect(a, b, ring[i], ring[(i + 1) % n], ROUNDOFF) != Crossing::None)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_square_area_and_orientation() {
        let sq = [
            DVec2::new(0.0, 0.0),
            DVec2::new(1.0, 0.0),
            DVec2::new(1.0, 1.0),
            DVec2::new(0.0, 1.0),
        ];
        assert_eq!(signed_area(sq), 1.0);
        assert_eq!(signed_area(sq.iter().rev().copied()), -1.0);
        assert!(contains_point(&sq, DVec2::new(0.5, 0.5)));
        assert!(!contains_point(&sq, DVec2::new(1.5, 0.5)));
    }
}
