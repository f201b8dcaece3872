//! An overlap oracle independent of foldcam's geometry: the union of polygons computed by
//! i_overlay, compared with the sum of their areas. Polygons that do not overlap have a union
//! exactly as large as their areas added up; any overlap makes the union smaller.

use glam::DVec2;
use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::float::overlay::FloatOverlay;

/// Area of a simple ring by the shoelace formula, always ≥ 0.
fn ring_area(ring: &[[f64; 2]]) -> f64 {
    let n = ring.len();
    let twice: f64 = (0..n)
        .map(|i| {
            let [x0, y0] = ring[i];
            let [x1, y1] = ring[(i + 1) % n];
            x0 * y1 - x1 * y0
        })
        .sum();
    0.5 * twice.abs()
}

/// Area of the union of `polygons` (each a ring of corners, either orientation), by i_overlay.
pub fn union_area(polygons: &[Vec<DVec2>]) -> f64 {
    let subject: Vec<Vec<[f64; 2]>> = polygons
        .iter()
        .map(|p| p.iter().map(|v| [v.x, v.y]).collect())
        .collect();
    let shapes = FloatOverlay::with_subj(&subject).overlay(OverlayRule::Subject, FillRule::NonZero);
    shapes
        .iter()
        .map(|shape| {
            let (outer, holes) = shape.split_first().expect("a shape has an outer ring");
            ring_area(outer) - holes.iter().map(|h| ring_area(h)).sum::<f64>()
        })
        .sum()
}

/// The polygons' areas added up (each by the shoelace formula).
pub fn area_sum(polygons: &[Vec<DVec2>]) -> f64 {
    polygons
        .iter()
        .map(|p| ring_area(&p.iter().map(|v| [v.x, v.y]).collect::<Vec<_>>()))
        .sum()
}

/// How much of the polygons' area is covered more than once: the sum of areas minus the
/// area of their union (0 for polygons that only touch).
pub fn overlap_area(polygons: &[Vec<DVec2>]) -> f64 {
    area_sum(polygons) - union_area(polygons)
}

#[test]
fn the_oracle_sees_an_overlap_and_ignores_a_shared_edge() {
    let square = |x: f64, y: f64| {
        vec![
            DVec2::new(x, y),
            DVec2::new(x + 1.0, y),
            DVec2::new(x + 1.0, y + 1.0),
            DVec2::new(x, y + 1.0),
        ]
    };
    // Side by side: no overlap.
    assert!(overlap_area(&[square(0.0, 0.0), square(1.0, 0.0)]).abs() < 1e-9);
    // Shifted by half: a quarter of a square is covered twice... here 0.5 × 0.5.
    let twice = overlap_area(&[square(0.0, 0.0), square(0.5, 0.5)]);
    assert!((twice - 0.25).abs() < 1e-9, "{twice}");
    // A non-convex L and a square in its notch: no overlap.
    let l = vec![
        DVec2::new(0.0, 0.0),
        DVec2::new(2.0, 0.0),
        DVec2::new(2.0, 1.0),
        DVec2::new(1.0, 1.0),
        DVec2::new(1.0, 2.0),
        DVec2::new(0.0, 2.0),
    ];
    assert!(overlap_area(&[l.clone(), square(1.0, 1.0)]).abs() < 1e-9);
    assert!((overlap_area(&[l, square(0.5, 0.5)]) - 0.75).abs() < 1e-9);
}
