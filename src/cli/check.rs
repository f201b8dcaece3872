//! `foldcam check IN`.

use std::path::PathBuf;

use anyhow::{Context, Result};
use foldcam::check::check_with_frame;
use foldcam::check::layers::{LayerOptions, LayerProgress, check_layers};

use super::Outcome;
use super::args::CheckArgs;
use super::input;

/// Check local flat-foldability and fabrication limits.
#[derive(clap::Args)]
#[command(
    long_about = "Checks what applies to the pattern. Kawasaki's theorem (alternating angle \
                  sum) and Maekawa's (|M - V| = 2) describe folding flat: they run at interior \
                  vertices whose creases all fold flat (fold angle ±180°, or no stored angle). \
                  Where a crease folds to less than 180° (a 3D target, such as a tessellation) \
                  they do not apply; a FOLD file's 3D frame is then checked for developability \
                  (every face keeps its flat shape). The smallest angle between neighbouring \
                  creases, the shortest edge and fold angles are checked against the limits \
                  given. With --layers, also whether the layers can be stacked at all (a global \
                  layer order, counted as Flat-Folder counts it), naming the faces of the first \
                  contradiction when they cannot. The report says which checks ran and why. The pattern is cleaned into \
                  a planar graph first; vertex and edge numbers refer to the cleaned pattern \
                  (the same as the file's when it was clean already).\n\nExit status: 0 all checks pass, 1 a \
                  check failed or, without --allow-unchecked, whether the pattern folds could not \
                  be checked at some vertices (3D targets without a 3D frame: NOT CHECKED), 2 \
                  the input could not be read.",
    after_help = "Examples:\n  foldcam check bird.fold\n  \
                  foldcam check tess.svg --min-vertex-angle 30 --max-fold-angle 165\n  \
                  foldcam check bird.cp --json > report.json\n  \
                  foldcam check twist.fold --layers --json"
)]
pub struct Args {
    #[arg(help = input::pattern_help("Input file"))]
    pub input: PathBuf,
    #[command(flatten)]
    pub frame: input::FrameArg,
    /// Print the report as JSON (for scripts) instead of text.
    #[arg(long)]
    pub json: bool,
    /// Exit 0 when nothing failed although whether the pattern folds was not checked at some
    /// vertices (3D targets: a crease folds to less than 180° and no 3D frame came, e.g. a
    /// Miura-ori generated at 170°); the verdict still says NOT CHECKED.
    #[arg(long)]
    pub allow_unchecked: bool,
    #[command(flatten)]
    pub limits: CheckArgs,
}

/// Runs the checks and prints the report.
pub fn run(args: Args) -> Result<Outcome> {
    let mut imported = input::load(&args.input, &args.frame)?;
    input::clean(&args.input, &mut imported, None, false)?;
    let cp = &imported.pattern;
    let mut report = check_with_frame(cp, imported.folded.as_ref(), &args.limits.options());
    let layers = args.limits.layers.then(|| {
        let progress = std::sync::Arc::new(LayerProgress::default());
        let options = LayerOptions {
            progress: Some(progress.clone()),
            ..args.limits.layer_options()
        };
        super::progress::watching_layers(&progress, || check_layers(cp, &mut report, &options))
    });
    let refused =
        |e: &dyn std::fmt::Display| anyhow::anyhow!("{}: layer order: {e}", args.input.display());
    if args.json {
        // A refused layer search is a report too: the local checks, and why the layer
        // order was not found (the exit status stays the refusal's).
        let mut value = serde_json::to_value(&report).context("encoding the report")?;
        if let Some(map) = value.as_object_mut() {
            map.insert("verdict".into(), report.verdict().into());
            match &layers {
                Some(Ok(l)) => {
                    map.insert(
                        "layers".into(),
                        serde_json::to_value(l).context("encoding the layer report")?,
                    );
                }
                Some(Err(e)) => {
                    map.insert(
                        "layers".into(),
                        serde_json::json!({ "refused": e.to_string() }),
                    );
                }
                None => {}
            }
        }
        let text = serde_json::to_string_pretty(&value).context("encoding the report")?;
        outln!("{text}");
        if let Some(Err(e)) = &layers {
            return Err(refused(e));
        }
    } else {
        let layers = layers.transpose().map_err(|e| refused(&e))?;
        outln!("{}", args.input.display());
        if let Some(l) = &layers {
            out!("{}", l.to_text());
        }
        out!("{}", report.to_text(cp.units.label()));
    }
    Ok(
        if report.passed() && (report.checked_folding() || args.allow_unchecked) {
            Outcome::Done
        } else {
            Outcome::CheckFailed
        },
    )
}
