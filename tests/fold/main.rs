//! Folding: the fold-sequence simulator with layer order (Miyazaki et al.), 3D folding and its
//! pictures.
//!
//! One test binary: each module is the tests of one part, so the crate is linked once.

#[path = "../common/isometry.rs"]
mod isometry;
#[path = "../common/render3d.rs"]
mod render3d_common;

mod fold3d;
mod folding;
mod render3d;
