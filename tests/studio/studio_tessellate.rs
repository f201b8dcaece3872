//! The studio's tessellation designer over HTTP (Tachi 2014): a bundled mesh solved through the
//! API with its progress polled, the saved design file run through `foldcam tessellate`, and
//! the two crease patterns compared; a solve stopped by its iteration cap shows where it misses
//! the limits, as the command's report says; a long solve is cancelled.

use crate::bin;
use crate::studio;

use std::time::{Duration, Instant};

use bin::{foldcam, repo_file};
use serde_json::{Value, json};
use studio::{Server, encode};

/// Coordinates and fold angles of the studio's FOLD and the command's agree this closely
/// (millimetres, degrees): the same solve on the same input.
const TOLERANCE: f64 = 1e-9;

/// Longest a test waits for a solve to end.
const SOLVE_WAIT: Duration = Duration::from_secs(240);

fn ok(reply: (u16, Value)) -> Value {
    assert_eq!(reply.0, 200, "{}", reply.1);
    reply.1
}

fn get_json(server: &Server, path: &str) -> (u16, Value) {
    let (status, body) = server.get(path);
    (status, serde_json::from_slice(&body).expect("a JSON reply"))
}

/// Polls job `job` until it leaves `running`: its last state and every event it sent.
fn wait(server: &Server, job: u64) -> (Value, Vec<Value>) {
    let start = Instant::now();
    let mut events = Vec::new();
    loop {
        let state = ok(get_json(
            server,
            &format!("/api/tess/jobs/{job}?since={}", events.len()),
        ));
        events.extend(state["events"].as_array().unwrap().iter().cloned());
        assert_eq!(state["next"].as_u64(), Some(events.len() as u64));
        if state["status"] != "running" {
            return (state, events);
        }
        assert!(start.elapsed() < SOLVE_WAIT, "the solve did not end");
        std::thread::sleep(Duration::from_millis(200));
    }
}

/// Starts a solve of mesh `mesh` with `options`: the job id.
fn start(server: &Server, mesh: u64, options: Value) -> u64 {
    let reply = ok(server.post_json(
        &format!("/api/tess/mesh/{mesh}/solve"),
        options.to_string().as_bytes(),
    ));
    reply["job"].as_u64().unwrap()
}

fn numbers(v: &Value) -> Vec<f64> {
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
}

/// The studio's FOLD equals the command's: topology and assignments exactly, coordinates of
/// both frames and fold angles within [`TOLERANCE`].
fn assert_same_fold(studio: &Value, cli: &Value) {
    for key in ["edges_vertices", "edges_assignment", "faces_vertices"] {
        assert_eq!(studio[key], cli[key], "{key}");
    }
    let (a, b) = (numbers(studio), numbers(cli));
    assert_eq!(a.len(), b.len(), "numbers in the two files");
    for (x, y) in a.iter().zip(&b) {
        assert!((x - y).abs() <= TOLERANCE, "{x} vs {y}");
    }
}

/// Faces of an OBJ file, counted from its text.
fn obj_faces(text: &str) -> usize {
    text.lines().filter(|l| l.starts_with("f ")).count()
}

