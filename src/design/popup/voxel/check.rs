//! The pop-up check of Mitani, Suzuki & Uno (2003), §2.6 (Fig. 8, Fig. 9).
//!
//! Two floods over the pattern's unit cells, never across a cut: (a) from the top-left corner
//! moving left, down and right; (b) from the bottom-left corner moving left, up and right.
//! Every front cell (a vertical face in front of the back sheet) must be reached by both;
//! one reached by neither floats (Fig. 8 a), one reached by only one flood is held from one
//! side only and is not pulled up when the card opens (Fig. 8 b).
//!
//! Addition to the paper: a piece of paper lying in the back sheet's plane but cut free of the
//! back sheet (a window shown on the back sheet, a left-out top face) is a vertical face too,
//! and its cells must be reached by both floods as well (see `runs.rs`). Without it a strip
//! hinged only at the central fold, or the disk inside a ring, passes the paper's check and
//! flaps when the card opens.

use super::VoxelCard;
use super::runs::ColumnRuns;
pub use crate::design::popup::problem::PopupProblem;

/// One vertical unit face of the card that fails the check: a front face, or a cell of a
/// piece of the back sheet's plane cut free of the back sheet.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FrontCellProblem {
    /// Cell column along the fold.
    pub x: usize,
    /// The face lies on the plane y = `depth`: it is the front of cell (x, depth − 1, z), or,
    /// at 0, a cell of a piece of paper in the back sheet's plane cut free of the back sheet.
    pub depth: usize,
    /// Height level.
    pub z: usize,
    /// What is wrong.
    pub problem: PopupProblem,
}

impl FrontCellProblem {
    /// Where the face lies on the crease pattern, in millimetres, for cells of `cell_mm`:
    /// `(u0, u1)` across from the cells' left edge and `(v0, v1)` up from the central fold
    /// (the pattern's coordinates, margin not counted). The face's pattern row is
    /// `z − depth` cells above the fold (eq. 6 at θ = 0).
    pub fn pattern_mm(&self, cell_mm: f64) -> ((f64, f64), (f64, f64)) {
        let u = self.x as f64 * cell_mm;
        let v = (self.z as f64 - self.depth as f64) * cell_mm;
        ((u, u + cell_mm), (v, v + cell_mm))
    }

    /// The sentence `foldcam` prints: the face (as [`Display`](std::fmt::Display)) and its
    /// place on the crease pattern in millimetres (see [`FrontCellProblem::pattern_mm`]).
    pub fn describe_at(&self, cell_mm: f64) -> String {
        let ((u0, u1), (v0, v1)) = self.pattern_mm(cell_mm);
        let side = if v0 < 0.0 { "below" } else { "above" };
        let (v0, v1) = if v0 < 0.0 { (-v1, -v0) } else { (v0, v1) };
        format!(
            "{self} (on the pattern x {u0:.1}–{u1:.1} mm from the cells' left edge, \
             {v0:.1}–{v1:.1} mm {side} the central fold)"
        )
    }
}

impl std::fmt::Display for FrontCellProblem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let why = self.problem.describe();
        let (x, z) = (self.x, self.z);
        match self.depth.checked_sub(1) {
            Some(y) => write!(f, "front face of cell ({x}, {y}, {z}) {why}"),
            None => write!(
                f,
                "back-sheet cell (x {x}, z {z}), part of a piece cut free of the back sheet, {why}"
            ),
        }
    }
}

/// The result of [`check_popup`]: empty when the card pops up.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct PopupReport {
    /// Failing front cells, by column then row.
    pub problems: Vec<FrontCellProblem>,
}

impl PopupReport {
    /// True when every front cell, and every cell of a piece cut free of the back sheet, is
    /// reached by both floods.
    pub fn passed(&self) -> bool {
        self.problems.is_empty()
    }
}

/// Runs both floods of §2.6 on `card`'s pattern cells; checks the front cells and the cells
/// of pieces cut free of the back sheet (see the module docs). A margin
/// ([`VoxelCard::margin_mm`]) joins back-sheet paper beside the first and last columns to the
/// back sheet.
pub fn check_popup(card: &VoxelCard) -> PopupReport {
    PopupReport {
        problems: ColumnRuns::new(card).problems(),
    }
}
