//! Checks of a crease pattern: planarity, local flat-foldability, global layer order
//! (Flat-Folder's published counts) and the command lines that run them.
//!
//! One test binary: each module is the tests of one part, so the crate is linked once.

mod check;
mod geom_oracles;
#[path = "../common/isometry.rs"]
mod isometry;
mod layers;
mod layers_cli;
mod planarize;
mod verdicts;
