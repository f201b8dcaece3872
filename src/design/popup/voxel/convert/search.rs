//! The greedy searches of Mitani, Suzuki & Uno (2003) §3.2 c) (windows where eq. 7 added voxels) and §3.3 (thin top faces
//! left out): each candidate is applied and kept only if the card still pops up (§2.6) and
//! holds together: it may not add a piece cut free on every side
//! ([`crate::design::popup::integrity::loose_pieces`], counted on the card's crease pattern).
//! A thin top whose removal would cut a strip loose is kept instead.
//!
//! # Cost
//! A try first looks at the runs of the edited columns and their neighbours
//! ([`ColumnRuns::fails_locally`]): a vertical face that no line beside it can let a flood
//! into fails the check, whatever the rest of the card, so most refused candidates cost a few
//! columns. The others get both floods over the card's runs, and, when those pass, the loose
//! pieces counted on the same runs ([`ColumnRuns::loose_pieces`]) instead of on a crease
//! pattern built and planarised per try. Both give the verdicts of the plain check exactly;
//! the unit tests compare the two searches (`Verify::Reference` keeps the plain one).

use std::collections::VecDeque;

use super::super::VoxelCard;
use super::super::runs::ColumnRuns;
use super::super::surface::{Plane, slice_planes};

/// A card under edit with its pop-up check kept up to date column by column.
pub(super) struct Search<'a> {
    card: &'a mut VoxelCard,
    runs: ColumnRuns,
    checks: usize,
    /// Tries that needed the floods over the whole card.
    full_checks: usize,
    /// Loose pieces of the card as it stands (edits may not add any).
    loose: usize,
    verify: Verify,
}

/// How a try is judged.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Verify {
    /// The local refusal, then the floods and the loose pieces on the runs (see the module
    /// docs).
    Runs,
    /// The plain check: both floods, then the loose pieces counted on the card's planarised
    /// crease pattern, on every try. The reference the tests hold [`Verify::Runs`] to.
    #[cfg(test)]
    Reference,
}

