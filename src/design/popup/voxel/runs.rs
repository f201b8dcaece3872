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
