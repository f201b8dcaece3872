//! `foldcam popup poly DESIGN -o card.fold`: pop-up cards from planar polygons (Mitani & Suzuki 2004).

use std::path::PathBuf;

use anyhow::Result;
use foldcam::design::source::{DesignFile, PolyOptions, poly, read_design_file};
use foldcam::formats::OutputSet;

use super::Outcome;
use super::design_output::built;
use super::progress::DesignProgress;

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
    after_help = "Examples:\n  foldcam popup poly examples/popup/house-door.popup.toml -o house.fold \\\n      --png house.png --gif house.gif\n  \
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
    #[arg(value_name = "PX", long, default_value_t = 640)]
    pub width: u32,
    /// Grow the back sheet (`[card] height`) so that, folded shut, the card holds every face
    /// (a card that reaches beyond its outline is otherwise only warned about); refuse (exit
    /// 1) with the place when more paper cannot hold it.
    #[arg(long)]
    pub fit: bool,
    #[command(flatten)]
    pub stdout: super::pipe::ToArg,
}

/// Runs `popup poly`.
pub fn run(args: PolyArgs) -> Result<Outcome> {
    let path = &args.design;
    let output = args.out.target()?;
    let png = super::outputs::optional(args.png.as_ref())?;
    let gif = super::outputs::optional(args.gif.as_ref())?;
    super::outputs::check(&[Some(&output), png.as_ref(), gif.as_ref()], &[path])?;
    let bytes = read_design_file(path)?;
    let file = DesignFile {
        name: path,
        bytes: &bytes,
    };
    let options = PolyOptions { fit: args.fit };
    let mut progress = DesignProgress::default();
    let design = match built(poly::build(&file, &options, &mut progress))? {
        Ok(design) => design,
        Err(outcome) => return Ok(outcome),
    };
    // The pattern and its pictures are written together: all of them, or none.
    let mut outputs = OutputSet::new();
    super::popup::card_previews(
        &mut outputs,
        png.as_ref(),
        gif.as_ref(),
        args.width,
        |angle| design.fold_at(angle),
    )?;
    args.out.stage(&mut outputs, &design.pattern, None)?;
    super::outputs::commit(outputs, &[path])?;
    for line in &design.summary {
        outln!("{line}");
    }
    Ok(Outcome::Done)
}
