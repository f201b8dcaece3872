//! The plane-geometry helpers other tests use as oracles (`contains_point`,
//! `segment_distance`, `intersect`, `slide_interval`), checked against brute force that shares
//! no code with them: winding numbers summed from angles, golden-section minimisation of a
//! convex distance, and dense sampling.

use foldcam::geom::contains_point;
use foldcam::geom::{Crossing, intersect, segment_distance, slide_interval};
use glam::DVec2;
use proptest::prelude::*;

/// Distance from `p` to segment `ab` by clamped projection.
fn point_segment(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let ab = b - a;
    let t = if ab.length_squared() > 0.0 {
        ((p - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0)
    } else {
        0.0
    };
    p.distance(a + t * ab)
}

/// Winding number of `ring` round `p`: the turning of the ray from `p`, summed edge by edge.
fn winding(ring: &[DVec2], p: DVec2) -> i64 {
    let mut total = 0.0;
    for i in 0..ring.len() {
        let a = ring[i] - p;
        let b = ring[(i + 1) % ring.len()] - p;
        total += a.perp_dot(b).atan2(a.dot(b));
    }
    (total / std::f64::consts::TAU).round() as i64
}

/// Smallest distance between segments `a` and `b`: the distance from a point of `a` to `b`
/// is convex along `a`, so golden-section search finds its minimum.
fn brute_segment_distance(a0: DVec2, a1: DVec2, b0: DVec2, b1: DVec2) -> f64 {
    let f = |s: f64| point_segment(a0.lerp(a1, s), b0, b1);
    let g = (5f64.sqrt() - 1.0) / 2.0;
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    for _ in 0..200 {
        let m1 = hi - g * (hi - lo);
        let m2 = lo + g * (hi - lo);
        if f(m1) <= f(m2) {
            hi = m2;
        } else {
            lo = m1;
        }
    }
    f(0.5 * (lo + hi)).min(f(0.0)).min(f(1.0))
}

fn point() -> impl Strategy<Value = DVec2> {
    (-100.0f64..100.0, -100.0f64..100.0).prop_map(|(x, y)| DVec2::new(x, y))
}

/// A simple polygon: corners at increasing angles round the origin, random radii (star-shaped,
/// so never self-intersecting), of either orientation.
fn star_polygon() -> impl Strategy<Value = Vec<DVec2>> {
    (
        proptest::collection::vec((0.0f64..1.0, 5.0f64..80.0), 3..14),
        any::<bool>(),
    )
        .prop_map(|(corners, reverse)| {
            let n = corners.len();
            let mut ring: Vec<DVec2> = corners
                .iter()
                .enumerate()
                .map(|(i, (jitter, r))| {
                    let a = (i as f64 + 0.8 * jitter) / n as f64 * std::f64::consts::TAU;
                    DVec2::new(r * a.cos(), r * a.sin())
                })
                .collect();
            if reverse {
                ring.reverse();
            }
            ring
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    #[test]
    fn contains_point_agrees_with_the_winding_number(ring in star_polygon(), p in point()) {
        let near_edge = (0..ring.len())
            .any(|i| point_segment(p, ring[i], ring[(i + 1) % ring.len()]) < 1e-6);
        prop_assume!(!near_edge);
        let w = winding(&ring, p);
        prop_assert!(w.abs() <= 1);
        prop_assert_eq!(contains_point(&ring, p), w != 0);
    }

    #[test]
    fn segment_distance_agrees_with_minimisation(a0 in point(), a1 in point(), b0 in point(), b1 in point()) {
        let got = segment_distance(a0, a1, b0, b1);
        let want = brute_segment_distance(a0, a1, b0, b1);
        prop_assert!((got - want).abs() < 1e-6, "{} vs {}", got, want);
        // Symmetric.
        prop_assert!((segment_distance(b0, b1, a0, a1) - got).abs() < 1e-9);
    }

    #[test]
    fn intersect_point_lies_on_both_segments(a0 in point(), a1 in point(), b0 in point(), b1 in point()) {
        match intersect(a0, a1, b0, b1, 1e-12) {
            Crossing::Point { t, u } => {
                prop_assert!((-1e-9..=1.0 + 1e-9).contains(&t) && (-1e-9..=1.0 + 1e-9).contains(&u));
                let (p, q) = (a0.lerp(a1, t), b0.lerp(b1, u));
                prop_assert!(p.distance(q) < 1e-6, "{} vs {}", p, q);
            }
            Crossing::None => {
                // Apart: the minimised distance is not zero.
                prop_assert!(brute_segment_distance(a0, a1, b0, b1) > 1e-9);
            }
            _ => {}
        }
    }

    #[test]
    fn slide_interval_holds_exactly_the_shifts_that_come_close(
        a0 in point(), a1 in point(), b0 in point(), b1 in point(), gap in 0.5f64..10.0
    ) {
        let span = slide_interval(a0, a1, b0, b1, gap);
        let close = |t: f64| {
            let s = DVec2::new(t, 0.0);
            brute_segment_distance(a0 + s, a1 + s, b0, b1) < gap
        };
        // Sample shifts over a range wide enough to pass both segments completely.
        for k in 0..=400 {
            let t = -500.0 + 2.5 * k as f64;
            let inside = span.is_some_and(|(lo, hi)| t > lo + 1e-6 && t < hi - 1e-6);
            let outside = span.is_none_or(|(lo, hi)| t < lo - 1e-6 || t > hi + 1e-6);
            if inside {
                prop_assert!(close(t), "t {} in {:?} but not within {}", t, span, gap);
            }
            if outside {
                prop_assert!(!close(t), "t {} outside {:?} but within {}", t, span, gap);
            }
        }
    }
}

#[test]
fn the_brute_force_is_right_on_hand_worked_cases() {
    let v = DVec2::new;
    // Parallel unit segments one apart; crossing diagonals; a T.
    assert!(
        (brute_segment_distance(v(0.0, 0.0), v(1.0, 0.0), v(0.0, 1.0), v(1.0, 1.0)) - 1.0).abs()
            < 1e-12
    );
    assert!(brute_segment_distance(v(0.0, 0.0), v(1.0, 1.0), v(0.0, 1.0), v(1.0, 0.0)) < 1e-9);
    assert!(
        (brute_segment_distance(v(0.0, 0.0), v(2.0, 0.0), v(1.0, 0.5), v(1.0, 3.0)) - 0.5).abs()
            < 1e-12
    );
    let square = [v(0.0, 0.0), v(1.0, 0.0), v(1.0, 1.0), v(0.0, 1.0)];
    assert_eq!(winding(&square, v(0.5, 0.5)), 1);
    assert_eq!(winding(&square, v(1.5, 0.5)), 0);
}
