//! PLACEHOLDER

use super::CreasePattern;

/// Options of [`planarize`].
#[derive(Clone, Debug, PartialEq, Default)]
pub struct PlanarizeOptions {
    /// Vertices closer than this merge, in the pattern's unit; `None` picks 1e-7 of the
    /// bounding-box diagonal.
    pub tolerance: Option<f64>,
    /// Also compute the faces of the planar graph.
    pub faces: bool,
}

/// What [`planarize`] changed.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct PlanarizeReport {
    /// The tolerance used.
    pub tolerance: f64,
    /// Vertices merged into others.
    pub merged_vertices: usize,
    /// Edge splits made at crossings and touching vertices.
    pub splits: usize,
    /// Zero-length edges removed.
    pub zero_length_removed: usize,
    /// Duplicate edges removed (the stronger assignment kept).
    pub duplicates_removed: usize,
    /// Per-element FOLD arrays dropped because elements were renumbered.
    pub dropped_keys: Vec<String>,
}

/// Turns `cp` into a clean planar graph.
pub fn planarize(_cp: &mut CreasePattern, _opts: &PlanarizeOptions) -> PlanarizeReport {
    todo!()
}
