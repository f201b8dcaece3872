//! The pattern view draws on a canvas: the creases are on it where the server's pattern puts
//! them, in their assignment's colour, dashed only when long enough on screen; the pointer
//! over a line finds the edge the server names, and a click with the Assign tool edits it; the
//! page's segment grid finds what a search of every segment finds.

use crate::bin;
use crate::browser;
use crate::studio;
use crate::studio_browser::{canvas_count, open};

use bin::foldcam;
use browser::{
    click, open_studio, pattern_ink, pointer_click, pointer_move, screen_in, text, wait_until,
};
use fantoccini::{Client, Locator};
use serde_json::{Value, json};
use studio::Server;

/// Points sampled along each line checked, between 30 % and 70 % of its length (away from the
/// ends, where other lines meet it).
const SAMPLES: usize = 9;

/// A point counts as off every line at least this far from all of them, screen pixels.
const CLEAR_PIXELS: f64 = 8.0;

/// Distance from `p` to segment `a`–`b`.
fn distance(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = dx * dx + dy * dy;
    let t = if l2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p.0 - a.0 - t * dx).hypot(p.1 - a.1 - t * dy)
}

/// One edge of the server's pattern view: its two ends and its assignment letter.
type Line = ((f64, f64), (f64, f64), String);

/// The server's pattern view: every edge, by index.
fn edges_of(view: &Value) -> Vec<Line> {
    let vertex = |k: &Value| {
        let p = &view["vertices"][k.as_u64().unwrap() as usize];
        (p[0].as_f64().unwrap(), p[1].as_f64().unwrap())
    };
    view["edges"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| {
            (
                vertex(&e["v"][0]),
                vertex(&e["v"][1]),
                e["a"].as_str().unwrap().to_string(),
            )
        })
        .collect()
}

/// `#cp-svg`'s data attribute `key` (`hovered`, `selected`), if set.
async fn overlay_data(c: &Client, key: &str) -> Option<String> {
    c.execute(
        "return document.getElementById('cp-svg').dataset[arguments[0]] ?? null",
        vec![json!(key)],
    )
    .await
    .unwrap()
    .as_str()
    .map(str::to_string)
}

/// The `#rrggbb` colour as numbers.
fn rgb(hex: &str) -> [u8; 3] {
    let n = u32::from_str_radix(hex.trim_start_matches('#'), 16).unwrap();
    [(n >> 16) as u8, (n >> 8) as u8, n as u8]
}

