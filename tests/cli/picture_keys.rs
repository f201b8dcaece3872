//! Every picture carries its key: the toolpath picture (whole bed, legend, scale bar, travel
//! and perforation in their own colours), the fold-step sheet (a caption per panel, one
//! scale), the check rings (sized to the picture, numbered as the report numbers them) and the
//! paper-craft sheet (edge numbers drawn dark). Each test runs the built program as a user
//! would and reads the PNG back.

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
    let all = 0..img.width();
    let blue = |p: &Rgba<u8>| p[2] > 180 && p[0] < 80 && p[1] < 120;
    let red = |p: &Rgba<u8>| p[0] > 180 && p[1] < 80 && p[2] < 80;
    assert!(
        count(&img, key.clone(), all.clone(), blue) > 20,
        "valley sample"
    );
    assert!(
        count(&img, key.clone(), all.clone(), red) > 20,
        "mountain sample"
    );
    assert!(count(&img, key, all, is_dark) > 300, "scale bar and labels");
}
