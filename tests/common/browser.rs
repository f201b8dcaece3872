//! Headless Chromium for the studio's browser scenarios (Debian's `chromium` and
//! `chromium-driver`, installed by `.ci/run`), driven over WebDriver: the driver, the browser,
//! waiting for the page, real pointer drags and screenshots. A machine without them fails the
//! scenarios: they do not pass quietly.
//!
//! Set `FOLDCAM_SCREENSHOTS=DIR` to keep the screenshots (the README's pictures come from
//! `FOLDCAM_SCREENSHOTS=docs cargo test --test browser MODULE`).
#![allow(dead_code)]

use std::net::TcpListener;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use fantoccini::actions::{InputSource, KeyAction, KeyActions, MouseActions, PointerAction};
use fantoccini::{Client, ClientBuilder, Locator};
use serde_json::{Value, json};

/// Longest wait for the page to reach a state (a debug build serves it).
pub const PAGE_TIMEOUT: Duration = Duration::from_secs(180);

/// Browser window size, pixels.
pub const WINDOW: (u32, u32) = (1400, 860);

/// `chromedriver` on a free port, stopped when dropped.
pub struct Driver(Child, u16);

impl Drop for Driver {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

pub fn free_port() -> u16 {
    TcpListener::bind("127.0.0.1:0")
        .unwrap()
        .local_addr()
        .unwrap()
        .port()
}

/// Starts `chromedriver`; panics naming the packages when it is missing.
pub fn start_driver() -> Driver {
    let port = free_port();
    let child = Command::new("chromedriver")
        .arg(format!("--port={port}"))
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap_or_else(|e| {
            panic!(
                "chromedriver could not start ({e}): install Debian's chromium and \
                 chromium-driver (`apt-get install -y chromium chromium-driver`, as .ci/run does)"
            )
        });
    let start = Instant::now();
    while std::net::TcpStream::connect(("127.0.0.1", port)).is_err() {
        assert!(
            start.elapsed() < Duration::from_secs(30),
            "chromedriver did not listen"
        );
        std::thread::sleep(Duration::from_millis(100));
    }
    Driver(child, port)
}

/// A headless Chromium session of [`WINDOW`]'s size.
pub async fn browser(driver: &Driver) -> Client {
    browser_with(driver, None).await
}

/// [`browser`], saving what the page downloads in `downloads` (when given) without asking.
async fn browser_with(driver: &Driver, downloads: Option<&Path>) -> Client {
    let mut caps = serde_json::Map::new();
    let mut options = json!({
            "args": [
                "--headless=new",
                "--no-sandbox",
                "--disable-dev-shm-usage",
                "--disable-gpu-sandbox",
                "--use-angle=swiftshader",
                "--enable-unsafe-swiftshader",
                "--hide-scrollbars",
                format!("--window-size={},{}", WINDOW.0, WINDOW.1),
            ]
    });
    if let Some(dir) = downloads {
        options["prefs"] = json!({
            "download.default_directory": dir,
            "download.prompt_for_download": false,
        });
    }
    caps.insert("goog:chromeOptions".into(), options);
    let connector = hyper_util::client::legacy::connect::HttpConnector::new();
    ClientBuilder::new(connector)
        .capabilities(caps)
        .connect(&format!("http://127.0.0.1:{}", driver.1))
        .await
        .unwrap_or_else(|e| panic!("headless Chromium did not start: {e}"))
}

/// A headless Chromium on `url` (the studio's address), once the page has started, with the
/// opening screen closed (as a user closes it) when the studio has no file; the driver lives
/// as long as the returned value is kept.
pub async fn open_studio(url: &str) -> (Driver, Client) {
    let (driver, c) = open_studio_with(url, None).await;
    if c.execute("return !document.getElementById('start').hidden", vec![])
        .await
        .unwrap()
        == Value::Bool(true)
    {
        click(&c, "#start-close").await;
    }
    (driver, c)
}

/// A headless Chromium on `url` once the page has started, its opening screen as the page
/// left it; what the page downloads goes to `downloads` (see [`downloaded`]).
pub async fn open_studio_downloading(url: &str, downloads: &Path) -> (Driver, Client) {
    open_studio_with(url, Some(downloads)).await
}

async fn open_studio_with(url: &str, downloads: Option<&Path>) -> (Driver, Client) {
    let driver = start_driver();
    let c = browser_with(&driver, downloads).await;
    c.goto(url).await.unwrap();
    wait_until(
        &c,
        "return document.body.dataset.ready === 'true'",
        "the page to start",
    )
    .await;
    (driver, c)
}

/// The bytes of the file `name` the browser downloaded into `dir`, once it is complete;
/// panics after [`PAGE_TIMEOUT`].
pub async fn downloaded(dir: &Path, name: &str) -> Vec<u8> {
    let start = Instant::now();
    let path = dir.join(name);
    loop {
        let partial = std::fs::read_dir(dir).unwrap().any(|e| {
            e.unwrap()
                .file_name()
                .to_string_lossy()
                .ends_with(".crdownload")
        });
        if path.exists() && !partial {
            return std::fs::read(&path).unwrap();
        }
        assert!(
            start.elapsed() < PAGE_TIMEOUT,
            "{name} was not downloaded; {} holds {:?}",
            dir.display(),
            std::fs::read_dir(dir)
                .unwrap()
                .map(|e| e.unwrap().file_name())
                .collect::<Vec<_>>()
        );
        tokio::time::sleep(Duration::from_millis(150)).await;
    }
}

/// Presses `key` with Control held (Ctrl+S and the like), as real key events.
pub async fn press_ctrl(c: &Client, key: char) {
    let control: char = fantoccini::key::Key::Control.into();
    let keys = KeyActions::new("keyboard".to_string())
        .then(KeyAction::Down { value: control })
        .then(KeyAction::Down { value: key })
        .then(KeyAction::Up { value: key })
        .then(KeyAction::Up { value: control });
    c.perform_actions(keys).await.unwrap();
}

/// Presses `key` alone (a [`fantoccini::key::Key`] such as Escape, or a letter).
pub async fn press(c: &Client, key: char) {
    let keys = KeyActions::new("keyboard".to_string())
        .then(KeyAction::Down { value: key })
        .then(KeyAction::Up { value: key });
    c.perform_actions(keys).await.unwrap();
}

/// Waits until `script` (a function body) returns true; panics with `what` and the page's
/// error after [`PAGE_TIMEOUT`].
pub async fn wait_until(c: &Client, script: &str, what: &str) {
    let start = Instant::now();
    loop {
        let done = c.execute(script, vec![]).await.expect("script runs");
        if done == Value::Bool(true) {
            return;
        }
        let error = c
            .execute(
                // A page without the studio's error line (another origin's, or one still
                // loading) says nothing: keep waiting.
                "return document.getElementById('error')?.textContent ?? null",
                vec![],
            )
            .await
            .unwrap();
        assert!(
            start.elapsed() < PAGE_TIMEOUT,
            "timed out waiting for {what}; the page says {error}"
        );
        tokio::time::sleep(Duration::from_millis(150)).await;
    }
}

/// The text of the element `css`.
pub async fn text(c: &Client, css: &str) -> String {
    c.find(Locator::Css(css))
        .await
        .expect(css)
        .text()
        .await
        .unwrap()
}

/// Chooses `machine` and `material` in the Machine view's selects.
pub async fn choose_machine(c: &Client, machine: &str, material: &str) {
    for (css, value) in [("#machine", machine), ("#material", material)] {
        c.find(Locator::Css(css))
            .await
            .unwrap()
            .select_by_value(value)
            .await
            .unwrap();
    }
}

/// Clicks the element `css`.
pub async fn click(c: &Client, css: &str) {
    c.find(Locator::Css(css))
        .await
        .expect(css)
        .click()
        .await
        .unwrap();
}

/// A real pointer click at a viewport point (CSS pixels).
pub async fn pointer_click(c: &Client, at: (f64, f64)) {
    let actions = MouseActions::new("mouse".to_string())
        .then(PointerAction::MoveTo {
            duration: None,
            x: at.0,
            y: at.1,
        })
        .then(PointerAction::Down { button: 0 })
        .then(PointerAction::Up { button: 0 });
    c.perform_actions(actions).await.unwrap();
}

/// The screenshot folder asked for with `FOLDCAM_SCREENSHOTS=DIR`, if any.
pub fn screenshots_dir() -> Option<PathBuf> {
    std::env::var_os("FOLDCAM_SCREENSHOTS").map(|d| {
        let d = Path::new(env!("CARGO_MANIFEST_DIR")).join(d);
        std::fs::create_dir_all(&d).unwrap();
        d
    })
}

/// Takes a screenshot; keeps it as `name` when `FOLDCAM_SCREENSHOTS` is set.
pub async fn keep_screenshot(c: &Client, name: &str) {
    let png = c.screenshot().await.unwrap();
    assert!(png.starts_with(b"\x89PNG"), "a PNG screenshot");
    if let Some(d) = screenshots_dir() {
        std::fs::write(d.join(name), png).unwrap();
    }
}

/// Viewport position (CSS pixels) of drawing point `(x, y)` in the SVG `svg` (its first group
/// holds the drawing in its own coordinates).
pub async fn screen_in(c: &Client, svg: &str, x: f64, y: f64) -> (f64, f64) {
    let at = c
        .execute(
            "const svg = document.getElementById(arguments[0]);
             const m = svg.querySelector('g').getScreenCTM();
             const p = svg.createSVGPoint(); p.x = arguments[1]; p.y = arguments[2];
             const q = p.matrixTransform(m); return [q.x, q.y];",
            vec![json!(svg), json!(x), json!(y)],
        )
        .await
        .unwrap();
    (at[0].as_f64().unwrap(), at[1].as_f64().unwrap())
}

/// A real pointer drag from one viewport point to another, in eight moves.
pub async fn pointer_drag(c: &Client, from: (f64, f64), to: (f64, f64)) {
    let mut drag = MouseActions::new("mouse".to_string())
        .then(PointerAction::MoveTo {
            duration: None,
            x: from.0,
            y: from.1,
        })
        .then(PointerAction::Down { button: 0 });
    for k in 1..=8 {
        let t = f64::from(k) / 8.0;
        drag = drag.then(PointerAction::MoveTo {
            duration: Some(Duration::from_millis(60)),
            x: from.0 + (to.0 - from.0) * t,
            y: from.1 + (to.1 - from.1) * t,
        });
    }
    c.perform_actions(drag.then(PointerAction::Up { button: 0 }))
        .await
        .unwrap();
}

/// Fetches `url` from the page (with its cookies and origin) as text.
pub async fn fetch_text(c: &Client, url: &str) -> String {
    let text = c
        .execute_async(
            "const done = arguments[arguments.length - 1];
             fetch(arguments[0]).then(r => r.text()).then(done, e => done('ERROR ' + e));",
            vec![json!(url)],
        )
        .await
        .unwrap();
    let text = text.as_str().unwrap().to_string();
    assert!(!text.starts_with("ERROR "), "{url}: {text}");
    text
}

/// The `href` of the link `css` selects (a download the page built).
pub async fn link_href(c: &Client, css: &str) -> String {
    c.find(Locator::Css(css))
        .await
        .expect(css)
        .attr("href")
        .await
        .unwrap()
        .unwrap_or_else(|| panic!("{css} has no href"))
}

/// The text the page would download from the link `css`, fetched in the page.
pub async fn download_text(c: &Client, css: &str) -> String {
    let href = link_href(c, css).await;
    fetch_text(c, &href).await
}

/// A real pointer move to a viewport point (CSS pixels), no button pressed.
pub async fn pointer_move(c: &Client, at: (f64, f64)) {
    let mouse = MouseActions::new("mouse".to_string()).then(PointerAction::MoveTo {
        duration: None,
        x: at.0,
        y: at.1,
    });
    c.perform_actions(mouse).await.unwrap();
}

/// What the pattern view's canvas (`#cp-canvas`) shows at pattern points `(x, y)` (y up):
/// of the 3 × 3 canvas pixels around each, the one with the most ink, as RGBA (alpha 0 where
/// nothing is drawn). Waits two animation frames first, so a redraw asked for is done.
pub async fn pattern_ink(c: &Client, points: &[(f64, f64)]) -> Vec<[u8; 4]> {
    let points: Vec<[f64; 2]> = points.iter().map(|&(x, y)| [x, y]).collect();
    let ink = c
        .execute_async(
            "const [points, done] = arguments;
             requestAnimationFrame(() => requestAnimationFrame(() => {
               const canvas = document.getElementById('cp-canvas');
               const m = canvas.patternView.root.getScreenCTM();
               const r = canvas.getBoundingClientRect();
               const dpr = window.devicePixelRatio || 1;
               const ctx = canvas.getContext('2d', { willReadFrequently: true });
               done(points.map(([x, y]) => {
                 const px = Math.floor((m.a * x + m.c * y + m.e - r.left) * dpr);
                 const py = Math.floor((m.b * x + m.d * y + m.f - r.top) * dpr);
                 const d = ctx.getImageData(px - 1, py - 1, 3, 3).data;
                 let best = 0;
                 for (let k = 4; k < d.length; k += 4) if (d[k + 3] > d[best + 3]) best = k;
                 return [d[best], d[best + 1], d[best + 2], d[best + 3]];
               }));
             }));",
            vec![json!(points)],
        )
        .await
        .unwrap();
    serde_json::from_value(ink).unwrap()
}

/// How the studio's 3D card view in the element `container` shows the card: the screen x
/// (normalised, −1 left to 1 right) of the card's leftmost and rightmost corner (smallest and
/// largest x on the card, where the pattern and the cut sheet put x = 0 at the card's left
/// edge), and whether the camera is in front of the card, on the base's side of the back
/// sheet (the papers' +y).
pub async fn card_sides(c: &Client, container: &str) -> (f64, f64, bool) {
    let script = r#"
const view = document.getElementById(arguments[0]).cardView;
const mesh = view.model.children.find((m) => m.isMesh);
view.scene.updateMatrixWorld(true);
const V = view.camera.position.constructor;
const pos = mesh.geometry.getAttribute('position');
let left = null, right = null, ymin = Infinity, ymax = -Infinity;
for (let i = 0; i < pos.count; i += 1) {
  const v = new V(pos.getX(i), pos.getY(i), pos.getZ(i));
  if (!left || v.x < left.x) left = v;
  if (!right || v.x > right.x) right = v;
  ymin = Math.min(ymin, v.y); ymax = Math.max(ymax, v.y);
}
const screen = (v) => v.clone().applyMatrix4(mesh.matrixWorld).project(view.camera).x;
const camera = view.camera.position.clone().applyMatrix4(mesh.matrixWorld.clone().invert());
return [screen(left), screen(right), camera.y > (ymin + ymax) / 2];"#;
    let got = c.execute(script, vec![json!(container)]).await.unwrap();
    (
        got[0].as_f64().unwrap(),
        got[1].as_f64().unwrap(),
        got[2].as_bool().unwrap(),
    )
}
