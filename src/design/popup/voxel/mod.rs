//! Voxel pop-up cards: Mitani, Suzuki & Uno (2003), "Computer aided design for
//! origamic architecture models with voxel data structure".
//!
//! - [`VoxelCard`] (`model.rs`): `cell[x][y][z]` (eq. 3) stored as one depth per (x, z) row,
//!   staircase by construction (eq. 4), window flags `isHole[x][z]` (eq. 5), the editing
//!   operations of §2.7.
//! - [`surface`]: which voxel face each pattern cell lands on, windows (§2.3), the line between
//!   neighbouring cells (Table 1).
//! - [`crease_pattern`] (`crease.rs`): the planarised [`CreasePattern`] with merged lines,
//!   ±90° fold angles and the outline (§2.5).
//! - [`check_popup`] (`check.rs`): the two floods of §2.6, over the front faces and over any
//!   piece of the back sheet's plane cut free of the back sheet (each vertical face needs both
//!   flags, a and b).
//! - [`fold_card`] (`fold.rs`): the open/close transform of eq. 6 as a [`FoldedState`].
//! - [`parse_voxel_card`], [`format_voxel_card`] (`format.rs`): the text format; samples in
//!   `examples/popup/`.
//! - [`card_from_depth_map`] (`depth_map.rs`): grey-level depth maps made staircase by eq. 7.
//! - [`apply_edit`] (`edit.rs`): the editor's edits from the front and side views (§2.7).
//! - [`card_verdict`] (`verdict.rs`): no pop-up, loose pieces and faces beyond the closed card,
//!   each at the pattern cells and voxel faces at fault.
//! - [`card_from_depths`] (`convert/`): §3 — a [`DepthField`] from a height map or a mesh
//!   rendered from the front ([`depth_field_from_mesh`]), bump removal by opening and closing,
//!   eq. 7, windows where the card still pops up, thin top faces left out.
//!
//! Every card is one sheet that folds flat (eq. 1, 2): each slice is a monotone staircase
//! whose rectangles have equal opposite sides.
//!
//! The pop-up check runs on face strips (`runs.rs`), not cells, and can rebuild one column
//! after an edit; the searches of §3.2 c) and §3.3 rely on that.
//!
//! ```
//! use foldcam::design::popup::voxel::{VoxelCard, check_popup, crease_pattern};
//!
//! let mut card = VoxelCard::new(6, 4, 4, 10.0)?;
//! card.add(2, 1, 1)?; // a 2 × 2 step, one cell wide
//! assert!(card.cell(2, 0, 0) && !card.cell(2, 2, 0));
//! assert!(check_popup(&card).passed());
//! let cp = crease_pattern(&card).unwrap();
//! assert!(cp.faces.is_some());
//! # Ok::<(), foldcam::design::popup::voxel::VoxelError>(())
//! ```
//!
//! [`CreasePattern`]: crate::pattern::CreasePattern
//! [`FoldedState`]: crate::pattern::FoldedState

mod check;
mod convert;
mod crease;
mod depth_map;
mod edit;
pub(crate) mod estimate;
pub(crate) mod fold;
mod format;
mod model;
mod runs;
pub(crate) mod surface;
mod verdict;

pub use check::{FrontCellProblem, PopupProblem, PopupReport, check_popup};
pub use convert::{
    ConvertOptions, ConvertReport, DepthField, MeshPlacement, PlacementError, UpAxis,
    card_from_depths, depth_field_from_mesh,
};
pub use crease::crease_pattern;
pub use depth_map::{DepthMap, MIN_MAP_SIDE, card_from_depth_map};
pub use edit::{EditChange, VoxelEdit, VoxelEditError, apply_edit};
pub use fold::{FoldedCard, fold_card, open_transform};
pub use format::{VoxelFormatError, format_voxel_card, parse_voxel_card};
pub use model::{MAX_CELLS_PER_AXIS, MAX_PATTERN_CELLS, VoxelCard, VoxelError};
pub use surface::{Line, Plane, Surface};
pub use verdict::{
    BeyondCell, CardVerdict, LooseCells, PatternCell, VoxelFace, card_verdict, face_of,
};
