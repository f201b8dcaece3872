//! The studio in a real browser: headless Chromium (Debian's `chromium` and
//! `chromium-driver`, installed by `.ci/run`) driven over WebDriver. A machine without them
//! fails this test: it does not pass quietly.
//!
//! Set `FOLDCAM_SCREENSHOTS=DIR` to keep the screenshots of each view (the README's pictures
//! come from `FOLDCAM_SCREENSHOTS=docs cargo test --test browser studio_browser::`).

use crate::bin;
use crate::browser;
use crate::studio;

use std::path::{Path, PathBuf};
use std::time::Duration;

use bin::{foldcam, repo_file};
use browser::{
    click, download_text, keep_screenshot, open_studio, pattern_ink, pointer_drag, pointer_move,
    screen_in, text, wait_until,
};
use fantoccini::actions::{InputSource, MouseActions, PointerAction};
use fantoccini::{Client, Locator};
use serde_json::{Value, json};
use studio::Server;

/// A fold frame counts as changed where a pixel's channels differ by more than this.
const PIXEL_TOLERANCE: u8 = 24;

/// Chooses `file` in the page's file picker and waits for the document to be shown.
pub(crate) async fn open(c: &Client, file: &Path) {
    let before = c
        .execute("return document.body.dataset.doc ?? null", vec![])
        .await
        .unwrap();
    let input = c.find(Locator::Css("#file-input")).await.unwrap();
    input.send_keys(&file.to_string_lossy()).await.unwrap();
    let script = format!(
        "return document.body.dataset.doc !== undefined && document.body.dataset.doc !== {} \
         && !document.body.dataset.busy",
        serde_json::to_string(&before.as_str().unwrap_or("none")).unwrap()
    );
    wait_until(c, &script, "the pattern to open").await;
}

/// Pixels that differ between two screenshots of the same size, as a fraction.
fn changed_fraction(a: &[u8], b: &[u8]) -> f64 {
    let a = image::load_from_memory(a).unwrap().to_rgb8();
    let b = image::load_from_memory(b).unwrap().to_rgb8();
    assert_eq!(a.dimensions(), b.dimensions());
    let changed = a
        .pixels()
        .zip(b.pixels())
        .filter(|(p, q)| {
            p.0.iter()
                .zip(q.0)
                .any(|(x, y)| x.abs_diff(y) > PIXEL_TOLERANCE)
        })
        .count();
    changed as f64 / (a.width() * a.height()) as f64
}

/// Expected counts read from the FOLD file itself.
fn fold_counts(path: &Path) -> (usize, usize, usize, usize) {
    let v: Value = serde_json::from_slice(&std::fs::read(path).unwrap()).unwrap();
    let letters: Vec<&str> = v["edges_assignment"]
        .as_array()
        .unwrap()
        .iter()
        .map(|a| a.as_str().unwrap())
        .collect();
    let count = |l: &str| letters.iter().filter(|a| a.eq_ignore_ascii_case(l)).count();
    (
        v["vertices_coords"].as_array().unwrap().len(),
        letters.len(),
        count("M"),
        count("V"),
    )
}

/// The pattern view canvas's data attribute `key` (camel case: `linesM` is `data-lines-m`),
/// a count of lines drawn.
pub(crate) async fn canvas_count(c: &Client, key: &str) -> usize {
    let n = c
        .execute(
            "return document.getElementById('cp-canvas').dataset[arguments[0]] ?? null",
            vec![json!(key)],
        )
        .await
        .unwrap();
    n.as_str()
        .unwrap_or_else(|| panic!("no data attribute {key}"))
        .parse()
        .unwrap()
}

/// The index of the first edge of a FOLD file with assignment `letter`.
fn first_edge(file: &Value, letter: &str) -> usize {
    file["edges_assignment"]
        .as_array()
        .unwrap()
        .iter()
        .position(|a| a.as_str().unwrap().eq_ignore_ascii_case(letter))
        .unwrap_or_else(|| panic!("no {letter} edge"))
}

