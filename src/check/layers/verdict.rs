//! The layer-order check as part of `check`: run after the local checks, turned into findings
//! (one per face of a contradiction) and a JSON object.

use std::fmt::Write as _;

use serde::Serialize;

use super::rounding::{KawasakiTolerance, local_faults};
use super::{LayerError, LayerOptions, LayerReport, LayerSolver};
use crate::check::{CheckReport, CheckRun, Finding, FindingKind, Quantity};
use crate::pattern::CreasePattern;

/// The outcome of the layer check: a report, or why there is none.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LayerCheck {
    /// The solver's report, when it ran.
    #[serde(flatten)]
    pub report: Option<LayerReport>,
    /// Why the solver did not run (the pattern fails a local check).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub skipped: Option<String>,
    /// Why the pattern has no folded form at all.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
    /// The findings the outcome adds to the check (listed in the report's findings too).
    #[serde(skip)]
    pub findings: Vec<Finding>,
    /// The Kawasaki tolerance the local faults were sorted with.
    pub kawasaki_tolerance: KawasakiTolerance,
    /// Kawasaki errors accepted as the drawing's rounding (listed in the check's warnings).
    pub rounding: usize,
}

impl LayerCheck {
    /// True when a valid layer order exists (false when skipped).
    pub fn passed(&self) -> bool {
        self.report.as_ref().is_some_and(LayerReport::foldable)
    }

    /// One or two lines for the text report.
    pub fn to_text(&self) -> String {
        let mut out = String::new();
        if let Some(reason) = &self.skipped {
            let _ = writeln!(out, "layer order: not checked: {reason}");
        }
        if let Some(e) = &self.error {
            let _ = writeln!(out, "layer order: {e}");
        }
        if self.rounding > 0 {
            let _ = writeln!(
                out,
                "layer order: folded with {} Kawasaki error(s) within the tolerance ({}), listed \
                 as warnings",
                self.rounding, self.kawasaki_tolerance
            );
        }
        if let Some(r) = &self.report {
            let c = &r.constraints;
            let _ = writeln!(
                out,
                "layer order: {} state(s){} in {} component(s); {} faces, {} overlapping pairs, \
                 constraints: taco-taco {} (two creases along one line), taco-tortilla {} \
                 (a crease across a face), tortilla-tortilla {} (faces sharing an overlap), \
                 transitivity {} (three faces stacked)",
                r.states,
                if r.exact {
                    ""
                } else {
                    " at least (a component reached --max-states)"
                },
                r.components,
                r.faces,
                r.variables,
                c.taco_taco,
                c.taco_tortilla,
                c.tortilla_tortilla,
                c.transitivity
            );
        }
        out
    }
}

/// Runs the layer solver on `cp` unless a local fault stops it, and appends its findings to
/// `local` (the local checks of the same pattern). Kawasaki errors within the tolerance of
/// `opts.kawasaki` ([`super::rounding`]: by default fitted to the drawing's precision) do not
/// stop it: they move from `local`'s findings to its warnings, reported beside the state count.
/// A Maekawa failure, an odd-degree vertex or a Kawasaki error beyond the tolerance stops it,
/// naming the vertex. Errors only for input it cannot judge: no faces, or a problem beyond the
/// size limits.
pub fn check_layers(
    cp: &CreasePattern,
    local: &mut CheckReport,
    opts: &LayerOptions,
) -> Result<LayerCheck, LayerError> {
    let mut out = LayerCheck {
        report: None,
        skipped: None,
        error: None,
        findings: Vec::new(),
        kawasaki_tolerance: opts.kawasaki,
        rounding: 0,
    };
    let faults = local_faults(cp, opts.kawasaki);
    if let Some(f) = faults.first_refusal() {
        let why = refusal(f);
        local.runs.push(CheckRun::skipped(LAYER_ORDER, why.clone()));
        out.skipped = Some(why);
        return Ok(out);
    }
    out.rounding = faults.rounding.len();
    accept_rounding(local, faults.rounding);
    match LayerSolver::new(cp, opts) {
        Ok(solver) => {
            let report = solver.into_report();
            if let Some(c) = &report.contradiction {
                for (f, &p) in c.faces.iter().zip(&c.positions) {
                    out.findings.push(finding(
                        p,
                        format!("face {f}: {}", c.message),
                        "change the mountain/valley assignment or the creases near these faces",
                    ));
                }
            }
            local.runs.push(CheckRun::ran(
                LAYER_ORDER,
                report.faces,
                format!(
                    "a global layer order of the faces folded flat (Flat-Folder's method): {} \
                     states",
                    report.states
                ),
            ));
            out.report = Some(report);
        }
        Err(
            e @ LayerError::NotFlat {
                vertex, position, ..
            },
        ) => {
            let mut f = finding(
                position,
                e.to_string(),
                "the creases around this vertex do not close up when folded flat",
            );
            f.vertex = Some(vertex);
            out.findings.push(f);
            local.runs.push(CheckRun::ran(
                LAYER_ORDER,
                0,
                "stopped: the creases do not fold flat",
            ));
            out.error = Some(e.to_string());
        }
        Err(e) => return Err(e),
    }
    local.findings.extend(out.findings.iter().cloned());
    Ok(out)
}

