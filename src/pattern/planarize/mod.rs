//! Planarisation: turns any line drawing into a clean planar graph.
//!
//! Steps, each linear or `n log n` in the number of edges:
//! 1. merge vertices closer than the tolerance ([`merge`]);
//! 2. split edges where they cross or where a vertex lies on them, through a uniform edge grid
//!    ([`grid`], [`split`]), then merge again (crossings found from several pairs at one point
//!    collapse); repeated until a pass finds nothing, at most [`MAX_PASSES`] times;
//! 3. drop zero-length edges and duplicates (keeping the stronger assignment, see
//!    [`Assignment::strength`](super::Assignment::strength)), and vertices no edge uses;
//! 4. optionally trace the faces ([`super::faces`]).
//!
//! A pattern that is already clean comes out unchanged, faces and FOLD extras included. When
//! anything changes, element numbering changes: faces are recomputed or cleared, and
//! per-element FOLD arrays kept from the input are dropped (listed in the report).

mod grid;
mod merge;
mod split;

use glam::DVec2;
use rayon::prelude::*;

use super::faces::find_faces;
use super::{Assignment, CreasePattern, Edge, VertexId};
pub use split::MAX_PAIR_TESTS;
use split::{Seg, find_splits, pieces};

/// Most split-and-merge passes made; a pass after the first is needed only where snapping a
/// crossing to a merged vertex creates a new touch, which converges at once in practice.
pub const MAX_PASSES: usize = 4;

/// Default tolerance relative to the bounding-box diagonal.
pub const RELATIVE_TOLERANCE: f64 = 1e-7;

/// Options of [`planarize`].
#[derive(Clone, Debug, PartialEq, Default)]
pub struct PlanarizeOptions {
    /// Vertices closer than this merge, and a vertex this close to an edge splits it, in the
    /// pattern's unit; `None` picks [`RELATIVE_TOLERANCE`] × the bounding-box diagonal.
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
    /// Vertices that no edge used, removed.
    pub isolated_removed: usize,
    /// Edges split (each split adds one piece).
    pub splits: usize,
    /// New vertices made at crossings.
    pub crossings: usize,
    /// Zero-length edges removed.
    pub zero_length_removed: usize,
    /// Duplicate edges removed (the stronger assignment kept).
    pub duplicates_removed: usize,
    /// Duplicates where a mountain and a valley coincide (equally strong: the first kept).
    pub assignment_conflicts: usize,
    /// Per-element FOLD arrays dropped because elements were renumbered.
    pub dropped_keys: Vec<String>,
}

impl PlanarizeReport {
    /// True when the pattern was already clean.
    pub fn unchanged(&self) -> bool {
        self.merged_vertices
            + self.isolated_removed
            + self.splits
            + self.zero_length_removed
            + self.duplicates_removed
            == 0
    }
}

/// Why a drawing could not be planarised.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum PlanarizeError {
    /// The drawing has so many edges lying on top of or across each other that cleaning it
    /// would take too long or too much memory (limits: [`MAX_PAIR_TESTS`] pair tests,
    /// [`MAX_SPLITS_PER_EDGE`] splits per edge).
    #[error(
        "the drawing is too tangled to clean: {edges} edges with too many overlaps or crossings \
         (more than the limits of {} edge-pair tests or {MAX_SPLITS_PER_EDGE} splits per edge)",
        MAX_PAIR_TESTS
    )]
    TooComplex {
        /// Edges at the time the limit was hit.
        edges: usize,
    },
    /// The merge tolerance is too large for the pattern (see [`crate::limits::check_tolerance`]).
    #[error(transparent)]
    Tolerance(#[from] crate::limits::LimitError),
}

/// Most splits per edge on average (plus a million) before planarisation gives up: a real
/// crease pattern has a handful; only piles of overlapping lines have more.
pub const MAX_SPLITS_PER_EDGE: usize = 16;

