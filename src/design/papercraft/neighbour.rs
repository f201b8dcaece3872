//! Automatic neighbouring patches (Ōgaki 2016, §3.5): a new patch P_new that meets already trimmed
//! patches P_exist along their shared boundary walls without a gap.
//!
//! The thesis's three steps, and what this module does for each:
//!
//! 1. **A plane** (point o, unit normal m) is placed; P_new's directrix lies on it and its
//!    rulings run along m ([`Plane`]).
//! 2. **P_exist and a boundary wall** are chosen: the wall of a cut line e that lies between
//!    P_exist and P_new in the network ([`NeighbourSpec::from`]).
//! 3. **Sweeping the real boundary**: the real boundary of P_exist on e's wall is sampled
//!    (the thesis casts rays from P_exist's directrix along its rulings to the wall; we take
//!    the same curve rib by rib, where P_exist crosses the wall's ribs, see [`super::trim`]),
//!    each point x is swept along m onto the plane, `y = x − ((x − o)·m) m`, and a degree-4
//!    B-spline is fitted to the y's by least squares ([`super::fit`]). It is P_new's
//!    directrix. Every x lies on the cylinder over y with rulings m, so P_new contains
//!    P_exist's real boundary on e up to the fit's error and crosses e's wall ribs where
//!    P_exist does.
//!
//! The number of control points may be given (the thesis lets the user choose any); by
//! default it grows from 5 (by half again each time, at most a third of the points) until
//! every swept point is within a tenth of the design tolerance of the curve, or until a
//! larger count no longer brings the largest distance below 0.8 of the last one (the runs
//! of several P_exist disagree, see below).
//!
//! The thesis's stated limits (§5.2.1), and what we do about them:
//!
//! - *P_new too short to be trimmed by its other walls*: the thesis suggests adding curve
//!   data at both ends of the swept boundary. We add points on the end tangents of the swept
//!   points, [`NeighbourSpec::extend`] beyond each end: the swept points are fitted once
//!   alone, then again with points on that curve's end tangents, weighted 1e-3 against the
//!   boundary's 1 so that they steer the curve's ends without pulling it off the boundary.
//! - *P_new meeting more than one existing patch*: [`NeighbourSpec::from`] may list several
//!   (P_exist, wall) pairs. All their swept points go into one least-squares fit, so P_new
//!   meets each as closely as one cylinder with rulings m can; where the boundaries are not
//!   on one common cylinder the residual spreads over them and [`Neighbour::fit_residual`]
//!   says how far. Parameters: the first pair's points by chord length; every other point
//!   by its closest point on the first run's polyline extended along its end tangents (so
//!   further runs must overlap the first one seen along m, as the two sides of a gore that
//!   closes a ring do, or continue it roughly straight), then improved by parameter
//!   correction.

use glam::DVec3;

use super::PapercraftError;
use super::cylinder::CylinderPatch;
use super::fit::fit_directrix;
use super::network::Network;
use super::trim::rib_crossing;
use super::walls::Walls;
use crate::geom::tolerance::TINY;
use crate::mesh::ReferenceMesh;

/// Parameter-correction rounds per fit.
const CORRECTIONS: usize = 4;
/// Most control points the automatic choice tries.
const MAX_CONTROL: usize = 120;
/// The automatic choice stops at a fit residual of this fraction of the tolerance …
const TARGET: f64 = 0.1;
/// … or when a larger count does not bring the residual below this fraction of the last.
const STALL: f64 = 0.8;
/// Weight of the extension points against the swept boundary's (1): they only steer the
/// curve beyond the ends, and must not pull it off the boundary near the corners.
const EXTENSION_WEIGHT: f64 = 1e-3;

/// The plane of §3.5 Step 1 (mesh units).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    /// A point on it.
    pub point: DVec3,
    /// Its normal: P_new's ruling direction (any non-zero length).
    pub normal: DVec3,
}

/// What the user chose for one automatic patch.
#[derive(Clone, Debug, PartialEq)]
pub struct NeighbourSpec {
    /// Step 1: the plane.
    pub plane: Plane,
    /// Step 2: `(P_exist, cut line)` pairs; the cut line lies between P_exist and P_new.
    pub from: Vec<(usize, usize)>,
    /// Control points of the fitted directrix (≥ 5), or `None` to choose by the tolerance.
    pub control_points: Option<usize>,
    /// How far the swept boundary is extended at each end before fitting (mesh units, ≥ 0).
    pub extend: f64,
    /// Real-boundary samples per cut-line segment (≥ 2).
    pub samples: usize,
}

/// A generated patch.
#[derive(Clone, Debug)]
pub struct Neighbour {
    /// The cylinder: fitted directrix on the plane, rulings along its normal.
    pub patch: CylinderPatch,
    /// Control points used.
    pub control_points: usize,
    /// Largest distance from a swept boundary point to the directrix (mesh units).
    pub fit_residual: f64,
}

