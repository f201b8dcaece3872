//! Other web pages cannot drive or read the studio (`src/studio/guard.rs`): a foreign `Host`
//! reads nothing, a state-changing request from another origin, without the page's token or
//! with a JSON body not sent as `application/json` changes nothing, every response carries
//! the security headers, and big assets are gzipped to the same bytes.

use crate::bin;
use crate::studio;

use std::io::Read;

use bin::foldcam;
use serde_json::Value;
use studio::{Reply, Server};

const PLAN: &str = "plan?machine=grbl-diode&material=card-300gsm";

/// The edit a hostile page sends: a mountain fold (edge 8 of the Miura-ori) becomes a cut.
const EDIT: &[u8] = br#"{"op": "assign", "edge": 8, "assignment": "C"}"#;

/// A studio on `miura.fold` (generated) with the file opened as document 0.
fn miura_studio(dir: &std::path::Path) -> (Server, u64) {
    let out = foldcam(&["generate", "miura", "-o", "miura.fold"], dir);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let server = Server::start(&["miura.fold"], dir);
    let (status, opened) = server.post_json("/api/files/0", b"");
    assert_eq!(status, 200, "{opened}");
    (server, opened["id"].as_u64().unwrap())
}

/// The plan of document `id` (its toolpaths and totals) and whether it has edits to undo.
fn snapshot(server: &Server, id: u64) -> (Value, Value) {
    let (status, plan) = server.get(&format!("/api/docs/{id}/{PLAN}"));
    assert_eq!(status, 200);
    let plan: Value = serde_json::from_slice(&plan).unwrap();
    (plan, undo_state(server, id))
}

/// Whether document `id` has edits to undo: an undo, redone at once when there was one.
fn undo_state(server: &Server, id: u64) -> Value {
    let (status, reply) = server.post_json(&format!("/api/docs/{id}/undo"), b"");
    if status == 200 {
        let (status, redone) = server.post_json(&format!("/api/docs/{id}/redo"), b"");
        assert_eq!(status, 200, "{redone}");
        return redone["history"].clone();
    }
    assert_eq!(status, 422, "{reply}");
    assert_eq!(reply["error"], "nothing to undo");
    serde_json::json!({"undo": false})
}

fn error_of(reply: &Reply) -> String {
    serde_json::from_slice::<Value>(&reply.body)
        .ok()
        .and_then(|v| v["error"].as_str().map(str::to_string))
        .unwrap_or_else(|| String::from_utf8_lossy(&reply.body).into_owned())
}

#[test]
fn a_text_plain_post_changes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let (server, id) = miura_studio(dir.path());
    let before = snapshot(&server, id);
    assert_eq!(before.1, serde_json::json!({"undo": false}));
    let host = server.addr;
    let path = format!("/api/docs/{id}/edit");

    // What another page's `fetch(…, {mode: 'no-cors', body: text})` or `<form
    // enctype=text/plain>` sends: no preflight, so it reaches the server.
    let browser_like = server.exact(
        &format!(
            "POST {path} HTTP/1.1\r\nHost: {host}\r\nOrigin: http://127.0.0.1:9\r\n\
             Sec-Fetch-Site: same-site\r\nContent-Type: text/plain;charset=UTF-8"
        ),
        EDIT,
    );
    assert_eq!(
        browser_like.status,
        403,
        "cross-origin text/plain edit: {}",
        error_of(&browser_like)
    );
    // Even with the page's token and no Origin, a JSON body must be sent as JSON.
    for content_type in [
        "Content-Type: text/plain",
        "Content-Type: application/x-www-form-urlencoded",
        "",
    ] {
        let sep = if content_type.is_empty() { "" } else { "\r\n" };
        let reply = server.exact(
            &format!(
                "POST {path} HTTP/1.1\r\nHost: {host}\r\nX-Foldcam-Token: {}{sep}{content_type}",
                server.token
            ),
            EDIT,
        );
        assert_eq!(reply.status, 415, "{content_type:?}: {}", error_of(&reply));
        assert!(
            error_of(&reply).contains("Content-Type: application/json"),
            "{}",
            error_of(&reply)
        );
    }
    assert_eq!(snapshot(&server, id), before, "the pattern changed");

    // The control: the same edit from the page is applied.
    let (status, edited) = server.post_json(&path, EDIT);
    assert_eq!(status, 200, "{edited}");
    assert_ne!(
        snapshot(&server, id).0,
        before.0,
        "the edit changed no plan"
    );
}

