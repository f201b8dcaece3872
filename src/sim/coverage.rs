//! Coverage: does a simulated run burn what the pattern asks, and nothing else?
//!
//! The job says which pattern edges each operation realises (`Toolpath::edges`,
//! `Toolpath::op`); `job.to_machine` places the pattern on the bed. For each such edge, in
//! machine coordinates, we measure two fractions of its length:
//!
//! - **planned**: covered by the job's own strokes of that operation (perforation dashes leave
//!   bridges and vertex clearances, cut contours leave tabs);
//! - **burned**: covered by the run's burns whose power matches the operation's setting.
//!
//! A burn covers the stretch of an edge it runs along within the tolerance band, kerf/2 plus
//! the resolution (kerf-offset contours run kerf/2 off the pattern line), and only where it
//! *follows* the edge: a burn piece more than [`CoverageOptions::max_follow_angle_deg`] off
//! the edge's direction covers nothing of it (a cut meeting a crease at a narrow angle, or a
//! straight chord across a curve, does not perforate the crease), unless the piece is shorter
//! than the resolution (G-code rounding decides its direction). An edge passes when
//! its burned fraction matches the planned one: for cuts, burned ≥ planned − (1 − min cut
//! coverage), so a 99 % rule still allows the planned tabs; for perforations, scores, marks and
//! plots, |burned − planned| ≤ the duty tolerance.
//!
//! **Edges the plan leaves out.** The plan's operation mapping says which pattern edges
//! should be machined at all; an edge it maps to an operation but that no toolpath of any job
//! of the plan realises (a crease too short for a dash, a curve whose dashes were dropped, a
//! toolpath removed by hand) is listed with `in_plan: false`, its burned share measured as
//! for any edge, and fails: a crease counts as covered only where a burn really follows it,
//! and the plan's own silence is not coverage. Each left-out edge is listed by one job of
//! the plan: in a two-sided plan the job of the side it would be machined from (valleys and
//! cuts from the back), so the front and back reports together list it once.
//!
//! **Stray burns.** Every burn is sampled every tolerance/2; a sample is explained when it lies
//! within the band of a pattern edge of an operation whose power matches the burn, or of a
//! stroke of the job (registration marks and lead-ins have no pattern edge). Unexplained
//! lengths above the tolerance are reported.
//!
//! Power matching maps `S` back to a fraction of the profile's range (`(S − min)/(max − min)`)
//! and compares it with the plan's `settings`; pen strokes (plots) match any power. Not
//! checked: the order of burns, passes counted separately (overlapping passes are a union).

use std::collections::HashSet;

use glam::DVec2;
use serde::Serialize;

use super::grid::{SegmentGrid, covered_interval, union_length};
use super::report::SimReport;
use crate::fab::operations::operation_for;
use crate::fab::sides::edge_on_back;
use crate::fab::{ContourRole, FabPlan, Operation, Setup, Side};
use crate::geom::Segment;
use crate::geom::segment::distance_to_point;
use crate::geom::tolerance::RELATIVE;
use crate::pattern::{Assignment, CreasePattern, EdgeId};
use crate::post::MIN_RESOLUTION_MM;

/// Thresholds of [`coverage_with`].
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct CoverageOptions {
    /// Kerf width, mm; `None` estimates it from the job's offset cut contours.
    pub kerf_mm: Option<f64>,
    /// Slack added to half the kerf for the tolerance band, mm.
    pub resolution_mm: f64,
    /// Least share of a cut edge's length burned (of what the plan covers).
    pub min_cut_coverage: f64,
    /// Largest difference between burned and planned share for other operations.
    pub duty_tolerance: f64,
    /// Largest difference between a burn's power fraction and its operation's.
    pub power_tolerance: f64,
    /// Largest angle, degrees, between a burn piece and an edge for the burn to cover it.
    pub max_follow_angle_deg: f64,
}

impl Default for CoverageOptions {
    fn default() -> Self {
        CoverageOptions {
            kerf_mm: None,
            resolution_mm: 0.05,
            min_cut_coverage: 0.99,
            duty_tolerance: 0.05,
            power_tolerance: 0.02,
            max_follow_angle_deg: 10.0,
        }
    }
}

/// How well one pattern edge is covered by one operation.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct EdgeCoverage {
    /// The pattern edge.
    pub edge: EdgeId,
    /// The operation the job gives it.
    pub op: Operation,
    /// Edge length, mm.
    pub length_mm: f64,
    /// Share of the length the job's strokes cover, 0..=1.
    pub planned: f64,
    /// Share of the length the run's burns cover, 0..=1.
    pub burned: f64,
    /// Whether burned matches planned (see the module docs).
    pub ok: bool,
    /// Whether a toolpath of the plan realises the edge; `false` for edges the plan's mapping
    /// gives an operation but no toolpath covers (these always fail).
    pub in_plan: bool,
}

