//! Design sources: programs that produce crease patterns.

pub mod classic;
pub(crate) mod estimate;
pub mod folding;
pub mod papercraft;
pub mod popup;
pub mod source;
pub mod tessellation;
