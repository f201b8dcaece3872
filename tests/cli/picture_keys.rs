//! Every picture carries its key: the toolpath picture (whole bed, legend, scale bar, travel
//! and perforation in their own colours, a title naming job file, machine and material), the
//! fold-step sheet (a caption per panel, one scale), the check rings (sized to the picture,
//! numbered as the report numbers them), the paper-craft sheet (edge numbers drawn dark and
//! upright), the 3D renders (caption, scale bar, colour samples; the strain picture's colour
//! scale) and every PNG and GIF the demo writes (a key band with a scale bar). Each test runs
//! the built program as a user would and reads the picture back.

use crate::bin;

use bin::{foldcam, repo_file};

use std::path::Path;
use std::process::Output;

use image::{Rgba, RgbaImage};

fn ok(o: &Output) {
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

fn example(rel: &str) -> String {
    repo_file(&format!("examples/{rel}"))
}

fn open(dir: &Path, name: &str) -> RgbaImage {
    image::open(dir.join(name)).expect("a PNG").to_rgba8()
}

fn near(p: &Rgba<u8>, c: [u8; 3], tol: u8) -> bool {
    (0..3).all(|i| p[i].abs_diff(c[i]) <= tol)
}

fn is_dark(p: &Rgba<u8>) -> bool {
    p[0] < 80 && p[1] < 80 && p[2] < 80
}

/// Pixels in rows `rows` and columns `cols` that satisfy `f`.
fn count(
    img: &RgbaImage,
    rows: std::ops::Range<u32>,
    cols: std::ops::Range<u32>,
    f: impl Fn(&Rgba<u8>) -> bool,
) -> usize {
    rows.flat_map(|y| cols.clone().map(move |x| (x, y)))
        .filter(|&(x, y)| f(img.get_pixel(x, y)))
        .count()
}

/// The key's mountain (red) and valley (blue) line samples: more than `min` pixels of each in
/// rows `rows`.
fn assert_line_samples(img: &RgbaImage, rows: std::ops::Range<u32>, min: usize) {
    let red = |p: &Rgba<u8>| p[0] > 180 && p[1] < 80 && p[2] < 80;
    let blue = |p: &Rgba<u8>| p[2] > 180 && p[0] < 80 && p[1] < 120;
    let all = 0..img.width();
    assert!(
        count(img, rows.clone(), all.clone(), red) > min,
        "mountain sample"
    );
    assert!(count(img, rows, all, blue) > min, "valley sample");
}

/// The longest run of pixels satisfying `f` in column `x`.
fn longest_col_run(img: &RgbaImage, x: u32, f: impl Fn(&Rgba<u8>) -> bool) -> u32 {
    let (mut best, mut run) = (0, 0);
    for y in 0..img.height() {
        run = if f(img.get_pixel(x, y)) { run + 1 } else { 0 };
        best = best.max(run);
    }
    best
}

/// The longest run of pixels satisfying `f` in row `y`.
fn longest_run(img: &RgbaImage, y: u32, f: impl Fn(&Rgba<u8>) -> bool) -> u32 {
    let (mut best, mut run) = (0, 0);
    for x in 0..img.width() {
        run = if f(img.get_pixel(x, y)) { run + 1 } else { 0 };
        best = best.max(run);
    }
    best
}

// LightBurn's palette, as the SVG and DXF layers use it (machines/README.md, post::style).
const CUT_RED: [u8; 3] = [255, 0, 0];
const PERFORATE_GREEN: [u8; 3] = [0, 224, 0];

#[test]
fn toolpath_shows_the_whole_bed_with_a_legend_and_a_scale_bar() {
    let dir = tempfile::tempdir().expect("temp dir");
    let d = dir.path();
    ok(&foldcam(
        &[
            "generate",
            "miura",
            "-o",
            "m.fold",
            "--columns",
            "12",
            "--rows",
            "8",
        ],
        d,
    ));
    ok(&foldcam(
        &[
            "cut",
            "m.fold",
            "-m",
            "grbl-diode",
            "-x",
            "card-300gsm",
            "-o",
            "m.gcode",
            "--valley",
            "perforate",
        ],
        d,
    ));
    ok(&foldcam(
        &[
            "simulate",
            "m.gcode",
            "-m",
            "grbl-diode",
            "--png",
            "p.png",
            "--width",
            "900",
        ],
        d,
    ));
    let img = open(d, "p.png");
    assert_eq!(img.width(), 900);
    // The bed outline: the rows and columns holding a grey line longer than half the image
    // are its edges; the box they make is square (grbl-diode: 400 × 400 mm) and lies wholly
    // inside the image, with white space on every side.
    let grey = |p: &Rgba<u8>| {
        p[0].abs_diff(p[1]) < 8 && p[1].abs_diff(p[2]) < 8 && (80..235).contains(&p[0])
    };
    let half = img.width() / 2;
    let rows: Vec<u32> = (0..img.height())
        .filter(|&y| longest_run(&img, y, grey) > half)
        .collect();
    let cols: Vec<u32> = (0..img.width())
        .filter(|&x| longest_col_run(&img, x, grey) > half)
        .collect();
    let (y0, bed_bottom) = (
        *rows.first().expect("bed top"),
        *rows.last().expect("bed bottom"),
    );
    let (x0, x1) = (
        *cols.first().expect("bed left"),
        *cols.last().expect("bed right"),
    );
    assert!(
        x0 > 5 && y0 > 5 && x1 < 894,
        "bed box {x0}..{x1} × {y0}..{bed_bottom}"
    );
    assert!(
        (x1 - x0).abs_diff(bed_bottom - y0) <= 3,
        "square bed drawn {} × {}",
        x1 - x0,
        bed_bottom - y0
    );
    // Under the bed: the key. Perforation green and cut red appear there as legend samples,
    // travel orange too, and text.
    let key = bed_bottom + 3..img.height();
    assert!(key.len() > 20, "a key band under the bed");
    let all = 0..img.width();
    let in_key = |c: [u8; 3]| count(&img, key.clone(), all.clone(), |p| near(p, c, 10));
    assert!(in_key(CUT_RED) > 20, "cut sample in the key");
    assert!(
        in_key(PERFORATE_GREEN) > 20,
        "perforation sample in the key"
    );
    let orange = |p: &Rgba<u8>| p[0] > 240 && p[1] > 150 && p[1] < 215 && p[2] < 140;
    assert!(
        count(&img, key.clone(), all.clone(), orange) > 5,
        "travel sample"
    );
    assert!(
        count(&img, key.clone(), all.clone(), is_dark) > 200,
        "labels"
    );
    // On the bed: perforations green, the outline cut red — two different colours.
    let bed = y0 + 2..bed_bottom - 2;
    let inside = x0 + 2..x1 - 2;
    assert!(
        count(&img, bed.clone(), inside.clone(), |p| near(
            p,
            PERFORATE_GREEN,
            10
        )) > 200
    );
    assert!(count(&img, bed, inside, |p| near(p, CUT_RED, 10)) > 200);
    // The scale bar: the longest dark run in the key is a round number of millimetres at the
    // bed's scale (its width in pixels over 400 mm).
    let scale = f64::from(x1 - x0) / 400.0;
    let bar = key
        .map(|y| longest_run(&img, y, is_dark))
        .max()
        .unwrap_or(0);
    let mm = f64::from(bar) / scale;
    let round = [10.0, 20.0, 50.0, 100.0, 200.0];
    assert!(
        round.iter().any(|r| (mm - r).abs() < 2.0 / scale + 0.5),
        "bar of {bar} px = {mm:.1} mm"
    );
}

#[test]
fn a_small_job_on_a_large_bed_is_drawn_on_the_bed_corner() {
    let dir = tempfile::tempdir().expect("temp dir");
    let d = dir.path();
    ok(&foldcam(&["generate", "miura", "-o", "m.fold"], d));
    ok(&foldcam(
        &[
            "cut",
            "m.fold",
            "-m",
            "linuxcnc-fiber",
            "-x",
            "stainless-0.5",
            "-o",
            "m.ngc",
        ],
        d,
    ));
    let args = [
        "simulate",
        "m.ngc",
        "-m",
        "linuxcnc-fiber",
        "--png",
        "p.png",
    ];
    ok(&foldcam(&args, d));
    let img = open(d, "p.png");
    // The perforations take a visible share of the picture, not a speck on a 1.5 × 3 m bed.
    let all = count(&img, 0..img.height(), 0..img.width(), |p| {
        near(p, PERFORATE_GREEN, 10)
    });
    assert!(all > 3000, "{all} perforation pixels");
}

#[test]
fn fold_steps_have_captions_and_one_scale() {
    let dir = tempfile::tempdir().expect("temp dir");
    let d = dir.path();
    let script = example("folding/bird-base.toml");
    let o = foldcam(
        &[
            "fold", &script, "-o", "b.fold", "--png", "s.png", "--width", "300",
        ],
        d,
    );
    ok(&o);
    let img = open(d, "s.png");
    // Ten pictures (the flat sheet and nine steps) in rows of four.
    assert_eq!(img.width(), 4 * 300);
    let panel_h = img.height() / 3;
    assert!(panel_h > 300 + 20, "a caption band under each panel");
    let white = |p: &Rgba<u8>| p[0] > 245 && p[1] > 245 && p[2] > 245;
    for i in 0..12u32 {
        let (x, y) = ((i % 4) * 300, (i / 4) * panel_h);
        let caption = count(&img, y + 300..y + panel_h, x + 2..x + 298, is_dark);
        if i < 10 {
            assert!(
                caption > 100,
                "panel {i} has a caption ({caption} dark pixels)"
            );
        } else {
            assert_eq!(caption, 0, "slot {i} is empty");
        }
    }
    // One scale: the folded bird base (last panel) covers much less than the flat square
    // (first panel); panels framed one by one would both fill their square.
    let drawn = |i: u32| {
        let (x, y) = ((i % 4) * 300, (i / 4) * panel_h);
        count(&img, y + 2..y + 298, x + 2..x + 298, |p| !white(p))
    };
    let (first, last) = (drawn(0), drawn(9));
    assert!(
        (last as f64) < 0.6 * first as f64,
        "flat sheet {first} px, folded base {last} px"
    );
}

#[test]
fn check_rings_are_large_numbered_and_match_the_report() {
    let dir = tempfile::tempdir().expect("temp dir");
    let d = dir.path();
    let input = example("patterns/broken-vertex.fold");
    let o = foldcam(
        &[
            "preview", &input, "-o", "b.png", "--width", "900", "--check",
        ],
        d,
    );
    assert_eq!(o.status.code(), Some(1), "a failed check exits 1");
    let err = String::from_utf8_lossy(&o.stderr);
    let report = String::from_utf8_lossy(&foldcam(&["check", &input], d).stdout).into_owned();
    // The same numbered findings in `preview --check` and in `check`'s report.
    for n in ["#1 ", "#2 "] {
        assert!(err.contains(n), "preview lists {n}: {err}");
        let line = |text: &str| {
            text.lines()
                .find(|l| l.contains(n))
                .map(str::trim)
                .map(String::from)
        };
        assert_eq!(line(&err), line(&report), "finding {n}");
    }
    let img = open(d, "b.png");
    let orange = |p: &Rgba<u8>| p[0] > 230 && p[1] > 110 && p[1] < 200 && p[2] < 110;
    // The drawing ends at the outline's bottom edge; the key (with its ring sample) is below.
    let bottom = (0..img.height())
        .filter(|&y| longest_run(&img, y, is_dark) > 600)
        .max()
        .expect("outline");
    // Both findings sit at one vertex: one ring, at least 1/15 of the width across.
    let ring: Vec<(u32, u32)> = img
        .enumerate_pixels()
        .filter(|&(_, y, p)| y < bottom && orange(p))
        .map(|(x, y, _)| (x, y))
        .collect();
    let span = |f: fn(&(u32, u32)) -> u32| {
        ring.iter().map(f).max().unwrap_or(0) - ring.iter().map(f).min().unwrap_or(0)
    };
    assert!(span(|p| p.0) >= 900 / 15, "ring {} px wide", span(|p| p.0));
    // Its label "1,2" is dark text on a white tab at the ring's upper right.
    let (cx, cy) = (
        ring.iter().map(|p| p.0).sum::<u32>() / ring.len() as u32,
        ring.iter().map(|p| p.1).sum::<u32>() / ring.len() as u32,
    );
    let label = count(
        &img,
        cy.saturating_sub(80)..cy,
        cx..(cx + 120).min(900),
        is_dark,
    );
    assert!(label > 30, "ring number drawn ({label} dark pixels)");
}

#[test]
fn paper_craft_edge_numbers_are_dark() {
    let dir = tempfile::tempdir().expect("temp dir");
    let d = dir.path();
    let design = example("papercraft/vase.craft.toml");
    ok(&foldcam(
        &[
            "papercraft",
            &design,
            "-o",
            "v.fold",
            "--png",
            "v.png",
            "--width",
            "1200",
        ],
        d,
    ));
    let img = open(d, "v.png");
    // Flat lines used to be drawn thin and light grey (190, 190, 190), adding no dark pixels;
    // drawn in ink they do.
    // Remove the labels (flat lines) from the sheet: fewer dark pixels.
    let text = std::fs::read_to_string(d.join("v.fold")).expect("sheet");
    let mut json: serde_json::Value = serde_json::from_str(&text).expect("FOLD");
    let assignments = json["edges_assignment"]
        .as_array_mut()
        .expect("assignments");
    let flats = assignments
        .iter()
        .filter(|a| a.as_str() == Some("F"))
        .count();
    assert!(flats > 50, "the sheet has label strokes");
    let keep: Vec<bool> = assignments
        .iter()
        .map(|a| a.as_str() != Some("F"))
        .collect();
    let obj = json.as_object_mut().expect("a FOLD object");
    obj.retain(|key, _| !key.starts_with("faces_") && !key.starts_with("foldcam:"));
    for (key, value) in obj.iter_mut() {
        if let (true, Some(list)) = (key.starts_with("edges_"), value.as_array_mut()) {
            let mut k = keep.iter();
            list.retain(|_| *k.next().unwrap_or(&true));
        }
    }
    std::fs::write(d.join("bare.fold"), json.to_string()).expect("write");
    ok(&foldcam(
        &["preview", "bare.fold", "-o", "bare.png", "--width", "1200"],
        d,
    ));
    let bare = open(d, "bare.png");
    let dark = |img: &RgbaImage| count(img, 0..img.height() * 3 / 4, 0..img.width(), is_dark);
    assert!(
        dark(&img) > dark(&bare) + 1000,
        "labels add dark pixels: {} vs {}",
        dark(&img),
        dark(&bare)
    );
}

#[test]
fn pattern_preview_has_a_legend_of_the_lines_drawn() {
    let dir = tempfile::tempdir().expect("temp dir");
    let d = dir.path();
    ok(&foldcam(&["generate", "miura", "-o", "m.fold"], d));
    ok(&foldcam(
        &["preview", "m.fold", "-o", "m.png", "--width", "900"],
        d,
    ));
    let img = open(d, "m.png");
    // The drawing's lowest black row (the outline's bottom edge); the key is under it.
    let bottom = (0..img.height())
        .filter(|&y| longest_run(&img, y, is_dark) > 400)
        .max()
        .expect("outline");
    let key = bottom + 4..img.height();
    assert_line_samples(&img, key.clone(), 20);
    assert!(
        count(&img, key, 0..img.width(), is_dark) > 300,
        "scale bar and labels"
    );
}

/// The scale bar of a key band: a dark horizontal run (the bar's foot) with a dark tick
/// rising at each end, a clear row just above the ticks (the band is apart from the
/// drawing) and dark label pixels right of the bar. Searched from the bottom up; returns
/// `(top of the ticks, row of the foot, bar length in pixels)`.
fn key_scale_bar(img: &RgbaImage) -> Option<(u32, u32, u32)> {
    let (w, h) = img.dimensions();
    let dark = |x: u32, y: u32| is_dark(img.get_pixel(x, y));
    let rise = |x: u32, y: u32| (0..=y).rev().take_while(|&yy| dark(x, yy)).count() as u32;
    for y in (h / 3..h).rev() {
        let mut x = 0;
        while x < w {
            if !dark(x, y) {
                x += 1;
                continue;
            }
            let x0 = x;
            while x < w && dark(x, y) {
                x += 1;
            }
            let len = x - x0;
            if len < (w / 60).max(12) {
                continue;
            }
            let (left, right) = (rise(x0, y), rise(x - 1, y));
            if !(5..=40).contains(&left) || left.abs_diff(right) > 1 {
                continue;
            }
            let top = y + 1 - left;
            let lo = x0.saturating_sub(3);
            let hi = (x + 3).min(w);
            let clear_above = top > 0 && (lo..hi).all(|xx| !dark(xx, top - 1));
            let label = count(img, top..y + 1, x..(x + 12 * left).min(w), is_dark);
            if clear_above && label > 10 {
                return Some((top, y, len));
            }
        }
    }
    None
}

#[test]
fn every_picture_the_demo_writes_carries_a_key_band() {
    let dir = tempfile::tempdir().expect("temp dir");
    let d = dir.path();
    ok(&foldcam(&["demo", "--out", "demo"], d));
    let out = d.join("demo");
    let mut names: Vec<String> = std::fs::read_dir(&out)
        .expect("listing")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".png") || n.ends_with(".gif"))
        .collect();
    names.sort();
    assert!(names.len() >= 20, "{names:?}");
    let mut missing = Vec::new();
    for name in &names {
        // A GIF: its first frame.
        let img = if name.ends_with(".gif") {
            use image::AnimationDecoder;
            let file = std::io::BufReader::new(std::fs::File::open(out.join(name)).expect("gif"));
            let decoder = image::codecs::gif::GifDecoder::new(file).expect("a GIF");
            let frame = decoder
                .into_frames()
                .next()
                .expect("a frame")
                .expect("decodes");
            frame.into_buffer()
        } else {
            open(&out, name)
        };
        match key_scale_bar(&img) {
            Some((top, foot, len)) => {
                // The bar is a readable length, and the band has text.
                let w = img.width();
                assert!(len >= w / 50 && len <= w / 2, "{name}: bar of {len} px");
                let band = count(&img, top..img.height(), 0..w, is_dark);
                assert!(band > 150, "{name}: {band} dark pixels in the key band");
                assert!(foot > img.height() / 3, "{name}");
            }
            None => missing.push(name.clone()),
        }
    }
    assert!(
        missing.is_empty(),
        "no key band with a scale bar: {missing:?}"
    );
}