/// Pieces of `card` cut free on every side, counted on its crease pattern; a card whose
/// pattern cannot be built counts as falling apart.
#[cfg(test)]
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
    pub(super) fn new(card: &'a mut VoxelCard, verify: Verify) -> Self {
        let runs = ColumnRuns::new(card);
        let loose = match verify {
            Verify::Runs => runs.loose_pieces(),
            #[cfg(test)]
            Verify::Reference => loose_count(card),
        };
        Search {
            card,
            runs,
            checks: 0,
            full_checks: 0,
            loose,
            verify,
        }
    }

    /// Pop-up checks run so far (candidates and groups of candidates tried).
    pub(super) fn checks(&self) -> usize {
        self.checks
    }

    /// Of those, the checks that needed the floods over the whole card (the others were
    /// refused on the edited columns alone).
    pub(super) fn full_checks(&self) -> usize {
        self.full_checks
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
        let mut before: Vec<(usize, Vec<Plane>)> = Vec::new();
        if self.verify == Verify::Runs {
            for e in edits {
                for x in e.block.x0..=e.block.x1 {
                    if before.iter().all(|(bx, _)| *bx != x) {
                        let mut planes = vec![Plane::Vertical(0); self.card.ny() + self.card.nz()];
                        slice_planes(self.card, x, &mut planes);
                        before.push((x, planes));
                    }
                }
            }
        }
        for e in edits {
            self.set(e, true);
        }
        self.checks += 1;
        if let Some(loose) = self.loose_if_passes(edits, &before)
            && loose <= self.loose
        {
            self.loose = loose;
            return true;
        }
        for e in edits {
            self.set(e, false);
        }
        false
    }

    /// With `edits` applied: `None` when the card fails the pop-up check, else its loose
    /// pieces.
    /// `before`: the planes of the edited columns before the edits.
    fn loose_if_passes(&mut self, edits: &[Edit], before: &[(usize, Vec<Plane>)]) -> Option<usize> {
        match self.verify {
            Verify::Runs => {
                let refused = edits.iter().any(|e| {
                    let b = e.block;
                    self.runs.fails_locally(b.x0.saturating_sub(1), b.x1 + 1)
                });
                if refused || self.runs.adds_loose_piece(before) {
                    return None;
                }
                self.full_checks += 1;
                self.runs.loose_if_passes()
            }
            #[cfg(test)]
            Verify::Reference => {
                self.full_checks += 1;
                self.runs.passes().then(|| loose_count(self.card))
            }
        }
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

#[cfg(test)]
mod tests {
    use super::super::{ConvertOptions, DepthField, convert};
    use super::*;

    /// A fixed linear congruential sequence.
    struct Lcg(u64);

    impl Lcg {
        fn below(&mut self, n: usize) -> usize {
            self.0 = self
                .0
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((self.0 >> 33) % n as u64) as usize
        }
    }

    /// A small bumpy field with overhangs, gaps and thin steps: per column a random walk of
    /// depth, sometimes dropping to nothing, next columns drifting from the last.
    fn bumpy(seed: u64) -> DepthField {
        let mut rng = Lcg(seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1);
        let (nx, ny, nz) = (4 + rng.below(10), 3 + rng.below(6), 4 + rng.below(10));
        let mut depths = vec![0u16; nx * nz];
        let mut previous = vec![0usize; nz];
        for x in 0..nx {
            let mut d = rng.below(ny);
            for z in 0..nz {
                match rng.below(6) {
                    0 => d = 0,
                    1 => d = rng.below(ny + 1),
                    2 => d = previous[z],
                    3 => d = (d + 1).min(ny),
                    4 => d = d.saturating_sub(1),
                    _ => {}
                }
                depths[x * nz + z] = d as u16;
                previous[z] = d;
            }
        }
        DepthField { nx, ny, nz, depths }
    }

    fn options(seed: u64) -> ConvertOptions {
        ConvertOptions {
            element: if seed.is_multiple_of(5) { 3 } else { 1 },
            windows: !seed.is_multiple_of(7),
            window_gap: [0.0, 0.25, 0.5][seed as usize % 3],
            thin_top: 1 + seed as usize % 3,
        }
    }

    #[test]
    fn the_search_on_runs_keeps_what_the_plain_search_keeps() {
        let (mut windows, mut tops, mut refused) = (0, 0, 0);
        for seed in 0..400 {
            let (field, opts) = (bumpy(seed), options(seed));
            let (fast, a) = convert(&field, 1.0, &opts, Verify::Runs).unwrap();
            let (plain, b) = convert(&field, 1.0, &opts, Verify::Reference).unwrap();
            assert_eq!(fast, plain, "seed {seed}: {field:?} {opts:?}");
            assert_eq!(
                (a.window_rows, a.tops_omitted, a.thin_tops, a.checks),
                (b.window_rows, b.tops_omitted, b.thin_tops, b.checks),
                "seed {seed}"
            );
            assert_eq!(b.full_checks, b.checks);
            windows += a.window_rows;
            tops += a.tops_omitted;
            refused += (a.window_candidates - a.window_rows) + (a.thin_tops - a.tops_omitted);
        }
        // The cards exercise both searches, with keeps and refusals.
        assert!(
            windows > 100 && tops > 100 && refused > 100,
            "{windows} {tops} {refused}"
        );
    }

    /// A random card with random windows and left-out tops (most do not pop up).
    fn edited(seed: u64) -> VoxelCard {
        let field = bumpy(seed);
        let (nx, nz) = (field.nx, field.nz);
        let mut card = VoxelCard::new(nx, field.ny, nz, 1.0).unwrap();
        let mut rng = Lcg(seed ^ 0x5555);
        for x in 0..nx {
            let mut d = 0;
            for z in (0..nz).rev() {
                d = d.max(field.depth(x, z));
                card.set_depth_unchecked_order(x, z, d);
            }
            for z in 0..nz {
                card.set_hole(x, z, rng.below(5) == 0).unwrap();
                card.set_top_omitted(x, z, rng.below(4) == 0).unwrap();
            }
        }
        if seed % 2 == 1 {
            card.set_margin_mm(2.0).unwrap();
        }
        card
    }

    #[test]
    fn loose_pieces_on_runs_are_those_of_the_crease_pattern() {
        let mut loose = 0;
        for seed in 0..400 {
            let card = edited(seed);
            let on_runs = ColumnRuns::new(&card).loose_pieces();
            assert_eq!(on_runs, loose_count(&card), "seed {seed}");
            loose += on_runs;
        }
        assert!(loose > 50, "{loose}");
    }

    #[test]
    fn a_loose_piece_seen_locally_is_one_more_on_the_crease_pattern() {
        let mut seen = 0;
        for seed in 0..400 {
            let card = edited(seed);
            let loose = loose_count(&card);
            let mut rng = Lcg(seed ^ 0xaaaa);
            for _ in 0..8 {
                let (x, z) = (rng.below(card.nx()), rng.below(card.nz()));
                let mut before = vec![Plane::Vertical(0); card.ny() + card.nz()];
                slice_planes(&card, x, &mut before);
                let mut edited = card.clone();
                if rng.below(2) == 0 {
                    let on = !edited.is_top_omitted(x, z);
                    edited.set_top_omitted(x, z, on).unwrap();
                } else {
                    let on = !edited.is_hole(x, z);
                    edited.set_hole(x, z, on).unwrap();
                }
                if ColumnRuns::new(&edited).adds_loose_piece(&[(x, before)]) {
                    assert!(loose_count(&edited) > loose, "seed {seed}, ({x}, {z})");
                    seen += 1;
                }
            }
        }
        assert!(seen > 50, "{seen}");
    }

    #[test]
    fn a_local_refusal_is_a_failing_check() {
        let (mut local, mut failing) = (0, 0);
        for seed in 0..400 {
            let card = edited(seed);
            let runs = ColumnRuns::new(&card);
            let passes = runs.passes();
            failing += usize::from(!passes);
            for x in 0..card.nx() {
                if runs.fails_locally(x, x) {
                    assert!(!passes, "seed {seed}, column {x}");
                    local += 1;
                }
            }
            assert_eq!(passes, runs.loose_if_passes().is_some(), "seed {seed}");
        }
        assert!(local > 100 && failing < 400, "{local} {failing}");
    }
}
