//! The studio's fold-sequence designer over HTTP (Miyazaki et al. 1992): drags made through the
//! API, the saved script run through `foldcam fold`, and the two crease patterns compared; the
//! pattern checked against facts of the folds themselves.

use crate::bin;
use crate::studio;

use bin::{foldcam, repo_file};
use serde_json::{Value, json};
use studio::{Server, encode};

/// Coordinates of the two FOLD files agree this closely, millimetres.
const COORD_TOLERANCE: f64 = 1e-9;

const SIDE: f64 = 150.0;

fn get_json(server: &Server, path: &str) -> (u16, Value) {
    let (status, body) = server.get(path);
    (status, serde_json::from_slice(&body).expect("a JSON reply"))
}

fn ok(reply: (u16, Value)) -> Value {
    assert_eq!(reply.0, 200, "{}", reply.1);
    reply.1
}

/// A drag request: pointer from `from` to `to` (millimetres), picking within 3 mm.
fn gesture(from: [f64; 2], to: [f64; 2], operation: &str) -> Vec<u8> {
    serde_json::to_vec(&json!({
        "from": from, "to": to, "pick": 3.0, "operation": operation, "angle": 90.0,
    }))
    .unwrap()
}

/// The fold lines of a FOLD file: (ends sorted, each rounded to 1e-6 mm; assignment), sorted.
fn fold_lines(fold: &Value) -> Vec<([[i64; 2]; 2], String)> {
    let coords = fold["vertices_coords"].as_array().unwrap();
    let point = |i: &Value| {
        let c = &coords[i.as_u64().unwrap() as usize];
        [
            (c[0].as_f64().unwrap() * 1e6).round() as i64,
            (c[1].as_f64().unwrap() * 1e6).round() as i64,
        ]
    };
    let mut out: Vec<_> = fold["edges_vertices"]
        .as_array()
        .unwrap()
        .iter()
        .zip(fold["edges_assignment"].as_array().unwrap())
        .filter(|(_, a)| matches!(a.as_str(), Some("M" | "V")))
        .map(|(e, a)| {
            let mut ends = [point(&e[0]), point(&e[1])];
            ends.sort();
            (ends, a.as_str().unwrap().to_string())
        })
        .collect();
    out.sort();
    out
}

/// The key frame of the studio's FOLD equals the CLI's: counts, assignments, fold angles and
/// coordinates (within [`COORD_TOLERANCE`]), vertex for vertex and edge for edge.
fn assert_same_pattern(studio: &Value, cli: &Value) {
    for key in [
        "vertices_coords",
        "edges_vertices",
        "edges_assignment",
        "faces_vertices",
    ] {
        assert_eq!(
            studio[key].as_array().map(Vec::len),
            cli[key].as_array().map(Vec::len),
            "{key} counts"
        );
    }
    assert_eq!(studio["edges_vertices"], cli["edges_vertices"]);
    assert_eq!(studio["edges_assignment"], cli["edges_assignment"]);
    let numbers = |v: &Value| -> Vec<f64> {
        let mut out = Vec::new();
        let mut stack = vec![v];
        while let Some(x) = stack.pop() {
            match x {
                Value::Array(items) => stack.extend(items.iter().rev()),
                Value::Number(n) => out.push(n.as_f64().unwrap()),
                _ => {}
            }
        }
        out
    };
    for key in ["vertices_coords", "edges_foldAngle"] {
        let (a, b) = (numbers(&studio[key]), numbers(&cli[key]));
        assert_eq!(a.len(), b.len(), "{key}");
        for (x, y) in a.iter().zip(&b) {
            assert!((x - y).abs() <= COORD_TOLERANCE, "{key}: {x} vs {y}");
        }
    }
}

/// Saves session `id`'s script, runs `foldcam fold` on it, and returns (studio FOLD, CLI FOLD).
fn studio_and_cli(server: &Server, id: u64, dir: &std::path::Path) -> (Value, Value) {
    let (status, script) = server.get(&format!("/api/fold/{id}/script"));
    assert_eq!(status, 200);
    std::fs::write(dir.join("saved.toml"), &script).unwrap();
    let out = foldcam(&["fold", "saved.toml", "-o", "cli.fold"], dir);
    assert!(
        out.status.success(),
        "{}\n{}",
        String::from_utf8_lossy(&out.stderr),
        String::from_utf8_lossy(&script)
    );
    let cli: Value = serde_json::from_slice(&std::fs::read(dir.join("cli.fold")).unwrap()).unwrap();
    let (status, fold) = server.get(&format!("/api/fold/{id}/fold"));
    assert_eq!(status, 200);
    (serde_json::from_slice(&fold).unwrap(), cli)
}

