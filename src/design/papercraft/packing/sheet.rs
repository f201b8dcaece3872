//! One sheet being filled: the placed shapes' edges, rings and raster, and the search for
//! the position of the next part.

use glam::DVec2;

use super::raster::Occupancy;
use super::shape::Turned;
use super::{REFINE, Rule};
use crate::design::papercraft::layout::bounds;
use crate::geom::polygon::contains_point;
use crate::geom::segment::slide_interval;
use crate::geom::tolerance::RELATIVE;

/// Smallest vertical step of the placement scan, in mm (the step is the sheet height / 300,
/// at least this and at most 1 mm).
const MIN_STEP_MM: f64 = 1e-3;

/// What is placed on one sheet, in usable-area coordinates (origin at the margin corner).
pub(super) struct Sheet {
    size: DVec2,
    gap: f64,
    row: f64,
    edges: Vec<[DVec2; 2]>,
    /// Edge indices by row of height `row`, each edge in every row its y range touches.
    rows: Vec<Vec<u32>>,
    /// Placed rings with their bounding boxes.
    rings: Vec<(DVec2, DVec2, Vec<DVec2>)>,
    /// Grid points ruled out for any part point.
    occupancy: Occupancy,
    pub(super) area: f64,
}

/// Reused buffers for one search.
#[derive(Default)]
pub(super) struct Scratch {
    intervals: Vec<(f64, f64)>,
    blocked: Vec<(i64, i64)>,
    cover: Vec<i32>,
    stamp: Vec<u32>,
    query: u32,
}

impl Sheet {
    pub(super) fn new(size: DVec2, gap: f64, cell: f64) -> Sheet {
        let row = gap.max(2.0);
        let count = (size.y / row).ceil().max(1.0) as usize;
        Sheet {
            size,
            gap,
            row,
            edges: Vec::new(),
            rows: vec![Vec::new(); count],
            rings: Vec::new(),
            occupancy: Occupancy::new(size, cell),
            area: 0.0,
        }
    }

    fn rows_of(&self, y0: f64, y1: f64) -> std::ops::RangeInclusive<usize> {
        let last = self.rows.len() - 1;
        let at = |y: f64| ((y / self.row).floor().max(0.0) as usize).min(last);
        at(y0)..=at(y1)
    }

    pub(super) fn add(&mut self, shape: &Turned, at: DVec2) {
        let placed: Vec<[DVec2; 2]> = shape.edges.iter().map(|e| [e[0] + at, e[1] + at]).collect();
        let rings: Vec<Vec<DVec2>> = shape
            .rings
            .iter()
            .map(|r| r.iter().map(|&p| p + at).collect())
            .collect();
        self.occupancy.mark(&placed, &rings, self.gap);
        for [a, b] in placed {
            let id = self.edges.len() as u32;
            for r in self.rows_of(a.y.min(b.y), a.y.max(b.y)) {
                self.rows[r].push(id);
            }
            self.edges.push([a, b]);
        }
        for ring in rings {
            let (lo, hi) = bounds(ring.iter().copied());
            self.rings.push((lo, hi, ring));
        }
    }

    /// The leftmost x at which `shape`, its box bottom at height `y`, keeps the gap to every
    /// placed shape and is not inside one (nor one inside it).
    fn leftmost(&self, shape: &Turned, y: f64, scratch: &mut Scratch) -> Option<f64> {
        let x_max = self.size.x - shape.size.x;
        if x_max < 0.0 || y + shape.size.y > self.size.y + RELATIVE {
            return None;
        }
        let g = self.gap;
        let (free_lo, free_hi) = self.free_window(shape, y, x_max, scratch)?;
        scratch.intervals.clear();
        scratch.stamp.resize(self.edges.len(), 0);
        let lift = DVec2::new(0.0, y);
        for e in &shape.edges {
            let (a0, a1) = (e[0] + lift, e[1] + lift);
            let (y0, y1) = (a0.y.min(a1.y) - g, a0.y.max(a1.y) + g);
            scratch.query = scratch.query.wrapping_add(1);
            if scratch.query == 0 {
                scratch.stamp.iter_mut().for_each(|s| *s = 0);
                scratch.query = 1;
            }
            for r in self.rows_of(y0, y1) {
                for &b in &self.rows[r] {
                    let seen = &mut scratch.stamp[b as usize];
                    if *seen == scratch.query {
                        continue;
                    }
                    *seen = scratch.query;
                    let [b0, b1] = self.edges[b as usize];
                    if b0.y.max(b1.y) <= y0 || b0.y.min(b1.y) >= y1 {
                        continue;
                    }
                    // The interval lies within these bounds; skip it if they miss the window.
                    let reach_lo = b0.x.min(b1.x) - a0.x.max(a1.x) - g;
                    let reach_hi = b0.x.max(b1.x) - a0.x.min(a1.x) + g;
                    if reach_hi <= free_lo || reach_lo >= free_hi {
                        continue;
                    }
                    if let Some(iv) = slide_interval(a0, a1, b0, b1, g) {
                        scratch.intervals.push(iv);
                    }
                }
            }
        }
        let cell = self.occupancy.cell();
        let blocked = scratch
            .blocked
            .iter()
            .map(|&(c0, c1)| ((c0 - 1) as f64 * cell, c1 as f64 * cell));
        scratch.intervals.extend(blocked);
        let iv = &mut scratch.intervals;
        iv.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
        let mut cur = 0.0f64;
        let mut i = 0;
        loop {
            while i < iv.len() && iv[i].0 < cur {
                cur = cur.max(iv[i].1);
                i += 1;
            }
            // Edges starting at or beyond free_hi were skipped above: stop there.
            if cur > free_hi {
                return None;
            }
            if !self.nested(shape, DVec2::new(cur, y)) {
                return Some(cur);
            }
            // The whole free stretch is nested (no edge comes near within it): skip it.
            let next = iv.get(i)?;
            cur = cur.max(next.1);
            i += 1;
        }
    }