#[test]
fn a_solve_streams_its_progress_and_saves_a_design_the_command_rebuilds() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let setup = ok(get_json(&server, "/api/tess/setup"));
    assert!(
        setup["examples"].to_string().contains("dome.obj"),
        "{setup}"
    );
    let steel = setup["materials"]
        .as_array()
        .unwrap()
        .iter()
        .find(|m| m["name"] == "stainless-0.5")
        .expect("the stainless material")
        .clone();
    let dome_text = std::fs::read_to_string(repo_file("examples/tessellation/dome.obj")).unwrap();
    let mesh = ok(server.post_json("/api/tess/example/dome.obj", b""));
    assert_eq!(
        mesh["faces"].as_array().unwrap().len(),
        obj_faces(&dome_text)
    );

    let job = start(
        &server,
        mesh["id"].as_u64().unwrap(),
        json!({"material": "stainless-0.5"}),
    );
    let (state, events) = wait(&server, job);
    assert_eq!(state["status"], "done", "{state}");
    // The progress: the command's notes (the estimate among them) and the solver's
    // iterations, numbered 1, 2, … within each attempt, the last one developable.
    let notes: Vec<&str> = events
        .iter()
        .filter(|e| e["kind"] == "note")
        .map(|e| e["text"].as_str().unwrap())
        .collect();
    // The estimate names as many solves as the page is told the plan has.
    let estimate = notes
        .iter()
        .find(|n| n.starts_with("estimate:"))
        .unwrap_or_else(|| panic!("{notes:?}"));
    let planned: u64 = estimate
        .split("up to ")
        .nth(1)
        .and_then(|t| t.split(' ').next())
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("{estimate}"));
    let iterations: Vec<&Value> = events.iter().filter(|e| e["kind"] == "iteration").collect();
    assert!(!iterations.is_empty());
    for it in &iterations {
        assert_eq!(it["attempts"].as_u64(), Some(planned), "{estimate}: {it}");
    }
    for pair in iterations.windows(2) {
        let (a, b) = (pair[0]["index"].as_u64(), pair[1]["index"].as_u64());
        let next_attempt = pair[1]["attempt"].as_u64() > pair[0]["attempt"].as_u64();
        assert!(next_attempt || b == a.map(|a| a + 1), "{pair:?}");
    }
    let last = iterations.last().unwrap();
    assert!(last["developability"].as_f64().unwrap() <= 1e-12, "{last}");

    // The folded form is within the material's limits at every crease and vertex: measured
    // here from the positions the page gets, not from the server's flags.
    let result = ok(get_json(&server, &format!("/api/tess/jobs/{job}/result")));

    // Each iteration's progress line is the command's bar: the iteration out of the cap, the
    // solve of the schedule with its shrink and triangles, the residual, the time left. The
    // solve that made the design is read off the report: its shrink and whether remeshed.
    let lines: Vec<&str> = result["lines"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l.as_str().unwrap())
        .collect();
    let shrink = lines[0]
        .split(", ")
        .find_map(|part| part.strip_prefix("shrink "))
        .expect("the report names the shrink");
    let triangles = if lines.iter().any(|l| l.contains("remeshed to")) {
        "re-triangulation"
    } else {
        "input's triangles"
    };
    let cap = setup["defaults"]["max_iterations"].as_u64().unwrap();
    let refused = notes.iter().filter(|n| n.starts_with("shrink ")).count() as u64;
    for it in &iterations {
        let text = it["progress"].as_str().unwrap();
        assert!(
            text.starts_with(&format!("iteration {}/{cap} ", it["index"])),
            "{text}"
        );
        // The time left is said only once two iterations of the solve are timed.
        if it["index"].as_u64().unwrap() >= 2 {
            assert!(text.contains(" left in this solve"), "{text}");
            assert!(it["seconds_left"].as_f64().unwrap() >= 0.0, "{it}");
        } else {
            assert!(
                text.ends_with("time left measured after two iterations"),
                "{text}"
            );
            assert!(it["seconds_left"].is_null(), "{it}");
        }
    }
    // The last solve is the one after every refused attempt (one note each).
    assert_eq!(last["attempt"].as_u64(), Some(refused + 1), "{last}");
    let solves = last["attempts"].as_u64().unwrap();
    let text = last["progress"].as_str().unwrap();
    assert!(
        text.contains(&format!(
            ": shrink {shrink} on the {triangles} (solve {} of at most {solves}), developability ",
            refused + 1
        )),
        "{text}"
    );
    // Converged within the tolerance: nothing left (the geometric estimate's closed form).
    assert!(text.ends_with("about 0 s left in this solve"), "{text}");
    assert_eq!(result["made"], true);
    assert_eq!(result["violations"], json!({"creases": 0, "vertices": 0}));
    let max_fold = steel["max_fold_angle"].as_f64().unwrap();
    assert_eq!(result["limits"]["max_fold_angle"].as_f64(), Some(max_fold));
    let folded = &result["folded"];
    let p: Vec<[f64; 3]> = folded["positions"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| [0, 1, 2].map(|k| v[k].as_f64().unwrap()))
        .collect();
    let min_angle = steel["min_vertex_angle"].as_f64().unwrap();
    for t in folded["triangles"].as_array().unwrap() {
        let t: Vec<usize> = t
            .as_array()
            .unwrap()
            .iter()
            .map(|i| i.as_u64().unwrap() as usize)
            .collect();
        // Every triangle corner is at least the vertex-angle limit (sectors joined across
        // flat diagonals are only larger), within the solver's developability tolerance.
        for k in 0..3 {
            let (o, a, b) = (p[t[k]], p[t[(k + 1) % 3]], p[t[(k + 2) % 3]]);
            let u = [a[0] - o[0], a[1] - o[1], a[2] - o[2]];
            let v = [b[0] - o[0], b[1] - o[1], b[2] - o[2]];
            let dot: f64 = (0..3).map(|i| u[i] * v[i]).sum();
            let nu = (0..3).map(|i| u[i] * u[i]).sum::<f64>().sqrt();
            let nv = (0..3).map(|i| v[i] * v[i]).sum::<f64>().sqrt();
            let angle = (dot / (nu * nv)).clamp(-1.0, 1.0).acos().to_degrees();
            let flat_diagonal_side = folded["creases"]
                .as_array()
                .unwrap()
                .iter()
                .any(|c| c["a"] == "F" && c["v"].as_array().unwrap().iter().any(|v| v == t[k]));
            assert!(
                flat_diagonal_side || angle >= min_angle - 1e-9,
                "corner of {angle} deg"
            );
        }
    }
    for c in folded["creases"].as_array().unwrap() {
        assert!(c["fold"].as_f64().unwrap().abs() <= max_fold, "{c}");
    }

    // The design saved and its mesh beside it, as the page saves them.
    let (status, design) = server.get(&format!("/api/tess/jobs/{job}/design"));
    assert_eq!(status, 200);
    let (status, mesh_bytes) = server.get(&format!("/api/tess/jobs/{job}/mesh"));
    assert_eq!(status, 200);
    assert_eq!(mesh_bytes, dome_text.as_bytes());
    std::fs::write(dir.path().join("dome.tess.toml"), &design).unwrap();
    std::fs::write(dir.path().join("dome.obj"), &mesh_bytes).unwrap();
    let out = foldcam(
        &["tessellate", "dome.tess.toml", "-o", "cli.fold"],
        dir.path(),
    );
    assert!(
        out.status.success(),
        "{}\n{}",
        String::from_utf8_lossy(&out.stderr),
        String::from_utf8_lossy(&design)
    );
    let cli: Value =
        serde_json::from_slice(&std::fs::read(dir.path().join("cli.fold")).unwrap()).unwrap();
    let (status, fold) = server.get(&format!("/api/tess/jobs/{job}/fold"));
    assert_eq!(status, 200);
    let studio: Value = serde_json::from_slice(&fold).unwrap();
    assert_same_fold(&studio, &cli);
    // The crease pattern the page draws is the file's.
    let pattern = &result["pattern"];
    assert_eq!(
        pattern["edges"].as_array().unwrap().len(),
        cli["edges_vertices"].as_array().unwrap().len()
    );
    // And the same as the mesh given directly with the stainless limits (the README's line).
    let out = foldcam(
        &[
            "tessellate",
            &repo_file("examples/tessellation/dome.obj"),
            "-x",
            "stainless-0.5",
            "-o",
            "direct.fold",
        ],
        dir.path(),
    );
    assert!(out.status.success());
    let direct: Value =
        serde_json::from_slice(&std::fs::read(dir.path().join("direct.fold")).unwrap()).unwrap();
    assert_same_fold(&direct, &cli);

    // Opened as a studio document: the pattern `foldcam check` sees.
    let doc = ok(server.post_json(&format!("/api/tess/jobs/{job}/pattern"), b""));
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
    assert_eq!(server.get(&format!("/api/docs/{}/check", doc["id"])).0, 200);
}

