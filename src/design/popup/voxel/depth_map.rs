//! Height maps: a front view whose grey level says how far each point stands out from the
//! back sheet (Mitani, Suzuki & Uno 2003, §3.1), read into a [`DepthField`] for the steps of §3.2–3.3.
//!
//! The samples are one `u16` grey level per pixel, row-major with the top row first, as
//! `image::DynamicImage::to_luma16()` yields them; decoding the PNG is left to the caller so
//! the design core does not depend on image codecs. Grey 0 is the back sheet, 65535 the full
//! base depth.

use super::{ConvertOptions, DepthField, VoxelCard, VoxelError, card_from_depths};

/// Fewest pixels a height map has across and up: one pixel is one cell, and a card a few cells
/// wide is stretched to the whole card width (a 1 × 1 map would become a single 160 mm cell).
pub const MIN_MAP_SIDE: usize = 3;

/// A depth map: `width × height` grey levels, top row first.
#[derive(Clone, Copy, Debug)]
pub struct DepthMap<'a> {
    /// Pixels per row: cells along the fold.
    pub width: usize,
    /// Rows: cells of height.
    pub height: usize,
    /// `width × height` grey levels.
    pub levels: &'a [u16],
}

impl DepthField {
    /// The depth field of a grey map: pixel columns along the fold, rows up the back sheet,
    /// grey level g standing `round(g / 65535 × depth_cells)` cells out. The base is one cell
    /// deeper (`ny = depth_cells + 1`) and the back sheet one row higher (`nz = height + 1`),
    /// so every face has base in front of it and back sheet above it.
    pub fn from_grey(map: DepthMap<'_>, depth_cells: usize) -> Result<DepthField, VoxelError> {
        let (nx, nz) = (map.width, map.height);
        if nx < MIN_MAP_SIDE || nz < MIN_MAP_SIDE {
            return Err(VoxelError::MapTooSmall {
                width: nx,
                height: nz,
                min: MIN_MAP_SIDE,
            });
        }
        if map.levels.len() != nx * nz {
            return Err(VoxelError::MapSize {
                expected: nx * nz,
                got: map.levels.len(),
            });
        }
        let scale = depth_cells as f64 / u16::MAX as f64;
        let rows = nz + 1;
        let mut depths = vec![0u16; nx * rows];
        for x in 0..nx {
            for z in 0..nz {
                let g = map.levels[(nz - 1 - z) * nx + x];
                depths[x * rows + z] = (g as f64 * scale).round() as u16;
            }
        }
        Ok(DepthField {
            nx,
            ny: depth_cells + 1,
            nz: rows,
            depths,
        })
    }
}

/// Builds a card `map.width` cells wide whose back sheet is `map.height + 1` cells high and base
/// `depth_cells + 1` deep (one more row and one more cell than the map, see
/// [`DepthField::from_grey`]), made a staircase by eq. 7 alone (no bump removal, windows or thin-face
/// search: use [`card_from_depths`] for those).
pub fn card_from_depth_map(
    map: DepthMap<'_>,
    depth_cells: usize,
    cell_mm: f64,
) -> Result<VoxelCard, VoxelError> {
    VoxelCard::new(map.width, depth_cells + 1, map.height + 1, cell_mm)?;
    let field = DepthField::from_grey(map, depth_cells)?;
    Ok(card_from_depths(&field, cell_mm, &ConvertOptions::EQ7_ONLY)?.0)
}
