//! Holding tabs and lead-ins on closed contours.
//!
//! # Tabs
//! A contour of perimeter `P` gets `n = max(1, round(P / spacing))` gaps of `width`, aimed at
//! the arc lengths `(k + ½)·P/n`. Each gap is moved to the nearest place on a *straight run*
//! (consecutive vertices turning by less than [`STRAIGHT_SINE`] are merged first) where it
//! keeps `margin` from both corners of the run — tabs on corners tear and leave burrs. Gaps
//! that would overlap or crowd a previous one (closer than `margin`) are dropped. The ring
//! then becomes one open stroke per stretch between gaps; the gaps are exactly `width` long
//! along the path. A contour with no run long enough (`width + 2·margin`) gets no tab.
//!
//! # Lead-ins
//! A lead-in is a short entry burn ending at the first point of a stroke, perpendicular to
//! its first segment and on the scrap side, so the pierce mark lands in scrap. An untabbed
//! ring is first rotated to start at the middle of its longest straight run. Inside a hole
//! the lead-in is shortened to half the free distance across the hole along the normal, so
//! it never reaches the far side.

use glam::DVec2;

use super::Tabs;
use crate::geom::tolerance::RELATIVE;

/// Largest sine of the turn at a vertex inside one straight run (about 0.06°).
pub const STRAIGHT_SINE: f64 = 1e-3;

/// Drops repeated points and vertices where the ring goes on straight (see
/// [`STRAIGHT_SINE`]). The ring does not repeat its first point.
pub fn merge_straight_runs(ring: &[DVec2]) -> Vec<DVec2> {
    let mut pts: Vec<DVec2> = Vec::with_capacity(ring.len());
    for &p in ring {
        if pts.last() != Some(&p) {
            pts.push(p);
        }
    }
    while pts.len() > 1 && pts.first() == pts.last() {
        pts.pop();
    }
    let n = pts.len();
    if n < 4 {
        return if n >= 3 { pts } else { ring.to_vec() };
    }
    let turns = |i: usize| {
        let (a, b, c) = (pts[(i + n - 1) % n], pts[i], pts[(i + 1) % n]);
        let (u, v) = (b - a, c - b);
        u.perp_dot(v).abs() > STRAIGHT_SINE * u.length() * v.length() || u.dot(v) < 0.0
    };
    let out: Vec<DVec2> = (0..n).filter(|&i| turns(i)).map(|i| pts[i]).collect();
    if out.len() >= 3 { out } else { pts }
}

/// The ring rotated to start at the middle of its longest side (a vertex is inserted there),
/// and closed (first point repeated last).
pub fn start_on_longest_side(ring: &[DVec2]) -> Vec<DVec2> {
    let n = ring.len();
    let longest = (0..n)
        .max_by(|&i, &j| side(ring, i).total_cmp(&side(ring, j)))
        .unwrap_or(0);
    let mid = ring[longest].lerp(ring[(longest + 1) % n], 0.5);
    let mut out = Vec::with_capacity(n + 2);
    out.push(mid);
    out.extend((1..=n).map(|k| ring[(longest + k) % n]));
    out.push(mid);
    out
}

fn side(ring: &[DVec2], i: usize) -> f64 {
    ring[i].distance(ring[(i + 1) % ring.len()])
}

/// Splits a ring (not repeating its first point) at holding tabs. Returns the open strokes
/// in path order, or `None` when no straight run can hold a tab.
pub fn split_at_tabs(ring: &[DVec2], tabs: &Tabs, margin: f64) -> Option<Vec<Vec<DVec2>>> {
    let cum = cumulative(ring);
    let perimeter = *cum.last()?;
    let count = (perimeter / tabs.spacing_mm).round().clamp(1.0, 1e6) as usize;
    let mut gaps: Vec<f64> = (0..count)
        .filter_map(|k| {
            place(
                ring,
                &cum,
                (k as f64 + 0.5) * perimeter / count as f64,
                tabs.width_mm,
                margin,
            )
        })
        .collect();
    gaps.sort_by(f64::total_cmp);
    let mut kept: Vec<f64> = Vec::with_capacity(gaps.len());
    for g in gaps {
        let clear = kept
            .last()
            .is_none_or(|&last| g - last >= tabs.width_mm + margin);
        let wraps = kept
            .first()
            .is_some_and(|&first| first + perimeter - g < tabs.width_mm + margin);
        if clear && !wraps {
            kept.push(g);
        }
    }
    if kept.is_empty() {
        return None;
    }
    let half = tabs.width_mm / 2.0;
    let strokes = (0..kept.len())
        .map(|k| {
            let from = kept[k] + half;
            let mut to = kept[(k + 1) % kept.len()] - half;
            if to <= from {
                to += perimeter;
            }
            sub_path(ring, &cum, from, to)
        })
        .collect();
    Some(strokes)
}

/// Arc length at every vertex of the closed ring, the last entry being the perimeter.
fn cumulative(ring: &[DVec2]) -> Vec<f64> {
    let mut cum = Vec::with_capacity(ring.len() + 1);
    let mut s = 0.0;
    cum.push(0.0);
    for i in 0..ring.len() {
        s += side(ring, i);
        cum.push(s);
    }
    cum
}

