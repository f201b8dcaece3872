//! `foldcam popup voxel INPUT -o card.fold`: pop-up cards from voxels (seed 001).

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, anyhow, bail};
use clap::Subcommand;
use foldcam::design::popup::voxel::{
    DepthMap, VoxelCard, card_from_depth_map, check_popup, crease_pattern, fold_card,
    parse_voxel_card,
};
use foldcam::formats::{read_text, write_atomic};
use foldcam::render::{View3d, render_folded_png, render_gif};

use super::Outcome;
use super::args::positive;

/// Pop-up card designers.
#[derive(Subcommand)]
pub enum Command {
    /// A card from a voxel model: a `.voxel.txt` front view or a height-map PNG.
    Voxel(VoxelArgs),
    /// A card from a polygon design (`.popup.toml`): faces and openings on reference planes.
    Poly(super::popup_poly::PolyArgs),
}

/// Make a pop-up card from voxels.
#[derive(clap::Args)]
#[command(
    long_about = "Builds an origamic-architecture card (seed 001, Mitani et al.) from a voxel \
                  model: a text front view (see examples/popup/README.txt) or a height-map PNG \
                  (grey level = how far a point stands out from the back sheet). Checks that the \
                  card pops up (§2.6: every front face held from both the base and the back \
                  sheet), writes the crease pattern (valleys +90°, mountains −90°, cuts) and, on \
                  request, a preview of the standing card and a GIF of it opening.\n\nExit \
                  status: 0 written, 1 the card would not pop up (the failing cells are listed \
                  and nothing is written), 2 bad input.",
    after_help = "Examples:\n  foldcam popup voxel examples/popup/house.voxel.txt -o house.fold --png house.png --gif house.gif\n  \
                  foldcam popup voxel relief.png --cell-mm 1 --depth 40 -o relief.svg"
)]
pub struct VoxelArgs {
    /// `.voxel.txt` model or height-map `.png`.
    pub input: PathBuf,
    /// Crease pattern to write (.fold, .svg or .cp), millimetres.
    #[arg(short, long)]
    pub output: PathBuf,
    /// For PNG input: cell size in mm.
    #[arg(long, value_name = "MM", value_parser = positive, default_value_t = 1.0)]
    pub cell_mm: f64,
    /// For PNG input: depth of the base in cells (white = this far out).
    #[arg(long, value_name = "CELLS", default_value_t = 40)]
    pub depth: usize,
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

/// Runs a popup subcommand.
pub fn run(command: Command) -> Result<Outcome> {
    match command {
        Command::Voxel(args) => voxel(args),
        Command::Poly(args) => super::popup_poly::run(args),
    }
}

fn voxel(args: VoxelArgs) -> Result<Outcome> {
    let card = load_card(&args)?;
    let report = check_popup(&card);
    if !report.passed() {
        println!("{}: the card would not pop up", args.input.display());
        for problem in report.problems.iter().take(40) {
            println!("  {problem}");
        }
        if report.problems.len() > 40 {
            println!("  … and {} more front faces", report.problems.len() - 40);
        }
        return Ok(Outcome::CheckFailed);
    }
    let cp = crease_pattern(&card).map_err(|e| anyhow!("{}: {e}", args.input.display()))?;
    // The card's base runs towards +y (the paper's axes) and the renderer's azimuth 0 looks
    // from −y: look from the front-left, above, at the front of the pop-up.
    let view = View3d {
        azimuth_deg: 200.0,
        elevation_deg: 28.0,
        ..View3d::with_width(args.width)
    };
    let mut images = Vec::new();
    if let Some(png) = &args.png {
        let state = fold_card(&card, &cp, 90.0).state;
        let bytes =
            render_folded_png(&state, &view).map_err(|e| anyhow!("{}: {e}", png.display()))?;
        images.push((png.clone(), bytes));
    }
    if let Some(gif) = &args.gif {
        let states: Vec<_> = (0..=24)
            .map(|k| fold_card(&card, &cp, 5.0 + 85.0 * f64::from(k) / 24.0).state)
            .collect();
        let bytes =
            render_gif(&states, &view, 80).map_err(|e| anyhow!("{}: {e}", gif.display()))?;
        images.push((gif.clone(), bytes));
    }
    super::input::save(&args.output, &cp, None)?;
    for (path, bytes) in images {
        write_atomic(&path, &bytes).with_context(|| path.display().to_string())?;
        eprintln!("foldcam: wrote {}", path.display());
    }
    let (w, h) = card.sheet_mm();
    println!(
        "{}: {} × {} × {} cells of {} mm, sheet {w:.1} × {h:.1} mm, pops up",
        args.input.display(),
        card.nx(),
        card.ny(),
        card.nz(),
        card.cell_mm()
    );
    Ok(Outcome::Done)
}

fn load_card(args: &VoxelArgs) -> Result<VoxelCard> {
    let path = &args.input;
    if is_png(path) {
        let image = image::open(path).map_err(|e| anyhow!("{}: {e}", path.display()))?;
        let grey = image.to_luma16();
        let (w, h) = (grey.width() as usize, grey.height() as usize);
        let map = DepthMap {
            width: w,
            height: h,
            levels: grey.as_raw(),
        };
        if args.depth == 0 {
            bail!("--depth must be at least 1 cell");
        }
        return card_from_depth_map(map, args.depth, args.cell_mm)
            .map_err(|e| anyhow!("{}: {e}", path.display()));
    }
    let text = read_text(path)?;
    parse_voxel_card(&text).map_err(|e| anyhow!("{}: {e}", path.display()))
}

fn is_png(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("png"))
}
