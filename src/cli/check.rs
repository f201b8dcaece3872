//! `foldcam check IN`.

use std::path::PathBuf;

use anyhow::{Context, Result};
use foldcam::check::check;

use super::Outcome;
use super::args::CheckArgs;
use super::input;

/// Check local flat-foldability and fabrication limits.
#[derive(clap::Args)]
#[command(
    long_about = "Checks every interior vertex for Kawasaki's theorem (alternating angle sum) and \
                  Maekawa's (|M - V| = 2), the smallest angle between neighbouring creases, the \
                  shortest edge and fold angles. The pattern is cleaned into a planar graph \
                  first; vertex and edge numbers refer to the cleaned pattern (the same as the \
                  file's when it was clean already).\n\nExit status: 0 all checks pass, 1 a \
                  check failed, 2 the input could not be read.",
    after_help = "Examples:\n  foldcam check bird.fold\n  \
                  foldcam check tess.svg --min-vertex-angle 30 --max-fold-angle 165\n  \
                  foldcam check bird.cp --json > report.json"
)]
pub struct Args {
    /// Input file (.fold, .svg or .cp).
    pub input: PathBuf,
    #[command(flatten)]
    pub frame: input::FrameArg,
    /// Print the report as JSON (for scripts) instead of text.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub limits: CheckArgs,
}

/// Runs the checks and prints the report.
pub fn run(args: Args) -> Result<Outcome> {
    let mut imported = input::load(&args.input, &args.frame)?;
    input::clean(&args.input, &mut imported, None, false)?;
    let cp = &imported.pattern;
    let report = check(cp, &args.limits.options());
    if args.json {
        let text = serde_json::to_string_pretty(&report).context("encoding the report")?;
        println!("{text}");
    } else {
        println!("{}", args.input.display());
        print!("{}", report.to_text(input::unit_label(cp.units)));
    }
    Ok(if report.passed() {
        Outcome::Done
    } else {
        Outcome::CheckFailed
    })
}