/// Generates patch `p_new` of `network` from `spec`; `existing(q)` is patch q if it is
/// already built. `tolerance` (mesh units, > 0) sets the automatic control-point count.
pub fn neighbour_patch<'a>(
    mesh: &ReferenceMesh,
    network: &Network,
    walls: &Walls,
    existing: impl Fn(usize) -> Option<&'a CylinderPatch>,
    p_new: usize,
    spec: &NeighbourSpec,
    tolerance: f64,
) -> Result<Neighbour, PapercraftError> {
    let fail = |message: String| PapercraftError::BadLoop {
        patch: p_new,
        message,
    };
    let m = spec
        .plane
        .normal
        .try_normalize()
        .filter(|_| spec.plane.point.is_finite())
        .ok_or_else(|| fail("the plane needs a finite point and a non-zero normal".into()))?;
    if spec.from.is_empty() || !(spec.extend.is_finite() && spec.extend >= 0.0) {
        return Err(fail(
            "an automatic patch needs at least one (patch, cut line) to grow from and a \
             finite extension ≥ 0"
                .into(),
        ));
    }
    if !(tolerance.is_finite() && tolerance > 0.0) || spec.samples < 2 {
        return Err(fail("tolerance must be > 0 and samples ≥ 2".into()));
    }
    let o = spec.plane.point;
    let sweep = |x: DVec3| x - (x - o).dot(m) * m; // onto the plane along m
    let mut runs = Vec::with_capacity(spec.from.len());
    for &(q, e) in &spec.from {
        let h_new = shared_side(network, q, e, p_new).map_err(fail)?;
        let patch = existing(q).ok_or_else(|| {
            fail(format!(
                "patch {q} must be built before this one to grow from it"
            ))
        })?;
        let run = boundary_run(mesh, walls, patch, q, e, Network::is_reversed(h_new), spec)?;
        runs.push(run.into_iter().map(sweep).collect::<Vec<_>>());
    }
    let (points, params) = parametrise(&runs);
    let data = points.len();
    let counts: Vec<usize> = match spec.control_points {
        Some(n) => vec![n],
        None => {
            let most = (data / 3).clamp(5, MAX_CONTROL);
            std::iter::successors(Some(5usize), |&n| Some(n + (n / 2).max(1)))
                .take_while(|&n| n <= most)
                .collect()
        }
    };
    let mut best: Option<(super::fit::Fit, usize, f64)> = None;
    for &n in &counts {
        let fit = fit_extended(&points, &params, n, spec.extend)?;
        let residual = fit.distances[..data]
            .iter()
            .fold(0.0, |a: f64, &d| a.max(d));
        let previous = best.as_ref().map_or(f64::INFINITY, |b| b.2);
        if residual > STALL * previous {
            break; // more control points no longer help: the runs disagree
        }
        best = Some((fit, n, residual));
        if residual <= TARGET * tolerance {
            break;
        }
    }
    let (fit, control_points, fit_residual) =
        best.ok_or_else(|| fail("no control-point count to try".into()))?;
    let control = fit.curve.control().iter().map(|&c| sweep(c)).collect();
    let directrix = super::bspline::BSpline::directrix(control, "automatic directrix")?;
    Ok(Neighbour {
        patch: CylinderPatch::new(directrix, m)?,
        control_points,
        fit_residual,
    })
}

/// P_new's half-edge on cut line `e`, which must lie between patches `q` and `p_new`.
fn shared_side(network: &Network, q: usize, e: usize, p_new: usize) -> Result<usize, String> {
    let hs = network.half_edges();
    if 2 * e + 1 >= hs.len() {
        return Err(format!("cut line {e} does not exist"));
    }
    let (a, b) = (hs[2 * e].patch, hs[2 * e + 1].patch);
    match (a, b) {
        _ if q == p_new => Err(format!("patch {q} cannot grow from itself")),
        (Some(x), Some(y)) if x == q && y == p_new => Ok(2 * e + 1),
        (Some(x), Some(y)) if x == p_new && y == q => Ok(2 * e),
        _ => Err(format!(
            "cut line {e} does not lie between patch {q} and this patch"
        )),
    }
}

/// Where `patch` (patch `q`) crosses the ribs of cut line `e`'s wall, `samples` per segment,
/// in the direction of P_new's half-edge.
fn boundary_run(
    mesh: &ReferenceMesh,
    walls: &Walls,
    patch: &CylinderPatch,
    q: usize,
    e: usize,
    reversed: bool,
    spec: &NeighbourSpec,
) -> Result<Vec<DVec3>, PapercraftError> {
    let n = walls.segments(e) as f64;
    let count = walls.segments(e) * spec.samples;
    (0..=count)
        .map(|k| {
            let f = k as f64 / count as f64;
            let s = if reversed { n * (1.0 - f) } else { n * f };
            let (inner, outer) = walls.rib(mesh, e, s);
            rib_crossing(patch, inner, outer)
                .map(|(_, x)| x)
                .ok_or(PapercraftError::MissesWall {
                    patch: q,
                    line: e,
                    s,
                })
        })
        .collect()
}