/// The centre (arc length) of the tab nearest to `target` that fits on one side with
/// `margin` from its ends, if any side can hold it.
fn place(ring: &[DVec2], cum: &[f64], target: f64, width: f64, margin: f64) -> Option<f64> {
    let perimeter = cum[ring.len()];
    let cyclic = |a: f64, b: f64| {
        let d = (a - b).rem_euclid(perimeter);
        d.min(perimeter - d)
    };
    (0..ring.len())
        .filter_map(|i| {
            let (lo, hi) = (
                cum[i] + margin + width / 2.0,
                cum[i + 1] - margin - width / 2.0,
            );
            (lo <= hi).then(|| {
                let inside = target.clamp(lo, hi);
                let wrapped = (target + perimeter).clamp(lo, hi);
                if cyclic(inside, target) <= cyclic(wrapped, target) {
                    inside
                } else {
                    wrapped
                }
            })
        })
        .min_by(|&a, &b| cyclic(a, target).total_cmp(&cyclic(b, target)))
}

/// The path along the ring from arc length `from` to `to` (`from < to`, `to` may exceed the
/// perimeter once).
fn sub_path(ring: &[DVec2], cum: &[f64], from: f64, to: f64) -> Vec<DVec2> {
    let n = ring.len();
    let perimeter = cum[n];
    let at = |s: f64| point_at(ring, cum, s.rem_euclid(perimeter));
    let mut out = vec![at(from)];
    let first_vertex = cum.partition_point(|&c| c <= from);
    // `to − from` is at most one perimeter, so at most 2n + 1 vertices are passed.
    for k in first_vertex..first_vertex + 2 * n + 1 {
        let s = cum[k % n] + perimeter * (k / n) as f64;
        if s >= to {
            break;
        }
        out.push(ring[k % n]);
    }
    out.push(at(to));
    out
}

fn point_at(ring: &[DVec2], cum: &[f64], s: f64) -> DVec2 {
    let n = ring.len();
    let i = cum
        .partition_point(|&c| c <= s)
        .saturating_sub(1)
        .min(n - 1);
    let len = cum[i + 1] - cum[i];
    let t = if len > 0.0 { (s - cum[i]) / len } else { 0.0 };
    ring[i].lerp(ring[(i + 1) % n], t.clamp(0.0, 1.0))
}

/// Prepends a lead-in of up to `length` mm to `stroke`, perpendicular to its first segment,
/// on the outside of `ring` when `scrap_inside` is false and on its inside otherwise
/// (shortened to half the free distance across `ring` there).
pub fn add_lead_in(stroke: &mut Vec<DVec2>, ring: &[DVec2], scrap_inside: bool, length: f64) {
    let (Some(&p0), Some(&p1)) = (stroke.first(), stroke.get(1)) else {
        return;
    };
    let t = (p1 - p0).normalize_or_zero();
    let left = t.perp();
    let ccw = crate::geom::polygon::signed_area(ring.iter().copied()) >= 0.0;
    let inward = if ccw { left } else { -left };
    let normal = if scrap_inside { inward } else { -inward };
    let reach = if scrap_inside {
        length.min(0.5 * free_distance(ring, p0, normal))
    } else {
        length
    };
    if normal != DVec2::ZERO && reach > 0.0 {
        stroke.insert(0, p0 + normal * reach);
    }
}

/// Sides whose cross product with the unit direction is below this (mm) are parallel to it
/// and never hit.
const PARALLEL_DENOM: f64 = 1e-15;

/// Distance from `p` along unit `dir` to the nearest side of `ring` not through `p` (hits
/// nearer than [`RELATIVE`] mm are `p`'s own sides).
fn free_distance(ring: &[DVec2], p: DVec2, dir: DVec2) -> f64 {
    let n = ring.len();
    let mut best = f64::INFINITY;
    for i in 0..n {
        let (a, b) = (ring[i], ring[(i + 1) % n]);
        let e = b - a;
        let denom = dir.perp_dot(e);
        if denom.abs() < PARALLEL_DENOM {
            continue;
        }
        let t = (a - p).perp_dot(e) / denom;
        let u = (a - p).perp_dot(dir) / denom;
        if t > RELATIVE && (0.0..=1.0).contains(&u) {
            best = best.min(t);
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square() -> Vec<DVec2> {
        let mut r = vec![DVec2::ZERO, DVec2::new(5.0, 0.0)];
        r.extend([
            DVec2::new(10.0, 0.0),
            DVec2::new(10.0, 10.0),
            DVec2::new(0.0, 10.0),
        ]);
        r
    }

    #[test]
    fn straight_runs_merge() {
        assert_eq!(merge_straight_runs(&square()).len(), 4);
    }

    #[test]
    fn tabs_leave_gaps_of_the_width() {
        let ring = merge_straight_runs(&square());
        let tabs = Tabs {
            width_mm: 1.0,
            spacing_mm: 20.0,
        };
        let strokes = split_at_tabs(&ring, &tabs, 1.0).unwrap();
        assert_eq!(strokes.len(), 2);
        for k in 0..2 {
            let gap = strokes[k].last().unwrap().distance(strokes[(k + 1) % 2][0]);
            assert!((gap - 1.0).abs() < 1e-9);
        }
        let drawn: f64 = strokes
            .iter()
            .flat_map(|s| s.windows(2))
            .map(|w| w[0].distance(w[1]))
            .sum();
        assert!((drawn - 38.0).abs() < 1e-9);
    }

    #[test]
    fn lead_in_inside_a_hole_is_shortened() {
        let ring = start_on_longest_side(&square());
        let mut stroke = ring.clone();
        add_lead_in(&mut stroke, &square(), true, 50.0);
        assert!((stroke[0].distance(stroke[1]) - 5.0).abs() < 1e-9);
    }
}
