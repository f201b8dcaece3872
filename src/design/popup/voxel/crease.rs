//! The crease pattern of a voxel card (seed 001 §2.5, Table 1; windows per §2.3).
//!
//! The lines between unit cells come from [`Surface`]; runs of equal lines along one grid line
//! are merged into one edge, so a crease 1000 cells long is one edge. Valleys get +90°,
//! mountains −90°; the sheet outline is the boundary. The result is planarised (T-junctions
//! split) with its faces computed, in millimetres, x right and v up (back sheet on top).

use glam::DVec2;

use super::VoxelCard;
use super::surface::{Line, Surface};
use crate::pattern::{Assignment, CreasePattern, PlanarizeError, PlanarizeOptions, planarize};

/// Builds the planarised crease pattern of `card`, with faces.
pub fn crease_pattern(card: &VoxelCard) -> Result<CreasePattern, PlanarizeError> {
    let surface = Surface::new(card);
    let mut cp = CreasePattern::new();
    let s = card.cell_mm();
    let at = |x: usize, r: usize| DVec2::new(x as f64 * s, (r as f64 - card.ny() as f64) * s);
    for r in 1..surface.rows {
        let lines: Vec<Line> = (0..surface.nx).map(|x| surface.line_below(x, r)).collect();
        for (kind, a, b) in runs(&lines) {
            push(&mut cp, at(a, r), at(b, r), kind);
        }
    }
    for x in 1..surface.nx {
        let lines: Vec<Line> = (0..surface.rows).map(|r| surface.line_left(x, r)).collect();
        for (kind, a, b) in runs(&lines) {
            push(&mut cp, at(x, a), at(x, b), kind);
        }
    }
    outline(&mut cp, at(0, 0), at(surface.nx, surface.rows));
    let opts = PlanarizeOptions {
        tolerance: Some(s * 1e-6),
        faces: true,
    };
    planarize(&mut cp, &opts)?;
    Ok(cp)
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
