//! The crease pattern of a polygon card (Mitani & Suzuki 2004, §3.4).
//!
//! The classified lines ([`super::lines`]) become edges in millimetres: valleys +90°, mountains
//! −90°, cuts; the sheet outline is the boundary. The pattern is planarised (T-junctions split)
//! with its faces, in the voxel card's convention: x along
//! the fold from 0, v up (back sheet on top), the central fold on v = 0.

use glam::DVec2;

use super::lines::{LineKind, Lines, classify};
use super::model::{PolygonCard, to_mm};
use crate::pattern::{Assignment, CreasePattern, PlanarizeError, PlanarizeOptions, planarize};

/// Vertices closer than this merge when the pattern is planarised, in millimetres: a tenth
/// of a grid unit. The faces tile the sheet exactly on the grid, so every vertex that lies on
/// another face's edge lies on it exactly; the tolerance only absorbs the conversion to
/// millimetres and never moves a vertex off its grid point (a crease stays parallel to x).
pub const PATTERN_TOLERANCE_MM: f64 = 1e-5;

/// Builds the planarised crease pattern of `card`, with faces.
pub fn crease_pattern(card: &PolygonCard) -> Result<CreasePattern, PlanarizeError> {
    crease_pattern_from(card, &classify(card))
}

/// [`crease_pattern`] from lines already classified.
pub fn crease_pattern_from(
    card: &PolygonCard,
    lines: &Lines,
) -> Result<CreasePattern, PlanarizeError> {
    let mut cp = CreasePattern::new();
    for l in &lines.lines {
        let (assignment, angle) = match l.kind {
            LineKind::Valley => (Assignment::Valley, Some(90.0)),
            LineKind::Mountain => (Assignment::Mountain, Some(-90.0)),
            LineKind::Cut => (Assignment::Cut, None),
            LineKind::Flat => continue,
        };
        let e = cp.add_segment(to_mm(l.a), to_mm(l.b), assignment);
        cp.edges[e.index()].fold_angle = angle;
    }
    let corners: Vec<DVec2> = card.sheet().iter().map(|&p| to_mm(p)).collect();
    for i in 0..4 {
        cp.add_segment(corners[i], corners[(i + 1) % 4], Assignment::Boundary);
    }
    let opts = PlanarizeOptions {
        tolerance: Some(PATTERN_TOLERANCE_MM),
        faces: true,
    };
    planarize(&mut cp, &opts)?;
    Ok(cp)
}
