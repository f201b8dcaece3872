//! The `foldcam` command: a thin front end over the library (see `cli/`).

mod cli;

use std::process::ExitCode;

/// mimalloc instead of the system allocator (see Cargo.toml).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() -> ExitCode {
    cli::run()
}
