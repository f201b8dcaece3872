//! Starting and saving over HTTP: the bundled examples and a blank sheet opened as
//! documents, the pattern saved as FOLD, SVG, `.cp`, `.opx` and its folded form (each read
//! back by `foldcam check --json`), the refusals, and the paper-craft job equal to the one
//! `foldcam papercraft --job` writes, edge numbers included.

use crate::bin;
use crate::studio;

use bin::{check_summary, foldcam, repo_file, vase_job_from_cli};
use serde_json::{Value, json};
use studio::Server;

fn ok(reply: (u16, Value)) -> Value {
    assert_eq!(reply.0, 200, "{}", reply.1);
    reply.1
}

fn json_of(bytes: &[u8]) -> Value {
    serde_json::from_slice(bytes)
        .unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(bytes)))
}

/// `foldcam check --json FILE`'s summary of `bytes` written as `name` in `dir`.
fn cli_summary(dir: &std::path::Path, name: &str, bytes: &[u8]) -> Value {
    std::fs::write(dir.join(name), bytes).unwrap();
    check_summary(dir, name)
}

/// `GET /api/docs/{id}/save?format={format}`: the whole reply, headers included.
fn save(server: &Server, id: u64, format: &str) -> studio::Reply {
    server.exact(
        &format!(
            "GET /api/docs/{id}/save?format={format} HTTP/1.1\r\nHost: {}",
            server.addr
        ),
        b"",
    )
}

/// The burn length of operation `op` in a plan's statistics, mm (0 when it has none).
fn length_of(stats: &Value, op: &str) -> f64 {
    stats["length_mm"]
        .as_array()
        .unwrap()
        .iter()
        .find(|e| e[0].as_str().is_some_and(|o| o.eq_ignore_ascii_case(op)))
        .map_or(0.0, |e| e[1].as_f64().unwrap())
}

#[test]
fn the_examples_are_listed_in_groups_and_open_as_the_cli_makes_them() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let (status, body) = server.get("/api/examples");
    assert_eq!(status, 200);
    let groups = json_of(&body);
    let groups = groups.as_array().unwrap();
    let names: Vec<&str> = groups
        .iter()
        .map(|g| g["group"].as_str().unwrap())
        .collect();
    for wanted in [
        "Simple folds",
        "Origami bases",
        "Tessellations",
        "Paper craft",
    ] {
        assert!(names.contains(&wanted), "{names:?}");
    }
    for g in groups {
        for e in g["examples"].as_array().unwrap() {
            for key in ["name", "file", "title", "description"] {
                assert!(
                    !e[key].as_str().unwrap_or_default().is_empty(),
                    "{key} of {e}"
                );
            }
        }
    }

    // The Miura-ori example is `foldcam generate miura`'s pattern.
    let opened = ok(server.post_json("/api/examples/miura-ori", b""));
    assert_eq!(opened["name"], "miura-ori.fold");
    let out = foldcam(&["generate", "miura", "-o", "miura.fold"], dir.path());
    assert!(out.status.success());
    let summary = check_summary(dir.path(), "miura.fold");
    assert_eq!(opened["counts"]["edges"], summary["edges"]);
    assert_eq!(opened["counts"]["assignments"], summary["assignments"]);

    // An ORIPA example is read as the file itself.
    let opened = ok(server.post_json("/api/examples/preliminary-base", b""));
    let path = repo_file("examples/patterns/preliminary-base.cp");
    let s = check_summary(dir.path(), &path);
    let counts =
        json!({"vertices": s["vertices"], "edges": s["edges"], "assignments": s["assignments"]});
    assert_eq!(opened["counts"], counts);

    // An unknown example: 404 naming the examples there are.
    let (status, body) = server.post_json("/api/examples/crane", b"");
    assert_eq!(status, 404);
    let message = body["error"].as_str().unwrap();
    assert!(
        message.contains("\"crane\"") && message.contains("miura-ori"),
        "{message}"
    );
}

#[test]
fn a_blank_sheet_is_a_bounded_square_outline() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let opened = ok(server.post_json("/api/blank", b""));
    assert_eq!(opened["counts"]["edges"], 4);
    assert_eq!(opened["counts"]["assignments"]["boundary"], 4);
    assert_eq!(opened["units"], "mm");
    let xs: Vec<f64> = (opened["vertices"].as_array().unwrap().iter())
        .flat_map(|p| [p[0].as_f64().unwrap(), p[1].as_f64().unwrap()])
        .collect();
    assert_eq!(xs.iter().copied().fold(f64::MIN, f64::max), 150.0);
    assert_eq!(xs.iter().copied().fold(f64::MAX, f64::min), 0.0);

    let opened = ok(server.post_json("/api/blank?side=297", b""));
    let top = (opened["vertices"].as_array().unwrap().iter())
        .map(|p| p[1].as_f64().unwrap())
        .fold(f64::MIN, f64::max);
    assert_eq!(top, 297.0);

    // Beyond the limits, or not a number: 422 naming the side and the range.
    for bad in ["0", "-3", "20000", "NaN", "wide"] {
        let (status, body) = server.post_json(&format!("/api/blank?side={bad}"), b"");
        assert_eq!(status, 422, "{bad}: {body}");
        let message = body["error"].as_str().unwrap();
        assert!(
            message.contains("side") && message.contains("from 1 to 10000 mm"),
            "{bad}: {message}"
        );
    }

    // Opening is a change: another page's request (no token, foreign origin) is refused.
    let reply = server.exact(
        &format!(
            "POST /api/blank HTTP/1.1\r\nHost: {}\r\nOrigin: http://evil.example\r\n\
             Content-Type: text/plain",
            server.addr
        ),
        b"",
    );
    assert_eq!(reply.status, 403);
    let reply = server.exact(
        &format!(
            "POST /api/examples/miura-ori HTTP/1.1\r\nHost: {}",
            server.addr
        ),
        b"",
    );
    assert_eq!(reply.status, 403, "no token");
}

