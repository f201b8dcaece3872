//! A raster filter that rules out most positions of a part before the exact test.
//!
//! The sheet keeps a grid of points (spacing `cell` mm) marked where a part's point is
//! certainly not allowed: inside a placed shape or closer than the gap to one of its edges.
//! A turned part keeps, row by row, the cells (squares of side `cell`) that lie wholly inside
//! it. A closed square of side `cell` always holds a grid point, the one at
//! `(⌈x/cell⌉ + i, ⌈y/cell⌉ + j)` cells for the square of cell `(i, j)` moved by `(x, y)`; so
//! when any solid cell's grid point is marked, the position is certainly infeasible
//! (a part point inside a placed shape, or within the gap of it, puts their outlines within
//! the gap or one inside the other). [`Occupancy::blocked`] turns this into the ranges of
//! `⌈x/cell⌉` ruled out at one height.

use glam::DVec2;

use crate::design::papercraft::layout::bounds;
use crate::geom::segment::slide_interval;
use crate::geom::tolerance::RELATIVE;

/// Marked grid points of a sheet, as runs of columns per grid row.
pub(super) struct Occupancy {
    cell: f64,
    /// Marked columns of each grid row, sorted disjoint inclusive runs.
    runs: Vec<Vec<(i64, i64)>>,
}

/// The solid cells of a turned part: per cell row from its box's bottom, inclusive runs of
/// cell columns from its box's left.
pub(super) struct Solid {
    rows: Vec<Vec<(i64, i64)>>,
}

/// The open x intervals where the horizontal line at `y` is inside the rings (even–odd).
fn inside_on_line(rings: &[Vec<DVec2>], y: f64, out: &mut Vec<(f64, f64)>) {
    let mut xs = Vec::new();
    for ring in rings {
        xs.clear();
        let n = ring.len();
        for i in 0..n {
            let (a, b) = (ring[i], ring[(i + 1) % n]);
            if (a.y > y) != (b.y > y) {
                xs.push(a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x));
            }
        }
        xs.sort_by(f64::total_cmp);
        out.extend(xs.chunks_exact(2).map(|c| (c[0], c[1])));
    }
}

/// Where the horizontal line at `y` comes closer than `r` to an edge: open x intervals.
fn near_on_line(edges: &[[DVec2; 2]], y: f64, r: f64, out: &mut Vec<(f64, f64)>) {
    let at = DVec2::new(0.0, y);
    out.extend(
        edges
            .iter()
            .filter(|e| e[0].y.min(e[1].y) < y + r && e[0].y.max(e[1].y) > y - r)
            .filter_map(|e| slide_interval(at, at, e[0], e[1], r)),
    );
}

/// Sorts and merges intervals (touching ones too).
fn merge(list: &mut Vec<(f64, f64)>) {
    list.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut out: Vec<(f64, f64)> = Vec::with_capacity(list.len());
    for &(lo, hi) in list.iter() {
        match out.last_mut() {
            Some(last) if lo <= last.1 => last.1 = last.1.max(hi),
            _ => out.push((lo, hi)),
        }
    }
    *list = out;
}

/// Adds an inclusive run to sorted disjoint runs, merging.
fn add_run(runs: &mut Vec<(i64, i64)>, run: (i64, i64)) {
    runs.push(run);
    runs.sort_unstable();
    let mut out: Vec<(i64, i64)> = Vec::with_capacity(runs.len());
    for &(lo, hi) in runs.iter() {
        match out.last_mut() {
            Some(last) if lo <= last.1 + 1 => last.1 = last.1.max(hi),
            _ => out.push((lo, hi)),
        }
    }
    *runs = out;
}

impl Occupancy {
    /// An empty sheet of `size` mm with grid spacing `cell` mm.
    pub(super) fn new(size: DVec2, cell: f64) -> Occupancy {
        let rows = (size.y / cell).ceil() as usize + 1;
        Occupancy {
            cell,
            runs: vec![Vec::new(); rows],
        }
    }

