//! The `foldcam` command line as a user runs it: options, outputs (all or nothing, `-` for
//! stdout), pipes, shop commands, pictures, hostile input, and every command line of the README.
//!
//! One test binary: each module is the tests of one part, so the crate is linked once.

#[path = "../common/bin.rs"]
mod bin;
#[path = "../common/isometry.rs"]
mod isometry;

mod atomic_write;
mod cli;
mod cli_options;
mod cli_outputs;
mod cli_pipes;
mod cli_shop;
mod design_outputs;
mod hardening;
mod hardening_inputs;
mod malformed;
mod picture_keys;
mod read_back;
mod readme;