#[test]
fn a_crease_drawn_on_a_blank_sheet_is_saved_in_every_format_and_read_back() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let opened = ok(server.post_json("/api/blank", b""));
    let id = opened["id"].as_u64().unwrap();
    let edit = json!({"op": "add", "from": [0.0, 0.0], "to": [150.0, 150.0], "assignment": "V"});
    let edited = ok(server.post_json(
        &format!("/api/docs/{id}/edit"),
        &serde_json::to_vec(&edit).unwrap(),
    ));
    assert_eq!(edited["counts"]["assignments"]["valley"], 1);

    for (format, file) in [
        ("fold", "blank.fold"),
        ("svg", "blank.svg"),
        ("cp", "blank.cp"),
        ("opx", "blank.opx"),
    ] {
        let reply = save(&server, id, format);
        assert_eq!(reply.status, 200, "{format}");
        assert_eq!(
            reply.header("content-disposition"),
            Some(format!("attachment; filename=\"{file}\"").as_str())
        );
        let summary = cli_summary(dir.path(), file, &reply.body);
        assert_eq!(summary["edges"], 5, "{format}: {summary}");
        assert_eq!(summary["assignments"]["valley"], 1, "{format}: {summary}");
        assert_eq!(summary["assignments"]["boundary"], 4, "{format}: {summary}");
    }

    // An unsupported format: 422 naming those saved; a closed document: 404.
    let (status, body) = server.get(&format!("/api/docs/{id}/save?format=dxf"));
    assert_eq!(status, 422);
    let message = json_of(&body)["error"].as_str().unwrap().to_string();
    assert!(
        message.contains("\"dxf\"") && message.contains("fold, svg, cp, opx or folded"),
        "{message}"
    );
    let (status, _) = server.get("/api/docs/999/save?format=fold");
    assert_eq!(status, 404);
}

#[test]
fn the_folded_form_is_a_fold_file_whose_key_frame_is_folded() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let opened = ok(server.post_json("/api/examples/flat-vertex", b""));
    let id = opened["id"].as_u64().unwrap();
    let reply = save(&server, id, "folded");
    assert_eq!(
        reply.status,
        200,
        "{}",
        String::from_utf8_lossy(&reply.body)
    );
    assert_eq!(
        reply.header("content-disposition"),
        Some("attachment; filename=\"flat-vertex-folded.fold\"")
    );
    let fold = json_of(&reply.body);
    assert_eq!(fold["frame_classes"], json!(["foldedForm"]));
    assert_eq!(fold["frame_attributes"], json!(["3D"]));
    assert!(fold.get("file_frames").is_none());
    let coords = fold["vertices_coords"].as_array().unwrap();
    assert!(coords.iter().all(|p| p.as_array().unwrap().len() == 3));
    assert!(
        coords.iter().any(|p| p[2].as_f64().unwrap().abs() > 1.0),
        "the sheet left the plane"
    );
    // foldcam reads it back (unfolded): the same creases.
    let summary = cli_summary(dir.path(), "folded.fold", &reply.body);
    assert_eq!(summary["edges"], opened["counts"]["edges"]);
    assert_eq!(summary["assignments"], opened["counts"]["assignments"]);
}

#[test]
fn the_paper_craft_job_is_the_clis_with_the_edge_numbers() {
    let dir = tempfile::tempdir().unwrap();
    let cli = vase_job_from_cli(dir.path(), "grbl-diode", "paper-160gsm");

    let server = Server::start(&[], dir.path());
    let opened = ok(server.post_json("/api/examples/vase", b""));
    let id = opened["id"].as_u64().unwrap();
    let query = "machine=grbl-diode&material=paper-160gsm";
    let (status, body) = server.get(&format!("/api/docs/{id}/plan?{query}"));
    assert_eq!(status, 200, "{}", String::from_utf8_lossy(&body));
    let plan = json_of(&body);
    let mark = length_of(&plan["stats"], "mark");
    assert!((mark - 144.0).abs() < 0.5, "edge numbers marked: {mark} mm");
    let (status, job) = server.get(&format!("/api/docs/{id}/cut?{query}&format=gcode"));
    assert_eq!(status, 200, "{}", String::from_utf8_lossy(&job));
    assert!(
        job == cli,
        "the studio's job differs from `foldcam papercraft --job`'s"
    );

    // Flat lines chosen "skip" in the studio leave them out, as `--flat skip` does.
    let (_, body) = server.get(&format!("/api/docs/{id}/plan?{query}&flat=skip"));
    assert_eq!(length_of(&json_of(&body)["stats"], "mark"), 0.0);
}
