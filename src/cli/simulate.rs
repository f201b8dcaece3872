//! `foldcam simulate JOB --machine M`: run a G-code job on the simulated machine.

use std::fmt::Write as _;
use std::path::PathBuf;

use anyhow::{Context, Result, anyhow, bail};
use foldcam::fab::plan;
use foldcam::machine::load_machine;
use foldcam::sim::{self, CoverageReport, SimReport};

use super::Outcome;
use super::args::ScaleArgs;
use super::fab_args::{FabArgs, load_pattern};
use super::input::FrameArg;

/// Run a G-code job on a simulated machine: violations, lengths, time, coverage.
#[derive(clap::Args)]
#[command(
    long_about = "Reads a G-code job back and executes it on a machine profile: moves outside \
                  the bed, the laser on during travel, power out of range and unknown words are \
                  reported with their line; burn length per power, travel, pierces and a time \
                  estimate with acceleration are printed. With --pattern and --material the job \
                  is also checked against the pattern (re-planned with the same options as given \
                  to `foldcam cut`): every crease covered at its duty cycle, every cut edge cut, \
                  nothing cut that should not be.\n\nExit status: 0 clean, 1 violations or \
                  coverage faults, 2 bad input.",
    after_help = "Examples:\n  foldcam simulate miura.gcode --machine grbl-diode --png path.png\n  \
                  foldcam simulate miura.gcode -m grbl-diode --pattern miura.fold -x card-300gsm"
)]
pub struct Args {
    /// G-code job to run.
    pub job: PathBuf,
    /// Machine profile (shipped name or TOML path).
    #[arg(long, short = 'm')]
    pub machine: String,
    /// Draw the toolpath (burns by power, travel dashed) to this PNG.
    #[arg(long)]
    pub png: Option<PathBuf>,
    /// Width of the PNG in pixels.
    #[arg(value_name = "PX", long, default_value_t = 1200)]
    pub width: u32,
    /// Print the report as JSON.
    #[arg(long)]
    pub json: bool,
    /// Pattern the job was made from, for the coverage check.
    #[arg(value_name = "FILE", long, requires = "material")]
    pub pattern: Option<PathBuf>,
    /// Material the job was planned for (with --pattern).
    #[arg(long, short = 'x')]
    pub material: Option<String>,
    /// The plan settings the job was made with (as given to `foldcam cut`).
    #[command(flatten)]
    pub fab: FabArgs,
    /// Which job of the plan this file is (front or back).
    #[arg(long, default_value = "front")]
    pub side: String,
    #[command(flatten)]
    pub frame: FrameArg,
    #[command(flatten)]
    pub scale: ScaleArgs,
    #[command(flatten)]
    pub stdout: super::pipe::ToArg,
}

/// Runs the simulation and prints the report.
pub fn run(args: Args) -> Result<Outcome> {
    let machine = load_machine(&args.machine)?;
    // Burns and travels are kept only where they are used; otherwise the run streams the
    // file in memory independent of its length.
    let keep_moves = args.png.is_some() || args.pattern.is_some() || args.json;
    let png = super::outputs::optional(args.png.as_ref())?;
    super::outputs::check(&[png.as_ref()], &[&args.job])?;
    let (source, size): (Box<dyn std::io::Read>, u64) = if super::pipe::is_stdio(&args.job) {
        (Box::new(std::io::stdin()), 0)
    } else {
        let file =
            std::fs::File::open(&args.job).with_context(|| args.job.display().to_string())?;
        let size = file.metadata().map(|m| m.len()).unwrap_or(0);
        (Box::new(file), size)
    };
    let bar = super::progress::bar(size, "simulating");
    let reader = std::io::BufReader::with_capacity(1 << 16, source);
    let report = sim::run_reader(reader, &machine, keep_moves, |bytes| {
        bar.set_position(bytes)
    })
    .map_err(|e| anyhow!("{}: {e}", args.job.display()))?;
    bar.finish_and_clear();
    let coverage = match (&args.pattern, &args.material) {
        (Some(pattern), Some(material)) => Some(check_coverage(&args, &report, pattern, material)?),
        _ => None,
    };
    if let Some(png) = &png {
        let file = args.job.file_name().map(|f| f.to_string_lossy());
        let names = sim::JobNames {
            file: file
                .as_deref()
                .filter(|_| !super::pipe::is_stdio(&args.job)),
            material: args.material.as_deref(),
        };
        let bytes = sim::render_png(&report, &machine, args.width, &names)
            .map_err(|e| anyhow!("{}: {e}", png.display()))?;
        super::outputs::write_one(png, bytes, &[&args.job])?;
    }
    if args.json {
        let value = serde_json::json!({ "run": report, "coverage": coverage });
        outln!("{}", serde_json::to_string_pretty(&value)?);
    } else {
        out!("{}", summary(&args.job, &report, coverage.as_ref()));
    }
    let clean = report.is_clean() && coverage.as_ref().is_none_or(CoverageReport::passed);
    Ok(if clean {
        Outcome::Done
    } else {
        Outcome::CheckFailed
    })
}

