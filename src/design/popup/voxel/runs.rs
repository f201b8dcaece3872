//! The pop-up check of Mitani, Suzuki & Uno (2003) §2.6 on runs of cells: each pattern column is a few runs of cells on one
//! plane (a face strip per step of the staircase), so both floods visit runs, not cells.
//!
//! Flood (a) moves down, left and right, so within a run it reaches every row up to the
//! highest row it entered at: its state per run is that row. Flood (b) moves up, left and
//! right and keeps the lowest row. Each flood is a best-first search (highest rows first for
//! (a), lowest first for (b), from buckets indexed by row), in which a run's value is final
//! when it is taken; the result is exactly the cell-by-cell flood's. Sideways links between
//! runs of neighbouring columns are found by one merge of the two columns per check. A column can be rebuilt alone after an edit
//! ([`ColumnRuns::update_column`]), which is what the window and thin-face searches of §3.2 c)
//! and §3.3 use.
//!
//! # Detached pieces of the back sheet
//! The paper checks the front faces (y > 0) only: the back sheet (y = 0) is one face, held by
//! the reader. A window shown on the back sheet (§2.3) or a top face left out (§3.3) can make
//! a piece of paper that lies in the back sheet's plane but is cut free of it on every side but
//! one fold, such as a strip hinged at the central fold or the disk inside a ring. Such a piece
//! is a vertical face of its own, and, as Mitani, Suzuki & Uno (2003) require of every vertical
//! face, it must be joined to the back (flood (a)) and to the base (flood (b)). So the check
//! also covers every back-sheet run that is not joined, across flat lines, to the back sheet
//! proper: the back-sheet runs reaching the top edge of the cells or, on a card with a margin,
//! the margin beside them above the fold.

use super::VoxelCard;
use super::check::{FrontCellProblem, PopupProblem};
use super::surface::{Line, Plane, line_between, slice_planes};
use crate::geom::DisjointSets;

/// Rows `lo..=hi` of one column on one plane; `below` is the line under row `lo`.
#[derive(Clone, Copy, Debug)]
struct Run {
    lo: u32,
    hi: u32,
    plane: Plane,
    below: Line,
}

/// Every column of a card's pattern as runs, bottom to top.
#[derive(Clone, Debug)]
pub(super) struct ColumnRuns {
    rows: usize,
    /// Base depth in cells (pattern row `ny` is the first above the central fold).
    ny: usize,
    /// The card has flat paper around the cells (joined to the back sheet above the fold).
    margin: bool,
    columns: Vec<Vec<Run>>,
    scratch: Vec<Plane>,
}

impl ColumnRuns {
    /// The runs of every column of `card`.
    pub(super) fn new(card: &VoxelCard) -> Self {
        let rows = card.ny() + card.nz();
        let mut runs = ColumnRuns {
            rows,
            ny: card.ny(),
            margin: card.margin_mm() > 0.0,
            columns: vec![Vec::new(); card.nx()],
            scratch: vec![Plane::Vertical(0); rows],
        };
        for x in 0..card.nx() {
            runs.update_column(card, x);
        }
        runs
    }

    /// Rebuilds column `x` after `card` changed there.
    pub(super) fn update_column(&mut self, card: &VoxelCard, x: usize) {
        slice_planes(card, x, &mut self.scratch);
        let ny = card.ny() as i64;
        let column = &mut self.columns[x];
        column.clear();
        for (r, &plane) in self.scratch.iter().enumerate() {
            match column.last_mut() {
                Some(run) if run.plane == plane => run.hi = r as u32,
                last => {
                    let below = match last {
                        Some(prev) => line_between(plane, prev.plane, r as i64 - ny),
                        None => Line::Cut,
                    };
                    column.push(Run {
                        lo: r as u32,
                        hi: r as u32,
                        plane,
                        below,
                    });
                }
            }
        }
    }

    /// True when every vertical cell the check covers (front cells and detached back-sheet
    /// cells, see the module docs) is reached by both floods.
    #[cfg(test)]
    pub(super) fn passes(&self) -> bool {
        let graph = Graph::new(&self.columns);
        let (from_back, from_base) = (
            graph.flood_from_back(self.rows),
            graph.flood_from_base(self.rows),
        );
        graph.checked_runs(self.ny, self.margin).all(|(id, _)| {
            let run = graph.runs[id];
            from_back[id] >= run.hi as i64 && from_base[id] <= run.lo as i64
        })
    }