#[test]
fn a_3d_render_keys_its_colours_and_captions_the_view() {
    let dir = tempfile::tempdir().expect("temp dir");
    let d = dir.path();
    let card = example("popup/house.voxel.txt");
    let o = foldcam(
        &["popup", "voxel", &card, "-o", "h.fold", "--png", "h.png"],
        d,
    );
    ok(&o);
    let img = open(d, "h.png");
    let (top, _, _) = key_scale_bar(&img).expect("a key band with a scale bar");
    let band = top..img.height();
    let all = 0..img.width();
    // Samples of the paper's front and back tints (View3d's defaults) and of the mountain
    // and valley lines, all in the band.
    assert_line_samples(&img, band.clone(), 10);
    let tinted = |c: [u8; 3]| {
        count(&img, band.clone(), all.clone(), |p| {
            (0..3).all(|i| p[i] <= c[i] && u16::from(p[i]) + 90 >= u16::from(c[i])) && !is_dark(p)
        })
    };
    assert!(tinted([246, 236, 208]) > 40, "front side sample");
    assert!(tinted([176, 204, 236]) > 40, "back side sample");
    let png = std::fs::read(d.join("h.png")).expect("png");
    let text = String::from_utf8_lossy(&png);
    assert!(
        text.contains("opened to 90"),
        "the caption in the PNG's text"
    );
}

