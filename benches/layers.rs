//! Global layer-order solver (Flat-Folder's method: Akitaya, Demaine & Ku 2023): time to fold,
//! build the constraints and count every state of
//! - the square twist from `generate` (9 faces, one state);
//! - Flat-Folder's grid 4x4 D112 (copied in `tests/data/flat-folder`, 4,096 states);
//! - when `../shared/testdata/flat-folder` is present: the traditional crane (72 faces, 5
//!   states), Jason Ku's kitten (182 faces, 81 states) and grid 4x4 D58 (531,441 states, the
//!   slowest grid).
//!
//! Run with `cargo bench --bench layers`. The whole published set runs in
//! `cargo run --release --example flat_folder_set`.

use std::path::PathBuf;

use criterion::{Criterion, criterion_group, criterion_main};
use foldcam::check::layers::{LayerOptions, solve_layers};
use foldcam::design::classic::SquareTwist;
use foldcam::formats;
use foldcam::pattern::{CreasePattern, PlanarizeOptions, planarize};

fn clean(mut cp: CreasePattern) -> CreasePattern {
    let options = PlanarizeOptions {
        tolerance: None,
        faces: true,
    };
    planarize(&mut cp, &options).expect("planarises");
    cp
}

fn load(path: PathBuf) -> Option<CreasePattern> {
    formats::load(&path).ok().map(|i| clean(i.pattern))
}

fn bench(c: &mut Criterion) {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let shared = root.join("../shared/testdata/flat-folder");
    let mut cases = vec![
        (
            "square_twist",
            Some(clean(SquareTwist::default().build().expect("twist"))),
        ),
        (
            "grid_4x4_D112",
            load(root.join("tests/data/flat-folder/372_brown_4x4_D112.fold")),
        ),
        (
            "crane",
            load(shared.join("instagram/004_traditional_Crane.fold")),
        ),
        ("kitten", load(shared.join("instagram/005_ku_Kitten.fold"))),
        (
            "grid_4x4_D58",
            load(shared.join("grids/318_brown_4x4_D58.fold")),
        ),
    ];
    let mut group = c.benchmark_group("layers");
    group.sample_size(10);
    for (name, cp) in cases.drain(..) {
        let Some(cp) = cp else {
            eprintln!("layers: {name} skipped (file absent)");
            continue;
        };
        group.bench_function(name, |b| {
            b.iter(|| solve_layers(&cp, &LayerOptions::default()).expect("solves"))
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
