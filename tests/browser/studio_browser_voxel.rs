//! The voxel pop-up editor in a real browser (headless Chromium, see `common/browser.rs`): the
//! bundled house opened in the editor, a voxel added by clicking the front view and one by
//! clicking the side view (Mitani, Suzuki & Uno 2003, §2.7), the card turned on the opening
//! slider; the design saved from the page and run through `foldcam popup voxel` gives the
//! pattern that "To crease pattern" opens.
//!
//! `FOLDCAM_SCREENSHOTS=docs cargo test --test browser studio_browser_voxel` keeps the README's
//! picture (`docs/studio-voxel.png`).

use crate::bin;
use crate::browser;
use crate::studio;

use bin::{foldcam, repo_file};
use browser::{card_sides, click, keep_screenshot, open_studio, text, wait_until};
use fantoccini::{Client, Locator};
use serde_json::Value;
use studio::Server;

/// Depths of a `.voxel.txt`'s front elevation, `[x][z]` for `nz` rows (rows above the listed
/// ones are empty).
fn depths(text: &str, nz: usize) -> Vec<Vec<usize>> {
    let rows: Vec<Vec<usize>> = text
        .lines()
        .map(|l| l.split('#').next().unwrap().trim())
        .skip_while(|l| *l != "rows")
        .skip(1)
        .filter(|l| !l.is_empty())
        .map(|l| {
            l.split_whitespace()
                .map(|t| t.trim_end_matches(['w', 't']).parse().unwrap())
                .collect()
        })
        .collect();
    (0..rows[0].len())
        .map(|x| {
            let mut col: Vec<usize> = rows.iter().rev().map(|r| r[x]).collect();
            col.resize(nz, 0);
            col
        })
        .collect()
}

/// Counts of a FOLD file: vertices, edges, mountains, valleys.
fn fold_counts(path: &std::path::Path) -> [usize; 4] {
    let v: Value = serde_json::from_slice(&std::fs::read(path).unwrap()).unwrap();
    let letters: Vec<&str> = v["edges_assignment"]
        .as_array()
        .unwrap()
        .iter()
        .map(|a| a.as_str().unwrap())
        .collect();
    let count = |l: &str| letters.iter().filter(|a| **a == l).count();
    [
        v["vertices_coords"].as_array().unwrap().len(),
        letters.len(),
        count("M"),
        count("V"),
    ]
}

