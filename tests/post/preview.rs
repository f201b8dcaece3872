//! The PNG preview: size, line colours and dashes, orientation, fault highlights, scale bar.

use foldcam::check::{CheckOptions, FindingKind, check};
use foldcam::pattern::{Assignment, CreasePattern, EdgeId, Units, VertexId};
use foldcam::render::{PreviewOptions, RenderError, preview_png, render_rgba};
use glam::DVec2;
use image::{Rgba, RgbaImage};

use Assignment::{Boundary as B, Mountain as M, Valley as V};

/// A 100 × 100 mm sheet with a horizontal valley at y = 25 and a vertical mountain at
/// x = 75, meeting nowhere (both run to the outline).
fn sheet() -> CreasePattern {
    let mut cp = CreasePattern::new();
    let pts = [
        (0.0, 0.0),
        (75.0, 0.0),
        (100.0, 0.0),
        (100.0, 25.0),
        (100.0, 100.0),
        (75.0, 100.0),
        (0.0, 100.0),
        (0.0, 25.0),
    ];
    let ring: Vec<VertexId> = pts
        .iter()
        .map(|&(x, y)| cp.add_vertex(DVec2::new(x, y)))
        .collect();
    for i in 0..ring.len() {
        cp.add_edge(ring[i], ring[(i + 1) % ring.len()], B);
    }
    cp
}

/// [`sheet`] with a valley from (0, 25) towards x = 60 and a mountain at x = 75 from the
/// bottom to the top.
fn sheet_with_folds() -> CreasePattern {
    let mut cp = sheet();
    let end = cp.add_vertex(DVec2::new(60.0, 25.0));
    cp.add_edge(VertexId(7), end, V);
    cp.add_edge(VertexId(1), VertexId(5), M);
    cp
}

fn render(cp: &CreasePattern, width: u32) -> RgbaImage {
    render_rgba(cp, &PreviewOptions::with_width(width), &[]).expect("render")
}

fn is_blue(p: &Rgba<u8>) -> bool {
    p[2] > 150 && p[0] < 120 && p[1] < 160
}

fn is_red(p: &Rgba<u8>) -> bool {
    p[0] > 150 && p[1] < 120 && p[2] < 120
}

fn is_dark(p: &Rgba<u8>) -> bool {
    p[0] < 90 && p[1] < 90 && p[2] < 90
}

fn is_white(p: &Rgba<u8>) -> bool {
    p[0] > 240 && p[1] > 240 && p[2] > 240
}

/// Pixel coordinates of a pattern point for the default layout of [`sheet`] at width 424:
/// margin 24, 100 mm over 376 px.
fn px(x: f64, y: f64) -> (u32, u32) {
    let s = 376.0 / 100.0;
    (
        (24.0 + x * s).round() as u32,
        (24.0 + (100.0 - y) * s).round() as u32,
    )
}

#[test]
fn png_decodes_with_the_requested_width() {
    let png = preview_png(&sheet_with_folds(), &PreviewOptions::with_width(300), &[]).expect("png");
    let img = image::load_from_memory(&png).expect("decode").to_rgba8();
    assert_eq!(img.width(), 300);
    // Square pattern: the height is the width plus the scale-bar band.
    assert!(img.height() > 300 && img.height() < 360, "{}", img.height());
}

#[test]
fn valley_is_dashed_blue_mountain_red_boundary_black() {
    let img = render(&sheet_with_folds(), 424);
    // Walk along the valley (y = 25, x from 2 to 58 mm).
    let (x0, y) = px(2.0, 25.0);
    let (x1, _) = px(58.0, 25.0);
    let row: Vec<bool> = (x0..x1).map(|x| is_blue(img.get_pixel(x, y))).collect();
    let blue = row.iter().filter(|&&b| b).count();
    let gaps = row.windows(2).filter(|w| w[0] && !w[1]).count();
    assert!(blue > row.len() / 3, "{blue} of {}", row.len());
    assert!(gaps >= 5, "a dashed line has gaps, found {gaps}");
    assert!(row.iter().any(|&b| !b));
    // The mountain (x = 75) is red, with gaps too.
    let (x, y0) = px(75.0, 98.0);
    let (_, y1) = px(75.0, 2.0);
    let col: Vec<bool> = (y0..y1).map(|y| is_red(img.get_pixel(x, y))).collect();
    assert!(col.iter().filter(|&&r| r).count() > col.len() / 3);
    assert!(col.windows(2).filter(|w| w[0] && !w[1]).count() >= 5);
    assert!((y0..y1).all(|y| !is_blue(img.get_pixel(x, y))));
    // The outline is solid black: every pixel of the left side at x = 0.
    let (x, top) = px(0.0, 98.0);
    let (_, bottom) = px(0.0, 2.0);
    assert!((top..bottom).all(|y| is_dark(img.get_pixel(x, y))));
    // Away from lines the background is white.
    let (cx, cy) = px(40.0, 60.0);
    assert!(is_white(img.get_pixel(cx, cy)));
}