#[test]
fn a_foreign_origin_or_a_missing_token_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let (server, id) = miura_studio(dir.path());
    let before = snapshot(&server, id);
    let host = server.addr;
    let token = &server.token;
    let port = host.port();
    let json = "Content-Type: application/json";
    let refused = [
        // Another origin, even on this machine or with the token (which it cannot read).
        format!(
            "Origin: http://127.0.0.1:{}\r\nX-Foldcam-Token: {token}",
            port + 1
        ),
        format!("Origin: http://attacker.example:{port}\r\nX-Foldcam-Token: {token}"),
        format!("Origin: null\r\nX-Foldcam-Token: {token}"),
        format!("Sec-Fetch-Site: cross-site\r\nX-Foldcam-Token: {token}"),
        // No token, or another launch's.
        format!("Origin: http://{host}"),
        "X-Foldcam-Token: 00000000000000000000000000000000".to_string(),
    ];
    for headers in &refused {
        for (path, body) in [
            (format!("/api/docs/{id}/edit"), EDIT),
            ("/api/files/0".to_string(), &b""[..]),
            ("/api/upload?name=x.fold".to_string(), &b"{}"[..]),
        ] {
            let reply = server.exact(
                &format!("POST {path} HTTP/1.1\r\nHost: {host}\r\n{json}\r\n{headers}"),
                body,
            );
            assert_eq!(
                reply.status,
                403,
                "{path} with {headers:?}: {}",
                error_of(&reply)
            );
            assert!(
                error_of(&reply).contains("only the"),
                "{}",
                error_of(&reply)
            );
        }
    }
    assert_eq!(snapshot(&server, id), before, "the pattern changed");
    // No other document was opened: the next one opened is number 1.
    let (_, opened) = server.post_json("/api/files/0", b"");
    assert_eq!(opened["id"], 1, "a refused request opened a document");

    // The studio's own origins are accepted (the control).
    for origin in [format!("http://{host}"), format!("http://localhost:{port}")] {
        let reply = server.exact(
            &format!(
                "POST /api/docs/{id}/edit HTTP/1.1\r\nHost: {host}\r\n{json}\r\nOrigin: {origin}\r\n\
                 Sec-Fetch-Site: same-origin\r\nX-Foldcam-Token: {token}"
            ),
            EDIT,
        );
        assert_eq!(reply.status, 200, "{origin}: {}", error_of(&reply));
    }
}

#[test]
fn a_foreign_host_reads_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let (server, id) = miura_studio(dir.path());
    let port = server.addr.port();
    let paths = [
        "/".to_string(),
        "/api/files".to_string(),
        format!("/api/docs/{id}/{PLAN}"),
        format!("/api/docs/{id}/check"),
        format!("/api/docs/{id}/cut?machine=grbl-diode&material=card-300gsm&format=gcode"),
    ];
    for host in [
        format!("attacker.example:{port}"),
        format!("localhost.attacker.example:{port}"),
        format!("127.0.0.1:{}", port + 1),
        "localhost".to_string(),
    ] {
        for path in &paths {
            let reply = server.exact(&format!("GET {path} HTTP/1.1\r\nHost: {host}"), b"");
            let text = String::from_utf8_lossy(&reply.body);
            assert_eq!(reply.status, 403, "Host {host}, {path}: {text}");
            assert!(!text.contains("miura"), "Host {host}, {path} read {text}");
            assert!(text.contains("not this studio's address"), "{text}");
        }
    }
    // No Host at all (HTTP/1.0).
    let reply = server.exact("GET /api/files HTTP/1.0", b"");
    assert_eq!(reply.status, 403, "{}", error_of(&reply));
    // The addresses served are read (the control).
    for host in [
        format!("127.0.0.1:{port}"),
        format!("localhost:{port}"),
        format!("LocalHost:{port}"),
    ] {
        let reply = server.exact(&format!("GET /api/files HTTP/1.1\r\nHost: {host}"), b"");
        assert_eq!(reply.status, 200, "{host}: {}", error_of(&reply));
        assert!(String::from_utf8_lossy(&reply.body).contains("miura.fold"));
    }
}

