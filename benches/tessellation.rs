//! Freeform origami tessellations (Tachi 2014): initial pattern plus the generalized
//! Newton–Raphson solve (§3.3) on the sample dome at about 100, 500 and 2,000 input faces (4, 9
//! and 18 rings: 96, 486 and 1,944 triangles). The issue aims for under 1 s at 500.
//!
//! - `star`: star tucks (§2.1), checkerboard layout, fold ≤ 178°, vertex angle ≥ 30°. The
//!   0.5 mm stainless fold limit of 165° is not reached with star tucks on these finer domes
//!   (the tucks of a shallow region must close almost flat).
//! - `truncated`: truncated stars (§2.2), the paper's design example, at the stainless limits
//!   (fold ≤ 165°, creases ≥ 30° apart) with face shrink 0.5, the shrink that converges at 486
//!   faces (0.8, 0.7 and 0.6 end with face collisions or a stalled solve there).
//!
//! The 1,944-face dome (18 rings) is solved with star tucks only: truncated stars at the
//! stainless limits tangle there (creases pass through vertex-adjacent faces, eq. 5–7).
//!
//! Run with `cargo bench --bench tessellation -- --quick`.

use criterion::{Criterion, criterion_group, criterion_main};
use foldcam::design::tessellation::{
    Limits, SampleSurface, TessellateOptions, TuckKind, assign_folds, disk, sample_surface, solve,
    star_tucks,
};

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("tessellation");
    g.sample_size(10);
    let cases = [
        ("star", TuckKind::Star, 178.0, 0.8),
        ("truncated", TuckKind::Truncated, 165.0, 0.5),
    ];
    for rings in [4, 9, 18] {
        let mesh = sample_surface(SampleSurface::Dome, rings, 20.0);
        let faces = mesh.faces().len();
        let cases = if rings == 18 { &cases[..1] } else { &cases[..] };
        for &(name, kind, fold, shrink) in cases {
            let mut opts = TessellateOptions::with_limits(Limits::from_degrees(fold, 30.0));
            opts.star.tuck.kind = kind;
            opts.star.shrink = shrink;
            g.bench_function(
                format!("dome_{faces}_faces_{name}_initial_and_solve"),
                |b| {
                    b.iter(|| {
                        let he = disk(&mesh).expect("disk");
                        let mut init = star_tucks(&he, &opts.star).expect("initial pattern");
                        assign_folds(&mut init.mesh);
                        let report =
                            solve(&mut init.mesh, &opts.solve, |_| {}).expect("valid options");
                        assert!(report.converged, "{name}: {}", report.summary());
                        report.iterations
                    })
                },
            );
        }
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
