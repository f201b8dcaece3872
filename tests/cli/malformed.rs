//! Every file under `tests/data/malformed/` is run through the reader it is written for, in
//! the release binary's own way (one subcommand per folder, below), and must end with the exit
//! status recorded for it in `EXPECTED.toml` — never 101 (panic) or a signal (134, abort) —
//! with a message that names the file and contains the recorded fragment (and place, where
//! recorded apart), and without leaving
//! an output file behind. A file without an entry, or an entry without a file, fails the test.

use crate::bin;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use serde::Deserialize;

/// Longest a run may take: well above the ~50 ms a refusal takes, far below a hang.
const RUN_LIMIT: Duration = Duration::from_secs(20);

/// Files in the folder that are not inputs.
const NOT_INPUTS: [&str; 2] = ["EXPECTED.toml", "README.md"];

/// One entry of `EXPECTED.toml`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct Expected {
    /// Exit status: 2 for a refused input; 1 only where the command reports problems it
    /// found in a file it could read (`simulate`'s violations).
    exit: i32,
    /// A fragment of the message (stderr for exit 2; stdout or stderr for exit 1).
    message: String,
    /// Where in the file, when the fragment does not say it (TOML errors give the line and
    /// column on a line of their own).
    place: Option<String>,
    /// The file the message must name, when it is not the input itself (a design naming a
    /// mesh that does not exist names that mesh).
    names: Option<String>,
}

fn malformed_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/malformed")
}

/// The manifest: relative path (`reader/file`) → expectation.
fn manifest() -> BTreeMap<String, Expected> {
    let text =
        std::fs::read_to_string(malformed_dir().join("EXPECTED.toml")).expect("EXPECTED.toml");
    toml::from_str(&text).expect("EXPECTED.toml parses")
}

/// Every input file, as `reader/file`, sorted.
fn inputs() -> Vec<String> {
    let mut out = Vec::new();
    for reader in std::fs::read_dir(malformed_dir()).expect("malformed dir") {
        let reader = reader.expect("entry").path();
        if !reader.is_dir() {
            let name = reader.file_name().unwrap().to_string_lossy().into_owned();
            assert!(
                NOT_INPUTS.contains(&name.as_str()),
                "{name}: a file directly in tests/data/malformed (put it in a reader's folder)"
            );
            continue;
        }
        for file in std::fs::read_dir(&reader).expect("reader dir") {
            let file = file.expect("entry").path();
            let rel = file.strip_prefix(malformed_dir()).unwrap();
            out.push(rel.to_string_lossy().replace('\\', "/"));
        }
    }
    out.sort();
    out
}

/// The command line that reads `input` with the reader of folder `reader`, writing any
/// output into `out`.
fn command_for(reader: &str, input: &str, out: &Path) -> Vec<String> {
    let pattern = bin::repo_file("tests/data/patterns/four-lines.fold");
    let fold = out.join("out.fold").to_string_lossy().into_owned();
    let svg = out.join("out.svg").to_string_lossy().into_owned();
    let args: Vec<&str> = match reader {
        "fold" | "svg" | "cp" | "opx" | "dxf" => vec!["convert", input, &fold],
        "obj" | "stl" => vec!["tessellate", input, "-o", &fold],
        "voxel" => vec!["popup", "voxel", input, "-o", &fold],
        "script" => vec!["fold", input, "-o", &fold],
        "popup" => vec!["popup", "poly", input, "-o", &fold],
        "papercraft" => vec!["papercraft", input, "-o", &svg],
        "machine" => vec!["plan", &pattern, "-m", input, "-x", "card-300gsm"],
        "material" => vec!["plan", &pattern, "-m", "grbl-diode", "-x", input],
        "gcode" => vec!["simulate", input, "-m", "grbl-diode"],
        other => panic!("tests/data/malformed/{other}: no reader is known for this folder"),
    };
    args.into_iter().map(String::from).collect()
}

/// Runs the binary with a time limit; `None` when it had to be killed.
fn run(args: &[String], dir: &Path) -> Option<(Option<i32>, String, String)> {
    let mut child = Command::new(env!("CARGO_BIN_EXE_foldcam"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the foldcam binary runs");
    let start = Instant::now();
    loop {
        if child.try_wait().expect("wait").is_some() {
            let o = child.wait_with_output().expect("output");
            let text = |b: &[u8]| String::from_utf8_lossy(b).into_owned();
            return Some((o.status.code(), text(&o.stdout), text(&o.stderr)));
        }
        if start.elapsed() > RUN_LIMIT {
            let _ = child.kill();
            let _ = child.wait();
            return None;
        }
        std::thread::sleep(Duration::from_millis(5));
    }
}

#[test]
fn every_malformed_file_has_an_expectation_and_every_expectation_a_file() {
    let expected = manifest();
    let files = inputs();
    let unlisted: Vec<&String> = files
        .iter()
        .filter(|f| !expected.contains_key(*f))
        .collect();
    let missing: Vec<&String> = expected.keys().filter(|k| !files.contains(*k)).collect();
    assert!(
        unlisted.is_empty(),
        "files without an entry in EXPECTED.toml: {unlisted:?}"
    );
    assert!(
        missing.is_empty(),
        "entries in EXPECTED.toml without a file: {missing:?}"
    );
    // The issue asks for at least 80, across every reader.
    assert!(files.len() >= 80, "only {} malformed files", files.len());
    for reader in [
        "fold",
        "svg",
        "cp",
        "opx",
        "dxf",
        "obj",
        "stl",
        "voxel",
        "script",
        "popup",
        "papercraft",
        "machine",
        "material",
        "gcode",
    ] {
        assert!(
            files.iter().any(|f| f.starts_with(&format!("{reader}/"))),
            "no malformed file for the {reader} reader"
        );
    }
}

#[test]
fn every_malformed_file_is_refused_with_its_message_and_no_output() {
    let expected = manifest();
    let mut failures = Vec::new();
    for rel in inputs() {
        let Some(want) = expected.get(&rel) else {
            continue; // reported by the test above
        };
        let (reader, name) = rel.split_once('/').expect("reader/file");
        let input = malformed_dir().join(&rel).to_string_lossy().into_owned();
        let out = tempfile::tempdir().expect("temp dir");
        let args = command_for(reader, &input, out.path());
        let Some((code, stdout, stderr)) = run(&args, out.path()) else {
            failures.push(format!("{rel}: still running after {RUN_LIMIT:?}"));
            continue;
        };
        let said = if want.exit == 1 {
            format!("{stdout}{stderr}")
        } else {
            stderr.clone()
        };
        let names = want.names.as_deref().unwrap_or(name);
        if matches!(code, Some(101) | Some(134) | None) {
            failures.push(format!("{rel}: crashed (status {code:?}): {stderr}"));
        } else if code != Some(want.exit) {
            failures.push(format!(
                "{rel}: exit {code:?}, expected {}: {stderr}",
                want.exit
            ));
        } else if !said.contains(&want.message) {
            failures.push(format!("{rel}: message lacks {:?}: {said}", want.message));
        } else if want
            .place
            .as_ref()
            .is_some_and(|p| !said.contains(p.as_str()))
        {
            failures.push(format!(
                "{rel}: message lacks the place {:?}: {said}",
                want.place
            ));
        } else if !said.contains(names) {
            failures.push(format!("{rel}: message does not name {names}: {said}"));
        }
        let left: Vec<String> = bin::listing(out.path());
        if !left.is_empty() {
            failures.push(format!("{rel}: left {left:?} behind"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
