//! The voxel card: the staircase voxels of Mitani, Suzuki & Uno (2003) (eq. 3–4), the windows (eq. 5) and the
//! editing operations of §2.7.
//!
//! Axes follow the paper: `x` runs along the central fold, `y` is the depth in front of the
//! back sheet (the back sheet is the plane y = 0), `z` is the height above the base sheet (the
//! plane z = 0). Cell `(x, y, z)` is the unit cube `[x, x+1] × [y, y+1] × [z, z+1]`.
//!
//! # Representation
//! Eq. 4 says a filled cell has filled cells below (z − 1) and behind (y − 1). So the filled
//! cells of row `(x, z)` are exactly `y < depth(x, z)`, and `depth(x, z)` never grows with z.
//! The card stores one `u16` depth and one window flag per `(x, z)` row: 3 bytes per row, so
//! 3 / ny bytes per cell (0.003 bytes per cell for a 2000 × 1000 × 1000 card: 6 MB).
//! Every value of this type satisfies eq. 4; the editing operations keep it so.

use thiserror::Error;

/// Largest number of cells along any axis ([`crate::limits::VOXEL_CELLS_PER_AXIS`]).
pub const MAX_CELLS_PER_AXIS: usize = crate::limits::VOXEL_CELLS_PER_AXIS;

/// Largest number of unit cells in the crease pattern, `nx × (ny + nz)`
/// ([`crate::limits::VOXEL_PATTERN_CELLS`]).
pub const MAX_PATTERN_CELLS: usize = crate::limits::VOXEL_PATTERN_CELLS;

/// Why a card cannot be made.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum VoxelError {
    /// A dimension is zero or above [`MAX_CELLS_PER_AXIS`], or the pattern would exceed
    /// [`MAX_PATTERN_CELLS`].
    #[error(
        "card size {nx} × {ny} × {nz} cells is out of range (1..={MAX_CELLS_PER_AXIS} per axis, at most {MAX_PATTERN_CELLS} pattern cells)"
    )]
    BadSize {
        /// Cells along the fold.
        nx: usize,
        /// Cells of depth (base sheet).
        ny: usize,
        /// Cells of height (back sheet).
        nz: usize,
    },
    /// The margin is not a finite number of millimetres in 0..=1000.
    #[error("margin {0} mm must be finite, at least 0 and at most 1000 mm")]
    BadMargin(f64),
    /// The cell size is not a finite positive number of millimetres.
    #[error("cell size {0} mm: expected {range} (--cell-mm)", range = crate::limits::CELL.expected())]
    BadCellSize(f64),
    /// A cell index is outside the card.
    #[error("cell ({x}, {y}, {z}) is outside the card")]
    OutOfRange {
        /// x index.
        x: usize,
        /// y index.
        y: usize,
        /// z index.
        z: usize,
    },
    /// A depth map's sample count is not width × height.
    #[error("depth map has {got} samples, expected {expected} (width × height)")]
    MapSize {
        /// width × height.
        expected: usize,
        /// Samples given.
        got: usize,
    },
    /// A height map smaller than [`super::MIN_MAP_SIDE`] pixels across or up.
    #[error(
        "the height map is {width} × {height} pixels; at least {min} × {min} are needed (one \
         pixel is one cell)"
    )]
    MapTooSmall {
        /// Pixels across.
        width: usize,
        /// Pixels up.
        height: usize,
        /// The least accepted on either side.
        min: usize,
    },
    /// The structuring element of §3.2 a) must have an odd side.
    #[error("the structuring element must be an odd number of cells across, got {0}")]
    BadElement(usize),
    /// The window gap is not a fraction in [0, 1].
    #[error("the window gap must be a fraction of the base depth in [0, 1], got {0}")]
    BadWindowGap(f64),
    /// Setting a row depth would break the staircase constraint (eq. 4).
    #[error("row (x {x}, z {z}): depth {depth} breaks the staircase (allowed {min}..={max})")]
    NotStaircase {
        /// x index.
        x: usize,
        /// z index (height level).
        z: usize,
        /// The depth asked for.
        depth: usize,
        /// Smallest allowed depth (the row above).
        min: usize,
        /// Largest allowed depth (the row below, or the base depth).
        max: usize,
    },
}