/// A burn, or part of one, that no pattern edge or job stroke explains.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct StrayBurn {
    /// Line of the burn in the program.
    pub line: usize,
    /// Start of the burn, mm.
    pub from: DVec2,
    /// End of the burn, mm.
    pub to: DVec2,
    /// Unexplained length, mm.
    pub stray_mm: f64,
}

/// The result of a coverage check.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CoverageReport {
    /// Kerf used, mm.
    pub kerf_mm: f64,
    /// Tolerance band half-width, mm.
    pub tolerance_mm: f64,
    /// Every edge the job realises, with its coverage.
    pub edges: Vec<EdgeCoverage>,
    /// Burns nothing explains.
    pub stray: Vec<StrayBurn>,
    /// Total unexplained burn length, mm.
    pub stray_length_mm: f64,
}

impl CoverageReport {
    /// True when every edge is covered as planned and nothing stray burns.
    pub fn passed(&self) -> bool {
        self.stray.is_empty() && self.edges.iter().all(|e| e.ok)
    }

    /// The edges that are not covered as planned.
    pub fn failed_edges(&self) -> impl Iterator<Item = &EdgeCoverage> {
        self.edges.iter().filter(|e| !e.ok)
    }

    /// The edges the plan's mapping asks for but no toolpath realises.
    pub fn left_out(&self) -> impl Iterator<Item = &EdgeCoverage> {
        self.edges.iter().filter(|e| !e.in_plan)
    }
}

/// Checks `report` against `pattern` and `job` of `plan` with default thresholds.
pub fn coverage(
    report: &SimReport,
    pattern: &CreasePattern,
    job: &Setup,
    plan: &FabPlan,
) -> CoverageReport {
    coverage_with(report, pattern, job, plan, &CoverageOptions::default())
}

/// A segment in machine coordinates with its operation.
#[derive(Clone, Copy, Debug)]
struct Seg {
    a: DVec2,
    b: DVec2,
    op: Operation,
}

/// Checks `report` against `pattern` and `job` of `plan` (see the module docs).
pub fn coverage_with(
    report: &SimReport,
    pattern: &CreasePattern,
    job: &Setup,
    plan: &FabPlan,
    opts: &CoverageOptions,
) -> CoverageReport {
    let mut edges: Vec<(EdgeId, Seg, bool)> = job_edges(pattern, job)
        .into_iter()
        .map(|(e, s)| (e, s, true))
        .collect();
    edges.extend(
        left_out_edges(pattern, job, plan)
            .into_iter()
            .map(|(e, s)| (e, s, false)),
    );
    let strokes = job_strokes(job);
    let kerf_mm = opts
        .kerf_mm
        .unwrap_or_else(|| estimate_kerf(pattern, job))
        .max(0.0);
    let tol = kerf_mm / 2.0 + opts.resolution_mm.max(MIN_RESOLUTION_MM);
    let matcher = PowerMatch {
        report,
        plan,
        tol: opts.power_tolerance,
    };
    // Burns as segments; their `op` is unused (power decides what they may realise).
    let burns: Vec<Seg> = report
        .burns
        .iter()
        .map(|b| Seg {
            a: b.from,
            b: b.to,
            op: Operation::Cut,
        })
        .collect();
    let cell = cell_size(edges.iter().map(|(_, s, _)| s), &strokes, &burns, tol);
    let burn_grid = grid(&burns, cell);
    let follow = Follow {
        band: tol,
        max_sine: opts.max_follow_angle_deg.to_radians().sin(),
        short_mm: opts.resolution_mm,
    };
    let stroke_grid = grid(&strokes, cell);
    let results = edges
        .iter()
        .map(|&(id, ref s, in_plan)| {
            let planned = if in_plan {
                covered(s, &strokes, &stroke_grid, &follow, |i| {
                    strokes[i].op == s.op
                })
            } else {
                0.0
            };
            let burned = covered(s, &burns, &burn_grid, &follow, |i| matcher.fits(i, s.op));
            let length_mm = s.a.distance(s.b);
            let ok = in_plan && judge(s.op, planned, burned, opts);
            EdgeCoverage {
                edge: id,
                op: s.op,
                length_mm,
                planned,
                burned,
                ok,
                in_plan,
            }
        })
        .collect();
    let allowed: Vec<Seg> = edges.iter().map(|(_, s, _)| *s).chain(strokes).collect();
    let stray = stray_burns(report, &allowed, &matcher, tol, cell);
    let stray_length_mm = stray.iter().map(|s| s.stray_mm).sum();
    CoverageReport {
        kerf_mm,
        tolerance_mm: tol,
        edges: results,
        stray,
        stray_length_mm,
    }
}