    /// `None` when the check fails (a vertical cell it covers is not reached by both floods),
    /// else the number of loose pieces of the card (counted as `loose_pieces` counts them);
    /// one graph serves both.
    pub(super) fn loose_if_passes(&self) -> Option<usize> {
        let graph = Graph::new(&self.columns);
        let (from_back, from_base) = (
            graph.flood_from_back(self.rows),
            graph.flood_from_base(self.rows),
        );
        let passes = graph.checked_runs(self.ny, self.margin).all(|(id, _)| {
            let run = graph.runs[id];
            from_back[id] >= run.hi as i64 && from_base[id] <= run.lo as i64
        });
        passes.then(|| graph.loose_pieces(self.ny, self.margin))
    }

    /// The pieces of the card cut free on every side: the regions of the pattern joined by no
    /// crease or flat line to the largest one. This is the count
    /// [`crate::design::popup::integrity::loose_pieces`] gives on the card's crease pattern,
    /// taken on the runs: within a column two runs are joined unless a cut lies between them
    /// (Table 1), runs of neighbouring columns on one plane over shared rows are joined by a
    /// flat line, and a margin is one piece of paper joined to every run beside it on its
    /// plane.
    pub(super) fn loose_pieces(&self) -> usize {
        Graph::new(&self.columns).loose_pieces(self.ny, self.margin)
    }

    /// True when some vertical run of columns `x0..=x1` that the check surely covers (a front
    /// run, or a back-sheet run with no flat line to any other run and away from the top edge
    /// and the margin) has no line over which flood (a) could reach its top row, or none over
    /// which flood (b) could reach its bottom row. Only the runs of those columns and of their
    /// neighbours are read, and true means the check fails: a quick refusal for the searches.
    /// False says nothing.
    pub(super) fn fails_locally(&self, x0: usize, x1: usize) -> bool {
        let columns = &self.columns;
        let last = columns.len().saturating_sub(1);
        let top = self.rows as u32 - 1;
        for x in x0..=x1.min(last) {
            let column = &columns[x];
            // A run of a neighbouring column on `run`'s plane over one of rows `lo..=hi`.
            let beside = |run: &Run, lo: u32, hi: u32| {
                let near = [x.checked_sub(1), (x < last).then_some(x + 1)];
                near.into_iter().flatten().any(|n| {
                    columns[n]
                        .iter()
                        .any(|u| u.plane == run.plane && u.lo <= hi && lo <= u.hi)
                })
            };
            for (i, run) in column.iter().enumerate() {
                let checked = match run.plane {
                    Plane::Horizontal(_) => false,
                    Plane::Vertical(0) => {
                        let edge = self.margin && (x == 0 || x == last);
                        let seed = run.hi == top || (edge && run.hi as usize >= self.ny);
                        let linked = beside(run, run.lo, run.hi);
                        !seed && !linked
                    }
                    Plane::Vertical(_) => true,
                };
                if !checked {
                    continue;
                }
                let from_back = (x == 0 && i + 1 == column.len())
                    || column.get(i + 1).is_some_and(|up| up.below != Line::Cut)
                    || beside(run, run.hi, run.hi);
                let from_base = (x == 0 && i == 0)
                    || (i > 0 && run.below != Line::Cut)
                    || beside(run, run.lo, run.lo);
                if !(from_back && from_base) {
                    return true;
                }
            }
        }
        false
    }

    /// True when the edit that changed columns `before` (each column's planes before it, row
    /// by row; `self` holds the card after it) surely leaves the card with more loose pieces
    /// (see [`ColumnRuns::loose_pieces`]) than before: every cell the edit moved to another
    /// plane now lies in a region of moved cells joined to no other cell, and before the edit
    /// every such region was joined to some unmoved cell. Then the regions of the card without
    /// the moved cells gained at most the old moved cells back as joins, and now gain at least
    /// one region of their own. Only the cells around the moved ones are read; false says
    /// nothing (also when more than a few hundred cells moved).
    pub(super) fn adds_loose_piece(&self, before: &[(usize, Vec<Plane>)]) -> bool {
        const MOST: usize = 512;
        let mut moved: Vec<(i64, i64)> = Vec::new();
        for (x, old) in before {
            let Some(column) = self.columns.get(*x) else {
                return false;
            };
            for run in column {
                for r in run.lo..=run.hi {
                    if old.get(r as usize) != Some(&run.plane) {
                        moved.push((*x as i64, r as i64));
                    }
                }
            }
            if moved.len() > MOST {
                return false;
            }
        }
        if moved.is_empty() {
            return false;
        }
        moved.sort_unstable();
        moved.dedup();
        let after = |x: i64, r: i64| self.plane_at(x, r);
        let old = |x: i64, r: i64| match before.iter().find(|(bx, _)| *bx as i64 == x) {
            Some((_, planes)) if (0..self.rows as i64).contains(&r) => {
                planes.get(r as usize).copied()
            }
            _ => self.plane_at(x, r),
        };
        // Per region of moved cells: whether it is joined to an unmoved cell.
        let held_now = self.moved_regions(&moved, &after);
        let held_before = self.moved_regions(&moved, &old);
        held_now.iter().all(|&held| !held) && held_before.iter().all(|&held| held)
    }

