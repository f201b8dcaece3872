//! Polygon pop-up cards: Mitani & Suzuki (2004), "Computer aided design for origamic
//! architecture models with polygonal representation".
//!
//! - [`PolygonCard`] (`model.rs`): faces of Fig. 5 (VFace/HFace, `t`, a polygon with holes on
//!   the pattern), the 3D ↔ 2D maps of eq. 1–3, adding a face by regularised difference (§3.2,
//!   eq. 5, with i_overlay on an integer grid) so the pattern condition (eq. 4) always holds,
//!   openings by the equivalent face (§3.3, eq. 6).
//! - [`lines`]: line types (§3.4, Fig. 10).
//! - [`crease_pattern`] (`crease.rs`): the planarised [`CreasePattern`], ±90° folds, cuts,
//!   outline.
//! - [`check_popup`] (`check.rs`): the two directed floods of §3.6.
//! - [`fold_card`] (`fold.rs`): the open/close transform of eq. 7 as a [`FoldedState`].
//! - [`apply_edit`] (`edit.rs`): the editor's add / move / resize / remove on a design, the
//!   failing faces in words ([`findings`]) and the design written back ([`write_design`]).
//! - [`from_voxel`](mod@from_voxel): a voxel card (Mitani, Suzuki & Uno 2003) as a polygon card, for refinement.
//! - [`parse_design`] (`design.rs`): TOML design files replaying the operations of §3.1;
//!   examples in `examples/popup/*.popup.toml`.
//!
//! Pattern convention as for the voxel card: x along the fold from 0, v = z − y up, the back
//! sheet on top (`0 ≤ v ≤ height`), the base below (`−depth ≤ v ≤ 0`), millimetres.
//!
//! Deviations from the paper: new faces are clipped to the sheet; coplanar faces sharing a line
//! are joined by flat paper (no line) and both floods cross such joins; the floods start from
//! the back-plane pieces on the sheet's top edge and the base-plane pieces on its bottom edge;
//! polygons are snapped to a 0.1 µm grid.
//!
//! ```
//! use foldcam::design::popup::polygon::{FaceKind, PolygonCard, check_popup, crease_pattern};
//! use glam::DVec2;
//!
//! let mut card = PolygonCard::new(100.0, 50.0, 50.0)?;
//! let quad = |x0: f64, y0: f64, x1: f64, y1: f64| {
//!     [DVec2::new(x0, y0), DVec2::new(x1, y0), DVec2::new(x1, y1), DVec2::new(x0, y1)]
//! };
//! card.add_face(FaceKind::Vertical, 20.0, &quad(30.0, 0.0, 70.0, 20.0))?; // front, (x, z)
//! card.add_face(FaceKind::Horizontal, 20.0, &quad(30.0, 0.0, 70.0, 20.0))?; // top, (x, y)
//! assert!(check_popup(&card).passed());
//! let cp = crease_pattern(&card).unwrap();
//! assert!(cp.faces.is_some());
//! # Ok::<(), foldcam::design::popup::polygon::PolygonError>(())
//! ```
//!
//! [`CreasePattern`]: crate::pattern::CreasePattern
//! [`FoldedState`]: crate::pattern::FoldedState

mod check;
mod crease;
mod design;
mod edit;
mod fold;
mod from_voxel;
mod grid;
pub(crate) mod lines;
mod model;

pub use check::{FaceProblem, PopupProblem, PopupReport, check_popup, check_with_lines};
pub use crease::{PATTERN_TOLERANCE_MM, crease_pattern, crease_pattern_from};
pub use design::{
    Add, CardSize, Design, DesignError, MAX_DESIGN_POINTS, MAX_OPERATIONS, Operation, PlaneName,
    Replay, Units, parse_design,
};
pub use edit::{
    Edit, EditError, Finding, MIN_RESIZE_MM, apply_edit, findings, outline_box, write_design,
};
pub use fold::{FoldedPolygonCard, face_planes, fold_card, holds_paper, standing_corners};
pub use from_voxel::from_voxel;
pub use model::{
    FaceKind, MAX_POLYGON_POINTS, MAX_SIDE_MM, OaFace, Plane, Point, PolygonCard, PolygonError,
    Shapes, UNIT_MM, pattern_point, to_mm,
};
