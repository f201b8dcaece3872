//! The per-edge pass: edge lengths (shortest edge, short-edge findings) and fold angles
//! (largest |fold angle|, findings beyond the limit). One sequential sweep, no allocation
//! unless an edge fails.

use super::report::EdgeMeasure;
use super::{CheckOptions, Finding, FindingKind, Quantity};
use crate::pattern::{CreasePattern, EdgeId};

/// Results of the edge pass.
#[derive(Default)]
pub(super) struct EdgeTally {
    /// Failures found.
    pub findings: Vec<Finding>,
    /// The shortest edge (value = length).
    pub shortest: Option<EdgeMeasure>,
    /// The edge with the largest |fold angle| (value = signed angle, degrees).
    pub largest_fold: Option<EdgeMeasure>,
}

/// Runs the edge checks.
pub(super) fn check_edges(cp: &CreasePattern, opts: &CheckOptions) -> EdgeTally {
    let mut tally = EdgeTally::default();
    for (i, edge) in cp.edges.iter().enumerate() {
        let id = EdgeId::new(i);
        let (a, b) = cp.segment(id);
        let length = a.distance(b);
        let mid = a.lerp(b, 0.5);
        if tally.shortest.is_none_or(|s| length < s.value) {
            tally.shortest = Some(EdgeMeasure::new(id, mid, length));
        }
        if let Some(limit) = opts.min_edge_length
            && length < limit
        {
            tally.findings.push(short_edge(cp, id, mid, length, limit));
        }
        // A mountain or valley without a stored angle is a full fold (±180°), as in ORIPA
        // files and as the FOLD writer records it.
        let angle = edge.fold_angle.or_else(|| {
            edge.assignment
                .is_fold()
                .then(|| edge.assignment.flat_folded_angle())
                .flatten()
        });
        if let Some(angle) = angle {
            if tally
                .largest_fold
                .is_none_or(|s| angle.abs() > s.value.abs())
            {
                tally.largest_fold = Some(EdgeMeasure::new(id, mid, angle));
            }
            if let Some(limit) = opts.max_fold_angle_deg
                && angle.abs() > limit
            {
                tally.findings.push(fold_angle(id, mid, angle, limit));
            }
        }
    }
    tally
}

fn short_edge(
    cp: &CreasePattern,
    id: EdgeId,
    mid: glam::DVec2,
    length: f64,
    limit: f64,
) -> Finding {
    let [a, b] = cp.edges[id.index()].vertices;
    let assignment = cp.edges[id.index()].assignment.name();
    let unit = cp.units.label();
    Finding {
        kind: FindingKind::ShortEdge,
        vertex: None,
        edge: Some(id),
        position: mid,
        value: length,
        limit,
        quantity: Quantity::Length,
        mv_counts: None,
        message: format!(
            "{assignment} edge {a}–{b} is {length:.4} {unit} long, below the limit of {limit} \
             {unit}"
        ),
        hint: format!("merge {a} and {b}, or move them at least {limit} {unit} apart"),
    }
}

fn fold_angle(id: EdgeId, mid: glam::DVec2, angle: f64, limit: f64) -> Finding {
    Finding {
        kind: FindingKind::FoldAngle,
        vertex: None,
        edge: Some(id),
        position: mid,
        value: angle.abs(),
        limit,
        quantity: Quantity::Degrees,
        mv_counts: None,
        message: format!("folds by {angle:.3}°, beyond the limit of ±{limit}°"),
        hint: format!(
            "fold to at most ±{limit}° (a shallower design or a wider relief), or use a \
             material that takes a sharper fold"
        ),
    }
}
