//! Reading and writing other tools' files: FOLD (conformance, round trips, Flat-Folder's and
//! Origami Simulator's files), SVG, ORIPA `.cp`, DXF, meshes, and structured fuzzing of the readers.
//!
//! One test binary: each module is the tests of one part, so the crate is linked once.

#[path = "../common/bin.rs"]
mod bin;
#[path = "../common/overlap.rs"]
mod overlap;
#[path = "../common/post.rs"]
mod post_common;

mod conformance;
mod cp_format;
mod cross_format;
mod dxf_input;
mod fold_conformance;
mod fold_malformed;
mod fold_roundtrip;
mod fold_testdata;
mod mesh_io;
mod structured_fuzz;
mod svg_conventions;
mod svg_format;
