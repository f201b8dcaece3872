//! Fold-sequence simulator (Miyazaki et al. 1992, Miyazaki, Yasuda, Yokoi, Toriwaki: "Interactive
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
//! - [`script`]: the TOML fold script (read and written).
//! - [`gesture`]: a drag on the sheet seen from above (the studio's fold mode) made into a
//!   script step.
//! - [`sheet`]: the sheet outline, cut into convex faces when it is not convex.
//! - [`small`]: short inline lists (face polygons, neighbour lists) that keep the per-step
//!   state copies cheap.
//! - [`display`]: step states with layers spread apart, for previews.
//!
//! Deviations from the paper:
//! - Faces are kept convex, so a line splits a face in two at most. A non-convex sheet (any
//!   simple polygon) is cut into convex pieces at step 0 ([`sheet`]); a fold line crossing it
//!   several times splits each piece it crosses, giving one face per piece on either side.
//!   The seams between pieces that end up unfolded are flat (F) lines of the crease pattern.
//! - The edge layer (§3.2) and the vertex cells (§3.3) are not stored: edges are the face
//!   polygons' sides with kept neighbour lists, vertex positions follow from each face's sheet
//!   polygon and rigid transform (isometry by construction), and the position history is the
//!   list of per-step states ([`crease::step_states`] gives every vertex's position per step).
//! - Input is a script, not the mouse Picker of §2.2; there is no viewpoint (§2.4): picking
//!   looks down from +z, and "valley" means turning towards the layer plane's normal.
//! - §4.5 gives no table for the new stack; the rules used are in [`operation`]'s docs (bend:
//!   reversed on the turning side; tuck-in: each half reversed next to its hinge; fold-up: a new
//!   group, or the side of arrival when landing on an existing plane).
//! - The fold line lies in one layer plane and splits faces of that plane only. Faces of
//!   other planes joined beyond the line are carried along rigidly with everything joined to
//!   them (§4.1 ②); one also joined to the stationary side refuses the fold, and tuck-ins carry
//!   nothing. Carried faces keep their stack order and join the group of the plane they land
//!   in on the side they arrive from (judged at their centre), or make a new group. Collisions
//!   between faces of different planes are not checked. A fold line along a layer's hinge
//!   turns that whole layer (a flap folded on about its crease); a fold is refused only when
//!   no face of the paper would stay.
//! - Tuck-ins are 180° and symmetric (the paper's restriction), with the moving layers split
//!   into a lower and an upper half of equal count.
//! - Edge-onto-edge snapping applies to bends only; a snapped drag's destination is the image
//!   of the picked vertex under the snapped fold.

pub(crate) mod crease;
pub(crate) mod display;
pub(crate) mod drag;
mod error;
pub(crate) mod geometry;
pub(crate) mod gesture;
pub(crate) mod layers;
pub(crate) mod operation;
pub(crate) mod script;
mod search;
pub(crate) mod sheet;
pub(crate) mod small;
mod snap;
mod stack;
pub(crate) mod state;

pub use crease::{crease_pattern, step_states};
pub use display::{TopFace, display_states, faces_from_above, sheet_size, step_captions};
pub use drag::{Drag, Snap, Snapped};
pub use error::FoldError;
pub use layers::{LayerProblem, layer_problems};
pub use operation::{Fold, FoldReport, Layers, Turn};
pub use script::{Script, ScriptError, parse_script, run_script, write_script};
pub use small::{Neighbours, Ring};
pub use state::{CellId, FaceCell, FaceGroup, Folding, LiveFace, Neighbour, State, Step};
