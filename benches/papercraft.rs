//! Paper craft (seed 004): design to parts for the bundled vase
//! (`examples/papercraft/vase.craft.toml`, 8 gores on a mesh of 7,680 triangles): `build`
//! runs the network, walls, trimming at 0.05 mm, unrolling, tabs, packing and the sheet
//! patterns; `reference` builds the projection grid; `project` is one closest-point query
//! (9 mm outside the vase: 207 µs before the grid visited only ring shells and skipped cells
//! and triangles whose boxes are no nearer than the best so far, 29 µs after, on the shared
//! 2-core machine).
//! The thesis gives no timings.
//!
//! Run with `cargo bench --bench papercraft`.

use criterion::{Criterion, criterion_group, criterion_main};
use foldcam::design::papercraft::ReferenceMesh;
use foldcam::design::papercraft::design::parse_design;
use foldcam::mesh::read_mesh;
use glam::DVec3;

fn bench(c: &mut Criterion) {
    let text = std::fs::read_to_string("examples/papercraft/vase.craft.toml").expect("vase design");
    let design = parse_design(&text).expect("valid design");
    let mesh = read_mesh(std::path::Path::new("examples/papercraft/vase.obj")).expect("vase mesh");
    let reference = ReferenceMesh::new(&mesh).expect("usable mesh");
    let mut group = c.benchmark_group("papercraft");
    group.sample_size(10);
    group.bench_function("vase/build", |b| {
        b.iter(|| design.build(&reference).expect("builds"))
    });
    group.bench_function("vase/reference", |b| {
        b.iter(|| ReferenceMesh::new(&mesh).expect("usable"))
    });
    group.bench_function("vase/project", |b| {
        b.iter(|| reference.project(std::hint::black_box(DVec3::new(50.0, 10.0, 40.0))))
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
