//! Design sources: programs that produce crease patterns.

pub mod classic;
pub mod papercraft;
pub mod popup;