/// The name of the layer-order family in [`CheckReport::runs`].
const LAYER_ORDER: &str = "layer_order";

/// Why the layer solver did not run: the local fault that stops it, with its vertex.
pub fn refusal(f: &Finding) -> String {
    format!(
        "the pattern is not locally flat-foldable: {} at {}: {}",
        f.kind.name(),
        f.vertex.map_or_else(|| "-".to_string(), |v| v.to_string()),
        f.message
    )
}

/// Moves the Kawasaki findings of `local` at the vertices of `rounding` to its warnings
/// (taking `rounding`'s version, which carries the fitted limit), and adds those `local`
/// did not list (its tolerance may be larger than the noise floor).
fn accept_rounding(local: &mut CheckReport, rounding: Vec<Finding>) {
    if rounding.is_empty() {
        return;
    }
    let vertices: std::collections::HashSet<_> = rounding.iter().filter_map(|f| f.vertex).collect();
    local.findings.retain(|f| {
        !(f.kind == FindingKind::Kawasaki && f.vertex.is_some_and(|v| vertices.contains(&v)))
    });
    local.warnings.extend(rounding);
}

fn finding(position: glam::DVec2, message: String, hint: &str) -> Finding {
    Finding {
        kind: FindingKind::LayerOrder,
        vertex: None,
        edge: None,
        position,
        value: 0.0,
        limit: 1.0,
        quantity: Quantity::States,
        mv_counts: None,
        message,
        hint: hint.to_string(),
    }
}

/// Largest number of edges [`flat_fold_warning`] looks at (beyond it the check would slow
/// down every cutting job; run `check --layers` instead).
pub const WARNING_MAX_EDGES: usize = 20_000;

/// True when the pattern is meant to fold flat: it has mountain or valley creases and every
/// one of them is unangled or at ±180°.
pub fn meant_to_fold_flat(cp: &CreasePattern) -> bool {
    let mut any = false;
    for e in cp.edges.iter().filter(|e| e.assignment.is_fold()) {
        any = true;
        if e.fold_angle
            .is_some_and(|a| (a.abs() - 180.0).abs() > crate::geom::tolerance::ANGLE_DEG)
        {
            return false;
        }
    }
    any
}

/// For the cutting commands: a one-line warning when a pattern meant to fold flat passes the
/// local checks but has no layer order (so the cut sheet could not be folded), naming the
/// faces; `None` otherwise, also when the pattern is larger than [`WARNING_MAX_EDGES`] or the
/// solver cannot judge it.
pub fn flat_fold_warning(cp: &CreasePattern) -> Option<String> {
    if !meant_to_fold_flat(cp) || cp.edges.len() > WARNING_MAX_EDGES {
        return None;
    }
    let mut local = crate::check::check(cp, &crate::check::CheckOptions::default());
    let options = LayerOptions {
        max_states: Some(1),
        ..LayerOptions::default()
    };
    let outcome = check_layers(cp, &mut local, &options).ok()?;
    let report = outcome.report?;
    let c = report.contradiction?;
    Some(format!(
        "the pattern passes every vertex check but cannot be folded flat: {} (run `foldcam check \
         --layers` for details)",
        c.message
    ))
}
