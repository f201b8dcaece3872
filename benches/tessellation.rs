//! Freeform origami tessellations (seed 002): initial star-tuck pattern plus the
//! generalized Newton–Raphson solve (§3.3) on the sample dome (checkerboard layout, fold
//! ≤ 178°, vertex angle ≥ 30°) at about 100 and 500 input faces (4 and 9 rings: 96 and 486
//! triangles). The issue aims for under 1 s at 500. The 0.5 mm stainless fold limit of 165°
//! is not reachable on the finer domes (the star tucks of a shallow region must close almost
//! flat), hence 178°; the 1,944-face dome does not converge yet and is left out.
//!
//! Run with `cargo bench --bench tessellation -- --quick`.

use criterion::{Criterion, criterion_group, criterion_main};
use foldcam::design::tessellation::{
    Limits, SampleSurface, TessellateOptions, assign_folds, disk, sample_surface, solve, star_tucks,
};

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("tessellation");
    g.sample_size(10);
    for rings in [4, 9] {
        let mesh = sample_surface(SampleSurface::Dome, rings, 20.0);
        let opts = TessellateOptions::with_limits(Limits::from_degrees(178.0, 30.0));
        let faces = mesh.faces().len();
        g.bench_function(format!("dome_{faces}_faces_initial_and_solve"), |b| {
            b.iter(|| {
                let he = disk(&mesh).expect("disk");
                let mut init = star_tucks(&he, &opts.star).expect("initial pattern");
                assign_folds(&mut init.mesh);
                let report = solve(&mut init.mesh, &opts.solve, |_| {}).expect("valid options");
                assert!(report.converged, "{}", report.summary());
                report.iterations
            })
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
