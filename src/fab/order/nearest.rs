//! Nearest-neighbour construction of a tour through one group of toolpaths.
//!
//! Every way of entering a toolpath is a point in a [`KdTree`]: the start (run forwards), the
//! end (run backwards, if reversible) and, for a closed contour, each vertex (the loop rotated
//! to start there). From the current position the nearest live point is taken, the toolpath is
//! run from it, and all its points are deleted. O(P log P) for P entry points in practice.

use glam::DVec2;

use super::kdtree::KdTree;
use super::visit::{Freedom, Orient, Visit, closed_loop, ends, entry_exit, freedom};
use crate::fab::Toolpath;

/// The entry points of the toolpaths `items` of `paths`: (point, local item, orientation).
fn entry_points(paths: &[Toolpath], items: &[usize]) -> Vec<(DVec2, usize, Orient)> {
    let mut out = Vec::with_capacity(items.len() * 2);
    for (local, &i) in items.iter().enumerate() {
        let p = &paths[i];
        let Some((a, b)) = ends(p) else { continue };
        match freedom(p) {
            Freedom::Fixed => out.push((a, local, Orient::Forward)),
            Freedom::Reversible => {
                out.push((a, local, Orient::Forward));
                out.push((b, local, Orient::Reversed));
            }
            Freedom::Rotatable => {
                let ring = closed_loop(p).unwrap_or(&[]);
                out.extend(
                    ring.iter()
                        .enumerate()
                        .map(|(k, &v)| (v, local, Orient::Rotated(k as u32))),
                );
            }
        }
    }
    out
}

/// A nearest-neighbour tour through `items` (indices into `paths`) starting at `start`.
/// Toolpaths without points come last, in their given order.
pub(super) fn tour(paths: &[Toolpath], items: &[usize], start: DVec2) -> Vec<Visit> {
    let entries = entry_points(paths, items);
    // Entry points of one item are contiguous: remember each item's range to delete them.
    let mut range = vec![(0usize, 0usize); items.len()];
    for (k, e) in entries.iter().enumerate() {
        let r = &mut range[e.1];
        if r.1 == 0 {
            r.0 = k;
        }
        r.1 = k + 1;
    }
    let mut tree = KdTree::new(entries.iter().map(|e| e.0).collect());
    let mut out = Vec::with_capacity(items.len());
    let mut done = vec![false; items.len()];
    let mut at = start;
    while let Some(k) = tree.nearest(at) {
        let (_, local, orient) = entries[k];
        for id in range[local].0..range[local].1 {
            tree.delete(id);
        }
        done[local] = true;
        let (entry, exit) = entry_exit(&paths[items[local]], orient).unwrap_or((at, at));
        out.push(Visit {
            item: items[local],
            orient,
            entry,
            exit,
            turnable: freedom(&paths[items[local]]) != Freedom::Fixed,
        });
        at = exit;
    }
    for (local, _) in done.iter().enumerate().filter(|(_, d)| !**d) {
        out.push(Visit {
            item: items[local],
            orient: Orient::Forward,
            entry: at,
            exit: at,
            turnable: false,
        });
    }
    out
}

/// A nearest-neighbour tour through `strokes` (runs of visits that continue one another,
/// every visit turnable) starting at `start`: each stroke is entered at whichever end is
/// nearer, and run backwards (each visit reversed) when entered at its last.
pub(super) fn tour_of_strokes(strokes: Vec<Vec<Visit>>, start: DVec2) -> Vec<Visit> {
    let mut entries = Vec::with_capacity(2 * strokes.len());
    for s in &strokes {
        let (Some(first), Some(last)) = (s.first(), s.last()) else {
            continue;
        };
        entries.push(first.entry);
        entries.push(last.exit);
    }
    let mut tree = KdTree::new(entries);
    let mut strokes: Vec<Option<Vec<Visit>>> = strokes
        .into_iter()
        .filter(|s| !s.is_empty())
        .map(Some)
        .collect();
    let mut out = Vec::with_capacity(strokes.iter().flatten().map(Vec::len).sum());
    let mut at = start;
    while let Some(k) = tree.nearest(at) {
        let s = k / 2;
        tree.delete(2 * s);
        tree.delete(2 * s + 1);
        let Some(mut stroke) = strokes[s].take() else {
            continue;
        };
        if k % 2 == 1 {
            stroke.reverse();
            for v in &mut stroke {
                *v = v.reversed();
            }
        }
        at = stroke.last().map_or(at, |v| v.exit);
        out.extend(stroke);
    }
    out
}

/// The tour that runs `items` as given, in the given order (no optimisation).
pub(super) fn as_given(paths: &[Toolpath], items: &[usize], start: DVec2) -> Vec<Visit> {
    let mut at = start;
    items
        .iter()
        .map(|&i| {
            let (entry, exit) = ends(&paths[i]).unwrap_or((at, at));
            at = exit;
            Visit {
                item: i,
                orient: Orient::Forward,
                entry,
                exit,
                turnable: false,
            }
        })
        .collect()
}