    /// The raster filter at height `y`: `None` when every x in `[0, x_max]` is ruled out,
    /// else the smallest and largest x it leaves. The ruled-out ranges of `⌈x/cell⌉` within
    /// `[0, ⌈x_max/cell⌉]` are left, merged and sorted, in `scratch.blocked`.
    fn free_window(
        &self,
        shape: &Turned,
        y: f64,
        x_max: f64,
        scratch: &mut Scratch,
    ) -> Option<(f64, f64)> {
        let cell = self.occupancy.cell();
        let last = (x_max / cell).ceil() as i64;
        let blocked = &mut scratch.blocked;
        blocked.clear();
        self.occupancy.blocked(&shape.solid, y, blocked);
        // Count the blocking ranges over every column of [0, last].
        let cover = &mut scratch.cover;
        cover.clear();
        cover.resize(last as usize + 2, 0);
        for &(c0, c1) in blocked.iter() {
            if c1 >= 0 && c0 <= last {
                cover[c0.max(0) as usize] += 1;
                cover[(c1.min(last) + 1) as usize] -= 1;
            }
        }
        blocked.clear();
        let (mut first, mut end) = (None, 0);
        let mut count = 0;
        for c in 0..=last {
            count += cover[c as usize];
            if count > 0 {
                match blocked.last_mut() {
                    Some(b) if b.1 + 1 == c => b.1 = c,
                    _ => blocked.push((c, c)),
                }
            } else {
                first.get_or_insert(c);
                end = c;
            }
        }
        let first = first?;
        // Column c holds x in ((c − 1) cell, c cell].
        Some((
            ((first - 1) as f64 * cell).max(0.0),
            (end as f64 * cell).min(x_max),
        ))
    }

    /// Whether `shape` at `at` lies inside a placed ring or holds one.
    fn nested(&self, shape: &Turned, at: DVec2) -> bool {
        let inside_placed = |p: DVec2| {
            self.rings.iter().any(|(lo, hi, ring)| {
                p.cmpge(*lo).all() && p.cmple(*hi).all() && contains_point(ring, p)
            })
        };
        if shape.rings.iter().any(|r| inside_placed(r[0] + at)) {
            return true;
        }
        self.rings.iter().any(|(_, _, ring)| {
            let p = ring[0] - at;
            p.cmpge(DVec2::ZERO).all()
                && p.cmple(shape.size).all()
                && shape.rings.iter().any(|r| contains_point(r, p))
        })
    }

    /// The position of any of `turns` on this sheet that `rule` prefers: the turn's index
    /// and the position of its box's lower left corner.
    pub(super) fn place(
        &self,
        turns: &[Turned],
        rule: Rule,
        scratch: &mut Scratch,
    ) -> Option<(usize, DVec2)> {
        let step = (self.size.y / 300.0).clamp(MIN_STEP_MM, 1.0);
        // (turn, position, the height the rule compares)
        let mut best: Option<(usize, DVec2, f64)> = None;
        for (k, t) in turns.iter().enumerate() {
            let lift = match rule {
                Rule::LowestTop => t.size.y,
                Rule::LowestBottom => 0.0,
            };
            let mut top = self.size.y - t.size.y;
            if let Some((_, _, best_height)) = best {
                top = top.min(best_height - lift + RELATIVE);
            }
            let Some(at) = self.lowest(t, top, step, scratch) else {
                continue;
            };
            let height = at.y + lift;
            let better = best.is_none_or(|(_, b, best_height)| {
                height < best_height - RELATIVE || (height <= best_height + RELATIVE && at.x < b.x)
            });
            if better {
                best = Some((k, at, height));
            }
        }
        best.map(|(k, at, _)| (k, at))
    }

    /// The lowest position of `shape` with its box's bottom at most `top`, leftmost at that
    /// height: heights in steps of `step`, the first feasible one refined by bisection.
    fn lowest(&self, shape: &Turned, top: f64, step: f64, scratch: &mut Scratch) -> Option<DVec2> {
        if top < 0.0 {
            return None;
        }
        let steps = (top / step).floor() as usize;
        let heights = (0..=steps)
            .map(|k| k as f64 * step)
            .chain((top > steps as f64 * step).then_some(top));
        let mut below: Option<f64> = None;
        for y in heights {
            let Some(x) = self.leftmost(shape, y, scratch) else {
                below = Some(y);
                continue;
            };
            let Some(mut lo) = below else {
                return Some(DVec2::new(x, y));
            };
            let mut found = DVec2::new(x, y);
            for _ in 0..REFINE {
                let mid = 0.5 * (lo + found.y);
                match self.leftmost(shape, mid, scratch) {
                    Some(x) => found = DVec2::new(x, mid),
                    None => lo = mid,
                }
            }
            return Some(found);
        }
        None
    }
}