/// `SAMPLES` points spread over the middle 40% of the segment `a`–`b`.
fn middle_of(a: (f64, f64), b: (f64, f64)) -> Vec<(f64, f64)> {
    (0..SAMPLES)
        .map(|k| {
            let t = 0.3 + 0.4 * k as f64 / (SAMPLES - 1) as f64;
            (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1))
        })
        .collect()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_canvas_draws_the_creases_and_the_pointer_finds_the_servers_edge() {
    let dir = tempfile::tempdir().unwrap();
    let out = foldcam(&["generate", "miura", "-o", "miura.fold"], dir.path());
    assert!(out.status.success());
    let miura = dir.path().join("miura.fold");
    let server = Server::start(&[], dir.path());
    // What the server reports for the file: its edges, by index, and the line colours.
    let (status, view) = server.post_json(
        "/api/upload?name=miura.fold",
        &std::fs::read(&miura).unwrap(),
    );
    assert_eq!(status, 200, "{view}");
    let edges = edges_of(&view);
    let (_, legend) = server.get("/api/legend");
    let legend: Value = serde_json::from_slice(&legend).unwrap();
    let colour = |letter: &str| {
        let a = legend["assignments"]
            .as_array()
            .unwrap()
            .iter()
            .find(|a| a["letter"] == letter)
            .unwrap();
        rgb(a["colour"].as_str().unwrap())
    };

    let (_driver, c) = open_studio(&server.url()).await;
    open(&c, &miura).await;
    // The canvas drew every edge, each assignment's in its own path.
    assert_eq!(canvas_count(&c, "lines").await, edges.len());
    for letter in ["M", "V", "B", "F", "U", "C", "J"] {
        let n = edges.iter().filter(|e| e.2 == letter).count();
        let key = format!("lines{letter}");
        assert_eq!(canvas_count(&c, &key).await, n, "{letter} lines drawn");
    }
    let units_per_pixel = c
        .execute(
            "return document.getElementById('cp-canvas').patternView.unitsPerPixel()",
            vec![],
        )
        .await
        .unwrap()
        .as_f64()
        .unwrap();
    let clear = CLEAR_PIXELS * units_per_pixel;
    let off_every_line = |p: (f64, f64)| edges.iter().all(|e| distance(p, e.0, e.1) >= clear);

    // Lines checked: the first of each assignment present, and a spread of the others.
    let mut checked: Vec<usize> = ["M", "V", "B"]
        .iter()
        .map(|l| edges.iter().position(|e| e.2 == *l).expect("a line"))
        .collect();
    checked.extend((0..edges.len()).step_by(edges.len().div_ceil(9)));
    for &i in &checked {
        let (a, b, letter) = &edges[i];
        // On the line: ink in its colour along most of it (dashes leave gaps).
        let ink = pattern_ink(&c, &middle_of(*a, *b)).await;
        let inked = ink.iter().filter(|p| p[3] > 128).count();
        assert!(
            2 * inked >= SAMPLES,
            "edge {i} ({letter}): ink at {inked} of {SAMPLES} points: {ink:?}"
        );
        let strongest = ink.iter().max_by_key(|p| p[3]).unwrap();
        let want = colour(letter);
        assert!(
            (0..3).all(|k| strongest[k].abs_diff(want[k]) <= 48),
            "edge {i} ({letter}) drawn in {strongest:?}, not {want:?}"
        );
        // Beside the line's middle, on whichever side is clear of every line: no ink.
        let mid = ((a.0 + b.0) / 2.0, (a.1 + b.1) / 2.0);
        let len = (b.0 - a.0).hypot(b.1 - a.1);
        let normal = (-(b.1 - a.1) / len, (b.0 - a.0) / len);
        let beside: Vec<(f64, f64)> = [1.0, -1.0]
            .iter()
            .map(|s| {
                let d = s * 1.5 * clear;
                (mid.0 + d * normal.0, mid.1 + d * normal.1)
            })
            .filter(|&p| off_every_line(p))
            .collect();
        assert!(!beside.is_empty(), "edge {i}: no clear side to sample");
        for (p, ink) in beside.iter().zip(pattern_ink(&c, &beside).await) {
            assert_eq!(ink[3], 0, "edge {i}: ink off every line at {p:?}: {ink:?}");
        }

        // The pointer on the line's middle: the page names the server's edge i, and a
        // click selects it.
        let at = screen_in(&c, "cp-svg", mid.0, mid.1).await;
        pointer_move(&c, at).await;
        assert_eq!(overlay_data(&c, "hovered").await, Some(i.to_string()));
        let info = text(&c, "#hover-info").await;
        let length = format!("length {len:.2} mm");
        assert!(
            info.starts_with(&format!("edge {i}: ")) && info.contains(&format!("({letter})")),
            "{info}"
        );
        assert!(info.contains(&length), "{info}: not {length}");
        pointer_click(&c, at).await;
        assert_eq!(overlay_data(&c, "selected").await, Some(i.to_string()));
        let marked = c
            .execute(
                "return document.querySelector('#cp-selection line')?.dataset.edge ?? null",
                vec![],
            )
            .await
            .unwrap();
        assert_eq!(marked, json!(i.to_string()));
    }
    // Off every line, the pointer finds none.
    let (a, b, _) = &edges[checked[0]];
    let mid = ((a.0 + b.0) / 2.0, (a.1 + b.1) / 2.0);
    let len = (b.0 - a.0).hypot(b.1 - a.1);
    let away = [1.0, -1.0]
        .iter()
        .map(|s| {
            let d = s * 1.5 * clear / len;
            (mid.0 - d * (b.1 - a.1), mid.1 + d * (b.0 - a.0))
        })
        .find(|&p| off_every_line(p))
        .expect("a clear point");
    pointer_move(&c, screen_in(&c, "cp-svg", away.0, away.1).await).await;
    assert_eq!(overlay_data(&c, "hovered").await, None);

    // Dashes only while the median line is at least DASH_FROM_PIXELS on screen: zoomed out
    // until it is 12 px, the lines are solid (ink all along a valley).
    let mut lengths: Vec<f64> = edges
        .iter()
        .map(|(a, b, _)| (b.0 - a.0).hypot(b.1 - a.1))
        .collect();
    lengths.sort_by(f64::total_cmp);
    let median_px = lengths[lengths.len() / 2] / units_per_pixel;
    let dashed = || async {
        c.execute(
            "return document.getElementById('cp-canvas').dataset.dashed ?? null",
            vec![],
        )
        .await
        .unwrap()
    };
    assert_eq!(dashed().await, json!((median_px >= 33.0).to_string()));
    c.execute(
        "const v = document.getElementById('cp-canvas').patternView, k = arguments[0];
         const [x, y, w, h] = v.home;
         v.setBox([x - w * (k - 1) / 2, y - h * (k - 1) / 2, w * k, h * k]);",
        vec![json!(median_px / 12.0)],
    )
    .await
    .unwrap();
    let valley = edges.iter().position(|e| e.2 == "V").unwrap();
    let (a, b, _) = &edges[valley];
    let ink = pattern_ink(&c, &middle_of(*a, *b)).await;
    assert_eq!(dashed().await, json!("false"));
    assert!(ink.iter().all(|p| p[3] > 128), "a solid valley: {ink:?}");

    // Editing picks lines the same way: back home, the Assign tool makes the clicked mountain
    // a cut, and the canvas draws one cut line and one mountain fewer.
    c.execute(
        "const v = document.getElementById('cp-canvas').patternView; v.setBox(v.home);",
        vec![],
    )
    .await
    .unwrap();
    let mountains = canvas_count(&c, "linesM").await;
    assert_eq!(canvas_count(&c, "linesC").await, 0);
    click(&c, "#edit-tools button[data-tool='assign']").await;
    c.find(Locator::Css("#edit-assignment"))
        .await
        .unwrap()
        .select_by_value("C")
        .await
        .unwrap();
    let (a, b, _) = &edges[checked[0]];
    let at = screen_in(&c, "cp-svg", (a.0 + b.0) / 2.0, (a.1 + b.1) / 2.0).await;
    pointer_click(&c, at).await;
    wait_until(
        &c,
        "return document.body.dataset.edits === '1' && !document.body.dataset.busy",
        "the assignment",
    )
    .await;
    assert_eq!(canvas_count(&c, "linesC").await, 1);
    assert_eq!(canvas_count(&c, "linesM").await, mountains - 1);
    c.close().await.unwrap();
}

