//! The studio's voxel pop-up editor over HTTP (Mitani, Suzuki & Uno 2003): voxels added on
//! the front and side views through the API, the saved `.voxel.txt` run through `foldcam popup
//! voxel`, and the two crease patterns compared; faults named at their place, as the command
//! refuses the same card.

use crate::bin;
use crate::studio;

use bin::{foldcam, repo_file};
use serde_json::{Value, json};
use studio::{Server, encode};

/// Coordinates of the two patterns agree this closely, millimetres.
const COORD_TOLERANCE_MM: f64 = 1e-9;

fn ok(reply: (u16, Value)) -> Value {
    assert_eq!(reply.0, 200, "{}", reply.1);
    reply.1
}

fn get_json(server: &Server, path: &str) -> (u16, Value) {
    let (status, body) = server.get(path);
    (status, serde_json::from_slice(&body).expect("a JSON reply"))
}

fn edit(server: &Server, id: u64, body: Value) -> (u16, Value) {
    server.post_json(
        &format!("/api/voxel/{id}/edit"),
        &serde_json::to_vec(&body).unwrap(),
    )
}

/// Two pattern views (`/api/upload` or a pattern route) hold the same pattern.
fn assert_same_pattern(got: &Value, want: &Value) {
    assert_eq!(got["counts"], want["counts"], "counts");
    let edges = |v: &Value| -> Vec<Value> {
        v["edges"]
            .as_array()
            .unwrap()
            .iter()
            .map(|e| json!([e["v"], e["a"]]))
            .collect()
    };
    assert_eq!(edges(got), edges(want), "edges and assignments");
    let (a, b) = (
        got["vertices"].as_array().unwrap(),
        want["vertices"].as_array().unwrap(),
    );
    assert_eq!(a.len(), b.len());
    for (p, q) in a.iter().zip(b) {
        for k in 0..2 {
            let d = (p[k].as_f64().unwrap() - q[k].as_f64().unwrap()).abs();
            assert!(d <= COORD_TOLERANCE_MM, "{p} vs {q}");
        }
    }
}

/// Depths of the saved file's front elevation, `[x][z]`, read from its `rows` lines (top row
/// first, a trailing `w` or `t` a flag).
fn saved_depths(text: &str) -> Vec<Vec<usize>> {
    let rows: Vec<Vec<usize>> = text
        .lines()
        .skip_while(|l| l.trim() != "rows")
        .skip(1)
        .map(|l| {
            l.split_whitespace()
                .map(|t| t.trim_end_matches(['w', 't']).parse().unwrap())
                .collect()
        })
        .collect();
    let nx = rows[0].len();
    (0..nx)
        .map(|x| rows.iter().rev().map(|r| r[x]).collect())
        .collect()
}

#[test]
fn voxels_added_in_the_studio_save_a_card_the_command_creases_the_same() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let new = ok(server.post_json(
        "/api/voxel/new",
        br#"{"nx": 10, "ny": 5, "nz": 6, "cell_mm": 5, "margin_mm": 10}"#,
    ));
    let id = new["id"].as_u64().unwrap();
    assert_eq!(new["makes_a_card"], true);
    assert_eq!(new["faults"], json!([]));
    assert_eq!(new["sheet_mm"], json!([70.0, 75.0]));

    // Front view: row (4, 2) pushed out one cell. §2.7 fills the cells below: 3 voxels.
    let v = ok(edit(&server, id, json!({"op": "push_out", "x": 4, "z": 2})));
    assert_eq!(v["change"], json!([3, 0]));
    // Side view: cell (5, 1, 3) added with the box below and behind it, 2 × 4 cells.
    let v = ok(edit(
        &server,
        id,
        json!({"op": "add", "x": 5, "y": 1, "z": 3}),
    ));
    assert_eq!(v["change"], json!([8, 0]));
    assert_eq!(v["depth"][5], json!([2, 2, 2, 2, 0, 0]));
    assert_eq!(v["makes_a_card"], true, "{v}");
    assert_eq!(v["undo"], true);

    // The saved design holds those depths and the command reads it.
    let (status, saved) = server.get(&format!("/api/voxel/{id}/save"));
    assert_eq!(status, 200);
    let text = String::from_utf8(saved).unwrap();
    let depths = saved_depths(&text);
    assert_eq!(depths[4], [1, 1, 1, 0, 0, 0]);
    assert_eq!(depths[5], [2, 2, 2, 2, 0, 0]);
    assert_eq!(depths.iter().flatten().sum::<usize>(), 11);
    std::fs::write(dir.path().join("saved.voxel.txt"), &text).unwrap();
    let out = foldcam(
        &["popup", "voxel", "saved.voxel.txt", "-o", "cli.fold"],
        dir.path(),
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let cli_fold = std::fs::read(dir.path().join("cli.fold")).unwrap();
    let cli = ok(server.post_json("/api/upload?name=cli.fold", &cli_fold));
    let studio = ok(server.post_json(&format!("/api/voxel/{id}/pattern"), b""));
    assert_same_pattern(&studio, &cli);
    assert!(studio["counts"]["assignments"]["valley"].as_u64().unwrap() > 0);
    // The document is a studio document: its check runs.
    let doc = studio["id"].as_u64().unwrap();
    let (status, _) = server.get(&format!("/api/docs/{doc}/check"));
    assert_eq!(status, 200);

    // Undo, redo: the versions come back.
    let back = ok(server.post_json(&format!("/api/voxel/{id}/undo"), b""));
    assert_eq!(back["depth"][5], json!([0, 0, 0, 0, 0, 0]));
    let again = ok(server.post_json(&format!("/api/voxel/{id}/redo"), b""));
    assert_eq!(again["depth"][5], json!([2, 2, 2, 2, 0, 0]));
}

