//! `foldcam popup voxel INPUT -o card.fold`: pop-up cards from voxels (Mitani, Suzuki & Uno 2003).

use std::path::PathBuf;

use anyhow::{Result, anyhow};
use clap::Subcommand;
use foldcam::design::popup::as_held;
use foldcam::design::popup::voxel::format_voxel_card;
use foldcam::design::source::{DesignFile, DesignKind, read_design_file, voxel};
use foldcam::formats::OutputSet;
use foldcam::render::{View3d, render_folded_png, render_gif};

use super::Outcome;
use super::design_output::built;
use super::progress::DesignProgress;

/// Pop-up card designers.
#[derive(Subcommand)]
pub enum Command {
    /// A card from voxels: a `.voxel.txt` model, a height-map PNG or an OBJ/STL mesh.
    Voxel(Box<VoxelArgs>),
    /// A card from a polygon design (`.popup.toml`): faces and openings on reference planes.
    Poly(Box<super::popup_poly::PolyArgs>),
}

/// Make a pop-up card from voxels.
#[derive(clap::Args)]
#[command(
    long_about = "Builds an origamic-architecture card (Mitani, Suzuki & Uno, 2003) from a voxel \
                  model: a text front view (see examples/popup/README.txt), a height-map PNG \
                  (grey level = how far a point stands out from the back sheet) or a polygon \
                  mesh (OBJ or STL) seen from the front. Height maps and meshes go through the \
                  paper's mesh conversion: bumps smaller than the structuring element are removed, voxels \
                  are added under overhangs until every slice is a staircase, windows \
                  open where they were added and thin top faces are left out, each only where \
                  the card still pops up. Checks that the card pops up (every vertical face, \
                  a piece of the back sheet cut free of it included, joined by folds to both \
                  the base and the back sheet), writes the crease pattern \
                  (valleys +90°, mountains −90°, cuts) or, with --machine and --material, the \
                  cutting job, and on request a preview of the standing card and a GIF of it \
                  opening, seen from the front (the design's left on the picture's left).\n\nExit status: 0 written, 1 the card would not pop up (the failing \
                  cells are listed and nothing is written), 2 bad input.",
    after_help = "Examples:\n  foldcam popup voxel examples/popup/house.voxel.txt -o house.fold --png house.png --gif house.gif\n  \
                  foldcam popup voxel examples/popup/building.obj --resolution 120 --card-width 180 \\\n      -o building.fold --png building.png\n  \
                  foldcam popup voxel examples/popup/building.obj -m grbl-diode -x card-300gsm -o building.gcode\n  \
                  foldcam popup voxel relief.png --cell-mm 1 --depth 40 -o relief.svg"
)]
pub struct VoxelArgs {
    /// `.voxel.txt` model, height-map `.png`, or `.obj`/`.stl` mesh.
    pub input: PathBuf,
    #[command(flatten)]
    pub out: super::design_output::DesignOutput,
    #[command(flatten)]
    pub model: super::popup_input::ModelArgs,
    /// Also write the final voxel model (windows, left-out tops) as a `.voxel.txt` to edit.
    #[arg(long, value_name = "PATH")]
    pub save_voxels: Option<PathBuf>,
    /// Write a preview of the card standing at 90°.
    #[arg(long)]
    pub png: Option<PathBuf>,
    /// Write an animated GIF of the card opening from closed to 90°.
    #[arg(long)]
    pub gif: Option<PathBuf>,
    /// Image width in pixels for --png and --gif.
    #[arg(value_name = "PX", long, default_value_t = 640)]
    pub width: u32,
    /// Grow the card's margin so that, folded shut, it holds every face (a card that reaches
    /// beyond its outline is otherwise only warned about); refuse (exit 1) with the place
    /// when more paper cannot hold it.
    #[arg(long)]
    pub fit: bool,
    #[command(flatten)]
    pub stdout: super::pipe::ToArg,
}

/// Runs a popup subcommand.
pub fn run(command: Command) -> Result<Outcome> {
    match command {
        Command::Voxel(args) => voxel(*args),
        Command::Poly(args) => super::popup_poly::run(*args),
    }
}

fn voxel(args: VoxelArgs) -> Result<Outcome> {
    let output = args.out.target()?;
    let png = super::outputs::optional(args.png.as_ref())?;
    let gif = super::outputs::optional(args.gif.as_ref())?;
    let voxels = super::outputs::optional(args.save_voxels.as_ref())?;
    super::outputs::check(
        &[Some(&output), png.as_ref(), gif.as_ref(), voxels.as_ref()],
        &[&args.input],
    )?;
    let bytes = read_design_file(&args.input)?;
    let file = DesignFile {
        name: &args.input,
        bytes: &bytes,
    };
    let mesh = match DesignKind::recognise(&args.input, &bytes) {
        Some(DesignKind::Mesh) => Some(file.mesh()?),
        _ => None,
    };
    let options = args.model.options(args.fit);
    let mut progress = DesignProgress::default();
    let design = match built(voxel::build(&file, mesh.as_ref(), &options, &mut progress))? {
        Ok(design) => design,
        Err(outcome) => return Ok(outcome),
    };
    // The pattern, pictures and voxel model are written together: all of them, or none.
    let mut outputs = OutputSet::new();
    card_previews(
        &mut outputs,
        png.as_ref(),
        gif.as_ref(),
        args.width,
        |angle| design.fold_at(angle),
    )?;
    if let Some(path) = &voxels {
        outputs.add(path, format_voxel_card(&design.card).into_bytes());
    }
    args.out.stage(&mut outputs, &design.pattern, None)?;
    super::outputs::commit(outputs, &[&args.input])?;
    for line in &design.summary {
        outln!("{line}");
    }
    Ok(Outcome::Done)
}

/// The camera of the card previews, `width` pixels wide: from the front of the card, a little
/// to its left and above. Meant for states turned by [`as_held`], whose front faces −y, the
/// camera's azimuth 0.
pub fn card_view(width: u32) -> View3d {
    View3d {
        azimuth_deg: -20.0,
        elevation_deg: 28.0,
        ..View3d::with_width(width)
    }
}

/// The PNG of a card standing at 90° and the GIF of it opening, as asked for, rendered
/// before anything is written, both as seen from the front of the card (the folded states
/// turned by [`as_held`], so the design's left is the picture's left). `fold(angle)` gives the card's folded state at an opening angle
/// in degrees. Shared by the voxel and polygon cards.
pub fn card_previews(
    outputs: &mut OutputSet,
    png: Option<&PathBuf>,
    gif: Option<&PathBuf>,
    width: u32,
    fold: impl Fn(f64) -> foldcam::pattern::FoldedState,
) -> Result<()> {
    let view = card_view(width);
    let fold = |angle| as_held(&fold(angle));
    if let Some(png) = png {
        let view = view.clone().with_key("card opened to 90°", "mm");
        let bytes =
            render_folded_png(&fold(90.0), &view).map_err(|e| anyhow!("{}: {e}", png.display()))?;
        super::outputs::stage_image(outputs, png, bytes, "png")?;
    }
    if let Some(gif) = gif {
        errln!("foldcam: rendering 25 frames");
        let states: Vec<_> = (0..=24)
            .map(|k| fold(5.0 + 85.0 * f64::from(k) / 24.0))
            .collect();
        let view = view.with_key("card opening from 5° to 90°", "mm");
        let bytes =
            render_gif(&states, &view, 80).map_err(|e| anyhow!("{}: {e}", gif.display()))?;
        super::outputs::stage_image(outputs, gif, bytes, "gif")?;
    }
    Ok(())
}
