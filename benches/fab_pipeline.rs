//! Plan and G-code for a 200,000-crease pattern (issue 3: "well under the ~90 s vpype needs
//! just to sort such a file").
//!
//! The pattern is a 316 × 316 flat-foldable grid of 5 mm cells (200,344 edges, all creases
//! perforated on 160 g/m² paper, outline cut) on a GRBL diode-laser profile with its bed
//! enlarged to 2 m. Cases: `plan` (perforation layout, contours, travel-optimised order,
//! statistics) and `gcode` (writing one job). The travel length of the optimised order and of
//! the pattern order are printed once before the measurements.
//!
//! `plot_55k_segments`: the plan of a pen plot of 55,760 segments (a triangulated grid of
//! 136 × 136 cells of 2.06 mm, every segment its own mountain line, in shuffled order) on the
//! pen plotter: Euler strokes, their order, statistics. The command it stands for, `foldcam
//! cut grid.svg -m grbl-pen-plotter -x card-300gsm --mountain plot`, is compared with vpype's
//! `read … linesort write` in the note (same drawing as an SVG).
//!
//! Run with `cargo bench --bench fab_pipeline`.

use criterion::{Criterion, criterion_group, criterion_main};
use foldcam::design::classic::grid;
use foldcam::fab::{PlanOptions, plan};
use foldcam::machine::{load_machine, load_material};
use foldcam::pattern::{Assignment, CreasePattern};
use glam::DVec2;

/// The shuffled triangulated grid of the plotting case: `n` × `n` cells of `cell` mm.
fn shuffled_grid(n: usize, cell: f64) -> CreasePattern {
    let mut cp = CreasePattern::new();
    let vertex = |i: usize, j: usize| foldcam::pattern::VertexId::new(i * (n + 1) + j);
    for i in 0..=n {
        for j in 0..=n {
            cp.add_vertex(DVec2::new(i as f64 * cell, j as f64 * cell));
        }
    }
    let mut segments = Vec::new();
    for i in 0..=n {
        for j in 0..n {
            segments.push((vertex(i, j), vertex(i, j + 1)));
            segments.push((vertex(j, i), vertex(j + 1, i)));
        }
    }
    for i in 0..n {
        for j in 0..n {
            segments.push((vertex(i, j), vertex(i + 1, j + 1)));
        }
    }
    let mut state = 7u64;
    for k in (1..segments.len()).rev() {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        segments.swap(k, (state >> 33) as usize % (k + 1));
    }
    for (a, b) in segments {
        cp.add_edge(a, b, Assignment::Mountain);
    }
    cp
}

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

    let cp = shuffled_grid(136, 280.0 / 136.0);
    let plotter = load_machine("grbl-pen-plotter").expect("shipped machine");
    let card = load_material("card-300gsm").expect("shipped material");
    let overrides = foldcam::fab::PlanOverrides {
        mountain: Some(Some(foldcam::fab::Operation::Plot)),
        ..Default::default()
    };
    let options = PlanOptions::for_machine(&plotter, &card, &overrides).expect("adapts");
    let p = plan(&cp, &plotter, &card, &options).expect("plans");
    eprintln!(
        "pen plot: {} segments → {} toolpaths (pen-downs {}), travel {:.0} mm",
        cp.edges.len(),
        p.jobs[0].paths.len(),
        p.stats.pierces,
        p.stats.travel_mm
    );
    let mut g = c.benchmark_group("plot_55k_segments");
    g.sample_size(10);
    g.bench_function("plan", |b| {
        b.iter(|| plan(&cp, &plotter, &card, &options).expect("plans"))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
