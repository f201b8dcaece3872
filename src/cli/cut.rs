//! `foldcam cut PATTERN --machine M --material X -o job.gcode`.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use foldcam::fab::{FabPlan, Operation};
use foldcam::formats::OutputSet;
use foldcam::job::{
    JOB_EXTENSIONS, Job, JobFormat, WriterChoices, check_gcode, job_files, job_paths,
};
use foldcam::machine::MachineProfile;

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
    #[arg(short, long, help = format!(
        "Job file ({}; .lbrn2 is a LightBurn project, one layer per operation with the \
         material's settings); written atomically",
        foldcam::job::JOB_EXTENSIONS
    ))]
    pub output: PathBuf,
    /// Write DXF R12 (LINE/POLYLINE) instead of R2000.
    #[arg(long)]
    pub r12: bool,
    /// In SVG output, draw each perforated crease as one path with a dash style (for viewing
    /// in Inkscape) instead of one path per dash; plotter software such as vpype, and
    /// LightBurn, draw dash styles as solid lines.
    #[arg(long)]
    pub dasharray: bool,
    /// In a LightBurn project (.lbrn2), hand perforations to LightBurn's perforation mode:
    /// each crease one path, one layer per distinct dash and gap, so every crease keeps its
    /// fitted dashes. By default every dash is a shape of its own.
    #[arg(long)]
    pub lightburn_perforation: bool,
    /// Write a framing job instead of the job (G-code only): the job's bounding box traced
    /// with the laser off (or the pen up), as LightBurn's Frame does, to see where it lands
    /// on the sheet. (The FOLD frame to read is --fold-frame.)
    #[arg(long)]
    pub frame: bool,
    /// Trace the frame with the laser on at this power, a fraction of the machine's range
    /// (0 to 1; default 0: off), at the material's mark speed. Ignored by pen plotters.
    #[arg(long, value_name = "SHARE", requires = "frame", value_parser = frame_power)]
    pub frame_power: Option<f64>,
    #[command(flatten)]
    pub stdout: super::pipe::ToArg,
}

impl Args {
    /// The writer choices asked for.
    pub fn choices(&self) -> WriterChoices {
        WriterChoices {
            r12: self.r12,
            dasharray: self.dasharray,
            lightburn_perforation: self.lightburn_perforation,
        }
    }
}

/// Parses a power from 0 to 1.
fn frame_power(s: &str) -> Result<f64, String> {
    let v: f64 = s.parse().map_err(|_| format!("{s:?} is not a number"))?;
    if (0.0..=1.0).contains(&v) {
        Ok(v)
    } else {
        Err(format!(
            "{s} must be from 0 to 1 (a share of the machine's power)"
        ))
    }
}

/// Plans and writes the job files (or their frames).
pub fn run(args: Args) -> Result<Outcome> {
    let output = super::outputs::target(&args.output)?;
    let input = args.request.input.as_path();
    super::outputs::check(&[Some(&output)], &[input])?;
    let l = args.request.load()?;
    let job = Job::plan_with(&l.pattern, &l.machine, &l.material, l.options)
        .with_context(|| args.request.input.display().to_string())?;
    if args.frame {
        let power = args.frame_power.unwrap_or(0.0);
        write_frames(&output, &job.plan, job.machine, power, input)?;
        return Ok(Outcome::Done);
    }
    let mut outputs = OutputSet::new();
    stage_job(&mut outputs, &output, &job, args.choices())?;
    super::outputs::commit(outputs, &[input])?;
    out!("{}", super::plan::summary(&job.plan));
    Ok(Outcome::Done)
}

