//! Planarising and checking a million-edge grid (issue 2's size target: under 1 s).
//!
//! Cases, all on a 707 × 707 flat-foldable square grid (1,001,112 edges):
//! - `planarize/clean`: the grid as a clean graph (shared vertices): detects that nothing needs
//!   doing, which is the cost every import pays;
//! - `planarize/segments`: the same grid drawn as 1,001,112 loose segments (two vertices each,
//!   as an SVG or `.cp` import delivers it): every vertex merges;
//! - `check`: Kawasaki, Maekawa, vertex angle and shortest edge over the clean grid;
//! - `planarize_and_check/segments`: the whole `foldcam check` pipeline from loose segments.
//!
//! Run with `cargo bench --bench planarize_check`.

use criterion::{BatchSize, Criterion, criterion_group, criterion_main};
use foldcam::check::{CheckOptions, check};
use foldcam::design::classic::grid;
use foldcam::pattern::{CreasePattern, PlanarizeOptions, planarize};

const CELLS: usize = 707;

fn loose_segments(cp: &CreasePattern) -> CreasePattern {
    let mut loose = CreasePattern::new();
    for e in &cp.edges {
        let [a, b] = e.vertices;
        loose.add_segment(cp.position(a), cp.position(b), e.assignment);
    }
    loose
}

fn bench(c: &mut Criterion) {
    let clean = grid(CELLS, 1.0).expect("grid parameters are valid");
    let loose = loose_segments(&clean);
    eprintln!(
        "grid: {} vertices, {} edges; loose: {} vertices",
        clean.vertices.len(),
        clean.edges.len(),
        loose.vertices.len()
    );
    let opts = PlanarizeOptions::default();
    let mut g = c.benchmark_group("million_edge_grid");
    g.sample_size(10);
    g.bench_function("planarize/clean", |b| {
        b.iter_batched_ref(
            || clean.clone(),
            |cp| planarize(cp, &opts).expect("planar"),
            BatchSize::LargeInput,
        )
    });
    g.bench_function("planarize/segments", |b| {
        b.iter_batched_ref(
            || loose.clone(),
            |cp| planarize(cp, &opts).expect("planar"),
            BatchSize::LargeInput,
        )
    });
    let check_opts = CheckOptions {
        min_vertex_angle_deg: Some(30.0),
        ..CheckOptions::default()
    };
    g.bench_function("check", |b| b.iter(|| check(&clean, &check_opts)));
    g.bench_function("planarize_and_check/segments", |b| {
        b.iter_batched_ref(
            || loose.clone(),
            |cp| {
                planarize(cp, &opts).expect("planar");
                check(cp, &check_opts)
            },
            BatchSize::LargeInput,
        )
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
