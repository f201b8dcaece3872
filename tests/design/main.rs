//! The design sources: pop-up cards from voxels and polygons (Mitani & Suzuki; Mitani, Suzuki &
//! Uno), freeform tessellations (Tachi) and paper craft (Ōgaki et al.).
//!
//! One test binary: each module is the tests of one part, so the crate is linked once.

#[path = "../common/bin.rs"]
mod bin;
#[path = "../common/cuts_clean.rs"]
mod cuts_clean;
#[path = "../common/overlap.rs"]
mod overlap;
mod support {
    pub mod popup_polygon;
    pub mod popup_voxel;
    pub mod tessellation;
    pub mod tessellation_checks;
}

mod design_source;
mod papercraft;
mod popup_fit;
mod popup_integrity;
mod popup_polygon;
mod popup_preview;
mod popup_voxel;
mod popup_voxel_convert;
mod popup_voxel_stands;
mod tessellation;
mod tessellation_caps;
mod tessellation_mask;
mod tessellation_rigid;
mod tessellation_samples;
mod tessellation_variations;
