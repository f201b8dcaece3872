//! Hostile inputs from the hardening review end with a clear refusal (exit 2, the option and
//! the limit named), never a hang or a panic.

use crate::bin;

use bin::foldcam;

#[test]
fn generators_refuse_sizes_beyond_a_kilometre() {
    let dir = tempfile::tempdir().expect("temp dir");
    for kind in ["miura", "square-twist", "waterbomb", "yoshimura"] {
        for (option, value) in [
            ("--width", "1e200"),
            ("--width", "1e308"),
            ("--height", "1e308"),
        ] {
            if kind == "waterbomb" && option == "--height" {
                continue;
            }
            let o = foldcam(
                &["generate", kind, "-o", "g.fold", option, value],
                dir.path(),
            );
            let err = String::from_utf8_lossy(&o.stderr);
            assert_eq!(o.status.code(), Some(2), "{kind} {option} {value}: {err}");
            assert!(
                err.contains("1,000,000 mm"),
                "{kind} {option} {value}: {err}"
            );
        }
    }
    assert!(!dir.path().join("g.fold").exists());
    // At the limit the pattern is made.
    let o = foldcam(
        &["generate", "miura", "-o", "g.fold", "--width", "1e6"],
        dir.path(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

#[test]
fn fold_pictures_beyond_the_pixel_limit_are_refused_with_a_width_that_fits() {
    let dir = tempfile::tempdir().expect("temp dir");
    let script = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("examples/folding/bird-base.toml")
        .to_string_lossy()
        .into_owned();
    for picture in ["--png", "--gif"] {
        let out = if picture == "--png" { "b.png" } else { "b.gif" };
        let o = foldcam(
            &[
                "fold", &script, "-o", "b.fold", picture, out, "--width", "16384",
            ],
            dir.path(),
        );
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert!(
            err.contains("--width 16384") && err.contains("or less"),
            "{err}"
        );
    }
    assert!(!dir.path().join("b.fold").exists());
}

/// Runs `args` in `dir` with standard output on `/dev/full` (every write fails with "no space
/// left on device").
fn to_full_device(args: &[&str], dir: &std::path::Path) -> std::process::Output {
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .expect("/dev/full (Linux) for the write-error tests");
    std::process::Command::new(env!("CARGO_BIN_EXE_foldcam"))
        .args(args)
        .current_dir(dir)
        .stdout(full)
        .output()
        .expect("the foldcam binary runs")
}

fn stderr(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// `args` followed by the machine and material every cutting test here uses.
fn on_machine<'a>(args: &[&'a str]) -> Vec<&'a str> {
    [args, &["-m", "grbl-diode", "-x", "card-300gsm"][..]].concat()
}

/// A temporary folder holding a generated Miura-ori, `m.fold`.
fn folder_with_miura() -> tempfile::TempDir {
    let dir = tempfile::tempdir().expect("temp dir");
    run_ok(&["generate", "miura", "-o", "m.fold"], dir.path());
    dir
}

fn run_ok(args: &[&str], dir: &std::path::Path) {
    let o = foldcam(args, dir);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
}

#[test]
fn a_full_disk_on_standard_output_is_an_error_not_a_panic() {
    let dir = folder_with_miura();
    run_ok(&on_machine(&["cut", "m.fold", "-o", "j.gcode"]), dir.path());
    let house = bin::repo_file("examples/popup/house.voxel.txt");
    let script = bin::repo_file("examples/folding/bird-base.toml");
    let runs: Vec<Vec<&str>> = vec![
        vec!["check", "m.fold"],
        vec!["check", "--json", "m.fold"],
        on_machine(&["plan", "m.fold"]),
        vec!["list", "machines"],
        vec!["simulate", "j.gcode", "-m", "grbl-diode"],
        vec!["fold", &script, "-o", "b.fold"],
        vec!["popup", "voxel", &house, "-o", "h.fold"],
        on_machine(&["cut", "m.fold", "-o", "k.gcode"]),
    ];
    for args in runs {
        let o = to_full_device(&args, dir.path());
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(
            err.contains("standard output") && err.contains("No space left"),
            "{args:?}: {err}"
        );
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
}

/// A folder holding `keep.fold` = "OLD" and a folder named `d.png`.
fn folder_with_a_trap() -> tempfile::TempDir {
    let dir = tempfile::tempdir().expect("temp dir");
    std::fs::write(dir.path().join("keep.fold"), "OLD").expect("write");
    std::fs::create_dir(dir.path().join("d.png")).expect("folder");
    dir
}

#[test]
fn an_output_that_is_a_folder_leaves_every_other_output_as_it_was() {
    let mesh = bin::repo_file("examples/tessellation/dome.obj");
    let script = bin::repo_file("examples/folding/bird-base.toml");
    for args in [
        vec!["tessellate", &mesh, "-o", "keep.fold", "--png", "d.png"],
        vec!["fold", &script, "-o", "keep.fold", "--png", "d.png"],
        vec!["fold3d", "m.fold", "-o", "keep.fold", "--png", "d.png"],
        vec!["fold-flat", "m.fold", "-o", "keep.fold", "--png", "d.png"],
    ] {
        let dir = folder_with_a_trap();
        run_ok(&["generate", "miura", "-o", "m.fold"], dir.path());
        let o = foldcam(&args, dir.path());
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains("d.png: is a folder"), "{args:?}: {err}");
        let kept = std::fs::read_to_string(dir.path().join("keep.fold")).expect("kept");
        assert_eq!(kept, "OLD", "{args:?}");
        assert_eq!(
            bin::listing(dir.path()),
            vec!["d.png", "keep.fold", "m.fold"],
            "{args:?}"
        );
    }
    // A two-sided job whose back is a folder keeps its front.
    let dir = folder_with_miura();
    std::fs::write(dir.path().join("job.front.gcode"), "OLD").expect("write");
    std::fs::create_dir(dir.path().join("job.back.gcode")).expect("folder");
    let o = foldcam(
        &on_machine(&["cut", "m.fold", "--two-sided", "-o", "job.gcode"]),
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("job.back.gcode: is a folder"));
    let front = std::fs::read_to_string(dir.path().join("job.front.gcode")).expect("kept");
    assert_eq!(front, "OLD");
}

#[test]
fn two_outputs_of_one_name_are_refused_before_the_work() {
    let dir = folder_with_miura();
    let vase = bin::repo_file("examples/papercraft/vase.craft.toml");
    for (args, culprit) in [
        (
            vec!["papercraft", &vase, "-o", "v.svg", "--svg", "./v.svg"],
            "named for two outputs",
        ),
        (
            vec!["fold-flat", "m.fold", "-o", "o.fold", "--png", "o.fold"],
            "o.fold",
        ),
    ] {
        let o = foldcam(&args, dir.path());
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(culprit), "{args:?}: {err}");
        assert_eq!(bin::listing(dir.path()), vec!["m.fold"], "{args:?}");
    }
}