    /// The plane of pattern cell (x, r) on the card as it stands, the margin's outside the
    /// cells when there is one; `None` beyond the sheet.
    fn plane_at(&self, x: i64, r: i64) -> Option<Plane> {
        let (nx, rows) = (self.columns.len() as i64, self.rows as i64);
        if (0..nx).contains(&x) && (0..rows).contains(&r) {
            let column = &self.columns[x as usize];
            let i = column.partition_point(|run| (run.hi as i64) < r);
            return column.get(i).map(|run| run.plane);
        }
        let in_margin = (-1..=nx).contains(&x) && (-1..=rows).contains(&r);
        let plane = if r >= self.ny as i64 {
            Plane::Vertical(0)
        } else {
            Plane::Horizontal(0)
        };
        (self.margin && in_margin).then_some(plane)
    }

    /// The regions that the cells `moved` (sorted) form on the planes `plane` gives, joined
    /// across lines that are not cuts (Table 1); per region, whether it is joined to a cell
    /// not in `moved`.
    fn moved_regions(
        &self,
        moved: &[(i64, i64)],
        plane: &dyn Fn(i64, i64) -> Option<Plane>,
    ) -> Vec<bool> {
        let ny = self.ny as i64;
        let joined = |(x, r): (i64, i64), (ox, or): (i64, i64)| -> bool {
            let (Some(a), Some(b)) = (plane(x, r), plane(ox, or)) else {
                return false;
            };
            if x == ox {
                let (upper, lower, row) = if or < r { (a, b, r) } else { (b, a, or) };
                line_between(upper, lower, row - ny) != Line::Cut
            } else {
                a == b
            }
        };
        let mut region = vec![usize::MAX; moved.len()];
        let mut held = Vec::new();
        for first in 0..moved.len() {
            if region[first] != usize::MAX {
                continue;
            }
            let id = held.len();
            held.push(false);
            region[first] = id;
            let mut stack = vec![first];
            while let Some(i) = stack.pop() {
                let (x, r) = moved[i];
                for next in [(x, r + 1), (x, r - 1), (x - 1, r), (x + 1, r)] {
                    if !joined((x, r), next) {
                        continue;
                    }
                    match moved.binary_search(&next) {
                        Ok(j) if region[j] == usize::MAX => {
                            region[j] = id;
                            stack.push(j);
                        }
                        Ok(_) => {}
                        Err(_) => held[id] = true,
                    }
                }
            }
        }
        held
    }

    /// The failing vertical cells (front cells and detached back-sheet cells), by column then
    /// row.
    pub(super) fn problems(&self) -> Vec<FrontCellProblem> {
        let ny = self.ny;
        let graph = Graph::new(&self.columns);
        let (from_back, from_base) = (
            graph.flood_from_back(self.rows),
            graph.flood_from_base(self.rows),
        );
        let mut problems = Vec::new();
        for (id, depth) in graph.checked_runs(ny, self.margin) {
            let run = graph.runs[id];
            let x = graph.column_of(id);
            let (top, bottom) = (from_back[id], from_base[id]);
            for r in run.lo..=run.hi {
                let r = r as i64;
                let Some(problem) = PopupProblem::from_floods(top >= r, bottom <= r) else {
                    continue;
                };
                problems.push(FrontCellProblem {
                    x,
                    depth: depth as usize,
                    z: r as usize + depth as usize - ny,
                    problem,
                });
            }
        }
        problems
    }
}

/// All runs in one array (column after column, bottom to top) with their sideways links: a
/// link joins runs of neighbouring columns on the same plane over the rows they share.
struct Graph {
    runs: Vec<Run>,
    /// `runs[start[x]..start[x + 1]]` is column x.
    start: Vec<usize>,
    /// `links[link_start[id]..link_start[id + 1]]`: (other run, first shared row, last).
    link_start: Vec<usize>,
    links: Vec<(u32, u32, u32)>,
}