    /// Marks the grid points inside a placed shape (its rings, sheet coordinates) or closer
    /// than `gap` to one of its edges.
    pub(super) fn mark(&mut self, edges: &[[DVec2; 2]], rings: &[Vec<DVec2>], gap: f64) {
        let (lo, hi) = bounds(edges.iter().flatten().copied());
        let c = self.cell;
        let first = ((lo.y - gap) / c).floor().max(0.0) as usize;
        let last = (((hi.y + gap) / c).ceil().max(0.0) as usize).min(self.runs.len() - 1);
        let mut spans = Vec::new();
        for m in first..=last {
            let y = m as f64 * c;
            spans.clear();
            inside_on_line(rings, y, &mut spans);
            near_on_line(edges, y, gap, &mut spans);
            merge(&mut spans);
            for &(a, b) in &spans {
                // Grid columns k with a < k c < b.
                let (k0, k1) = ((a / c).floor() as i64 + 1, (b / c).ceil() as i64 - 1);
                if k0 <= k1 {
                    add_run(&mut self.runs[m], (k0, k1));
                }
            }
        }
    }

    /// The ranges of `⌈x/cell⌉` (inclusive) at which `solid`, its box's bottom at height
    /// `y`, certainly meets a marked point; appended to `out` unsorted.
    pub(super) fn blocked(&self, solid: &Solid, y: f64, out: &mut Vec<(i64, i64)>) {
        let base = (y / self.cell).ceil() as usize;
        for (j, part_runs) in solid.rows.iter().enumerate() {
            let Some(sheet_runs) = self.runs.get(base + j) else {
                break;
            };
            for &(i0, i1) in part_runs {
                // Cell i's point is at column c + i: marked when c + i ∈ [k0, k1].
                out.extend(sheet_runs.iter().map(|&(k0, k1)| (k0 - i1, k1 - i0)));
            }
        }
    }

    /// Grid spacing, mm.
    pub(super) fn cell(&self) -> f64 {
        self.cell
    }
}

impl Solid {
    /// The cells of spacing `cell` mm wholly inside a turned shape (rings and edges with its
    /// box from the origin to `size`): cells whose centre is inside and further than half a
    /// diagonal from every edge.
    pub(super) fn new(edges: &[[DVec2; 2]], rings: &[Vec<DVec2>], size: DVec2, cell: f64) -> Solid {
        let count = (size.y / cell).floor() as usize;
        let r = 0.5 * std::f64::consts::SQRT_2 * cell * (1.0 + RELATIVE);
        let (mut inside, mut near) = (Vec::new(), Vec::new());
        let rows = (0..count)
            .map(|j| {
                let y = (j as f64 + 0.5) * cell;
                inside.clear();
                near.clear();
                inside_on_line(rings, y, &mut inside);
                merge(&mut inside);
                near_on_line(edges, y, r, &mut near);
                merge(&mut near);
                let mut runs = Vec::new();
                for &(a, b) in &inside {
                    // Centres (i + 0.5) cell in (a, b), outside every near interval.
                    let mut from = a;
                    for &(n0, n1) in near.iter().filter(|n| n.1 > a && n.0 < b) {
                        push_centres(&mut runs, from, n0.min(b), cell);
                        from = from.max(n1);
                    }
                    push_centres(&mut runs, from, b, cell);
                }
                runs
            })
            .collect();
        Solid { rows }
    }
}

/// Appends the run of cells whose centre lies strictly between `a` and `b`.
fn push_centres(runs: &mut Vec<(i64, i64)>, a: f64, b: f64, cell: f64) {
    if b <= a {
        return;
    }
    let i0 = (a / cell - 0.5).floor() as i64 + 1;
    let i1 = (b / cell - 0.5).ceil() as i64 - 1;
    if i0 <= i1 {
        runs.push((i0, i1));
    }
}
