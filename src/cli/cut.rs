//! `foldcam cut PATTERN --machine M --material X -o job.gcode`.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use foldcam::fab::{FabPlan, Job};
use foldcam::machine::MachineProfile;
use foldcam::post::{self, DxfVersion};

use super::Outcome;
use super::fab_args::PlanRequest;

/// Output kinds by extension.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Output {
    Gcode,
    Dxf,
    Svg,
    Lbrn2,
}

fn output_kind(path: &Path) -> Result<Output> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .unwrap_or_default();
    Ok(match ext.as_str() {
        "gcode" | "nc" | "ngc" | "gc" => Output::Gcode,
        "dxf" => Output::Dxf,
        "svg" => Output::Svg,
        "lbrn2" => Output::Lbrn2,
        _ => bail!(
            "{}: unknown job type (expected .gcode, .nc, .ngc, .dxf, .svg or .lbrn2)",
            path.display()
        ),
    })
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
    let mut outputs = foldcam::formats::OutputSet::new();
    stage_jobs(&mut outputs, output, p, machine, r12, dasharray)?;
    super::input::commit(outputs, &[])?;
    print!("{}", super::plan::summary(p));
    Ok(())
}

/// Renders every job of the plan (G-code read back by the simulated machine) and adds the
/// files to `outputs`, written all together or not at all by [`super::input::commit`].
pub fn stage_jobs(
    outputs: &mut foldcam::formats::OutputSet,
    output: &Path,
    p: &FabPlan,
    machine: &MachineProfile,
    r12: bool,
    dasharray: bool,
) -> Result<()> {
    let kind = output_kind(output)?;
    if dasharray && kind != Output::Svg {
        eprintln!("warning: --dasharray applies to SVG output only: ignored");
    }
    let perforates = p
        .jobs
        .iter()
        .flat_map(|j| &j.paths)
        .any(|t| t.op == foldcam::fab::Operation::Perforate);
    if dasharray && kind == Output::Svg && !perforates {
        eprintln!("warning: --dasharray: the plan has no perforation to draw dashed");
    }
    let paths = job_paths(output, p);
    for (job, path) in p.jobs.iter().zip(&paths) {
        let bytes = render(kind, p, job, machine, r12, dasharray)
            .with_context(|| path.display().to_string())?;
        outputs.add(path, bytes);
    }
    Ok(())
}

fn render(
    kind: Output,
    p: &FabPlan,
    job: &Job,
    m: &MachineProfile,
    r12: bool,
    dasharray: bool,
) -> Result<Vec<u8>> {
    Ok(match kind {
        Output::Gcode => {
            let text = post::gcode(p, job, m)?;
            let report = foldcam::sim::run(&text, m)?;
            if let Some(v) = report.violations.first() {
                bail!(
                    "the simulated {} found {} problem(s) in the job, first at line {}: {}",
                    m.name,
                    report.violation_count,
                    v.line,
                    v.message
                );
            }
            text.into_bytes()
        }
        Output::Dxf => {
            let version = if r12 {
                DxfVersion::R12
            } else {
                DxfVersion::R2000
            };
            post::dxf(p, job, version)?
        }
        Output::Svg => post::svg(p, job, &m.bed, dasharray)?.into_bytes(),
        Output::Lbrn2 => post::lbrn2(p, job, m)?.into_bytes(),
    })
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
