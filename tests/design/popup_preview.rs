//! The preview of a pop-up card is drawn as seen from the front of the open card: what the
//! design has on its left (x from 0 at the card's left edge, as the pattern and the README
//! have it) is on the picture's left. Checked by reading the PNGs `foldcam popup voxel --png`
//! and `foldcam popup poly --png` write.

use foldcam::design::popup::as_held;
use foldcam::design::popup::voxel::{crease_pattern, fold_card, parse_voxel_card};
use foldcam::render::{View3d, render_folded_png};

use crate::bin::foldcam;

/// A card 16 columns wide with one block, 4 cells deep and 8 high, on columns 1–4: the
/// design's left quarter.
const LEFT_BLOCK: &str = "cell_mm 5\ndepth 6\nheight 12\nmargin_mm 5\nrows\n\
0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n\
0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n\
0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n\
0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n\
0 4 4 4 4 0 0 0 0 0 0 0 0 0 0 0\n\
0 4 4 4 4 0 0 0 0 0 0 0 0 0 0 0\n\
0 4 4 4 4 0 0 0 0 0 0 0 0 0 0 0\n\
0 4 4 4 4 0 0 0 0 0 0 0 0 0 0 0\n\
0 4 4 4 4 0 0 0 0 0 0 0 0 0 0 0\n\
0 4 4 4 4 0 0 0 0 0 0 0 0 0 0 0\n\
0 4 4 4 4 0 0 0 0 0 0 0 0 0 0 0\n\
0 4 4 4 4 0 0 0 0 0 0 0 0 0 0 0\n";

/// Where the block's top face lands in a preview, as a share of the image width: the mean
/// column of the pixels in the upper half of the image that are brighter than the back sheet
/// by a clear margin. In the upper half only the back sheet, the block's front and the
/// block's top are paper; the back sheet (and the block's front, on a parallel plane) has the
/// most common paper colour there, and the top, lit from above, is brighter. Returns the
/// share and the number of pixels found.
fn block_top_across(png: &[u8]) -> (f64, usize) {
    let image = image::load_from_memory(png).expect("a PNG").to_rgba8();
    let (w, h) = image.dimensions();
    let luma =
        |p: &image::Rgba<u8>| 0.299 * p[0] as f64 + 0.587 * p[1] as f64 + 0.114 * p[2] as f64;
    let paper = |p: &image::Rgba<u8>| p[3] > 200 && luma(p) < 235.0;
    let upper = || (0..h / 2).flat_map(|y| (0..w).map(move |x| (x, y)));
    let mut counts: std::collections::HashMap<[u8; 4], usize> = Default::default();
    for (x, y) in upper() {
        let p = image.get_pixel(x, y);
        if paper(p) {
            *counts.entry(p.0).or_default() += 1;
        }
    }
    let (sheet, _) = counts
        .iter()
        .max_by_key(|&(_, n)| *n)
        .expect("paper in the upper half");
    let sheet_luma = luma(&image::Rgba(*sheet));
    let (mut sum, mut n) = (0.0, 0usize);
    for (x, y) in upper() {
        let p = image.get_pixel(x, y);
        if paper(p) && luma(p) > sheet_luma + 15.0 {
            sum += f64::from(x);
            n += 1;
        }
    }
    (sum / n.max(1) as f64 / f64::from(w), n)
}

/// Where the block's lit top lands across the preview `foldcam popup KIND FILE --png` draws
/// of the design `text`: its share of the width, and how many pixels it covers.
fn preview_across(kind: &str, file: &str, text: &str) -> (f64, usize) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join(file), text).unwrap();
    let out = foldcam(
        &[
            "popup",
            kind,
            file,
            "-o",
            "left.fold",
            "--png",
            "left.png",
            "--width",
            "400",
        ],
        dir.path(),
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    block_top_across(&std::fs::read(dir.path().join("left.png")).unwrap())
}

#[test]
fn the_card_preview_has_the_design_left_on_the_image_left() {
    let (across, pixels) = preview_across("voxel", "left.voxel.txt", LEFT_BLOCK);
    assert!(pixels > 200, "{pixels} pixels of the block's top");
    // Columns 1–4 of 16, seen a little from the left: well inside the left half.
    assert!(
        across < 0.4,
        "the block's top is {across:.2} of the way across"
    );
}

/// A polygon card (Mitani & Suzuki 2004) with the same kind of block: a wall 20 mm in front
/// of the back sheet and its roof 60 mm up, over x 10–30 mm of a 120 mm card.
const LEFT_BOX: &str = r#"[card]
width = 120.0
depth = 60.0
height = 80.0
grid = 5.0

[[operation]]
plane = "vertical"
at = 4
units = "grid"
polygon = [[2, 0], [6, 0], [6, 12], [2, 12]]

[[operation]]
plane = "horizontal"
at = 12
units = "grid"
polygon = [[2, 0], [6, 0], [6, 4], [2, 4]]
"#;

#[test]
fn the_polygon_card_preview_has_the_design_left_on_the_image_left() {
    let (across, pixels) = preview_across("poly", "left.popup.toml", LEFT_BOX);
    assert!(pixels > 200, "{pixels} pixels of the box's roof");
    assert!(
        across < 0.4,
        "the box's roof is {across:.2} of the way across"
    );
}

#[test]
fn seen_from_the_base_side_in_the_papers_axes_the_design_left_is_on_the_right() {
    // The old preview: the folded state in the papers' axes (base towards +y) seen from the
    // front at azimuth 200°, a little from the −x side. The block lands on the right, which
    // the measure above tells apart from the preview `as_held` gives.
    let card = parse_voxel_card(LEFT_BLOCK).unwrap();
    let cp = crease_pattern(&card).unwrap();
    let state = fold_card(&card, &cp, 90.0).state;
    let view = |azimuth_deg| View3d {
        azimuth_deg,
        elevation_deg: 28.0,
        ..View3d::with_width(400)
    };
    let old = block_top_across(&render_folded_png(&state, &view(200.0)).unwrap());
    let held = block_top_across(&render_folded_png(&as_held(&state), &view(-20.0)).unwrap());
    assert!(old.1 > 200 && held.1 > 200, "{old:?} {held:?}");
    assert!(old.0 > 0.6 && held.0 < 0.4, "{old:?} {held:?}");
}
