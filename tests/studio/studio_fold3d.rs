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

#[test]
fn the_flat_sheet_comes_first_and_the_fold_starts_from_it() {
    let dir = tempfile::tempdir().unwrap();
    let out = foldcam(&["generate", "miura", "-o", "miura.fold"], dir.path());
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let bytes = std::fs::read(dir.path().join("miura.fold")).unwrap();
    let file: Value = serde_json::from_slice(&bytes).unwrap();
    let server = Server::start(&[], dir.path());
    let (status, opened) = server.post_json("/api/upload?name=miura.fold", &bytes);
    assert_eq!(status, 200, "{opened}");
    let id = opened["id"].as_u64().unwrap();

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
