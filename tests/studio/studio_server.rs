//! `foldcam serve` over plain HTTP: what the server refuses (paths from requests, oversized
//! uploads, profiles that are not shipped), errors carrying the command line's message, and
//! job files byte-identical to `foldcam cut`'s.

use crate::bin;
use crate::studio;

use bin::{foldcam, repo_file};
use serde_json::Value;
use studio::{Server, encode, flat_vertex_folded_flat};

/// A text no reply may ever contain: it is only in a file the server was not given.
const SECRET: &str = "studio-test-secret-0f3a9c";

fn generate_miura(dir: &std::path::Path) {
    let out = foldcam(&["generate", "miura", "-o", "miura.fold"], dir);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The message `foldcam check FILE` prints for a bad file, without `foldcam: `.
fn cli_error(file: &str, dir: &std::path::Path) -> String {
    let out = foldcam(&["check", file], dir);
    assert_eq!(out.status.code(), Some(2), "the CLI refuses {file}");
    let stderr = String::from_utf8_lossy(&out.stderr);
    let line = stderr
        .lines()
        .find_map(|l| l.strip_prefix("foldcam: "))
        .expect("an error line");
    line.to_string()
}

#[test]
fn requests_reach_no_file_but_the_embedded_pages_and_the_given_files() {
    let dir = tempfile::tempdir().unwrap();
    let served = dir.path().join("served");
    std::fs::create_dir(&served).unwrap();
    std::fs::write(dir.path().join("secret.txt"), SECRET).unwrap();
    std::fs::write(dir.path().join("secret.fold"), SECRET).unwrap();
    // A valid machine profile on disk: the CLI would take its path, the studio must not.
    let profile = dir.path().join("my-machine.toml");
    std::fs::copy(repo_file("machines/grbl-diode.toml"), &profile).unwrap();
    generate_miura(&served);
    let server = Server::start(&["miura.fold"], &served);

    // Controls: the page and the named file are served.
    let (status, page) = server.get("/");
    assert_eq!(status, 200);
    assert!(String::from_utf8_lossy(&page).contains("foldcam studio"));
    let (status, opened) = server.post_json("/api/files/0", b"");
    assert_eq!(status, 200, "{opened}");
    let id = opened["id"].as_u64().unwrap();

    let attempts = [
        "/../secret.txt",
        "/../../secret.txt",
        "/..%2Fsecret.txt",
        "/%2e%2e/secret.txt",
        "/vendor/../../secret.txt",
        "/vendor/..%2F..%2Fsecret.txt",
        "//etc/passwd",
        "/..\\secret.txt",
        "/api/files/1",
        "/api/files/..%2F..%2Fsecret.txt",
    ];
    for path in attempts {
        for method in ["GET", "POST"] {
            let (status, body) = server.raw(&format!("{method} {path} HTTP/1.1"), b"");
            let text = String::from_utf8_lossy(&body);
            assert!(!text.contains(SECRET), "{method} {path} leaked the file");
            assert!(
                !text.contains("root:"),
                "{method} {path} leaked /etc/passwd"
            );
            assert!(
                (400..500).contains(&status),
                "{method} {path}: status {status}"
            );
        }
    }
    // An upload's name is a name, never a path that is read.
    let (status, reply) = server.post_json(
        &format!("/api/upload?name={}", encode("../secret.fold")),
        b"{}",
    );
    assert_eq!(status, 422);
    assert!(!reply.to_string().contains(SECRET));
    // Profiles are shipped names only: a path to a valid profile is refused.
    for machine in [
        profile.to_string_lossy().into_owned(),
        "../machines/grbl-diode.toml".into(),
    ] {
        let (status, body) = server.get(&format!(
            "/api/docs/{id}/plan?machine={}&material=card-300gsm",
            encode(&machine)
        ));
        let reply: Value = serde_json::from_slice(&body).unwrap();
        assert_eq!(status, 422, "{reply}");
        assert!(
            reply["error"]
                .as_str()
                .unwrap()
                .contains("not a shipped profile")
        );
    }
    // The shipped name works (the control for the refusal above).
    let (status, _) = server.get(&format!(
        "/api/docs/{id}/plan?machine=grbl-diode&material=card-300gsm"
    ));
    assert_eq!(status, 200);
}

#[test]
fn an_upload_over_the_limit_is_refused_with_a_json_error() {
    let dir = tempfile::tempdir().unwrap();
    generate_miura(dir.path());
    let server = Server::start(&["--max-upload", "1"], dir.path());
    let limit = 1024 * 1024;
    // Valid FOLD text padded with spaces past the limit.
    let mut big = std::fs::read(dir.path().join("miura.fold")).unwrap();
    let pattern_len = big.len();
    big.resize(limit + 1, b' ');
    let (status, reply) = server.post_expecting("/api/upload?name=big.fold", &big);
    let reply: Value = serde_json::from_slice(&reply).expect("a JSON reply");
    assert_eq!(status, 413, "{reply}");
    let error = reply["error"].as_str().unwrap();
    assert!(
        error.contains("big.fold") && error.contains(&limit.to_string()),
        "{error}"
    );
    // The same file within the limit is read (so the refusal is the size, not the content),
    // asked for with the same protocol.
    big.truncate(pattern_len + 1000);
    let (status, reply) = server.post_expecting("/api/upload?name=big.fold", &big);
    assert_eq!(status, 200, "{}", String::from_utf8_lossy(&reply));
}

#[test]
fn bad_input_gets_the_command_lines_message() {
    let dir = tempfile::tempdir().unwrap();
    let cases: [(&str, &[u8]); 4] = [
        (
            "dangling.fold",
            br#"{"vertices_coords": [[0,0],[1,0]], "edges_vertices": [[0,5]]}"#,
        ),
        ("broken.fold", b"{\"vertices_coords\": [[0,0],"),
        ("notes.txt", b"hello"),
        ("latin1.cp", b"1 0 0 1 1\n\xff\xfe"),
    ];
    let server = Server::start(&[], dir.path());
    for (name, bytes) in cases {
        std::fs::write(dir.path().join(name), bytes).unwrap();
        let expected = cli_error(name, dir.path());
        let (status, reply) = server.post_json(&format!("/api/upload?name={name}"), bytes);
        assert_eq!(status, 422, "{name}: {reply}");
        assert_eq!(reply["error"].as_str().unwrap(), expected, "{name}");
    }
}

#[test]
fn job_files_are_byte_identical_to_foldcam_cut() {
    let dir = tempfile::tempdir().unwrap();
    generate_miura(dir.path());
    let pattern = std::fs::read(dir.path().join("miura.fold")).unwrap();
    let server = Server::start(&[], dir.path());
    let (status, opened) = server.post_json("/api/upload?name=miura.fold", &pattern);
    assert_eq!(status, 200, "{opened}");
    let id = opened["id"].as_u64().unwrap();
    for (machine, material, ext) in [
        ("grbl-diode", "card-300gsm", "gcode"),
        ("linuxcnc-fiber", "stainless-0.5", "ngc"),
        ("grbl-pen-plotter", "paper-160gsm", "gcode"),
        ("lightburn", "card-300gsm", "dxf"),
        ("grbl-diode", "card-300gsm", "svg"),
        ("lightburn", "card-300gsm", "lbrn2"),
    ] {
        let file = format!("cli-{machine}.{ext}");
        let out = foldcam(
            &[
                "cut",
                "miura.fold",
                "-m",
                machine,
                "-x",
                material,
                "-o",
                &file,
            ],
            dir.path(),
        );
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let cli = std::fs::read(dir.path().join(&file)).unwrap();
        let (status, served) = server.get(&format!(
            "/api/docs/{id}/cut?machine={machine}&material={material}&format={ext}"
        ));
        assert_eq!(status, 200, "{}", String::from_utf8_lossy(&served));
        assert!(!served.is_empty());
        assert!(
            served == cli,
            "{machine} {material} .{ext} differs from foldcam cut's"
        );
    }
}

#[test]
fn every_format_foldcam_reads_opens_with_the_clis_counts() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    // ORIPA's .opx, written by foldcam from a generated Miura-ori (no .opx file is bundled).
    generate_miura(dir.path());
    let out = foldcam(&["convert", "miura.fold", "miura.opx"], dir.path());
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let opx = dir.path().join("miura.opx").to_string_lossy().into_owned();
    for rel in [
        "examples/patterns/preliminary-base.cp",
        "examples/patterns/broken-vertex.fold",
        "tests/data/oripa-style.dxf",
        "tests/data/rabbit-ear-style.svg",
        opx.as_str(),
    ] {
        let path = if rel == opx {
            opx.clone()
        } else {
            repo_file(rel)
        };
        let name = std::path::Path::new(&path)
            .file_name()
            .unwrap()
            .to_string_lossy()
            .into_owned();
        let bytes = std::fs::read(&path).unwrap();
        let (status, opened) = server.post_json(&format!("/api/upload?name={name}"), &bytes);
        assert_eq!(status, 200, "{rel}: {opened}");
        // The CLI's own count of the cleaned pattern (check --json's summary).
        let out = foldcam(&["check", &path, "--json"], dir.path());
        let report: Value = serde_json::from_slice(&out.stdout).expect("check --json");
        let summary = &report["summary"];
        assert_eq!(opened["counts"]["vertices"], summary["vertices"], "{rel}");
        assert_eq!(opened["counts"]["edges"], summary["edges"], "{rel}");
        assert_eq!(
            opened["counts"]["assignments"], summary["assignments"],
            "{rel}"
        );
        // And its check: the same findings.
        let id = opened["id"].as_u64().unwrap();
        let (status, body) = server.get(&format!("/api/docs/{id}/check"));
        assert_eq!(status, 200);
        let served: Value = serde_json::from_slice(&body).unwrap();
        assert_eq!(served["findings"], report["findings"], "{rel}");
    }
}

