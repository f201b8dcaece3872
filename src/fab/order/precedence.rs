//! Execution groups: which toolpaths must run before which.
//!
//! Groups follow [`Operation::ALL`]: marks, plot, scores, perforations, cuts. Within the cuts,
//! a toolpath must be cut before the contour that contains it (its `container`), at any depth
//! of nesting: once a contour is cut, what lies inside may drop out or shift. Cuts are layered
//! by nesting depth d (0 for a contour with no container): layer `2·(D − d) + outer`, with D the
//! greatest depth and `outer` 1 for outer contours. Layers run in increasing order, so the
//! deepest contours go first, holes and slits before outer contours of the same depth, and
//! every toolpath before its container (whose layer is at least one higher). Without islands
//! (parts inside holes) this is simply: inner contours, then outer contours last.
//!
//! Container links that are out of range, point to a non-cut toolpath or form a cycle are
//! ignored. O(n) for n toolpaths.

use crate::fab::{ContourRole, Operation, Toolpath};

/// The execution rank of every toolpath: (operation group, layer); run in increasing order.
pub fn ranks(paths: &[Toolpath]) -> Vec<(usize, usize)> {
    let depth = nesting_depths(paths);
    let deepest = depth.iter().copied().max().unwrap_or(0);
    paths
        .iter()
        .zip(&depth)
        .map(|(p, &d)| {
            let group = Operation::ALL.iter().position(|&o| o == p.op).unwrap_or(0);
            let layer = if p.op == Operation::Cut {
                2 * (deepest - d) + usize::from(p.role == ContourRole::Outer)
            } else {
                0
            };
            (group, layer)
        })
        .collect()
}

/// The valid container of cut toolpath `i`, if any.
fn container(paths: &[Toolpath], i: usize) -> Option<usize> {
    let c = paths[i].container?;
    let valid = paths[i].op == Operation::Cut && c != i && paths.get(c)?.op == Operation::Cut;
    valid.then_some(c)
}

/// Nesting depth of every toolpath through valid container links (0 for non-cuts).
fn nesting_depths(paths: &[Toolpath]) -> Vec<usize> {
    const UNKNOWN: usize = usize::MAX;
    let n = paths.len();
    let mut depth = vec![UNKNOWN; n];
    let mut walk_stamp = vec![usize::MAX; n];
    let mut chain = Vec::new();
    for i in 0..n {
        chain.clear();
        let mut at = Some(i);
        // Climb until a known depth, a root or a cycle (a node seen in this walk).
        while let Some(k) = at {
            if depth[k] != UNKNOWN || walk_stamp[k] == i {
                break;
            }
            walk_stamp[k] = i;
            chain.push(k);
            at = container(paths, k);
        }
        let base = match at {
            Some(k) if depth[k] != UNKNOWN => depth[k] + 1,
            _ => 0,
        };
        for (d, &k) in chain.iter().rev().enumerate() {
            depth[k] = base + d;
        }
    }
    depth
}
