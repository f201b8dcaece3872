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

/// The G-code `foldcam papercraft vase.craft.toml --job -m MACHINE -x MATERIAL` writes for the
/// bundled vase (its design and mesh copied into `dir` first).
pub fn vase_job_from_cli(dir: &Path, machine: &str, material: &str) -> Vec<u8> {
    for f in ["vase.craft.toml", "vase.obj"] {
        std::fs::copy(repo_file(&format!("examples/papercraft/{f}")), dir.join(f)).unwrap();
    }
    let args = [
        "papercraft",
        "vase.craft.toml",
        "-o",
        "vase.fold",
        "--job",
        "cli.gcode",
        "-m",
        machine,
        "-x",
        material,
    ];
    let out = foldcam(&args, dir);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    std::fs::read(dir.join("cli.gcode")).unwrap()
}

/// The `summary` of `foldcam check FILE --json` run in `dir` (vertex, edge and assignment
/// counts of the file as foldcam reads it).
pub fn check_summary(dir: &Path, file: &str) -> serde_json::Value {
    let out = foldcam(&["check", file, "--json"], dir);
    let report: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "{file}: check --json: {e}: {}",
            String::from_utf8_lossy(&out.stderr)
        )
    });
    report["summary"].clone()
}
