//! The paper-craft editor (Ōgaki 2016) in a real browser (headless Chromium, see
//! `common/browser.rs`): on the vase example a meridian cut line is removed, then drawn again
//! by clicking points on the 3D mesh; the regions close again and the saved design, run
//! through `foldcam papercraft`, gives the parts the page shows.
//!
//! The README's picture: `FOLDCAM_SCREENSHOTS=docs cargo test --test browser studio_browser_craft`.

use crate::bin;
use crate::browser;
use crate::studio;

use bin::{foldcam, repo_file};
use browser::{click, keep_screenshot, link_href, open_studio, pointer_click, wait_until};
use serde_json::{Value, json};
use studio::Server;

/// The page's sheet coordinates and the CLI's agree this closely, millimetres (the page
/// draws `height − y`, one rounding).
const COORD_TOLERANCE: f64 = 1e-6;

async fn dataset(c: &fantoccini::Client, key: &str) -> String {
    let v = c
        .execute(
            &format!("return document.getElementById('view-craft').dataset.{key} ?? ''"),
            vec![],
        )
        .await
        .unwrap();
    v.as_str().unwrap_or_default().to_string()
}

/// The example's meridian 1 (foot to rim), read from the example file itself.
fn meridian_one() -> Vec<[f64; 3]> {
    let text = std::fs::read_to_string(repo_file("examples/papercraft/vase.craft.toml")).unwrap();
    let design: toml::Value = toml::from_str(&text).unwrap();
    (design["cut_lines"][1]["points"].as_array().unwrap().iter())
        .map(|p| {
            let a = p.as_array().unwrap();
            [0, 1, 2].map(|i| a[i].as_float().unwrap())
        })
        .collect()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn clicking_a_cut_line_on_the_mesh_gives_the_parts_the_cli_makes() {
    let dir = tempfile::tempdir().unwrap();
    let server = Server::start(&[], dir.path());
    let (_driver, c) = open_studio(&server.url()).await;

    // The tab opens the first example, the vase: 24 cut lines, eight gores, eight parts.
    click(&c, "#tabs button[data-view='craft']").await;
    wait_until(
        &c,
        "return document.getElementById('view-craft').dataset.parts === '8' \
         && !document.body.dataset.busy",
        "the vase's parts",
    )
    .await;

    // Lines that close no region get a hint saying what makes one (the page's own view,
    // with its regions taken away and two lines left loose).
    let hint = c
        .execute(
            "const saved = craftView.view; \
             craftView.show({ ...saved, regions: [], parts: [], unglued: [], \
               paint: saved.paint.map(() => -1), \
               lines: saved.lines.map((l, i) => ({ ...l, open: i < 2 })) }); \
             const shown = document.getElementById('craft-hint').textContent; \
             craftView.show(saved); \
             return [shown, document.getElementById('craft-hint').textContent];",
            vec![],
        )
        .await
        .unwrap();
    let shown = hint[0].as_str().unwrap();
    assert!(
        shown.starts_with("No region yet") && shown.contains("2 line(s) have a loose end"),
        "{shown}"
    );
    assert_eq!(hint[1], json!(""), "no hint once the lines close regions");

    // Remove meridian 1 with its button: gores 0 and 1 become one region.
    click(&c, "#craft-lines button[data-line='1']").await;
    wait_until(
        &c,
        "return document.getElementById('view-craft').dataset.lines === '23' \
         && !document.body.dataset.busy",
        "the line to go",
    )
    .await;
    assert_eq!(
        c.find_all(fantoccini::Locator::Css("#craft-regions li"))
            .await
            .unwrap()
            .len(),
        7
    );

    // Turn the vase so that meridian 1 (azimuth 45°) faces the eye, seen from the side (from
    // above or below, the bulge would hide the foot or the rim).
    c.execute(
        "craftView.model.rotation.set(-Math.PI / 2, 0, -3 * Math.PI / 4); craftView.draw(); return true",
        vec![],
    )
    .await
    .unwrap();
    // Click near its six points on the mesh (real pointer clicks, picked by raycasting): a
    // hand never lands on the exact point, and an exact mesh vertex on the open foot or rim
    // is where a ray may slip past both triangles. So each point is turned by half a degree
    // about the axis and the ends moved 2 % of the way inside; the snapping must bring the
    // ends back onto the foot and rim vertices.
    let points = meridian_one();
    let last = points.len() - 1;
    for (i, p) in points.iter().enumerate() {
        let inward = match i {
            0 => points[1],
            i if i == last => points[last - 1],
            _ => *p,
        };
        let q: Vec<f64> = (0..3).map(|k| p[k] + 0.02 * (inward[k] - p[k])).collect();
        let (sin, cos) = 0.5f64.to_radians().sin_cos();
        let p = [q[0] * cos - q[1] * sin, q[0] * sin + q[1] * cos, q[2]];
        let at = c
            .execute("return craftView.screenOf(arguments[0])", vec![json!(p)])
            .await
            .unwrap();
        let at = at
            .as_array()
            .unwrap_or_else(|| panic!("point {p:?} is hidden from the eye"));
        pointer_click(&c, (at[0].as_f64().unwrap(), at[1].as_f64().unwrap())).await;
    }
    let clicked = c
        .execute("return craftView.clicked.length", vec![])
        .await
        .unwrap();
    assert_eq!(clicked, json!(6), "every click hit the mesh");
    click(&c, "#craft-finish").await;
    wait_until(
        &c,
        "return document.getElementById('view-craft').dataset.lines === '24' \
         && !document.body.dataset.busy",
        "the new cut line",
    )
    .await;
    // The ends snapped onto the foot and rim vertices: the two gores close again and get
    // fitted patches, without a fault.
    assert_eq!(dataset(&c, "parts").await, "8");
    assert_eq!(dataset(&c, "faults").await, "0");
    let regions = c
        .find_all(fantoccini::Locator::Css("#craft-regions li:not(.unglued)"))
        .await
        .unwrap();
    assert_eq!(regions.len(), 8);
    // The meridian drawn by hand runs across the mesh's triangles (half a degree off the
    // mesh's own edges): the triangles it divides are drawn as the server's pieces, each in
    // its region's colour, so the colours meet along the line and not along triangle edges.
    let painted = c
        .execute(
            "const v = craftView.view, g = craftView.surface.geometry; \
             const divided = new Set(v.pieces.triangles); \
             const kept = v.paint.length - divided.size; \
             const colour = g.getAttribute('color'); \
             const C = craftView.surface.material.color.constructor; \
             const wrong = v.pieces.regions.filter((r, i) => { \
               const want = new C(); want.setHex(r < 0 ? 0 : craftView.regionColour(r)); \
               const k = 3 * (kept + i); \
               return r >= 0 && Math.abs(colour.getX(k) - want.r) + Math.abs(colour.getY(k) - want.g) \
                 + Math.abs(colour.getZ(k) - want.b) > 1e-6; }).length; \
             const normal = g.getAttribute('normal'); let unlit = 0; \
             for (let i = 0; i < g.getAttribute('position').count; i += 1) { \
               if (Math.hypot(normal.getX(i), normal.getY(i), normal.getZ(i)) < 0.5) unlit += 1; } \
             return [v.pieces.regions.length, new Set(v.pieces.regions).size, \
               g.getAttribute('position').count, 3 * (kept + v.pieces.regions.length), wrong, \
               normal.count, unlit];",
            vec![],
        )
        .await
        .unwrap();
    let n = |k: usize| painted[k].as_u64().unwrap();
    assert!(n(0) > 0, "no triangle drawn in pieces: {painted}");
    assert!(n(1) >= 2, "the pieces lie in one region only: {painted}");
    assert_eq!(
        n(2),
        n(3),
        "the surface is the whole triangles and the pieces: {painted}"
    );
    assert_eq!(n(4), 0, "pieces in another region's colour: {painted}");
    // Every corner has a normal (the pieces were drawn dark, unlit, when the normals of the
    // previous, shorter surface were refilled).
    assert_eq!(n(5), n(2), "normals for every corner: {painted}");
    assert_eq!(n(6), 0, "corners without a normal: {painted}");
    // Glued cut lines whose two sides differ are listed under the regions, by number.
    let unglued: Vec<String> = {
        let items = c
            .find_all(fantoccini::Locator::Css("#craft-regions li.unglued"))
            .await
            .unwrap();
        let mut texts = Vec::new();
        for item in items {
            texts.push(item.text().await.unwrap());
        }
        texts
    };
    c.execute(
        "document.getElementById('craft-side').scrollTop = 0; return true",
        vec![],
    )
    .await
    .unwrap();
    keep_screenshot(&c, "studio-craft.png").await;

    // "Save design" and "Save mesh" are what the CLI builds.
    let design = link_href(&c, "#craft-save").await;
    let mesh = link_href(&c, "#craft-save-mesh").await;
    let (status, design) = server.get(&design);
    assert_eq!(status, 200);
    let (status, mesh) = server.get(&mesh);
    assert_eq!(status, 200);
    std::fs::write(dir.path().join("saved.craft.toml"), design).unwrap();
    std::fs::write(dir.path().join("vase.obj"), mesh).unwrap();
    let out = foldcam(
        &["papercraft", "saved.craft.toml", "-o", "cli.fold"],
        dir.path(),
    );
    // The CLI names the same cut lines the page lists, and exits 1 for them.
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(
        out.status.code(),
        Some(if unglued.is_empty() { 0 } else { 1 }),
        "{stderr}"
    );
    assert_eq!(
        stderr.matches("the glued edges do not match").count(),
        unglued.len(),
        "{stderr}"
    );
    for item in &unglued {
        let line = item.split(':').next().expect("cut line N: …").to_string();
        assert!(stderr.contains(&format!("{line}:")), "{item} in {stderr}");
    }
    let cli: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("cli.fold")).unwrap())
            .unwrap();
    let coords: Vec<[f64; 2]> = (cli["vertices_coords"].as_array().unwrap().iter())
        .map(|c| [c[0].as_f64().unwrap(), c[1].as_f64().unwrap()])
        .collect();
    // Every corner of every part the page draws on sheet 1 is a vertex of the CLI's sheet.
    let drawn = c
        .execute(
            "const h = craftView.view.sheet[1];
             return [...document.querySelectorAll('#craft-parts g[data-sheet=\"0\"] polygon.craft-part')]
               .map((p) => p.getAttribute('points').trim().split(' ')
                 .map((xy) => { const [x, y] = xy.split(',').map(Number); return [x, h - y]; }));",
            vec![],
        )
        .await
        .unwrap();
    let drawn = drawn.as_array().unwrap();
    assert!(!drawn.is_empty());
    for part in drawn {
        for p in part.as_array().unwrap() {
            let (x, y) = (p[0].as_f64().unwrap(), p[1].as_f64().unwrap());
            assert!(
                coords
                    .iter()
                    .any(|q| (q[0] - x).abs() <= COORD_TOLERANCE
                        && (q[1] - y).abs() <= COORD_TOLERANCE),
                "corner ({x}, {y}) drawn in the page is not in the CLI's sheet"
            );
        }
    }
    let printed =
        String::from_utf8_lossy(&out.stdout).to_string() + &String::from_utf8_lossy(&out.stderr);
    assert!(printed.contains("8 parts"), "{printed}");

    // "To crease pattern" opens the sheet as a document in the pattern view.
    click(&c, "#craft-pattern").await;
    wait_until(
        &c,
        "return document.body.dataset.doc !== undefined && !document.body.dataset.busy \
         && !document.getElementById('view-pattern').hidden",
        "the parts as a document",
    )
    .await;
    c.close().await.unwrap();
}