#[test]
fn a_dash_is_standard_output_for_every_command_that_writes() {
    let dir = folder_with_miura();
    let script = bin::repo_file("examples/folding/bird-base.toml");
    for (args, starts) in [
        (
            vec!["fold", &script, "-o", "-", "--to", "svg"],
            &b"<?xml"[..],
        ),
        (
            vec!["generate", "waterbomb", "-o", "-", "--to", "fold"],
            &b"{"[..],
        ),
        (
            vec![
                "fold-flat",
                "m.fold",
                "-o",
                "f.fold",
                "--png",
                "-",
                "--to",
                "png",
            ],
            &b"\x89PNG"[..],
        ),
        (
            vec!["fold3d", "m.fold", "-o", "-", "--to", "fold"],
            &b"{"[..],
        ),
    ] {
        let o = foldcam(&args, dir.path());
        assert!(o.status.success(), "{args:?}: {}", stderr(&o));
        assert!(o.stdout.starts_with(starts), "{args:?}");
        assert!(
            !bin::listing(dir.path()).iter().any(|n| n.starts_with('-')),
            "{args:?} wrote a file named -"
        );
    }
    // Two outputs cannot both be standard output; a folder of pages cannot be.
    let o = foldcam(
        &["fold", &script, "-o", "-", "--png", "-", "--to", "png"],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let o = foldcam(&["demo", "--out", "-"], dir.path());
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("standard output"), "{}", stderr(&o));
}

#[test]
fn patterns_without_a_sheet_are_refused_not_passed() {
    let dir = tempfile::tempdir().expect("temp dir");
    for (kind, option) in [("waterbomb", "--width"), ("yoshimura", "--width")] {
        let o = foldcam(
            &["generate", kind, "-o", "g.fold", option, "1e-12"],
            dir.path(),
        );
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{kind}: {err}");
        assert!(err.contains("leave no sheet"), "{kind}: {err}");
    }
    std::fs::write(
        dir.path().join("line.fold"),
        r#"{"file_spec": 1.2, "frame_unit": "mm", "vertices_coords": [[0,0],[10,0],[20,0]],
            "edges_vertices": [[0,1],[1,2]], "edges_assignment": ["B","M"]}"#,
    )
    .expect("write");
    let o = foldcam(&["check", "line.fold"], dir.path());
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(!String::from_utf8_lossy(&o.stdout).contains("PASS"));
    assert!(stderr(&o).contains("one straight line"), "{}", stderr(&o));
    assert_eq!(bin::listing(dir.path()), vec!["line.fold"]);
}

