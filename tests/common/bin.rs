//! Running the `foldcam` binary from the end-to-end tests, and looking at what it left.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Runs `foldcam ARGS` in `dir` and returns its output.
pub fn foldcam(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_foldcam"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("the foldcam binary runs")
}

/// A file of the repository, as an argument.
pub fn repo_file(rel: &str) -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join(rel)
        .to_string_lossy()
        .into_owned()
}

/// Files in `dir`, sorted (to see that nothing was left behind).
pub fn listing(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .expect("listing")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}
