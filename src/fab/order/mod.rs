//! The order of a job's toolpaths: precedence first, then short travel.
//!
//! # Algorithm
//! 1. **Groups** ([`ranks`]): marks, plot, scores, perforations, then cuts layered by nesting
//!    (every contour after what it contains; holes and slits before outer contours). Groups
//!    and layers never mix, so precedence holds whatever the travel optimisation does.
//! 2. **Nearest neighbour** within each group, from where the previous group ended (the first
//!    from `start`, the machine origin): the next toolpath is the one with the nearest entry,
//!    found in a 2-d tree of entry points. Open paths may run backwards; closed contours
//!    (one closed stroke) may start at any vertex; contours with lead-ins or tabs run as given.
//!    A group of pen, mark or score lines is first made into as few strokes as its odd
//!    vertices allow (Euler paths, `order/euler.rs`), and the strokes are ordered instead.
//! 3. **Improvement**: windowed 2-opt and Or-opt passes (`order/improve.rs`), bounded
//!    work.
//! 4. **Joining**: consecutive toolpaths that continue each other (same operation, end = start)
//!    become one, saving a pierce.
//!
//! Containers are renumbered to the new positions. With `optimize` off, steps 2–4 are skipped:
//! the groups keep the given order and direction (precedence is kept, it is a safety matter).
//!
//! # Limits
//! Groups and layers never interleave: with several parts on a sheet, every hole of every part
//! is cut before the first outer contour, which costs some travel but keeps each part held
//! until its own contour is cut. The improvement is local (see `order/improve.rs`).
//!
//! # Cost
//! O(n log n) for the sort and the nearest-neighbour tours (P entry points: 2 per open path,
//! one per vertex of a closed contour), plus O(n · window · passes) for the improvement.

mod euler;
mod improve;
mod join;
mod kdtree;
mod nearest;
mod precedence;
mod visit;

use glam::DVec2;

pub use precedence::ranks;

use crate::fab::Toolpath;
use visit::Visit;

/// Orders `paths` for execution from `start` (see the module docs).
///
/// The result holds every input toolpath exactly once (possibly reversed, rotated, or joined
/// with the one before it), with `container` indices pointing into the result.
pub fn order(paths: Vec<Toolpath>, start: DVec2, optimize: bool) -> Vec<Toolpath> {
    let tour = plan_tour(&paths, start, optimize);
    let mut slots: Vec<Option<Toolpath>> = paths.into_iter().map(Some).collect();
    let mut position = vec![0; slots.len()];
    let mut ordered = Vec::with_capacity(slots.len());
    for v in &tour {
        if let Some(mut p) = slots[v.item].take() {
            visit::apply(&mut p, v.orient);
            position[v.item] = ordered.len();
            ordered.push(p);
        }
    }
    let (mut out, holder) = if optimize {
        join::join(ordered)
    } else {
        let n = ordered.len();
        (ordered, (0..n).collect())
    };
    for p in &mut out {
        p.container = p
            .container
            .and_then(|c| position.get(c))
            .map(|&k| holder[k]);
    }
    out
}

/// The tour through all groups: visits in execution order.
fn plan_tour(paths: &[Toolpath], start: DVec2, optimize: bool) -> Vec<Visit> {
    let rank = ranks(paths);
    let mut sorted: Vec<usize> = (0..paths.len()).collect();
    sorted.sort_by_key(|&i| rank[i]);
    let mut tour = Vec::with_capacity(paths.len());
    let mut at = start;
    for group in sorted.chunk_by(|&a, &b| rank[a] == rank[b]) {
        let mut part = if !optimize {
            nearest::as_given(paths, group, at)
        } else if let Some(strokes) = euler::strokes(paths, group) {
            nearest::tour_of_strokes(strokes, at)
        } else {
            nearest::tour(paths, group, at)
        };
        if optimize {
            improve::improve(&mut part, at);
        }
        at = part.last().map_or(at, |v| v.exit);
        tour.extend(part);
    }
    tour
}

/// Travel (tool off) from `start` through `paths` in order, mm: to each stroke's first point
/// from the previous stroke's last point.
pub fn travel_mm(paths: &[Toolpath], start: DVec2) -> f64 {
    let mut at = start;
    let mut total = 0.0;
    for s in paths.iter().flat_map(|p| &p.strokes) {
        if let (Some(&a), Some(&b)) = (s.first(), s.last()) {
            total += at.distance(a);
            at = b;
        }
    }
    total
}