#[test]
fn the_card_opens_from_shut_to_flat() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let new = ok(server.post_json(
        "/api/voxel/new",
        br#"{"nx": 6, "ny": 4, "nz": 5, "cell_mm": 4, "margin_mm": 3}"#,
    ));
    let id = new["id"].as_u64().unwrap();
    ok(edit(
        &server,
        id,
        json!({"op": "add", "x": 2, "y": 1, "z": 2}),
    ));
    let heights = |angle: f64| -> Vec<f64> {
        let v = ok(get_json(
            &server,
            &format!("/api/voxel/{id}/open?angle={angle}"),
        ));
        assert!(!v["triangles"].as_array().unwrap().is_empty());
        v["positions"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| p[2].as_f64().unwrap())
            .collect()
    };
    // Standing (90°), the back sheet reaches nz cells and the margin up: 5 × 4 + 3 mm.
    let top = heights(90.0).into_iter().fold(f64::MIN, f64::max);
    assert!((top - 23.0).abs() < 1e-9, "{top}");
    // Shut and flat, every point lies in the base's plane.
    for angle in [0.0, 180.0] {
        assert!(heights(angle).iter().all(|z| z.abs() < 1e-9), "{angle}°");
    }
    let (status, reply) = get_json(&server, &format!("/api/voxel/{id}/open?angle=abc"));
    assert_eq!(status, 400, "{reply}");
}

#[test]
fn a_card_that_cannot_pop_up_is_marked_where_the_command_refuses_it() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let new = ok(server.post_json(
        "/api/voxel/new",
        br#"{"nx": 5, "ny": 4, "nz": 5, "cell_mm": 5, "margin_mm": 5}"#,
    ));
    let id = new["id"].as_u64().unwrap();
    // A one-cell step whose top face is left out: its front face keeps the base only.
    ok(edit(
        &server,
        id,
        json!({"op": "add", "x": 2, "y": 0, "z": 0}),
    ));
    let v = ok(edit(
        &server,
        id,
        json!({"op": "omit_top", "x": 2, "z": 0, "on": true}),
    ));
    assert_eq!(v["makes_a_card"], false, "{v}");
    let popup: Vec<&Value> = v["faults"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|f| f["kind"] == "popup")
        .collect();
    assert_eq!(popup.len(), 1, "{v}");
    assert_eq!(popup[0]["faces"][0]["kind"], "front");
    assert_eq!(popup[0]["faces"][0]["cell"], json!([2, 0, 0]));

    // The command refuses the saved file and names the same face.
    let (_, saved) = server.get(&format!("/api/voxel/{id}/save"));
    std::fs::write(dir.path().join("bad.voxel.txt"), saved).unwrap();
    let out = foldcam(
        &["popup", "voxel", "bad.voxel.txt", "-o", "bad.fold"],
        dir.path(),
    );
    assert_eq!(out.status.code(), Some(1));
    // The refusal is the command's report, on its standard output.
    let report = String::from_utf8_lossy(&out.stdout);
    assert!(report.contains("front face of cell (2, 0, 0)"), "{report}");
    let message = popup[0]["message"].as_str().unwrap();
    assert!(
        message.contains("front face of cell (2, 0, 0)"),
        "{message}"
    );
    assert!(!dir.path().join("bad.fold").exists());
    // And so does the studio's crease pattern.
    let (status, reply) = server.post_json(&format!("/api/voxel/{id}/pattern"), b"");
    assert_eq!(status, 422);
    assert!(
        reply["error"]
            .as_str()
            .unwrap()
            .contains("front face of cell (2, 0, 0)"),
        "{reply}"
    );
}

