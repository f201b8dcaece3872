//! `foldcam cut PATTERN --machine M --material X -o job.gcode`.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use foldcam::fab::Operation;
use foldcam::formats::OutputSet;
use foldcam::job::{JOB_EXTENSIONS, Job, JobFormat};

use super::Outcome;
use super::fab_args::PlanRequest;

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
    let l = args.request.load()?;
    let job = Job::plan_with(&l.pattern, &l.machine, &l.material, l.options)
        .with_context(|| args.request.input.display().to_string())?;
    let mut outputs = OutputSet::new();
    stage_job(&mut outputs, &args.output, job, args.r12, args.dasharray)?;
    super::input::commit(outputs, &[&args.request.input])?;
    Ok(Outcome::Done)
}

/// The job format `output`'s extension asks for, with the DXF and SVG choices.
pub fn job_format(output: &Path, r12: bool, dasharray: bool) -> Result<JobFormat> {
    let Some(format) = JobFormat::from_path(output) else {
        bail!(
            "{}: unknown job type (expected {JOB_EXTENSIONS})",
            output.display()
        );
    };
    if dasharray && !matches!(format, JobFormat::Svg { .. }) {
        eprintln!("warning: --dasharray applies to SVG output only: ignored");
    }
    Ok(format.with_choices(r12, dasharray))
}

/// Renders a planned job as `output`'s extension says (G-code first read back by the
/// simulated machine: a violation stops the run) and adds its files to `outputs`; prints the
/// plan's summary. Nothing is staged unless every job renders and checks.
pub fn stage_job(
    outputs: &mut OutputSet,
    output: &Path,
    job: Job<'_>,
    r12: bool,
    dasharray: bool,
) -> Result<()> {
    let format = job_format(output, r12, dasharray)?;
    let perforates = job
        .plan
        .jobs
        .iter()
        .flat_map(|j| &j.paths)
        .any(|t| t.op == Operation::Perforate);
    if format == (JobFormat::Svg { dasharray: true }) && !perforates {
        eprintln!("warning: --dasharray: the plan has no perforation to draw dashed");
    }
    let mut job = job
        .post(format)
        .with_context(|| output.display().to_string())?;
    if format == JobFormat::Gcode {
        job = job.verify().with_context(|| output.display().to_string())?;
        let m = job.machine;
        for r in &job.readback {
            if let Some(v) = r.sim.violations.first() {
                bail!(
                    "the simulated {} found {} problem(s) in the job, first at line {}: {}",
                    m.name,
                    r.sim.violation_count,
                    v.line,
                    v.message
                );
            }
        }
    }
    job.stage(output, outputs)?;
    print!("{}", super::plan::summary(&job.plan));
    Ok(())
}