/// Whether a burn's power fits an operation.
struct PowerMatch<'a> {
    report: &'a SimReport,
    plan: &'a FabPlan,
    tol: f64,
}

impl PowerMatch<'_> {
    fn fits(&self, burn: usize, op: Operation) -> bool {
        // A pen has no power: on a plotter every stroke may realise any operation.
        if op == Operation::Plot || self.report.dialect == crate::machine::Dialect::Plotter {
            return true;
        }
        let Some(b) = self.report.burns.get(burn) else {
            return false;
        };
        let want = self.plan.settings.get(op).power;
        (self.report.power_fraction(b.power) - want).abs() <= self.tol
    }
}

fn judge(op: Operation, planned: f64, burned: f64, opts: &CoverageOptions) -> bool {
    match op {
        Operation::Cut => burned + RELATIVE >= planned - (1.0 - opts.min_cut_coverage),
        _ => (burned - planned).abs() <= opts.duty_tolerance,
    }
}

/// The pattern edges of the job's toolpaths, with their operation, in machine coordinates.
fn job_edges(pattern: &CreasePattern, job: &Setup) -> Vec<(EdgeId, Seg)> {
    let mut out: Vec<(EdgeId, Seg)> = Vec::new();
    let mut seen: HashSet<(EdgeId, Operation)> = HashSet::new();
    for tp in &job.paths {
        for &e in &tp.edges {
            if !seen.insert((e, tp.op)) {
                continue;
            }
            if let Some(Segment { a, b }) = edge_segment(pattern, e) {
                let (a, b) = (
                    job.to_machine.transform_point2(a),
                    job.to_machine.transform_point2(b),
                );
                out.push((e, Seg { a, b, op: tp.op }));
            }
        }
    }
    out
}

/// Whether `job` is the one job of `plan` that reports a left-out edge of `assignment` and
/// `op`: the first job on the side the edge would be machined from (the two-sided rule of
/// [`crate::fab::sides::edge_on_back`]), or the first job when the plan has none on that side
/// (a one-sided plan). A job outside the plan's list (a caller's own) reports it too.
fn reports_left_out(plan: &FabPlan, job: &Setup, assignment: Assignment, op: Operation) -> bool {
    let side = if edge_on_back(assignment, op) {
        Side::Back
    } else {
        Side::Front
    };
    let owner = plan
        .jobs
        .iter()
        .find(|j| j.side == side)
        .or(plan.jobs.first());
    owner.is_none_or(|o| o.name == job.name) || !plan.jobs.iter().any(|j| j.name == job.name)
}

/// The pattern edges the plan's mapping gives an operation but that no toolpath of any job
/// realises with that operation, in `job`'s machine coordinates; each is reported by one job
/// only ([`reports_left_out`]), so a two-sided plan lists it once, on the side it belongs to.
fn left_out_edges(pattern: &CreasePattern, job: &Setup, plan: &FabPlan) -> Vec<(EdgeId, Seg)> {
    let realised: HashSet<(EdgeId, Operation)> = plan
        .jobs
        .iter()
        .chain(std::iter::once(job))
        .flat_map(|j| j.paths.iter())
        .flat_map(|tp| tp.edges.iter().map(move |&e| (e, tp.op)))
        .collect();
    pattern
        .edge_ids()
        .filter_map(|e| {
            let assignment = pattern.edges[e.index()].assignment;
            let op = operation_for(assignment, &plan.mapping)?;
            if realised.contains(&(e, op)) || !reports_left_out(plan, job, assignment, op) {
                return None;
            }
            let Segment { a, b } = edge_segment(pattern, e)?;
            let (a, b) = (
                job.to_machine.transform_point2(a),
                job.to_machine.transform_point2(b),
            );
            Some((e, Seg { a, b, op }))
        })
        .collect()
}

fn edge_segment(pattern: &CreasePattern, e: EdgeId) -> Option<Segment> {
    let edge = pattern.edges.get(e.index())?;
    let a = *pattern.vertices.get(edge.vertices[0].index())?;
    let b = *pattern.vertices.get(edge.vertices[1].index())?;
    Some(Segment::new(a, b))
}

/// Every straight piece of the job's strokes.
fn job_strokes(job: &Setup) -> Vec<Seg> {
    job.paths
        .iter()
        .flat_map(|tp| {
            tp.strokes.iter().flat_map(move |s| {
                s.windows(2).map(move |w| Seg {
                    a: w[0],
                    b: w[1],
                    op: tp.op,
                })
            })
        })
        .collect()
}

