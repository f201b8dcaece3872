//! The pop-up check of seed 001 §2.6 (Fig. 8, Fig. 9).
//!
//! Two floods over the pattern's unit cells, never across a cut: (a) from the top-left corner
//! moving left, down and right; (b) from the bottom-left corner moving left, up and right.
//! Every front cell (a vertical face in front of the back sheet) must be reached by both;
//! one reached by neither floats (Fig. 8 a), one reached by only one flood is held from one
//! side only and is not pulled up when the card opens (Fig. 8 b).

use std::collections::VecDeque;

use super::VoxelCard;
use super::surface::{Line, Plane, Surface};

/// Why a front cell fails the pop-up check.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PopupProblem {
    /// Reached by neither flood: a part with no connection to the sheet.
    Floating,
    /// Reached only from the back sheet (flood a): it hangs and is not pushed up.
    HeldFromBackOnly,
    /// Reached only from the base sheet (flood b): it is not pulled up.
    HeldFromBaseOnly,
}

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
        let why = match self.problem {
            PopupProblem::Floating => "floats: cut off from both sheets",
            PopupProblem::HeldFromBackOnly => "is held from the back sheet only",
            PopupProblem::HeldFromBaseOnly => "is held from the base sheet only",
        };
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
    let surface = Surface::new(card);
    let top = surface.rows - 1;
    let from_back = flood(&surface, (0, top), -1);
    let from_base = flood(&surface, (0, 0), 1);
    let mut problems = Vec::new();
    for x in 0..surface.nx {
        for r in 0..surface.rows {
            let Plane::Vertical(depth) = surface.plane(x as i64, r as i64) else {
                continue;
            };
            let i = x * surface.rows + r;
            let problem = match (depth > 0, from_back[i], from_base[i]) {
                (false, _, _) | (true, true, true) => continue,
                (true, false, false) => PopupProblem::Floating,
                (true, true, false) => PopupProblem::HeldFromBackOnly,
                (true, false, true) => PopupProblem::HeldFromBaseOnly,
            };
            let z = r + depth as usize - surface.ny;
            problems.push(FrontCellProblem {
                x,
                depth: depth as usize,
                z,
                problem,
            });
        }
    }
    PopupReport { problems }
}

/// Breadth-first flood from `start` moving left, right and `dr` rows (−1 down, +1 up).
fn flood(s: &Surface, start: (usize, usize), dr: i64) -> Vec<bool> {
    let mut seen = vec![false; s.planes.len()];
    let mut queue = VecDeque::from([start]);
    seen[start.0 * s.rows + start.1] = true;
    while let Some((x, r)) = queue.pop_front() {
        for (nx, nr) in steps(s, x, r, dr) {
            let i = nx * s.rows + nr;
            if !seen[i] {
                seen[i] = true;
                queue.push_back((nx, nr));
            }
        }
    }
    seen
}

/// The neighbours of (x, r) reachable without crossing a cut.
fn steps(s: &Surface, x: usize, r: usize, dr: i64) -> impl Iterator<Item = (usize, usize)> {
    let mut out = [None; 3];
    let (xi, ri) = (x as i64, r as i64);
    if x > 0 && s.line_left(xi, ri) != Line::Cut {
        out[0] = Some((x - 1, r));
    }
    if x + 1 < s.nx && s.line_left(xi + 1, ri) != Line::Cut {
        out[1] = Some((x + 1, r));
    }
    let nr = ri + dr;
    if (0..s.rows as i64).contains(&nr) && s.line_below(xi, ri.max(nr)) != Line::Cut {
        out[2] = Some((x, nr as usize));
    }
    out.into_iter().flatten()
}
