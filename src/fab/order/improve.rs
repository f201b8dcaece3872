//! Local improvement of a tour: windowed 2-opt and Or-opt.
//!
//! The tour is open (it starts at a given point and ends at its last toolpath). Two moves are
//! tried until a pass finds nothing better or [`MAX_PASSES`] passes are done:
//! - **2-opt**: reverse the run of visits `i..=j` (each toolpath then runs the other way), for
//!   `j − i < WINDOW`; only runs of turnable toolpaths may be reversed.
//! - **Or-opt**: move a run of 1 to 3 visits, possibly reversed, to a gap at most `OR_WINDOW`
//!   positions away.
//!
//! A move is taken when it shortens the travel by more than [`MIN_GAIN_MM`]. A pass costs
//! O(n · (WINDOW + 12 · OR_WINDOW)) distance evaluations, and there are at most
//! [`MAX_PASSES`]: bounded work, which is what lets 200,000 toolpaths plan in seconds. On
//! random scattered segments it shortens the nearest-neighbour travel by about 8 %. Windows
//! only see moves between toolpaths close in the tour, which the nearest-neighbour
//! construction makes mostly close in space too; long-range defects are not repaired.

use glam::DVec2;

use super::visit::Visit;

/// Positions a 2-opt reversal may span.
pub(super) const WINDOW: usize = 24;
/// Positions an Or-opt move may carry a run, either way.
pub(super) const OR_WINDOW: usize = 8;
/// Passes over the tour at most.
pub(super) const MAX_PASSES: usize = 3;
/// Smallest travel saving that counts as an improvement, mm.
pub(super) const MIN_GAIN_MM: f64 = 1e-9;

/// A link (travel between two consecutive visits) this short is closed: a move that only
/// re-links at a closed link cannot gain [`MIN_GAIN_MM`] (triangle inequality, below), so such
/// moves are not evaluated. A pen plot's continuous lines are chains of closed links.
const CLOSED_MM: f64 = MIN_GAIN_MM / 4.0;

/// Improves `tour` (starting at `start`) in place.
pub(super) fn improve(tour: &mut [Visit], start: DVec2) {
    for _ in 0..MAX_PASSES {
        let a = two_opt_pass(tour, start);
        let b = or_opt_pass(tour, start);
        if !(a || b) {
            break;
        }
    }
}

/// Distance to an optional next point (0 at the open end of the tour).
fn to_next(p: DVec2, next: Option<DVec2>) -> f64 {
    next.map_or(0.0, |q| p.distance(q))
}

/// Exit of position `k − 1` (the start for `k == 0`).
fn exit_before(tour: &[Visit], k: usize, start: DVec2) -> DVec2 {
    if k == 0 { start } else { tour[k - 1].exit }
}

/// Reverses the run `seg` in place: order and each visit's direction.
fn reverse_run(seg: &mut [Visit]) {
    seg.reverse();
    for v in seg.iter_mut() {
        *v = v.reversed();
    }
}

/// One pass of windowed 2-opt; true if the tour changed.
fn two_opt_pass(tour: &mut [Visit], start: DVec2) -> bool {
    let n = tour.len();
    let mut changed = false;
    for i in 0..n {
        let before = exit_before(tour, i, start);
        // Reversing i..=j turns links (before, a) + (b, next) into (before, b) + (a, next).
        // With (before, a) closed, before = a and the new pair is at least |ab| + |a next|
        // ≥ |b next|, the old pair: nothing to gain at this i.
        if before.distance(tour[i].entry) < CLOSED_MM {
            continue;
        }
        for j in i..(i + WINDOW).min(n) {
            if !tour[j].turnable {
                break;
            }
            let next = tour.get(j + 1).map(|v| v.entry);
            // Likewise with (b, next) closed.
            if next.is_some_and(|q| tour[j].exit.distance(q) < CLOSED_MM) {
                continue;
            }
            let (a, b) = (tour[i].entry, tour[j].exit);
            let old = before.distance(a) + to_next(b, next);
            let new = before.distance(b) + to_next(a, next);
            if new < old - MIN_GAIN_MM {
                reverse_run(&mut tour[i..=j]);
                changed = true;
            }
        }
    }
    changed
}

/// One pass of windowed Or-opt; true if the tour changed.
fn or_opt_pass(tour: &mut [Visit], start: DVec2) -> bool {
    let mut changed = false;
    for len in 1..=3 {
        let mut i = 0;
        while i + len <= tour.len() {
            changed |= try_move_run(tour, start, i, len);
            i += 1;
        }
    }
    changed
}

