//! Compliant 3D fold simulation (Ghassaei, Demaine & Gershenfeld 2018, on the CPU): solver
//! steps per second on Miura-ori sheets of about 1,000, 10,000 and 100,000 triangles, a
//! 20 × 20 Miura-ori folded to 90 % end to end (model, triangulation, dynamics until settled,
//! report), and a 71 × 71 one (10,082 triangles) by the explicit dynamics and by the static
//! solve.
//!
//! The targets on 2 cores: ≥ 200 steps/s at 10,000 triangles, the Miura-ori in under
//! 1 s. Run with `cargo bench --bench fold3d`.

use criterion::{BatchSize, Criterion, criterion_group, criterion_main};
use foldcam::check::fold3d::Solver;
use foldcam::check::fold3d::{BarHingeModel, FoldOptions, fold};
use foldcam::design::classic::MiuraOri;
use foldcam::pattern::CreasePattern;

/// A Miura-ori sheet; `build` cleans it and traces its faces, as the simulation needs.
fn miura(columns: usize, rows: usize) -> CreasePattern {
    MiuraOri {
        columns,
        rows,
        ..MiuraOri::default()
    }
    .build()
    .expect("miura")
}

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("fold3d");
    // 22 × 22, 71 × 71 and 224 × 224 parallelograms: 968, 10,082 and 100,352 triangles.
    for (side, name) in [(22, "1k"), (71, "10k"), (224, "100k")] {
        let cp = miura(side, side);
        let model = BarHingeModel::build(&cp).expect("model");
        eprintln!("steps: {} triangles", model.triangles.len());
        let opts = FoldOptions::default();
        group.sample_size(if side > 100 { 10 } else { 20 });
        group.bench_function(format!("100 steps, {name} triangles"), |b| {
            b.iter_batched_ref(
                || {
                    let mut s = Solver::new(&model, &opts);
                    s.set_fraction(0.5);
                    s
                },
                |s| {
                    for _ in 0..100 {
                        s.step();
                    }
                },
                BatchSize::LargeInput,
            )
        });
    }
    group.sample_size(20);
    let small = miura(20, 20);
    let opts = FoldOptions {
        percent: 90.0,
        ..FoldOptions::default()
    };
    let f = fold(&small, &opts).expect("fold");
    eprintln!(
        "miura 20x20 to 90%: {} triangles, {} steps, {:?}, strain {:.2e}, angle error {:.2} deg",
        f.report.triangles,
        f.report.steps,
        f.report.stop,
        f.report.max_strain,
        f.report.max_angle_error_deg
    );
    group.bench_function("miura 20x20 to 90%", |b| {
        b.iter(|| fold(&small, &opts).expect("fold"))
    });
    // The target: a 10,000-triangle pattern settled to 90 % in under 3 s, by the
    // explicit dynamics and by the static solve (`FoldOptions::implicit`).
    group.sample_size(10);
    let big = miura(71, 71);
    for implicit in [false, true] {
        let opts = FoldOptions {
            percent: 90.0,
            implicit,
            ..FoldOptions::default()
        };
        let name = if implicit { "static solve" } else { "explicit" };
        group.bench_function(format!("miura 71x71 to 90%, {name}"), |b| {
            b.iter(|| fold(&big, &opts).expect("fold"))
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
