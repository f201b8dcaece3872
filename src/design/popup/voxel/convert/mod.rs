//! From a depth field to a card that pops up: Mitani, Suzuki & Uno (2003), §3.2–3.3.
//!
//! A [`DepthField`] says, per front-view cell (x, z), how far the shape stands out from the
//! back sheet: a height map (§3.1: [`DepthField::from_grey`]) or an orthographic depth
//! rendering of a mesh ([`depth_field_from_mesh`]). [`card_from_depths`] then
//! 1. removes small bumps with a morphological opening and closing of every x-slice (§3.2 a),
//!    [`ConvertOptions::element`] cells square (3 in the paper);
//! 2. adds voxels top-down until every slice is a staircase (§3.2 b, eq. 7);
//! 3. makes windows where voxels were added, keeping each only if the card still pops up
//!    (§3.2 c, the check of §2.6); rows filled by a thin layer only are left solid
//!    ([`ConvertOptions::window_gap`]);
//! 4. leaves out top faces at most [`ConvertOptions::thin_top`] columns wide, again only where
//!    the card still pops up, lowest first so the tallest stay as supports (§3.3, Fig. 14).
//!
//! # Deviations from the paper
//! The paper makes every filled row a window candidate; a wall just behind an eave then
//! vanishes into one tall window. Here a row is a candidate only when eq. 7 filled at least
//! [`ConvertOptions::window_gap`] of the base depth (0 restores the paper's rule).
//!
//! The paper sets one window flag at a time and checks the whole card after each. Here the
//! candidates are grouped: the rows eq. 7 filled under one overhang in one column form a run,
//! equal runs side by side form a block, and a block is tried whole; when it fails it is split
//! in two along x and each half tried again, down to single columns. Consecutive candidates
//! are also tried in groups (doubled after a success, halved after a failure), so a search
//! where most candidates are kept needs few checks. This keeps what the
//! one-at-a-time search keeps in the common cases (all windows under a porch whose pillars
//! hold it; all but one supporting column under a free balcony) with far fewer checks. A
//! column's run is all window or none. The check itself runs on face strips instead of cells
//! and rebuilds only the edited columns (see `runs.rs`); it gives the same answer cell for cell.

mod mesh_depth;
mod morphology;
mod search;

use std::time::Duration;

use crate::clock::Stopwatch;

pub use mesh_depth::{MeshPlacement, PlacementError, UpAxis, depth_field_from_mesh};

use super::{VoxelCard, VoxelError};

/// Per front-view cell, how many cells the shape stands out from the back sheet. Unlike a
/// [`VoxelCard`] it need not be a staircase.
#[derive(Clone, Debug, PartialEq)]
pub struct DepthField {
    /// Cells along the fold.
    pub nx: usize,
    /// Largest depth (cells of base in front of the fold).
    pub ny: usize,
    /// Rows of height.
    pub nz: usize,
    /// `depths[x * nz + z]`, z = 0 on the base; each at most `ny`.
    pub depths: Vec<u16>,
}

impl DepthField {
    /// Depth of cell (x, z).
    pub fn depth(&self, x: usize, z: usize) -> usize {
        self.depths[x * self.nz + z] as usize
    }
}

/// Options of §3.2–3.3.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConvertOptions {
    /// Side in cells of the square structuring element of the bump removal (§3.2 a): odd;
    /// 1 turns it off. The paper uses 3.
    pub element: usize,
    /// Make windows where voxels were added, where the card still pops up (§3.2 c).
    pub windows: bool,
    /// Only rows where eq. 7 added at least this part of the base depth become window
    /// candidates, in [0, 1]; 0 is the paper (every filled row). Rows filled by a thin layer,
    /// such as a wall just behind an eave, stay solid: their front face stands for the wall.
    pub window_gap: f64,
    /// Leave out top faces at most this many columns wide, where the card still pops up
    /// (§3.3); 0 keeps them all. The paper's example uses 1.
    pub thin_top: usize,
}

impl Default for ConvertOptions {
    /// The paper's settings: 3 × 3 element, windows, thin tops of one column left out.
    fn default() -> Self {
        ConvertOptions {
            element: 3,
            windows: true,
            window_gap: 0.25,
            thin_top: 1,
        }
    }
}

impl ConvertOptions {
    /// Only eq. 7: no bump removal, no windows, every top face kept.
    pub const EQ7_ONLY: ConvertOptions = ConvertOptions {
        element: 1,
        windows: false,
        window_gap: 0.0,
        thin_top: 0,
    };
}

