//! The pop-up check of Mitani & Suzuki (2004), §3.6 (Fig. 12): two floods over the pattern's faces.
//!
//! (a) From the back sheet, across folds only: a VFace passes to an HFace only across a valley,
//! an HFace to a VFace only across a mountain. (b) From the base sheet: a VFace passes to an
//! HFace only across a mountain, an HFace to a VFace only across a valley. Every VFace must be
//! reached by both; otherwise the card does not stand up (Fig. 7: floating parts, parts held
//! from one side only).
//!
//! The floods run over face pieces (connected shapes of a face's polygon, [`PieceId`]). The
//! floods start from the pieces on the back plane that reach the top edge of the sheet and
//! those on the base plane that reach its bottom edge (the sheets the hands hold). Addition to
//! the paper: two pieces on the same plane sharing a line are one sheet of paper, and both
//! floods cross such flat joins either way. As in the paper, HFaces are not required to be
//! reached.

use std::collections::{HashMap, VecDeque};

use super::lines::{LineKind, Lines, PieceId, classify};
use super::model::{FaceKind, Plane, PolygonCard};
pub use crate::design::popup::problem::PopupProblem;

/// One VFace piece that fails the check.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FaceProblem {
    /// The piece.
    pub piece: PieceId,
    /// Its plane.
    pub plane: Plane,
    /// What is wrong.
    pub problem: PopupProblem,
}

impl std::fmt::Display for FaceProblem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let why = self.problem.describe();
        let PieceId { face, shape } = self.piece;
        let t = self.plane.t_mm();
        write!(
            f,
            "face {face} (vertical, y = {t} mm), piece {shape}, {why}"
        )
    }
}

/// The result of [`check_popup`]: empty when the card pops up.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct PopupReport {
    /// Failing VFace pieces, by face then piece.
    pub problems: Vec<FaceProblem>,
}

impl PopupReport {
    /// True when every VFace is reached by both floods.
    pub fn passed(&self) -> bool {
        self.problems.is_empty()
    }

    /// The indices of the failing faces, sorted, without repeats.
    pub fn faces(&self) -> Vec<usize> {
        let mut out: Vec<usize> = self.problems.iter().map(|p| p.piece.face).collect();
        out.dedup();
        out
    }
}

/// Runs both floods of §3.6 on `card`.
pub fn check_popup(card: &PolygonCard) -> PopupReport {
    check_with_lines(card, &classify(card))
}

/// [`check_popup`] on lines already classified.
pub fn check_with_lines(card: &PolygonCard, lines: &Lines) -> PopupReport {
    let pieces: Vec<PieceId> = card
        .faces()
        .iter()
        .enumerate()
        .flat_map(|(face, f)| (0..f.polygon.len()).map(move |shape| PieceId { face, shape }))
        .collect();
    let index: HashMap<PieceId, usize> = pieces.iter().enumerate().map(|(i, &p)| (p, i)).collect();
    let mut graph = vec![Vec::new(); pieces.len()];
    for l in &lines.links {
        let (u, d) = (index[&l.upper], index[&l.lower]);
        graph[u].push((d, l.kind));
        graph[d].push((u, l.kind));
    }
    let plane = |i: usize| card.faces()[pieces[i].face].plane;
    let [lo, _, hi, _] = card.sheet();
    let touches = |i: usize, v: i32| {
        let p = pieces[i];
        card.faces()[p.face].polygon[p.shape]
            .iter()
            .flatten()
            .any(|q| q.y == v)
    };
    let starts = |sheet: Plane, v: i32| -> Vec<usize> {
        (0..pieces.len())
            .filter(|&i| plane(i) == sheet && touches(i, v))
            .collect()
    };
    // (a): V→H across valleys, H→V across mountains; (b): the other way round.
    let from_back = flood(&graph, &plane, starts(Plane::BACK, hi.y), LineKind::Valley);
    let from_base = flood(
        &graph,
        &plane,
        starts(Plane::BASE, lo.y),
        LineKind::Mountain,
    );
    let mut problems = Vec::new();
    for i in 0..pieces.len() {
        if plane(i).kind != FaceKind::Vertical {
            continue;
        }
        let Some(problem) = PopupProblem::from_floods(from_back[i], from_base[i]) else {
            continue;
        };
        problems.push(FaceProblem {
            piece: pieces[i],
            plane: plane(i),
            problem,
        });
    }
    PopupReport { problems }
}

/// Breadth-first flood over the piece graph; `v_to_h` is the fold a VFace must cross to reach
/// an HFace (the other fold leads from an HFace to a VFace). Flat joins are crossed freely.
fn flood(
    graph: &[Vec<(usize, LineKind)>],
    plane: &impl Fn(usize) -> Plane,
    starts: Vec<usize>,
    v_to_h: LineKind,
) -> Vec<bool> {
    let h_to_v = if v_to_h == LineKind::Valley {
        LineKind::Mountain
    } else {
        LineKind::Valley
    };
    let mut seen = vec![false; graph.len()];
    for &s in &starts {
        seen[s] = true;
    }
    let mut queue = VecDeque::from(starts);
    while let Some(i) = queue.pop_front() {
        for &(j, kind) in &graph[i] {
            let pass = match (plane(i).kind, plane(j).kind, kind) {
                (_, _, LineKind::Flat) => true,
                (FaceKind::Vertical, FaceKind::Horizontal, k) => k == v_to_h,
                (FaceKind::Horizontal, FaceKind::Vertical, k) => k == h_to_v,
                _ => false,
            };
            if pass && !seen[j] {
                seen[j] = true;
                queue.push_back(j);
            }
        }
    }
    seen
}
