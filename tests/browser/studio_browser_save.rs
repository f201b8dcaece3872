//! Starting and saving in a real browser (headless Chromium, see `common/browser.rs`): the
//! opening screen of a studio started without a file lists the bundled examples and opens
//! one; a crease drawn on a blank sheet with real pointer clicks is saved with Ctrl+S and the
//! Save menu as FOLD, SVG and `.cp`, each file downloaded by the browser and read back by
//! `foldcam check --json`; the paper-craft job downloaded from the studio is byte for byte
//! the one `foldcam papercraft --job` writes (edge numbers marked).
//!
//! The README's picture: `FOLDCAM_SCREENSHOTS=docs cargo test --test browser studio_browser_save`.

use crate::bin;
use crate::browser;
use crate::studio;

use bin::{check_summary, vase_job_from_cli};
use browser::{
    click, downloaded, keep_screenshot, open_studio_downloading, pointer_click, press, press_ctrl,
    screen_in, text, wait_until,
};
use fantoccini::{Client, Locator};
use serde_json::Value;
use studio::Server;

/// Viewport position (CSS pixels) of pattern point `(x, y)` (millimetres, y up) in the
/// pattern view: the one place that knows how the view is drawn.
async fn pattern_point(c: &Client, x: f64, y: f64) -> (f64, f64) {
    screen_in(c, "cp-svg", x, y).await
}

/// Waits until a new document is shown and the page is idle.
async fn document_shown(c: &Client, what: &str) {
    wait_until(
        c,
        "return document.body.dataset.doc !== undefined && !document.body.dataset.busy \
         && document.getElementById('start').hidden",
        what,
    )
    .await;
}

async fn start_visible(c: &Client) -> bool {
    c.execute("return !document.getElementById('start').hidden", vec![])
        .await
        .unwrap()
        == Value::Bool(true)
}