#[test]
fn a_stopped_solve_shows_where_it_misses_the_limits() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let mesh = ok(server.post_json("/api/tess/example/dome.obj", b""))["id"]
        .as_u64()
        .unwrap();
    // One iteration cannot make the tucked dome developable.
    let options = json!({"shrink": 0.8, "max_iterations": 1, "remesh": "never"});
    let job = start(&server, mesh, options);
    let (state, _) = wait(&server, job);
    assert_eq!(state["status"], "refused", "{state}");
    let result = ok(get_json(&server, &format!("/api/tess/jobs/{job}/result")));
    assert_eq!(result["made"], false);
    assert!(result["pattern"].is_null());
    // Every vertex the page marks as off developability is off by more than the tolerance.
    let marked: Vec<&Value> = result["folded"]["vertices"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|v| v["undevelopable"] == true)
        .collect();
    assert!(!marked.is_empty());
    assert!(marked.iter().all(|v| v["defect"].as_f64().unwrap() > 1e-12));
    assert_eq!(
        result["violations"]["vertices"].as_u64().unwrap() as usize,
        result["folded"]["vertices"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|v| v["undevelopable"] == true || v["under"] == true)
            .count()
    );
    // The command refuses the saved design the same way, with the same report.
    let (_, design) = server.get(&format!("/api/tess/jobs/{job}/design"));
    std::fs::write(dir.path().join("dome.tess.toml"), &design).unwrap();
    std::fs::copy(
        repo_file("examples/tessellation/dome.obj"),
        dir.path().join("dome.obj"),
    )
    .unwrap();
    let out = foldcam(
        &["tessellate", "dome.tess.toml", "-o", "x.fold"],
        dir.path(),
    );
    assert_eq!(out.status.code(), Some(1));
    assert!(!dir.path().join("x.fold").exists());
    let stdout = String::from_utf8_lossy(&out.stdout);
    let studio_lines: Vec<&str> = result["lines"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l.as_str().unwrap())
        .collect();
    // The first line names the mesh as each was given; the rest are the same.
    let cli_lines: Vec<&str> = stdout.lines().collect();
    assert_eq!(cli_lines.len(), studio_lines.join("\n").lines().count());
    assert_eq!(
        cli_lines[1..],
        studio_lines.join("\n").lines().collect::<Vec<_>>()[1..]
    );
    // Nothing to save as a pattern.
    assert_eq!(server.get(&format!("/api/tess/jobs/{job}/fold")).0, 409);
}