async fn edits_shown(c: &Client, n: usize) {
    wait_until(
        c,
        &format!(
            "return document.body.dataset.voxelEdits === '{n}' && !document.body.dataset.busy"
        ),
        "the edit",
    )
    .await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn clicking_voxels_in_saves_a_card_the_command_creases_as_the_page_does() {
    let dir = tempfile::tempdir().unwrap();
    let house = repo_file("examples/popup/house.voxel.txt");
    let server = Server::start(&[], dir.path());
    let (_driver, c) = open_studio(&server.url()).await;
    click(&c, "#tabs button[data-view='voxel']").await;
    edits_shown(&c, 1).await;

    // The house, opened in the editor.
    let input = c.find(Locator::Css("#voxel-file")).await.unwrap();
    input.send_keys(&house).await.unwrap();
    edits_shown(&c, 2).await;
    assert_eq!(text(&c, "#voxel-status").await, "pops up");
    let file = std::fs::read_to_string(&house).unwrap();
    let mut expected = depths(&file, 12);

    // §2.7, written out here: adding cell (x, y, z) fills y' ≤ y, z' ≤ z of its slice.
    let mut add = |x: usize, y: usize, z: usize| {
        for d in &mut expected[x][..=z] {
            *d = (*d).max(y + 1);
        }
    };
    // Front view: the empty row (6, 7) above the roof pushed out one cell (a chimney).
    click(&c, "#voxel-front rect.cell[data-x='6'][data-z='7']").await;
    edits_shown(&c, 3).await;
    add(6, 0, 7);
    // Side view of column 6 (chosen by that click): cell (6, 1, 7) added.
    assert_eq!(text(&c, "#voxel-side-label").await, "Side view of column 6");
    click(&c, "#voxel-side rect.cell[data-y='1'][data-z='7']").await;
    edits_shown(&c, 4).await;
    add(6, 1, 7);
    assert_eq!(
        text(&c, "#voxel-info").await,
        "2 voxel(s) added, 0 removed."
    );
    let filled = c
        .find_all(Locator::Css("#voxel-side rect.cell.filled"))
        .await
        .unwrap()
        .len();
    assert_eq!(filled, expected[6].iter().sum::<usize>());

    // The opening slider: 30 steps down from 90° with the keyboard, the 3D view follows.
    let canvas = c.find(Locator::Css("#voxel-3d canvas")).await.unwrap();
    let standing = canvas.screenshot().await.unwrap();
    let slider = c.find(Locator::Css("#voxel-angle")).await.unwrap();
    for _ in 0..30 {
        slider.send_keys("\u{E012}").await.unwrap();
    }
    wait_until(
        &c,
        "return document.body.dataset.voxelAngle === '60' && !document.body.dataset.busy",
        "the card at 60°",
    )
    .await;
    let opened = canvas.screenshot().await.unwrap();
    assert_ne!(standing, opened, "the 3D view did not change");
    keep_screenshot(&c, "studio-voxel.png").await;
    // Seen from the front, as the reader holds it: the card's left edge on the left (the
    // papers' axes, drawn as they are, show it mirrored).
    let (left, right, front) = card_sides(&c, "voxel-3d").await;
    assert!(front, "the camera is behind the card's back sheet");
    assert!(
        left < right,
        "the card's left edge is drawn at screen x {left:.2}, right of its right edge at {right:.2}"
    );

    // The saved design holds the clicked voxels, and the command creases it.
    let saved = c
        .execute_async(
            "const done = arguments[arguments.length - 1];
             fetch(document.getElementById('voxel-save').href).then(r => r.text())
               .then(done, e => done('ERROR ' + e));",
            vec![],
        )
        .await
        .unwrap();
    let saved = saved.as_str().unwrap().to_string();
    assert_eq!(depths(&saved, 12), expected);
    std::fs::write(dir.path().join("saved.voxel.txt"), &saved).unwrap();
    let out = foldcam(
        &["popup", "voxel", "saved.voxel.txt", "-o", "cli.fold"],
        dir.path(),
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let [vertices, edges, m, v] = fold_counts(&dir.path().join("cli.fold"));

    // The chimney's top left out (§3.3): its front face keeps the base only and the card no
    // longer pops up. The page lists and marks the faces the command names when it refuses.
    click(&c, "#voxel-tools button[data-voxel-tool='top']").await;
    click(&c, "#voxel-front rect.cell[data-x='6'][data-z='7']").await;
    edits_shown(&c, 5).await;
    assert_eq!(text(&c, "#voxel-status").await, "cannot be made");
    let saved = c
        .execute_async(
            "const done = arguments[arguments.length - 1];
             fetch(document.getElementById('voxel-save').href).then(r => r.text())
               .then(done, e => done('ERROR ' + e));",
            vec![],
        )
        .await
        .unwrap();
    std::fs::write(dir.path().join("bad.voxel.txt"), saved.as_str().unwrap()).unwrap();
    let out = foldcam(
        &["popup", "voxel", "bad.voxel.txt", "-o", "bad.fold"],
        dir.path(),
    );
    assert_eq!(out.status.code(), Some(1));
    let report = String::from_utf8_lossy(&out.stdout).to_string();
    let named: Vec<&str> = report
        .lines()
        .filter_map(|l| l.trim().strip_prefix("front face of cell "))
        .collect();
    assert!(!named.is_empty(), "{report}");
    let listed = c
        .find_all(Locator::Css("#voxel-faults li.fault-popup"))
        .await
        .unwrap();
    assert_eq!(listed.len(), named.len());
    for (li, line) in listed.iter().zip(&named) {
        assert!(li.text().await.unwrap().ends_with(line), "{line}");
    }
    // Marked where the command says: (x, z) of each named cell "(x, y, z) …".
    let mut want: Vec<(u64, u64)> = named
        .iter()
        .map(|l| {
            let inside = &l[1..l.find(')').unwrap()];
            let n: Vec<u64> = inside.split(", ").map(|t| t.parse().unwrap()).collect();
            (n[0], n[2])
        })
        .collect();
    let marks = c
        .execute(
            "return [...document.querySelectorAll('#voxel-front rect.mark-popup')]
               .map((r) => [+r.dataset.x, +r.dataset.z])",
            vec![],
        )
        .await
        .unwrap();
    let mut marked: Vec<(u64, u64)> = serde_json::from_value(marks).unwrap();
    want.sort_unstable();
    marked.sort_unstable();
    assert_eq!(marked, want);
    keep_screenshot(&c, "studio-voxel-fault.png").await;
    click(&c, "#voxel-undo").await;
    edits_shown(&c, 6).await;
    assert_eq!(text(&c, "#voxel-status").await, "pops up");

    // To a crease pattern document: the command's counts; the check passes.
    click(&c, "#voxel-pattern").await;
    wait_until(
        &c,
        "return document.body.dataset.doc !== undefined && !document.body.dataset.busy \
         && !document.getElementById('view-pattern').hidden",
        "the crease pattern document",
    )
    .await;
    assert_eq!(text(&c, "#count-vertices").await, vertices.to_string());
    assert_eq!(text(&c, "#count-edges").await, edges.to_string());
    assert_eq!(text(&c, "#count-M").await, m.to_string());
    assert_eq!(text(&c, "#count-V").await, v.to_string());
    assert!(text(&c, "#made").await.contains("voxel pop-up card"));
    c.close().await.unwrap();
}