/// Kawasaki's theorem (Kawasaki 1989) at `centre`: the alternating sum of the sector angles
/// between the creases to `ends`, degrees (zero where the vertex folds flat).
fn kawasaki_sum(centre: [f64; 2], ends: &[[f64; 2]]) -> f64 {
    let mut angles: Vec<f64> = ends
        .iter()
        .map(|p| (p[1] - centre[1]).atan2(p[0] - centre[0]))
        .collect();
    angles.sort_by(f64::total_cmp);
    let n = angles.len();
    (0..n)
        .map(|k| {
            let next = if k + 1 < n {
                angles[k + 1]
            } else {
                angles[0] + std::f64::consts::TAU
            };
            let sector = (next - angles[k]).to_degrees();
            if k % 2 == 0 { sector } else { -sector }
        })
        .sum()
}

fn point(v: &Value) -> [f64; 2] {
    [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()]
}

/// The vertex of a pattern view at `p`, and the other ends of its creases (not boundary).
fn crease_fan(view: &Value, p: [f64; 2]) -> (usize, Vec<[f64; 2]>) {
    let vertices: Vec<[f64; 2]> = view["vertices"]
        .as_array()
        .unwrap()
        .iter()
        .map(point)
        .collect();
    let v = vertices
        .iter()
        .position(|q| (q[0] - p[0]).abs() < 1e-9 && (q[1] - p[1]).abs() < 1e-9)
        .unwrap_or_else(|| panic!("no vertex at {p:?}"));
    let ends = view["edges"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|e| e["a"] != "B")
        .filter_map(|e| {
            let (a, b) = (e["v"][0].as_u64()? as usize, e["v"][1].as_u64()? as usize);
            (a == v).then_some(b).or((b == v).then_some(a))
        })
        .map(|w| vertices[w])
        .collect();
    (v, ends)
}

