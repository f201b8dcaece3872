//! The layers of ARCHITECTURE.md, checked on the source: no module imports from a layer
//! above it or beside it. Layers, bottom up: clock, limits and geom; mesh and pattern; formats and check;
//! design and render; machine; fab; post; sim; job; studio.

use std::path::{Path, PathBuf};

/// Each top-level module of the library and its layer (lower may not use higher or equal).
const LAYERS: &[(&str, u8)] = &[
    ("clock", 0),
    ("limits", 0),
    ("geom", 0),
    ("mesh", 1),
    ("pattern", 1),
    ("formats", 2),
    ("check", 2),
    ("design", 3),
    ("render", 3),
    ("machine", 4),
    ("fab", 5),
    ("post", 6),
    ("sim", 7),
    ("job", 8),
    ("studio", 9),
];

fn layer(name: &str) -> Option<u8> {
    LAYERS.iter().find(|(n, _)| *n == name).map(|&(_, l)| l)
}

fn rust_files(path: &Path, out: &mut Vec<PathBuf>) {
    if path.is_file() {
        out.push(path.to_path_buf());
        return;
    }
    let Ok(entries) = std::fs::read_dir(path) else {
        return;
    };
    for entry in entries.flatten() {
        let p = entry.path();
        if p.is_dir() || p.extension().is_some_and(|e| e == "rs") {
            rust_files(&p, out);
        }
    }
}

/// The top-level modules a line of code names through `crate::`, including `crate::{a, b}`.
fn crate_paths(line: &str) -> Vec<String> {
    let mut names = Vec::new();
    let mut rest = line;
    while let Some(i) = rest.find("crate::") {
        rest = &rest[i + "crate::".len()..];
        if let Some(group) = rest.strip_prefix('{') {
            let end = group.find('}').unwrap_or(group.len());
            for item in group[..end].split(',') {
                let name: String = item
                    .trim()
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                names.push(name);
            }
        } else {
            names.push(
                rest.chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect(),
            );
        }
    }
    names
}

/// Every `crate::` path (outside comments) from a module to a module not below it.
fn violations() -> Vec<String> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut found = Vec::new();
    for &(module, rank) in LAYERS {
        let mut files = Vec::new();
        rust_files(&src.join(module), &mut files);
        rust_files(&src.join(format!("{module}.rs")), &mut files);
        assert!(!files.is_empty(), "src/{module} not found");
        for file in files {
            let text = std::fs::read_to_string(&file).unwrap();
            for (n, line) in text.lines().enumerate() {
                if line.trim_start().starts_with("//") {
                    continue;
                }
                for target in crate_paths(line) {
                    let Some(other) = layer(&target) else {
                        continue;
                    };
                    if target != module && other >= rank {
                        found.push(format!(
                            "{}:{}: {module} uses {target}",
                            file.strip_prefix(&src).unwrap().display(),
                            n + 1
                        ));
                    }
                }
            }
        }
    }
    found
}

#[test]
fn the_parser_sees_plain_and_grouped_paths() {
    assert_eq!(crate_paths("use crate::fab::Operation;"), ["fab"]);
    assert_eq!(
        crate_paths("use crate::{machine::Bed, pattern};"),
        ["machine", "pattern"]
    );
    assert!(crate_paths("use super::Operation;").is_empty());
}

#[test]
fn every_library_module_is_listed_in_a_layer() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    for entry in std::fs::read_dir(&src).unwrap().flatten() {
        let p = entry.path();
        let name = p.file_stem().unwrap().to_string_lossy().into_owned();
        if ["lib", "main", "cli", "test_rng"].contains(&name.as_str()) {
            continue;
        }
        if p.is_dir() || p.extension().is_some_and(|e| e == "rs") {
            assert!(layer(&name).is_some(), "src/{name} is in no layer");
        }
    }
}

#[test]
fn no_module_imports_from_a_layer_above_it() {
    let v = violations();
    assert!(
        v.is_empty(),
        "{} imports against the layers:\n{}",
        v.len(),
        v.join("\n")
    );
}

/// The public modules: the areas and the sub-areas that are namespaces of their own. Every
/// other module is private or `pub(crate)` and its API is re-exported by its area's `pub use`
/// list, so the documented surface stays curated. A new public module is a decision: add it
/// here only if it is a namespace a library user needs (else `pub(crate) mod` and `pub use`).
const PUBLIC_MODULES: &[&str] = &[
    "check",
    "check::fold3d",
    "check::layers",
    "clock",
    "design",
    "design::classic",
    "design::folding",
    "design::papercraft",
    "design::popup",
    "design::popup::polygon",
    "design::popup::voxel",
    "design::source",
    "design::source::craft",
    "design::source::poly",
    "design::source::script",
    "design::source::tess_design",
    "design::source::tessellate",
    "design::source::voxel",
    "design::tessellation",
    "design::tessellation::measure",
    "design::tessellation::rigid",
    "design::tessellation::rigid::model",
    "design::tessellation::samples",
    "design::tessellation::steps",
    "fab",
    "fab::testgrid",
    "formats",
    "formats::cp",
    "formats::dxf",
    "formats::fold",
    "formats::opx",
    "formats::svg",
    "geom",
    "geom::tolerance",
    "job",
    "limits",
    "machine",
    "mesh",
    "pattern",
    "pattern::edit",
    "pattern::snap",
    "post",
    "post::gcode",
    "render",
    "sim",
    "studio",
];

