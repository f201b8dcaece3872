//! The fabrication plan: perforation, scores, cuts, curved creases, order of operations and
//! placement on the bed.
//!
//! One test binary: each module is the tests of one part, so the crate is linked once.

#[path = "../common/fab.rs"]
mod fab_common;

mod classic;
mod curved_creases;
mod fab_geometry;
mod fab_order;
mod fab_plan;
mod perforation;
mod pipeline;
mod snap_curves;