#[test]
fn top_of_the_pattern_is_at_the_top_of_the_image() {
    // A single valley from (0, 0) to (10, 40): its upper end must be drawn near the top.
    let mut cp = CreasePattern::new();
    cp.add_segment(DVec2::new(0.0, 0.0), DVec2::new(10.0, 40.0), V);
    cp.add_segment(DVec2::new(0.0, 40.0), DVec2::new(2.0, 40.0), B);
    let img = render(&cp, 200);
    let black_rows: Vec<u32> = (0..img.height())
        .filter(|&y| (0..img.width() / 2).any(|x| is_dark(img.get_pixel(x, y))))
        .collect();
    let first = *black_rows.first().expect("the top segment is drawn");
    assert!(first < 40, "the y = 40 boundary is drawn at row {first}");
    // No mirroring: the valley's top end is to the right of its bottom end.
    let blue_x = |rows: std::ops::Range<u32>| {
        rows.flat_map(|y| (0..img.width()).map(move |x| (x, y)))
            .filter(|&(x, y)| is_blue(img.get_pixel(x, y)))
            .map(|(x, _)| x)
            .max()
    };
    let h = img.height();
    let upper = blue_x(0..h / 3).expect("upper blue");
    let lower = blue_x(h / 2..h).expect("lower blue");
    assert!(upper > lower, "{upper} vs {lower}");
}

#[test]
fn fault_positions_and_edges_are_highlighted() {
    let mut cp = sheet_with_folds();
    // Creases without an angle count as fully folded (±180°): give them a gentle one.
    for e in cp.edges.iter_mut().filter(|e| e.assignment.is_fold()) {
        e.fold_angle = Some(e.assignment.flat_folded_angle().unwrap_or(0.0) / 2.0);
    }
    cp.edges[9].fold_angle = Some(170.0);
    let opts = CheckOptions {
        max_fold_angle_deg: Some(120.0),
        ..CheckOptions::default()
    };
    let report = check(&cp, &opts);
    let fault: Vec<_> = report.of_kind(FindingKind::FoldAngle).cloned().collect();
    assert_eq!(fault.len(), 1);
    assert_eq!(fault[0].edge, Some(EdgeId(9)));
    let plain = render(&cp, 424);
    let marked = render_rgba(&cp, &PreviewOptions::with_width(424), &fault).expect("render");
    let orange = |p: &Rgba<u8>| p[0] > 200 && p[1] > 100 && p[1] < 220 && p[2] < 130;
    // Beside the mountain (a few pixels off its centre line) the halo is orange.
    let (x, y) = px(75.0, 70.0);
    assert!(
        orange(marked.get_pixel(x + 4, y)),
        "{:?}",
        marked.get_pixel(x + 4, y)
    );
    assert!(!orange(plain.get_pixel(x + 4, y)));
    // A ring around the finding's position (the mountain's midpoint).
    let (cx, cy) = px(75.0, 50.0);
    let ring_hits = (0..40)
        .filter(|&d| orange(marked.get_pixel(cx - 20 + d, cy - 10)))
        .count();
    assert!(ring_hits > 0);
    assert!(
        marked.pixels().filter(|p| orange(p)).count()
            > plain.pixels().filter(|p| orange(p)).count() + 100
    );
}