/// Every `pub mod name;` of the library, as its path from the crate root (`a::b::name`).
fn public_modules() -> Vec<String> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    let mut found = Vec::new();
    for file in files {
        let rel = file.strip_prefix(&src).unwrap();
        if rel.starts_with("cli") || rel == Path::new("main.rs") {
            continue;
        }
        let mut parent: Vec<String> = rel
            .with_extension("")
            .components()
            .map(|c| c.as_os_str().to_string_lossy().into_owned())
            .collect();
        if parent.last().is_some_and(|l| l == "mod" || l == "lib") {
            parent.pop();
        }
        let text = std::fs::read_to_string(&file).unwrap();
        for line in text.lines() {
            let Some(name) = line.trim_start().strip_prefix("pub mod ") else {
                continue;
            };
            let name = name.trim_end_matches(';').trim();
            let mut path = parent.clone();
            path.push(name.to_string());
            found.push(path.join("::"));
        }
    }
    found.sort();
    found
}

#[test]
fn public_modules_are_the_curated_list() {
    let found = public_modules();
    assert!(
        found.iter().any(|m| m == "pattern"),
        "no module found: {found:?}"
    );
    let unlisted: Vec<&String> = found
        .iter()
        .filter(|m| !PUBLIC_MODULES.contains(&m.as_str()))
        .collect();
    assert!(
        unlisted.is_empty(),
        "public modules outside the curated list (make them `pub(crate) mod` and re-export \
         what users need from the area's `pub use` list): {unlisted:?}"
    );
    let stale: Vec<&&str> = PUBLIC_MODULES
        .iter()
        .filter(|m| !found.iter().any(|f| f == *m))
        .collect();
    assert!(
        stale.is_empty(),
        "listed but not public any more: {stale:?}"
    );
}

/// The names a module file exports at its top level, parsed from its source: every name a
/// `pub use` brings in (the alias when renamed), every `pub mod`, and every `pub` item the
/// file defines outside braces (`pub fn`, `pub struct`, `pub enum`, `pub const`, ...). A
/// glob re-export (`pub use a::*`) cannot be counted and is reported as `*`.
fn exported_names(source: &str) -> Vec<String> {
    let code: String = source
        .lines()
        .map(|l| l.split("//").next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join("\n");
    let mut names = Vec::new();
    let mut depth = 0usize;
    let mut i = 0;
    let bytes = code.as_bytes();
    while i < bytes.len() {
        match bytes[i] {
            b'{' => depth += 1,
            b'}' => depth = depth.saturating_sub(1),
            b'p' if depth == 0
                && code[i..].starts_with("pub ")
                && (i == 0 || !bytes[i - 1].is_ascii_alphanumeric()) =>
            {
                let rest = code[i + 4..].trim_start();
                let word: String = rest
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                if word == "use" {
                    let end = rest.find(';').unwrap_or(rest.len());
                    let tree = &rest[3..end];
                    for piece in tree.split(['{', '}', ',']) {
                        let piece = piece.trim();
                        if piece.is_empty() || piece.ends_with("::") {
                            continue;
                        }
                        let leaf = match piece.split_once(" as ") {
                            Some((_, alias)) => alias.trim(),
                            None => piece.rsplit("::").next().unwrap_or(piece),
                        };
                        names.push(leaf.to_string());
                    }
                    i += 4 + (code[i + 4..].len() - rest.len()) + end;
                    continue;
                }
                let after = rest[word.len()..].trim_start();
                let name: String = after
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                if !name.is_empty() {
                    names.push(name);
                }
            }
            _ => {}
        }
        i += 1;
    }
    names
}

#[test]
fn the_export_counter_sees_uses_modules_and_items() {
    let source = "//! Docs.\npub mod rigid;\npub(crate) mod model;\n\
                  pub use a::{B, c::{D, E as F}};\npub use g::H;\n\
                  /// Doc.\npub enum Error { A }\nimpl Error { pub fn x() {} }\npub fn run() {}\n";
    assert_eq!(
        exported_names(source),
        ["rigid", "B", "D", "F", "H", "Error", "run"]
    );
}

/// Issue 37, "a narrow surface": `design::tessellation` offers one entry point and a few
/// named submodules, not every step of its pipeline at the top level.
#[test]
fn tessellation_exports_at_most_twenty_names() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/design/tessellation/mod.rs");
    let names = exported_names(&std::fs::read_to_string(path).unwrap());
    assert!(
        names.len() <= 20 && !names.iter().any(|n| n == "*"),
        "design::tessellation exports {} names at its top level (at most 20, no globs): \
         {names:?}",
        names.len()
    );
}

/// The design sub-areas (ARCHITECTURE.md's table: `design::tessellation` uses mesh and
/// pattern, `design::papercraft` mesh, geom and pattern, `design::popup` pattern and geom, ...)
/// do not use each other; only `design::source` ties them together. The files directly in
/// `src/design/` (`estimate.rs`) are the area's own and shared.
#[test]
fn design_sub_areas_do_not_use_each_other() {
    let design = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/design");
    let areas: Vec<String> = std::fs::read_dir(&design)
        .unwrap()
        .flatten()
        .filter(|e| e.path().is_dir())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    assert!(areas.iter().any(|a| a == "tessellation"), "{areas:?}");
    let mut found = Vec::new();
    for area in areas.iter().filter(|a| *a != "source") {
        let mut files = Vec::new();
        rust_files(&design.join(area), &mut files);
        for file in files {
            let text = std::fs::read_to_string(&file).unwrap();
            for (n, line) in text.lines().enumerate() {
                if line.trim_start().starts_with("//") {
                    continue;
                }
                for used in crate_paths(&line.replace("crate::design::", "crate::")) {
                    if used != *area && areas.contains(&used) {
                        found.push(format!(
                            "{}:{}: design::{area} uses design::{used}",
                            file.strip_prefix(&design).unwrap().display(),
                            n + 1
                        ));
                    }
                }
            }
        }
    }
    assert!(found.is_empty(), "{}", found.join("\n"));
}
