//! The studio's pattern view in headless Chromium (software GL, as the browser tests run it):
//! frames drawn per second while panning Miura-ori patterns of about 140, 10,000 and 100,000
//! edges, and the 3D fold of the 10,000-edge one (time to its first frame, the flat sheet, and
//! to the settled fold).
//!
//! Each pattern is made with `foldcam generate miura`, served by `foldcam serve` and opened
//! through the page's file picker. The pan is a drag on the view: pointer events dispatched in
//! the page once per animation frame (`requestAnimationFrame`), a circle of 150 px a second,
//! for [`PAN_SECONDS`] after [`WARM_UP_SECONDS`] unmeasured; the figure is the frames the view
//! drew on its canvas over the seconds elapsed (the page's rAF callbacks are printed beside
//! it). The fold is timed from the click on its tab to the flat sheet, the first folded frame
//! (streamed while the static solve runs) and the settled fold. The targets: ≥ 30 frames/s at
//! 10k edges, ≥ 10 at 100k, the fold's first frame within 1 s, the fold settled within 3 s.
//!
//! Needs Debian's `chromium` and `chromium-driver`. Run with `cargo bench --bench studio_pan`.

#[path = "../tests/common/browser.rs"]
mod browser;
#[path = "../tests/common/studio.rs"]
mod studio;

use std::path::Path;
use std::process::Command;

use fantoccini::{Client, Locator};
use serde_json::{Value, json};

/// Seconds of panning measured, per pattern.
const PAN_SECONDS: f64 = 4.0;
/// Seconds of panning before the measure (the first frames rasterise the paths).
const WARM_UP_SECONDS: f64 = 1.0;

/// The patterns: name, Miura-ori columns and rows.
const PATTERNS: [(&str, usize, usize); 3] = [("small", 8, 8), ("10k", 70, 70), ("100k", 224, 223)];

/// Pans the pattern view for `seconds`: frames drawn, rAF callbacks and the seconds elapsed.
const PAN: &str = r#"
const [seconds, done] = arguments;
const svg = document.getElementById('cp-svg');
const view = document.getElementById('cp-canvas').patternView;
const r = svg.getBoundingClientRect();
const cx = r.left + r.width / 2, cy = r.top + r.height / 2;
const fire = (type, x, y) => svg.dispatchEvent(new PointerEvent(type, {
  clientX: x, clientY: y, bubbles: true, pointerId: 1, isPrimary: true, button: 0,
  buttons: type === 'pointerup' ? 0 : 1 }));
let rafs = 0;
const drawn = view.frames, t0 = performance.now();
fire('pointerdown', cx, cy);
const step = (now) => {
  rafs += 1;
  const t = (now - t0) / 1000;
  fire('pointermove', cx + 150 * Math.sin(2 * Math.PI * t), cy + 150 * (1 - Math.cos(2 * Math.PI * t)));
  if (now - t0 < seconds * 1000) { requestAnimationFrame(step); return; }
  fire('pointerup', cx, cy);
  requestAnimationFrame(() => done({ drawn: view.frames - drawn, rafs, seconds: (performance.now() - t0) / 1000 }));
};
requestAnimationFrame(step);
"#;

/// Records when the fold view shows its flat sheet and its fold (`body[data-fold-stage]`),
/// milliseconds from now.
const WATCH_FOLD: &str = r#"
window.foldTimes = {};
const t0 = performance.now();
new MutationObserver(() => {
  const stage = document.body.dataset.foldStage;
  if (stage && !(stage in window.foldTimes)) window.foldTimes[stage] = performance.now() - t0;
}).observe(document.body, { attributes: true, attributeFilter: ['data-fold-stage'] });
"#;

fn generate(dir: &Path, name: &str, columns: usize, rows: usize) -> std::path::PathBuf {
    let file = dir.join(format!("miura-{name}.fold"));
    let out = Command::new(env!("CARGO_BIN_EXE_foldcam"))
        .args(["generate", "miura", "--columns", &columns.to_string()])
        .args(["--rows", &rows.to_string(), "-o"])
        .arg(&file)
        .output()
        .expect("foldcam runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    file
}

/// Opens `file` with the page's file picker; waits until it is shown.
async fn open(c: &Client, file: &Path) {
    let before = c
        .execute("return document.body.dataset.doc ?? 'none'", vec![])
        .await
        .unwrap();
    let input = c.find(Locator::Css("#file-input")).await.unwrap();
    input.send_keys(&file.to_string_lossy()).await.unwrap();
    let script = format!(
        "return document.body.dataset.doc !== undefined && document.body.dataset.doc !== {before} \
         && !document.body.dataset.busy"
    );
    browser::wait_until(c, &script, "the pattern to open").await;
}

async fn pan(c: &Client, seconds: f64) -> Value {
    c.execute_async(PAN, vec![json!(seconds)]).await.unwrap()
}

async fn run() {
    let dir = tempfile::tempdir().unwrap();
    let server = studio::Server::start(&[], dir.path());
    let (_driver, c) = browser::open_studio(&server.url()).await;
    for (name, columns, rows) in PATTERNS {
        let file = generate(dir.path(), name, columns, rows);
        open(&c, &file).await;
        let edges = browser::text(&c, "#count-edges").await;
        pan(&c, WARM_UP_SECONDS).await;
        let r = pan(&c, PAN_SECONDS).await;
        let seconds = r["seconds"].as_f64().unwrap();
        let drawn = r["drawn"].as_f64().unwrap();
        let rafs = r["rafs"].as_f64().unwrap();
        println!(
            "studio_pan: Miura-ori {columns} x {rows}, {edges} edges: {:.1} frames/s drawn \
             ({:.1} rAF/s) over {seconds:.1} s",
            drawn / seconds,
            rafs / seconds
        );
        if name != "10k" {
            continue;
        }
        c.execute(WATCH_FOLD, vec![]).await.unwrap();
        browser::click(&c, "#tabs button[data-view='fold']").await;
        browser::wait_until(
            &c,
            "return document.body.dataset.foldStage === 'folded' && !document.body.dataset.busy",
            "the fold",
        )
        .await;
        let times = c.execute("return window.foldTimes", vec![]).await.unwrap();
        let report = browser::text(&c, "#fold-report").await;
        let seconds = |stage: &str| times[stage].as_f64().map_or(f64::NAN, |t| t / 1000.0);
        println!(
            "studio_pan: fold 3D at {edges} edges: flat sheet {:.2} s, first folded frame {:.2} s, \
             settled {:.2} s; {report}",
            seconds("flat"),
            seconds("folding"),
            seconds("folded")
        );
        browser::click(&c, "#tabs button[data-view='pattern']").await;
    }
    c.close().await.unwrap();
}

fn main() {
    tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()
        .unwrap()
        .block_on(run());
}