/// Turns `cp` into a clean planar graph (see the module docs). `cp` must be valid
/// ([`CreasePattern::validate`]). On error `cp` is left partly cleaned but valid.
///
/// ```
/// use foldcam::pattern::{Assignment, CreasePattern, PlanarizeOptions, planarize};
/// use glam::DVec2;
///
/// // Two strokes crossing in an X, as a drawing program writes them.
/// let mut cp = CreasePattern::new();
/// cp.add_segment(DVec2::new(0.0, 0.0), DVec2::new(10.0, 10.0), Assignment::Valley);
/// cp.add_segment(DVec2::new(0.0, 10.0), DVec2::new(10.0, 0.0), Assignment::Mountain);
/// let report = planarize(&mut cp, &PlanarizeOptions::default())?;
/// assert_eq!(report.crossings, 1);
/// assert_eq!((cp.vertices.len(), cp.edges.len()), (5, 4));
/// # Ok::<(), foldcam::pattern::PlanarizeError>(())
/// ```
pub fn planarize(
    cp: &mut CreasePattern,
    opts: &PlanarizeOptions,
) -> Result<PlanarizeReport, PlanarizeError> {
    if let Some(tol) = opts.tolerance {
        let diagonal = cp.bounds().map_or(0.0, |(lo, hi)| lo.distance(hi));
        crate::limits::check_tolerance(tol, diagonal)?;
    }
    let tol = opts.tolerance.unwrap_or_else(|| default_tolerance(cp));
    let mut report = PlanarizeReport {
        tolerance: tol,
        ..Default::default()
    };
    merge_vertices(cp, tol, &mut report);
    // Exact duplicates first, so piles of identical lines cost nothing in the crossing search.
    remove_duplicates(cp, &mut report);
    for _ in 0..MAX_PASSES {
        if !split_pass(cp, tol, &mut report)? {
            break;
        }
        merge_vertices(cp, tol, &mut report);
        remove_zero_length(cp, &mut report);
    }
    remove_zero_length(cp, &mut report);
    remove_duplicates(cp, &mut report);
    remove_unused_vertices(cp, &mut report);
    if !report.unchanged() {
        cp.faces = None;
        cp.face_orders.clear();
        report.dropped_keys = cp.meta.drop_per_element_extras();
    }
    if opts.faces && (cp.faces.is_none() || !report.unchanged()) {
        cp.faces = Some(find_faces(cp).faces);
    }
    Ok(report)
}

/// [`RELATIVE_TOLERANCE`] of the bounding-box diagonal (at least 1e-12).
pub fn default_tolerance(cp: &CreasePattern) -> f64 {
    let diag = cp.bounds().map_or(0.0, |(lo, hi)| lo.distance(hi));
    (diag * RELATIVE_TOLERANCE).max(crate::limits::MIN_TOLERANCE)
}

fn merge_vertices(cp: &mut CreasePattern, tol: f64, report: &mut PlanarizeReport) {
    let (rep, merged) = merge::merge_close(&cp.vertices, tol);
    if merged == 0 {
        return;
    }
    report.merged_vertices += merged;
    for e in &mut cp.edges {
        for v in &mut e.vertices {
            *v = VertexId(rep[v.index()]);
        }
    }
    let before = cp.vertices.len();
    remove_unused_vertices(cp, report);
    // Vertices removed here were merged, not isolated: do not count them twice.
    report.isolated_removed -= (before - cp.vertices.len()).min(report.isolated_removed);
}

