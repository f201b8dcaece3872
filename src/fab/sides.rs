//! Two-sided jobs: mountains from the front, valleys from the back, registration marks.
//!
//! A crease is scored or perforated from the side it folds away from, so with
//! `PlanOptions::two_sided` the toolpaths split in two jobs:
//! - **front**: everything except valley creases and cuts, with the sheet as drawn;
//! - **back**: toolpaths whose edges are all valleys, then every cut. Cuts go in the last job
//!   so the part stays held by the sheet until nothing else is left to do.
//!
//! The back job is mirrored about the vertical line through the centre of the sheet (the
//! placed extent): turning the sheet over about that line brings every point of the back job
//! onto the pattern point it realises. [`mirror`] is an involution (applying it twice is the
//! identity).
//!
//! **Registration marks** are crosses ([`MARK_SIZE_MM`] wide, [`MARK_GAP_MM`] outside the
//! content) at three corners: bottom-left, top-left and bottom-right. Both jobs mark them, the
//! back job at the mirrored positions, so after turning the sheet the back job's marks fall on
//! the front's. Three corners out of four make the set asymmetric: a sheet turned the wrong
//! way (about the horizontal axis) puts the top-left mark where no mark is expected.

use glam::{DAffine2, DVec2};

use super::{ContourRole, Operation, Toolpath};
use crate::pattern::{Assignment, CreasePattern};

/// Width and height of a registration cross, mm.
pub const MARK_SIZE_MM: f64 = 6.0;
/// Distance between the content's bounding box and a cross, mm.
pub const MARK_GAP_MM: f64 = 3.0;

/// Splits `paths` into (front, back) for a two-sided job; `container` indices are renumbered
/// within each side (a container on the other side is dropped).
pub fn split(cp: &CreasePattern, paths: Vec<Toolpath>) -> (Vec<Toolpath>, Vec<Toolpath>) {
    let on_back: Vec<bool> = paths.iter().map(|p| belongs_to_back(cp, p)).collect();
    let mut new_index = Vec::with_capacity(paths.len());
    let (mut nf, mut nb) = (0, 0);
    for &b in &on_back {
        let counter = if b { &mut nb } else { &mut nf };
        new_index.push(*counter);
        *counter += 1;
    }
    let (mut front, mut back) = (Vec::with_capacity(nf), Vec::with_capacity(nb));
    for (i, mut p) in paths.into_iter().enumerate() {
        p.container = p
            .container
            .filter(|&c| on_back.get(c) == Some(&on_back[i]))
            .map(|c| new_index[c]);
        if on_back[i] { &mut back } else { &mut front }.push(p);
    }
    (front, back)
}

/// Whether `p` is done from the back: cuts, and toolpaths whose edges are all valleys.
fn belongs_to_back(cp: &CreasePattern, p: &Toolpath) -> bool {
    let valley = |e: &crate::pattern::EdgeId| {
        cp.edges
            .get(e.index())
            .is_some_and(|e| e.assignment == Assignment::Valley)
    };
    p.op == Operation::Cut || (!p.edges.is_empty() && p.edges.iter().all(valley))
}

/// Whether a single edge of `assignment`, realised by `op`, is done from the back in a
/// two-sided job (the rule of [`split`] for a toolpath of that one edge).
pub fn edge_on_back(assignment: Assignment, op: Operation) -> bool {
    op == Operation::Cut || assignment == Assignment::Valley
}

/// The reflection about the vertical line `x = axis_x`.
pub fn mirror(axis_x: f64) -> DAffine2 {
    DAffine2::from_scale_angle_translation(
        DVec2::new(-1.0, 1.0),
        0.0,
        DVec2::new(2.0 * axis_x, 0.0),
    )
}

/// Registration crosses around `extent` (min, max), in the same coordinates.
pub fn registration_marks(extent: (DVec2, DVec2)) -> Vec<Toolpath> {
    let reach = MARK_GAP_MM + MARK_SIZE_MM / 2.0;
    let (lo, hi) = (extent.0 - reach, extent.1 + reach);
    [lo, DVec2::new(lo.x, hi.y), DVec2::new(hi.x, lo.y)]
        .into_iter()
        .map(cross)
        .collect()
}

/// A cross centred on `c`: a horizontal and a vertical stroke.
fn cross(c: DVec2) -> Toolpath {
    let h = MARK_SIZE_MM / 2.0;
    Toolpath {
        op: Operation::Mark,
        strokes: vec![
            vec![c - DVec2::X * h, c + DVec2::X * h],
            vec![c - DVec2::Y * h, c + DVec2::Y * h],
        ],
        role: ContourRole::None,
        container: None,
        edges: Vec::new(),
    }
}
