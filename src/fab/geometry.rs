//! The toolpaths of a pattern before ordering: the geometry of the fabrication plan.
//!
//! Steps, each in its own module:
//! 1. [`operations`](super::operations): the operation of every edge from the mapping;
//! 2. [`contours`](super::contours): edges cut through become closed contours (outer
//!    boundaries and holes, nested) and open slits;
//! 3. [`kerf`](super::kerf): closed contours are offset by `kerf/2` toward the scrap, without
//!    sides shorter than the machine's resolution and without bevels within half of it (a
//!    short round join becomes the corner of its neighbours: [`merge_short_sides`]);
//! 4. [`tabs`](super::tabs): holding tabs split outer contours, lead-ins start every closed
//!    ring from the scrap side;
//! 5. [`lines`](super::lines): perforated creases become dashes laid out per crease with
//!    vertex clearances ([`perforation`](super::perforation)); scores, marks and pen lines
//!    become polylines.
//!
//! All coordinates are the pattern's millimetres (x right, y up); the plan places them on the
//! bed and orders them. Closed contours come first in the returned list, in the order of
//! [`cut_lines`], so that `container` indices index that list. Every nested contour carries
//! its direct container: a hole its part, and an island (an outer contour inside a hole) its
//! hole — in both cases the contained path must be cut before its container.
//!
//! Closed contour strokes are closed polylines (last point equals first). A lead-in adds one
//! point in front: the stroke then runs lead-in start → ring start → … → ring start.

use glam::DVec2;

use super::contours::{Contour, cut_lines};
use super::kerf::offset_ring;
use super::lines::{LineContext, edge_names, line_toolpaths};
use super::operations::edge_operations;
use super::tabs::{add_lead_in, merge_straight_runs, split_at_tabs, start_on_longest_side};
use super::{
    ContourRole, FabError, Operation, PlanOptions, PlanWarning, PlanWarningKind, Toolpath,
};
use crate::geom::polygon::{merge_short_sides, signed_area};
use crate::pattern::CreasePattern;
use crate::pattern::vertex_fan::VertexFans;

/// Every toolpath of `cp` in pattern coordinates (mm), unordered: perforation dashes laid out
/// per crease with vertex clearances, scores and marks as polylines, cut contours chained,
/// kerf-offset, with tabs and lead-ins. Warnings are dropped; see
/// [`toolpaths_with_warnings`].
pub fn toolpaths(cp: &CreasePattern, opts: &PlanOptions) -> Result<Vec<Toolpath>, FabError> {
    toolpaths_with_warnings(cp, opts).map(|(paths, _)| paths)
}

/// [`toolpaths`] with its remarks: creases too short for a dash, holes too small for kerf
/// compensation, contours without room for a tab.
///
/// # Errors
/// A unitless pattern, options that are not finite and non-negative (a zero perforation
/// period, tab width or spacing), or a pattern with no edge mapped to an operation.
pub fn toolpaths_with_warnings(
    cp: &CreasePattern,
    opts: &PlanOptions,
) -> Result<(Vec<Toolpath>, Vec<PlanWarning>), FabError> {
    cp.require_millimetres()?;
    check_options(opts)?;
    let ops = edge_operations(cp, &opts.mapping);
    if ops.iter().all(Option::is_none) {
        return Err(FabError::NothingToDo);
    }
    let mut warnings = Vec::new();
    let mut paths = cut_toolpaths(cp, &ops, opts, &mut warnings);
    let fans = VertexFans::new(cp);
    let ctx = LineContext::new(cp, &fans, &ops);
    paths.extend(line_toolpaths(&ctx, opts, &mut warnings));
    Ok((paths, warnings))
}

/// Rejects option values the geometry cannot use.
fn check_options(opts: &PlanOptions) -> Result<(), FabError> {
    let p = &opts.perforation;
    let mut checks = vec![
        ("kerf", opts.kerf_mm, false),
        ("perforation cut length", p.cut_mm, true),
        ("perforation bridge", p.bridge_mm, false),
        ("perforation minimum dash", p.min_dash_mm, false),
        ("perforation minimum web", p.min_web_mm, false),
        ("perforation vertex clearance", p.vertex_clearance_mm, false),
    ];
    if let Some(t) = opts.tabs {
        checks.push(("tab width", t.width_mm, true));
        checks.push(("tab spacing", t.spacing_mm, true));
    }
    if let Some(l) = opts.lead_in_mm {
        checks.push(("lead-in length", l, false));
    }
    for (name, value, positive) in checks {
        let ok = value.is_finite() && value >= 0.0 && (!positive || value > 0.0);
        if !ok {
            let expected = if positive {
                "a positive"
            } else {
                "a non-negative"
            };
            return Err(FabError::Geometry {
                step: "options",
                message: format!("{name} is {value} mm; expected {expected} finite length"),
            });
        }
    }
    Ok(())
}