#[test]
fn drags_in_the_studio_save_a_script_that_folds_the_same_pattern() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let new = ok(server.post_json("/api/fold/new", br#"{"sheet": {"square": 150}}"#));
    let id = new["id"].as_u64().unwrap();
    assert_eq!(new["step"], 0);

    // A preview: the fold line follows the pointer as the perpendicular bisector; the pointer
    // misses the corners a little and snapping puts it on them. Nothing is kept.
    let drag = gesture([149.4, 150.5], [0.6, -0.4], "bend");
    let preview = ok(server.post_json(&format!("/api/fold/{id}/preview"), &drag));
    for p in preview["line"].as_array().unwrap() {
        let (x, y) = (p[0].as_f64().unwrap(), p[1].as_f64().unwrap());
        assert!(
            (x + y - SIDE).abs() < 1e-9,
            "({x}, {y}) is off the diagonal"
        );
    }
    assert!(
        preview["snapped"].to_string().contains("vertex"),
        "{preview}"
    );
    assert!(preview["refused"].is_null());
    assert_eq!(preview["faces"].as_array().unwrap().len(), 2);
    assert_eq!(ok(get_json(&server, &format!("/api/fold/{id}")))["step"], 0);

    // The drag made: corner onto the opposite corner.
    let view = ok(server.post_json(&format!("/api/fold/{id}/drag"), &drag));
    assert_eq!(view["step"], 1);
    assert_eq!(view["steps"].as_array().unwrap().len(), 1);
    let (studio, cli) = studio_and_cli(&server, id, dir.path());
    assert_same_pattern(&studio, &cli);
    // Folded corner to corner, a square's crease is the other diagonal, side·√2 long, one
    // valley (the corner came up towards the eye).
    let lines = fold_lines(&cli);
    assert_eq!(lines.len(), 1, "{lines:?}");
    let ([a, b], assignment) = &lines[0];
    assert_eq!(assignment, "V");
    let length = ((a[0] - b[0]) as f64).hypot((a[1] - b[1]) as f64) * 1e-6;
    assert!((length - SIDE * 2f64.sqrt()).abs() < 1e-5, "{length}");
    assert_eq!(
        [*a, *b],
        [[0, 150_000_000], [150_000_000, 0]],
        "the diagonal from (150, 0) to (0, 150)"
    );

    // Tuck both sharp corners onto the right angle: the preliminary base, as the hand-written
    // example script folds it.
    for corner in [[150.0, 0.0], [0.0, 150.0]] {
        ok(server.post_json(
            &format!("/api/fold/{id}/drag"),
            &gesture(corner, [0.0, 0.0], "tuck"),
        ));
    }
    let (studio, cli) = studio_and_cli(&server, id, dir.path());
    assert_same_pattern(&studio, &cli);
    let example = repo_file("examples/folding/preliminary-base.toml");
    let out = foldcam(&["fold", &example, "-o", "example.fold"], dir.path());
    assert!(out.status.success());
    let example: Value =
        serde_json::from_slice(&std::fs::read(dir.path().join("example.fold")).unwrap()).unwrap();
    assert_eq!(fold_lines(&cli), fold_lines(&example));
    // Both midlines and one diagonal (each cut where they cross): 2 + 2 + 2 fold lines.
    assert_eq!(fold_lines(&cli).len(), 6);

    // Back one step: the script holds the steps up to the one shown; forward again.
    let back = ok(server.post_json(&format!("/api/fold/{id}/back"), b""));
    assert_eq!(
        (back["step"].as_u64(), back["last"].as_u64()),
        (Some(2), Some(3))
    );
    let (_, script) = server.get(&format!("/api/fold/{id}/script"));
    assert_eq!(
        String::from_utf8_lossy(&script).matches("[[step]]").count(),
        2
    );
    let forward = ok(server.post_json(&format!("/api/fold/{id}/forward"), b""));
    assert_eq!(forward["step"], 3);
    let (status, end) = server.post_json(&format!("/api/fold/{id}/forward"), b"");
    assert_eq!(status, 422, "{end}");

    // The result as a studio document: the pattern `foldcam check` sees in the CLI's file.
    let doc = ok(server.post_json(&format!("/api/fold/{id}/pattern"), b""));
    let counted = |a: &str| {
        cli["edges_assignment"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|x| x.as_str() == Some(a))
            .count()
    };
    assert_eq!(doc["counts"]["assignments"]["mountain"], counted("M"));
    assert_eq!(doc["counts"]["assignments"]["valley"], counted("V"));
    assert_eq!(
        doc["counts"]["vertices"],
        cli["vertices_coords"].as_array().unwrap().len()
    );
    let check = server.get(&format!("/api/docs/{}/check", doc["id"]));
    assert_eq!(check.0, 200);
}

#[test]
fn refused_folds_come_back_as_errors_and_change_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let id = ok(server.post_json("/api/fold/new", br#"{"sheet": {"square": 150}}"#))["id"]
        .as_u64()
        .unwrap();
    // The corner dragged far off the sheet: the bisector misses the paper.
    let away = gesture([150.0, 150.0], [400.0, 400.0], "bend");
    let preview = ok(server.post_json(&format!("/api/fold/{id}/preview"), &away));
    let refused = preview["refused"].as_str().expect("refused");
    assert!(refused.contains("misses the sheet"), "{refused}");
    let (status, body) = server.post_json(&format!("/api/fold/{id}/drag"), &away);
    assert_eq!(status, 422);
    assert_eq!(
        body["error"].as_str().unwrap(),
        format!("step 1: {refused}")
    );
    // No vertex near the press.
    let (status, body) = server.post_json(
        &format!("/api/fold/{id}/drag"),
        &gesture([75.0, 75.0], [0.0, 0.0], "bend"),
    );
    assert_eq!(status, 422);
    assert!(
        body["error"]
            .as_str()
            .unwrap()
            .starts_with("no vertex of the paper lies within 3 mm"),
        "{body}"
    );
    let (status, _) = server.post_json(&format!("/api/fold/{id}/back"), b"");
    assert_eq!(status, 422);
    assert_eq!(ok(get_json(&server, &format!("/api/fold/{id}")))["last"], 0);
    // A bad sheet and a bad script carry the CLI's messages.
    let (status, body) = server.post_json("/api/fold/new", br#"{"sheet": {"square": -1}}"#);
    assert_eq!(status, 422, "{body}");
    std::fs::write(
        dir.path().join("bad.toml"),
        "[sheet]\nsquare = 100\n[[step]]\n",
    )
    .unwrap();
    let out = foldcam(&["fold", "bad.toml", "-o", "x.fold"], dir.path());
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    let cli = stderr
        .lines()
        .find_map(|l| l.strip_prefix("foldcam: "))
        .expect("an error line");
    let (status, body) = server.post_json(
        &format!("/api/fold/script?name={}", encode("bad.toml")),
        b"[sheet]\nsquare = 100\n[[step]]\n",
    );
    assert_eq!(status, 422);
    assert_eq!(body["error"].as_str().unwrap(), cli);
}

#[test]
fn an_opened_script_replays_and_saves_back_to_the_same_fold() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let example = repo_file("examples/folding/bird-base.toml");
    let text = std::fs::read(&example).unwrap();
    let view = ok(server.post_json("/api/fold/script?name=bird-base.toml", &text));
    let id = view["id"].as_u64().unwrap();
    let steps = String::from_utf8_lossy(&text).matches("[[step]]").count();
    assert_eq!(view["step"].as_u64(), Some(steps as u64));
    assert_eq!(view["steps"].as_array().unwrap().len(), steps);
    // The saved script folds to the same file, frames and all, as the original.
    let (studio, cli) = studio_and_cli(&server, id, dir.path());
    let out = foldcam(&["fold", &example, "-o", "original.fold"], dir.path());
    assert!(out.status.success());
    let original: Value =
        serde_json::from_slice(&std::fs::read(dir.path().join("original.fold")).unwrap()).unwrap();
    assert_same_pattern(&cli, &original);
    assert_same_pattern(&studio, &original);
    assert_eq!(cli["file_frames"], original["file_frames"]);
}
