//! `foldcam popup poly DESIGN -o card.fold`: pop-up cards from planar polygons (Mitani & Suzuki 2004).

use std::path::PathBuf;

use anyhow::{Result, anyhow};
use foldcam::design::popup::polygon::{
    Replay, crease_pattern, fold_card, holds_paper, parse_design,
};
use foldcam::formats::{OutputSet, read_text};

use super::Outcome;

/// Make a pop-up card from a polygon design.
#[derive(clap::Args)]
#[command(
    long_about = "Builds an origamic-architecture card (Mitani & Suzuki, 2004) by replaying \
                  a TOML design (see examples/popup/README-poly.txt): reference planes, \
                  polygons on them, each added as a face or an opening; every new face is cut \
                  out of the older ones so the card stays one sheet. Checks that the card pops \
                  up (every vertical face held from both the base and the back sheet), \
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
    #[command(flatten)]
    pub out: super::design_output::DesignOutput,
    /// Write a preview of the card standing at 90°.
    #[arg(long)]
    pub png: Option<PathBuf>,
    /// Write an animated GIF of the card opening from closed to 90°.
    #[arg(long)]
    pub gif: Option<PathBuf>,
    /// Image width in pixels for --png and --gif.
    #[arg(long, default_value_t = 640)]
    pub width: u32,
    /// Grow the back sheet (`[card] height`) so that, folded shut, the card holds every face
    /// (a card that reaches beyond its outline is otherwise only warned about); refuse (exit
    /// 1) with the place when more paper cannot hold it.
    #[arg(long)]
    pub fit: bool,
}

/// Runs `popup poly`.
pub fn run(args: PolyArgs) -> Result<Outcome> {
    let path = &args.design;
    let text = read_text(path)?;
    let design = parse_design(&text).map_err(|e| anyhow!("{}: {e}", path.display()))?;
    let design = if args.fit {
        match foldcam::design::popup::fit::fit_design(&design) {
            Ok(fitted) => {
                super::popup::report_fit(path, &fitted, "back sheet");
                fitted.card
            }
            Err(e) => {
                println!("{}: {e}", path.display());
                return Ok(Outcome::CheckFailed);
            }
        }
    } else {
        design
    };
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
    let closed = fold_card(&card, &cp, 0.0).state;
    let hint = "join every face to the card through a fold (move or grow the face that is cut \
                free)";
    let paper = |f: &foldcam::pattern::Face| holds_paper(&card, &cp, f);
    if !super::popup::card_holds(path, &cp, &closed, args.fit, hint, paper) {
        return Ok(Outcome::CheckFailed);
    }
    // The pattern and its pictures are written together: all of them, or none.
    let mut outputs = OutputSet::new();
    super::popup::card_previews(
        &mut outputs,
        args.png.as_ref(),
        args.gif.as_ref(),
        args.width,
        |angle| fold_card(&card, &cp, angle).state,
    )?;
    args.out.stage(&mut outputs, &cp, None)?;
    super::input::commit(outputs, &[path])?;
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