#[test]
fn toolpath_picture_is_titled_with_its_file_machine_and_material() {
    let dir = tempfile::tempdir().expect("temp dir");
    let d = dir.path();
    ok(&foldcam(&["generate", "miura", "-o", "m.fold"], d));
    let cut = [
        "cut",
        "m.fold",
        "-m",
        "grbl-diode",
        "-x",
        "card-300gsm",
        "-o",
        "m.gcode",
    ];
    ok(&foldcam(&cut, d));
    let sim = [
        "simulate",
        "m.gcode",
        "-m",
        "grbl-diode",
        "-x",
        "card-300gsm",
        "--png",
        "p.png",
        "--width",
        "900",
    ];
    ok(&foldcam(&sim, d));
    let img = open(d, "p.png");
    // The bed's top edge: the first row holding a long grey line.
    let grey = |p: &Rgba<u8>| {
        p[0].abs_diff(p[1]) < 8 && p[1].abs_diff(p[2]) < 8 && (80..235).contains(&p[0])
    };
    let bed_top = (0..img.height())
        .find(|&y| longest_run(&img, y, grey) > img.width() / 2)
        .expect("bed");
    let title = count(&img, 0..bed_top, 0..img.width(), is_dark);
    assert!(title > 300, "a title above the bed ({title} dark pixels)");
    let png = std::fs::read(d.join("p.png")).expect("png");
    let text = String::from_utf8_lossy(&png);
    for name in ["m.gcode", "grbl-diode", "card-300gsm"] {
        assert!(text.contains(name), "the title names {name}");
    }
}