fn findings(server: &Server, id: u64) -> Vec<Value> {
    let (status, body) = server.get(&format!("/api/docs/{id}/check"));
    assert_eq!(status, 200);
    let report: Value = serde_json::from_slice(&body).unwrap();
    report["findings"].as_array().unwrap().clone()
}

#[test]
fn moving_a_vertex_breaks_kawasaki_and_undo_restores_the_pattern() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let bytes = flat_vertex_folded_flat();
    let (status, opened) = server.post_json("/api/upload?name=flat-vertex.fold", &bytes);
    assert_eq!(status, 200, "{opened}");
    let id = opened["id"].as_u64().unwrap();
    assert_eq!(
        opened["history"],
        serde_json::json!({"undo": false, "redo": false})
    );
    // The file's vertex folds flat (the control): Kawasaki's sum is zero and the check passes.
    let (v, ends) = crease_fan(&opened, [50.0, 50.0]);
    assert!(kawasaki_sum([50.0, 50.0], &ends).abs() < 1e-6);
    assert!(findings(&server, id).is_empty());

    let to = [40.0, 40.0];
    let body = format!(
        r#"{{"op": "move", "vertex": {v}, "to": [{}, {}]}}"#,
        to[0], to[1]
    );
    let (status, moved) = server.post_json(&format!("/api/docs/{id}/edit"), body.as_bytes());
    assert_eq!(status, 200, "{moved}");
    assert_eq!(moved["id"].as_u64(), Some(id));
    assert_eq!(
        moved["history"],
        serde_json::json!({"undo": true, "redo": false})
    );
    let (_, ends) = crease_fan(&moved, to);
    let sum = kawasaki_sum(to, &ends);
    assert!(
        sum.abs() > 1.0,
        "the moved vertex still folds flat ({sum}°)"
    );
    let found = findings(&server, id);
    let kawasaki: Vec<&Value> = found.iter().filter(|f| f["kind"] == "kawasaki").collect();
    assert_eq!(kawasaki.len(), 1, "{found:?}");
    let at = &kawasaki[0]["position"];
    let at = [
        at["x"].as_f64().unwrap_or_else(|| at[0].as_f64().unwrap()),
        at["y"].as_f64().unwrap_or_else(|| at[1].as_f64().unwrap()),
    ];
    assert!(
        (at[0] - to[0]).abs() < 1e-9 && (at[1] - to[1]).abs() < 1e-9,
        "{at:?}"
    );

    // Undo: the pattern as opened, and the check passes again; redo: moved again.
    let (status, undone) = server.post_json(&format!("/api/docs/{id}/undo"), b"");
    assert_eq!(status, 200, "{undone}");
    assert_eq!(undone["vertices"], opened["vertices"]);
    assert_eq!(undone["edges"], opened["edges"]);
    assert_eq!(
        undone["history"],
        serde_json::json!({"undo": false, "redo": true})
    );
    assert!(findings(&server, id).is_empty());
    let (status, redone) = server.post_json(&format!("/api/docs/{id}/redo"), b"");
    assert_eq!(status, 200);
    assert_eq!(redone["vertices"], moved["vertices"]);
    assert_eq!(findings(&server, id).len(), found.len());
}

