//! The studio's polygon pop-up editor over HTTP (Mitani & Suzuki 2004): faces added, moved and
//! resized through the API, the live pop-up check naming the failing face, undo and redo, the
//! saved design run through `foldcam popup poly` and its crease pattern compared with the one
//! the editor shows, and the card at an opening angle compared with eq. 2 and eq. 7 worked by
//! hand.

use crate::bin;
use crate::lines;
use crate::studio;

use bin::{foldcam, repo_file};
use lines::{Lines, fold_lines};
use serde_json::{Value, json};
use studio::{Server, encode};

/// Coordinates agree this closely, millimetres.
const COORD_TOLERANCE: f64 = 1e-6;

fn ok(reply: (u16, Value)) -> Value {
    assert_eq!(reply.0, 200, "{}", reply.1);
    reply.1
}

fn post(server: &Server, path: &str, body: Value) -> (u16, Value) {
    server.post_json(path, &serde_json::to_vec(&body).unwrap())
}

fn get_json(server: &Server, path: &str) -> (u16, Value) {
    let (status, body) = server.get(path);
    (status, serde_json::from_slice(&body).expect("a JSON reply"))
}

fn rect(x0: f64, w0: f64, x1: f64, w1: f64) -> Value {
    json!([[x0, w0], [x1, w0], [x1, w1], [x0, w1]])
}

fn round(v: f64) -> i64 {
    (v / COORD_TOLERANCE).round() as i64
}

/// The lines of a view: `edges` as `[[i, j], letter]` (the editor's) or `{v, a}` (a document's).
fn view_lines(vertices: &Value, edges: &Value) -> Lines {
    let coords = vertices.as_array().unwrap();
    let point = |i: &Value| {
        let c = &coords[i.as_u64().unwrap() as usize];
        [round(c[0].as_f64().unwrap()), round(c[1].as_f64().unwrap())]
    };
    let mut out: Lines = edges
        .as_array()
        .unwrap()
        .iter()
        .map(|e| {
            let (ends, letter) = if e.is_array() {
                (&e[0], e[1].as_str().unwrap())
            } else {
                (&e["v"], e["a"].as_str().unwrap())
            };
            let mut ends = [point(&ends[0]), point(&ends[1])];
            ends.sort();
            (ends, letter.to_string())
        })
        .collect();
    out.sort();
    out
}

/// A new 120 × 60 × 80 mm card with a wall 30 mm in front of the back sheet, x 40..80 and
/// 20 mm high (the first operation).
fn card_with_wall(server: &Server) -> (u64, Value) {
    let view = ok(post(
        server,
        "/api/popup/new",
        json!({"width": 120.0, "depth": 60.0, "height": 80.0}),
    ));
    assert_eq!(view["valid"], true, "a blank card pops up (it lies flat)");
    let id = view["id"].as_u64().unwrap();
    let view = ok(post(
        server,
        &format!("/api/popup/{id}/edit"),
        json!({"add": {"plane": "vertical", "at": 30.0, "polygon": rect(40.0, 0.0, 80.0, 20.0)}}),
    ));
    (id, view)
}