/// A voxel pop-up card: `nx × ny × nz` cells of `cell_mm` millimetres, staircase by
/// construction (eq. 4), with window flags on the rows' front faces (eq. 5).
#[derive(Clone, Debug, PartialEq)]
pub struct VoxelCard {
    nx: usize,
    ny: usize,
    nz: usize,
    cell_mm: f64,
    margin_mm: f64,
    /// `depth[x * nz + z]`: filled cells of row (x, z) are y < depth.
    depth: Vec<u16>,
    /// `hole[x * nz + z]`: the front face of row (x, z) is a window (eq. 5, `isHole[x][z]`).
    hole: Vec<bool>,
    /// `top_omitted[x * nz + z]`: the top face of row (x, z) is left out (§3.3).
    top_omitted: Vec<bool>,
}

impl VoxelCard {
    /// An empty card: `nx` cells along the fold, a base `ny` cells deep, a back sheet `nz`
    /// cells high, each cell `cell_mm` millimetres. The sheet is `nx × (ny + nz)` cells.
    pub fn new(nx: usize, ny: usize, nz: usize, cell_mm: f64) -> Result<Self, VoxelError> {
        let axis_ok = |n: usize| (1..=MAX_CELLS_PER_AXIS).contains(&n);
        if !(axis_ok(nx) && axis_ok(ny) && axis_ok(nz)) || nx * (ny + nz) > MAX_PATTERN_CELLS {
            return Err(VoxelError::BadSize { nx, ny, nz });
        }
        if crate::limits::CELL.check(cell_mm).is_err() {
            return Err(VoxelError::BadCellSize(cell_mm));
        }
        Ok(VoxelCard {
            nx,
            ny,
            nz,
            cell_mm,
            margin_mm: 0.0,
            depth: vec![0; nx * nz],
            hole: vec![false; nx * nz],
            top_omitted: vec![false; nx * nz],
        })
    }

    /// Cells along the fold (x).
    pub fn nx(&self) -> usize {
        self.nx
    }

    /// Cells of depth (y): the base sheet's depth.
    pub fn ny(&self) -> usize {
        self.ny
    }

    /// Cells of height (z): the back sheet's height.
    pub fn nz(&self) -> usize {
        self.nz
    }

    /// Edge length of one cell in millimetres.
    pub fn cell_mm(&self) -> f64 {
        self.cell_mm
    }

    /// Flat paper added around the cells on all four sides, in millimetres: the upper half
    /// belongs to the back sheet, the lower half to the base.
    pub fn margin_mm(&self) -> f64 {
        self.margin_mm
    }

    /// Sets the margin (0..=1000 mm).
    pub fn set_margin_mm(&mut self, margin: f64) -> Result<(), VoxelError> {
        if !(margin.is_finite() && (0.0..=1000.0).contains(&margin)) {
            return Err(VoxelError::BadMargin(margin));
        }
        self.margin_mm = margin;
        Ok(())
    }

    /// Sheet size in millimetres: `(nx, ny + nz) × cell_mm`, plus a margin on each side.
    pub fn sheet_mm(&self) -> (f64, f64) {
        let (s, m) = (self.cell_mm, 2.0 * self.margin_mm);
        (self.nx as f64 * s + m, (self.ny + self.nz) as f64 * s + m)
    }

    /// Filled cells of row (x, z) are `y < depth(x, z)`; 0 outside the card.
    pub fn depth(&self, x: usize, z: usize) -> usize {
        self.index(x, z).map_or(0, |i| self.depth[i] as usize)
    }

    /// `cell[x][y][z]` of eq. 3; false outside the card.
    pub fn cell(&self, x: usize, y: usize, z: usize) -> bool {
        y < self.depth(x, z)
    }

    /// `isHole[x][z]` of eq. 5: the front face of row (x, z) is a window. A window on an
    /// empty row (depth 0) has no effect.
    pub fn is_hole(&self, x: usize, z: usize) -> bool {
        self.index(x, z).is_some_and(|i| self.hole[i])
    }

    /// A window whose front face exists (its row is not empty).
    pub fn is_window(&self, x: usize, z: usize) -> bool {
        self.is_hole(x, z) && self.depth(x, z) > 0
    }

