//! The simulator's state (Miyazaki et al. 1992, §3): the face tree (face cells, one per face ever made, each with
//! its parent and its polygon on the sheet), the current faces (the tree's leaves) with their
//! rigid transforms and edge-neighbours, and the face groups (coplanar faces) with their face
//! stacks (layer order). A [`Folding`] keeps one immutable [`State`] per step, so undo
//! restores any earlier state exactly.

use glam::{DAffine3, DVec2, DVec3};

use super::FoldError;
use super::geometry::{double_area, shared_segment};
use super::sheet::{check_simple, convex_pieces, is_convex};
use super::small::{Neighbours, Ring};
use crate::geom::Segment;
use crate::pattern::MAX_COORDINATE;

/// Tolerance of the sheet's simplicity check, relative to its bounding-box diagonal (the
/// planariser's `RELATIVE_TOLERANCE`: corners closer than this are one).
const SHEET_RELATIVE: f64 = 1e-7;

/// Index of a cell of the face tree ([`Folding::cells`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct CellId(pub u32);

impl CellId {
    /// The index into [`Folding::cells`].
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// A node of the face tree (§3.1): a region of the original sheet.
#[derive(Clone, Debug, PartialEq)]
pub struct FaceCell {
    /// The face this one was split from; `None` for the sheet.
    pub parent: Option<CellId>,
    /// The region on the flat sheet, a counter-clockwise polygon in millimetres; convex for
    /// every cell but a non-convex sheet's root (which is never a current face).
    pub polygon: Ring,
    /// The step that made the cell (0 for the sheet).
    pub step: usize,
}

/// A face of the current state: a leaf of the face tree placed in space.
#[derive(Clone, Debug, PartialEq)]
pub struct LiveFace {
    /// Its cell in the face tree.
    pub cell: CellId,
    /// The rigid motion from the sheet (z = 0) to its place in space (rotation and
    /// translation only, so the face keeps its shape by construction).
    pub transform: DAffine3,
    /// The faces sharing an edge with it on the sheet, with that edge.
    pub neighbours: Neighbours,
}

/// A face sharing an edge with another on the sheet.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Neighbour {
    /// Its index in [`State::faces`].
    pub face: usize,
    /// The shared segment on the sheet, millimetres.
    pub edge: Segment,
}

/// A face group (§3.1): faces lying in one plane, with their face stack.
#[derive(Clone, Debug, PartialEq)]
pub struct FaceGroup {
    /// A point of the plane, millimetres.
    pub origin: DVec3,
    /// Unit normal; "above" in the stack means further along it.
    pub normal: DVec3,
    /// Indices into [`State::faces`], from the bottom layer to the top one along `normal`.
    /// Faces that do not overlap may stand in any order relative to each other.
    pub stack: Vec<usize>,
}

/// The paper after some steps.
#[derive(Clone, Debug, PartialEq)]
pub struct State {
    /// Current faces (leaves of the face tree).
    pub faces: Vec<LiveFace>,
    /// Coplanar groups; every face is in exactly one stack.
    pub groups: Vec<FaceGroup>,
}

impl State {
    /// For each face, its group and position in that group's stack.
    pub fn layers(&self) -> Vec<(usize, usize)> {
        let mut out = vec![(usize::MAX, usize::MAX); self.faces.len()];
        for (g, group) in self.groups.iter().enumerate() {
            for (pos, &f) in group.stack.iter().enumerate() {
                out[f] = (g, pos);
            }
        }
        out
    }

    /// The unit normal of face `f` in space (the image of the sheet's +z).
    pub fn face_normal(&self, f: usize) -> DVec3 {
        self.faces[f].transform.matrix3 * DVec3::Z
    }
}

/// One recorded step: the state after it and what made it.
#[derive(Clone, Debug, PartialEq)]
pub struct Step {
    /// The user's name for the step, if any.
    pub name: Option<String>,
    /// What the step did, in words (e.g. "bend (valley), 2 faces moved, 1 split").
    pub summary: String,
    /// The state after the step.
    pub state: State,
    /// Number of face-tree cells that existed after the step.
    pub cells: usize,
}

/// Largest number of corners of a sheet outline.
pub const MAX_SHEET_CORNERS: usize = 1_000;

/// Largest number of faces a state may have.
pub const MAX_FACES: usize = 200_000;

/// A sheet being folded step by step: the face tree and the state after every step.
#[derive(Clone, Debug, PartialEq)]
pub struct Folding {
    pub(super) sheet: Vec<DVec2>,
    pub(super) tol: f64,
    pub(super) cells: Vec<FaceCell>,
    pub(super) steps: Vec<Step>,
}

