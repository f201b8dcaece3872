//! `foldcam fold SCRIPT -o model.fold`: run a fold script (Miyazaki et al. 1992) and write the crease
//! pattern with one folded frame per step.

use std::path::PathBuf;

use anyhow::{Context, Result, anyhow};
use foldcam::design::folding::{display_states, sheet_size, step_captions};
use foldcam::design::source::{DesignFile, read_design_file, script};
use foldcam::formats::fold::write_string_frames;
use foldcam::formats::{Format, OutputSet};
use foldcam::render::{View3d, render_gif, step_sheet_png};

use super::Outcome;
use super::progress::DesignProgress;

/// Fold a sheet step by step and write the crease pattern.
#[derive(clap::Args)]
#[command(
    long_about = "Runs a fold script (TOML: a sheet, then bend, fold, tuck and drag steps; see \
                  examples/folding/README.txt) on the origami simulator of Miyazaki et al. (1992) (Miyazaki et \
                  al.): faces split by every fold, layer order kept, tuck-ins checked. Writes a \
                  FOLD file whose key frame is the crease pattern (the unfolded fold lines, \
                  mountain/valley from the final state, boundary B) and whose further frames are \
                  the folded states after each step (frame 1 the flat sheet), with faceOrders for \
                  flat layers; on request a PNG with one captioned picture per step (all at one scale) and an \
                  animated GIF.\n\n\
                  Exit status: 0 written, 2 bad script or a step that cannot be folded (the step \
                  is named; nothing is written).",
    after_help = "Examples:\n  foldcam fold examples/folding/waterbomb-base.toml -o waterbomb.fold --png steps.png\n  \
                  foldcam fold examples/folding/bird-base.toml -o bird.fold --gif bird.gif\n  \
                  foldcam cut bird.fold -m grbl-diode -x card-300gsm -o bird.gcode"
)]
pub struct Args {
    /// Fold script (.toml).
    pub script: PathBuf,
    #[command(flatten)]
    pub out: super::design_output::DesignOutput,
    /// Write a PNG with one 3D picture per step (layers spread apart to be visible).
    #[arg(long)]
    pub png: Option<PathBuf>,
    /// Write an animated GIF of the steps.
    #[arg(long)]
    pub gif: Option<PathBuf>,
    /// Width of one step's picture, pixels.
    #[arg(value_name = "PX", long, default_value_t = 320)]
    pub width: u32,
    #[command(flatten)]
    pub stdout: super::pipe::ToArg,
}

/// Runs `foldcam fold`.
pub fn run(args: Args) -> Result<Outcome> {
    let name = args.script.display().to_string();
    let output = args.out.target()?;
    let png = super::outputs::optional(args.png.as_ref())?;
    let gif = super::outputs::optional(args.gif.as_ref())?;
    super::outputs::check(
        &[Some(&output), png.as_ref(), gif.as_ref()],
        &[&args.script],
    )?;
    let bytes = read_design_file(&args.script)?;
    let file = DesignFile {
        name: &args.script,
        bytes: &bytes,
    };
    let design = script::build(&file, &mut DesignProgress::default())?;
    let folding = &design.folding;
    let view = View3d {
        azimuth_deg: 20.0,
        elevation_deg: 55.0,
        ..View3d::with_width(args.width)
    };
    let shown = display_states(folding, sheet_size(folding) * 0.004);
    // Every output is made first and written together: a failure leaves all files as they were.
    let mut outputs = OutputSet::new();
    if args.out.machine.is_some() || Format::from_path(&output) != Some(Format::Fold) {
        args.out.stage(&mut outputs, &design.sheet.pattern, None)?;
    } else {
        // The crease pattern with one folded frame per step.
        outputs.add(
            &output,
            write_string_frames(&design.sheet.pattern, &design.states).into_bytes(),
        );
    }
    if let Some(png) = &png {
        check_picture_size(shown.len(), view.width, "step sheet")?;
        let bytes = step_sheet_png(&shown, &step_captions(folding), &view)
            .with_context(|| png.display().to_string())?;
        super::outputs::stage_image(&mut outputs, png, bytes, "png")?;
    }
    if let Some(gif) = &gif {
        check_picture_size(shown.len(), view.width, "animation")?;
        let unit = design.sheet.pattern.units.label();
        let view = view.clone().with_key("folding step by step", unit);
        let bytes =
            render_gif(&shown, &view, 700).map_err(|e| anyhow!("{}: {e}", gif.display()))?;
        super::outputs::stage_image(&mut outputs, gif, bytes, "gif")?;
    }
    super::outputs::commit(outputs, &[&args.script])?;
    for p in &design.warnings {
        errln!("foldcam: {name}: warning: {p}");
    }
    outln!(
        "{} written to {}",
        design.summary,
        args.out.output.display()
    );
    Ok(Outcome::Done)
}

/// Most pixels a step sheet or an animation may hold in all (64 megapixels, 256 MB of RGBA):
/// each step is drawn at `--width` pixels square, so a long script needs a smaller width.
const MAX_PICTURE_PIXELS: u64 = 64_000_000;

/// Refuses pictures of `panels` steps at `width` pixels square beyond [`MAX_PICTURE_PIXELS`],
/// naming the width that would fit.
fn check_picture_size(panels: usize, width: u32, what: &str) -> Result<()> {
    let panels = panels.max(1) as u64;
    let total = panels * u64::from(width) * u64::from(width);
    if total > MAX_PICTURE_PIXELS {
        let fits = ((MAX_PICTURE_PIXELS / panels) as f64).sqrt().floor();
        anyhow::bail!(
            "--width {width}: the {what} of {panels} steps would hold {:.0} megapixels, over the \
             limit of {}; use --width {fits} or less",
            total as f64 / 1e6,
            MAX_PICTURE_PIXELS / 1_000_000
        );
    }
    Ok(())
}