#[test]
fn cards_and_height_maps_load_and_bad_edits_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let house = std::fs::read(repo_file("examples/popup/house.voxel.txt")).unwrap();
    let v = ok(server.post_json("/api/voxel/load?name=house.voxel.txt", &house));
    let want = saved_depths(std::str::from_utf8(&house).unwrap());
    assert_eq!((v["nx"].as_u64(), v["nz"].as_u64()), (Some(14), Some(12)));
    for (x, col) in want.iter().enumerate() {
        // The file lists the top rows; rows above them are empty.
        let got: Vec<usize> = v["depth"][x]
            .as_array()
            .unwrap()
            .iter()
            .map(|d| d.as_u64().unwrap() as usize)
            .collect();
        assert_eq!(&got[..col.len()], &col[..], "column {x}");
        assert!(got[col.len()..].iter().all(|&d| d == 0));
    }
    assert_eq!(v["window"][4][2], true);
    assert_eq!(v["makes_a_card"], true);
    let id = v["id"].as_u64().unwrap();

    // A height map: one pixel per cell along the fold, the back sheet one row higher than the
    // map and the base one cell deeper than the depth asked for (white stands that far out).
    let mut png = Vec::new();
    let map = image::GrayImage::from_fn(7, 5, |x, y| {
        image::Luma([if (2..5).contains(&x) && y >= 2 {
            255
        } else {
            0
        }])
    });
    image::DynamicImage::ImageLuma8(map)
        .write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
        .unwrap();
    let m = ok(server.post_json(
        &format!("/api/voxel/load?name={}&depth=10", encode("relief.png")),
        &png,
    ));
    assert_eq!(
        (m["nx"].as_u64(), m["ny"].as_u64(), m["nz"].as_u64()),
        (Some(7), Some(11), Some(6))
    );
    assert_eq!(m["depth"][3][0], 10, "{}", m["depth"]);
    let (status, reply) = server.post_json("/api/voxel/load?name=relief.png&resolution=0", &png);
    assert_eq!(status, 422);
    assert!(
        reply["error"].as_str().unwrap().contains("--resolution"),
        "{reply}"
    );

    // A mesh seen from the front: 80 cells along the fold by default, as the command.
    let building = std::fs::read(repo_file("examples/popup/building.obj")).unwrap();
    let b = ok(server.post_json("/api/voxel/load?name=building.obj", &building));
    assert_eq!(b["nx"], 80);

    let (status, reply) = edit(&server, id, json!({"op": "add", "x": 14, "y": 0, "z": 0}));
    assert_eq!(status, 422);
    assert_eq!(
        reply["error"],
        "house.voxel.txt: cell (14, 0, 0) is outside the 14 × 8 × 12 card (x 0..14, y 0..8, z 0..12)"
    );
    let (status, reply) = edit(&server, id, json!({"op": "grow"}));
    assert_eq!(status, 400, "{reply}");
    let (status, reply) = server.post_json("/api/voxel/load?name=bad.voxel.txt", b"cell_mm 5\n");
    assert_eq!(status, 422);
    assert!(
        reply["error"]
            .as_str()
            .unwrap()
            .starts_with("bad.voxel.txt"),
        "{reply}"
    );
    let (status, _) = get_json(&server, "/api/voxel/999/open?angle=90");
    assert_eq!(status, 404);
}

