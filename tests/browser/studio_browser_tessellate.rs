//! The tessellation designer in a real browser (headless Chromium, see `common/browser.rs`):
//! the bundled dome solved with the stainless limits (Tachi 2014), the progress seen while it
//! runs, the folded form and the crease pattern shown; the design saved from the page and run
//! through `foldcam tessellate` gives the pattern the page draws, and "To crease pattern" opens
//! it as a document.
//!
//! `FOLDCAM_SCREENSHOTS=docs cargo test --test browser studio_browser_tessellate` keeps the README's
//! picture (`docs/studio-tessellate.png`).

use crate::bin;
use crate::browser;
use crate::lines;
use crate::studio;

use bin::foldcam;
use browser::{click, keep_screenshot, open_studio, text, wait_until};
use fantoccini::Client;
use lines::{Lines, fold_lines, line};
use serde_json::{Value, json};
use studio::Server;

/// Line ends of the page's crease pattern and the file's agree this closely, millimetres.
const TOLERANCE_MM: f64 = 1e-6;

/// The text a link of the page downloads (fetched by the page itself).
async fn fetch_link(c: &Client, css: &str) -> String {
    let text = c
        .execute_async(
            "const done = arguments[arguments.length - 1];
             const a = document.querySelector(arguments[0]);
             fetch(a.href).then(r => r.text()).then(done, e => done('ERROR ' + e));",
            vec![json!(css)],
        )
        .await
        .unwrap();
    text.as_str().unwrap().to_string()
}