#[test]
fn every_response_carries_the_security_headers() {
    let dir = tempfile::tempdir().unwrap();
    let (server, id) = miura_studio(dir.path());
    let host = server.addr;
    let token = &server.token;
    let requests = [
        ("page", format!("GET / HTTP/1.1\r\nHost: {host}")),
        ("module", format!("GET /app.js HTTP/1.1\r\nHost: {host}")),
        (
            "three.js gzipped",
            format!(
                "GET /vendor/three.module.min.js HTTP/1.1\r\nHost: {host}\r\nAccept-Encoding: gzip"
            ),
        ),
        ("API", format!("GET /api/files HTTP/1.1\r\nHost: {host}")),
        (
            "API plan",
            format!("GET /api/docs/{id}/{PLAN} HTTP/1.1\r\nHost: {host}"),
        ),
        (
            "no such page",
            format!("GET /nothing.js HTTP/1.1\r\nHost: {host}"),
        ),
        (
            "no such document",
            format!("GET /api/docs/99/check HTTP/1.1\r\nHost: {host}"),
        ),
        (
            "wrong method",
            format!("DELETE /api/files HTTP/1.1\r\nHost: {host}\r\nX-Foldcam-Token: {token}"),
        ),
        (
            "foreign host",
            "GET / HTTP/1.1\r\nHost: attacker.example".to_string(),
        ),
        (
            "no token",
            format!("POST /api/files/0 HTTP/1.1\r\nHost: {host}"),
        ),
        (
            "not JSON",
            format!(
                "POST /api/docs/{id}/edit HTTP/1.1\r\nHost: {host}\r\nX-Foldcam-Token: {token}\r\n\
                 Content-Type: text/plain"
            ),
        ),
    ];
    for (what, head) in &requests {
        let reply = server.exact(head, b"");
        let csp = reply.header("content-security-policy").unwrap_or_default();
        for part in [
            "default-src 'none'",
            "script-src 'self'",
            "frame-ancestors 'none'",
        ] {
            assert!(csp.contains(part), "{what} ({}): CSP {csp:?}", reply.status);
        }
        assert!(!csp.contains("unsafe"), "{what}: {csp}");
        assert_eq!(reply.header("x-frame-options"), Some("DENY"), "{what}");
        assert_eq!(
            reply.header("x-content-type-options"),
            Some("nosniff"),
            "{what}"
        );
        assert_eq!(
            reply.header("referrer-policy"),
            Some("no-referrer"),
            "{what}"
        );
    }
}

#[test]
fn big_assets_are_gzipped_and_decode_to_the_same_bytes() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let host = server.addr;
    let on_disk = std::fs::read(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("studio/vendor/three.module.min.js"),
    )
    .unwrap();
    let path = "/vendor/three.module.min.js";
    let plain = server.exact(&format!("GET {path} HTTP/1.1\r\nHost: {host}"), b"");
    assert_eq!(plain.status, 200);
    assert_eq!(plain.header("content-encoding"), None);
    assert!(plain.body == on_disk, "the plain reply is not the file");

    let gz = server.exact(
        &format!("GET {path} HTTP/1.1\r\nHost: {host}\r\nAccept-Encoding: gzip, deflate, br"),
        b"",
    );
    assert_eq!(gz.status, 200);
    assert_eq!(gz.header("content-encoding"), Some("gzip"));
    assert_eq!(
        gz.header("content-type"),
        Some("text/javascript; charset=utf-8")
    );
    let mut decoded = Vec::new();
    flate2::read::GzDecoder::new(&gz.body[..])
        .read_to_end(&mut decoded)
        .expect("valid gzip");
    assert!(
        decoded == on_disk,
        "the gzipped reply decodes to other bytes"
    );
    eprintln!(
        "three.js: {} bytes, {} gzipped",
        on_disk.len(),
        gz.body.len()
    );
    assert!(gz.body.len() * 3 < on_disk.len(), "{} bytes", gz.body.len());

    // Refused with q=0: sent as is.
    let no = server.exact(
        &format!("GET {path} HTTP/1.1\r\nHost: {host}\r\nAccept-Encoding: gzip;q=0"),
        b"",
    );
    assert_eq!(no.header("content-encoding"), None);
    assert!(no.body == on_disk);
}