#[test]
fn a_wall_alone_is_named_and_a_roof_makes_the_card_the_cli_makes() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let (id, view) = card_with_wall(&server);
    // A wall on the base with nothing to the back sheet does not rise (Mitani & Suzuki 2004,
    // Fig. 7): named as operation 1, outlined where eq. 1 puts it, v = z − y from −30 to −10.
    assert_eq!(view["valid"], false);
    let findings = view["findings"].as_array().unwrap();
    assert_eq!(findings.len(), 1, "{findings:?}");
    assert_eq!(findings[0]["operation"], 1);
    let words = findings[0]["words"].as_str().unwrap();
    assert!(words.contains("operation 1 (y = 30 mm)"), "{words}");
    assert!(words.contains("held from the base sheet only"), "{words}");
    let vs: Vec<f64> = findings[0]["outline"][0]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p[1].as_f64().unwrap())
        .collect();
    let (lo, hi) = vs
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &v| {
            (l.min(v), h.max(v))
        });
    assert_eq!((lo, hi), (-30.0, -10.0));
    // The CLI refuses the same design, at the same operation.
    let (status, text) = server.get(&format!("/api/popup/{id}/design"));
    assert_eq!(status, 200);
    std::fs::write(dir.path().join("wall.popup.toml"), &text).unwrap();
    let out = foldcam(
        &["popup", "poly", "wall.popup.toml", "-o", "wall.fold"],
        dir.path(),
    );
    // Exit 1: the card's own check refused it, the report on standard output.
    assert_eq!(out.status.code(), Some(1));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("invalid at operation 1"), "{stdout}");
    assert!(!dir.path().join("wall.fold").exists());

    // The roof, from the back sheet to the wall's top: the card pops up.
    let view = ok(post(
        &server,
        &format!("/api/popup/{id}/edit"),
        json!({"add": {"plane": "horizontal", "at": 20.0, "polygon": rect(40.0, 0.0, 80.0, 30.0)}}),
    ));
    assert_eq!(view["valid"], true, "{}", view["lines"]);
    assert!(view["findings"].as_array().unwrap().is_empty());

    // Saved, built by `foldcam popup poly`: the pattern the editor shows, line for line.
    let (status, text) = server.get(&format!("/api/popup/{id}/design"));
    assert_eq!(status, 200);
    std::fs::write(dir.path().join("box.popup.toml"), &text).unwrap();
    let out = foldcam(
        &["popup", "poly", "box.popup.toml", "-o", "box.fold"],
        dir.path(),
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let cli: Value =
        serde_json::from_slice(&std::fs::read(dir.path().join("box.fold")).unwrap()).unwrap();
    let cli_lines = fold_lines(&cli, COORD_TOLERANCE);
    let shown = view_lines(&view["pattern"]["vertices"], &view["pattern"]["edges"]);
    assert_eq!(shown, cli_lines);
    // The box's own folds where eq. 1 puts them by hand, x 40..80: the roof on the back
    // sheet (v = 20), roof on wall (v = −10), wall on base (v = −30).
    for v in [20.0, -10.0, -30.0] {
        let ends = [[round(40.0), round(v)], [round(80.0), round(v)]];
        assert!(
            cli_lines
                .iter()
                .any(|(e, a)| *e == ends && (a == "M" || a == "V")),
            "no fold at v = {v}: {cli_lines:?}"
        );
    }

    // To a crease pattern document: the same lines again.
    let doc = ok(server.post_json(&format!("/api/popup/{id}/pattern"), b""));
    assert_eq!(doc["made"], "polygon pop-up card (Mitani & Suzuki 2004)");
    assert_eq!(view_lines(&doc["vertices"], &doc["edges"]), cli_lines);

    // Undo goes back to the wall alone, redo to the box.
    let back = ok(server.post_json(&format!("/api/popup/{id}/undo"), b""));
    assert_eq!(back["operations"].as_array().unwrap().len(), 1);
    assert_eq!(back["valid"], false);
    assert_eq!(back["history"], json!({"undo": true, "redo": true}));
    let again = ok(server.post_json(&format!("/api/popup/{id}/redo"), b""));
    assert_eq!(again["valid"], true);
    assert_eq!(again["history"]["redo"], false);
}

#[test]
fn moves_and_resizes_are_the_papers_operations_and_refusals_change_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let (id, _) = card_with_wall(&server);
    let edit = |body: Value| post(&server, &format!("/api/popup/{id}/edit"), body);
    ok(edit(
        json!({"add": {"plane": "horizontal", "at": 20.0, "polygon": rect(40.0, 0.0, 80.0, 30.0)}}),
    ));
    // Moving the wall 10 mm forward leaves the roof 10 mm short of it.
    let moved = ok(edit(
        json!({"move": {"operation": 1, "by": [0.0, 10.0, 0.0]}}),
    ));
    assert_eq!(moved["operations"][0]["at"], 40.0);
    assert_eq!(moved["valid"], false);
    assert_eq!(moved["findings"][0]["operation"], 1);
    // Stretching the roof to reach it mends the card.
    let mended = ok(edit(
        json!({"resize": {"operation": 2, "lo": [40.0, 0.0], "hi": [80.0, 40.0]}}),
    ));
    assert_eq!(mended["valid"], true, "{}", mended["lines"]);
    assert_eq!(mended["operations"][1]["hi"], json!([80.0, 40.0]));
    // A move beyond the base is refused with the operation named; nothing changes.
    let (status, body) = edit(json!({"move": {"operation": 1, "by": [0.0, 30.0, 0.0]}}));
    assert_eq!(status, 422);
    let error = body["error"].as_str().unwrap();
    assert!(error.contains("operation 1"), "{error}");
    assert!(error.contains("outside the card"), "{error}");
    let still = ok(get_json(&server, &format!("/api/popup/{id}")));
    assert_eq!(still["operations"], mended["operations"]);
    // Removing an operation the design lacks is refused too.
    let (status, body) = edit(json!({"remove": {"operation": 9}}));
    assert_eq!(status, 422);
    assert!(body["error"].as_str().unwrap().contains("no operation 9"));
    // An opening in the wall (Mitani & Suzuki 2004, §3.3): still a card the CLI makes.
    let door = ok(edit(
        json!({"add": {"plane": "vertical", "at": 40.0, "add": "opening",
        "polygon": rect(55.0, 0.0, 65.0, 12.0)}}),
    ));
    assert_eq!(door["operations"][2]["opening"], true);
    assert_eq!(door["valid"], true, "{}", door["lines"]);
    let (_, text) = server.get(&format!("/api/popup/{id}/design"));
    std::fs::write(dir.path().join("door.popup.toml"), &text).unwrap();
    let out = foldcam(
        &["popup", "poly", "door.popup.toml", "-o", "door.fold"],
        dir.path(),
    );
    assert!(out.status.success());
    let cli: Value =
        serde_json::from_slice(&std::fs::read(dir.path().join("door.fold")).unwrap()).unwrap();
    assert_eq!(
        view_lines(&door["pattern"]["vertices"], &door["pattern"]["edges"]),
        fold_lines(&cli, COORD_TOLERANCE)
    );
}

