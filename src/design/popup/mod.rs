//! Pop-up cards (origamic architecture): one sheet, cut and folded, that stands up in 3D when
//! opened to 90° and folds flat when closed.
//!
//! - [`voxel`]: the voxel model of Mitani, Suzuki & Uno (2003): staircase voxels with
//!   windows, the crease pattern (Table 1), the pop-up check (§2.6) and the open/close
//!   transform (eq. 6).
//! - [`polygon`]: the polygon model of Mitani & Suzuki (2004).
//! - [`opening`]: opening and closing either model (the papers' shared transform), the folded
//!   card with vertices split on cuts; [`as_held`], the folded card as the reader holds it (the
//!   papers' axes give its mirror image), for pictures.
//! - [`problem`]: what both models' pop-up checks report about a face that does not stand up.
//! - [`integrity`]: whether a finished card holds together and closes within its outline.
//! - [`fit`]: `--fit`, more paper above the model until the closed card holds every face.

pub(crate) mod fit;
pub(crate) mod integrity;
pub(crate) mod opening;
pub mod polygon;
pub(crate) mod problem;
pub mod voxel;

pub use integrity::{loose_pieces, loose_pieces_where};
pub use opening::as_held;
pub use problem::PopupProblem;
