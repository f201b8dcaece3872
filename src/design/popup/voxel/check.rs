//! The pop-up check of Mitani, Suzuki & Uno (2003), §2.6 (Fig. 8, Fig. 9).
//!
//! Two floods over the pattern's unit cells, never across a cut: (a) from the top-left corner
//! moving left, down and right; (b) from the bottom-left corner moving left, up and right.
//! Every front cell (a vertical face in front of the back sheet) must be reached by both;
//! one reached by neither floats (Fig. 8 a), one reached by only one flood is held from one
//! side only and is not pulled up when the card opens (Fig. 8 b).

use super::VoxelCard;
use super::runs::ColumnRuns;
pub use crate::design::popup::problem::PopupProblem;

/// One front face of the card that fails the check.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FrontCellProblem {
    /// Cell column along the fold.
    pub x: usize,
    /// The face lies on the plane y = `depth`: it is the front of cell (x, depth − 1, z).
    pub depth: usize,
    /// Height level.
    pub z: usize,
    /// What is wrong.
    pub problem: PopupProblem,
}

impl std::fmt::Display for FrontCellProblem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let why = self.problem.describe();
        let (x, y, z) = (self.x, self.depth - 1, self.z);
        write!(f, "front face of cell ({x}, {y}, {z}) {why}")
    }
}

/// The result of [`check_popup`]: empty when the card pops up.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct PopupReport {
    /// Failing front cells, by column then row.
    pub problems: Vec<FrontCellProblem>,
}

impl PopupReport {
    /// True when every front cell is reached by both floods.
    pub fn passed(&self) -> bool {
        self.problems.is_empty()
    }
}

/// Runs both floods of §2.6 on `card`'s pattern cells.
pub fn check_popup(card: &VoxelCard) -> PopupReport {
    PopupReport {
        problems: ColumnRuns::new(card).problems(card.ny()),
    }
}
