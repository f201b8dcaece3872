//! The per-vertex pass: flat-foldability at interior vertices and the smallest angle between
//! neighbouring creases at every vertex, folded into a [`Tally`] so the pass can run in
//! parallel without allocating per vertex.

use std::f64::consts::TAU;

use super::applies::vertex_folds_flat;
use super::flat_foldability::{self, Maekawa, is_crease};
use super::report::VertexMeasure;
use super::{CheckOptions, Finding, FindingKind, Quantity};
use crate::geom::angle::ccw_between;
use crate::pattern::vertex_fan::{Spoke, VertexFans};
use crate::pattern::{CreasePattern, EdgeId, VertexId};

/// What every vertex needs to see.
pub(super) struct Context<'a> {
    /// The pattern.
    pub cp: &'a CreasePattern,
    /// Its fans.
    pub fans: &'a VertexFans,
    /// Interior vertices (empty when flat-foldability is not checked).
    pub interior: &'a [bool],
    /// The options.
    pub opts: &'a CheckOptions,
    /// Whether a 3D frame will judge the 3D-target vertices; without one, their Kawasaki and
    /// Maekawa faults are listed in [`Tally::faults_3d`].
    pub framed: bool,
}

/// Accumulated results of the vertex pass.
#[derive(Default)]
pub(super) struct Tally {
    /// Failures found.
    pub findings: Vec<Finding>,
    /// Interior vertices with creases that were checked.
    pub checked: usize,
    /// Interior vertices not checked for Maekawa because of an unassigned crease.
    pub maekawa_skipped: usize,
    /// Interior vertices with creases not checked for flat-foldability because a crease
    /// there folds to less than 180° (a 3D target).
    pub vertices_3d: usize,
    /// Of those, the vertices whose creases satisfy Kawasaki and Maekawa all the same (within
    /// the tolerance, every crease assigned): they fold flat, so they fold at all, and their
    /// folding counts as checked; the others fail nothing, as a 3D target need not fold flat.
    pub vertices_3d_flat: usize,
    /// Kawasaki and Maekawa faults at 3D-target vertices when no 3D frame judges them: not
    /// failures, listed so the report names the same vertices as one of a format without fold
    /// angles (which reads every crease as folding flat).
    pub faults_3d: Vec<Finding>,
    /// The narrowest crease sector seen.
    pub smallest_angle: Option<VertexMeasure>,
}

impl Tally {
    /// Adds the results of vertex `v`.
    pub fn add(mut self, ctx: &Context<'_>, v: VertexId) -> Self {
        let fan = ctx.fans.of(v);
        if ctx.interior.get(v.index()).copied().unwrap_or(false) {
            self.flat_foldability(ctx, v, fan);
        }
        if let Some(narrow) = narrowest_sector(ctx.cp, fan) {
            let degrees = narrow.angle.to_degrees();
            if self.smallest_angle.is_none_or(|m| degrees < m.degrees) {
                self.smallest_angle = Some(VertexMeasure {
                    vertex: v,
                    position: ctx.cp.position(v),
                    degrees,
                });
            }
            if let Some(limit) = ctx.opts.min_vertex_angle_deg
                && degrees < limit
            {
                self.findings
                    .push(vertex_angle_finding(ctx.cp, v, narrow, limit));
            }
        }
        self
    }

    fn flat_foldability(&mut self, ctx: &Context<'_>, v: VertexId, fan: &[Spoke]) {
        let degree = fan.iter().filter(|s| is_crease(ctx.cp, s)).count();
        if degree == 0 {
            return;
        }
        let tol = ctx.opts.kawasaki_tolerance_deg;
        if !vertex_folds_flat(ctx.cp, fan) {
            self.vertices_3d += 1;
            if flat_foldability::creases_fold_flat(ctx.cp, fan, tol) {
                self.vertices_3d_flat += 1;
            } else if !ctx.framed {
                let (faults, _) = flat_foldability_faults(ctx.cp, v, fan, degree, tol);
                self.faults_3d.extend(faults);
            }
            return;
        }
        self.checked += 1;
        let (faults, maekawa_skipped) = flat_foldability_faults(ctx.cp, v, fan, degree, tol);
        self.findings.extend(faults);
        self.maekawa_skipped += usize::from(maekawa_skipped);
    }

