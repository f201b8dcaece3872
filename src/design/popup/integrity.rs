//! Whether a pop-up card holds together and closes inside its outline: checks on the finished
//! crease pattern and folded state, independent of the builder that made them.
//!
//! - **Loose pieces.** The faces of the pattern (traced anew by
//!   [`crate::pattern::faces::find_faces`], not taken from the builder) are flooded across
//!   every edge that holds material together: creases and flat lines (M, V, U, F, J). Cuts and
//!   the outline (C, B) stop the flood. The component with the largest area is the card; every
//!   other component that holds paper is cut on every side and falls out when the card is cut
//!   ([`loose_pieces`]). Which traced faces are paper the caller says
//!   ([`loose_pieces_where`]): a cut-out's scrap, such as a polygon card's opening with
//!   slanted sides, is meant to fall out.
//! - **Closed overhang.** With the card folded shut (opening angle 0°), the outline of the
//!   sheet (its boundary edges) lies on the closed card's rectangle; every folded vertex
//!   should lie within that rectangle's x–y bounds. [`closed_overhang`] measures how far the
//!   farthest one reaches beyond it, mm.
//!
//! Cost: O(E log d) to trace the faces and O(F + E) for the flood; O(V) for the overhang.

use std::collections::HashMap;

use glam::DVec2;

use crate::geom::DisjointSets;
use crate::geom::polygon::signed_area;
use crate::pattern::faces::find_faces;
use crate::pattern::{Assignment, CreasePattern, Face, FoldedState, VertexId};

/// A region of the sheet cut free on every side.
#[derive(Clone, Debug, PartialEq)]
pub struct LoosePiece {
    /// Area, mm².
    pub area_mm2: f64,
    /// Lower-left corner of its bounding box in the pattern, mm.
    pub min: DVec2,
    /// Upper-right corner of its bounding box in the pattern, mm.
    pub max: DVec2,
    /// Number of pattern faces in it.
    pub faces: usize,
}

impl std::fmt::Display for LoosePiece {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "a piece of {:.1} mm² at x = {:.1}–{:.1} mm, y = {:.1}–{:.1} mm is cut on every side \
             and falls out",
            self.area_mm2, self.min.x, self.max.x, self.min.y, self.max.y
        )
    }
}

/// Whether an edge holds the faces on its two sides together.
fn holds(a: Assignment) -> bool {
    !a.is_boundary_like()
}

/// Every region of `cp` that no crease joins to the largest one (see the module docs), the
/// largest first; every face is paper.
pub fn loose_pieces(cp: &CreasePattern) -> Vec<LoosePiece> {
    loose_pieces_where(cp, |_| true)
}

/// [`loose_pieces`] counting only regions with a face for which `paper` holds (faces as
/// traced from `cp`, outer cycle counter-clockwise).
pub fn loose_pieces_where(cp: &CreasePattern, paper: impl Fn(&Face) -> bool) -> Vec<LoosePiece> {
    let faces = find_faces(cp).faces;
    let mut by_pair: HashMap<(VertexId, VertexId), Vec<usize>> = HashMap::new();
    let key = |a: VertexId, b: VertexId| if a < b { (a, b) } else { (b, a) };
    for (f, face) in faces.iter().enumerate() {
        for ring in std::iter::once(&face.outer).chain(&face.holes) {
            for (i, &a) in ring.iter().enumerate() {
                let b = ring[(i + 1) % ring.len()];
                by_pair.entry(key(a, b)).or_default().push(f);
            }
        }
    }
    let mut groups = DisjointSets::new(faces.len());
    for e in &cp.edges {
        if !holds(e.assignment) {
            continue;
        }
        if let Some(fs) = by_pair.get(&key(e.vertices[0], e.vertices[1])) {
            for w in fs.windows(2) {
                groups.union(w[0], w[1]);
            }
        }
    }
    let declared: Vec<bool> = faces.iter().map(&paper).collect();
    let mut has_paper: HashMap<usize, bool> = HashMap::new();
    let mut pieces: HashMap<usize, LoosePiece> = HashMap::new();
    for (f, face) in faces.iter().enumerate() {
        let ring: Vec<DVec2> = face.outer.iter().map(|&v| cp.position(v)).collect();
        let holes: f64 = face
            .holes
            .iter()
            .map(|h| signed_area(h.iter().map(|&v| cp.position(v))))
            .sum();
        let area = signed_area(ring.iter().copied()) + holes;
        let root = groups.find(f);
        *has_paper.entry(root).or_default() |= declared[f];
        let piece = pieces.entry(root).or_insert(LoosePiece {
            area_mm2: 0.0,
            min: DVec2::INFINITY,
            max: DVec2::NEG_INFINITY,
            faces: 0,
        });
        piece.area_mm2 += area;
        piece.faces += 1;
        for p in ring {
            piece.min = piece.min.min(p);
            piece.max = piece.max.max(p);
        }
    }
    let mut all: Vec<(usize, LoosePiece)> = pieces.into_iter().collect();
    all.sort_by(|a, b| b.1.area_mm2.total_cmp(&a.1.area_mm2));
    all.into_iter()
        .skip(1)
        .filter(|(root, _)| has_paper.get(root).copied().unwrap_or(false))
        .map(|(_, piece)| piece)
        .collect()
}

/// How far a card folded shut reaches beyond its own outline.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Overhang {
    /// Largest distance of a folded vertex outside the closed outline's x–y rectangle, mm
    /// (0 when every vertex is inside).
    pub beyond_mm: f64,
    /// Where: the farthest vertex in the folded state, x and y, mm.
    pub at: DVec2,
    /// The closed outline's rectangle, lower-left and upper-right, mm.
    pub outline: (DVec2, DVec2),
}

/// The overhang of `closed`, a card's folded state at opening 0° (see the module docs);
/// `None` without boundary edges.
pub fn closed_overhang(closed: &FoldedState) -> Option<Overhang> {
    let mut lo = DVec2::INFINITY;
    let mut hi = DVec2::NEG_INFINITY;
    for e in closed
        .edges
        .iter()
        .filter(|e| e.assignment == Assignment::Boundary)
    {
        for v in e.vertices {
            let p = closed.positions.get(v.index())?.truncate();
            lo = lo.min(p);
            hi = hi.max(p);
        }
    }
    if !lo.is_finite() {
        return None;
    }
    let mut worst = Overhang {
        beyond_mm: 0.0,
        at: lo,
        outline: (lo, hi),
    };
    for p in closed.positions.iter().map(|p| p.truncate()) {
        let out = (lo - p).max(p - hi).max(DVec2::ZERO);
        let d = out.length();
        if d > worst.beyond_mm {
            worst.beyond_mm = d;
            worst.at = p;
        }
    }
    Some(worst)
}
