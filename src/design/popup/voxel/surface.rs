//! The card's surface cell by cell: which voxel face plane each unit cell of the pattern lands
//! on when the card stands at 90°, and what lies between neighbouring cells (Mitani, Suzuki & Uno 2003, §2.3,
//! §2.5, Table 1).
//!
//! # Pattern coordinates
//! The sheet is flattened by eq. 6 at θ = 0: a point `(x, y, z)` of the card goes to
//! `(u, v) = (x, z − y)` (in cells). The back sheet is the upper half (v > 0), the base the
//! lower half (v < 0), the central fold is v = 0. Pattern row `r` is the band
//! `v ∈ [r − ny, r − ny + 1]`.
//!
//! Each x-slice of a staircase is a monotone path from the top of the back sheet `(y, z) =
//! (0, nz)` to the front of the base `(ny, 0)`: one step down (a vertical face) or forward (a
//! horizontal face) per pattern row. A vertical face at depth `y0` maps `(u, v) ↦ (u, y0, v +
//! y0)`, a horizontal face at height `z0` maps `(u, v) ↦ (u, z0 − v, z0)`.
//!
//! # Windows (§2.3, Fig. 5)
//! The front face of a window row `k` (depth `j + 1`) is shown instead as the top face of cell
//! `(x, j − (k − h) + 1, h)`, `h` the highest non-window row below `k` (the base when there is
//! none); when that index is negative the cell folds on to the back sheet. Both keep the
//! pattern coordinate v, which is how they are computed here.
//!
//! # Omitted top faces (§3.3, Fig. 14)
//! A top face left out ([`VoxelCard::is_top_omitted`]) keeps its pattern coordinate v and lies
//! on the back sheet (`y = 0`, z = v) where v ≥ 0, on the base (`z = 0`, y = −v) where v < 0,
//! as a window that would show on it does.
//!
//! # Lines (Table 1)
//! Two neighbouring cells on the same plane: nothing (180°). A vertical cell above a horizontal
//! one meeting at the same 3D edge: valley (90°); a horizontal above a vertical: mountain
//! (270°). Cells whose faces do not share the 3D edge: cut.

use super::VoxelCard;

/// The plane a pattern cell lands on at 90°.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Plane {
    /// The vertical plane y = depth (0 is the back sheet).
    Vertical(u32),
    /// The horizontal plane z = height (0 is the base sheet).
    Horizontal(u32),
}

impl Plane {
    /// Maps pattern coordinates (cells) to card coordinates (cells) at 90°.
    pub fn to_card(self, u: f64, v: f64) -> [f64; 3] {
        match self {
            Plane::Vertical(y0) => [u, y0 as f64, v + y0 as f64],
            Plane::Horizontal(z0) => [u, z0 as f64 - v, z0 as f64],
        }
    }
}

/// What separates two neighbouring pattern cells (Table 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Line {
    /// Same plane: no line (180°).
    Flat,
    /// 90°, the upper cell vertical and the lower horizontal.
    Valley,
    /// 270°, the upper cell horizontal and the lower vertical.
    Mountain,
    /// The faces do not meet.
    Cut,
}

/// The plane of every pattern cell: `nx` columns of `ny + nz` rows.
#[derive(Clone, Debug, PartialEq)]
pub struct Surface {
    /// Columns (x).
    pub nx: usize,
    /// Rows per column (`ny + nz`).
    pub rows: usize,
    /// Base depth in cells: row `r` is `v ∈ [r − ny, r − ny + 1]`.
    pub ny: usize,
    /// `planes[x * rows + r]`.
    pub planes: Vec<Plane>,
}

impl Surface {
    /// Walks every slice of `card` (see the module docs).
    pub fn new(card: &VoxelCard) -> Self {
        let rows = card.ny() + card.nz();
        let mut planes = Vec::with_capacity(card.nx() * rows);
        for x in 0..card.nx() {
            let start = planes.len();
            planes.resize(start + rows, Plane::Vertical(0));
            slice_planes(card, x, &mut planes[start..]);
        }
        Surface {
            nx: card.nx(),
            rows,
            ny: card.ny(),
            planes,
        }
    }