#[test]
fn fold3d_strain_picture_has_a_colour_scale() {
    let dir = tempfile::tempdir().expect("temp dir");
    let d = dir.path();
    ok(&foldcam(&["generate", "miura", "-o", "m.fold"], d));
    let args = [
        "fold3d",
        "m.fold",
        "-o",
        "f.fold",
        "--png",
        "f.png",
        "--strain",
        "--percent",
        "60",
    ];
    let o = foldcam(&args, d);
    assert!(o.status.code().is_some_and(|c| c <= 1), "{o:?}");
    let img = open(d, "f.png");
    let (top, _, _) = key_scale_bar(&img).expect("a key band");
    // In one row of the band: the scale's low blue, its green middle and its top red
    // (render::heat_color), left to right.
    let found = (top..img.height()).any(|y| {
        let at = |c: [u8; 3]| (0..img.width()).find(|&x| near(img.get_pixel(x, y), c, 12));
        match (at([49, 54, 149]), at([102, 189, 99]), at([215, 48, 39])) {
            (Some(lo), Some(mid), Some(hi)) => lo < mid && mid < hi && hi - lo >= 40,
            _ => false,
        }
    });
    assert!(found, "a blue-green-red gradient in the key band");
}

/// Flat edges of a FOLD file grouped into connected strokes (one digit each), as point pairs.
fn digit_strokes(fold: &serde_json::Value) -> Vec<Vec<[[f64; 2]; 2]>> {
    let coords: Vec<[f64; 2]> = fold["vertices_coords"]
        .as_array()
        .expect("coords")
        .iter()
        .map(|c| [c[0].as_f64().unwrap_or(0.0), c[1].as_f64().unwrap_or(0.0)])
        .collect();
    let flats: Vec<[usize; 2]> = fold["edges_vertices"]
        .as_array()
        .expect("edges")
        .iter()
        .zip(fold["edges_assignment"].as_array().expect("assignments"))
        .filter(|(_, a)| a.as_str() == Some("F"))
        .map(|(e, _)| [0, 1].map(|i| e[i].as_u64().unwrap_or(0) as usize))
        .collect();
    // Union-find over vertices.
    let mut parent: Vec<usize> = (0..coords.len()).collect();
    fn root(p: &mut [usize], mut i: usize) -> usize {
        while p[i] != i {
            p[i] = p[p[i]];
            i = p[i];
        }
        i
    }
    for &[a, b] in &flats {
        let (ra, rb) = (root(&mut parent, a), root(&mut parent, b));
        parent[ra] = rb;
    }
    let mut groups: std::collections::BTreeMap<usize, Vec<[[f64; 2]; 2]>> = Default::default();
    for &[a, b] in &flats {
        let r = root(&mut parent, a);
        groups.entry(r).or_default().push([coords[a], coords[b]]);
    }
    groups.into_values().collect()
}

