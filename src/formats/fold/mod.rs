//! FOLD 1.2 reading and writing (<https://github.com/edemaine/fold>, `doc/spec.md`).
//!
//! # Reading
//! [`read_str`] reads the key frame (the top-level dictionary) into a [`CreasePattern`];
//! [`read_frame_str`] reads any frame, with `frame_parent`/`frame_inherit` resolved by
//! [`resolve_frame`]. The reader:
//!
//! - converts `frame_unit` lengths (`in`, `pt`, `m`, `cm`, `mm`, `um`, `nm`) to millimetres;
//!   `"unit"` or no `frame_unit` gives [`Units::Unitless`](crate::pattern::Units::Unitless);
//! - reads `vertices_coords` as 2D when every z is absent or 0; rotates coplanar 3D
//!   coordinates (Origami Simulator writes flat patterns in the x–z plane) onto the xy plane,
//!   the plane's normal pointing along the positive direction of its dominant axis (so an
//!   Origami Simulator pattern reads as the SVG it came from), and reverses the faces if they
//!   then all run clockwise;
//! - treats non-coplanar 3D coordinates, and 2D frames of class `foldedForm` whose faces
//!   overlap (some faces flipped), as a folded state: it is returned in
//!   [`Imported::folded`] and the crease pattern is its isometric unfolding (see [`unfold`](mod@unfold));
//! - takes a `foldedForm` frame of `file_frames` as the folded state of a crease-pattern key
//!   frame when its vertex and edge counts match;
//! - derives edges from `faces_vertices` when `edges_vertices` is missing (one face: `B`,
//!   more: `U`); missing `edges_assignment` means all `U`; lower-case letters are accepted;
//!   `null` fold angles mean "unknown";
//! - keeps every key it does not interpret verbatim and in order in
//!   [`Metadata::file_extra`](crate::pattern::Metadata::file_extra) (keys starting with
//!   `file_`, and custom `ns:key` keys not about elements) or
//!   [`Metadata::frame_extra`](crate::pattern::Metadata::frame_extra) (`frame_*`,
//!   `vertices_*`, `edges_*`, `faces_*`, `faceOrders`, `edgeOrders`, also behind a namespace
//!   as in `ns:edges_x`); topology keys the writer can derive (see [`DERIVED_KEYS`]) are only
//!   recorded by name in `derived_keys`;
//! - reports every malformed value as a [`ParseError`] naming the key and index, and caps
//!   element counts at `u32::MAX`.
//!
//! # Writing
//! [`write_string`] writes `file_spec: 1.2`, `file_creator: "foldcam"` (a creator read from
//! the input is kept in [`SOURCE_CREATOR_KEY`] and read back from there), the metadata
//! (`file_title` etc., or `frame_title` when the file level already holds another title),
//! the pattern as the key frame (`frame_classes: ["creasePattern"]` unless the input gave
//! classes), coordinates in mm (`frame_unit: "mm"`) or `"unit"`, the derived keys recomputed
//! from the model, then the extras. Faces: always (see [`faces`]), so Origami Simulator
//! opens every file. Fold angles: `edges_foldAngle` holds every edge, an edge without an angle getting its assignment's flat-folded angle
//! (V +180, M −180, others 0) and its index listed in [`UNKNOWN_ANGLE_KEY`], so reading back
//! restores "unknown" exactly and readers unaware of the key see a sensible full fold.
//! Faces with holes: `faces_vertices` holds the outer cycle, [`HOLES_KEY`] the holes. A folded
//! state is written as a `file_frames` entry (see [`write_string`]). Output is indented JSON
//! with short arrays on one line and numbers in shortest round-trip form, so a write → read
//! round trip reproduces every coordinate bit for bit.

mod derived;
pub(crate) mod faces;
mod frames;
mod json;
mod plane;
mod raw;
mod read;
mod relax;
mod shape;
mod strict;
mod unfold;
mod units;
mod values;
mod write;

pub use faces::with_faces;
pub use frames::{frame_count, resolve_frame};
pub use read::{parse_root, read_frame_str, read_str};
pub use unfold::{Unfolding, unfold};
pub use write::{write_folded_string, write_string, write_string_frames};

#[cfg(doc)]
use super::{Imported, ParseError};
#[cfg(doc)]
use crate::pattern::CreasePattern;

/// The `file_creator` written by foldcam.
pub const CREATOR: &str = "foldcam";

/// The FOLD version written.
pub const SPEC_VERSION: f64 = 1.2;

/// Custom file-level key holding the `file_creator` of the file foldcam read, when that was
/// another program (a string).
pub const SOURCE_CREATOR_KEY: &str = "foldcam:source_creator";

/// Custom frame-level key holding the holes of faces, parallel to `faces_vertices`: for each
/// face an array of hole cycles, each an array of vertex ids (clockwise), `[]` for a face
/// without holes. Written only when some face has a hole.
pub const HOLES_KEY: &str = "foldcam:faces_holes";

/// Custom frame-level key listing (ascending) the ids of edges whose fold angle is unknown
/// although `edges_foldAngle` gives a number for them (the writer's placeholder).
pub const UNKNOWN_ANGLE_KEY: &str = "foldcam:edges_foldAngleUnknown";

/// Standard keys derivable from the model's topology and geometry: when present in the input
/// they are recorded in `meta.derived_keys` and recomputed by the writer, in this order.
pub const DERIVED_KEYS: [&str; 7] = [
    "vertices_vertices",
    "vertices_edges",
    "vertices_faces",
    "edges_faces",
    "edges_length",
    "faces_edges",
    "faces_faces",
];
