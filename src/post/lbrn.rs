//! LightBurn project (`.lbrn2`): one layer (`CutSetting`) per operation carrying the
//! material's speed, power and passes — and one per settings override of the plan (the cells
//! of a calibration grid, see [`super::layers`]) carrying its own — and the job's lines as
//! `Path` shapes.
//!
//! Format facts followed (the condensed `.lbrn2` form, `FormatVersion="1"`, compared with
//! projects saved by LightBurn 1.4.03 and 2.0.02): the root `LightBurnProject` with
//! `AppVersion` and `FormatVersion`; each layer a `<CutSetting type="Cut">` whose settings are
//! child elements with a `Value` attribute: `index` (the colour layer, 0–29), `name`,
//! `minPower`/`maxPower` (per cent), `speed` (mm/s), `numPasses`, `priority` (the layer
//! order), `runBlower` (air assist), and for LightBurn's perforation mode `perforate` (1 on),
//! `perfLen` (cut length, mm) and `perfSkip` (skip length, mm). Shapes are
//! `<Shape Type="Path" CutIndex="n" VertID="k" PrimID="k">` with an identity
//! `<XForm>1 0 0 1 0 0</XForm>`, a `<VertList>` of vertices written as LightBurn writes a
//! corner without Bézier handles, `Vx yc0x1c1x1` (the `c0x1`/`c1x1` flags say "no control
//! point"), and a `<PrimList>` of lines `La b`, or `LineClosed` for a closed polyline. The
//! `VertID`/`PrimID` attributes name the shape's lists (LightBurn lets shapes with the same ids
//! share one list); every shape here has its own, numbered from 0 in file order. Coordinates
//! are millimetres with y up from the bed's front-left corner.
//!
//! # Perforations
//! [`LbrnPerforation::Dashes`] (the default) writes every dash foldcam fitted as a shape of
//! its own on a perforate layer with LightBurn's perforation mode off: LightBurn burns exactly
//! the dashes `simulate` checked.
//!
//! [`LbrnPerforation::LightBurn`] hands the dashes to LightBurn's perforation mode, which
//! lays cut (`perfLen`), skip (`perfSkip`), cut, … from the start of each path to its end.
//! Each perforated crease is written as one path from the start of its first dash to the end of
//! its last through every point of every dash (a bridge is the straight chord between two
//! dashes), so the path is `n·dash + (n − 1)·gap` long and LightBurn lays the same dashes from
//! either end. Creases are fitted one by one (each its own period), so the layer is split into
//! one `CutSetting` per distinct dash/gap pair, each with the layer's speed, power and passes:
//! a crease joins an existing pair when that pair lays every one of its dashes within
//! [`PERFORATION_TOLERANCE_MM`] of foldcam's, and a new pair is added otherwise. Where a crease's
//! dashes are not evenly spaced as LightBurn measures them (a bridge across a corner of a
//! polyline crease), its path is split into runs that are, each run starting at a dash. A
//! project holds 30 colour layers; a plan needing more pairs is refused
//! ([`PostError::TooManyDashPatterns`]).

use std::fmt::Write as _;

use glam::DVec2;

use super::PostError;
use super::layers::{Layer, layers};
use super::number::fixed;
use crate::fab::{FabPlan, Operation, Setup};
use crate::machine::MachineProfile;

/// The LightBurn version whose project format is written.
pub const LIGHTBURN_APP_VERSION: &str = "1.7.08";
/// Decimals of coordinates and settings.
const DECIMALS: usize = 4;
/// Decimals of `perfLen` and `perfSkip`: finer than coordinates, so that the pattern's
/// rounding does not add up over a long crease (1 nm × 1,000 dashes = 1 µm).
const PERF_DECIMALS: usize = 6;
/// Most layers in a project: LightBurn's colour layers 00–29.
pub const MAX_LAYERS: usize = 30;
/// Largest distance, mm, between a dash end as LightBurn's perforation mode lays it (from the
/// written path and its layer's `perfLen`/`perfSkip`) and the dash end foldcam fitted. Creases
/// whose periods differ by less than this over their length share a layer: Origami
/// Simulator's `HexSpiralTess` at 120 mm needs 47 layers at 0.005 mm, 25 at 0.02 mm.
pub const PERFORATION_TOLERANCE_MM: f64 = 0.02;

/// A dash/gap pair for LightBurn's perforation mode, `(perfLen, perfSkip)`, mm.
type Pair = (f64, f64);
/// A run of a crease's dashes written as one path: `(first dash, last dash)`, indices.
type Run = (usize, usize);

