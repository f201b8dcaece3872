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
        foldcam(&["generate", "square-twist", "-o", t])
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