/// What [`card_from_depths`] did.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ConvertReport {
    /// Cells changed by the opening and closing (§3.2 a).
    pub smoothed_cells: u64,
    /// Voxels added by eq. 7.
    pub added_cells: u64,
    /// Rows that became windows, of the rows eq. 7 filled (§3.2 c).
    pub window_rows: usize,
    /// Rows eq. 7 filled.
    pub filled_rows: usize,
    /// Rows filled deeply enough to be window candidates ([`ConvertOptions::window_gap`]).
    pub window_candidates: usize,
    /// Top faces left out, of the thin ones tried (§3.3).
    pub tops_omitted: usize,
    /// Thin top faces tried.
    pub thin_tops: usize,
    /// Pop-up checks run by the two searches: candidates and groups of candidates tried.
    pub checks: usize,
    /// Of those, the checks that flooded the whole card; the others were refused on the
    /// edited columns and their neighbours alone.
    pub full_checks: usize,
    /// Time of the bump removal.
    pub smoothing_time: Duration,
    /// Time of eq. 7 and the window search.
    pub constraint_time: Duration,
    /// Time of the thin-top search.
    pub thin_top_time: Duration,
}

/// Builds a card of `cell_mm` cells from `field` by §3.2–3.3 (see the module docs). Depths
/// are capped at `ny − 1`, one cell of base in front of every face, and the top row (z =
/// `nz − 1`) is emptied, one cell of back sheet above every face. The card pops up: a
/// staircase does, and every later step keeps the check of §2.6 passing.
pub fn card_from_depths(
    field: &DepthField,
    cell_mm: f64,
    options: &ConvertOptions,
) -> Result<(VoxelCard, ConvertReport), VoxelError> {
    convert(field, cell_mm, options, search::Verify::Runs)
}

/// [`card_from_depths`] with the searches' tries judged by `verify`.
fn convert(
    field: &DepthField,
    cell_mm: f64,
    options: &ConvertOptions,
    verify: search::Verify,
) -> Result<(VoxelCard, ConvertReport), VoxelError> {
    let (nx, ny, nz) = (field.nx, field.ny, field.nz);
    let mut card = VoxelCard::new(nx, ny, nz, cell_mm)?;
    if field.depths.len() != nx * nz {
        return Err(VoxelError::MapSize {
            expected: nx * nz,
            got: field.depths.len(),
        });
    }
    if options.element.is_multiple_of(2) {
        return Err(VoxelError::BadElement(options.element));
    }
    if !(0.0..=1.0).contains(&options.window_gap) {
        return Err(VoxelError::BadWindowGap(options.window_gap));
    }
    let min_gap = ((options.window_gap * ny as f64).ceil() as usize).max(1);
    let mut report = ConvertReport::default();
    let start = Stopwatch::start();
    // A face on the base's front edge would have nothing to stand on: depths stop one cell
    // short of it.
    // Nor can a top face on the back sheet's top edge hang from it: the top row stays empty.
    // Both hold after the bump removal too: closing with a large element fills the top row
    // next to a tall face (the slice's edge does not erode) and may reach past the cap.
    let cap = (ny - 1) as u16;
    let bound = |slice: &mut [u16]| {
        for d in slice.iter_mut() {
            *d = (*d).min(cap);
        }
        slice[nz - 1] = 0;
    };
    let mut depths: Vec<u16> = field.depths.clone();
    let radius = options.element / 2;
    for slice in depths.chunks_mut(nz) {
        bound(slice);
        let before = slice.to_vec();
        // Unbounded in depth: closing never goes beyond the deepest row of its window.
        morphology::open_close(slice, u16::MAX, radius);
        bound(slice);
        report.smoothed_cells += before
            .iter()
            .zip(slice.iter())
            .map(|(&a, &b)| a.abs_diff(b) as u64)
            .sum::<u64>();
    }
    report.smoothing_time = start.elapsed();

    let start = Stopwatch::start();
    let mut filled = vec![false; nx * nz];
    for x in 0..nx {
        let mut above = 0usize;
        for z in (0..nz).rev() {
            // Eq. 7 from the top row down: a cell is filled when the one above it is.
            let own = depths[x * nz + z] as usize;
            let d = own.max(above);
            if d > own {
                report.added_cells += (d - own) as u64;
                report.filled_rows += 1;
                if d - own >= min_gap {
                    filled[x * nz + z] = true;
                    report.window_candidates += 1;
                }
            }
            card.set_depth_unchecked_order(x, z, d);
            above = d;
        }
    }
    let mut search = search::Search::new(&mut card, verify);
    if options.windows {
        report.window_rows = search.windows(&filled);
    }
    report.constraint_time = start.elapsed();

    let start = Stopwatch::start();
    if options.thin_top > 0 {
        (report.tops_omitted, report.thin_tops) = search.thin_tops(options.thin_top);
    }
    report.checks = search.checks();
    report.full_checks = search.full_checks();
    report.thin_top_time = start.elapsed();
    Ok((card, report))
}