#[test]
fn faces_beyond_the_closed_card_are_marked_and_the_command_warns_as_far() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let new = ok(server.post_json(
        "/api/voxel/new",
        br#"{"nx": 5, "ny": 4, "nz": 5, "cell_mm": 5, "margin_mm": 1}"#,
    ));
    let id = new["id"].as_u64().unwrap();
    // A block 3 cells deep and 4 high under a back sheet 5 high.
    let v = ok(edit(
        &server,
        id,
        json!({"op": "add", "x": 2, "y": 2, "z": 3}),
    ));
    assert_eq!(v["makes_a_card"], true, "a warning only: {v}");
    let beyond: Vec<&Value> = v["faults"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|f| f["kind"] == "beyond")
        .collect();
    assert_eq!(beyond.len(), 1, "{v}");
    // Folded shut (eq. 6 at θ = 180°) a face corner at (y, z) lies y + z cells from the fold;
    // the closed outline reaches max(ny, nz) cells and the margin: the front and top faces
    // whose far corner (y + 1, z + 1) passes 5 cells + 1 mm are beyond.
    let limit = 5.0 + 1.0 / 5.0;
    let mut expected = Vec::new();
    for z in 0..4 {
        if (2 + z + 2) as f64 > limit {
            expected.push(json!(["front", [2, 2, z]]));
        }
    }
    for y in 0..3 {
        if (y + 3 + 2) as f64 > limit {
            expected.push(json!(["top", [2, y, 3]]));
        }
    }
    let mut got: Vec<Value> = beyond[0]["faces"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| json!([f["kind"], f["cell"]]))
        .collect();
    let key = |v: &Value| v.to_string();
    got.sort_by_key(key);
    expected.sort_by_key(key);
    assert_eq!(got, expected);

    // The command builds the card with a warning that names the same distance.
    let (_, saved) = server.get(&format!("/api/voxel/{id}/save"));
    std::fs::write(dir.path().join("tall.voxel.txt"), saved).unwrap();
    let out = foldcam(
        &["popup", "voxel", "tall.voxel.txt", "-o", "tall.fold"],
        dir.path(),
    );
    assert!(out.status.success());
    let warning = String::from_utf8_lossy(&out.stderr);
    let reach = |text: &str, after: &str| -> String {
        let rest = &text[text.find(after).unwrap_or_else(|| panic!("{text}")) + after.len()..];
        rest.split(" mm").next().unwrap().to_string()
    };
    let message = beyond[0]["message"].as_str().unwrap();
    assert_eq!(
        reach(message, "up to "),
        reach(&warning, "the card reaches ")
    );
}

/// The issue's three requests that aborted the server: three 4000³ cards at once and a
/// re-triangulation to 10⁸ faces are refused before they allocate, with the limit named, and
/// the server goes on serving.
#[test]
fn requests_beyond_memory_are_refused_and_the_server_survives() {
    let dir = tempfile::tempdir().expect("temp dir");
    let server = Server::start(&[], dir.path());
    let big = br#"{"nx": 4000, "ny": 4000, "nz": 4000, "cell_mm": 1}"#;
    let replies: Vec<(u16, Value)> = std::thread::scope(|s| {
        let asks: Vec<_> = (0..3)
            .map(|_| s.spawn(|| server.post_json("/api/voxel/new", big)))
            .collect();
        asks.into_iter().map(|a| a.join().expect("reply")).collect()
    });
    for (status, body) in &replies {
        assert_eq!(*status, 422, "{body}");
        let error = body["error"].as_str().expect("an error");
        assert!(
            error.contains("32000000 cells") && error.contains("1000000"),
            "{error}"
        );
    }
    let dome = server.post_json("/api/tess/example/dome.obj", b"");
    let dome = ok(dome)["id"].as_u64().expect("mesh id");
    let (status, body) = server.post_json(
        &format!("/api/tess/mesh/{dome}/solve"),
        br#"{"remesh": "only", "remesh_faces": 100000000}"#,
    );
    assert_eq!(status, 422, "{body}");
    assert!(
        body["error"].as_str().unwrap_or("").contains("50000"),
        "{body}"
    );
    // Still serving: a small card is made.
    let small = ok(server.post_json(
        "/api/voxel/new",
        br#"{"nx": 6, "ny": 4, "nz": 4, "cell_mm": 5}"#,
    ));
    assert_eq!(small["nx"].as_u64(), Some(6));
}