impl Graph {
    fn new(columns: &[Vec<Run>]) -> Self {
        let mut start = Vec::with_capacity(columns.len() + 1);
        let mut runs = Vec::new();
        for column in columns {
            start.push(runs.len());
            runs.extend_from_slice(column);
        }
        start.push(runs.len());
        // Count, then fill, the links of every pair of neighbouring columns.
        let mut count = vec![0usize; runs.len() + 1];
        for x in 1..columns.len() {
            shared_rows(&runs, &start, x, |a, b, _, _| {
                count[a] += 1;
                count[b] += 1;
            });
        }
        let mut link_start = Vec::with_capacity(runs.len() + 1);
        let mut total = 0;
        for c in &count {
            link_start.push(total);
            total += c;
        }
        let mut fill = link_start.clone();
        let mut links = vec![(0, 0, 0); total];
        for x in 1..columns.len() {
            shared_rows(&runs, &start, x, |a, b, lo, hi| {
                links[fill[a]] = (b as u32, lo, hi);
                fill[a] += 1;
                links[fill[b]] = (a as u32, lo, hi);
                fill[b] += 1;
            });
        }
        Graph {
            runs,
            start,
            link_start,
            links,
        }
    }

    fn column_of(&self, id: usize) -> usize {
        self.start.partition_point(|&s| s <= id) - 1
    }

    fn links(&self, id: usize) -> &[(u32, u32, u32)] {
        &self.links[self.link_start[id]..self.link_start[id + 1]]
    }