/// Uploads the bundled cap.obj (432 faces, a solve of a few hundred iterations) and starts
/// its solve with the default options: the job's id.
fn start_cap(server: &Server) -> u64 {
    let cap = std::fs::read(repo_file("examples/tessellation/cap.obj")).unwrap();
    let mesh = ok(server.post_json("/api/tess/mesh?name=cap.obj", &cap));
    start(server, mesh["id"].as_u64().unwrap(), json!({}))
}

#[test]
fn a_long_solve_is_cancelled_and_bad_options_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    // cap.obj (432 faces) takes a few hundred iterations: cancelled after its first, it stops
    // after the iteration running when the cancel is answered.
    let job = start_cap(&server);
    let begun = Instant::now();
    loop {
        let state = ok(get_json(&server, &format!("/api/tess/jobs/{job}")));
        let events = state["events"].as_array().unwrap();
        if events.iter().any(|e| e["kind"] == "iteration") {
            break;
        }
        assert_eq!(state["status"], "running", "{state}");
        assert!(begun.elapsed() < SOLVE_WAIT, "no iteration came");
        std::thread::sleep(Duration::from_millis(100));
    }
    ok(server.post_json(&format!("/api/tess/jobs/{job}/cancel"), b""));
    // Iterations heard once the cancel is answered: the solve may finish the one running.
    let at_cancel = ok(get_json(&server, &format!("/api/tess/jobs/{job}")))["events"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|e| e["kind"] == "iteration")
        .count();
    let (state, events) = wait(&server, job);
    assert_eq!(state["status"], "cancelled", "{state}");
    // Stopped after the running iteration, not at the end of the solve (minutes away, a few
    // hundred iterations): a cancelled job carries no error.
    assert!(state["error"].is_null(), "{state}");
    let late = events.iter().filter(|e| e["kind"] == "iteration").count();
    assert!(
        late <= at_cancel + 1 && late < 100,
        "{late} iterations heard in all, {at_cancel} when the cancel was answered"
    );
    let after = ok(get_json(&server, &format!("/api/tess/jobs/{job}")));
    assert_eq!(after["next"].as_u64(), Some(events.len() as u64));
    assert_eq!(server.get(&format!("/api/tess/jobs/{job}/result")).0, 409);

    // Options out of range carry the command's messages; a file that is no mesh is refused.
    let dome = ok(server.post_json("/api/tess/example/dome.obj", b""))["id"]
        .as_u64()
        .unwrap();
    let (status, body) = server.post_json(
        &format!("/api/tess/mesh/{dome}/solve"),
        br#"{"max_iterations": 0}"#,
    );
    assert_eq!(status, 422);
    assert!(
        body["error"].as_str().unwrap().contains("--max-iterations"),
        "{body}"
    );
    let (status, body) = server.post_json(
        &format!("/api/tess/mesh/{dome}/solve"),
        br#"{"tuck": "spiral"}"#,
    );
    assert_eq!(status, 422, "{body}");
    let (status, body) = server.post_json(
        &format!("/api/tess/mesh?name={}", encode("x.obj")),
        b"v 1 2\n",
    );
    assert_eq!(status, 422, "{body}");
    assert!(
        body["error"].as_str().unwrap().starts_with("x.obj"),
        "{body}"
    );
}

