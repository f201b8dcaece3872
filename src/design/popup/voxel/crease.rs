//! The crease pattern of a voxel card (Mitani, Suzuki & Uno 2003, §2.5, Table 1; windows per §2.3).
//!
//! The lines between unit cells come from [`Surface`]; runs of equal lines along one grid line
//! are merged into one edge, so a crease 1000 cells long is one edge. Valleys get +90°,
//! mountains −90°; the sheet outline is the boundary. The result is planarised (T-junctions
//! split) with its faces computed, in millimetres, x right and v up (back sheet on top), the
//! central fold on v = 0 and the card's left edge on u = 0. A margin adds flat paper around
//! the cells: above the fold it continues the back sheet, below it the base.

use glam::DVec2;

use super::VoxelCard;
use super::surface::{Line, Surface};
use crate::pattern::{Assignment, CreasePattern, PlanarizeError, PlanarizeOptions, planarize};

/// The planariser's merge tolerance as a share of the voxel cell's side: the pattern's
/// coordinates are whole multiples of a cell or of its half, so anything closer is equal.
const MERGE_PER_CELL: f64 = 1e-6;

/// Builds the planarised crease pattern of `card`, with faces.
pub fn crease_pattern(card: &VoxelCard) -> Result<CreasePattern, PlanarizeError> {
    let surface = Surface::new(card);
    let grid = Grid::new(card);
    let mut cp = CreasePattern::new();
    for r in grid.inner_lines(surface.rows) {
        let lines: Vec<Line> = grid
            .cells(surface.nx)
            .map(|x| surface.line_below(x, r))
            .collect();
        for (kind, a, b) in runs(&lines) {
            let (a, b) = (grid.cell_index(a), grid.cell_index(b - 1));
            let y = grid.at(0, r).y;
            push(
                &mut cp,
                grid.at(a, 0).with_y(y),
                grid.at_end(b, 0).with_y(y),
                kind,
            );
        }
    }
    for x in grid.inner_lines(surface.nx) {
        let lines: Vec<Line> = grid
            .cells(surface.rows)
            .map(|r| surface.line_left(x, r))
            .collect();
        for (kind, a, b) in runs(&lines) {
            let (a, b) = (grid.cell_index(a), grid.cell_index(b - 1));
            let xm = grid.at(x, 0).x;
            push(
                &mut cp,
                grid.at(0, a).with_x(xm),
                grid.at_end(0, b).with_x(xm),
                kind,
            );
        }
    }
    outline(
        &mut cp,
        grid.at(grid.first(), grid.first()),
        grid.at_end(
            surface.nx as i64 - 1 + grid.pad,
            surface.rows as i64 - 1 + grid.pad,
        ),
    );
    let opts = PlanarizeOptions {
        tolerance: Some(card.cell_mm() * MERGE_PER_CELL),
        faces: true,
    };
    planarize(&mut cp, &opts)?;
    Ok(cp)
}

/// The pattern's grid in millimetres: unit cells plus, when the card has a margin, one margin
/// cell of that width on each side (index −1 and n).
struct Grid {
    s: f64,
    margin: f64,
    ny: f64,
    nx: i64,
    rows: i64,
    /// 1 with margins, 0 without.
    pad: i64,
}

impl Grid {
    fn new(card: &VoxelCard) -> Self {
        let margin = card.margin_mm();
        Grid {
            s: card.cell_mm(),
            margin,
            ny: card.ny() as f64,
            nx: card.nx() as i64,
            rows: (card.ny() + card.nz()) as i64,
            pad: i64::from(margin > 0.0),
        }
    }

    /// Index of the first cell along an axis.
    fn first(&self) -> i64 {
        -self.pad
    }

    /// Cell indices along an axis of `n` cells, margins included.
    fn cells(&self, n: usize) -> impl Iterator<Item = i64> {
        -self.pad..n as i64 + self.pad
    }

    /// Grid lines strictly inside the sheet along an axis of `n` cells.
    fn inner_lines(&self, n: usize) -> impl Iterator<Item = i64> {
        1 - self.pad..n as i64 + self.pad
    }

    /// The cell index of position `i` in a [`Grid::cells`] list.
    fn cell_index(&self, i: usize) -> i64 {
        i as i64 - self.pad
    }

    /// One coordinate of the lower/left grid line of cell `i` (`n` cells, origin `o`).
    fn line(&self, i: i64, n: i64, o: f64) -> f64 {
        match i {
            i if i < 0 => -o * self.s - self.margin,
            i if i > n => (n as f64 - o) * self.s + self.margin,
            i => (i as f64 - o) * self.s,
        }
    }

    /// Lower-left corner of cell (x, r): u along the fold, v = 0 on the fold.
    fn at(&self, x: i64, r: i64) -> DVec2 {
        DVec2::new(self.line(x, self.nx, 0.0), self.line(r, self.rows, self.ny))
    }

    /// Upper-right corner of cell (x, r).
    fn at_end(&self, x: i64, r: i64) -> DVec2 {
        DVec2::new(
            self.line(x + 1, self.nx, 0.0),
            self.line(r + 1, self.rows, self.ny),
        )
    }
}

/// Maximal runs of equal non-flat lines: `(kind, first cell, one past the last cell)`.
fn runs(lines: &[Line]) -> Vec<(Line, usize, usize)> {
    let mut out = Vec::new();
    let mut start = 0;
    for i in 1..=lines.len() {
        if i == lines.len() || lines[i] != lines[start] {
            if lines[start] != Line::Flat {
                out.push((lines[start], start, i));
            }
            start = i;
        }
    }
    out
}

/// Adds one merged line with its assignment and fold angle.
fn push(cp: &mut CreasePattern, a: DVec2, b: DVec2, kind: Line) {
    let (assignment, angle) = match kind {
        Line::Valley => (Assignment::Valley, Some(90.0)),
        Line::Mountain => (Assignment::Mountain, Some(-90.0)),
        Line::Cut => (Assignment::Cut, None),
        Line::Flat => return,
    };
    let e = cp.add_segment(a, b, assignment);
    cp.edges[e.index()].fold_angle = angle;
}

/// The sheet outline, lower-left `lo` to upper-right `hi`, as four boundary edges.
fn outline(cp: &mut CreasePattern, lo: DVec2, hi: DVec2) {
    let corners = [lo, DVec2::new(hi.x, lo.y), hi, DVec2::new(lo.x, hi.y)];
    for i in 0..4 {
        cp.add_segment(corners[i], corners[(i + 1) % 4], Assignment::Boundary);
    }
}
