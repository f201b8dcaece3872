//! Every design command writes a crease pattern with `-o`, or with `-m` and `-x` the machine
//! job its extension names. The job a design command writes must be byte for byte the job
//! `foldcam cut` makes from the pattern the same command writes with `-o`, and the simulated
//! machine must read it back clean.

use crate::bin;

use bin::{foldcam, listing, repo_file};
use foldcam::machine::load_machine;

/// `design ARGS -o NAME.fold`, then `cut NAME.fold`, against `design ARGS -m -x -o NAME.gcode`.
fn same_job_both_ways(name: &str, design: &[&str]) {
    let dir = tempfile::tempdir().unwrap();
    let pattern = format!("{name}.fold");
    let run = |extra: &[&str]| {
        let args: Vec<&str> = design.iter().chain(extra).copied().collect();
        let out = foldcam(&args, dir.path());
        assert!(
            out.status.success(),
            "{name}: foldcam {args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    };
    run(&["-o", &pattern]);
    let cut = foldcam(
        &[
            "cut",
            &pattern,
            "-m",
            "grbl-diode",
            "-x",
            "card-300gsm",
            "-o",
            "via-cut.gcode",
        ],
        dir.path(),
    );
    assert!(
        cut.status.success(),
        "{}",
        String::from_utf8_lossy(&cut.stderr)
    );
    run(&[
        "-m",
        "grbl-diode",
        "-x",
        "card-300gsm",
        "-o",
        "direct.gcode",
    ]);
    let via_cut = std::fs::read_to_string(dir.path().join("via-cut.gcode")).unwrap();
    let direct = std::fs::read_to_string(dir.path().join("direct.gcode")).unwrap();
    assert_eq!(direct, via_cut, "{name}: the two routes differ");
    let machine = load_machine("grbl-diode").unwrap();
    let report = foldcam::sim::run(&direct, &machine).unwrap();
    assert!(report.is_clean(), "{name}: {:?}", report.violations.first());
    assert!(report.burn_length_mm > 0.0, "{name}: nothing burned");
}

#[test]
fn generate_writes_the_job_cut_would_write() {
    same_job_both_ways(
        "miura",
        &["generate", "miura", "--columns", "4", "--rows", "3"],
    );
}

#[test]
fn popup_poly_writes_the_job_cut_would_write() {
    let design = repo_file("examples/popup/house-door.popup.toml");
    same_job_both_ways("house", &["popup", "poly", design.as_str()]);
}

#[test]
fn fold_writes_the_job_cut_would_write() {
    let script = repo_file("examples/folding/waterbomb-base.toml");
    same_job_both_ways("waterbomb", &["fold", script.as_str()]);
}

#[test]
fn a_job_that_fails_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    // A pattern far larger than the diode laser's bed: refused, no file left behind.
    let out = foldcam(
        &[
            "generate",
            "miura",
            "--width",
            "5000",
            "--height",
            "5000",
            "-m",
            "grbl-diode",
            "-x",
            "card-300gsm",
            "-o",
            "big.gcode",
        ],
        dir.path(),
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("does not fit"));
    assert!(listing(dir.path()).is_empty(), "{:?}", listing(dir.path()));
}

#[test]
fn machine_needs_material() {
    let dir = tempfile::tempdir().unwrap();
    let out = foldcam(
        &["generate", "miura", "-m", "grbl-diode", "-o", "m.gcode"],
        dir.path(),
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(listing(dir.path()).is_empty());
}
