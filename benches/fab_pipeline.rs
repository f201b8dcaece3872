//! Plan and G-code for a 200,000-crease pattern (issue 3: "well under the ~90 s vpype needs
//! just to sort such a file").
//!
//! The pattern is a 316 × 316 flat-foldable grid of 5 mm cells (200,344 edges, all creases
//! perforated on 160 g/m² paper, outline cut) on a GRBL diode-laser profile with its bed
//! enlarged to 2 m. Cases: `plan` (perforation layout, contours, travel-optimised order,
//! statistics) and `gcode` (writing one job). The travel length of the optimised order and of
//! the pattern order are printed once before the measurements.
//!
//! Run with `cargo bench --bench fab_pipeline`.

use criterion::{Criterion, criterion_group, criterion_main};
use foldcam::design::classic::grid;
use foldcam::fab::{PlanOptions, plan};
use foldcam::machine::{load_machine, load_material};

fn bench(c: &mut Criterion) {
    let cp = grid(316, 5.0).expect("grid parameters are valid");
    let mut machine = load_machine("grbl-diode").expect("shipped machine");
    machine.bed.width_mm = 2000.0;
    machine.bed.height_mm = 2000.0;
    let material = load_material("paper-160gsm").expect("shipped material");
    let options = PlanOptions::from_material(&material);
    let p = plan(&cp, &machine, &material, &options).expect("plans");
    let paths: usize = p.jobs.iter().map(|j| j.paths.len()).sum();
    eprintln!(
        "{} edges → {} toolpaths, {} pierces; travel {:.0} mm optimised vs {:.0} mm in pattern \
         order ({:.1}×); estimated time {:.0} s",
        cp.edges.len(),
        paths,
        p.stats.pierces,
        p.stats.travel_mm,
        p.stats.naive_travel_mm,
        p.stats.naive_travel_mm / p.stats.travel_mm.max(1e-9),
        p.stats.time_s
    );
    let gcode = foldcam::post::gcode(&p, &p.jobs[0], &machine).expect("G-code");
    eprintln!(
        "G-code: {} bytes, {} lines",
        gcode.len(),
        gcode.lines().count()
    );
    let mut g = c.benchmark_group("fab_200k_creases");
    g.sample_size(10);
    g.bench_function("plan", |b| {
        b.iter(|| plan(&cp, &machine, &material, &options).expect("plans"))
    });
    g.bench_function("gcode", |b| {
        b.iter(|| foldcam::post::gcode(&p, &p.jobs[0], &machine).expect("G-code"))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