    /// (run, depth) of every run the check covers, by column then row: the runs on a front
    /// plane (y > 0) and the back-sheet runs detached from the back sheet proper (see the
    /// module docs). `ny`: the base depth; `margin`: the card has flat paper around the cells.
    fn checked_runs(&self, ny: usize, margin: bool) -> impl Iterator<Item = (usize, u32)> + '_ {
        let proper = self.back_sheet_proper(ny, margin);
        self.runs
            .iter()
            .enumerate()
            .filter_map(move |(id, run)| match run.plane {
                Plane::Vertical(0) if proper[id] => None,
                Plane::Vertical(depth) => Some((id, depth)),
                Plane::Horizontal(_) => None,
            })
    }

    /// Per run: true for the back-sheet runs joined across flat lines to a back-sheet run on
    /// the cells' top edge or, with a margin, to the margin above the central fold (pattern
    /// rows `ny..`) beside the first or last column.
    fn back_sheet_proper(&self, ny: usize, margin: bool) -> Vec<bool> {
        let n = self.runs.len();
        let columns = self.start.len() - 1;
        let top = self.runs.iter().map(|r| r.hi).max().unwrap_or(0);
        let on_back = |id: usize| self.runs[id].plane == Plane::Vertical(0);
        let mut proper = vec![false; n];
        let edge_column = |x: usize| margin && (x == 0 || x + 1 == columns);
        let mut stack: Vec<usize> = (0..columns)
            .flat_map(|x| (self.start[x]..self.start[x + 1]).map(move |id| (x, id)))
            .filter(|&(x, id)| {
                let run = self.runs[id];
                let beside_margin = edge_column(x) && run.hi as usize >= ny;
                on_back(id) && (run.hi == top || beside_margin)
            })
            .map(|(_, id)| id)
            .collect();
        for &id in &stack {
            proper[id] = true;
        }
        // Runs of one column never share a plane with their neighbours in the column, so
        // back-sheet paper spreads only through the sideways links.
        while let Some(id) = stack.pop() {
            for &(other, _, _) in self.links(id) {
                let other = other as usize;
                if !proper[other] {
                    proper[other] = true;
                    stack.push(other);
                }
            }
        }
        proper
    }

    /// See [`ColumnRuns::loose_pieces`]: the connected regions of runs (and the margin, when
    /// there is one), less the one card.
    fn loose_pieces(&self, ny: usize, margin: bool) -> usize {
        let n = self.runs.len();
        let columns = self.start.len() - 1;
        let rows = self
            .runs
            .iter()
            .map(|r| r.hi as usize + 1)
            .max()
            .unwrap_or(0);
        let mut sets = DisjointSets::new(n + usize::from(margin));
        let mut regions = n + usize::from(margin);
        for x in 0..columns {
            for id in self.start[x] + 1..self.start[x + 1] {
                if self.runs[id].below != Line::Cut && sets.union(id, id - 1) {
                    regions -= 1;
                }
            }
        }
        for id in 0..n {
            for &(other, _, _) in self.links(id) {
                if sets.union(id, other as usize) {
                    regions -= 1;
                }
            }
        }
        if margin {
            let ny = ny as i64;
            // Margin cells lie on the back sheet above the fold (rows ny..) and on the base
            // below it; they form one ring of paper.
            let margin_plane = |r: i64| {
                if r >= ny {
                    Plane::Vertical(0)
                } else {
                    Plane::Horizontal(0)
                }
            };
            for x in 0..columns {
                for id in self.start[x]..self.start[x + 1] {
                    let run = self.runs[id];
                    let on_margin_plane = match run.plane {
                        Plane::Vertical(0) => run.hi as i64 >= ny,
                        Plane::Horizontal(0) => (run.lo as i64) < ny,
                        _ => false,
                    };
                    let side = (x == 0 || x + 1 == columns) && on_margin_plane;
                    let below =
                        run.lo == 0 && line_between(run.plane, margin_plane(-1), -ny) != Line::Cut;
                    let above = run.hi as usize + 1 == rows
                        && line_between(margin_plane(rows as i64), run.plane, rows as i64 - ny)
                            != Line::Cut;
                    if (side || below || above) && sets.union(id, n) {
                        regions -= 1;
                    }
                }
            }
        }
        regions.saturating_sub(1)
    }

    /// Flood (a) from the top-left cell: per run, the highest row reached (−1: none). Runs
    /// are taken highest value first from buckets indexed by row.
    fn flood_from_back(&self, rows: usize) -> Vec<i64> {
        let mut best = vec![-1i64; self.runs.len()];
        let mut buckets: Vec<Vec<u32>> = vec![Vec::new(); rows];
        let start = self.start[1] - 1;
        best[start] = rows as i64 - 1;
        buckets[rows - 1].push(start as u32);
        for r in (0..rows).rev() {
            while let Some(id) = buckets[r].pop() {
                let id = id as usize;
                let reach = r as i64;
                if best[id] != reach {
                    continue;
                }
                let run = self.runs[id];
                let mut offer = |other: usize, value: i64, buckets: &mut Vec<Vec<u32>>| {
                    if value > best[other] {
                        best[other] = value;
                        buckets[value as usize].push(other as u32);
                    }
                };
                // Every column covers rows from 0: a run above row 0 has its column's run below.
                if run.lo > 0 && run.below != Line::Cut {
                    offer(id - 1, self.runs[id - 1].hi as i64, &mut buckets);
                }
                for &(other, lo, hi) in self.links(id) {
                    if lo as i64 <= reach {
                        offer(other as usize, reach.min(hi as i64), &mut buckets);
                    }
                }
            }
        }
        best
    }

    /// Flood (b) from the bottom-left cell: per run, the lowest row reached (`rows`: none).
    fn flood_from_base(&self, rows: usize) -> Vec<i64> {
        let none = rows as i64;
        let mut best = vec![none; self.runs.len()];
        let mut buckets: Vec<Vec<u32>> = vec![Vec::new(); rows];
        best[0] = 0;
        buckets[0].push(0);
        for r in 0..rows {
            while let Some(id) = buckets[r].pop() {
                let id = id as usize;
                let reach = r as i64;
                if best[id] != reach {
                    continue;
                }
                let run = self.runs[id];
                let mut offer = |other: usize, value: i64, buckets: &mut Vec<Vec<u32>>| {
                    if value < best[other] {
                        best[other] = value;
                        buckets[value as usize].push(other as u32);
                    }
                };
                if (run.hi as usize) + 1 < rows && self.runs[id + 1].below != Line::Cut {
                    offer(id + 1, run.hi as i64 + 1, &mut buckets);
                }
                for &(other, lo, hi) in self.links(id) {
                    if hi as i64 >= reach {
                        offer(other as usize, reach.max(lo as i64), &mut buckets);
                    }
                }
            }
        }
        best
    }
}

/// Calls `link(a, b, lo, hi)` for every run `a` of column `x − 1` and `b` of column `x` on
/// the same plane sharing rows `lo..=hi`.
fn shared_rows(
    runs: &[Run],
    start: &[usize],
    x: usize,
    mut link: impl FnMut(usize, usize, u32, u32),
) {
    let (mut a, a_end) = (start[x - 1], start[x]);
    let (mut b, b_end) = (start[x], start[x + 1]);
    while a < a_end && b < b_end {
        let (ra, rb) = (runs[a], runs[b]);
        let (lo, hi) = (ra.lo.max(rb.lo), ra.hi.min(rb.hi));
        if lo <= hi && ra.plane == rb.plane {
            link(a, b, lo, hi);
        }
        if ra.hi < rb.hi {
            a += 1;
        } else {
            b += 1;
        }
    }
}
