//! `foldcam fold-flat IN -o OUT.fold [--png OUT.png] [--state K]`.

use std::path::PathBuf;

use anyhow::{Result, bail};
use foldcam::check::layers::{
    DEFAULT_MAX_STATES, FlatFoldError, FlatFolding, KawasakiTolerance, LayerOptions, LayerProgress,
};
use foldcam::formats;
use foldcam::render::render_top_view_png;

use super::Outcome;
use super::{input, outputs};

/// Fold a crease pattern flat and write the folded state.
#[derive(clap::Args)]
#[command(
    long_about = "Folds a locally flat-foldable crease pattern flat: places every face (one held \
                  fixed), finds the valid layer orders (Flat-Folder's method: Akitaya, Demaine \
                  & Ku 2023) and writes state K as a FOLD file: the pattern as the key frame and \
                  the folded form as a foldedForm frame with faceOrders. --png draws the folded \
                  model from above, faces shaded by the number of layers beneath (front side \
                  cream, back side blue); --xray shades by layer count only.\n\nExit status: 0 \
                  written, 1 the pattern has no valid layer order (nothing written), 2 bad \
                  input.",
    after_help = "Examples:\n  foldcam fold-flat crane.fold -o crane-folded.fold --png crane.png\n  \
                  foldcam fold-flat twist.fold -o twist-folded.fold --state 1"
)]
pub struct Args {
    #[arg(help = input::pattern_help("Input file"))]
    pub input: PathBuf,
    #[command(flatten)]
    pub frame: input::FrameArg,
    /// Output FOLD file (key frame: the pattern; second frame: the folded form).
    #[arg(short, long)]
    pub output: PathBuf,
    /// Also draw the folded model from above as a PNG.
    #[arg(long, value_name = "PNG")]
    pub png: Option<PathBuf>,
    /// Which valid state to write, from 0 (states are numbered across independent components).
    #[arg(long, value_name = "N", default_value_t = 0)]
    pub state: u64,
    /// Shade the picture by layer count only (X-ray view).
    #[arg(long, requires = "png")]
    pub xray: bool,
    /// Picture width in pixels.
    #[arg(value_name = "PX", long, default_value_t = 1200, requires = "png")]
    pub width: u32,
    /// Stop counting each component at N states (states beyond are not reachable).
    #[arg(long, value_name = "N", default_value_t = DEFAULT_MAX_STATES)]
    pub max_states: u64,
    /// Kawasaki tolerance of the local check run first, degrees [default: fitted to the
    /// drawing: an error is rounding when closing the vertex moves the end of its shortest
    /// crease by at most 1/300 of the pattern's shortest edge].
    #[arg(long, value_name = "DEG", value_parser = |s: &str| foldcam::limits::KAWASAKI_TOLERANCE.parse(s))]
    pub kawasaki_tolerance: Option<f64>,
    /// Stop the layer-order search after this many seconds (exit 2, naming the limit;
    /// nothing written).
    #[arg(long, value_name = "SECONDS", value_parser = super::args::time_limit)]
    pub time_limit: Option<f64>,
    #[command(flatten)]
    pub stdout: super::pipe::ToArg,
}

/// Folds and writes.
pub fn run(args: Args) -> Result<Outcome> {
    let output = outputs::target(&args.output)?;
    let png_path = outputs::optional(args.png.as_ref())?;
    outputs::require_extension(&output, "fold", "the folded state")?;
    if let Some(p) = &png_path {
        outputs::require_extension(p, "png", "the picture")?;
    }
    outputs::check(&[Some(&output), png_path.as_ref()], &[&args.input])?;
    let mut imported = input::load(&args.input, &args.frame)?;
    input::clean(&args.input, &mut imported, None, true)?;
    let cp = &imported.pattern;
    let progress = std::sync::Arc::new(LayerProgress::default());
    let options = LayerOptions {
        max_states: Some(args.max_states.max(1)),
        kawasaki: KawasakiTolerance::from_degrees(args.kawasaki_tolerance),
        time_limit: args.time_limit.map(std::time::Duration::from_secs_f64),
        progress: Some(progress.clone()),
        ..LayerOptions::default()
    };
    let name = args.input.display();
    let folding =
        match super::progress::watching_layers(&progress, || FlatFolding::new(cp, &options)) {
            Ok(f) => f,
            Err(e @ (FlatFoldError::NotLocallyFlat(_) | FlatFoldError::NoLayerOrder(_))) => {
                errln!("foldcam: {name}: {e}; nothing written");
                return Ok(Outcome::CheckFailed);
            }
            Err(e) => bail!("{name}: {e}"),
        };
    let rounding = &folding.local.rounding;
    if !rounding.is_empty() {
        errln!(
            "foldcam: warning: {name}: folded with {} Kawasaki error(s) within the drawing's \
             precision (largest {:.4}°; --kawasaki-tolerance sets a fixed one)",
            rounding.len(),
            rounding.iter().map(|f| f.value).fold(0.0, f64::max)
        );
    }
    let report = folding.solver.report();
    let k = u128::from(args.state);
    let folded = folding
        .state(cp, k)
        .map_err(|e| anyhow::anyhow!("{name}: {e}"))?;
    // The top view searches the state again: only when a picture is asked for.
    let png = match &png_path {
        Some(_) => {
            let view = folding
                .top_view(k)
                .map_err(|e| anyhow::anyhow!("{name}: {e}"))?;
            Some(
                render_top_view_png(&view, args.width, args.xray)
                    .map_err(|e| anyhow::anyhow!("{}: {e}", args.input.display()))?,
            )
        }
        None => None,
    };
    let mut staged = formats::OutputSet::new();
    outputs::stage(&mut staged, &output, cp, Some(&folded))?;
    if let (Some(path), Some(bytes)) = (&png_path, png) {
        staged.add(path, bytes);
    }
    outputs::commit(staged, &[&args.input])?;
    errln!(
        "foldcam: {}: state {} of {}{}",
        args.input.display(),
        args.state,
        report.states,
        if report.exact { "" } else { " (at least)" }
    );
    Ok(Outcome::Done)
}