/// The best gap for the run `i..i + len` within the window: (gap, reversed, gain), if any
/// saves travel. Gap `g` is the place before `tour[g]`.
fn best_gap(tour: &[Visit], start: DVec2, i: usize, len: usize) -> Option<(usize, bool, f64)> {
    let n = tour.len();
    let (first, last) = (tour[i], tour[i + len - 1]);
    let prev = exit_before(tour, i, start);
    let next = tour.get(i + len).map(|v| v.entry);
    // A run whose links are both closed has prev = its entry and next = its exit, so taking
    // it out saves −|entry exit|, and putting it in a gap (p, q) costs at least
    // −|entry exit| (|pq| ≤ |p entry| + |entry exit| + |exit q|): nothing to gain. (At the
    // open end of the tour, with no next, a move can gain.)
    if prev.distance(first.entry) < CLOSED_MM
        && next.is_some_and(|q| last.exit.distance(q) < CLOSED_MM)
    {
        return None;
    }
    let removed = prev.distance(first.entry) + to_next(last.exit, next) - to_next(prev, next);
    let turnable = tour[i..i + len].iter().all(|v| v.turnable);
    let gaps = (i.saturating_sub(OR_WINDOW)..i).chain(i + len + 1..=(i + len + OR_WINDOW).min(n));
    let mut best: Option<(usize, bool, f64)> = None;
    for g in gaps {
        let (p, q) = (exit_before(tour, g, start), tour.get(g).map(|v| v.entry));
        let base = to_next(p, q);
        let forward = p.distance(first.entry) + to_next(last.exit, q) - base;
        let backward = p.distance(last.exit) + to_next(first.entry, q) - base;
        let mut consider = |added: f64, rev: bool| {
            let gain = removed - added;
            if gain > MIN_GAIN_MM && best.is_none_or(|b| gain > b.2) {
                best = Some((g, rev, gain));
            }
        };
        consider(forward, false);
        if turnable {
            consider(backward, true);
        }
    }
    best
}

/// Moves the run `i..i + len` to its best gap if that saves travel; true if moved.
fn try_move_run(tour: &mut [Visit], start: DVec2, i: usize, len: usize) -> bool {
    let Some((g, rev, _)) = best_gap(tour, start, i, len) else {
        return false;
    };
    let at = if g < i {
        tour[g..i + len].rotate_right(len);
        g
    } else {
        tour[i..g].rotate_left(len);
        g - len
    };
    if rev {
        reverse_run(&mut tour[at..at + len]);
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fab::order::visit::Orient;

    fn visit(item: usize, a: DVec2, b: DVec2, turnable: bool) -> Visit {
        Visit {
            item,
            orient: Orient::Forward,
            entry: a,
            exit: b,
            turnable,
        }
    }

    fn travel(tour: &[Visit], start: DVec2) -> f64 {
        let mut at = start;
        tour.iter()
            .map(|v| {
                let d = at.distance(v.entry);
                at = v.exit;
                d
            })
            .sum()
    }

    #[test]
    fn untangles_a_crossing() {
        // Points along a line visited as 0, 2, 1, 3: one reversal fixes it.
        let p = |x: f64| DVec2::new(x, 0.0);
        let mut tour = vec![
            visit(0, p(0.0), p(0.0), true),
            visit(2, p(2.0), p(2.0), true),
            visit(1, p(1.0), p(1.0), true),
            visit(3, p(3.0), p(3.0), true),
        ];
        improve(&mut tour, DVec2::ZERO);
        assert_eq!(travel(&tour, DVec2::ZERO), 3.0);
    }

    #[test]
    fn never_lengthens_and_keeps_every_visit() {
        let mut rng = crate::test_rng::TestRng::new(99);
        let mut next = move || rng.unit() * 100.0;
        for round in 0..20 {
            let mut tour: Vec<Visit> = (0..200)
                .map(|i| {
                    let a = DVec2::new(next(), next());
                    visit(
                        i,
                        a,
                        a + DVec2::new(next(), next()) / 20.0,
                        i % 7 != round % 7,
                    )
                })
                .collect();
            let fixed: Vec<Visit> = tour.iter().filter(|v| !v.turnable).copied().collect();
            let before = travel(&tour, DVec2::ZERO);
            improve(&mut tour, DVec2::ZERO);
            assert!(travel(&tour, DVec2::ZERO) <= before + 1e-9);
            let mut items: Vec<usize> = tour.iter().map(|v| v.item).collect();
            items.sort_unstable();
            assert!(items.iter().copied().eq(0..200));
            // Toolpaths that may not turn keep their direction.
            for v in tour.iter().filter(|v| !v.turnable) {
                assert!(fixed.contains(v));
            }
        }
    }
}