    /// Combines two tallies (order-preserving: `self` came first).
    pub fn merge(mut self, other: Self) -> Self {
        self.findings.extend(other.findings);
        self.checked += other.checked;
        self.maekawa_skipped += other.maekawa_skipped;
        self.vertices_3d += other.vertices_3d;
        self.vertices_3d_flat += other.vertices_3d_flat;
        self.faults_3d.extend(other.faults_3d);
        self.smallest_angle = match (self.smallest_angle, other.smallest_angle) {
            (Some(a), Some(b)) => Some(if b.degrees < a.degrees { b } else { a }),
            (a, b) => a.or(b),
        };
        self
    }
}

/// Kawasaki's condition at `v`, then Maekawa's at an even crease `degree`: the findings, and
/// whether Maekawa was skipped for an unassigned crease.
fn flat_foldability_faults(
    cp: &CreasePattern,
    v: VertexId,
    fan: &[Spoke],
    degree: usize,
    tolerance_deg: f64,
) -> (Vec<Finding>, bool) {
    let mut found: Vec<Finding> = flat_foldability::kawasaki(cp, v, fan, tolerance_deg)
        .into_iter()
        .collect();
    if degree % 2 == 1 {
        return (found, false);
    }
    match flat_foldability::maekawa(cp, v, fan) {
        Maekawa::Pass => (found, false),
        Maekawa::Skipped => (found, true),
        Maekawa::Fail(f) => {
            found.push(*f);
            (found, false)
        }
    }
}

/// The narrowest counted sector at a vertex.
#[derive(Clone, Copy, Debug)]
struct Sector {
    /// Angle, radians.
    angle: f64,
    /// The clockwise-side spoke's edge.
    from: EdgeId,
    /// The counter-clockwise-side spoke's edge.
    to: EdgeId,
    /// A crease among the two (for highlighting).
    crease: EdgeId,
}

/// The narrowest sector between consecutive relevant spokes (creases and outlines) where at
/// least one side is a crease. Streams over the fan without allocating.
fn narrowest_sector(cp: &CreasePattern, fan: &[Spoke]) -> Option<Sector> {
    let kind = |s: &Spoke| {
        let a = cp.edges[s.edge.index()].assignment;
        if a.may_fold() {
            Some(true)
        } else if a.is_boundary_like() {
            Some(false)
        } else {
            None
        }
    };
    let mut relevant = fan.iter().filter_map(|s| kind(s).map(|c| (s, c)));
    let first = relevant.next()?;
    let mut prev = first;
    let mut best: Option<Sector> = None;
    let mut consider = |a: (&Spoke, bool), b: (&Spoke, bool), angle: f64| {
        if !(a.1 || b.1) || best.is_some_and(|s| s.angle <= angle) {
            return;
        }
        best = Some(Sector {
            angle,
            from: a.0.edge,
            to: b.0.edge,
            crease: if a.1 { a.0.edge } else { b.0.edge },
        });
    };
    let mut count = 1;
    for cur in relevant {
        consider(prev, cur, ccw_between(prev.0.angle, cur.0.angle));
        prev = cur;
        count += 1;
    }
    if count >= 2 {
        consider(prev, first, first.0.angle + TAU - prev.0.angle);
    }
    best
}

fn vertex_angle_finding(cp: &CreasePattern, v: VertexId, s: Sector, limit: f64) -> Finding {
    let deg = s.angle.to_degrees();
    Finding {
        kind: FindingKind::VertexAngle,
        vertex: Some(v),
        edge: Some(s.crease),
        position: cp.position(v),
        value: deg,
        limit,
        quantity: Quantity::Degrees,
        mv_counts: None,
        message: format!(
            "{} and {} meet at {deg:.3}°, below the limit of {limit}°",
            s.from, s.to
        ),
        hint: format!(
            "open the sector by {:.3}° (move an end of {} or {}), or merge the two lines",
            limit - deg,
            s.from,
            s.to
        ),
    }
}