/// All runs' points with initial parameters (see the module docs).
fn parametrise(runs: &[Vec<DVec3>]) -> (Vec<DVec3>, Vec<f64>) {
    let first = &runs[0];
    let mut cumulative = vec![0.0];
    for w in first.windows(2) {
        cumulative.push(cumulative[cumulative.len() - 1] + w[0].distance(w[1]));
    }
    let (t0, t1) = end_tangents(first);
    let length = cumulative[cumulative.len() - 1];
    let locate = |y: DVec3| -> f64 {
        // Closest point on the polyline, or on the tangent lines beyond its ends.
        let mut best = (f64::INFINITY, 0.0);
        let mut consider = |d: f64, t: f64| {
            if d < best.0 {
                best = (d, t)
            }
        };
        let before = (y - first[0]).dot(t0).min(0.0);
        consider(y.distance(first[0] + before * t0), before);
        let last = first[first.len() - 1];
        let after = (y - last).dot(t1).max(0.0);
        consider(y.distance(last + after * t1), length + after);
        for (i, w) in first.windows(2).enumerate() {
            let ab = w[1] - w[0];
            let f = if ab.length_squared() > 0.0 {
                ((y - w[0]).dot(ab) / ab.length_squared()).clamp(0.0, 1.0)
            } else {
                0.0
            };
            consider(y.distance(w[0] + f * ab), cumulative[i] + f * ab.length());
        }
        best.1
    };
    let mut points = first.clone();
    let mut params = cumulative.clone();
    for run in &runs[1..] {
        for &y in run {
            points.push(y);
            params.push(locate(y));
        }
    }
    (points, params)
}

/// Unit tangents at the start and end of a run (chords over its first and last twentieth).
fn end_tangents(run: &[DVec3]) -> (DVec3, DVec3) {
    let k = (run.len() / 20).max(1).min(run.len() - 1);
    let n = run.len() - 1;
    (
        (run[k] - run[0]).normalize_or_zero(),
        (run[n] - run[n - k]).normalize_or_zero(),
    )
}

/// Fits `n` control points to the swept points alone, then again with points appended on
/// that curve's end tangents, `extend` beyond its ends and spaced like the data (§5.2.1's
/// first limit), weighted [`EXTENSION_WEIGHT`].
fn fit_extended(
    points: &[DVec3],
    params: &[f64],
    n: usize,
    extend: f64,
) -> Result<super::fit::Fit, PapercraftError> {
    let ones = vec![1.0; points.len()];
    let bare = fit_directrix(points, params, &ones, n, CORRECTIONS)?;
    if extend <= 0.0 {
        return Ok(bare);
    }
    let curve = &bare.curve;
    let d = curve.derivative();
    let end = curve.spans() as f64;
    let (lo, hi) = params
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &t| {
            (a.min(t), b.max(t))
        });
    let length: f64 = (0..64)
        .map(|k| {
            curve
                .at(end * k as f64 / 64.0)
                .distance(curve.at(end * (k + 1) as f64 / 64.0))
        })
        .sum();
    // Parameters per unit length, to continue the data's parameters beyond the ends.
    let rate = (hi - lo) / length.max(TINY);
    let steps = ((extend / (length / points.len() as f64)).ceil() as usize).clamp(1, points.len());
    let (mut all, mut t, mut w) = (points.to_vec(), params.to_vec(), ones);
    let ends = [
        (curve.at(0.0), -d.at(0.0).normalize_or_zero(), lo, -rate),
        (curve.at(end), d.at(end).normalize_or_zero(), hi, rate),
    ];
    for (p, dir, t0, sign) in ends {
        for k in 1..=steps {
            let s = extend * k as f64 / steps as f64;
            all.push(p + s * dir);
            t.push(t0 + sign * s);
            w.push(EXTENSION_WEIGHT);
        }
    }
    fit_directrix(&all, &t, &w, n, CORRECTIONS)
}

/// The largest distance between where patches `a` and `b` cross the ribs of cut line `e`'s
/// wall, over `count + 1` ribs evenly spaced in the cut-line parameter (mesh units); `None`
/// if either misses a rib. Two patches meet without a gap on e when this is ~0.
pub fn boundary_gap(
    mesh: &ReferenceMesh,
    walls: &Walls,
    e: usize,
    a: &CylinderPatch,
    b: &CylinderPatch,
    count: usize,
) -> Option<f64> {
    let n = walls.segments(e) as f64;
    let count = count.max(1);
    (0..=count).try_fold(0.0, |worst: f64, k| {
        let (inner, outer) = walls.rib(mesh, e, n * k as f64 / count as f64);
        let (_, x) = rib_crossing(a, inner, outer)?;
        let (_, y) = rib_crossing(b, inner, outer)?;
        Some(worst.max(x.distance(y)))
    })
}