/// The page's `SegmentGrid` against a search of every segment, on random segments (short,
/// long, axis-parallel, of no length) and on a lattice whose lines share ends (ties), for
/// thousands of points in and around them and reaches from 0 to a few lines' lengths.
const GRID_CHECK: &str = r#"
const done = arguments[arguments.length - 1];
import(new URL('segments.js', location.href).href).then(({ SegmentGrid }) => {
  let seed = 12345;
  const random = () => { seed = (Math.imul(seed, 1103515245) + 12345) >>> 0; return seed / 4294967296; };
  const dist = (px, py, c, k) => {
    const [ax, ay, bx, by] = [c[4 * k], c[4 * k + 1], c[4 * k + 2], c[4 * k + 3]];
    const dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
    const t = l2 > 0 ? Math.min(1, Math.max(0, ((px - ax) * dx + (py - ay) * dy) / l2)) : 0;
    return Math.hypot(px - ax - t * dx, py - ay - t * dy);
  };
  const sets = [];
  const n = 4000, loose = new Float64Array(4 * n);
  for (let k = 0; k < n; k++) {
    const x = random() * 200, y = random() * 120, kind = random();
    const length = kind < 0.03 ? random() * 200 : kind < 0.06 ? 0 : random() * 4;
    const angle = kind < 0.2 ? 0 : kind < 0.3 ? Math.PI / 2 : random() * 2 * Math.PI;
    loose.set([x, y, x + length * Math.cos(angle), y + length * Math.sin(angle)], 4 * k);
  }
  sets.push(loose);
  const side = 60, lattice = [];
  for (let i = 0; i < side; i++) for (let j = 0; j < side; j++) {
    lattice.push(i, j, i + 1, j, i, j, i, j + 1, i, j, i + 1, j + 1);
  }
  sets.push(new Float64Array(lattice));
  let queries = 0, found = 0, wrong = [];
  for (const c of sets) {
    const grid = new SegmentGrid(c), count = c.length / 4;
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    for (let k = 0; k < c.length; k += 2) {
      x0 = Math.min(x0, c[k]); x1 = Math.max(x1, c[k]);
      y0 = Math.min(y0, c[k + 1]); y1 = Math.max(y1, c[k + 1]);
    }
    for (let q = 0; q < 3000; q++) {
      const onEnd = q % 5 === 0;
      const k0 = Math.floor(random() * count);
      const x = onEnd ? c[4 * k0] : x0 - 5 + random() * (x1 - x0 + 10);
      const y = onEnd ? c[4 * k0 + 1] : y0 - 5 + random() * (y1 - y0 + 10);
      const reach = q % 7 === 0 ? 0 : random() * random() * 8;
      let best = -1, bestD = reach;
      for (let k = 0; k < count; k++) {
        const d = dist(x, y, c, k);
        if (d < bestD || (d === bestD && (best < 0 || k < best))) { best = k; bestD = d; }
      }
      const got = grid.nearest(x, y, reach);
      queries += 1;
      if (best >= 0) found += 1;
      if (got !== best && wrong.length < 10) wrong.push({ x, y, reach, got, best });
    }
  }
  done({ queries, found, wrong });
}, (e) => done({ error: String(e) }));
"#;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_segment_grid_finds_what_a_search_of_every_segment_finds() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let (_driver, c) = open_studio(&server.url()).await;
    let result = c.execute_async(GRID_CHECK, vec![]).await.unwrap();
    assert!(result["error"].is_null(), "{result}");
    assert_eq!(result["queries"], 6000);
    // Both answers occur often: points near a line and points near none.
    let found = result["found"].as_u64().unwrap();
    assert!((1000..5000).contains(&found), "{result}");
    assert_eq!(
        result["wrong"],
        json!([]),
        "the grid differs from the search"
    );
    c.close().await.unwrap();
}
