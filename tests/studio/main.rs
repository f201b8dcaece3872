//! The studio's HTTP API, driven as the browser drives it: documents, designs, folding,
//! pop-ups, tessellations and jobs.
//!
//! One test binary: each module is the tests of one part, so the crate is linked once.

#[path = "../common/bin.rs"]
mod bin;
#[path = "../common/lines.rs"]
mod lines;
#[path = "../common/studio.rs"]
mod studio;

mod studio_craft;
mod studio_designs;
mod studio_fold3d;
mod studio_folding;
mod studio_guard;
mod studio_popup;
mod studio_server;
mod studio_start;
mod studio_tessellate;
mod studio_voxel;