/// The creases of the page's pattern drawing.
async fn page_lines(c: &Client) -> Lines {
    let drawn = c
        .execute(
            "return [...document.querySelectorAll('#tess-cp line')].map((l) => \
             [['x1', 'y1', 'x2', 'y2'].map((k) => +l.getAttribute(k)), \
              l.getAttribute('class').replace('edge edge-', '')])",
            vec![],
        )
        .await
        .unwrap();
    let drawn: Vec<([f64; 4], String)> = serde_json::from_value(drawn).unwrap();
    let mut out: Lines = drawn
        .into_iter()
        .map(|(ends, a)| line(ends, &a, TOLERANCE_MM))
        .collect();
    out.sort();
    out
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_solve_in_the_browser_saves_a_design_the_command_rebuilds() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let (_driver, c) = open_studio(&server.url()).await;
    // The mode opens on the first bundled example, the dome.
    click(&c, "#tabs button[data-view='tessellate']").await;
    wait_until(
        &c,
        "return document.body.dataset.tessStatus === 'ready' && !document.body.dataset.busy",
        "the example mesh",
    )
    .await;
    let info = text(&c, "#tess-mesh-info").await;
    assert!(info.starts_with("dome.obj"), "{info}");
    // No time is promised before one is measured (the face-count guess said "under a second"
    // for solves of minutes).
    assert!(
        !info.contains("about") && !info.contains("second"),
        "{info}"
    );
    // The mesh's edges are drawn on the paper: the first edge starts at its face's first
    // corner as the paper places it (both centred by the same offset).
    let offset = c
        .execute(
            "const v = tessellationView; const [paper, , lines] = v.shell.model.children; \
             const i = v.mesh.faces[0][0]; \
             const p = paper.geometry.getAttribute('position'); \
             const l = lines.geometry.getAttribute('position'); \
             return [Math.hypot(p.getX(i) - l.getX(0), p.getY(i) - l.getY(0), p.getZ(i) - l.getZ(0)), \
               v.shell.radius];",
            vec![],
        )
        .await
        .unwrap();
    let (gap, radius) = (offset[0].as_f64().unwrap(), offset[1].as_f64().unwrap());
    assert!(
        gap < 1e-5 * radius,
        "the mesh's lines are drawn {gap} off the paper"
    );
    // The stainless sheet's limits, chosen by material: the angle fields follow.
    c.execute(
        "const s = document.getElementById('tess-material'); s.value = 'stainless-0.5'; \
         s.dispatchEvent(new Event('change'));",
        vec![],
    )
    .await
    .unwrap();
    let max_fold = c
        .execute(
            "return +document.getElementById('tess-max-fold').value",
            vec![],
        )
        .await
        .unwrap();
    assert!(max_fold.as_f64().unwrap() > 0.0);

    click(&c, "#tess-solve").await;
    wait_until(
        &c,
        "return document.body.dataset.tessStatus !== 'running' && !document.body.dataset.busy",
        "the solve to end",
    )
    .await;
    let status = c
        .execute("return document.body.dataset.tessStatus", vec![])
        .await
        .unwrap();
    assert_eq!(status, "done", "{}", text(&c, "#tess-report").await);
    // The progress the page received: iterations, the last one in words, the residual plot.
    let iterations: usize = c
        .execute("return document.body.dataset.tessIterations", vec![])
        .await
        .unwrap()
        .as_str()
        .unwrap()
        .parse()
        .unwrap();
    assert!(iterations > 0);
    // Every progress line the page showed says a time only once two iterations of its solve
    // were timed.
    let lines = c
        .execute(
            "return tessellationView.events.filter((e) => e.kind === 'iteration') \
               .map((e) => [e.index, e.progress, e.seconds_left])",
            vec![],
        )
        .await
        .unwrap();
    for line in lines.as_array().unwrap() {
        let (index, text) = (line[0].as_u64().unwrap(), line[1].as_str().unwrap());
        assert_eq!(index >= 2, text.contains(" left in this solve"), "{line}");
        assert_eq!(index >= 2, !line[2].is_null(), "{line}");
    }
    // The command's progress line: the iteration out of the cap, the solve of the schedule,
    // the time left (none once converged).
    let progress = text(&c, "#tess-progress").await;
    assert!(progress.starts_with("iteration "), "{progress}");
    assert!(progress.contains("(solve "), "{progress}");
    assert!(
        progress.contains("about 0 s left in this solve"),
        "{progress}"
    );
    assert_eq!(
        c.find_all(fantoccini::Locator::Css("#tess-plot polyline"))
            .await
            .unwrap()
            .len(),
        1
    );
    assert!(
        text(&c, "#tess-violations")
            .await
            .starts_with("every crease")
    );
    keep_screenshot(&c, "studio-tessellate.png").await;

    // The design and its mesh saved from the page, rebuilt by the command line.
    let design = fetch_link(&c, "#tess-design").await;
    let mesh = fetch_link(&c, "#tess-mesh").await;
    assert!(design.contains("mesh = \"dome.obj\""), "{design}");
    std::fs::write(dir.path().join("dome.tess.toml"), &design).unwrap();
    std::fs::write(dir.path().join("dome.obj"), &mesh).unwrap();
    let out = foldcam(
        &["tessellate", "dome.tess.toml", "-o", "cli.fold"],
        dir.path(),
    );
    assert!(
        out.status.success(),
        "{}\n{design}",
        String::from_utf8_lossy(&out.stderr)
    );
    let cli: Value =
        serde_json::from_slice(&std::fs::read(dir.path().join("cli.fold")).unwrap()).unwrap();
    let (drawn, written) = (page_lines(&c).await, fold_lines(&cli, TOLERANCE_MM));
    assert!(!written.is_empty());
    assert_eq!(drawn, written, "the page's crease pattern is the command's");

    // Another mesh starts clean: nothing of the dome's solve stays on the page.
    click(&c, "#tabs button[data-view='tessellate']").await;
    click(&c, "#tess-load").await;
    wait_until(
        &c,
        "return document.body.dataset.tessStatus === 'ready' && !document.body.dataset.busy",
        "the mesh loaded again",
    )
    .await;
    let left = c
        .execute(
            "return [document.getElementById('tess-progress').textContent, \
               document.getElementById('tess-notes').children.length, \
               document.getElementById('tess-plot').children.length, \
               document.body.dataset.tessIterations ?? null]",
            vec![],
        )
        .await
        .unwrap();
    assert_eq!(
        left,
        json!(["", 0, 0, null]),
        "the previous solve's progress stays"
    );
    click(&c, "#tess-solve").await;
    wait_until(
        &c,
        "return document.body.dataset.tessStatus === 'done'",
        "the solve again",
    )
    .await;

    // To crease pattern: the document the pattern view checks, plans and cuts.
    click(&c, "#tess-pattern").await;
    wait_until(
        &c,
        "return document.body.dataset.doc !== undefined && !document.body.dataset.busy \
         && !document.getElementById('view-pattern').hidden",
        "the crease pattern document",
    )
    .await;
    let count = |a: &str| written.iter().filter(|(_, x)| x == a).count();
    assert_eq!(text(&c, "#count-edges").await, written.len().to_string());
    assert_eq!(text(&c, "#count-M").await, count("M").to_string());
    assert_eq!(text(&c, "#count-V").await, count("V").to_string());
    c.close().await.unwrap();
}
