//! Packing parts on their shapes: bottom-left fill over the parts' real outlines.
//!
//! A part's shape is its outline and its glue tabs (the outline's edges and each tab's three
//! free edges). Parts go in order of decreasing shape area. Each is tried at the angle whose
//! bounding box is smallest (the 5° search of [`super::layout`]) and that angle plus 90°,
//! 180° and 270°, and at 0°, 90°, 180° and 270°, on every open sheet in turn; on a sheet it
//! goes to the lowest position, then the leftmost, where no edge of its shape comes closer
//! than the gap to an edge of a placed shape, neither shape lies inside the other, and its
//! bounding box stays inside the margins; of the angles, the one whose top edge then lies
//! lowest wins, leftmost on ties. A part that fits on no open sheet opens a new one.
//!
//! The search is exact in x and stepped in y: for each height (steps of at most 1 mm, the
//! first feasible step refined by bisection to 1/32 of a step) every pair of nearby edges
//! forbids an open interval of x ([`crate::geom::segment::slide_interval`]), and the part
//! goes to the left end of the first free stretch in which it is not inside a placed part
//! (or one inside it). Two placed shapes are therefore never closer than the gap, measured
//! between the actual outlines and tab edges, not their boxes.

mod raster;
mod shape;
mod sheet;

use glam::DVec2;
use rayon::prelude::*;

use shape::{Shape, Turned};
use sheet::{Scratch, Sheet};

use super::PapercraftError;
use super::layout::{Placement, SheetSpec, best_angle, check_parts, usable_size};
use super::parts::Part;
use crate::geom::tolerance::{RELATIVE, ROUNDOFF};

/// Bisection rounds that refine the first feasible height step.
const REFINE: usize = 5;
/// Smallest gap used, millimetres: with no gap at all, crossing edges would go unseen.
const MIN_GAP: f64 = 1e-6;

/// The angles tried for a part whose smallest bounding box is at `best`.
fn angles(best: f64) -> Vec<f64> {
    let quarter = std::f64::consts::FRAC_PI_2;
    let mut out: Vec<f64> = Vec::with_capacity(8);
    for a in (0..4).flat_map(|k| [best + k as f64 * quarter, k as f64 * quarter]) {
        let a = a.rem_euclid(4.0 * quarter);
        let same = |b: &f64| {
            let d = (a - b).rem_euclid(4.0 * quarter);
            d < RELATIVE || 4.0 * quarter - d < RELATIVE
        };
        if !out.iter().any(same) {
            out.push(a);
        }
    }
    out
}

/// Which position of a part wins on a sheet.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Rule {
    /// The lowest top edge, then the leftmost.
    LowestTop,
    /// The lowest bottom edge, then the leftmost.
    LowestBottom,
}

/// The orders and rules tried; the packing with the fewest sheets, then the lowest sum of
/// the sheets' used heights, is kept.
const STRATEGIES: [(Order, Rule); 4] = [
    (Order::Area, Rule::LowestTop),
    (Order::Area, Rule::LowestBottom),
    (Order::Longest, Rule::LowestTop),
    (Order::Longest, Rule::LowestBottom),
];

/// In which order parts are placed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Order {
    /// Decreasing shape area.
    Area,
    /// Decreasing longest side of the smallest bounding box.
    Longest,
}

/// A part ready to place: its shape's area and its turns.
struct Ready {
    area: f64,
    longest: f64,
    turns: Vec<Turned>,
}

/// Packs `parts` on their shapes onto as many sheets as needed (see the module docs).
/// Refuses a bad spec or a part larger than the usable sheet at every angle tried. Parts
/// keep at least `spec.gap` millimetres apart (at least 1 µm), outlines and tabs included.
pub fn pack_shapes(parts: &[Part], spec: &SheetSpec) -> Result<Vec<Placement>, PapercraftError> {
    let usable = usable_size(spec)?;
    check_parts(parts)?;
    let gap = spec.gap.max(MIN_GAP) * (1.0 + RELATIVE) + ROUNDOFF;
    let cell = (usable.x.max(usable.y) / 300.0).max(0.05);
    let mut ready = Vec::with_capacity(parts.len());
    for (i, part) in parts.iter().enumerate() {
        let best = best_angle(part, usable).ok_or(PapercraftError::PartTooLarge { part: i })?;
        let shape = Shape::of(part);
        let turns: Vec<Turned> = angles(best)
            .into_iter()
            .map(|a| shape.turned(a, cell))
            .filter(|t| t.size.x <= usable.x && t.size.y <= usable.y)
            .collect();
        let longest = turns.first().map_or(0.0, |t| t.size.x.max(t.size.y));
        ready.push(Ready {
            area: shape.area,
            longest,
            turns,
        });
    }
    let runs: Vec<_> = STRATEGIES
        .par_iter()
        .map(|&(order, rule)| {
            let key = |r: &Ready| match order {
                Order::Area => r.area,
                Order::Longest => r.longest,
            };
            let mut sequence: Vec<usize> = (0..parts.len()).collect();
            sequence.sort_by(|&a, &b| key(&ready[b]).total_cmp(&key(&ready[a])));
            greedy(&ready, &sequence, rule, usable, gap, cell, spec.margin)
        })
        .collect();
    let mut best: Option<((usize, f64), Vec<Placement>)> = None;
    for run in runs {
        let (score, placements) = run?;
        if best
            .as_ref()
            .is_none_or(|(s, _)| score.0 < s.0 || (score.0 == s.0 && score.1 < s.1 - RELATIVE))
        {
            best = Some((score, placements));
        }
    }
    Ok(best.map(|b| b.1).unwrap_or_default())
}

/// One greedy packing in `sequence` order by `rule`: its score (sheets, sum of the sheets'
/// used heights) and placements.
fn greedy(
    ready: &[Ready],
    sequence: &[usize],
    rule: Rule,
    usable: DVec2,
    gap: f64,
    cell: f64,
    margin: f64,
) -> Result<((usize, f64), Vec<Placement>), PapercraftError> {
    let room = usable.x * usable.y;
    let mut sheets: Vec<Sheet> = Vec::new();
    let mut tops: Vec<f64> = Vec::new();
    let mut scratch = Scratch::default();
    let mut out = Vec::with_capacity(sequence.len());
    for &i in sequence {
        let turns = &ready[i].turns;
        let found = sheets.iter().enumerate().find_map(|(s, sheet)| {
            if sheet.area + ready[i].area > room {
                return None;
            }
            sheet
                .place(turns, rule, &mut scratch)
                .map(|(k, at)| (s, k, at))
        });
        let (s, k, at) = match found {
            Some(f) => f,
            None => {
                let sheet = Sheet::new(usable, gap, cell);
                let (k, at) = sheet
                    .place(turns, rule, &mut scratch)
                    .ok_or(PapercraftError::PartTooLarge { part: i })?;
                sheets.push(sheet);
                tops.push(0.0);
                (sheets.len() - 1, k, at)
            }
        };
        sheets[s].add(&turns[k], at);
        sheets[s].area += ready[i].area;
        tops[s] = tops[s].max(at.y + turns[k].size.y);
        out.push(Placement {
            part: i,
            sheet: s,
            angle: turns[k].angle,
            offset: DVec2::splat(margin) + at - turns[k].lo,
        });
    }
    out.sort_by_key(|p| p.part);
    Ok(((sheets.len(), tops.iter().sum()), out))
}