#[test]
fn the_card_at_an_angle_is_where_eq_7_puts_it() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let (id, _) = card_with_wall(&server);
    ok(post(
        &server,
        &format!("/api/popup/{id}/edit"),
        json!({"add": {"plane": "horizontal", "at": 20.0, "polygon": rect(40.0, 0.0, 80.0, 30.0)}}),
    ));
    // Standing at 90°: the wall is the rectangle x 40..80, y = 30, z 0..20 (eq. 2).
    let card = ok(get_json(&server, &format!("/api/popup/{id}/card?angle=90")));
    let faces = card["faces"].as_array().unwrap();
    let points =
        |f: &Value| -> Vec<[f64; 3]> { serde_json::from_value(f["space"][0].clone()).unwrap() };
    let near = |a: f64, b: f64| (a - b).abs() < COORD_TOLERANCE;
    let wall = faces
        .iter()
        .map(points)
        .find(|p| p.iter().all(|q| near(q[1], 30.0)) && p.iter().any(|q| near(q[2], 20.0)));
    let wall = wall.expect("a face on the plane y = 30");
    for q in &wall {
        assert!((40.0 - 1e-9..=80.0 + 1e-9).contains(&q[0]), "{q:?}");
        assert!((-1e-9..=20.0 + 1e-9).contains(&q[2]), "{q:?}");
    }
    // Opened flat (180°), eq. 7 with θ = 0 puts every pattern point (x, v) at (x, −v, 0).
    let flat = ok(get_json(
        &server,
        &format!("/api/popup/{id}/card?angle=180"),
    ));
    for f in flat["faces"].as_array().unwrap() {
        let on_pattern: Vec<[f64; 2]> = serde_json::from_value(f["flat"][0].clone()).unwrap();
        for (p, q) in on_pattern.iter().zip(points(f)) {
            assert!(
                near(q[0], p[0]) && near(q[1], -p[1]) && near(q[2], 0.0),
                "{p:?} → {q:?}"
            );
        }
    }
    let (status, body) = get_json(&server, &format!("/api/popup/{id}/card?angle=200"));
    assert_eq!(status, 422);
    assert!(body["error"].as_str().unwrap().contains("0 to 180"));
}

#[test]
fn a_bundled_design_opens_for_editing_and_saves_as_the_cli_reads_it() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let path = repo_file("examples/popup/house-door.popup.toml");
    let text = std::fs::read(&path).unwrap();
    let view = ok(server.post_json(
        &format!("/api/popup/design?name={}", encode("house-door.popup.toml")),
        &text,
    ));
    assert_eq!(view["valid"], true, "{}", view["lines"]);
    assert_eq!(view["operations"].as_array().unwrap().len(), 4);
    // In millimetres whatever the file's units: the wall at 6 grid units of 5 mm.
    assert_eq!(view["operations"][0]["at"], 30.0);
    let id = view["id"].as_u64().unwrap();
    let (_, saved) = server.get(&format!("/api/popup/{id}/design"));
    std::fs::write(dir.path().join("saved.popup.toml"), &saved).unwrap();
    for (file, out) in [
        (path.as_str(), "original.fold"),
        ("saved.popup.toml", "saved.fold"),
    ] {
        let o = foldcam(&["popup", "poly", file, "-o", out], dir.path());
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    let read = |n: &str| -> Value {
        serde_json::from_slice(&std::fs::read(dir.path().join(n)).unwrap()).unwrap()
    };
    assert_eq!(
        fold_lines(&read("saved.fold"), COORD_TOLERANCE),
        fold_lines(&read("original.fold"), COORD_TOLERANCE)
    );
    // A file that is not a design is refused with its name and place.
    let (status, body) = server.post_json(
        &format!("/api/popup/design?name={}", encode("bad.popup.toml")),
        b"[card]\nwidth = 1\n",
    );
    assert_eq!(status, 422);
    assert!(
        body["error"]
            .as_str()
            .unwrap()
            .starts_with("bad.popup.toml: ")
    );
}
