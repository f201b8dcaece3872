//! The `foldcam` command: a thin front end over the library (see `cli/`).

mod cli;

use std::process::ExitCode;

fn main() -> ExitCode {
    cli::run()
}
