//! `foldcam serve` over plain HTTP: what the server refuses (paths from requests, oversized
//! uploads, profiles that are not shipped), errors carrying the command line's message, and
//! job files byte-identical to `foldcam cut`'s.

#[path = "common/bin.rs"]
mod bin;
#[path = "common/studio.rs"]
mod studio;

use bin::{foldcam, repo_file};
use serde_json::Value;
use studio::{Server, encode};

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