/// Reads a seven-segment digit drawn upright (y up): `None` if its strokes are not one.
fn read_digit(strokes: &[[[f64; 2]; 2]]) -> Option<u32> {
    let xs = strokes.iter().flat_map(|s| [s[0][0], s[1][0]]);
    let ys = strokes.iter().flat_map(|s| [s[0][1], s[1][1]]);
    let (x0, x1) = xs.fold((f64::MAX, f64::MIN), |(a, b), x| (a.min(x), b.max(x)));
    let (y0, y1) = ys.fold((f64::MAX, f64::MIN), |(a, b), y| (a.min(y), b.max(y)));
    let h = y1 - y0;
    let tol = 0.1 * h;
    if h <= 0.0 || x1 - x0 > 0.7 * h {
        return None; // wider than a digit: turned or mirrored across
    }
    if x1 - x0 < tol {
        return Some(1);
    }
    let mut lit = 0u8;
    for s in strokes {
        let ([ax, ay], [bx, by]) = (s[0], s[1]);
        let (mx, my) = (0.5 * (ax + bx), 0.5 * (ay + by));
        let bit = if (ay - by).abs() < tol {
            // Horizontal: top a, middle g, bottom d.
            match my {
                _ if (my - y1).abs() < tol => 0,
                _ if (my - y0).abs() < tol => 3,
                _ => 6,
            }
        } else {
            let upper = my > 0.5 * (y0 + y1);
            match ((mx - x1).abs() < tol, upper) {
                (true, true) => 1,
                (true, false) => 2,
                (false, false) => 4,
                (false, true) => 5,
            }
        };
        lit |= 1 << bit;
    }
    const DIGITS: [u8; 10] = [
        0b011_1111, 0b000_0110, 0b101_1011, 0b100_1111, 0b110_0110, 0b110_1101, 0b111_1101,
        0b000_0111, 0b111_1111, 0b110_1111,
    ];
    DIGITS.iter().position(|&d| d == lit).map(|i| i as u32)
}

