//! From a FOLD file to G-code through the library's public surface only: read the pattern,
//! clean it into a planar graph, give it a size if it has none, check it, plan it for a machine
//! and material, post-process it as G-code, read the G-code back on the simulated machine and
//! check that every crease and cut comes out as planned, then write it.
//!
//! ```text
//! cargo run --example pattern_to_gcode -- [IN.fold] [OUT.gcode] [MACHINE] [MATERIAL]
//! ```
//! Defaults: `examples/patterns/flat-vertex.fold`, `foldcam-examples/flat-vertex.gcode`, the
//! shipped `grbl-diode` machine and `card-300gsm` material. A unitless pattern is scaled so
//! its longer side is 150 mm.

use std::path::PathBuf;
use std::process::ExitCode;

use foldcam::{
    CheckOptions, Job, JobFormat, OutputSet, PlanOverrides, PlanarizeOptions, Scale, Units, check,
    load, load_machine, load_material, planarize,
};

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("pattern_to_gcode: {e}");
            ExitCode::from(2)
        }
    }
}

fn run() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let input = PathBuf::from(
        args.next()
            .unwrap_or_else(|| "examples/patterns/flat-vertex.fold".into()),
    );
    let output = PathBuf::from(
        args.next()
            .unwrap_or_else(|| "foldcam-examples/flat-vertex.gcode".into()),
    );
    let machine = load_machine(&args.next().unwrap_or_else(|| "grbl-diode".into()))?;
    let material = load_material(&args.next().unwrap_or_else(|| "card-300gsm".into()))?;

    let mut pattern = load(&input)?.pattern;
    planarize(&mut pattern, &PlanarizeOptions::default())?;
    if pattern.units == Units::Unitless {
        pattern.scale_to(Scale::Size(150.0))?;
    }
    let report = check(&pattern, &CheckOptions::default());
    println!(
        "{}: {} vertices, {} edges, {}",
        input.display(),
        pattern.vertices.len(),
        pattern.edges.len(),
        if report.passed() {
            "folds flat at every vertex"
        } else {
            "does not fold flat everywhere (cut anyway)"
        }
    );

    let job = Job::plan(&pattern, &machine, &material, &PlanOverrides::default())?
        .post(JobFormat::Gcode)?
        .verify()?;
    for (file, r) in job.paths(&output).iter().zip(&job.readback) {
        println!(
            "{}: {:.0} mm burned, {} pierces, {:.0} s on {}; {} violations; {} of {} edges as planned",
            file.display(),
            r.sim.burn_length_mm,
            r.sim.pierces,
            r.sim.time_s,
            machine.name,
            r.sim.violation_count,
            r.coverage.edges.len() - r.coverage.failed_edges().count(),
            r.coverage.edges.len(),
        );
    }
    if !job.is_clean() {
        return Err("the simulated machine found problems: nothing written".into());
    }
    if let Some(dir) = output.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)?;
    }
    let mut files = OutputSet::new();
    job.stage(&output, &mut files)?;
    files.commit()?;
    Ok(())
}
