//! `foldcam convert IN OUT`.

use std::path::PathBuf;

use anyhow::Result;
use foldcam::formats;

use super::Outcome;
use super::args::ScaleArgs;
use super::{input, outputs};

/// Convert between FOLD, SVG and ORIPA .cp (and read DXF).
#[derive(clap::Args)]
#[command(after_help = "Examples:\n  foldcam convert bird.cp bird.fold\n  \
    foldcam convert bird.fold bird.svg --size 150\n  foldcam convert drawing.svg clean.fold --planarize\n  \
    foldcam convert animation.fold frame3.svg --fold-frame 3")]
pub struct Args {
    #[arg(help = input::pattern_help("Input file"))]
    pub input: PathBuf,
    #[command(flatten)]
    pub frame: input::FrameArg,
    #[arg(help = format!("Output file ({}); written atomically", foldcam::formats::Format::WRITABLE))]
    pub output: PathBuf,
    /// Clean the pattern into a planar graph (split crossings, merge close vertices, drop
    /// duplicates) and compute its faces. SVG and .cp inputs are always cleaned.
    #[arg(long)]
    pub planarize: bool,
    /// Merge tolerance for --planarize, in the pattern's unit (default 1e-7 of the diagonal).
    #[arg(value_name = "LEN", long, value_parser = |s: &str| foldcam::limits::TOLERANCE.parse(s), requires = "planarize")]
    pub tolerance: Option<f64>,
    #[command(flatten)]
    pub scale: ScaleArgs,
    #[command(flatten)]
    pub stdout: super::pipe::ToArg,
}

/// Runs the conversion.
pub fn run(args: Args) -> Result<Outcome> {
    let output = outputs::target(&args.output)?;
    outputs::check(&[Some(&output)], &[&args.input])?;
    formats::Format::from_path(&output)
        .filter(|f| f.writable())
        .ok_or_else(|| {
            anyhow::anyhow!(
                "{}: unknown output type (expected one of {})",
                output.display(),
                formats::Format::WRITABLE
            )
        })?;
    let mut imported = input::load(&args.input, &args.frame)?;
    if args.planarize {
        input::clean(&args.input, &mut imported, args.tolerance, true)?;
    }
    args.scale
        .apply(&mut imported.pattern, imported.folded.as_mut())?;
    let mut staged = formats::OutputSet::new();
    outputs::stage(
        &mut staged,
        &output,
        &imported.pattern,
        imported.folded.as_ref(),
    )?;
    outputs::commit(staged, &[&args.input])?;
    Ok(Outcome::Done)
}
