//! `foldcam check --layers`, `fold-flat` and the cutting commands' warning, run as a user
//! would; outputs read back (JSON parsed, FOLD re-imported).

use std::path::PathBuf;
use std::process::Command;

fn foldcam(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_foldcam"))
        .args(args)
        .output()
        .expect("foldcam runs")
}

fn grid(name: &str) -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/flat-folder")
        .join(name)
        .display()
        .to_string()
}

#[test]
fn check_layers_json_reports_the_published_count() {
    let out = foldcam(&[
        "check",
        &grid("002_brown_2x2_D1.fold"),
        "--layers",
        "--json",
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("one JSON object");
    assert_eq!(v["layers"]["states"], "16");
    assert_eq!(v["layers"]["exact"], true);
    assert!(v["layers"]["components"].as_u64().is_some());
}

#[test]
fn generated_square_twist_folds_and_fold_flat_writes_orders() {
    let dir = tempfile::tempdir().expect("temp dir");
    let twist = dir.path().join("twist.fold");
    let folded = dir.path().join("folded.fold");
    let png = dir.path().join("folded.png");
    let t = twist.to_str().expect("utf-8");
    assert!(
        // Folded flat (180°): a flat target the local check and the layer order judge.
        foldcam(&["generate", "square-twist", "--fold-angle", "180", "-o", t])
            .status
            .success()
    );
    let out = foldcam(&["check", t, "--layers", "--json"]);
    assert_eq!(out.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    assert_ne!(v["layers"]["states"], "0");
    let out = foldcam(&[
        "fold-flat",
        t,
        "-o",
        folded.to_str().expect("utf-8"),
        "--png",
        png.to_str().expect("utf-8"),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&folded).expect("written");
    let fold: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    let frame = &fold["file_frames"][0];
    assert_eq!(frame["frame_classes"][0], "foldedForm");
    let orders = frame["faceOrders"].as_array().expect("faceOrders");
    assert!(!orders.is_empty());
    // The folded form is flat and smaller than the sheet (the pleats hide paper).
    let coords = frame["vertices_coords"].as_array().expect("coords");
    assert!(
        coords
            .iter()
            .all(|c| c[2].as_f64().is_none_or(|z| z == 0.0))
    );
    let png_bytes = std::fs::read(&png).expect("png written");
    assert_eq!(&png_bytes[1..4], b"PNG");
    // A state beyond the count is refused without writing anything.
    let other = dir.path().join("other.fold");
    let out = foldcam(&[
        "fold-flat",
        t,
        "-o",
        other.to_str().expect("utf-8"),
        "--state",
        "99",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(!other.exists());
}

#[test]
fn unsatisfiable_pattern_exits_one_and_names_faces() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/flat-folder/001_ku_Bad_Twist.fold");
    let p = path.to_str().expect("utf-8");
    let out = foldcam(&["check", p, "--layers", "--json"]);
    assert_eq!(out.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    assert_eq!(v["layers"]["states"], "0");
    let faces = v["layers"]["contradiction"]["faces"]
        .as_array()
        .expect("faces");
    assert!(faces.len() >= 2);
    let ringed = v["findings"]
        .as_array()
        .expect("findings")
        .iter()
        .filter(|f| f["kind"] == "layer_order")
        .count();
    assert_eq!(ringed, faces.len());
    let dir = tempfile::tempdir().expect("temp dir");
    let out_path = dir.path().join("x.fold");
    let out = foldcam(&["fold-flat", p, "-o", out_path.to_str().expect("utf-8")]);
    assert_eq!(out.status.code(), Some(1));
    assert!(!out_path.exists());
}

/// Flat-Folder's grid 002 (16 states) turned by 17°, 100 units wide, every coordinate
/// rounded to 0.01, written as FOLD into `dir`.
fn rounded_grid(dir: &std::path::Path) -> String {
    let mut cp = foldcam::formats::load(grid("002_brown_2x2_D1.fold").as_ref())
        .expect("grid")
        .pattern;
    let turn = glam::DMat2::from_angle(17f64.to_radians());
    for p in &mut cp.vertices {
        *p = (turn * *p * 10_000.0).round() / 100.0;
    }
    let path = dir.join("rounded.fold");
    foldcam::formats::save(&path, &cp, None).expect("written");
    path.to_str().expect("utf-8").to_string()
}

#[test]
fn rounding_is_a_warning_beside_the_count_and_a_broken_vertex_is_refused() {
    let dir = tempfile::tempdir().expect("temp dir");
    let rounded = rounded_grid(dir.path());
    // The local check alone fails on the rounding …
    let out = foldcam(&["check", &rounded]);
    assert_eq!(out.status.code(), Some(1));
    // … the layer check counts the states and lists the rounding as warnings: exit 0.
    let out = foldcam(&["check", &rounded, "--layers", "--json"]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    assert_eq!(v["layers"]["states"], "16");
    let warnings = v["warnings"].as_array().expect("warnings");
    assert!(!warnings.is_empty());
    assert!(warnings.iter().all(|w| w["kind"] == "kawasaki"));
    assert_eq!(
        v["layers"]["rounding"].as_u64(),
        Some(warnings.len() as u64)
    );
    assert_eq!(v["layers"]["kawasaki_tolerance"], "fitted");
    let text =
        String::from_utf8_lossy(&foldcam(&["check", &rounded, "--layers"]).stdout).into_owned();
    assert!(text.contains("PASS with"), "{text}");
    // A fixed tolerance below the rounding refuses it, naming the vertex; one above passes
    // without warnings.
    let out = foldcam(&[
        "check",
        &rounded,
        "--layers",
        "--kawasaki-tolerance",
        "0.0001",
    ]);
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(
        text.contains("not locally flat-foldable: kawasaki at v"),
        "{text}"
    );
    let out = foldcam(&[
        "check",
        &rounded,
        "--layers",
        "--kawasaki-tolerance",
        "1",
        "--json",
    ]);
    assert_eq!(out.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    assert!(v.get("warnings").is_none());
    // fold-flat folds it too, saying so on standard error.
    let folded = dir.path().join("folded.fold");
    let out = foldcam(&["fold-flat", &rounded, "-o", folded.to_str().expect("utf-8")]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(String::from_utf8_lossy(&out.stderr).contains("within the drawing's precision"));
    assert!(folded.exists());
    // A vertex off by 5° is refused by name, and fold-flat writes nothing.
    let broken =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/patterns/broken-vertex.fold");
    let b = broken.to_str().expect("utf-8");
    let out = foldcam(&["check", b, "--layers"]);
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(text.contains("kawasaki at v0"), "{text}");
    assert!(text.contains("5.0000°"), "{text}");
    let not_written = dir.path().join("broken.fold");
    let out = foldcam(&["fold-flat", b, "-o", not_written.to_str().expect("utf-8")]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("kawasaki at v0"));
    assert!(!not_written.exists());
}

#[test]
fn a_kawasaki_tolerance_of_zero_or_ninety_degrees_is_refused() {
    let p = grid("002_brown_2x2_D1.fold");
    for bad in ["0", "90", "nan", "x"] {
        for command in ["check", "fold-flat"] {
            let mut args = vec![command, p.as_str(), "--kawasaki-tolerance", bad];
            if command == "fold-flat" {
                args.extend(["-o", "/nonexistent/never.fold"]);
            }
            let out = foldcam(&args);
            assert_eq!(out.status.code(), Some(2), "{command} {bad}");
            let err = String::from_utf8_lossy(&out.stderr);
            assert!(
                err.contains("--kawasaki-tolerance") && err.contains("to 45 degrees"),
                "{command} {bad}: {err}"
            );
        }
    }
}

/// `fold-flat` on Flat-Folder's 2×2 grid (16 states): each state written is the flat sheet
/// folded without stretching, flat, smaller than the sheet, with `faceOrders` the layer solver
/// admits; states 0 and 1 are different orders.
#[test]
fn fold_flat_states_are_isometric_admitted_and_distinct() {
    use foldcam::check::layers::{LayerOptions, LayerSolver};
    use foldcam::pattern::{PlanarizeOptions, planarize};

    let dir = tempfile::tempdir().expect("temp dir");
    let mut orders = Vec::new();
    for state in ["0", "1"] {
        let out_path = dir.path().join(format!("state{state}.fold"));
        let out = foldcam(&[
            "fold-flat",
            &grid("002_brown_2x2_D1.fold"),
            "-o",
            out_path.to_str().expect("utf-8"),
            "--state",
            state,
        ]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let imported = foldcam::formats::load(&out_path).expect("reads back");
        let folded = imported.folded.expect("a foldedForm frame");
        let mut flat = imported.pattern;
        // Isometric: every edge keeps its length.
        let (mut lo, mut hi) = (glam::DVec2::splat(f64::MAX), glam::DVec2::splat(f64::MIN));
        crate::isometry::assert_isometric(&flat, &folded, 1e-6, &format!("state {state}"));
        for p in &folded.positions {
            assert!(p.z.abs() < 1e-9, "state {state}: not flat");
            lo = lo.min(p.truncate());
            hi = hi.max(p.truncate());
        }
        let (flo, fhi) = flat.bounds().expect("vertices");
        let area = |a: glam::DVec2, b: glam::DVec2| (b - a).x * (b - a).y;
        assert!(
            area(lo, hi) < 0.9 * area(flo, fhi),
            "state {state}: no smaller than the sheet"
        );
        // The orders written are a state of the layer problem.
        planarize(
            &mut flat,
            &PlanarizeOptions {
                tolerance: None,
                faces: true,
            },
        )
        .expect("planarises");
        let solver = LayerSolver::new(&flat, &LayerOptions::default()).expect("layer problem");
        assert_eq!(solver.report().states, "16");
        assert!(!folded.face_orders.is_empty());
        assert!(
            solver.admits(&folded.face_orders),
            "state {state} not admitted"
        );
        orders.push(folded.face_orders);
    }
    let as_set = |o: &Vec<_>| o.iter().copied().collect::<std::collections::BTreeSet<_>>();
    assert!(
        as_set(&orders[0]) != as_set(&orders[1]),
        "state 1 repeats state 0 ({} face orders)",
        orders[0].len()
    );
}