/// The cut toolpaths: closed contours (offset, tabbed, with lead-ins) then slits.
fn cut_toolpaths(
    cp: &CreasePattern,
    ops: &[Option<Operation>],
    opts: &PlanOptions,
    warnings: &mut Vec<PlanWarning>,
) -> Vec<Toolpath> {
    let lines = cut_lines(cp, ops);
    let mut out: Vec<Toolpath> = lines
        .contours
        .iter()
        .map(|c| contour_path(c, opts, warnings))
        .collect();
    out.extend(lines.slits.iter().map(|chain| Toolpath {
        op: Operation::Cut,
        strokes: vec![chain.points(cp)],
        role: ContourRole::Slit,
        container: None,
        edges: chain.edges.clone(),
    }));
    out
}

/// One closed contour as a toolpath.
fn contour_path(c: &Contour, opts: &PlanOptions, warnings: &mut Vec<PlanWarning>) -> Toolpath {
    let mut strokes = Vec::new();
    for (ring, scrap_inside) in kerf_rings(c, opts, warnings) {
        let ring = merge_straight_runs(&ring);
        let mut ring_strokes =
            tabbed(c, &ring, opts, warnings).unwrap_or_else(|| vec![start_on_longest_side(&ring)]);
        if let (Some(length), Some(first)) = (opts.lead_in_mm, ring_strokes.first_mut()) {
            add_lead_in(first, &ring, scrap_inside, length);
        }
        strokes.extend(ring_strokes);
    }
    Toolpath {
        op: Operation::Cut,
        strokes,
        role: c.role,
        container: c.container,
        edges: c.edges.clone(),
    }
}

/// The contour offset toward the scrap, or as drawn when offsetting is off or would
/// consume a hole (with a warning); each ring with whether the scrap is inside it. An offset
/// ring that runs clockwise bounds a pocket of the offset region (an outer contour whose
/// mouth closed up when grown): its scrap side is the other one.
fn kerf_rings(
    c: &Contour,
    opts: &PlanOptions,
    warnings: &mut Vec<PlanWarning>,
) -> Vec<(Vec<DVec2>, bool)> {
    let hole = c.role == ContourRole::Hole;
    let half = opts.kerf_mm / 2.0;
    if !opts.kerf_offset || half == 0.0 {
        return vec![(c.ring.clone(), hole)];
    }
    let distance = if c.role == ContourRole::Hole {
        -half
    } else {
        half
    };
    let rings = offset_ring(&c.ring, distance);
    if rings.is_empty() {
        warnings.push(PlanWarningKind::HoleBelowKerf.says(format!(
            "hole {} is smaller than the kerf ({:.3} mm): cut on the drawn line without kerf \
             compensation, so it comes out up to {:.3} mm larger",
            edge_names(&c.edges),
            opts.kerf_mm,
            opts.kerf_mm
        ))
        .on(c.edges.iter().copied()));
        return vec![(c.ring.clone(), hole)];
    }
    rings
        .into_iter()
        .map(|r| merge_short_sides(&r, opts.resolution_mm, opts.resolution_mm / 2.0))
        .map(|r| {
            let pocket = signed_area(r.iter().copied()) < 0.0;
            (r, hole != pocket)
        })
        .collect()
}

/// The ring split at holding tabs, for outer contours when tabs are asked for; `None` when
/// it stays whole. Tabs keep a tab width (or the kerf, if wider) from every corner.
fn tabbed(
    c: &Contour,
    ring: &[DVec2],
    opts: &PlanOptions,
    warnings: &mut Vec<PlanWarning>,
) -> Option<Vec<Vec<DVec2>>> {
    let tabs = opts.tabs.filter(|_| c.role == ContourRole::Outer)?;
    let margin = tabs.width_mm.max(opts.kerf_mm);
    let strokes = split_at_tabs(ring, &tabs, margin);
    if strokes.is_none() {
        warnings.push(
            PlanWarningKind::NoRoomForTab
                .says(format!(
                    "contour {} has no straight side long enough for a {:.2} mm tab: left untabbed",
                    edge_names(&c.edges),
                    tabs.width_mm
                ))
                .on(c.edges.iter().copied()),
        );
    }
    strokes
}
