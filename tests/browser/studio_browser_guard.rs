//! A web page on another origin (another port of 127.0.0.1) opened in Chromium tries what a
//! hostile page can do without CORS: `no-cors` `fetch`es with `text/plain` and empty bodies,
//! a `text/plain` form post, and a CORS read of the file list. The studio's API then shows
//! that nothing changed and nothing was opened.

use crate::bin;
use crate::browser;
use crate::studio;

use std::io::{BufRead, BufReader, Write};
use std::net::TcpListener;
use std::time::Duration;

use bin::foldcam;
use browser::{browser, click, open_studio, start_driver, wait_until};
use serde_json::Value;
use studio::Server;

/// The hostile page; `STUDIO` is replaced by the studio's URL (no trailing slash).
const PAGE: &str = r#"<!doctype html>
<html><head><meta charset="utf-8"><title>elsewhere</title></head>
<body>
<form id="f" method="POST" action="STUDIO/api/docs/0/edit" enctype="text/plain" target="sink">
<input name='{"op": "assign", "edge": 9, "assignment": "C", "x": "' value='"}'>
</form>
<iframe name="sink"></iframe>
<script>
const studio = 'STUDIO';
const edit = JSON.stringify({ op: 'assign', edge: 8, assignment: 'C' });
const tries = [
  fetch(studio + '/api/docs/0/edit',
    { method: 'POST', mode: 'no-cors', headers: { 'content-type': 'text/plain' }, body: edit }),
  fetch(studio + '/api/files/0', { method: 'POST', mode: 'no-cors' }),
  fetch(studio + '/api/upload?name=x.fold', { method: 'POST', mode: 'no-cors', body: '{}' }),
  fetch(studio + '/api/files').then((r) => r.text()).then((t) => { document.body.dataset.read = t; }),
];
Promise.allSettled(tries).then((rs) => {
  document.body.dataset.fetched = rs.map((r) => r.status).join(',');
  document.getElementById('f').submit();
});
</script>
</body></html>
"#;

/// Serves `page` to every request on a free 127.0.0.1 port, from a thread; returns its URL.
fn serve_page(page: String) -> String {
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let url = format!("http://{}/", listener.local_addr().unwrap());
    std::thread::spawn(move || {
        for stream in listener.incoming() {
            let Ok(mut stream) = stream else { continue };
            let mut reader = BufReader::new(&stream);
            let mut line = String::new();
            // The request head, up to the blank line.
            while reader.read_line(&mut line).is_ok_and(|n| n > 2) {
                line.clear();
            }
            let _ = write!(
                stream,
                "HTTP/1.1 200 OK\r\nContent-Type: text/html; charset=utf-8\r\n\
                 Content-Length: {}\r\nConnection: close\r\n\r\n{page}",
                page.len()
            );
        }
    });
    url
}

/// The plan of document 0 and whether it has an edit to undo.
fn snapshot(server: &Server) -> (Value, u16) {
    let (status, plan) = server.get("/api/docs/0/plan?machine=grbl-diode&material=card-300gsm");
    assert_eq!(status, 200);
    let (undo, reply) = server.post_json("/api/docs/0/undo", b"");
    if undo == 200 {
        let (redo, _) = server.post_json("/api/docs/0/redo", b"");
        assert_eq!(redo, 200, "{reply}");
    }
    (serde_json::from_slice(&plan).unwrap(), undo)
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_page_on_another_origin_changes_and_reads_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let out = foldcam(&["generate", "miura", "-o", "miura.fold"], dir.path());
    assert!(out.status.success());
    let server = Server::start(&["miura.fold"], dir.path());
    let (status, opened) = server.post_json("/api/files/0", b"");
    assert_eq!(status, 200, "{opened}");
    assert_eq!(opened["id"], 0);
    let before = snapshot(&server);
    assert_eq!(before.1, 422, "a new document has nothing to undo");

    let studio_url = format!("http://{}", server.addr);
    let hostile = serve_page(PAGE.replace("STUDIO", &studio_url));
    let driver = start_driver();
    let c = browser(&driver).await;
    c.goto(&hostile).await.unwrap();
    wait_until(
        &c,
        "return document.body.dataset.fetched !== undefined",
        "the hostile page's requests",
    )
    .await;
    // Every no-cors request was sent (an opaque reply resolves), the CORS read failed.
    let fetched = c
        .execute("return document.body.dataset.fetched", vec![])
        .await
        .unwrap();
    assert_eq!(
        fetched.as_str(),
        Some("fulfilled,fulfilled,fulfilled,rejected")
    );
    let read = c
        .execute("return document.body.dataset.read ?? null", vec![])
        .await
        .unwrap();
    assert_eq!(read, Value::Null, "the page read the file list");
    // The form post navigates the frame; give it time to reach the studio.
    tokio::time::sleep(Duration::from_secs(3)).await;
    c.close().await.unwrap();

    let after = snapshot(&server);
    assert_eq!(after.1, 422, "the hostile page edited the pattern");
    assert!(after.0 == before.0, "the plan changed");
    let (_, next) = server.post_json("/api/files/0", b"");
    assert_eq!(next["id"], 1, "the hostile page opened a document");
}

/// The studio's own page under its content security policy: every view shown and a job
/// planned (the plan's totals once had an inline `style`) break none of it.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_studio_page_breaks_none_of_its_own_policy() {
    let dir = tempfile::tempdir().unwrap();
    let out = foldcam(&["generate", "miura", "-o", "miura.fold"], dir.path());
    assert!(out.status.success());
    let server = Server::start(&["miura.fold"], dir.path());
    let (_driver, c) = open_studio(&server.url()).await;
    c.execute(
        "window.cspViolations = [];
         document.addEventListener('securitypolicyviolation',
           (e) => window.cspViolations.push(`${e.violatedDirective} ${e.blockedURI} ${e.sample}`));",
        vec![],
    )
    .await
    .unwrap();
    for view in [
        "fold",
        "flat",
        "folding",
        "tessellate",
        "voxel",
        "popup",
        "craft",
        "pattern",
        "machine",
    ] {
        click(&c, &format!("#tabs button[data-view='{view}']")).await;
    }
    browser::choose_machine(&c, "grbl-diode", "card-300gsm").await;
    click(&c, "#plan-btn").await;
    wait_until(
        &c,
        "return document.body.dataset.planned === 'true' \
         && document.getElementById('plan-stats').textContent.includes('travel')",
        "the plan",
    )
    .await;
    // Let the views' late work (3D scenes, examples lists) finish.
    tokio::time::sleep(Duration::from_secs(2)).await;
    let violations = c
        .execute("return window.cspViolations", vec![])
        .await
        .unwrap();
    assert_eq!(
        violations,
        serde_json::json!([]),
        "the page broke its policy"
    );
}
