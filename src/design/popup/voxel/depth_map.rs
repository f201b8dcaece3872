//! Cards from a depth map: a front view whose grey level says how far each point stands out
//! from the back sheet (seed 001 §3.1), made a staircase by eq. 7 (§3.2 b).
//!
//! Eq. 7, `cell[x][y][z] = 1 if cell[x][y][z + 1] = 1`, applied for z in descending order,
//! adds every cell below a filled one; with one depth per row it reads
//! `depth(x, z) = max(depth(x, z), depth(x, z + 1))` from the top row down.
//!
//! The samples are one `u16` grey level per pixel, row-major with the top row first, as
//! `image::DynamicImage::to_luma16()` yields them; decoding the PNG is left to the caller so
//! the design core does not depend on image codecs. Grey 0 is the back sheet, 65535 the full
//! base depth. The small-bump removal of §3.2 a) and the window search of §3.2 c) are not done.

use super::{VoxelCard, VoxelError};

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

/// Builds a card `map.width` cells wide whose back sheet is `map.height` cells high and base
/// `depth_cells` deep; grey level g becomes depth `round(g / 65535 × depth_cells)`.
pub fn card_from_depth_map(
    map: DepthMap<'_>,
    depth_cells: usize,
    cell_mm: f64,
) -> Result<VoxelCard, VoxelError> {
    let (nx, nz) = (map.width, map.height);
    let mut card = VoxelCard::new(nx, depth_cells, nz, cell_mm)?;
    if map.levels.len() != nx * nz {
        return Err(VoxelError::MapSize {
            expected: nx * nz,
            got: map.levels.len(),
        });
    }
    let scale = depth_cells as f64 / u16::MAX as f64;
    for x in 0..nx {
        let mut above = 0;
        for z in (0..nz).rev() {
            let g = map.levels[(nz - 1 - z) * nx + x];
            let d = ((g as f64 * scale).round() as usize).max(above);
            card.set_depth_unchecked_order(x, z, d);
            above = d;
        }
    }
    Ok(card)
}