/// Twice the median distance from the midpoints of the pieces of offset cut contours to their
/// pattern edges (the median ignores lead-ins and corner pieces); 0 without offset contours.
fn estimate_kerf(pattern: &CreasePattern, job: &Setup) -> f64 {
    let mut d: Vec<f64> = Vec::new();
    for tp in job
        .paths
        .iter()
        .filter(|t| matches!(t.role, ContourRole::Outer | ContourRole::Hole))
    {
        let segs: Vec<Segment> = tp
            .edges
            .iter()
            .filter_map(|&e| edge_segment(pattern, e))
            .map(|s| {
                Segment::new(
                    job.to_machine.transform_point2(s.a),
                    job.to_machine.transform_point2(s.b),
                )
            })
            .collect();
        let mids = tp
            .strokes
            .iter()
            .flat_map(|s| s.windows(2).map(|w| (w[0] + w[1]) / 2.0));
        for p in mids {
            let near = segs
                .iter()
                .map(|s| s.distance_to_point(p))
                .fold(f64::INFINITY, f64::min);
            if near.is_finite() {
                d.push(near);
            }
        }
    }
    if d.is_empty() {
        return 0.0;
    }
    d.sort_by(f64::total_cmp);
    (2.0 * d[d.len() / 2]).min(10.0)
}

/// Grid cells at least four tolerances wide and at most 1024 across the whole extent.
fn cell_size<'a>(
    edges: impl Iterator<Item = &'a Seg>,
    strokes: &'a [Seg],
    burns: &'a [Seg],
    tol: f64,
) -> f64 {
    let points = edges.chain(strokes).chain(burns).flat_map(|s| [s.a, s.b]);
    let (lo, hi) = points.fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(lo, hi), p| {
        (lo.min(p), hi.max(p))
    });
    let extent = (hi - lo).max_element();
    let by_extent = if extent.is_finite() {
        extent / 1024.0
    } else {
        0.0
    };
    (4.0 * tol).max(by_extent)
}

fn grid(segs: &[Seg], cell: f64) -> SegmentGrid {
    let mut g = SegmentGrid::new(cell);
    for (i, s) in segs.iter().enumerate() {
        g.insert(i as u32, s.a, s.b);
    }
    g
}

/// When a burn piece counts as running along an edge (see the module docs).
struct Follow {
    /// Half-width of the band around the edge, mm.
    band: f64,
    /// Largest sine of the angle between piece and edge.
    max_sine: f64,
    /// Pieces shorter than this count whatever their direction, mm.
    short_mm: f64,
}

impl Follow {
    /// Whether `piece` runs along `edge`, whose length is `edge_len` (known to the caller).
    fn along(&self, edge: &Seg, edge_len: f64, piece: &Seg) -> bool {
        let (e, p) = (edge.b - edge.a, piece.b - piece.a);
        let piece_len = p.length();
        piece_len < self.short_mm || e.perp_dot(p).abs() <= self.max_sine * edge_len * piece_len
    }
}

/// Share of `edge` covered by the segments of `by` (those in `grid` near the edge) that `keep`
/// accepts and that follow the edge.
fn covered(
    edge: &Seg,
    by: &[Seg],
    grid: &SegmentGrid,
    follow: &Follow,
    keep: impl Fn(usize) -> bool,
) -> f64 {
    let tol = follow.band;
    let len = edge.a.distance(edge.b);
    if len <= 0.0 {
        return 1.0;
    }
    let intervals = grid
        .near_segment(edge.a, edge.b)
        .iter()
        .map(|&i| i as usize)
        .filter(|&i| keep(i))
        .filter_map(|i| by.get(i))
        .filter(|s| follow.along(edge, len, s))
        .filter_map(|s| covered_interval(edge.a, edge.b, s.a, s.b, tol))
        .collect();
    (union_length(intervals) / len).min(1.0)
}

/// Burns with parts farther than `tol` from every allowed segment of a matching operation.
fn stray_burns(
    report: &SimReport,
    allowed: &[Seg],
    matcher: &PowerMatch,
    tol: f64,
    cell: f64,
) -> Vec<StrayBurn> {
    let g = grid(allowed, cell);
    let mut out = Vec::new();
    for (i, b) in report.burns.iter().enumerate() {
        let len = b.length();
        let n = (len / (tol / 2.0)).ceil().clamp(1.0, 10_000.0) as usize;
        let unexplained = (0..=n)
            .map(|k| b.from.lerp(b.to, k as f64 / n as f64))
            .filter(|&p| {
                !g.near_point(p).iter().any(|&j| {
                    let s = allowed[j as usize];
                    matcher.fits(i, s.op) && distance_to_point(s.a, s.b, p) <= tol
                })
            })
            .count();
        let stray_mm = len * unexplained as f64 / (n + 1) as f64;
        if stray_mm > tol {
            out.push(StrayBurn {
                line: b.line,
                from: b.from,
                to: b.to,
                stray_mm,
            });
        }
    }
    out
}
