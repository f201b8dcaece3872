//! How a toolpath is run: forwards, backwards, or (closed contours) from another vertex.

use glam::DVec2;

use crate::fab::{ContourRole, Toolpath};

/// Two points closer than this (mm) are the same point: closed loops, continuing paths.
pub const SAME_POINT_MM: f64 = 1e-6;

/// The direction and starting point a toolpath is run with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Orient {
    /// As given.
    Forward,
    /// Strokes in reverse order, each stroke reversed.
    Reversed,
    /// A closed single-stroke contour started at vertex `k` (same direction).
    Rotated(u32),
}

/// What the order may do with a toolpath.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Freedom {
    /// Only as given (contours with lead-ins or tabs: their entry is chosen on purpose).
    Fixed,
    /// Forwards or backwards.
    Reversible,
    /// A closed loop: started at any vertex; entry and exit coincide.
    Rotatable,
}

/// The freedom of `p`.
pub(super) fn freedom(p: &Toolpath) -> Freedom {
    let contour = matches!(p.role, ContourRole::Hole | ContourRole::Outer);
    match (contour, closed_loop(p)) {
        (true, Some(_)) => Freedom::Rotatable,
        (true, None) => Freedom::Fixed,
        (false, _) => Freedom::Reversible,
    }
}

/// For a single closed stroke, its vertices without the repeated last one.
pub(super) fn closed_loop(p: &Toolpath) -> Option<&[DVec2]> {
    match p.strokes.as_slice() {
        [s] if s.len() >= 4 && s[0].distance(s[s.len() - 1]) <= SAME_POINT_MM => {
            Some(&s[..s.len() - 1])
        }
        _ => None,
    }
}

/// First and last point of `p` run as given, `None` for a toolpath without points.
pub(super) fn ends(p: &Toolpath) -> Option<(DVec2, DVec2)> {
    let first = p.strokes.iter().find_map(|s| s.first())?;
    let last = p.strokes.iter().rev().find_map(|s| s.last())?;
    Some((*first, *last))
}

/// Entry and exit of `p` run with `orient`.
pub(super) fn entry_exit(p: &Toolpath, orient: Orient) -> Option<(DVec2, DVec2)> {
    let (a, b) = ends(p)?;
    match orient {
        Orient::Forward => Some((a, b)),
        Orient::Reversed => Some((b, a)),
        Orient::Rotated(k) => {
            let v = *closed_loop(p)?.get(k as usize)?;
            Some((v, v))
        }
    }
}

/// Rewrites `p` to run with `orient`.
pub(super) fn apply(p: &mut Toolpath, orient: Orient) {
    match orient {
        Orient::Forward => {}
        Orient::Reversed => {
            p.strokes.reverse();
            for s in &mut p.strokes {
                s.reverse();
            }
        }
        Orient::Rotated(k) => {
            if let Some(ring) = closed_loop(p) {
                let mut ring = ring.to_vec();
                let shift = k as usize % ring.len();
                ring.rotate_left(shift);
                ring.push(ring[0]);
                p.strokes[0] = ring;
            }
        }
    }
}

/// One step of a tour: a toolpath (index into the group's list) and how it is run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Visit {
    /// Index of the toolpath.
    pub item: usize,
    /// How it is run.
    pub orient: Orient,
    /// Where the tool goes down first.
    pub entry: DVec2,
    /// Where it leaves.
    pub exit: DVec2,
    /// Whether it may be run the other way (reversible or rotatable).
    pub turnable: bool,
}

impl Visit {
    /// The same toolpath run the other way (only for reversible or rotatable toolpaths).
    pub(super) fn reversed(self) -> Visit {
        let orient = match self.orient {
            Orient::Forward => Orient::Reversed,
            Orient::Reversed => Orient::Forward,
            rotated => rotated,
        };
        Visit {
            orient,
            entry: self.exit,
            exit: self.entry,
            ..self
        }
    }
}
