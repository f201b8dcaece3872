//! Fold-sequence simulator (seed 003, Miyazaki, Yasuda, Yokoi, Toriwaki: "Interactive
//! manipulation of origami in 3D virtual space"): a sheet folded step by step by folding up,
//! bending and tucking in, with the layer order kept, from which the crease pattern is cut.
//!
//! - [`state`]: the data of §3 — the face tree (every face ever made, with its parent and its
//!   region of the sheet), the current faces with rigid transforms, face groups (coplanar
//!   faces) with their face stacks; one immutable state per step, so undo is exact.
//! - [`operation`]: the operations of §2.1 and the list update of §4 (the moving-face search
//!   in `search`, the face stack update and tuck-in conditions in `stack`).
//! - [`drag`]: the paper's interaction (§2.3): pick a vertex, move it; the fold line is the
//!   perpendicular bisector of the move, the fold angle twice the plane angle (Fig. 3); the
//!   snapping rules of §2.3 4) (in `snap`).
//! - [`layers`]: consistency of flat layer orders (no face passes through another).
//! - [`crease`]: the crease pattern (unfolded fold lines, mountain/valley from the final state)
//!   and the folded state of every step on that pattern's topology.
//! - [`script`]: the TOML fold script.
//! - [`display`]: step states with layers spread apart, for previews.
//!
//! Deviations from the paper: the sheet must be convex (faces stay convex, so splitting a face
//! by a line gives two faces); vertex positions are not stored as cells with a history but
//! derived from each face's sheet polygon and its rigid transform (the history is the list of
//! per-step states); a fold may only move faces of one layer plane (the paper's §4.5 says the
//! same), and a face of another plane attached beyond the fold line is an error, not moved
//! along; collisions between faces of different planes are not checked.

pub mod crease;
pub mod display;
pub mod drag;
mod error;
pub mod geometry;
pub mod layers;
pub mod operation;
pub mod script;
mod search;
mod snap;
mod stack;
pub mod state;

pub use error::FoldError;
pub use operation::{Fold, FoldReport, Layers, Turn};
pub use state::{CellId, FaceCell, FaceGroup, Folding, LiveFace, State, Step};