/// How a LightBurn project draws perforated creases.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LbrnPerforation {
    /// Every dash is a shape of its own; LightBurn's perforation mode stays off.
    #[default]
    Dashes,
    /// Each crease is one path on a layer with LightBurn's perforation mode on, one layer per
    /// distinct dash/gap pair (see the module docs).
    LightBurn,
}

/// One `CutSetting` to write: a layer of the job, with a dash/gap pair for LightBurn's
/// perforation mode.
struct Setting<'a> {
    layer: &'a Layer,
    /// `(perfLen, perfSkip)`, mm, already rounded to [`PERF_DECIMALS`].
    perforation: Option<(f64, f64)>,
    /// The layer has more than one pair: the name says which.
    split: bool,
}

/// The LightBurn project of `job` on `machine`, perforations drawn as `perforation` says.
pub fn write(
    plan: &FabPlan,
    job: &Setup,
    machine: &MachineProfile,
    perforation: LbrnPerforation,
) -> Result<String, PostError> {
    let to_drawing = machine.bed.to_machine().inverse();
    let layers = layers(plan, job);
    if layers.len() > MAX_LAYERS {
        return Err(PostError::TooManyLayers {
            job: job.name.clone(),
            layers: layers.len(),
            limit: MAX_LAYERS,
        });
    }
    let lightburn = perforation == LbrnPerforation::LightBurn;
    // The dash/gap pairs of each layer (LightBurn's perforation mode only) and every shape:
    // (layer, pair, points), in job order.
    let mut pairs: Vec<Vec<(f64, f64)>> = vec![Vec::new(); layers.len()];
    let mut shapes: Vec<(usize, usize, Vec<DVec2>)> = Vec::new();
    for path in &job.paths {
        let Some(i) = super::layers::layer_of(&layers, plan, path) else {
            continue;
        };
        let lines: Vec<Vec<DVec2>> = path
            .strokes
            .iter()
            .filter_map(|s| drawn(s, |p| to_drawing.transform_point2(p)))
            .collect();
        if !(lightburn && path.op == Operation::Perforate) {
            shapes.extend(lines.into_iter().map(|line| (i, 0, line)));
            continue;
        }
        let Some((pair, runs)) = fit_crease(&lines, &pairs[i]) else {
            continue;
        };
        let k = match pairs[i].iter().position(|&q| q == pair) {
            Some(k) => k,
            None => {
                pairs[i].push(pair);
                pairs[i].len() - 1
            }
        };
        for (a, b) in runs {
            let mut points: Vec<DVec2> = lines[a..=b].iter().flatten().copied().collect();
            points.dedup();
            shapes.push((i, k, points));
        }
    }
    if shapes.is_empty() {
        return Err(PostError::EmptyJob {
            job: job.name.clone(),
        });
    }
    let mut settings: Vec<Setting> = Vec::new();
    let mut first = Vec::with_capacity(layers.len());
    for (l, layer_pairs) in layers.iter().zip(&pairs) {
        first.push(settings.len());
        if layer_pairs.is_empty() {
            settings.push(Setting {
                layer: l,
                perforation: None,
                split: false,
            });
        }
        let split = layer_pairs.len() > 1;
        settings.extend(layer_pairs.iter().map(|&pair| Setting {
            layer: l,
            perforation: Some(pair),
            split,
        }));
    }
    if settings.len() > MAX_LAYERS {
        return Err(PostError::TooManyDashPatterns {
            job: job.name.clone(),
            layers: settings.len(),
            limit: MAX_LAYERS,
        });
    }
    let mut out = String::new();
    let _ = writeln!(out, r#"<?xml version="1.0" encoding="UTF-8"?>"#);
    let _ = writeln!(
        out,
        r#"<LightBurnProject AppVersion="{LIGHTBURN_APP_VERSION}" FormatVersion="1" MaterialHeight="0" MirrorX="False" MirrorY="False">"#
    );
    for (index, s) in settings.iter().enumerate() {
        cut_setting(&mut out, plan, machine, s, index);
    }
    for (id, (i, k, points)) in shapes.iter().enumerate() {
        shape(&mut out, first[*i] + k, id, points);
    }
    out.push_str("</LightBurnProject>\n");
    Ok(out)
}

/// `stroke` mapped by `to` and rounded to the written decimals, repeats dropped; `None` when
/// it has no length.
fn drawn(stroke: &[DVec2], to: impl Fn(DVec2) -> DVec2) -> Option<Vec<DVec2>> {
    let scale = 10f64.powi(DECIMALS as i32);
    let mut points: Vec<DVec2> = stroke
        .iter()
        .map(|&p| {
            let q = to(p);
            DVec2::new((q.x * scale).round() / scale, (q.y * scale).round() / scale)
        })
        .collect();
    points.dedup();
    (points.len() >= 2).then_some(points)
}

/// Length of a polyline, mm.
fn length(points: &[DVec2]) -> f64 {
    points.windows(2).map(|w| w[0].distance(w[1])).sum()
}

/// The median of `values` (not empty).
fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

/// `value` rounded to [`PERF_DECIMALS`].
fn perf_round(value: f64) -> f64 {
    let scale = 10f64.powi(PERF_DECIMALS as i32);
    (value * scale).round() / scale
}

/// The dash/gap pair for one perforated crease (its `dashes` as drawn, in order) and the runs
/// `(first dash, last dash)` its paths cover: the first of `pairs` that lays the dashes
/// within [`PERFORATION_TOLERANCE_MM`] in no more runs than the crease's own pair (median
/// dash, median gap), else that own pair. `None` for a crease without dashes.
fn fit_crease(dashes: &[Vec<DVec2>], pairs: &[(f64, f64)]) -> Option<(Pair, Vec<Run>)> {
    if dashes.is_empty() {
        return None;
    }
    let lengths: Vec<f64> = dashes.iter().map(|d| length(d)).collect();
    let gaps: Vec<f64> = dashes
        .windows(2)
        .map(|w| w[0][w[0].len() - 1].distance(w[1][0]))
        .collect();
    let own_dash = perf_round(median(&mut lengths.clone()));
    let own_gap = if gaps.is_empty() {
        own_dash
    } else {
        perf_round(median(&mut gaps.clone()))
    };
    let own = (own_dash, own_gap.max(10f64.powi(-(PERF_DECIMALS as i32))));
    let own_runs = runs(&lengths, &gaps, own);
    if !fits(&lengths, &gaps, own, &own_runs) {
        // Dashes of unequal lengths (not laid by foldcam's layout): the longest as the cut and
        // every dash a path of its own, cut to the path's end.
        let longest = perf_round(lengths.iter().copied().fold(0.0, f64::max));
        return Some((
            (longest, own.1),
            (0..lengths.len()).map(|j| (j, j)).collect(),
        ));
    }
    for &pair in pairs {
        let r = runs(&lengths, &gaps, pair);
        if r.len() <= own_runs.len() && fits(&lengths, &gaps, pair, &r) {
            return Some((pair, r));
        }
    }
    Some((own, own_runs))
}

/// Whether every run of `runs` is laid within tolerance by `pair` (see [`runs`]).
fn fits(lengths: &[f64], gaps: &[f64], pair: (f64, f64), runs: &[(usize, usize)]) -> bool {
    runs.iter()
        .all(|&(a, b)| (a..=b).all(|j| laid(lengths, gaps, pair, a, j, j == b)))
}

/// Whether LightBurn's perforation of `pair`, laid from the start of dash `a`, cuts dash `j`
/// where foldcam fitted it: its start within tolerance, and its end too — or, for the last
/// dash of a path (`last`), anywhere up to the pattern's dash end, where LightBurn stops at the
/// path's end.
fn laid(
    lengths: &[f64],
    gaps: &[f64],
    (dash, gap): (f64, f64),
    a: usize,
    j: usize,
    last: bool,
) -> bool {
    let start: f64 = (a..j).map(|i| lengths[i] + gaps[i]).sum();
    let want = (j - a) as f64 * (dash + gap);
    let end = start + lengths[j];
    let tol = PERFORATION_TOLERANCE_MM;
    (start - want).abs() <= tol
        && if last {
            end <= want + dash + tol
        } else {
            (end - (want + dash)).abs() <= tol
        }
}

/// The runs `(first dash, last dash)` into which `pair` splits a crease of dash `lengths` and
/// `gaps` (as LightBurn measures them): each run as long as the pattern laid from its first
/// dash stays within tolerance. A dash no run can hold (longer than the pattern's dash) is a
/// run of its own that does not fit; [`fits`] tells.
fn runs(lengths: &[f64], gaps: &[f64], pair: (f64, f64)) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut a = 0;
    while a < lengths.len() {
        let mut b = a;
        loop {
            if b + 1 < lengths.len()
                && laid(lengths, gaps, pair, a, b, false)
                && laid(lengths, gaps, pair, a, b + 1, true)
            {
                b += 1;
                continue;
            }
            break;
        }
        out.push((a, b));
        a = b + 1;
    }
    out
}

