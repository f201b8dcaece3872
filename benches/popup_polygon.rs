//! Polygon pop-up cards (Mitani & Suzuki 2004): 1,000 face additions on one card (§3.2, eq. 5 with the
//! regularised differences of i_overlay), then the line types, pop-up check and crease
//! pattern of the result.
//!
//! The faces are boxes of a "city" (a front wall and a roof each) and slanted quadrilateral
//! openings, at positions from a fixed linear congruential sequence, on a 400 × (200 + 200) mm
//! card: every addition is cut out of the faces it overlaps, so the back and base sheets end up
//! with hundreds of holes.
//!
//! Run with `cargo bench --bench popup_polygon`.

use criterion::{Criterion, criterion_group, criterion_main};
use foldcam::design::popup::polygon::{FaceKind, PolygonCard, check_popup, crease_pattern};
use glam::DVec2;

/// One edit: kind, t, points on the plane, opening or face.
type Edit = (FaceKind, f64, Vec<DVec2>, bool);

fn edits(n: usize) -> Vec<Edit> {
    let mut seed = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = move |range: f64| {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64 * range
    };
    let quad = |x0: f64, y0: f64, x1: f64, y1: f64, skew: f64| {
        vec![
            DVec2::new(x0, y0),
            DVec2::new(x1, y0),
            DVec2::new(x1 + skew, y1),
            DVec2::new(x0 + skew, y1),
        ]
    };
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let (x, w) = (next(380.0), 4.0 + next(16.0));
        let (d, h) = (5.0 + next(150.0), 5.0 + next(150.0));
        out.push((FaceKind::Vertical, d, quad(x, 0.0, x + w, h, 0.0), false));
        out.push((FaceKind::Horizontal, h, quad(x, 0.0, x + w, d, 0.0), false));
        let (z, s) = (next(h * 0.5), next(4.0) - 2.0);
        let hole = quad(x + 1.0, z, x + w * 0.5, z + 2.0 + next(h * 0.3), s);
        out.push((FaceKind::Vertical, d, hole, true));
    }
    out.truncate(n);
    out
}

fn build(edits: &[Edit]) -> PolygonCard {
    let mut card = PolygonCard::new(400.0, 200.0, 200.0).expect("card");
    for (kind, t, pts, opening) in edits {
        let r = if *opening {
            card.add_opening(*kind, *t, pts)
        } else {
            card.add_face(*kind, *t, pts)
        };
        r.ok();
    }
    card
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("popup_polygon");
    g.sample_size(10);
    let list = edits(1000);
    g.bench_function("add_1000_faces", |b| b.iter(|| build(&list)));
    let card = build(&list);
    g.bench_function("check_1000", |b| b.iter(|| check_popup(&card)));
    g.bench_function("crease_pattern_1000", |b| {
        b.iter(|| crease_pattern(&card).expect("pattern"))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