/// Chooses `format` in the Save menu.
async fn save_as(c: &Client, format: &str) {
    click(c, "#save-btn").await;
    click(c, &format!("#save-menu button[data-format='{format}']")).await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_opening_screen_opens_an_example_and_saves_its_folded_form() {
    let dir = tempfile::tempdir().unwrap();
    let downloads = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let (_driver, c) = open_studio_downloading(&server.url(), downloads.path()).await;

    // Started without a file: the opening screen, the examples by group and a blank sheet.
    assert!(start_visible(&c).await, "the opening screen is shown");
    let groups = c
        .execute(
            "return [...document.querySelectorAll('#start-examples h3')].map((h) => h.textContent)",
            vec![],
        )
        .await
        .unwrap();
    for g in [
        "Simple folds",
        "Origami bases",
        "Tessellations",
        "Paper craft",
    ] {
        assert!(
            groups.as_array().unwrap().iter().any(|x| x == g),
            "{g} in {groups}"
        );
    }
    for e in ["miura-ori", "vase", "blank"] {
        c.find(Locator::Css(&format!("#start button[data-example='{e}']")))
            .await
            .unwrap_or_else(|_| panic!("{e} is offered"));
    }
    keep_screenshot(&c, "studio-start.png").await;

    // Esc closes it, New… brings it back.
    press(&c, fantoccini::key::Key::Escape.into()).await;
    assert!(!start_visible(&c).await, "Esc closes the opening screen");
    click(&c, "#new-btn").await;
    assert!(start_visible(&c).await, "New… shows it again");

    click(&c, "#start-examples button[data-example='miura-ori']").await;
    document_shown(&c, "the Miura-ori").await;
    assert_eq!(text(&c, "#doc-name").await, "miura-ori.fold");
    let edges: u64 = text(&c, "#count-edges").await.parse().unwrap();

    // Save ▸ Folded form: a FOLD file whose key frame is the folded form, which foldcam
    // reads back (unfolded) with the pattern's edges.
    save_as(&c, "folded").await;
    let bytes = downloaded(downloads.path(), "miura-ori-folded.fold").await;
    let fold: Value = serde_json::from_slice(&bytes).unwrap();
    assert_eq!(fold["frame_classes"], serde_json::json!(["foldedForm"]));
    let coords = fold["vertices_coords"].as_array().unwrap();
    assert!(coords.iter().any(|p| p[2].as_f64().unwrap().abs() > 1.0));
    let summary = check_summary(downloads.path(), "miura-ori-folded.fold");
    assert_eq!(summary["edges"].as_u64(), Some(edges), "{summary}");
    c.close().await.unwrap();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_crease_drawn_on_a_blank_sheet_is_saved_and_read_back_by_the_cli() {
    let dir = tempfile::tempdir().unwrap();
    let downloads = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let (_driver, c) = open_studio_downloading(&server.url(), downloads.path()).await;
    click(&c, "#start-blank").await;
    document_shown(&c, "the blank sheet").await;
    assert_eq!(text(&c, "#count-edges").await, "4");

    // Draw a mountain crease corner to corner with two real pointer clicks.
    click(&c, "#edit-tools button[data-tool='draw']").await;
    let from = pattern_point(&c, 0.0, 0.0).await;
    let to = pattern_point(&c, 150.0, 150.0).await;
    pointer_click(&c, from).await;
    wait_until(
        &c,
        "return window.patternEditor.start !== null",
        "the crease's first end",
    )
    .await;
    pointer_click(&c, to).await;
    wait_until(
        &c,
        "return document.body.dataset.edits === '1' && !document.body.dataset.busy",
        "the crease",
    )
    .await;
    assert_eq!(text(&c, "#count-M").await, "1");

    // Ctrl+S saves as FOLD at first; then the menu's SVG and .cp.
    press_ctrl(&c, 's').await;
    downloaded(downloads.path(), "blank.fold").await;
    save_as(&c, "svg").await;
    downloaded(downloads.path(), "blank.svg").await;
    save_as(&c, "cp").await;
    downloaded(downloads.path(), "blank.cp").await;
    for file in ["blank.fold", "blank.svg", "blank.cp"] {
        let summary = check_summary(downloads.path(), file);
        assert_eq!(summary["edges"], 5, "{file}: {summary}");
        assert_eq!(summary["assignments"]["mountain"], 1, "{file}: {summary}");
        assert_eq!(summary["assignments"]["boundary"], 4, "{file}: {summary}");
    }
    // Ctrl+S now saves in the format used last (.cp): the browser names the second copy.
    press_ctrl(&c, 's').await;
    let again = downloaded(downloads.path(), "blank (1).cp").await;
    assert_eq!(
        again,
        std::fs::read(downloads.path().join("blank.cp")).unwrap()
    );
    c.close().await.unwrap();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_paper_craft_job_downloaded_from_the_studio_is_the_clis() {
    let dir = tempfile::tempdir().unwrap();
    let downloads = tempfile::tempdir().unwrap();
    let cli = vase_job_from_cli(dir.path(), "grbl-diode", "paper-160gsm");

    let server = Server::start(&[], dir.path());
    let (_driver, c) = open_studio_downloading(&server.url(), downloads.path()).await;
    click(&c, "#start-examples button[data-example='vase']").await;
    document_shown(&c, "the vase's sheet").await;
    click(&c, "#tabs button[data-view='machine']").await;
    browser::choose_machine(&c, "grbl-diode", "paper-160gsm").await;
    click(&c, "#plan-btn").await;
    wait_until(
        &c,
        "return document.body.dataset.planned === 'true' && !document.body.dataset.busy",
        "the plan",
    )
    .await;
    click(&c, "#dl-gcode").await;
    // Named as every job is: pattern, machine, material, extension.
    let served = downloaded(downloads.path(), "vase.grbl-diode.paper-160gsm.gcode").await;
    assert!(
        served == cli,
        "the studio's job ({} bytes) differs from `foldcam papercraft --job`'s ({} bytes)",
        served.len(),
        cli.len()
    );
    c.close().await.unwrap();
}
