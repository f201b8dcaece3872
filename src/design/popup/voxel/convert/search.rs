//! The greedy searches of Mitani, Suzuki & Uno (2003) §3.2 c) (windows where eq. 7 added voxels) and §3.3 (thin top faces
//! left out): each candidate is applied and kept only if the card still pops up (§2.6) and
//! holds together: it may not add a piece cut free on every side
//! ([`crate::design::popup::integrity::loose_pieces`], counted on the card's crease pattern).
//! A thin top whose removal would cut a strip loose is kept instead.

use std::collections::VecDeque;

use super::super::VoxelCard;
use super::super::runs::ColumnRuns;

/// A card under edit with its pop-up check kept up to date column by column.
pub(super) struct Search<'a> {
    card: &'a mut VoxelCard,
    runs: ColumnRuns,
    checks: usize,
    /// Loose pieces of the card as it stands (edits may not add any).
    loose: usize,
}

/// Pieces of `card` cut free on every side; a card whose pattern cannot be built counts as
/// falling apart.
fn loose_count(card: &VoxelCard) -> usize {
    crate::design::popup::voxel::crease_pattern(card).map_or(usize::MAX, |cp| {
        crate::design::popup::integrity::loose_pieces(&cp).len()
    })
}

/// Columns `x0..=x1` of one candidate, with the rows it flags.
#[derive(Clone, Copy, Debug)]
struct Block {
    x0: usize,
    x1: usize,
    z0: usize,
    z1: usize,
}

impl<'a> Search<'a> {
    pub(super) fn new(card: &'a mut VoxelCard) -> Self {
        let runs = ColumnRuns::new(card);
        let loose = loose_count(card);
        Search {
            card,
            runs,
            checks: 0,
            loose,
        }
    }

    /// Pop-up checks run so far.
    pub(super) fn checks(&self) -> usize {
        self.checks
    }

    /// §3.2 c): windows on the rows eq. 7 filled (`filled[x * nz + z]`), highest first, kept
    /// where the card pops up; a block that fails alone is split along x. Returns the window
    /// rows kept.
    pub(super) fn windows(&mut self, filled: &[bool]) -> usize {
        let nz = self.card.nz();
        let mut runs = Vec::new();
        for x in 0..self.card.nx() {
            let column = &filled[x * nz..(x + 1) * nz];
            let mut z = 0;
            while z < nz {
                if !column[z] {
                    z += 1;
                    continue;
                }
                let z0 = z;
                while z < nz && column[z] {
                    z += 1;
                }
                runs.push((x, z0, z - 1));
            }
        }
        let mut blocks = merge_along_x(&runs, |&(x, z0, z1)| {
            (x, (z0, z1, self.card.depth(x, z0)), (z0, z1))
        });
        blocks.sort_by_key(|b| (std::cmp::Reverse(b.z1), b.x0));
        let edits = blocks.into_iter().map(|b| Edit {
            block: b,
            window: true,
        });
        self.greedy(edits.collect())
            .iter()
            .map(|e| (e.block.x1 - e.block.x0 + 1) * (e.block.z1 - e.block.z0 + 1))
            .sum()
    }

    /// §3.3: leaves out top faces at most `max_width` columns wide, lowest first, each only if
    /// the card still pops up. Returns (faces left out, faces tried).
    pub(super) fn thin_tops(&mut self, max_width: usize) -> (usize, usize) {
        let (nx, nz) = (self.card.nx(), self.card.nz());
        let mut tops = Vec::new();
        for z in 0..nz {
            for x in 0..nx {
                if self.card.top_width(x, z) > 0 {
                    tops.push((x, z, z));
                }
            }
        }
        let card = &*self.card;
        let mut faces = merge_along_x(&tops, |&(x, z, _)| {
            (x, (z, card.depth(x, z), card.depth(x, z + 1)), (z, z))
        });
        faces.retain(|f| f.x1 - f.x0 < max_width);
        faces.sort_by_key(|f| (f.z0, f.x0));
        let tried = faces.len();
        let edits = faces.into_iter().map(|b| Edit {
            block: b,
            window: false,
        });
        (self.greedy(edits.collect()).len(), tried)
    }

    /// Applies the edits in order, each kept only if the card still pops up with it and the
    /// ones kept before. To save checks, runs of edits are tried together (doubling after a
    /// success, halving after a failure); a window block that fails alone is split along x
    /// and its halves tried next. Returns the edits kept.
    fn greedy(&mut self, edits: Vec<Edit>) -> Vec<Edit> {
        let mut queue: VecDeque<Edit> = edits.into();
        let mut kept = Vec::new();
        let mut group = 1usize;
        while !queue.is_empty() {
            let n = group.min(queue.len());
            let batch: Vec<Edit> = queue.drain(..n).collect();
            if self.try_edits(&batch) {
                kept.extend(batch);
                group *= 2;
                continue;
            }
            if n > 1 {
                group = n / 2;
                for e in batch.into_iter().rev() {
                    queue.push_front(e);
                }
                continue;
            }
            let b = batch[0].block;
            if batch[0].window && b.x0 < b.x1 {
                let mid = (b.x0 + b.x1) / 2;
                queue.push_front(Edit {
                    block: Block { x0: mid + 1, ..b },
                    window: true,
                });
                queue.push_front(Edit {
                    block: Block { x1: mid, ..b },
                    window: true,
                });
            }
        }
        kept
    }

    /// Applies `edits`; keeps them if the card pops up, else undoes them.
    fn try_edits(&mut self, edits: &[Edit]) -> bool {
        for e in edits {
            self.set(e, true);
        }
        self.checks += 1;
        if self.runs.passes() {
            let loose = loose_count(self.card);
            if loose <= self.loose {
                self.loose = loose;
                return true;
            }
        }
        for e in edits {
            self.set(e, false);
        }
        false
    }

    fn set(&mut self, e: &Edit, on: bool) {
        let b = e.block;
        for x in b.x0..=b.x1 {
            for z in b.z0..=b.z1 {
                // In range by construction.
                let _ = if e.window {
                    self.card.set_hole(x, z, on)
                } else {
                    self.card.set_top_omitted(x, z, on)
                };
            }
            self.runs.update_column(self.card, x);
        }
    }
}

/// A candidate: window flags on rows `z0..=z1`, or the top face of row `z0`, over columns
/// `x0..=x1`.
#[derive(Clone, Copy, Debug)]
struct Edit {
    block: Block,
    window: bool,
}

/// Merges items whose `key` gives (column, identity, rows) into blocks of consecutive columns
/// with equal identity. Items must come column by column.
fn merge_along_x<T, K: PartialEq + Ord + Copy>(
    items: &[T],
    key: impl Fn(&T) -> (usize, K, (usize, usize)),
) -> Vec<Block> {
    let mut keyed: Vec<(K, usize, (usize, usize))> = items
        .iter()
        .map(|item| {
            let (x, k, rows) = key(item);
            (k, x, rows)
        })
        .collect();
    keyed.sort_by_key(|&(k, x, _)| (k, x));
    let mut blocks: Vec<(K, Block)> = Vec::new();
    for (k, x, (z0, z1)) in keyed {
        match blocks.last_mut() {
            Some((last, block)) if *last == k && block.x1 + 1 == x => block.x1 = x,
            _ => blocks.push((
                k,
                Block {
                    x0: x,
                    x1: x,
                    z0,
                    z1,
                },
            )),
        }
    }
    blocks.into_iter().map(|(_, b)| b).collect()
}
