//! Which checks apply to a pattern: folding flat or folding to a 3D target.
//!
//! Kawasaki's and Maekawa's theorems describe vertices that fold *flat* (every crease folded
//! by ±180°). A crease is **meant to fold flat** when its stored fold angle is within
//! [`FLAT_FOLD_TOLERANCE_DEG`] of ±180°, or when it is a crease (M, V or U) without a stored
//! angle — the FOLD and Origami Simulator convention for a fully folded crease. An interior
//! vertex whose creases are all meant to fold flat is checked for Kawasaki and Maekawa; one
//! with a crease folding to less than 180° belongs to a **3D target** (a tessellation, a
//! curved or partly folded form) and is not: what applies to it is the developability of the
//! 3D frame, when the file carries one ([`super::developability`]), and the fabrication
//! limits (vertex and fold angles, edge lengths), which apply to every pattern.
//!
//! [`CheckRun`] records, for the report, each family of checks, whether it ran, where and
//! why.

use serde::Serialize;

use crate::pattern::vertex_fan::Spoke;
use crate::pattern::{CreasePattern, Edge};

/// Fold angles within this many degrees of ±180° count as folded flat (Origami Simulator
/// SVGs carry the angle as a stroke opacity, rounded when written).
pub const FLAT_FOLD_TOLERANCE_DEG: f64 = 0.5;

/// Whether a crease is meant to fold flat (see the module docs). Edges that do not fold
/// (boundary, cut, flat facet lines, joins) return `true`: they never make a vertex 3D.
pub fn folds_flat(edge: &Edge) -> bool {
    if !edge.assignment.may_fold() {
        return true;
    }
    edge.fold_angle
        .is_none_or(|a| a.abs() >= 180.0 - FLAT_FOLD_TOLERANCE_DEG)
}

/// Whether every crease at a vertex (its fan) is meant to fold flat.
pub fn vertex_folds_flat(cp: &CreasePattern, fan: &[Spoke]) -> bool {
    fan.iter().all(|s| folds_flat(&cp.edges[s.edge.index()]))
}

/// What a file format without fold angles (ORIPA's `.cp` and `.opx`) loses of `cp`, or `None`
/// when nothing: its creases that fold to less than 180° (a 3D target) read back as creases
/// without an angle, which fold flat, so `check` holds their vertices to Kawasaki and Maekawa
/// there and its findings differ from the original's.
pub fn fold_angles_lost(cp: &CreasePattern) -> Option<String> {
    let short = cp.edges.iter().filter(|e| !folds_flat(e)).count();
    (short > 0).then(|| {
        format!(
            "{short} creases fold to less than 180° (a 3D target), and this format carries no \
             fold angles: they read back as folding flat, so a check of this file holds their \
             vertices to Kawasaki and Maekawa and may find more than a check of the original \
             (keep FOLD or SVG for the 3D target)"
        )
    })
}

/// One family of checks in the report: whether it ran, over how many elements, and why.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CheckRun {
    /// Short name: `flat_foldability`, `developability`, `vertex_angle`, `fold_angle`,
    /// `edge_length`.
    pub name: &'static str,
    /// Whether it ran at all.
    pub ran: bool,
    /// Vertices, edges or faces it looked at.
    pub count: usize,
    /// Why it ran or did not, in a sentence.
    pub why: String,
}

impl CheckRun {
    /// A family that ran over `count` elements.
    pub fn ran(name: &'static str, count: usize, why: impl Into<String>) -> Self {
        CheckRun {
            name,
            ran: true,
            count,
            why: why.into(),
        }
    }

    /// A family that did not run.
    pub fn skipped(name: &'static str, why: impl Into<String>) -> Self {
        CheckRun {
            name,
            ran: false,
            count: 0,
            why: why.into(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pattern::{Assignment, VertexId};

    fn edge(assignment: Assignment, fold_angle: Option<f64>) -> Edge {
        Edge {
            vertices: [VertexId::new(0), VertexId::new(1)],
            assignment,
            fold_angle,
        }
    }

    #[test]
    fn flat_means_plus_or_minus_180_or_no_angle() {
        assert!(folds_flat(&edge(Assignment::Mountain, None)));
        assert!(folds_flat(&edge(Assignment::Mountain, Some(-180.0))));
        assert!(folds_flat(&edge(Assignment::Valley, Some(179.8))));
        assert!(!folds_flat(&edge(Assignment::Valley, Some(165.0))));
        assert!(!folds_flat(&edge(Assignment::Mountain, Some(-90.0))));
        assert!(!folds_flat(&edge(Assignment::Unassigned, Some(0.0))));
        assert!(folds_flat(&edge(Assignment::Boundary, Some(0.0))));
    }
}
