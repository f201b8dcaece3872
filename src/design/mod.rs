//! Design sources: programs that produce crease patterns.

pub mod classic;