/// A 100 mm square sheet: four corners and four boundary edges.
const SQUARE: &str = r#"{"file_spec": 1.2, "frame_unit": "mm",
  "vertices_coords": [[0,0],[100,0],[100,100],[0,100]],
  "edges_vertices": [[0,1],[1,2],[2,3],[3,0]],
  "edges_assignment": ["B","B","B","B"]}"#;

fn count(view: &Value, letter: &str) -> usize {
    view["edges"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|e| e["a"] == letter)
        .count()
}

#[test]
fn drawn_creases_split_at_their_crossing_and_maekawa_judges_the_assignments() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let (status, opened) = server.post_json("/api/upload?name=square.fold", SQUARE.as_bytes());
    assert_eq!(status, 200, "{opened}");
    let id = opened["id"].as_u64().unwrap();
    let edit = |body: &str| {
        let (status, view) = server.post_json(&format!("/api/docs/{id}/edit"), body.as_bytes());
        assert_eq!(status, 200, "{body}: {view}");
        view
    };
    // One diagonal: ends on the corners (merged), no new vertex.
    let view = edit(r#"{"op": "add", "from": [0, 0], "to": [100, 100], "assignment": "V"}"#);
    assert_eq!(
        (
            view["counts"]["vertices"].as_u64(),
            view["counts"]["edges"].as_u64()
        ),
        (Some(4), Some(5))
    );
    // The other crosses it: one new vertex at the centre, both diagonals split in two.
    let view = edit(r#"{"op": "add", "from": [100, 0], "to": [0, 100], "assignment": "M"}"#);
    assert_eq!(
        (
            view["counts"]["vertices"].as_u64(),
            view["counts"]["edges"].as_u64()
        ),
        (Some(5), Some(8))
    );
    assert_eq!((count(&view, "V"), count(&view, "M")), (2, 2));
    // Drawn creases fold fully: mountains at -180°, valleys at +180° (FOLD's sign).
    for e in view["edges"].as_array().unwrap() {
        match e["a"].as_str().unwrap() {
            "M" => assert_eq!(e["angle"].as_f64(), Some(-180.0)),
            "V" => assert_eq!(e["angle"].as_f64(), Some(180.0)),
            _ => {}
        }
    }
    // Maekawa (Maekawa 1987; Kasahara & Takahama 1987): mountains and valleys at a flat vertex
    // differ by two. Two and two at the centre is a fault there.
    let (centre, _) = crease_fan(&view, [50.0, 50.0]);
    let found = findings(&server, id);
    assert!(
        found.iter().any(|f| f["kind"] == "maekawa"),
        "two mountains and two valleys pass: {found:?}"
    );
    // Making one mountain a valley (3 V, 1 M, four right angles) satisfies both theorems.
    let m = view["edges"]
        .as_array()
        .unwrap()
        .iter()
        .position(|e| e["a"] == "M")
        .unwrap();
    let view = edit(&format!(
        r#"{{"op": "assign", "edge": {m}, "assignment": "V"}}"#
    ));
    assert_eq!((count(&view, "V"), count(&view, "M")), (3, 1));
    assert_eq!(view["edges"][m]["angle"].as_f64(), Some(180.0));
    assert!(
        findings(&server, id).is_empty(),
        "{:?}",
        findings(&server, id)
    );
    // Deleting a crease at the centre leaves three: an odd number never folds flat.
    let crease = view["edges"]
        .as_array()
        .unwrap()
        .iter()
        .position(|e| {
            e["a"] != "B"
                && e["v"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .any(|v| v.as_u64() == Some(centre as u64))
        })
        .unwrap();
    let view = edit(&format!(r#"{{"op": "delete", "edge": {crease}}}"#));
    assert_eq!(view["counts"]["edges"].as_u64(), Some(7));
    assert!(!findings(&server, id).is_empty());
}

#[test]
fn refused_edits_name_the_problem_and_change_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let (status, opened) = server.post_json("/api/upload?name=square.fold", SQUARE.as_bytes());
    assert_eq!(status, 200, "{opened}");
    let id = opened["id"].as_u64().unwrap();
    let path = format!("/api/docs/{id}/edit");
    let cases: [(&str, u16, &str); 6] = [
        (
            r#"{"op": "delete", "edge": 9}"#,
            422,
            "edge 9: the pattern has 4 edges (0 to 3)",
        ),
        (
            r#"{"op": "move", "vertex": 4, "to": [0, 0]}"#,
            422,
            "vertex 4: the pattern has 4 vertices",
        ),
        (
            r#"{"op": "assign", "edge": 0, "assignment": "X"}"#,
            422,
            "assignment 'X'",
        ),
        (
            r#"{"op": "add", "from": [0, 0], "to": [1e300, 0], "assignment": "M"}"#,
            422,
            "coordinates must be finite",
        ),
        (
            r#"{"op": "fold", "edge": 0}"#,
            400,
            "edit request: unknown variant `fold`",
        ),
        (r#"{"op": "delete""#, 400, "edit request: EOF"),
    ];
    for (body, expected_status, message) in cases {
        let (status, reply) = server.post_json(&path, body.as_bytes());
        assert_eq!(status, expected_status, "{body}: {reply}");
        let error = reply["error"].as_str().unwrap();
        assert!(error.contains(message), "{body}: {error}");
    }
    // Nothing changed: no edit to undo, the same pattern.
    let (status, reply) = server.post_json(&format!("/api/docs/{id}/undo"), b"");
    assert_eq!(status, 422);
    assert_eq!(reply["error"], "nothing to undo");
    // A valid edit on the same document (the control) is taken.
    let (status, _) = server.post_json(&path, br#"{"op": "delete", "edge": 0}"#);
    assert_eq!(status, 200);
}

#[test]
fn snapping_finds_vertices_and_22_5_degree_lines_but_not_the_dragged_vertex() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let (status, opened) = server.post_json("/api/upload?name=square.fold", SQUARE.as_bytes());
    assert_eq!(status, 200, "{opened}");
    let id = opened["id"].as_u64().unwrap();
    let path = format!("/api/docs/{id}/snap");
    let (status, s) = server.post_json(&path, br#"{"point": [97, 102], "radius": 5}"#);
    assert_eq!(status, 200, "{s}");
    assert_eq!(
        (s["kind"].as_str(), point(&s["point"])),
        (Some("vertex"), [100.0, 100.0])
    );
    let corner = s["vertex"].as_u64().unwrap();
    let body = format!(r#"{{"point": [97, 102], "radius": 5, "exclude_vertex": {corner}}}"#);
    let (_, s) = server.post_json(&path, body.as_bytes());
    assert_ne!(s["kind"], "vertex", "{s}");
    // The 22.5° line from corner (0, 0) meets the side x = 100 at y = 100 tan 22.5° = 100 (√2 − 1).
    let (_, s) = server.post_json(
        &path,
        br#"{"point": [99, 43], "radius": 5, "angle_step_deg": 22.5, "anchors": [[0, 0]]}"#,
    );
    assert_eq!(s["kind"], "crossing", "{s}");
    let p = point(&s["point"]);
    assert!(
        (p[0] - 100.0).abs() < 1e-9 && (p[1] - 100.0 * (2f64.sqrt() - 1.0)).abs() < 1e-9,
        "{p:?}"
    );
}

/// Area of a ring (shoelace formula), absolute.
fn ring_area(ring: &[Value]) -> f64 {
    let p: Vec<[f64; 2]> = ring.iter().map(point).collect();
    (0..p.len())
        .map(|k| {
            let (a, b) = (p[k], p[(k + 1) % p.len()]);
            a[0] * b[1] - b[0] * a[1]
        })
        .sum::<f64>()
        .abs()
        / 2.0
}

#[test]
fn the_flat_folded_view_keeps_the_paper_area_and_counts_as_fold_flat() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let file = repo_file("examples/patterns/flat-vertex.fold");
    let bytes = std::fs::read(&file).unwrap();
    let (status, opened) = server.post_json("/api/upload?name=flat-vertex.fold", &bytes);
    assert_eq!(status, 200, "{opened}");
    let id = opened["id"].as_u64().unwrap();
    let (status, body) = server.get(&format!("/api/docs/{id}/flat"));
    assert_eq!(status, 200, "{}", String::from_utf8_lossy(&body));
    let view: Value = serde_json::from_slice(&body).unwrap();
    // Folding moves paper without stretching it: the layers over every cell add up to the
    // 100 mm × 100 mm sheet.
    let covered: f64 = view["cells"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| {
            let rings = c["rings"].as_array().unwrap();
            let outer = ring_area(rings[0].as_array().unwrap());
            let holes: f64 = rings[1..]
                .iter()
                .map(|r| ring_area(r.as_array().unwrap()))
                .sum();
            (outer - holes) * c["layers"].as_f64().unwrap()
        })
        .sum();
    assert!((covered - 100.0 * 100.0).abs() < 1e-6, "{covered}");
    // Deeper cells are darker: fills ordered by layer count.
    let mut by_depth: Vec<(u64, u32, bool)> = view["cells"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| {
            let fill = c["xray"].as_str().unwrap();
            (
                c["layers"].as_u64().unwrap(),
                u32::from_str_radix(&fill[1..3], 16).unwrap(),
                c["flipped"].as_bool().unwrap(),
            )
        })
        .collect();
    by_depth.sort();
    assert!(
        by_depth
            .windows(2)
            .all(|w| w[0].0 == w[1].0 || w[0].1 > w[1].1),
        "{by_depth:?}"
    );
    assert!(
        by_depth.last().unwrap().0 >= 2,
        "the sheet folds over itself"
    );
    // The same count as `foldcam fold-flat` prints ("state 0 of N").
    let out = foldcam(&["fold-flat", &file, "-o", "folded.fold"], dir.path());
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains(&format!("state 0 of {}", view["states"].as_str().unwrap())),
        "{stderr} vs {view}"
    );
    // A state past the count is refused, naming the count.
    let (status, body) = server.get(&format!("/api/docs/{id}/flat?state=1000000"));
    assert_eq!(status, 422);
    assert!(String::from_utf8_lossy(&body).contains("there is no state 1000000"));

    // A pattern that does not fold flat gets fold-flat's message.
    let broken = repo_file("examples/patterns/broken-vertex.fold");
    let (status, opened) = server.post_json(
        "/api/upload?name=broken-vertex.fold",
        &std::fs::read(&broken).unwrap(),
    );
    assert_eq!(status, 200);
    let id = opened["id"].as_u64().unwrap();
    let (status, body) = server.get(&format!("/api/docs/{id}/flat"));
    assert_eq!(status, 422);
    let reply: Value = serde_json::from_slice(&body).unwrap();
    std::fs::copy(&broken, dir.path().join("broken-vertex.fold")).unwrap();
    let out = foldcam(
        &["fold-flat", "broken-vertex.fold", "-o", "b.fold"],
        dir.path(),
    );
    assert_eq!(out.status.code(), Some(1));
    let cli = String::from_utf8_lossy(&out.stderr);
    // The error line (after the note of the size read).
    let cli = cli
        .lines()
        .find(|l| l.ends_with("nothing written"))
        .unwrap_or_else(|| panic!("{cli}"))
        .strip_prefix("foldcam: ")
        .unwrap();
    assert_eq!(
        format!("{}; nothing written", reply["error"].as_str().unwrap()),
        cli
    );
}

#[test]
fn plan_options_and_uploaded_profiles_give_foldcam_cuts_file() {
    let dir = tempfile::tempdir().unwrap();
    generate_miura(dir.path());
    let pattern = std::fs::read(dir.path().join("miura.fold")).unwrap();
    // A machine profile of the user's: the shipped diode laser with a smaller bed and feed.
    let text = std::fs::read_to_string(repo_file("machines/grbl-diode.toml"))
        .unwrap()
        .replace("acceleration_mm_s2 = 1000", "acceleration_mm_s2 = 800");
    assert!(text.contains("= 800"));
    std::fs::write(dir.path().join("my-diode.toml"), &text).unwrap();
    let server = Server::start(&[], dir.path());
    let (status, reply) =
        server.post_json("/api/profiles/machine?name=my-diode.toml", text.as_bytes());
    assert_eq!(status, 200, "{reply}");
    let key = reply["name"].as_str().unwrap().to_string();
    let (_, opened) = server.post_json("/api/upload?name=miura.fold", &pattern);
    let id = opened["id"].as_u64().unwrap();
    let cli_args = [
        "--mountain",
        "perforate",
        "--valley",
        "score",
        "--dash",
        "2",
        "--bridge",
        "0.8",
        "--margin",
        "12",
        "--origin",
        "centre",
        "--two-sided",
    ];
    let query =
        "mountain=perforate&valley=score&dash=2&bridge=0.8&margin=12&origin=centre&two_sided=true";
    let mut args = vec![
        "cut",
        "miura.fold",
        "-m",
        "my-diode.toml",
        "-x",
        "card-300gsm",
        "-o",
        "cli.gcode",
    ];
    args.extend(cli_args);
    let out = foldcam(&args, dir.path());
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for job in ["front", "back"] {
        let cli = std::fs::read(dir.path().join(format!("cli.{job}.gcode"))).unwrap();
        let (status, served) = server.get(&format!(
            "/api/docs/{id}/cut?machine={}&material=card-300gsm&format=gcode&job={job}&{query}",
            encode(&key)
        ));
        assert_eq!(status, 200, "{}", String::from_utf8_lossy(&served));
        assert!(
            served == cli,
            "{job}: the served G-code differs from foldcam cut's"
        );
    }
    // Without the options the file differs (so the options were used).
    let (_, plain) = server.get(&format!(
        "/api/docs/{id}/cut?machine={}&material=card-300gsm&format=gcode",
        encode(&key)
    ));
    assert!(plain != std::fs::read(dir.path().join("cli.front.gcode")).unwrap());
    // An option out of range names the option.
    let (status, body) = server.get(&format!(
        "/api/docs/{id}/plan?machine=grbl-diode&material=card-300gsm&dash=-1"
    ));
    assert_eq!(status, 422);
    assert!(
        String::from_utf8_lossy(&body).contains("dash"),
        "{}",
        String::from_utf8_lossy(&body)
    );
    // A broken profile gets the command line's message; an oversized one is refused.
    let bad = text.replace("max_feed_mm_min = 6000", "max_feed_mm_min = \"fast\"");
    std::fs::write(dir.path().join("bad.toml"), &bad).unwrap();
    let out = foldcam(
        &["plan", "miura.fold", "-m", "bad.toml", "-x", "card-300gsm"],
        dir.path(),
    );
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    let (status, reply) = server.post_json("/api/profiles/machine?name=bad.toml", bad.as_bytes());
    assert_eq!(status, 422);
    let message = reply["error"].as_str().unwrap();
    assert!(
        message.starts_with("bad.toml: max_feed_mm_min"),
        "{message}"
    );
    assert!(stderr.contains(message), "{stderr} vs {message}");
    let huge = format!("{text}\n# {}\n", "x".repeat(70 * 1024));
    let (status, reply) = server.post_json("/api/profiles/machine?name=huge.toml", huge.as_bytes());
    assert_eq!(status, 413, "{reply}");
}

#[test]
fn the_layer_order_takes_the_kawasaki_tolerance_of_the_check_panel() {
    // Flat-Folder's grid 002 turned by 17° and rounded to 0.01 of 100 units: the fitted tolerance (empty field) folds it and lists
    // the rounding as warnings, as `check --layers` does; a fixed 0.0001° refuses it, naming a
    // vertex, in the layer check and the flat-folded view alike; nonsense is refused with the
    // range.
    let dir = tempfile::tempdir().unwrap();
    let grid = repo_file("tests/data/flat-folder/002_brown_2x2_D1.fold");
    let mut cp = foldcam::formats::load(std::path::Path::new(&grid))
        .unwrap()
        .pattern;
    let turn = glam::DMat2::from_angle(17f64.to_radians());
    for p in &mut cp.vertices {
        *p = (turn * *p * 10_000.0).round() / 100.0;
    }
    let path = dir.path().join("rounded.fold");
    foldcam::formats::save(&path, &cp, None).unwrap();
    let server = Server::start(&[], dir.path());
    let (status, opened) = server.post_json(
        "/api/upload?name=rounded.fold",
        &std::fs::read(&path).unwrap(),
    );
    assert_eq!(status, 200, "{opened}");
    let id = opened["id"].as_u64().unwrap();
    for query in ["", "?kawasaki_tolerance=", "?kawasaki_tolerance=%20"] {
        let (status, body) = server.get(&format!("/api/docs/{id}/layers{query}"));
        assert_eq!(status, 200, "{query}: {}", String::from_utf8_lossy(&body));
        let v: Value = serde_json::from_slice(&body).unwrap();
        assert_eq!(v["layers"]["states"], "16", "{query}");
        assert!(!v["check"]["warnings"].as_array().unwrap().is_empty());
        assert_eq!(v["check"]["findings"].as_array().unwrap().len(), 0);
        assert!(v["text"].as_str().unwrap().contains("within the tolerance"));
    }
    let (status, body) = server.get(&format!("/api/docs/{id}/layers?kawasaki_tolerance=0.0001"));
    assert_eq!(status, 200);
    let v: Value = serde_json::from_slice(&body).unwrap();
    assert!(v["layers"]["states"].is_null(), "{v}");
    assert!(v["text"].as_str().unwrap().contains("kawasaki at v"), "{v}");
    let (status, body) = server.get(&format!("/api/docs/{id}/flat?kawasaki_tolerance=0.0001"));
    assert_eq!(status, 422, "{}", String::from_utf8_lossy(&body));
    assert!(String::from_utf8_lossy(&body).contains("kawasaki at v"));
    let (status, _) = server.get(&format!("/api/docs/{id}/flat"));
    assert_eq!(status, 200);
    for bad in ["0", "90", "abc"] {
        let (status, body) = server.get(&format!("/api/docs/{id}/layers?kawasaki_tolerance={bad}"));
        assert_eq!(status, 422, "{bad}");
        let text = String::from_utf8_lossy(&body);
        assert!(
            text.contains("45 degrees") && text.contains("fit it to the drawing"),
            "{bad}: {text}"
        );
    }
}

#[test]
fn a_unitless_pattern_asks_for_a_size_in_the_studios_words() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    // An ORIPA file has no physical size.
    let cp = std::fs::read(repo_file("examples/patterns/bird-base.cp")).unwrap();
    let (status, doc) = server.post_json("/api/upload?name=bird-base.cp", &cp);
    assert_eq!(status, 200, "{doc}");
    let id = doc["id"].as_u64().unwrap();
    let (status, body) = server.get(&format!(
        "/api/docs/{id}/plan?machine=grbl-diode&material=card-300gsm"
    ));
    let reply: Value = serde_json::from_slice(&body).unwrap();
    assert_eq!(status, 422, "{reply}");
    let error = reply["error"].as_str().unwrap();
    assert!(
        error.contains("no physical size") && error.contains("the studio's Size field"),
        "{error}"
    );
    // With the Size field's value the same plan is made.
    let (status, _) = server.get(&format!(
        "/api/docs/{id}/plan?machine=grbl-diode&material=card-300gsm&size=150"
    ));
    assert_eq!(status, 200);
}