#[test]
fn paper_craft_edge_numbers_read_upright() {
    let dir = tempfile::tempdir().expect("temp dir");
    let d = dir.path();
    let design = example("papercraft/vase.craft.toml");
    ok(&foldcam(&["papercraft", &design, "-o", "v.fold"], d));
    let text = std::fs::read_to_string(d.join("v.fold")).expect("sheet");
    let json: serde_json::Value = serde_json::from_str(&text).expect("FOLD");
    let digits = digit_strokes(&json);
    assert!(digits.len() >= 16, "{} digits", digits.len());
    // Every digit reads as one, upright on the sheet (not turned a quarter or half turn, not
    // mirrored), and the vase's eight cut lines 0 to 7 are each numbered on both their parts.
    let mut read: Vec<u32> = digits
        .iter()
        .map(|s| read_digit(s).unwrap_or_else(|| panic!("not an upright digit: {s:?}")))
        .collect();
    read.sort_unstable();
    let expected: Vec<u32> = (0..8).flat_map(|i| [i, i]).collect();
    assert_eq!(read, expected);
    // The fish: small parts and two-digit numbers; every digit still reads upright.
    let design = example("papercraft/fish.craft.toml");
    ok(&foldcam(&["papercraft", &design, "-o", "f.fold"], d));
    let text = std::fs::read_to_string(d.join("f.fold")).expect("sheet");
    let json: serde_json::Value = serde_json::from_str(&text).expect("FOLD");
    let digits = digit_strokes(&json);
    assert!(digits.len() >= 36, "{} digits", digits.len());
    for s in &digits {
        assert!(read_digit(s).is_some(), "not an upright digit: {s:?}");
    }
}