#[test]
fn the_command_reads_a_design_file_whose_options_its_flags_override() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::copy(
        repo_file("examples/tessellation/dome.obj"),
        d.join("dome.obj"),
    )
    .unwrap();
    let design = "mesh = \"dome.obj\"\n[tessellation]\ntuck = \"truncated\"\nshrink = 0.7\n";
    std::fs::write(d.join("d.tess.toml"), design).unwrap();
    let run = |args: &[&str]| foldcam(args, d);
    let read = |name: &str| -> Value {
        serde_json::from_slice(&std::fs::read(d.join(name)).unwrap()).unwrap()
    };
    // The file's truncated stars are what `--tuck truncated --shrink 0.7` makes.
    assert!(
        run(&["tessellate", "d.tess.toml", "-o", "file.fold"])
            .status
            .success()
    );
    let flags = ["--tuck", "truncated", "--shrink", "0.7", "-o", "flags.fold"];
    assert!(
        run(&[&["tessellate", "dome.obj"][..], &flags].concat())
            .status
            .success()
    );
    assert_same_fold(&read("file.fold"), &read("flags.fold"));
    // A flag given overrides the file: `--tuck star` is the plain star at shrink 0.7.
    let over = [
        "tessellate",
        "d.tess.toml",
        "--tuck",
        "star",
        "-o",
        "over.fold",
    ];
    assert!(run(&over).status.success());
    let plain = [
        "tessellate",
        "dome.obj",
        "--shrink",
        "0.7",
        "-o",
        "plain.fold",
    ];
    assert!(run(&plain).status.success());
    assert_same_fold(&read("over.fold"), &read("plain.fold"));
    assert_ne!(
        read("over.fold")["edges_vertices"],
        read("file.fold")["edges_vertices"]
    );

    // Bad input: exit 2, the file and the key named, nothing written.
    std::fs::write(
        d.join("bad.tess.toml"),
        "mesh = \"dome.obj\"\n[tessellation]\nmax_fold_angle = 200\n",
    )
    .unwrap();
    let out = run(&["tessellate", "bad.tess.toml", "-o", "bad.fold"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("bad.tess.toml") && err.contains("max_fold_angle"),
        "{err}"
    );
    std::fs::write(d.join("lost.tess.toml"), "mesh = \"nowhere.obj\"\n").unwrap();
    let out = run(&["tessellate", "lost.tess.toml", "-o", "lost.fold"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("nowhere.obj"));
    assert!(!d.join("bad.fold").exists() && !d.join("lost.fold").exists());
}

#[test]
fn a_solve_whose_page_stops_asking_is_cancelled() {
    let dir = tempfile::tempdir().unwrap();
    // Cancelled after 1 s without a progress request (90 s by default).
    let server = Server::start(&["--abandon-after", "1"], dir.path());
    let job = start_cap(&server);
    // While the page asks several times a second, the solve runs on.
    let begun = Instant::now();
    loop {
        let state = ok(get_json(&server, &format!("/api/tess/jobs/{job}")));
        let iterations = state["events"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|e| e["kind"] == "iteration")
            .count();
        assert_eq!(state["status"], "running", "{state}");
        if iterations >= 2 && begun.elapsed() > Duration::from_secs(2) {
            break;
        }
        assert!(begun.elapsed() < SOLVE_WAIT, "no iterations came");
        std::thread::sleep(Duration::from_millis(200));
    }
    // Then it goes quiet, as a closed tab does: the solve stops at its next iteration.
    let state = loop {
        std::thread::sleep(Duration::from_secs(4));
        let state = ok(get_json(&server, &format!("/api/tess/jobs/{job}")));
        if state["status"] != "running" {
            break state;
        }
        assert!(begun.elapsed() < SOLVE_WAIT, "never cancelled: {state}");
    };
    assert_eq!(state["status"], "cancelled", "{state}");
    assert!(
        state["error"]
            .as_str()
            .is_some_and(|e| e.contains("stopped asking for progress")),
        "{state}"
    );
}

/// The studio says what the command says of a partial form: the saddle's star tucks leave a
/// face corner over 5% of its size from it (`partial` names why, as `foldcam tessellate`
/// does before it exits 1); the dome's form is whole (`partial` null).
#[test]
fn a_partial_form_is_named_as_the_command_names_it() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let mut why = Vec::new();
    for example in ["saddle.obj", "dome.obj"] {
        let mesh = ok(server.post_json(&format!("/api/tess/example/{example}"), b""))["id"]
            .as_u64()
            .unwrap();
        let job = start(&server, mesh, json!({"material": "stainless-0.5"}));
        let (state, _) = wait(&server, job);
        assert_eq!(state["status"], "done", "{example}: {state}");
        let result = ok(get_json(&server, &format!("/api/tess/jobs/{job}/result")));
        why.push(result["partial"].clone());
    }
    let saddle = why[0].as_str().expect("the saddle is partial");
    assert!(saddle.starts_with("a face corner lies 10.7 mm"), "{saddle}");
    assert!(why[1].is_null(), "{}", why[1]);
    // The command's words for the same mesh.
    let o = foldcam(
        &[
            "tessellate",
            &repo_file("examples/tessellation/saddle.obj"),
            "-x",
            "stainless-0.5",
            "-o",
            "s.fold",
        ],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&o.stderr).contains(saddle));
}