/// One search for crossings and touches; returns whether any edge was split.
fn split_pass(
    cp: &mut CreasePattern,
    tol: f64,
    report: &mut PlanarizeReport,
) -> Result<bool, PlanarizeError> {
    let segs: Vec<Seg> = cp
        .edges
        .iter()
        .map(|e| {
            let v = [e.vertices[0].0, e.vertices[1].0];
            Seg {
                v,
                p: [cp.vertices[v[0] as usize], cp.vertices[v[1] as usize]],
            }
        })
        .collect();
    let too_complex = PlanarizeError::TooComplex {
        edges: cp.edges.len(),
    };
    let max_splits = MAX_SPLITS_PER_EDGE * segs.len() + 1_000_000;
    let splits = find_splits(&segs, tol, max_splits).ok_or(too_complex)?;
    if splits.touches.is_empty() && splits.crossings.is_empty() {
        return Ok(false);
    }
    let mut cuts: Vec<(u32, u32, DVec2)> = splits
        .touches
        .iter()
        .map(|&(e, v)| (e, v, cp.vertices[v as usize]))
        .collect();
    for &(e1, e2, x) in &splits.crossings {
        let v = cp.add_vertex(x).0;
        cuts.push((e1, v, x));
        cuts.push((e2, v, x));
    }
    report.crossings += splits.crossings.len();
    report.splits += cuts.len();
    cuts.sort_unstable_by_key(|c| c.0);
    let mut edges = Vec::with_capacity(cp.edges.len() + cuts.len());
    let mut k = 0;
    for (i, edge) in cp.edges.iter().enumerate() {
        let start = k;
        while k < cuts.len() && cuts[k].0 as usize == i {
            k += 1;
        }
        if start == k {
            edges.push(edge.clone());
            continue;
        }
        let mut here: Vec<(u32, DVec2)> = cuts[start..k].iter().map(|c| (c.1, c.2)).collect();
        for [a, b] in pieces(&segs[i], &mut here) {
            edges.push(Edge {
                vertices: [VertexId(a), VertexId(b)],
                ..edge.clone()
            });
        }
    }
    cp.edges = edges;
    Ok(true)
}

fn remove_zero_length(cp: &mut CreasePattern, report: &mut PlanarizeReport) {
    let before = cp.edges.len();
    cp.edges.retain(|e| e.vertices[0] != e.vertices[1]);
    report.zero_length_removed += before - cp.edges.len();
}

/// Keeps one edge per vertex pair: the strongest assignment, the first among equals; the
/// survivors keep their original order and orientation.
fn remove_duplicates(cp: &mut CreasePattern, report: &mut PlanarizeReport) {
    // Sort (vertex pair, edge) keys once, then scan runs of equal pairs.
    let mut order: Vec<(u64, u32)> = cp
        .edges
        .par_iter()
        .enumerate()
        .map(|(i, e)| {
            let [a, b] = e.vertices;
            let key = ((a.0.min(b.0) as u64) << 32) | a.0.max(b.0) as u64;
            (key, i as u32)
        })
        .collect();
    order.par_sort_unstable();
    let mut keep = vec![false; cp.edges.len()];
    for run in order.chunk_by(|x, y| x.0 == y.0) {
        let has = |k| {
            run.iter()
                .any(|&(_, i)| cp.edges[i as usize].assignment == k)
        };
        if run.len() > 1 && has(Assignment::Mountain) && has(Assignment::Valley) {
            report.assignment_conflicts += 1;
        }
        let best = run
            .iter()
            .map(|&(_, i)| i as usize)
            .reduce(|best, i| {
                let (sb, si) = (
                    cp.edges[best].assignment.strength(),
                    cp.edges[i].assignment.strength(),
                );
                if si > sb { i } else { best }
            })
            .unwrap_or_default();
        keep[best] = true;
    }
    let before = cp.edges.len();
    let mut i = 0;
    cp.edges.retain(|_| {
        i += 1;
        keep[i - 1]
    });
    report.duplicates_removed += before - cp.edges.len();
}

/// Drops vertices no edge uses, renumbering the rest in their original order.
fn remove_unused_vertices(cp: &mut CreasePattern, report: &mut PlanarizeReport) {
    let mut used = vec![false; cp.vertices.len()];
    for e in &cp.edges {
        used[e.vertices[0].index()] = true;
        used[e.vertices[1].index()] = true;
    }
    if used.iter().all(|&u| u) {
        return;
    }
    let mut new_index = vec![u32::MAX; cp.vertices.len()];
    let mut vertices = Vec::with_capacity(cp.vertices.len());
    for (i, &p) in cp.vertices.iter().enumerate() {
        if used[i] {
            new_index[i] = vertices.len() as u32;
            vertices.push(p);
        }
    }
    report.isolated_removed += cp.vertices.len() - vertices.len();
    cp.vertices = vertices;
    for e in &mut cp.edges {
        for v in &mut e.vertices {
            *v = VertexId(new_index[v.index()]);
        }
    }
}