/// The viewport position (CSS pixels) of the middle of edge `index` of a FOLD file, in the
/// crease-pattern view.
async fn edge_middle_on_screen(c: &Client, file: &Value, index: usize) -> (f64, f64) {
    let ends = &file["edges_vertices"][index];
    let p = |k: usize| {
        let q = &file["vertices_coords"][ends[k].as_u64().unwrap() as usize];
        (q[0].as_f64().unwrap(), q[1].as_f64().unwrap())
    };
    let (a, b) = (p(0), p(1));
    screen_of(c, (a.0 + b.0) / 2.0, (a.1 + b.1) / 2.0).await
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_studio_works_in_a_real_browser() {
    let dir = tempfile::tempdir().unwrap();
    let out = foldcam(&["generate", "miura", "-o", "miura.fold"], dir.path());
    assert!(out.status.success());
    let miura = dir.path().join("miura.fold");
    let server = Server::start(&[], dir.path());
    let (_driver, c) = open_studio(&server.url()).await;

    // 1. Upload a pattern: the page shows the counts the file holds.
    open(&c, &miura).await;
    let (vertices, edges, m, v) = fold_counts(&miura);
    assert_eq!(text(&c, "#count-vertices").await, vertices.to_string());
    assert_eq!(text(&c, "#count-edges").await, edges.to_string());
    assert_eq!(text(&c, "#count-M").await, m.to_string());
    assert_eq!(text(&c, "#count-V").await, v.to_string());
    // The default Miura-ori folds to 170°: its 7 × 7 interior vertices are 3D targets, which
    // Kawasaki and Maekawa do not judge, and the page says so (as `check` does).
    assert_eq!(
        text(&c, "#check-status").await,
        "passed, but not checked at 49 vertices: 3D targets (a crease folds to less than 180°)"
    );
    // Every edge is drawn, the mountains in their own path (the canvas counts what it drew).
    assert_eq!(canvas_count(&c, "lines").await, edges);
    assert_eq!(canvas_count(&c, "linesM").await, m);
    assert_eq!(canvas_count(&c, "linesV").await, v);
    // Hover over one mountain: the page names it with the length the file gives.
    let file: Value = serde_json::from_slice(&std::fs::read(&miura).unwrap()).unwrap();
    let index = first_edge(&file, "M");
    // A real pointer move onto the line's middle (WebDriver actions).
    pointer_move(&c, edge_middle_on_screen(&c, &file, index).await).await;
    let ends = &file["edges_vertices"][index];
    let p = |k: usize| {
        let q = &file["vertices_coords"][ends[k].as_u64().unwrap() as usize];
        (q[0].as_f64().unwrap(), q[1].as_f64().unwrap())
    };
    let length = ((p(0).0 - p(1).0).powi(2) + (p(0).1 - p(1).1).powi(2)).sqrt();
    let info = text(&c, "#hover-info").await;
    assert!(
        info.starts_with(&format!("edge {index}: mountain (M)"))
            && info.contains(&format!("length {length:.2} mm")),
        "{info}"
    );
    // The layer order, as `foldcam check --layers` prints it.
    click(&c, "#layers-btn").await;
    let layer_line =
        "return document.getElementById('layers-result').textContent.startsWith('layer order')";
    wait_until(&c, layer_line, "the layer order").await;
    let cli = foldcam(&["check", "miura.fold", "--layers"], dir.path());
    let cli = String::from_utf8_lossy(&cli.stdout);
    let expected = cli
        .lines()
        .find(|l| l.starts_with("layer order"))
        .expect("a layer line");
    assert_eq!(text(&c, "#layers-result").await, expected);
    // The Kawasaki tolerance beside the button goes with the request: out of range, the
    // server's message shows and the result line is cleared; emptied, it fits the drawing again.
    let field = c.find(Locator::Css("#kawasaki-tolerance")).await.unwrap();
    field.send_keys("90").await.unwrap();
    click(&c, "#layers-btn").await;
    wait_until(
        &c,
        "const e = document.getElementById('error'); \
         return !e.hidden && e.textContent.includes('45 degrees')",
        "the tolerance refused",
    )
    .await;
    assert_eq!(text(&c, "#layers-result").await, "");
    // The message sits in the page's flow (it covers no control) and closes.
    let overlaps = c
        .execute(
            "const e = document.getElementById('error').getBoundingClientRect(); \
             return [...document.querySelectorAll('main button, main input, main select')] \
               .filter((b) => b.offsetParent && !document.getElementById('error').contains(b)) \
               .some((b) => { const r = b.getBoundingClientRect(); \
                 return r.bottom > e.top && r.top < e.bottom && r.right > e.left && r.left < e.right; })",
            vec![],
        )
        .await
        .unwrap();
    assert_eq!(overlaps, json!(false), "the message covers a control");
    click(&c, "#error-close").await;
    assert_eq!(
        c.execute("return document.getElementById('error').hidden", vec![])
            .await
            .unwrap(),
        json!(true)
    );
    field.clear().await.unwrap();
    click(&c, "#layers-btn").await;
    wait_until(&c, layer_line, "the layer order again").await;
    assert_eq!(text(&c, "#layers-result").await, expected);
    keep_screenshot(&c, "studio-pattern.png").await;

    // 2. A broken pattern: the check's findings listed and ringed, as `foldcam check` finds them.
    let broken = PathBuf::from(repo_file("examples/patterns/broken-vertex.fold"));
    let cli = foldcam(&["check", &broken.to_string_lossy(), "--json"], dir.path());
    let report: Value = serde_json::from_slice(&cli.stdout).unwrap();
    let expected: Vec<&str> = report["findings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["message"].as_str().unwrap())
        .collect();
    assert!(!expected.is_empty(), "the example is broken");
    open(&c, &broken).await;
    let items = c.find_all(Locator::Css("#findings li")).await.unwrap();
    let mut listed = Vec::new();
    for item in &items {
        listed.push(item.text().await.unwrap());
    }
    assert_eq!(listed, expected);
    let rings = c.find_all(Locator::Css("#cp-rings circle")).await.unwrap();
    assert_eq!(rings.len(), expected.len());
    let home = c
        .find(Locator::Css("#cp-svg"))
        .await
        .unwrap()
        .attr("viewBox")
        .await
        .unwrap();
    items[0].click().await.unwrap();
    let zoomed = c
        .find(Locator::Css("#cp-svg"))
        .await
        .unwrap()
        .attr("viewBox")
        .await
        .unwrap();
    assert_ne!(home, zoomed, "clicking a finding zooms to it");
    keep_screenshot(&c, "studio-check.png").await;

    // 3. The folded form: moving the slider changes the 3D view.
    open(&c, &miura).await;
    c.find(Locator::Css("#tabs button[data-view='fold']"))
        .await
        .unwrap()
        .click()
        .await
        .unwrap();
    wait_until(
        &c,
        "return document.body.dataset.foldPercent !== undefined && !document.body.dataset.busy",
        "the fold simulation",
    )
    .await;
    let canvas = c.find(Locator::Css("#fold-canvas canvas")).await.unwrap();
    let flat = canvas.screenshot().await.unwrap();
    let slider = c.find(Locator::Css("#fold-slider")).await.unwrap();
    // Keyboard on the range input, as a person would: End is 100%, then back to about 70%.
    slider.send_keys("\u{E010}").await.unwrap();
    wait_until(
        &c,
        "return document.body.dataset.foldPercent === '100.0'",
        "100%",
    )
    .await;
    let folded = canvas.screenshot().await.unwrap();
    let changed = changed_fraction(&flat, &folded);
    assert!(
        changed > 0.02,
        "folding changed only {:.2}% of the view",
        100.0 * changed
    );
    for _ in 0..30 {
        slider.send_keys("\u{E012}").await.unwrap();
    }
    let label = text(&c, "#fold-label").await;
    assert!(label.contains('%'), "{label}");
    keep_screenshot(&c, "studio-fold.png").await;

    // 4. Machine and material: the downloaded G-code is byte-identical to `foldcam cut`'s.
    c.find(Locator::Css("#tabs button[data-view='machine']"))
        .await
        .unwrap()
        .click()
        .await
        .unwrap();
    browser::choose_machine(&c, "grbl-diode", "card-300gsm").await;
    c.find(Locator::Css("#plan-btn"))
        .await
        .unwrap()
        .click()
        .await
        .unwrap();
    wait_until(
        &c,
        "return document.body.dataset.planned === 'true' && !!document.getElementById('sim-result')",
        "the plan",
    )
    .await;
    // The simulated machine's verdict is shown: an HTML paragraph with a size on screen.
    let shown = c
        .execute(
            "const p = document.getElementById('sim-result'); const r = p.getBoundingClientRect(); \
             return p instanceof HTMLParagraphElement && r.width > 0 && r.height > 0 \
               && p.innerText.startsWith('Simulated ')",
            vec![],
        )
        .await
        .unwrap();
    assert_eq!(shown, json!(true), "the simulation's result is not visible");
    // The preview frames the job (its burns with a margin of 8%, at least 5 mm), not the
    // whole bed.
    let framing = c
        .execute(
            "const b = document.getElementById('tp-burns').getBBox(); \
             const v = document.getElementById('toolpath-svg').dataset.view.split(' ').map(Number); \
             return [b.x, b.y, b.x + b.width, b.y + b.height, ...v];",
            vec![],
        )
        .await
        .unwrap();
    let f: Vec<f64> = framing
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    let (burns, view) = (&f[..4], &f[4..]);
    let size = (burns[2] - burns[0]).max(burns[3] - burns[1]);
    let pad = (0.08 * size).max(5.0);
    for k in 0..4 {
        let want = burns[k] + if k < 2 { -pad } else { pad };
        assert!(
            (view[k] - want).abs() < 0.02 + 0.08 * size,
            "view {view:?} does not frame the burns {burns:?}"
        );
    }
    let travel = c.find_all(Locator::Css("#tp-travel line")).await.unwrap();
    assert!(!travel.is_empty(), "travel is drawn");
    let served = download_text(&c, "#dl-gcode").await;
    let out = foldcam(
        &[
            "cut",
            "miura.fold",
            "-m",
            "grbl-diode",
            "-x",
            "card-300gsm",
            "-o",
            "cli.gcode",
        ],
        dir.path(),
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let cli = std::fs::read_to_string(dir.path().join("cli.gcode")).unwrap();
    assert!(
        served == cli,
        "the page's G-code differs from foldcam cut's"
    );
    keep_screenshot(&c, "studio-machine.png").await;

    c.close().await.unwrap();
}

/// Viewport position (CSS pixels) of pattern point `(x, y)` in the crease-pattern view.
async fn screen_of(c: &Client, x: f64, y: f64) -> (f64, f64) {
    let at = c
        .execute(
            "const svg = document.getElementById('cp-svg');
             const m = svg.querySelector('g').getScreenCTM();
             const p = svg.createSVGPoint(); p.x = arguments[0]; p.y = arguments[1];
             const q = p.matrixTransform(m); return [q.x, q.y];",
            vec![json!(x), json!(y)],
        )
        .await
        .unwrap();
    (at[0].as_f64().unwrap(), at[1].as_f64().unwrap())
}

async fn edits_done(c: &Client, n: usize) {
    wait_until(
        c,
        &format!("return document.body.dataset.edits === '{n}' && !document.body.dataset.busy"),
        "the edit and its check",
    )
    .await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn dragging_a_vertex_in_the_browser_breaks_kawasaki_and_undo_mends_it() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let (_driver, c) = open_studio(&server.url()).await;
    // A degree-4 vertex at (50, 50) that folds flat (the example's description: opposite
    // sectors sum to 180°, Kawasaki 1989), its creases folded all the way.
    let file = dir.path().join("flat-vertex.fold");
    std::fs::write(&file, studio::flat_vertex_folded_flat()).unwrap();
    open(&c, &file).await;
    assert_eq!(text(&c, "#check-status").await, "passed");

    // The hover label names an edge only while the pointer is on it.
    let file: Value = serde_json::from_slice(&studio::flat_vertex_folded_flat()).unwrap();
    let (x0, y0) = screen_of(&c, 5.0, 95.0).await; // empty paper near a corner
    let mountain = first_edge(&file, "M");
    pointer_move(&c, edge_middle_on_screen(&c, &file, mountain).await).await;
    let info = text(&c, "#hover-info").await;
    assert!(
        info.starts_with(&format!("edge {mountain}: mountain (M)")),
        "{info}"
    );
    let away = MouseActions::new("mouse".to_string()).then(PointerAction::MoveTo {
        duration: None,
        x: x0,
        y: y0,
    });
    c.perform_actions(away).await.unwrap();
    assert_eq!(
        text(&c, "#hover-info").await,
        "Hover over a line to see it."
    );

    // Drag the vertex to (40, 40) with snapping off: the sectors change and Kawasaki fails.
    click(&c, "#edit-tools button[data-tool='move']").await;
    c.find(Locator::Css("#snap-grid"))
        .await
        .unwrap()
        .select_by_value("0")
        .await
        .unwrap();
    click(&c, "#snap-angles").await;
    let (sx, sy) = screen_of(&c, 50.0, 50.0).await;
    let (tx, ty) = screen_of(&c, 40.0, 40.0).await;
    let mut drag = MouseActions::new("mouse".to_string())
        .then(PointerAction::MoveTo {
            duration: None,
            x: sx,
            y: sy,
        })
        .then(PointerAction::Down { button: 0 });
    for k in 1..=8 {
        let t = f64::from(k) / 8.0;
        drag = drag.then(PointerAction::MoveTo {
            duration: Some(Duration::from_millis(60)),
            x: sx + (tx - sx) * t,
            y: sy + (ty - sy) * t,
        });
    }
    drag = drag.then(PointerAction::Up { button: 0 });
    c.perform_actions(drag).await.unwrap();
    edits_done(&c, 1).await;
    assert!(text(&c, "#check-status").await.contains("finding"));
    let kawasaki = c
        .find_all(Locator::Css("#findings li.finding-kawasaki"))
        .await
        .unwrap();
    assert_eq!(kawasaki.len(), 1, "one Kawasaki fault, at the moved vertex");
    // The vertex is where it was dropped (to a pixel): read back from the page's pattern,
    // and the canvas draws lines there.
    let moved = c
        .execute(
            "return document.getElementById('cp-canvas').patternView.pattern.vertices",
            vec![],
        )
        .await
        .unwrap();
    let at = moved.as_array().unwrap().iter().find_map(|p| {
        let (x, y) = (p[0].as_f64().unwrap(), p[1].as_f64().unwrap());
        ((x - 40.0).abs() < 1.0 && (y - 40.0).abs() < 1.0).then_some((x, y))
    });
    let at = at.expect("no vertex near (40, 40)");
    assert!(
        pattern_ink(&c, &[at]).await[0][3] > 0,
        "nothing drawn at {at:?}"
    );
    keep_screenshot(&c, "studio-edit.png").await;

    // Undo: the file's pattern again, and the check passes.
    click(&c, "#undo-btn").await;
    edits_done(&c, 2).await;
    assert_eq!(text(&c, "#check-status").await, "passed");
    let still = c.find_all(Locator::Css("#findings li")).await.unwrap();
    assert!(still.is_empty());
    c.close().await.unwrap();
}

/// Ends of the lines drawn in `css`, in drawing coordinates.
async fn line_ends(c: &Client, css: &str) -> Vec<[f64; 4]> {
    let ends = c
        .execute(
            "return [...document.querySelectorAll(arguments[0])].map((l) => \
             ['x1', 'y1', 'x2', 'y2'].map((k) => +l.getAttribute(k)))",
            vec![json!(css)],
        )
        .await
        .unwrap();
    serde_json::from_value(ends).unwrap()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn dragging_a_corner_onto_the_opposite_one_folds_the_diagonal() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let (_driver, c) = open_studio(&server.url()).await;
    // The fold mode starts on a 150 mm square.
    click(&c, "#tabs button[data-view='folding']").await;
    wait_until(
        &c,
        "return document.body.dataset.foldStep === '0' && !document.body.dataset.busy",
        "the sheet",
    )
    .await;
    assert!(
        c.find_all(Locator::Css("#folding-steps li"))
            .await
            .unwrap()
            .is_empty()
    );

    // Drag the corner (150, 150) onto (0, 0) (Miyazaki et al. 1992: the fold line is the
    // perpendicular bisector of the move; a bend by default).
    let from = screen_in(&c, "folding-svg", 150.0, 150.0).await;
    let to = screen_in(&c, "folding-svg", 0.0, 0.0).await;
    pointer_drag(&c, from, to).await;
    wait_until(
        &c,
        "return document.body.dataset.foldStep === '1' && !document.body.dataset.busy",
        "the fold step",
    )
    .await;
    let steps = c.find_all(Locator::Css("#folding-steps li")).await.unwrap();
    assert_eq!(steps.len(), 1, "one step in the list");
    // Two faces drawn, the flap folded over showing the back of the paper.
    let backs = c
        .find_all(Locator::Css("#folding-faces polygon.back"))
        .await
        .unwrap();
    assert_eq!(backs.len(), 1);
    // The crease pattern holds one valley: the diagonal from (150, 0) to (0, 150).
    let valleys = line_ends(&c, "#folding-cp line.edge-V").await;
    assert_eq!(valleys.len(), 1, "{valleys:?}");
    let [x1, y1, x2, y2] = valleys[0];
    let mut ends = [(x1, y1), (x2, y2)];
    ends.sort_by(|a, b| a.0.total_cmp(&b.0));
    let near = |p: (f64, f64), q: (f64, f64)| (p.0 - q.0).abs() < 1e-6 && (p.1 - q.1).abs() < 1e-6;
    assert!(
        near(ends[0], (0.0, 150.0)) && near(ends[1], (150.0, 0.0)),
        "{ends:?}"
    );

    // The saved script, folded by the CLI, gives the same crease.
    let script = download_text(&c, "#folding-script").await;
    std::fs::write(dir.path().join("saved.toml"), &script).unwrap();
    let out = foldcam(&["fold", "saved.toml", "-o", "saved.fold"], dir.path());
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let (vertices, edges, m, v) = fold_counts(&dir.path().join("saved.fold"));
    assert_eq!((m, v), (0, 1));

    // Tuck in the corner (150, 0), the pointer held near (0, 0): the preview draws the fold
    // line (snapped onto the corner: the midline x = 75) before anything is made.
    click(&c, "#folding-tools button[data-op='tuck']").await;
    let from = screen_in(&c, "folding-svg", 150.0, 0.0).await;
    let to = screen_in(&c, "folding-svg", 1.5, 1.0).await;
    let mut hold = MouseActions::new("mouse".to_string())
        .then(PointerAction::MoveTo {
            duration: None,
            x: from.0,
            y: from.1,
        })
        .then(PointerAction::Down { button: 0 });
    for k in 1..=8 {
        let t = f64::from(k) / 8.0;
        hold = hold.then(PointerAction::MoveTo {
            duration: Some(Duration::from_millis(60)),
            x: from.0 + (to.0 - from.0) * t,
            y: from.1 + (to.1 - from.1) * t,
        });
    }
    c.perform_actions(hold).await.unwrap();
    wait_until(
        &c,
        "const l = document.querySelector('#folding-svg line.fold-line');          return !!l && Math.abs(+l.getAttribute('x1') - 75) < 1e-6          && Math.abs(+l.getAttribute('x2') - 75) < 1e-6",
        "the fold line at x = 75",
    )
    .await;
    assert_eq!(
        c.execute("return document.body.dataset.foldStep", vec![])
            .await
            .unwrap(),
        json!("1"),
        "a preview makes no step"
    );
    keep_screenshot(&c, "studio-folding.png").await;
    let release = MouseActions::new("mouse".to_string()).then(PointerAction::Up { button: 0 });
    c.perform_actions(release).await.unwrap();
    wait_until(
        &c,
        "return document.body.dataset.foldStep === '2' && !document.body.dataset.busy",
        "the tuck-in",
    )
    .await;
    // Back to the diagonal fold: the tuck-in stays in the list, undone.
    click(&c, "#folding-back").await;
    wait_until(
        &c,
        "return document.body.dataset.foldStep === '1' && !document.body.dataset.busy",
        "the step back",
    )
    .await;
    assert_eq!(
        c.find_all(Locator::Css("#folding-steps li"))
            .await
            .unwrap()
            .len(),
        2
    );
    assert_eq!(
        c.find_all(Locator::Css("#folding-steps li.undone"))
            .await
            .unwrap()
            .len(),
        1
    );

    // To a crease pattern document: the counts of the CLI's file, and check, plan and cut
    // work on it as on any pattern.
    click(&c, "#folding-pattern").await;
    wait_until(
        &c,
        "return document.body.dataset.doc !== undefined && !document.body.dataset.busy \
         && !document.getElementById('view-pattern').hidden",
        "the crease pattern document",
    )
    .await;
    assert_eq!(text(&c, "#count-vertices").await, vertices.to_string());
    assert_eq!(text(&c, "#count-edges").await, edges.to_string());
    assert_eq!(text(&c, "#count-V").await, "1");
    assert_eq!(text(&c, "#check-status").await, "passed");
    c.close().await.unwrap();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_design_file_uploaded_in_the_browser_opens_as_the_command_builds_it() {
    let dir = tempfile::tempdir().unwrap();
    let house = PathBuf::from(repo_file("examples/popup/house.voxel.txt"));
    // What `foldcam popup voxel` writes for the same file: the counts to see.
    let out = foldcam(
        &[
            "popup",
            "voxel",
            &house.to_string_lossy(),
            "-o",
            "house.fold",
        ],
        dir.path(),
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let summary = String::from_utf8_lossy(&out.stdout).trim().to_string();
    let server = Server::start(&[], dir.path());
    let (_driver, c) = open_studio(&server.url()).await;
    // Record what the page says while it works.
    c.execute(
        "window.busySeen = []; const b = document.getElementById('busy'); \
         new MutationObserver(() => { if (!b.hidden) window.busySeen.push(b.textContent); })\
         .observe(b, { attributes: true, childList: true });",
        vec![],
    )
    .await
    .unwrap();
    open(&c, &house).await;
    let (vertices, edges, m, v) = fold_counts(&dir.path().join("house.fold"));
    assert_eq!(text(&c, "#count-vertices").await, vertices.to_string());
    assert_eq!(text(&c, "#count-edges").await, edges.to_string());
    assert_eq!(text(&c, "#count-M").await, m.to_string());
    assert_eq!(text(&c, "#count-V").await, v.to_string());
    assert!(text(&c, "#made").await.contains("voxel pop-up card"));
    // The command's summary (the name as uploaded) is among the messages.
    let name_free = summary.split_once(": ").map(|(_, rest)| rest).unwrap();
    assert!(text(&c, "#messages").await.contains(name_free), "{summary}");
    let seen = c.execute("return window.busySeen", vec![]).await.unwrap();
    assert!(
        seen.as_array().unwrap().iter().any(|s| s
            .as_str()
            .unwrap()
            .contains("building the design from house.voxel.txt")),
        "the page said it was working: {seen}"
    );
    keep_screenshot(&c, "studio-design.png").await;
    c.close().await.unwrap();
}

#[tokio::test]
async fn a_file_named_by_a_long_path_shows_its_name_with_the_path_on_hover() {
    let dir = tempfile::tempdir().unwrap();
    let deep = dir
        .path()
        .join("a-folder-with-a-rather-long-name-for-designs")
        .join("and-another-one-below-it-for-this-season");
    std::fs::create_dir_all(&deep).unwrap();
    let out = foldcam(&["generate", "miura", "-o", "miura.fold"], &deep);
    assert!(out.status.success());
    let file = deep.join("miura.fold");
    let full = file.to_str().unwrap().to_string();
    let server = Server::start(&[&full], dir.path());
    let (_driver, c) = open_studio(&server.url()).await;
    let button = c.find(Locator::Css("#cli-files button")).await.unwrap();
    assert_eq!(button.text().await.unwrap(), "miura.fold");
    assert_eq!(
        button.attr("title").await.unwrap().as_deref(),
        Some(full.as_str())
    );
    button.click().await.unwrap();
    wait_until(
        &c,
        "return document.getElementById('doc-name').textContent === 'miura.fold'",
        "the document's name",
    )
    .await;
    let name = c.find(Locator::Css("#doc-name")).await.unwrap();
    let title = name.attr("title").await.unwrap().unwrap_or_default();
    assert!(
        title.ends_with("miura.fold") && title.len() > full.len() / 2,
        "{title}"
    );
    // The header keeps one row: the name does not wrap it.
    let rows = c
        .execute(
            "const n = document.getElementById('doc-name'); \
             const line = parseFloat(getComputedStyle(n).lineHeight) || 20; \
             return n.getBoundingClientRect().height / line;",
            vec![],
        )
        .await
        .unwrap();
    assert!(rows.as_f64().unwrap() < 1.5, "the name spans {rows} lines");
}

#[tokio::test]
async fn a_plan_warning_about_lines_rings_them_on_the_pattern() {
    // A 100 mm square with a 0.8 mm valley from the bottom side: too short for a perforation
    // dash, so the plan warns about that one line (edge 5).
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("short.fold"),
        r#"{"file_spec":1.2,"frame_unit":"mm",
            "vertices_coords":[[0,0],[50,0],[100,0],[100,100],[0,100],[50,0.8]],
            "edges_vertices":[[0,1],[1,2],[2,3],[3,4],[4,0],[1,5]],
            "edges_assignment":["B","B","B","B","B","V"]}"#,
    )
    .unwrap();
    let server = Server::start(&["short.fold"], dir.path());
    // What the API says: one warning, typed, about edge 5.
    let (status, opened) = server.post_json("/api/files/0", b"");
    assert_eq!(status, 200, "{opened}");
    let (status, plan) = server.get(&format!(
        "/api/docs/{}/plan?machine=grbl-diode&material=card-300gsm&valley=perforate",
        opened["id"]
    ));
    assert_eq!(status, 200);
    let plan: Value = serde_json::from_slice(&plan).unwrap();
    let warnings = plan["warnings"].as_array().unwrap();
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert_eq!(warnings[0]["kind"], "creases_too_short");
    assert_eq!(warnings[0]["edges"], json!([5]));
    let (_driver, c) = open_studio(&server.url()).await;
    wait_until(
        &c,
        "return document.getElementById('doc-name').textContent === 'short.fold'",
        "the document",
    )
    .await;
    click(&c, "#tabs button[data-view='machine']").await;
    browser::choose_machine(&c, "grbl-diode", "card-300gsm").await;
    // The overrides sit in a folded section: set the valley's operation as a pick would.
    c.execute(
        "const s = document.querySelector(\"select[data-option='valley']\"); \
         s.value = 'perforate'; s.dispatchEvent(new Event('change'));",
        vec![],
    )
    .await
    .unwrap();
    click(&c, "#plan-btn").await;
    wait_until(
        &c,
        "return !!document.querySelector('.plan-warning[data-kind=creases_too_short] .show-edges')",
        "the warning with its button",
    )
    .await;
    click(&c, ".plan-warning .show-edges").await;
    wait_until(
        &c,
        "return !document.getElementById('view-pattern').hidden \
           && document.querySelectorAll('#cp-rings line.warning-edge').length === 1",
        "the pattern view with the line ringed",
    )
    .await;
    // The ringed line is edge 5 where the pattern view draws it, and the view zoomed to it.
    let ringed = c
        .execute(
            "const l = document.querySelector('#cp-rings line.warning-edge'); \
             return [Number(l.dataset.edge), ...['x1', 'y1', 'x2', 'y2'].map((a) => Number(l.getAttribute(a)))];",
            vec![],
        )
        .await
        .unwrap();
    assert_eq!(ringed, json!([5, 50, 0, 50, 0.8]), "{ringed}");
    let view = c
        .execute(
            "return document.getElementById('cp-svg').getAttribute('viewBox').split(' ').map(Number);",
            vec![],
        )
        .await
        .unwrap();
    let width = view[2].as_f64().unwrap();
    assert!(width < 30.0, "the view was not zoomed to the line: {view}");
    c.close().await.unwrap();
}