/// Writes one framing job per job of the plan (G-code, read back by the simulated machine
/// first), and says what each traces.
fn write_frames(
    output: &Path,
    p: &FabPlan,
    machine: &MachineProfile,
    power: f64,
    input: &Path,
) -> Result<()> {
    if job_format(output, WriterChoices::default())? != JobFormat::Gcode {
        bail!(
            "{}: --frame writes G-code (.gcode, .nc, .ngc); LightBurn and other job software \
             frame a drawing themselves",
            output.display()
        );
    }
    let mut outputs = OutputSet::new();
    for (job, path) in p.jobs.iter().zip(job_paths(output, p)) {
        let text = foldcam::post::gcode::frame(p, job, machine, power)
            .with_context(|| path.display().to_string())?;
        check_gcode(&text, machine).with_context(|| path.display().to_string())?;
        outputs.add(path, text);
    }
    super::outputs::commit(outputs, &[input])?;
    for job in &p.jobs {
        if let Some((lo, hi)) = foldcam::fab::bounds(job) {
            let how = if power > 0.0 && !machine.pen_tool() {
                format!("at {:.0}% power", power * 100.0)
            } else {
                "with the tool off".to_string()
            };
            outln!(
                "frame {:<6} X {:.3} to {:.3}, Y {:.3} to {:.3} mm ({:.1} × {:.1} mm), {how}",
                job.name,
                lo.x,
                hi.x,
                lo.y,
                hi.y,
                hi.x - lo.x,
                hi.y - lo.y
            );
        }
    }
    Ok(())
}

/// The job format `output`'s extension asks for, with the writer choices that apply to it
/// (a warning names each one that does not).
pub fn job_format(output: &Path, choices: WriterChoices) -> Result<JobFormat> {
    let Some(format) = JobFormat::from_path(output) else {
        bail!(
            "{}: unknown job type (expected {JOB_EXTENSIONS})",
            output.display()
        );
    };
    if choices.dasharray && !matches!(format, JobFormat::Svg { .. }) {
        errln!("warning: --dasharray applies to SVG output only: ignored");
    }
    if choices.lightburn_perforation && !matches!(format, JobFormat::Lbrn2 { .. }) {
        errln!("warning: --lightburn-perforation applies to .lbrn2 output only: ignored");
    }
    Ok(format.with_choices(choices))
}

/// Stages a planned job's files as `output`'s extension says (see [`stage_plan`]).
pub fn stage_job(
    outputs: &mut OutputSet,
    output: &Path,
    job: &Job<'_>,
    choices: WriterChoices,
) -> Result<()> {
    stage_plan(outputs, output, &job.plan, job.machine, choices)
}

/// Renders every job of the plan as `output`'s extension says (G-code first read back by
/// the simulated machine: a violation stops the run) and adds the files to `outputs`,
/// written all together or not at all by [`super::outputs::commit`].
pub fn stage_plan(
    outputs: &mut OutputSet,
    output: &Path,
    p: &FabPlan,
    machine: &MachineProfile,
    choices: WriterChoices,
) -> Result<()> {
    let format = job_format(output, choices)?;
    if super::pipe::is_stdout(output) && p.jobs.len() > 1 {
        bail!(
            "-: a two-sided plan is {} files (front and back): name the output instead of \
             writing standard output",
            p.jobs.len()
        );
    }
    let perforates = p
        .jobs
        .iter()
        .flat_map(|j| &j.paths)
        .any(|t| t.op == Operation::Perforate);
    if format == (JobFormat::Svg { dasharray: true }) && !perforates {
        errln!("warning: --dasharray: the plan has no perforation to draw dashed");
    }
    if format == (JobFormat::Svg { dasharray: true }) && perforates && machine.pen_tool() {
        errln!(
            "warning: --dasharray on a plotter: vpype and plotter drivers draw dash styles as \
             solid lines; without --dasharray every dash is a path of its own"
        );
    }
    let files = job_files(format, p, machine).with_context(|| output.display().to_string())?;
    for (path, bytes) in job_paths(output, p).into_iter().zip(files) {
        outputs.add(path, bytes);
    }
    Ok(())
}

/// Writes the plan's jobs (see [`stage_plan`]), then its summary.
pub fn write_plan(
    output: &Path,
    p: &FabPlan,
    machine: &MachineProfile,
    choices: WriterChoices,
) -> Result<()> {
    let mut outputs = OutputSet::new();
    stage_plan(&mut outputs, output, p, machine, choices)?;
    super::outputs::commit(outputs, &[])?;
    out!("{}", super::plan::summary(p));
    Ok(())
}
