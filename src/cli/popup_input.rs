//! Where a voxel card comes from: the text format, a height-map PNG, or an OBJ/STL mesh put
//! through the mesh conversion of Mitani, Suzuki & Uno (2003), section 3 (depth from the front,
//! bump removal, filling under overhangs (their eq. 7), windows, thin tops).

use std::path::Path;

use anyhow::{Result, anyhow, bail};
use clap::ValueEnum;
use foldcam::design::popup::voxel::{
    ConvertOptions, ConvertReport, DepthField, DepthMap, MeshPlacement, UpAxis, VoxelCard,
    card_from_depths, depth_field_from_mesh, parse_voxel_card,
};
use foldcam::formats::read_text;

use foldcam::limits;

/// The mesh's up axis.
#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum Up {
    /// z up, front view from −y (Blender, most CAD).
    Z,
    /// y up, front view from +z (many game and web formats).
    Y,
}

/// How a height map or mesh becomes a card.
#[derive(clap::Args)]
#[command(next_help_heading = "From a mesh or height map")]
pub struct ModelArgs {
    /// Mesh: cells along the fold (Mitani, Suzuki & Uno 2003 used 80).
    #[arg(long, value_name = "CELLS", default_value_t = 80, value_parser = |s: &str| limits::RESOLUTION.parse(s))]
    pub resolution: u64,
    /// Mesh: which axis points up.
    #[arg(long, value_enum, default_value = "z")]
    pub up: Up,
    /// Mesh: part of the model's depth, from its front, that stands out of the card (the
    /// paper kept the front half).
    #[arg(long, value_name = "FRACTION", default_value_t = 0.5)]
    pub keep_depth: f64,
    /// Height map: depth of the base in cells (white = this far out).
    #[arg(long, value_name = "CELLS", default_value_t = 40)]
    pub depth: usize,
    /// Cell size in mm (default: --card-width over the cells along the fold).
    #[arg(long, value_name = "MM", value_parser = |s: &str| limits::CELL.parse(s), conflicts_with = "card_width")]
    pub cell_mm: Option<f64>,
    /// Width of the cells along the fold in mm.
    #[arg(long, value_name = "MM", value_parser = |s: &str| limits::CARD_WIDTH.parse(s), default_value_t = 160.0)]
    pub card_width: f64,
    /// Flat paper around the cells, in mm.
    #[arg(long, value_name = "MM", default_value_t = 10.0)]
    pub card_margin: f64,
    /// Side of the square element that removes small bumps, in cells (odd; 1 = off).
    #[arg(long, value_name = "CELLS", default_value_t = 3)]
    pub morphology: usize,
    /// Do not open windows under overhangs.
    #[arg(long)]
    pub no_windows: bool,
    /// Open a window only where the overhang stands out at least this part of the base
    /// depth in front of what is below it (0 = wherever voxels were added, as Mitani, Suzuki & Uno 2003 do).
    #[arg(long, value_name = "FRACTION", default_value_t = 0.25)]
    pub window_gap: f64,
    /// Leave out top faces at most this many columns wide where the card still pops up
    /// (0 = keep all).
    #[arg(long, value_name = "COLUMNS", default_value_t = 1)]
    pub thin_top: usize,
}

/// Loads or builds the card `path` describes.
pub fn load_card(path: &Path, args: &ModelArgs) -> Result<VoxelCard> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .unwrap_or_default();
    let at = |e: &dyn std::fmt::Display| anyhow!("{}: {e}", path.display());
    let field = match ext.as_str() {
        "png" => {
            if args.depth == 0 {
                bail!("--depth must be at least 1 cell");
            }
            let image = image::open(path).map_err(|e| at(&e))?;
            let grey = image.to_luma16();
            let map = DepthMap {
                width: grey.width() as usize,
                height: grey.height() as usize,
                levels: grey.as_raw(),
            };
            DepthField::from_grey(map, args.depth).map_err(|e| at(&e))?
        }
        "obj" | "stl" => {
            let mesh = foldcam::mesh::read_mesh(path).map_err(|e| at(&e))?;
            let placement = MeshPlacement {
                up: match args.up {
                    Up::Z => UpAxis::Z,
                    Up::Y => UpAxis::Y,
                },
                resolution: usize::try_from(args.resolution).unwrap_or(usize::MAX),
                keep_depth: args.keep_depth,
            };
            let started = std::time::Instant::now();
            let (field, _) = depth_field_from_mesh(&mesh, &placement).map_err(|e| at(&e))?;
            eprintln!(
                "foldcam: {} faces seen from the front as {} × {} × {} cells in {:.1?}",
                mesh.faces().len(),
                field.nx,
                field.ny,
                field.nz,
                started.elapsed()
            );
            field
        }
        _ => {
            let text = read_text(path)?;
            return parse_voxel_card(&text).map_err(|e| at(&e));
        }
    };
    let cell_mm = args.cell_mm.unwrap_or(args.card_width / field.nx as f64);
    eprintln!(
        "foldcam: building a card of {} × {} × {} cells: {} (estimated)",
        field.nx,
        field.ny,
        field.nz,
        foldcam::design::popup::voxel::estimate::conversion_estimate(&field)
    );
    let options = ConvertOptions {
        element: args.morphology,
        windows: !args.no_windows,
        window_gap: args.window_gap,
        thin_top: args.thin_top,
    };
    let bar = super::progress::spinner("building the card");
    let built = card_from_depths(&field, cell_mm, &options);
    bar.finish_and_clear();
    let (mut card, report) = built.map_err(|e| at(&e))?;
    card.set_margin_mm(args.card_margin)
        .map_err(|e| anyhow!("--card-margin: {e}"))?;
    progress(&report);
    Ok(card)
}

fn progress(r: &ConvertReport) {
    eprintln!(
        "foldcam: bumps removed ({} cells changed) in {:.1?}",
        r.smoothed_cells, r.smoothing_time
    );
    eprintln!(
        "foldcam: filling under overhangs added {} voxels in {} rows; {} of {} candidate rows became windows; {:.1?}",
        r.added_cells, r.filled_rows, r.window_rows, r.window_candidates, r.constraint_time
    );
    eprintln!(
        "foldcam: {} of {} thin top faces left out; {} pop-up checks; {:.1?}",
        r.tops_omitted, r.thin_tops, r.checks, r.thin_top_time
    );
}
