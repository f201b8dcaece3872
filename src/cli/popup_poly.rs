//! `foldcam popup poly DESIGN -o card.fold`: pop-up cards from planar polygons (seed 000).

use std::path::PathBuf;

use anyhow::{Context, Result, anyhow};
use foldcam::design::popup::polygon::{
    PolygonCard, Replay, crease_pattern, fold_card, parse_design,
};
use foldcam::formats::{read_text, write_atomic};
use foldcam::pattern::CreasePattern;
use foldcam::render::{View3d, render_folded_png, render_gif};

use super::Outcome;

/// Make a pop-up card from a polygon design.
#[derive(clap::Args)]
#[command(
    long_about = "Builds an origamic-architecture card (seed 000, Mitani & Suzuki) by replaying \
                  a TOML design (see examples/popup/README-poly.txt): reference planes, \
                  polygons on them, each added as a face or an opening; every new face is cut \
                  out of the older ones so the card stays one sheet. Checks that the card pops \
                  up (§3.6: every vertical face held from both the base and the back sheet), \
                  writes the crease pattern (valleys +90°, mountains −90°, cuts) and, on \
                  request, a preview of the standing card and a GIF of it opening.\n\nExit \
                  status: 0 written, 1 the card would not pop up (the operation after which it \
                  became invalid and the failing faces are listed, nothing is written), 2 bad \
                  input.",
    after_help = "Examples:\n  foldcam popup poly examples/popup/house-door.popup.toml -o house.fold --png house.png --gif house.gif\n  \
                  foldcam popup poly examples/popup/taj-mahal.popup.toml -o taj.svg --width 800"
)]
pub struct PolyArgs {
    /// Design file (`.popup.toml`).
    pub design: PathBuf,
    /// Crease pattern to write (.fold, .svg or .cp), millimetres.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Write a preview of the card standing at 90°.
    #[arg(long)]
    pub png: Option<PathBuf>,
    /// Write an animated GIF of the card opening from closed to 90°.
    #[arg(long)]
    pub gif: Option<PathBuf>,
    /// Image width in pixels for --png and --gif.
    #[arg(long, default_value_t = 640)]
    pub width: u32,
}

/// Runs `popup poly`.
pub fn run(args: PolyArgs) -> Result<Outcome> {
    let path = &args.design;
    let text = read_text(path)?;
    let design = parse_design(&text).map_err(|e| anyhow!("{}: {e}", path.display()))?;
    eprintln!("foldcam: replaying {} operations", design.operations.len());
    let replay = design
        .replay()
        .map_err(|e| anyhow!("{}: {e}", path.display()))?;
    if !replay.report.passed() {
        report_failure(&args, &replay);
        return Ok(Outcome::CheckFailed);
    }
    let card = replay.card;
    let cp = crease_pattern(&card).map_err(|e| anyhow!("{}: {e}", path.display()))?;
    let images = previews(&args, &card, &cp)?;
    super::input::save(&args.output, &cp, None)?;
    for (path, bytes) in images {
        write_atomic(&path, &bytes).with_context(|| path.display().to_string())?;
        eprintln!("foldcam: wrote {}", path.display());
    }
    let (w, d, h) = card.size_mm();
    let faces = card
        .faces()
        .iter()
        .filter(|f| !f.polygon.is_empty())
        .count();
    println!(
        "{}: {} operations, {faces} faces, sheet {w:.1} × {:.1} mm (base {d:.1}, back {h:.1}), pops up",
        path.display(),
        design.operations.len(),
        d + h
    );
    Ok(Outcome::Done)
}

/// Prints the operation after which the card became invalid and the failing faces.
fn report_failure(args: &PolyArgs, replay: &Replay) {
    let after = replay.became_invalid_after.unwrap_or(0);
    println!(
        "{}: the card would not pop up; it became invalid at operation {after}",
        args.design.display()
    );
    for problem in replay.report.problems.iter().take(40) {
        let face = problem.piece.face;
        let from = if face >= 2 {
            format!(" (operation {})", face - 1)
        } else {
            String::new()
        };
        println!("  {problem}{from}");
    }
    if replay.report.problems.len() > 40 {
        println!("  … and {} more faces", replay.report.problems.len() - 40);
    }
}

/// The PNG and GIF previews asked for, rendered before anything is written.
fn previews(
    args: &PolyArgs,
    card: &PolygonCard,
    cp: &CreasePattern,
) -> Result<Vec<(PathBuf, Vec<u8>)>> {
    // As for the voxel card: the base runs towards +y and azimuth 0 looks from −y, so look
    // from the front-left, above, at the front of the pop-up.
    let view = View3d {
        azimuth_deg: 200.0,
        elevation_deg: 28.0,
        ..View3d::with_width(args.width)
    };
    let mut images = Vec::new();
    if let Some(png) = &args.png {
        let state = fold_card(card, cp, 90.0).state;
        let bytes =
            render_folded_png(&state, &view).map_err(|e| anyhow!("{}: {e}", png.display()))?;
        images.push((png.clone(), bytes));
    }
    if let Some(gif) = &args.gif {
        eprintln!("foldcam: rendering 25 frames");
        let states: Vec<_> = (0..=24)
            .map(|k| fold_card(card, cp, 5.0 + 85.0 * f64::from(k) / 24.0).state)
            .collect();
        let bytes =
            render_gif(&states, &view, 80).map_err(|e| anyhow!("{}: {e}", gif.display()))?;
        images.push((gif.clone(), bytes));
    }
    Ok(images)
}