/// The `CutSetting` `s` as layer number `index`.
fn cut_setting(
    out: &mut String,
    plan: &FabPlan,
    machine: &MachineProfile,
    s: &Setting,
    index: usize,
) {
    let l = s.layer;
    let op = l.op;
    let v = l.settings(plan, Some(machine));
    let speed_mm_s = v.speed_mm_min.min(machine.max_feed_mm_min) / 60.0;
    let power = fixed(v.power.clamp(0.0, 1.0) * 100.0, DECIMALS);
    let value = |out: &mut String, key: &str, v: &str| {
        let _ = writeln!(out, r#"    <{key} Value="{v}"/>"#);
    };
    let name = match (s.perforation, s.split) {
        (Some((dash, gap)), true) => format!("{} {}/{} mm", l.name, fixed(dash, 3), fixed(gap, 3)),
        _ => l.name.clone(),
    };
    out.push_str("  <CutSetting type=\"Cut\">\n");
    value(out, "index", &index.to_string());
    value(out, "name", &crate::formats::svg::write::escape(&name));
    value(out, "minPower", &power);
    value(out, "maxPower", &power);
    value(out, "speed", &fixed(speed_mm_s, DECIMALS));
    value(out, "numPasses", &v.passes.to_string());
    value(out, "priority", &index.to_string());
    value(
        out,
        "runBlower",
        if machine.air_for(op) { "1" } else { "0" },
    );
    if let Some((dash, gap)) = s.perforation {
        value(out, "perforate", "1");
        value(out, "perfLen", &fixed(dash, PERF_DECIMALS));
        value(out, "perfSkip", &fixed(gap, PERF_DECIMALS));
    }
    out.push_str("  </CutSetting>\n");
}

/// One `Path` shape of `points` (at least two, no repeats) on layer `index`, its lists
/// numbered `id`.
fn shape(out: &mut String, index: usize, id: usize, points: &[DVec2]) {
    let mut pts: Vec<DVec2> = points.to_vec();
    let closed = pts.len() > 3 && pts[0] == pts[pts.len() - 1];
    if closed {
        pts.pop();
    }
    let _ = writeln!(
        out,
        r#"  <Shape Type="Path" CutIndex="{index}" VertID="{id}" PrimID="{id}">"#
    );
    out.push_str("    <XForm>1 0 0 1 0 0</XForm>\n    <VertList>");
    for p in &pts {
        let _ = write!(
            out,
            "V{} {}c0x1c1x1",
            fixed(p.x, DECIMALS),
            fixed(p.y, DECIMALS)
        );
    }
    out.push_str("</VertList>\n    <PrimList>");
    if closed {
        out.push_str("LineClosed");
    } else {
        for i in 0..pts.len() - 1 {
            let _ = write!(out, "L{} {}", i, i + 1);
        }
    }
    out.push_str("</PrimList>\n  </Shape>\n");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn even_dashes_are_one_run_and_a_shifted_one_starts_another() {
        let lengths = [1.0, 1.0, 1.0, 1.0];
        assert_eq!(runs(&lengths, &[0.5, 0.5, 0.5], (1.0, 0.5)), vec![(0, 3)]);
        // A bridge 0.1 mm short (the chord across a corner) moves the dashes after it.
        assert_eq!(
            runs(&lengths, &[0.5, 0.4, 0.5], (1.0, 0.5)),
            vec![(0, 1), (2, 3)]
        );
        // A pattern 0.01 mm off per period drifts out of tolerance by the third dash.
        let off = (1.0, 0.51);
        assert!(!fits(&lengths, &[0.5, 0.5, 0.5], off, &[(0, 3)]));
        // A last dash shorter than the pattern's is cut to the path's end.
        assert!(fits(&[1.0, 0.6], &[0.5], (1.0, 0.5), &[(0, 1)]));
        assert!(!fits(&[1.0, 1.2], &[0.5], (1.0, 0.5), &[(0, 1)]));
    }

    #[test]
    fn a_crease_joins_a_pair_that_lays_its_dashes_and_not_one_that_drifts() {
        let dash = |x: f64, len: f64| vec![DVec2::new(x, 0.0), DVec2::new(x + len, 0.0)];
        let crease: Vec<Vec<DVec2>> = (0..10).map(|k| dash(k as f64 * 1.5, 1.0)).collect();
        let (pair, r) = fit_crease(&crease, &[(1.0, 0.5)]).expect("dashes");
        assert_eq!((pair, r), ((1.0, 0.5), vec![(0, 9)]));
        // 0.001 mm per period is 0.009 mm over the crease: within tolerance, shared.
        let (pair, _) = fit_crease(&crease, &[(1.0, 0.501)]).expect("dashes");
        assert_eq!(pair, (1.0, 0.501));
        // 0.005 mm per period is 0.045 mm: the crease gets its own pair.
        let (pair, r) = fit_crease(&crease, &[(1.0, 0.505)]).expect("dashes");
        assert_eq!((pair, r), ((1.0, 0.5), vec![(0, 9)]), "own pair");
        assert!(fit_crease(&[], &[]).is_none());
    }
}
