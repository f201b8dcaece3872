//! The 3D fold over HTTP: `fold3d?flat=true` answers with the flat sheet at once (the page
//! shows it as the first frame), and the simulation starts from that same sheet.

use crate::bin;
use crate::studio;

use bin::foldcam;
use serde_json::Value;
use studio::Server;

/// `GET path`, expecting a JSON reply with status 200.
fn get_json(server: &Server, path: &str) -> Value {
    let (status, body) = server.get(path);
    let reply: Value = serde_json::from_slice(&body).expect("a JSON reply");
    assert_eq!(status, 200, "{path}: {reply}");
    reply
}

/// The positions of a frame, as numbers.
fn positions(frame: &Value) -> Vec<f64> {
    frame["positions"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

/// A server with `foldcam generate miura`'s pattern uploaded: the server, the document id and
/// the FOLD file as JSON.
fn open_miura(dir: &std::path::Path) -> (Server, u64, Value) {
    let out = foldcam(&["generate", "miura", "-o", "miura.fold"], dir);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let bytes = std::fs::read(dir.join("miura.fold")).unwrap();
    let file: Value = serde_json::from_slice(&bytes).unwrap();
    let server = Server::start(&[], dir);
    let (status, opened) = server.post_json("/api/upload?name=miura.fold", &bytes);
    assert_eq!(status, 200, "{opened}");
    let id = opened["id"].as_u64().unwrap();
    (server, id, file)
}

#[test]
fn the_flat_sheet_comes_first_and_the_fold_starts_from_it() {
    let dir = tempfile::tempdir().unwrap();
    let (server, id, file) = open_miura(dir.path());

    // The flat sheet: one frame at 0 %, no simulation report, and every vertex where the
    // FOLD file puts it, with z = 0 (a Miura-ori has no cuts: one model vertex per vertex).
    let flat = get_json(&server, &format!("/api/docs/{id}/fold3d?flat=true"));
    assert!(
        flat["report"].is_null(),
        "nothing simulated: {}",
        flat["report"]
    );
    let frames = flat["frames"].as_array().unwrap();
    assert_eq!(frames.len(), 1);
    assert_eq!(frames[0]["percent"], 0.0);
    let sheet = positions(&frames[0]);
    let coords = file["vertices_coords"].as_array().unwrap();
    assert_eq!(sheet.len(), 3 * coords.len());
    for (v, c) in coords.iter().enumerate() {
        let (x, y) = (c[0].as_f64().unwrap(), c[1].as_f64().unwrap());
        // Sent as f32.
        assert_eq!(sheet[3 * v], f64::from(x as f32), "x of vertex {v}");
        assert_eq!(sheet[3 * v + 1], f64::from(y as f32), "y of vertex {v}");
        assert_eq!(sheet[3 * v + 2], 0.0, "z of vertex {v}");
    }
    let triangles = flat["triangles"].as_array().unwrap();
    assert!(!triangles.is_empty() && triangles.len().is_multiple_of(3));
    assert_eq!(
        flat["triangle_face"].as_array().unwrap().len(),
        triangles.len() / 3
    );

    // The simulation: the same triangles, its first frame is that sheet, and it folds away
    // from it (the settled end leaves the plane).
    let fold = get_json(&server, &format!("/api/docs/{id}/fold3d"));
    assert!(
        fold["report"]["steps"].as_u64().unwrap() > 0,
        "{}",
        fold["report"]
    );
    assert_eq!(fold["triangles"], flat["triangles"]);
    assert_eq!(fold["triangle_face"], flat["triangle_face"]);
    let frames = fold["frames"].as_array().unwrap();
    assert!(frames.len() > 2);
    assert_eq!(positions(&frames[0]), sheet);
    let end = frames.last().unwrap();
    assert_eq!(end["settled"], true);
    let height = positions(end)
        .chunks(3)
        .map(|p| p[2].abs())
        .fold(0.0, f64::max);
    assert!(height > 1.0, "the settled fold stays flat: |z| ≤ {height}");
}

/// `stream=true`: each load step's frame as a line as soon as it is made, then the whole fold.
/// The streamed frames are the fold's own, in order of rising percentage, each a folded state
/// of the same sheet: every crease and side keeps its flat length within 1% (the bars are
/// three to four orders stiffer than the creases), and the sheet contracts further at each
/// (a Miura-ori shrinks in both directions as it folds: its corners come closer).
#[test]
fn a_streamed_fold_sends_its_frames_as_lines_then_the_whole_fold() {
    let dir = tempfile::tempdir().unwrap();
    let (server, id, file) = open_miura(dir.path());

    let (status, body) = server.get(&format!("/api/docs/{id}/fold3d?stream=true"));
    assert_eq!(status, 200, "{}", String::from_utf8_lossy(&body));
    let text = String::from_utf8(body).unwrap();
    assert!(text.ends_with('\n'), "every line ends with a newline");
    let lines: Vec<Value> = text
        .lines()
        .map(|l| serde_json::from_str(l).expect("a JSON line"))
        .collect();
    let (done, streamed) = lines.split_last().unwrap();
    let fold = &done["done"];
    assert!(fold.is_object(), "the last line is the whole fold: {done}");
    assert!(fold["report"]["static_solve"]["used"].as_bool().unwrap());
    let streamed: Vec<&Value> = streamed.iter().map(|l| &l["frame"]).collect();
    assert!(streamed.len() >= 2 && streamed.iter().all(|f| f.is_object()));

    // The whole fold's frames: the flat sheet, the streamed ones, the end at 100 %.
    let frames = fold["frames"].as_array().unwrap();
    assert_eq!(frames.len(), streamed.len() + 2);
    assert_eq!(frames[0]["percent"], 0.0);
    assert_eq!(frames.last().unwrap()["percent"], 100.0);
    for (sent, kept) in streamed.iter().zip(&frames[1..]) {
        assert_eq!(*sent, kept);
        assert_eq!(sent["settled"], true, "a load step is a settled state");
    }

    // Lengths of the pattern's edges (model vertex v is pattern vertex v: no cuts).
    let edges: Vec<[usize; 2]> = file["edges_vertices"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| [0, 1].map(|k| e[k].as_u64().unwrap() as usize))
        .collect();
    let lengths = |p: &[f64]| -> Vec<f64> {
        let at = |v: usize| glam::DVec3::new(p[3 * v], p[3 * v + 1], p[3 * v + 2]);
        edges.iter().map(|[a, b]| at(*a).distance(at(*b))).collect()
    };
    let sheet = positions(&frames[0]);
    let flat = lengths(&sheet);
    // The corner farthest from vertex 0 in the flat sheet: the opposite one.
    let at = |p: &[f64], v: usize| glam::DVec3::new(p[3 * v], p[3 * v + 1], p[3 * v + 2]);
    let far = (0..sheet.len() / 3)
        .max_by(|&a, &b| {
            let d = |v| at(&sheet, 0).distance(at(&sheet, v));
            d(a).total_cmp(&d(b))
        })
        .unwrap();
    let mut span = at(&sheet, 0).distance(at(&sheet, far));
    let mut percent = 0.0;
    for frame in &frames[1..] {
        let p = positions(frame);
        for (e, (now, was)) in lengths(&p).iter().zip(&flat).enumerate() {
            assert!(
                (now - was).abs() < 0.01 * was,
                "edge {e} at {}%: {now} against {was} flat",
                frame["percent"]
            );
        }
        let now = at(&p, 0).distance(at(&p, far));
        let reached = frame["percent"].as_f64().unwrap();
        assert!(reached > percent, "{reached}% after {percent}%");
        assert!(
            now < span,
            "at {reached}% the corners are {now} apart, {span} before"
        );
        (span, percent) = (now, reached);
    }
}

/// A pattern without a face to fold is refused before anything is sent: the same 422, stage
/// and file with and without `stream`, never a stream that starts and then fails.
#[test]
fn a_fold_without_faces_is_refused_with_its_status_streamed_or_not() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let line = br#"{"file_spec":1.1,"vertices_coords":[[0,0],[1,0]],"edges_vertices":[[0,1]],"edges_assignment":["V"]}"#;
    let (status, opened) = server.post_json("/api/upload?name=line.fold", line);
    assert_eq!(status, 200, "{opened}");
    let id = opened["id"].as_u64().unwrap();
    for query in ["", "?stream=true"] {
        let (status, body) = server.get(&format!("/api/docs/{id}/fold3d{query}"));
        let reply: Value = serde_json::from_slice(&body).expect("one JSON body");
        assert_eq!(status, 422, "{query}: {reply}");
        assert_eq!(reply["stage"], "fold", "{reply}");
        assert_eq!(reply["file"], "line.fold", "{reply}");
        assert!(
            reply["error"].as_str().unwrap().contains("no face"),
            "{reply}"
        );
    }
}
