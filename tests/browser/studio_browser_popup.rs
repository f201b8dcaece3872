//! The polygon pop-up editor (Mitani & Suzuki 2004) in headless Chromium: a wall and its roof
//! added with the mouse on the card's side section, the live check naming the wall until the
//! roof holds it, the wall moved with the mouse off its roof and named again, undo and redo, the saved design run through `foldcam popup poly` and its
//! crease pattern compared line for line with the one the page draws, and the pattern opened
//! as a studio document. Keeps `docs/studio-popup.png` with `FOLDCAM_SCREENSHOTS=docs`.

use crate::bin;
use crate::browser;
use crate::lines;
use crate::studio;

use bin::foldcam;
use browser::{
    card_sides, click, download_text, keep_screenshot, open_studio, pointer_drag, screen_in, text,
    wait_until,
};
use fantoccini::{Client, Locator};
use lines::{Lines, fold_lines, line};
use serde_json::Value;
use studio::Server;

/// Coordinates agree this closely, millimetres.
const COORD_TOLERANCE: f64 = 1e-6;

/// The lines the page draws in its crease-pattern view.
async fn drawn_lines(c: &Client) -> Lines {
    let drawn = c
        .execute(
            "return [...document.querySelectorAll('#popup-cp line.edge')].map((l) => \
             [['x1', 'y1', 'x2', 'y2'].map((k) => +l.getAttribute(k)), \
              [...l.classList].find((k) => k.startsWith('edge-')).slice(5)])",
            vec![],
        )
        .await
        .unwrap();
    let drawn: Vec<([f64; 4], String)> = serde_json::from_value(drawn).unwrap();
    let mut out: Lines = drawn
        .iter()
        .map(|(e, a)| line(*e, a, COORD_TOLERANCE))
        .collect();
    out.sort();
    out
}

async fn operations_shown(c: &Client, n: usize, valid: bool) {
    wait_until(
        c,
        &format!(
            "return document.body.dataset.popupOperations === '{n}' \
             && document.body.dataset.popupValid === '{valid}' && !document.body.dataset.busy"
        ),
        &format!("{n} operations, valid {valid}"),
    )
    .await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_wall_and_its_roof_drawn_with_the_mouse_save_as_the_cli_builds_them() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let (_driver, c) = open_studio(&server.url()).await;
    // The tab starts on a blank 120 × 60 × 80 mm card; new faces span x 40..80 mm.
    click(&c, "#tabs button[data-view='popup']").await;
    operations_shown(&c, 0, true).await;

    // A wall: drag up the side section at y = 30 mm from the base to z = 20 mm.
    click(&c, "#popup-tools button[data-popup-tool='vertical']").await;
    let from = screen_in(&c, "popup-side", 30.0, 0.0).await;
    let to = screen_in(&c, "popup-side", 30.0, 20.0).await;
    pointer_drag(&c, from, to).await;
    operations_shown(&c, 1, false).await;
    // Said at the place: the wall is drawn red and named in words.
    let failing = c
        .find_all(Locator::Css("#popup-side line.popup-op.failing"))
        .await
        .unwrap();
    assert_eq!(failing.len(), 1);
    assert_eq!(
        failing[0].attr("data-operation").await.unwrap().as_deref(),
        Some("1")
    );
    let words = text(&c, "#popup-findings li").await;
    assert!(words.contains("operation 1 (y = 30 mm)"), "{words}");
    assert!(words.contains("back sheet"), "{words}");
    assert_eq!(text(&c, "#popup-status").await, "does not pop up");

    // Its roof: drag across at z = 20 mm from the back sheet to the wall.
    click(&c, "#popup-tools button[data-popup-tool='horizontal']").await;
    let from = screen_in(&c, "popup-side", 0.0, 20.0).await;
    let to = screen_in(&c, "popup-side", 30.0, 20.0).await;
    pointer_drag(&c, from, to).await;
    operations_shown(&c, 2, true).await;
    assert_eq!(text(&c, "#popup-status").await, "pops up");
    assert!(
        c.find_all(Locator::Css("#popup-side line.failing"))
            .await
            .unwrap()
            .is_empty()
    );
    // The card half open, for the picture.
    c.execute(
        "const s = document.getElementById('popup-angle'); s.value = 60; \
         s.dispatchEvent(new Event('input'));",
        vec![],
    )
    .await
    .unwrap();
    wait_until(
        &c,
        "return document.body.dataset.popupAngle === '60'",
        "the card at 60°",
    )
    .await;
    keep_screenshot(&c, "studio-popup.png").await;
    // Seen from the front, as the reader holds it: the card's left edge on the left (the
    // papers' axes, drawn as they are, show it mirrored).
    let (left, right, front) = card_sides(&c, "popup-3d").await;
    assert!(front, "the camera is behind the card's back sheet");
    assert!(
        left < right,
        "the card's left edge is drawn at screen x {left:.2}, right of its right edge at {right:.2}"
    );

    // Saved and built by the CLI: the pattern the page draws, line for line.
    let saved = download_text(&c, "#popup-save").await;
    std::fs::write(dir.path().join("box.popup.toml"), &saved).unwrap();
    let out = foldcam(
        &["popup", "poly", "box.popup.toml", "-o", "box.fold"],
        dir.path(),
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let cli: Value =
        serde_json::from_slice(&std::fs::read(dir.path().join("box.fold")).unwrap()).unwrap();
    let cli_lines = fold_lines(&cli, COORD_TOLERANCE);
    assert_eq!(drawn_lines(&c).await, cli_lines);
    // The box's folds where eq. 1 (v = z − y) puts them by hand, x from 40 to 80 mm.
    for v in [20.0, -10.0, -30.0] {
        let fold = line([40.0, v, 80.0, v], "", COORD_TOLERANCE);
        assert!(
            cli_lines
                .iter()
                .any(|(e, a)| *e == fold.0 && (a == "M" || a == "V")),
            "no fold at v = {v}"
        );
    }

    // Select the wall and drag it 10 mm forward: the roof no longer reaches it, and the
    // page says so at the wall. Undo puts it back.
    click(&c, "#popup-tools button[data-popup-tool='select']").await;
    let from = screen_in(&c, "popup-side", 30.0, 10.0).await;
    let to = screen_in(&c, "popup-side", 40.0, 10.0).await;
    pointer_drag(&c, from, to).await;
    operations_shown(&c, 2, false).await;
    let failing = c
        .find_all(Locator::Css("#popup-side line.popup-op.failing"))
        .await
        .unwrap();
    assert_eq!(failing.len(), 1);
    assert_eq!(failing[0].attr("x1").await.unwrap().as_deref(), Some("40"));
    assert!(text(&c, "#popup-findings li").await.contains("(y = 40 mm)"));
    click(&c, "#popup-undo").await;
    operations_shown(&c, 2, true).await;

    // Undo takes the roof away again, redo brings it back.
    click(&c, "#popup-undo").await;
    operations_shown(&c, 1, false).await;
    click(&c, "#popup-redo").await;
    operations_shown(&c, 2, true).await;

    // To a crease pattern document: the CLI's counts, checked as any pattern.
    click(&c, "#popup-pattern").await;
    wait_until(
        &c,
        "return document.body.dataset.doc !== undefined && !document.body.dataset.busy \
         && !document.getElementById('view-pattern').hidden",
        "the crease pattern document",
    )
    .await;
    assert_eq!(
        text(&c, "#count-edges").await,
        cli["edges_vertices"].as_array().unwrap().len().to_string()
    );
    c.close().await.unwrap();
}