    /// The plane of cell (x, r). Cells outside the grid are the margins: flat paper of the
    /// back sheet above the fold (r ≥ ny) and of the base below it.
    pub fn plane(&self, x: i64, r: i64) -> Plane {
        let inside = (0..self.nx as i64).contains(&x) && (0..self.rows as i64).contains(&r);
        if inside {
            self.planes[x as usize * self.rows + r as usize]
        } else if r >= self.ny as i64 {
            Plane::Vertical(0)
        } else {
            Plane::Horizontal(0)
        }
    }

    /// The line between row `r − 1` and row `r` of column x (margins included).
    pub fn line_below(&self, x: i64, r: i64) -> Line {
        line_between(self.plane(x, r), self.plane(x, r - 1), r - self.ny as i64)
    }

    /// The line between column `x − 1` and column `x` at row r (margins included).
    pub fn line_left(&self, x: i64, r: i64) -> Line {
        if self.plane(x, r) == self.plane(x - 1, r) {
            Line::Flat
        } else {
            Line::Cut
        }
    }
}

/// The line at pattern height `v` between a cell on `upper` and the cell below it on `lower`
/// (Table 1).
pub fn line_between(upper: Plane, lower: Plane, v: i64) -> Line {
    match (upper, lower) {
        (a, b) if a == b => Line::Flat,
        (Plane::Vertical(y0), Plane::Horizontal(z0)) if z0 as i64 == v + y0 as i64 => Line::Valley,
        (Plane::Horizontal(z0), Plane::Vertical(y0)) if z0 as i64 == v + y0 as i64 => {
            Line::Mountain
        }
        _ => Line::Cut,
    }
}

/// Fills `out` (one slice, row 0 at the bottom) by walking the staircase path top-down.
pub(super) fn slice_planes(card: &VoxelCard, x: usize, out: &mut [Plane]) {
    let ny = card.ny() as i64;
    let (mut y, mut z) = (0usize, card.nz());
    while y < card.ny() || z > 0 {
        let v_low = z as i64 - y as i64 - 1;
        let r = (v_low + ny) as usize;
        if z > 0 && card.depth(x, z - 1) <= y {
            out[r] = vertical_or_window(card, x, z - 1, y);
            z -= 1;
        } else {
            out[r] = horizontal_or_omitted(card, x, z, v_low);
            y += 1;
        }
    }
}

/// The plane of a cell of the horizontal face at height `z0` (the top of row `z0 − 1`, or the
/// base), moved to the sheets per §3.3 when that top face is omitted.
fn horizontal_or_omitted(card: &VoxelCard, x: usize, z0: usize, v_low: i64) -> Plane {
    if z0 > 0 && card.is_top_omitted(x, z0 - 1) {
        on_the_sheets(v_low)
    } else {
        Plane::Horizontal(z0 as u32)
    }
}

/// Where a cell at pattern height `v_low` lies when it stays in the sheets' plane: the back
/// sheet above the central fold, the base below it.
fn on_the_sheets(v_low: i64) -> Plane {
    if v_low >= 0 {
        Plane::Vertical(0)
    } else {
        Plane::Horizontal(0)
    }
}

/// The plane of the front face of row k at depth `y0`, moved per §2.3 when it is a window.
fn vertical_or_window(card: &VoxelCard, x: usize, k: usize, y0: usize) -> Plane {
    if y0 == 0 || !card.is_hole(x, k) {
        return Plane::Vertical(y0 as u32);
    }
    let top = (0..k)
        .rev()
        .find(|&h| !card.is_hole(x, h))
        .map_or(0, |h| h + 1);
    // The horizontal cell at height `top` with the same v starts at y = top + y0 − k − 1.
    let v_low = k as i64 - y0 as i64;
    if top + y0 > k {
        horizontal_or_omitted(card, x, top, v_low)
    } else {
        Plane::Vertical(0)
    }
}