fn check_coverage(
    args: &Args,
    report: &SimReport,
    pattern: &std::path::Path,
    material: &str,
) -> Result<CoverageReport> {
    let (machine, material, options) = args.fab.resolve(&args.machine, material)?;
    let cp = load_pattern(pattern, &args.frame, &args.scale)?;
    let p =
        plan(&cp, &machine, &material, &options).with_context(|| pattern.display().to_string())?;
    let Some(job) = p.jobs.iter().find(|j| j.name == args.side) else {
        let names: Vec<&str> = p.jobs.iter().map(|j| j.name.as_str()).collect();
        bail!(
            "the plan has no job {:?} (it has {})",
            args.side,
            names.join(", ")
        );
    };
    Ok(sim::coverage(report, &cp, job, &p))
}

fn summary(job: &std::path::Path, r: &SimReport, coverage: Option<&CoverageReport>) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{} on {} ({} lines)", job.display(), r.machine, r.lines);
    for pl in &r.burn_by_power {
        let _ = writeln!(s, "  burn at S{:<8} {:>12.1} mm", pl.power, pl.length_mm);
    }
    let _ = writeln!(s, "  travel           {:>12.1} mm", r.travel_length_mm);
    let _ = writeln!(s, "  pierces          {:>12}", r.pierces);
    let _ = writeln!(
        s,
        "  time             {:>12.1} s (with acceleration)",
        r.time_s
    );
    for v in r.violations.iter().take(20) {
        let _ = writeln!(s, "  line {:>6}: {}: {}", v.line, v.kind, v.message);
    }
    if r.violation_count > 20 {
        let _ = writeln!(s, "  … and {} more violations", r.violation_count - 20);
    }
    if let Some(c) = coverage {
        let ok = c.edges.iter().filter(|e| e.ok).count();
        let _ = writeln!(s, "  coverage: {ok} of {} edges as planned", c.edges.len());
        let left_out = c.left_out().count();
        if left_out > 0 {
            let _ = writeln!(
                s,
                "    {left_out} edges have no toolpath although the operation mapping asks for \
                 one (left uncut by the plan: see its warnings)"
            );
        }
        for e in c.failed_edges().take(10) {
            let _ = writeln!(
                s,
                "    {} ({}): planned {:.0}%, burned {:.0}%",
                e.edge,
                e.op.name(),
                100.0 * e.planned,
                100.0 * e.burned
            );
        }
        if !c.stray.is_empty() {
            let _ = writeln!(
                s,
                "    {} stray burns, {:.1} mm in all (first at line {})",
                c.stray.len(),
                c.stray_length_mm,
                c.stray[0].line
            );
        }
    }
    let verdict = if r.is_clean() && coverage.is_none_or(CoverageReport::passed) {
        "PASS"
    } else {
        "FAIL"
    };
    let _ = writeln!(s, "{verdict}: {} violations", r.violation_count);
    s
}
