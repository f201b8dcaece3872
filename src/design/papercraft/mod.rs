//! Paper craft from developable patches with user cut lines (Ōgaki 2016, Ōgaki's thesis).
//!
//! The user traces cut lines on a reference mesh, places cylindrical developable patches, and
//! the system trims them and unrolls them into parts. Built so far:
//!
//! - the reference mesh with closest-point projection and normals (§3.1) is
//!   [`ReferenceMesh`](crate::mesh::ReferenceMesh), in `mesh`.
//! - [`cut_line`]: Catmull–Rom cut lines through points on the mesh, sampled and projected
//!   (§3.2 Step 1).
//! - [`network`]: the cut-line network as a half-edge structure, patches as faces (§3.3).
//! - [`bspline`], [`cylinder`]: degree-4 B-spline directrices and cylindrical patches with
//!   their isometric unrolling (§3.2 Step 2).
//! - [`walls`]: boundary walls, swept vertices v_s = v + k·normalize(Σ n_p) (§3.4).
//! - [`trim`]: the real boundary of a patch, where it crosses its walls (§3.2 Step 3), as a
//!   closed polyline in 3D and unrolled, refined to a tolerance.
//! - [`neighbour`], [`fit`]: automatic neighbouring patches (§3.5 Steps 1–3): P_exist's
//!   real boundary on the chosen wall swept along the plane's normal and fitted by least
//!   squares with a degree-4 B-spline; extended at both ends (§5.2.1's first limit) and
//!   fitted to several P_exist at once (its second), with the gaps measured.
//! - [`parts`], [`labels`], [`layout`], [`packing`]: parts with glue tabs and matching edge
//!   labels (cut-line numbers in stroke digits, flat lines the machine marks or skips),
//!   packed on sheets on their shapes (bottom-left fill over outlines and tabs), one crease
//!   pattern per sheet (outlines cut, tab roots mountain folds).
//! - [`design`]: the TOML design file (placed and automatic patches) and the whole chain,
//!   run by `foldcam papercraft DESIGN -o parts.fold`.
//! - [`sketch`], [`autofit`]: the studio's cut-line drawing — regions traced from the cut
//!   lines, a cylinder fitted to each, the design file written and built.
//! - [`shapes`]: meshes of bodies of revolution and of elliptic-section bodies (the fish)
//!   for tests and examples.
//!
//! Examples (`examples/papercraft/`): `vase.craft.toml` (eight placed gores),
//! `vase_auto.craft.toml` (one placed gore, seven generated, closing the ring) and
//! `fish.craft.toml` (one placed gore, five generated, two placed flat caps; the snout and
//! tail cut lines are straight chords that every gore contains, so caps and gores meet
//! within 0.005 mm, where arcs left gaps of up to 1.8 mm that no flat or cylindrical cap
//! could close).

pub(crate) mod autofit;
pub(crate) mod bspline;
pub(crate) mod cut_line;
pub(crate) mod cylinder;
pub(crate) mod design;
pub(crate) mod fit;
pub(crate) mod labels;
pub(crate) mod layout;
pub(crate) mod neighbour;
pub(crate) mod network;
pub(crate) mod packing;
pub(crate) mod paint;
pub(crate) mod parts;
pub(crate) mod shapes;
pub(crate) mod sketch;
pub(crate) mod trim;
pub(crate) mod walls;

pub use autofit::{FittedPatch, fit_cylinder};
pub use bspline::BSpline;
pub use cut_line::CutLine;
pub use cylinder::CylinderPatch;
pub use design::{Design, Made, parse_design};
pub use fit::{Fit, fit_directrix};
pub use labels::{Label, baseline, frames_overlap, make_upright, reads_upright};
pub use layout::{Placement, SheetSpec, pack, pack_boxes, part_points, sheet_pattern, usage};
pub use neighbour::boundary_gap;
pub use network::Network;
pub use packing::pack_shapes;
pub use paint::{Paint, Piece, paint_regions};
pub use parts::{GLUE_TOLERANCE_MM, GLUE_TOLERANCE_SHARE, Part, Seam, TabStyle, add_tabs, seams};
pub use shapes::{elliptic_body, revolution, sphere};
pub use sketch::{
    Evaluation, RegionReport, Regions, Sketch, SketchParams, outline_crosses_itself, regions,
    snap_line,
};
pub use trim::{BoundaryPoint, RealBoundary, real_boundary};
pub use walls::Walls;

use thiserror::Error;

/// Why a paper-craft design cannot be built.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum PapercraftError {
    /// A parameter is out of range (the message names it).
    #[error("bad parameter: {0}")]
    BadParameter(String),
    /// A cut line has too few points.
    #[error("cut line {line} has {points} points (at least 2 needed)")]
    ShortCutLine {
        /// Cut-line index.
        line: usize,
        /// Its point count.
        points: usize,
    },
    /// A point is NaN or infinite.
    #[error("{what} has a non-finite coordinate")]
    NonFinite {
        /// Which input ("cut line 3", "patch 1 directrix").
        what: String,
    },
    /// A patch's cut lines do not close into a loop.
    #[error("patch {patch}: cut line {from} does not meet cut line {to} (the loop is open)")]
    OpenLoop {
        /// Patch index.
        patch: usize,
        /// The cut line whose end is loose.
        from: usize,
        /// The next cut line in the patch's list.
        to: usize,
    },
    /// A patch names a cut line that does not exist, or names one twice.
    #[error("patch {patch}: {message}")]
    BadLoop {
        /// Patch index.
        patch: usize,
        /// What is wrong.
        message: String,
    },
    /// The mesh normals along a patch's cut lines cancel out, so it has no rough direction.
    #[error("patch {patch}: the mesh normals along its cut lines cancel out (no direction n_p)")]
    NoPatchDirection {
        /// Patch index.
        patch: usize,
    },
    /// A patch does not reach the wall of one of its cut lines, so it cannot be trimmed there.
    #[error(
        "patch {patch} does not reach the wall of cut line {line} near parameter {s:.3} \
         (extend its directrix or move it closer to the cut line; for an automatic patch, \
         raise `extend`)"
    )]
    MissesWall {
        /// Patch index.
        patch: usize,
        /// Cut-line index.
        line: usize,
        /// Cut-line parameter of the rib that is missed.
        s: f64,
    },
    /// A part does not fit on the sheet at any angle tried.
    #[error("part {part} does not fit on the sheet (use a larger sheet or a smaller scale)")]
    PartTooLarge {
        /// Part index.
        part: usize,
    },
    /// More than two patches share a cut line, or their loops cannot be oriented consistently.
    #[error("cut line {line}: {message}")]
    BadSharing {
        /// Cut-line index.
        line: usize,
        /// What is wrong.
        message: String,
    },
}
