//! Fold-sequence simulator (Miyazaki et al. 1992): time of one fold step on a state of about 1,000 faces.
//!
//! The paper folds interactively in real time on an IRIS 4D/70; here a 100 mm square is
//! folded in half ten times (alternately across x and y, all layers), giving 1,024 stacked
//! faces, and one more fold is timed (and undone after every iteration): `all_layers` bends
//! every layer along the small square's diagonal (1,024 faces split), `outer_layer` bends only
//! the top layer's corner (the §4.1 search runs over the whole stack).
//!
//! Run with `cargo bench --bench folding`.

use criterion::{Criterion, criterion_group, criterion_main};
use foldcam::design::folding::{Fold, Folding, Layers, Turn};
use glam::{DVec2, DVec3};

fn stacked(folds: usize) -> (Folding, f64) {
    let side = 100.0;
    let mut f = Folding::new(&[
        DVec2::ZERO,
        DVec2::new(side, 0.0),
        DVec2::new(side, side),
        DVec2::new(0.0, side),
    ])
    .expect("sheet");
    let (mut w, mut h) = (side, side);
    for k in 0..folds {
        let p = |x: f64, y: f64| DVec3::new(x, y, 0.0);
        let fold = if k % 2 == 0 {
            w /= 2.0;
            Fold {
                line: [p(w, 0.0), p(w, h)],
                moving: p(w * 1.5, h / 2.0),
                turn: Turn::Angle(180.0),
                layers: Layers::All,
            }
        } else {
            h /= 2.0;
            Fold {
                line: [p(0.0, h), p(w, h)],
                moving: p(w / 2.0, h * 1.5),
                turn: Turn::Angle(-180.0),
                layers: Layers::All,
            }
        };
        f.fold(&fold, None).expect("fold in half");
    }
    (f, w)
}

fn bench(c: &mut Criterion) {
    let (mut f, s) = stacked(10);
    assert_eq!(f.current().faces.len(), 1024);
    let p = |x: f64, y: f64| DVec3::new(x, y, 0.0);
    let diagonal = Fold {
        line: [p(0.0, 0.0), p(s, s)],
        moving: p(s * 0.9, s * 0.1),
        turn: Turn::Angle(180.0),
        layers: Layers::All,
    };
    let corner = Fold {
        line: [p(s * 0.5, 0.0), p(s, s * 0.5)],
        moving: p(s * 0.95, s * 0.05),
        turn: Turn::Angle(180.0),
        layers: Layers::Outer(1),
    };
    let mut group = c.benchmark_group("fold_1024_faces");
    for (name, fold) in [("all_layers", &diagonal), ("outer_layer", &corner)] {
        group.bench_function(name, |b| {
            b.iter(|| {
                f.fold(fold, None).expect("fold");
                f.undo().expect("undo");
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