#[test]
fn a_piece_smaller_than_the_kerf_and_a_dash_below_the_limit_are_refused_alike() {
    let dir = folder_with_miura();
    // (cut's option, testgrid's option, the value, what both say)
    for (cut_option, grid_option, value, said) in [
        ("--size", "--crease", "1e-9", "smaller than the kerf"),
        (
            "--dash",
            "--dash",
            "1e-300",
            "expected a number from 0.01 to 1000 mm",
        ),
    ] {
        let cut = on_machine(&["cut", "m.fold", cut_option, value, "-o", "j.gcode"]);
        let grid = on_machine(&["testgrid", grid_option, value, "-o", "g.gcode"]);
        for args in [cut, grid] {
            let o = foldcam(&args, dir.path());
            assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
            assert!(stderr(&o).contains(said), "{args:?}: {}", stderr(&o));
        }
    }
    assert_eq!(bin::listing(dir.path()), vec!["m.fold"]);
}

#[test]
fn a_diverged_fold_writes_nothing() {
    let dir = tempfile::tempdir().expect("temp dir");
    // A square twist a tenth of a micrometre across: the explicit dynamics blow up (the
    // static solve, the default, folds it).
    run_ok(
        &[
            "generate",
            "square-twist",
            "--width",
            "0.0001",
            "--height",
            "0.00004",
            "-o",
            "t.fold",
        ],
        dir.path(),
    );
    let o = foldcam(
        &[
            "fold3d", "t.fold", "-o", "f.fold", "--png", "f.png", "--method", "explicit",
        ],
        dir.path(),
    );
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.contains("diverged") && err.contains("nothing written"),
        "{err}"
    );
    assert_eq!(bin::listing(dir.path()), vec!["t.fold"]);
}

#[test]
fn a_re_triangulation_beyond_its_cap_is_refused_before_it_is_built() {
    let dir = tempfile::tempdir().expect("temp dir");
    let mesh = bin::repo_file("examples/tessellation/dome.obj");
    let o = foldcam(
        &["tessellate", &mesh, "-o", "t.fold", "--remesh", "100000000"],
        dir.path(),
    );
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("--remesh") && err.contains("50000"), "{err}");
    std::fs::write(
        dir.path().join("d.tess.toml"),
        format!("mesh = {mesh:?}\n\n[tessellation]\nremesh = \"only\"\nremesh_faces = 100000000\n"),
    )
    .expect("write");
    let o = foldcam(&["tessellate", "d.tess.toml", "-o", "t.fold"], dir.path());
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("remesh_faces") && err.contains("50000"),
        "{err}"
    );
}

/// An accordion of `pleats` parallel creases, alternately mountain and valley, 1 mm apart on
/// a strip 10 mm wide, as ORIPA's `.cp`: every panel folds onto the same place, one stack of
/// `pleats + 1` layers.
fn accordion(pleats: usize) -> String {
    let length = (pleats + 1) as f64;
    let mut text =
        format!("1 0 0 {length} 0\n1 {length} 0 {length} 10\n1 {length} 10 0 10\n1 0 10 0 0\n");
    for i in 1..=pleats {
        let kind = if i % 2 == 0 { 2 } else { 3 };
        text.push_str(&format!("{kind} {i} 0 {i} 10\n"));
    }
    text
}

#[test]
fn the_layer_search_stops_at_its_time_limit_and_a_deep_stack_is_refused_at_once() {
    let dir = tempfile::tempdir().expect("temp dir");
    std::fs::write(dir.path().join("a.cp"), accordion(3000)).expect("write");
    for args in [
        vec!["check", "--layers", "--time-limit", "1", "a.cp"],
        vec!["fold-flat", "a.cp", "-o", "a.fold", "--time-limit", "1"],
    ] {
        let o = foldcam(&args, dir.path());
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(
            err.contains("time limit of 1 s") || err.contains("transitivity constraints at least"),
            "{args:?}: {err}"
        );
    }
    // 200 layers in one stack: 1.3 million triples, within the limit; 800: 85 million, not.
    std::fs::write(dir.path().join("b.cp"), accordion(799)).expect("write");
    let o = foldcam(&["check", "--layers", "b.cp"], dir.path());
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("85013600 transitivity constraints at least"),
        "{err}"
    );
    // With --json the refusal is a report too: the local checks, and why no layer order.
    let o = foldcam(&["check", "--layers", "--json", "b.cp"], dir.path());
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let report: serde_json::Value =
        serde_json::from_slice(&o.stdout).expect("standard output is a JSON report");
    let why = report["layers"]["refused"]
        .as_str()
        .expect("layers.refused");
    assert!(
        why.contains("85013600 transitivity constraints at least"),
        "{why}"
    );
    assert!(report["verdict"].is_string(), "{report}");
    assert_eq!(bin::listing(dir.path()), vec!["a.cp", "b.cp"]);
}
