//! Design sources: programs that produce crease patterns.

pub mod classic;
pub mod folding;
pub mod popup;
pub mod tessellation;
