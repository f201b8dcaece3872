//! `foldcam preview IN -o OUT.png`.

use std::path::PathBuf;

use anyhow::{Result, bail};
use foldcam::check::check_with_frame;
use foldcam::check::layers::check_layers;
use foldcam::render::{PreviewOptions, preview_png};

use super::Outcome;
use super::args::CheckArgs;
use super::input;

/// Draw a crease pattern as a PNG.
#[derive(clap::Args)]
#[command(
    long_about = "Draws the pattern with the usual origami line styles: valley dashed blue, \
                  mountain dash-dot red, boundary black, cut green, flat grey, unassigned \
                  magenta, with a scale bar. With --check, faults found by `foldcam check` are \
                  ringed; with --check --layers, so are the faces where no layer order \
                  exists.\n\nExit status: 0 written (and, with --check, no fault), 1 written \
                  with faults ringed (like `foldcam check`), 2 bad input.",
    after_help = "Examples:\n  foldcam preview bird.fold -o bird.png\n  \
                  foldcam preview tess.svg -o tess.png --width 2400 --check --min-vertex-angle 30"
)]
pub struct Args {
    #[arg(help = input::pattern_help("Input file"))]
    pub input: PathBuf,
    #[command(flatten)]
    pub frame: input::FrameArg,
    /// Output PNG; written atomically.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Image width in pixels (16 to 16384); the height follows the pattern's aspect ratio.
    #[arg(value_name = "PX", long, default_value_t = 1200)]
    pub width: u32,
    /// Run the checks and ring every fault on the image.
    #[arg(long)]
    pub check: bool,
    #[command(flatten)]
    pub limits: CheckArgs,
    #[command(flatten)]
    pub stdout: super::pipe::ToArg,
}

/// Renders the preview.
pub fn run(args: Args) -> Result<Outcome> {
    let output = super::outputs::target(&args.output)?;
    super::outputs::check(&[Some(&output)], &[&args.input])?;
    let is_png = output
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("png"));
    if !is_png {
        bail!(
            "{}: the preview is written as PNG: use a .png name",
            args.output.display()
        );
    }
    let mut imported = input::load(&args.input, &args.frame)?;
    input::clean(&args.input, &mut imported, None, false)?;
    let cp = &imported.pattern;
    let checked = args.check;
    let findings = if checked {
        let mut report = check_with_frame(cp, imported.folded.as_ref(), &args.limits.options());
        if args.limits.layers {
            let layers = check_layers(cp, &mut report, &args.limits.layer_options())
                .map_err(|e| anyhow::anyhow!("{}: layer order: {e}", args.input.display()))?;
            super::say::err(format_args!(
                "foldcam: {}: {}",
                args.input.display(),
                layers.to_text()
            ));
        }
        errln!(
            "foldcam: {}: {} fault(s) ringed, numbered as listed:",
            args.input.display(),
            report.findings.len()
        );
        for (i, f) in report.findings.iter().enumerate() {
            errln!("  {}", foldcam::check::finding_line(i + 1, f));
        }
        report.findings
    } else {
        Vec::new()
    };
    let options = PreviewOptions {
        width: args.width,
        ..PreviewOptions::default()
    };
    let png = preview_png(cp, &options, &findings)
        .map_err(|e| anyhow::anyhow!("{}: {e}", args.input.display()))?;
    super::outputs::write_one(&output, png, &[&args.input])?;
    Ok(if checked && !findings.is_empty() {
        Outcome::CheckFailed
    } else {
        Outcome::Done
    })
}