#[test]
fn scale_bar_sits_bottom_left_with_a_label() {
    let cp = sheet_with_folds();
    // The bar alone, without the legend that follows it.
    let bar_only = PreviewOptions {
        legend: false,
        ..PreviewOptions::with_width(424)
    };
    let with = render_rgba(&cp, &bar_only, &[]).expect("render");
    let opts = PreviewOptions {
        scale_bar: false,
        legend: false,
        ..PreviewOptions::with_width(424)
    };
    let without = render_rgba(&cp, &opts, &[]).expect("render");
    assert!(without.height() < with.height());
    let (_, bottom) = px(0.0, 0.0);
    let band = |img: &RgbaImage, x: std::ops::Range<u32>| {
        x.flat_map(|x| (bottom + 4..img.height()).map(move |y| (x, y)))
            .filter(|&(x, y)| is_dark(img.get_pixel(x, y)))
            .count()
    };
    // The bar: 376 px for 100 mm, at most 30 % → 20 mm = 75 px; the label follows it.
    assert!(band(&with, 0..212) > 100);
    assert_eq!(band(&with, 212..424), 0, "the bar stays in the left half");
    // The longest dark run in a row is the bar itself.
    let longest_run = |y: u32| {
        let (mut best, mut run) = (0, 0);
        for x in 0..212 {
            run = if is_dark(with.get_pixel(x, y)) {
                run + 1
            } else {
                0
            };
            best = best.max(run);
        }
        best
    };
    let bar = (bottom + 4..with.height())
        .map(longest_run)
        .max()
        .unwrap_or(0);
    assert!((74..=77).contains(&bar), "bar of {bar} px");
}

#[test]
fn unitless_and_degenerate_patterns_render() {
    let mut cp = sheet_with_folds();
    for p in &mut cp.vertices {
        *p /= 100.0;
    }
    cp.units = Units::Unitless;
    let img = render(&cp, 424);
    assert_eq!(img.width(), 424);
    assert!(img.pixels().any(is_blue));
    // Same drawing and bar length as in millimetres; the label "0.2 units" is longer than
    // "20 mm", so the band holds more dark pixels.
    let mm = render(&sheet_with_folds(), 424);
    let (_, bottom) = px(0.0, 0.0);
    let band_dark = |img: &RgbaImage| {
        (bottom + 4..img.height())
            .flat_map(|y| (0..img.width()).map(move |x| (x, y)))
            .filter(|&(x, y)| is_dark(img.get_pixel(x, y)))
            .count()
    };
    assert!(band_dark(&img) > band_dark(&mm) + 20);
    // A horizontal line (zero height) and a single point.
    let mut line = CreasePattern::new();
    line.add_segment(DVec2::ZERO, DVec2::new(5.0, 0.0), M);
    assert!(render(&line, 100).pixels().any(is_red));
    let mut point = CreasePattern::new();
    let v = point.add_vertex(DVec2::ONE);
    let w = point.add_vertex(DVec2::ONE);
    point.add_edge(v, w, M);
    assert_eq!(render(&point, 64).width(), 64);
}

#[test]
fn tall_patterns_are_capped_at_four_widths() {
    let mut cp = CreasePattern::new();
    cp.add_segment(DVec2::ZERO, DVec2::new(1.0, 100.0), B);
    assert_eq!(render(&cp, 100).height(), 400);
}

#[test]
fn bad_input_is_an_error() {
    let opts = PreviewOptions::default();
    assert!(matches!(
        preview_png(&CreasePattern::new(), &opts, &[]),
        Err(RenderError::Empty)
    ));
    let cp = sheet();
    for width in [0, 15, 16385] {
        let r = preview_png(&cp, &PreviewOptions::with_width(width), &[]);
        assert!(matches!(r, Err(RenderError::Width(w)) if w == width));
    }
    let bad_line = PreviewOptions {
        line_width_px: f32::NAN,
        ..opts.clone()
    };
    assert!(matches!(
        preview_png(&cp, &bad_line, &[]),
        Err(RenderError::Option { .. })
    ));
    // A margin too wide for the image is reduced, not an error.
    let wide_margin = PreviewOptions {
        margin: 300,
        ..PreviewOptions::with_width(100)
    };
    let img = render_rgba(&cp, &wide_margin, &[]).expect("render");
    assert!(img.pixels().any(is_dark));
}