    /// Adds cell (x, y, z) and, as §2.7 does, every cell below and behind it in the slice
    /// (`y' ≤ y`, `z' ≤ z`), so eq. 4 still holds.
    pub fn add(&mut self, x: usize, y: usize, z: usize) -> Result<(), VoxelError> {
        let i = self.checked(x, y, z)?;
        let d = (y + 1) as u16;
        for v in &mut self.depth[i - z..=i] {
            *v = (*v).max(d);
        }
        Ok(())
    }

    /// Deletes cell (x, y, z) and, as §2.7 does, every cell above and in front of it in the
    /// slice (`y' ≥ y`, `z' ≥ z`), so eq. 4 still holds.
    pub fn delete(&mut self, x: usize, y: usize, z: usize) -> Result<(), VoxelError> {
        let i = self.checked(x, y, z)?;
        let row_end = i - z + self.nz;
        for v in &mut self.depth[i..row_end] {
            *v = (*v).min(y as u16);
        }
        Ok(())
    }

    /// Sets the depth of row (x, z) directly; refused when it would break eq. 4.
    pub fn set_depth(&mut self, x: usize, z: usize, depth: usize) -> Result<(), VoxelError> {
        let i = self.checked(x, 0, z)?;
        let min = self.depth(x, z + 1);
        let max = if z == 0 {
            self.ny
        } else {
            self.depth(x, z - 1)
        };
        if !(min..=max).contains(&depth) {
            return Err(VoxelError::NotStaircase {
                x,
                z,
                depth,
                min,
                max,
            });
        }
        self.depth[i] = depth as u16;
        Ok(())
    }

    /// Sets the depth of an in-range row filled top-down (callers keep eq. 4 themselves by
    /// never going below the row above; the rows below are set next).
    pub(super) fn set_depth_unchecked_order(&mut self, x: usize, z: usize, depth: usize) {
        let i = x * self.nz + z;
        self.depth[i] = depth.min(self.ny) as u16;
    }

    /// Turns the window of row (x, z) on or off (eq. 5).
    pub fn set_hole(&mut self, x: usize, z: usize, on: bool) -> Result<(), VoxelError> {
        let i = self.checked(x, 0, z)?;
        self.hole[i] = on;
        Ok(())
    }

    /// The top face of row (x, z) (the horizontal face at height z + 1 between the fronts of
    /// rows z and z + 1) is left out, as §3.3 does for thin faces: its paper lies on the back
    /// sheet instead (or on the base, where it falls below the fold; Fig. 14).
    pub fn is_top_omitted(&self, x: usize, z: usize) -> bool {
        self.index(x, z).is_some_and(|i| self.top_omitted[i])
    }

    /// Leaves out, or restores, the top face of row (x, z) (§3.3). It has an effect only where
    /// the row stands out further than the row above it.
    pub fn set_top_omitted(&mut self, x: usize, z: usize, on: bool) -> Result<(), VoxelError> {
        let i = self.checked(x, 0, z)?;
        self.top_omitted[i] = on;
        Ok(())
    }

    /// Width in cells of the top face of row (x, z): how far the row stands out beyond the
    /// row above it (0 when there is no top face).
    pub fn top_width(&self, x: usize, z: usize) -> usize {
        self.depth(x, z) - self.depth(x, z + 1)
    }

    /// True when every x-slice is a staircase (eq. 4); always true for this type, kept for
    /// tests and debug checks.
    pub fn is_staircase(&self) -> bool {
        self.depth.chunks(self.nz).all(|col| {
            col.windows(2).all(|w| w[0] >= w[1]) && col.iter().all(|&d| d as usize <= self.ny)
        })
    }

    fn index(&self, x: usize, z: usize) -> Option<usize> {
        (x < self.nx && z < self.nz).then(|| x * self.nz + z)
    }

    fn checked(&self, x: usize, y: usize, z: usize) -> Result<usize, VoxelError> {
        match self.index(x, z) {
            Some(i) if y < self.ny => Ok(i),
            _ => Err(VoxelError::OutOfRange { x, y, z }),
        }
    }
}
