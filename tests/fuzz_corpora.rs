//! The fuzz targets of `fuzz/` as ordinary tests on stable Rust: each target's own file (the
//! one cargo-fuzz builds, with its assertions) runs on every seed of its corpus
//! (`fuzz/corpus/TARGET/`) and on every hostile input of `tests/data/malformed/` written for
//! its reader, so a change that makes a reader panic on one of them fails here without the
//! nightly toolchain. Coverage-guided fuzzing itself still needs cargo-fuzz (fuzz/README.md).

// Each target includes its helpers (`common.rs`, `mesh_common.rs`) as a module of its own, as
// each is a crate of its own in the fuzz build.
#![allow(clippy::duplicate_mod)]

// The targets `use libfuzzer_sys::fuzz_target;`: this crate stands in for libfuzzer-sys, and
// its `fuzz_target!` turns a target's body into a function `fuzz_input(data)`.
extern crate self as libfuzzer_sys;

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::PathBuf;

// Each target, as a module of its own file (its `#![no_main]` is for the fuzz build only).
#[allow(unused_attributes)]
#[path = "../fuzz/fuzz_targets/cp.rs"]
mod cp;
#[allow(unused_attributes)]
#[path = "../fuzz/fuzz_targets/design_toml.rs"]
mod design_toml;
#[allow(unused_attributes)]
#[path = "../fuzz/fuzz_targets/dxf.rs"]
mod dxf;
#[allow(unused_attributes)]
#[path = "../fuzz/fuzz_targets/fold.rs"]
mod fold;
#[allow(unused_attributes)]
#[path = "../fuzz/fuzz_targets/gcode.rs"]
mod gcode;
#[allow(unused_attributes)]
#[path = "../fuzz/fuzz_targets/obj.rs"]
mod obj;
#[allow(unused_attributes)]
#[path = "../fuzz/fuzz_targets/opx.rs"]
mod opx;
#[allow(unused_attributes)]
#[path = "../fuzz/fuzz_targets/profile_toml.rs"]
mod profile_toml;
#[allow(unused_attributes)]
#[path = "../fuzz/fuzz_targets/stl.rs"]
mod stl;
#[allow(unused_attributes)]
#[path = "../fuzz/fuzz_targets/svg.rs"]
mod svg;
#[allow(unused_attributes)]
#[path = "../fuzz/fuzz_targets/voxel.rs"]
mod voxel;

/// Runs `target` on every file of `folders` (relative to the repository), each at least one
/// file; fails naming every input that made it panic.
fn replay(target: fn(&[u8]), folders: &[&str]) {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let mut failed = Vec::new();
    for folder in folders {
        let dir = root.join(folder);
        let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
            .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
            .map(|e| e.expect("entry").path())
            .filter(|p| p.is_file())
            .collect();
        files.sort();
        assert!(!files.is_empty(), "{folder}: no inputs");
        for file in files {
            let bytes = std::fs::read(&file).expect("read");
            if catch_unwind(AssertUnwindSafe(|| target(&bytes))).is_err() {
                failed.push(file.display().to_string());
            }
        }
    }
    assert!(failed.is_empty(), "the target panicked on: {failed:#?}");
}

#[test]
fn fold_corpus_and_malformed_files() {
    replay(
        fold::fuzz_input,
        &["fuzz/corpus/fold", "tests/data/malformed/fold"],
    );
}

#[test]
fn svg_corpus_and_malformed_files() {
    replay(
        svg::fuzz_input,
        &["fuzz/corpus/svg", "tests/data/malformed/svg"],
    );
}

#[test]
fn cp_corpus_and_malformed_files() {
    replay(
        cp::fuzz_input,
        &["fuzz/corpus/cp", "tests/data/malformed/cp"],
    );
}

#[test]
fn opx_corpus_and_malformed_files() {
    replay(
        opx::fuzz_input,
        &["fuzz/corpus/opx", "tests/data/malformed/opx"],
    );
}

#[test]
fn dxf_corpus_and_malformed_files() {
    replay(
        dxf::fuzz_input,
        &["fuzz/corpus/dxf", "tests/data/malformed/dxf"],
    );
}

#[test]
fn mesh_corpora_and_malformed_files() {
    replay(
        obj::fuzz_input,
        &["fuzz/corpus/obj", "tests/data/malformed/obj"],
    );
    replay(
        stl::fuzz_input,
        &["fuzz/corpus/stl", "tests/data/malformed/stl"],
    );
}

#[test]
fn voxel_corpus_and_malformed_files() {
    replay(
        voxel::fuzz_input,
        &["fuzz/corpus/voxel", "tests/data/malformed/voxel"],
    );
}

#[test]
fn design_toml_corpus_and_malformed_files() {
    replay(
        design_toml::fuzz_input,
        &[
            "fuzz/corpus/design_toml",
            "tests/data/malformed/script",
            "tests/data/malformed/popup",
            "tests/data/malformed/papercraft",
        ],
    );
}

#[test]
fn profile_toml_corpus_and_malformed_files() {
    replay(
        profile_toml::fuzz_input,
        &[
            "fuzz/corpus/profile_toml",
            "tests/data/malformed/machine",
            "tests/data/malformed/material",
        ],
    );
}

#[test]
fn gcode_corpus_and_malformed_files() {
    replay(
        gcode::fuzz_input,
        &["fuzz/corpus/gcode", "tests/data/malformed/gcode"],
    );
}

/// libfuzzer-sys's macro, for the replay: the target's closure becomes `pub fn
/// fuzz_input` (defined after the modules, so that their `use` of it is what finds it).
#[macro_export]
macro_rules! fuzz_target {
    (|$data:ident: &[u8]| $body:block) => {
        pub fn fuzz_input($data: &[u8]) $body
    };
}
