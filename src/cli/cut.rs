//! `foldcam cut PATTERN --machine M --material X -o job.gcode`.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use foldcam::fab::FabPlan;
use foldcam::formats::write_atomic;
use foldcam::machine::MachineProfile;
use foldcam::post::{JobFileOptions, JobKind, job_file};

use super::Outcome;
use super::fab_args::PlanRequest;

fn output_kind(path: &Path) -> Result<JobKind> {
    match JobKind::from_path(path) {
        Some(kind) => Ok(kind),
        None => bail!(
            "{}: unknown job type (expected {})",
            path.display(),
            JobKind::EXTENSIONS
        ),
    }
}

/// Plan a pattern for a machine and material and write the job.
#[derive(clap::Args)]
#[command(
    long_about = "Plans the pattern (perforations per crease with vertex clearances, scores, \
                  cuts with kerf offset, travel-optimised order) for a machine and material and \
                  writes G-code, DXF or SVG. Two-sided jobs write NAME.front.EXT and \
                  NAME.back.EXT. G-code is read back by the simulated machine before it is \
                  written; a violation stops the run.",
    after_help = "Examples:\n  foldcam cut miura.fold -m grbl-diode -x card-300gsm -o miura.gcode\n  \
                  foldcam cut tess.svg -m linuxcnc-fiber -x stainless-0.5 -o tess.ngc --two-sided\n  \
                  foldcam cut bird.cp --size 150 -m lightburn -x card-300gsm -o bird.dxf"
)]
pub struct Args {
    #[command(flatten)]
    pub request: PlanRequest,
    /// Job file: .gcode/.nc/.ngc (G-code), .dxf, .svg or .lbrn2 (LightBurn project, one
    /// layer per operation with the material's settings); written atomically.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Write DXF R12 (LINE/POLYLINE) instead of R2000.
    #[arg(long)]
    pub r12: bool,
    /// In SVG output, draw perforations as dashed strokes (for plotting) instead of dashes.
    #[arg(long)]
    pub dasharray: bool,
}

/// Plans and writes the job files.
pub fn run(args: Args) -> Result<Outcome> {
    let (machine, p) = args.request.plan()?;
    write_jobs(&args.output, &p, &machine, args.r12, args.dasharray)?;
    Ok(Outcome::Done)
}

/// Writes the plan's jobs as the output's extension says (G-code read back by the simulated
/// machine first, DXF R2000 or `r12`, SVG with `dasharray` perforations), then its summary.
/// Nothing is written unless every job renders and checks.
pub fn write_jobs(
    output: &Path,
    p: &FabPlan,
    machine: &MachineProfile,
    r12: bool,
    dasharray: bool,
) -> Result<()> {
    let kind = output_kind(output)?;
    if dasharray && kind != JobKind::Svg {
        eprintln!("warning: --dasharray applies to SVG output only: ignored");
    }
    let perforates = p
        .jobs
        .iter()
        .flat_map(|j| &j.paths)
        .any(|t| t.op == foldcam::fab::Operation::Perforate);
    if dasharray && kind == JobKind::Svg && !perforates {
        eprintln!("warning: --dasharray: the plan has no perforation to draw dashed");
    }
    let paths = job_paths(output, p);
    let mut files = Vec::new();
    for (job, path) in p.jobs.iter().zip(&paths) {
        let bytes = job_file(kind, p, job, machine, JobFileOptions { r12, dasharray })
            .with_context(|| path.display().to_string())?;
        files.push((path, bytes));
    }
    for (path, bytes) in &files {
        write_atomic(path, bytes).with_context(|| path.display().to_string())?;
        eprintln!("foldcam: wrote {}", path.display());
    }
    print!("{}", super::plan::summary(p));
    Ok(())
}

/// One path per job: the output itself, or NAME.JOB.EXT for several jobs.
fn job_paths(output: &Path, p: &FabPlan) -> Vec<PathBuf> {
    if p.jobs.len() <= 1 {
        return vec![output.to_path_buf()];
    }
    let stem = output
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let ext = output
        .extension()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    p.jobs
        .iter()
        .map(|j| output.with_file_name(format!("{stem}.{}.{ext}", j.name)))
        .collect()
}
