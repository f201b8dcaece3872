//! The flags of `popup voxel` that say how a height map or an OBJ/STL mesh becomes a card
//! (the mesh conversion of Mitani, Suzuki & Uno (2003), section 3, in
//! [`foldcam::design::source::voxel`]).

use clap::ValueEnum;
use foldcam::design::popup::voxel::UpAxis;
use foldcam::design::source::VoxelOptions;
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
    #[arg(long, value_name = "SHARE", default_value_t = 0.5)]
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
    #[arg(long, value_name = "SHARE", default_value_t = 0.25)]
    pub window_gap: f64,
    /// Leave out top faces at most this many columns wide where the card still pops up
    /// (0 = keep all).
    #[arg(long, value_name = "N", default_value_t = 1)]
    pub thin_top: usize,
}

impl ModelArgs {
    /// The library's options for these flags, fitting when `fit`.
    pub fn options(&self, fit: bool) -> VoxelOptions {
        VoxelOptions {
            resolution: usize::try_from(self.resolution).unwrap_or(usize::MAX),
            up: match self.up {
                Up::Z => UpAxis::Z,
                Up::Y => UpAxis::Y,
            },
            keep_depth: self.keep_depth,
            depth: self.depth,
            cell_mm: self.cell_mm,
            card_width: self.card_width,
            card_margin: self.card_margin,
            morphology: self.morphology,
            windows: !self.no_windows,
            window_gap: self.window_gap,
            thin_top: self.thin_top,
            fit,
            ..VoxelOptions::default()
        }
    }
}