impl Folding {
    /// A flat sheet in the x-y plane (z = 0, front side facing +z) with the given outline in
    /// millimetres (either orientation): a simple polygon. A convex sheet is one face; a
    /// non-convex one starts as several convex faces, children of the sheet in the face tree
    /// (see [`super::sheet`]). Errors: fewer than 3 corners, non-finite or huge coordinates,
    /// an outline that has no area, repeats a corner or crosses itself.
    pub fn new(outline: &[DVec2]) -> Result<Folding, FoldError> {
        if outline.len() < 3 {
            return Err(FoldError::Sheet("needs at least 3 corners".into()));
        }
        if outline.len() > MAX_SHEET_CORNERS {
            return Err(FoldError::Sheet(format!(
                "has more than {MAX_SHEET_CORNERS} corners"
            )));
        }
        if outline
            .iter()
            .any(|p| !p.is_finite() || p.abs().max_element() > MAX_COORDINATE)
        {
            return Err(FoldError::NotFinite {
                what: "a sheet corner",
            });
        }
        let mut sheet = outline.to_vec();
        if double_area(&sheet) < 0.0 {
            sheet.reverse();
        }
        let (lo, hi) = sheet
            .iter()
            .fold((sheet[0], sheet[0]), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
        let size = (hi - lo).length();
        let tol = SHEET_RELATIVE * size;
        check_simple(&sheet, tol)?;
        let mut cells = vec![FaceCell {
            parent: None,
            polygon: Ring::from(&sheet[..]),
            step: 0,
        }];
        if !is_convex(&sheet, tol) {
            for piece in convex_pieces(&sheet, tol)? {
                cells.push(FaceCell {
                    parent: Some(CellId(0)),
                    polygon: piece.iter().map(|&i| sheet[i]).collect(),
                    step: 0,
                });
            }
        }
        let leaves = if cells.len() == 1 {
            0..1
        } else {
            1..cells.len()
        };
        let mut faces: Vec<LiveFace> = leaves
            .map(|c| LiveFace {
                cell: CellId(c as u32),
                transform: DAffine3::IDENTITY,
                neighbours: Neighbours::new(),
            })
            .collect();
        for a in 0..faces.len() {
            for b in a + 1..faces.len() {
                let (pa, pb) = (
                    &cells[faces[a].cell.index()].polygon,
                    &cells[faces[b].cell.index()].polygon,
                );
                if let Some(edge) = contact(pa, pb, tol) {
                    faces[a].neighbours.push(Neighbour { face: b, edge });
                    faces[b].neighbours.push(Neighbour { face: a, edge });
                }
            }
        }
        let state = State {
            groups: vec![FaceGroup {
                origin: DVec3::ZERO,
                normal: DVec3::Z,
                stack: (0..faces.len()).collect(),
            }],
            faces,
        };
        Ok(Folding {
            sheet,
            tol,
            steps: vec![Step {
                name: None,
                summary: "flat sheet".into(),
                state,
                cells: cells.len(),
            }],
            cells,
        })
    }

    /// The sheet outline, counter-clockwise, millimetres.
    pub fn sheet(&self) -> &[DVec2] {
        &self.sheet
    }

    /// The geometric tolerance, millimetres (1e-7 × the sheet's bounding-box diagonal).
    pub fn tolerance(&self) -> f64 {
        self.tol
    }

    /// The face tree: every face cell made so far (the sheet is cell 0).
    pub fn cells(&self) -> &[FaceCell] {
        &self.cells
    }

    /// Every step so far; step 0 is the flat sheet.
    pub fn steps(&self) -> &[Step] {
        &self.steps
    }

    /// The current state.
    pub fn current(&self) -> &State {
        &self.steps[self.steps.len() - 1].state
    }

    /// The sheet polygon of a current face.
    pub fn polygon(&self, face: &LiveFace) -> &[DVec2] {
        &self.cells[face.cell.index()].polygon
    }

    /// The corners of a face in space, millimetres.
    pub fn corners(&self, face: &LiveFace) -> Vec<DVec3> {
        self.polygon(face)
            .iter()
            .map(|p| face.transform.transform_point3(p.extend(0.0)))
            .collect()
    }

    /// The chain of face-tree cells a cell came from, itself first, the sheet last.
    pub fn ancestry(&self, cell: CellId) -> Vec<CellId> {
        let mut out = vec![cell];
        while let Some(p) = self.cells[out[out.len() - 1].index()].parent {
            out.push(p);
        }
        out
    }

    /// Undoes the last step (the flat sheet cannot be undone).
    pub fn undo(&mut self) -> Result<(), FoldError> {
        let last = self.steps.len() - 1;
        if last == 0 {
            return Err(FoldError::NothingToUndo);
        }
        self.undo_to(last - 1)
    }

    /// Returns to the state after step `step` (0 = the flat sheet), forgetting later steps and
    /// the face cells they made.
    pub fn undo_to(&mut self, step: usize) -> Result<(), FoldError> {
        let last = self.steps.len() - 1;
        if step > last {
            return Err(FoldError::NoSuchStep { step, last });
        }
        self.steps.truncate(step + 1);
        self.cells.truncate(self.steps[step].cells);
        Ok(())
    }

    /// Records a new state (used by the operations).
    pub(super) fn push(&mut self, name: Option<String>, summary: String, state: State) {
        self.steps.push(Step {
            name,
            summary,
            state,
            cells: self.cells.len(),
        });
    }
}

/// The segment two sheet polygons share (longer than `tol`), if they touch along an edge.
pub fn contact(a: &[DVec2], b: &[DVec2], tol: f64) -> Option<Segment> {
    let (na, nb) = (a.len(), b.len());
    for i in 0..na {
        for j in 0..nb {
            if let Some(s) = shared_segment(a[i], a[(i + 1) % na], b[j], b[(j + 1) % nb], tol) {
                return Some(s);
            }
        }
    }
    None
}
