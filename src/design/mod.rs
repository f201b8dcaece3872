//! Design sources: programs that produce crease patterns.

pub mod classic;
pub mod popup;
pub mod tessellation;
