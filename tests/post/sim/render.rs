//! The toolpath PNG: size, orientation (y up), colours of burns and travel.
//! (Legend, scale bar and the whole bed: `tests/cli/picture_keys.rs`.)

use super::*;
use image::Rgba;

fn decode(png: &[u8]) -> image::RgbaImage {
    image::load_from_memory(png).expect("a PNG").to_rgba8()
}

/// The pixel of bed point (x, y) on a 300 × 200 mm bed drawn `w` pixels wide (4 % margin).
fn pixel_of(w: u32, x: f64, y: f64) -> (u32, u32) {
    let margin = (f64::from(w) * 0.04).round();
    let scale = (f64::from(w) - 2.0 * margin) / 300.0;
    (
        (margin + x * scale) as u32,
        (margin + (200.0 - y) * scale) as u32,
    )
}

fn is_red(p: Rgba<u8>) -> bool {
    p[0] > 200 && p[2] < 100
}

#[test]
fn burns_are_red_at_full_power_and_y_points_up() {
    // A full-power burn along y = 20 (near the front), travel along y = 180.
    let text = "G0 X10 Y180\nG0 X290 Y180\nG0 X20 Y20\nM4 S1000\nG1 X280 F1200\nM5\nM2";
    let machine = laser(Dialect::Grbl);
    let report = run(text, &machine);
    let img = decode(&sim::render_png(&report, &machine, 600, &sim::JobNames::default()).unwrap());
    assert_eq!(img.width(), 600);
    let (bx, by) = pixel_of(600, 150.0, 20.0);
    assert!(
        is_red(*img.get_pixel(bx, by)),
        "{:?}",
        img.get_pixel(bx, by)
    );
    // The mirrored position (y = 180) holds no burn.
    let (mx, my) = pixel_of(600, 150.0, 180.0);
    assert!(!is_red(*img.get_pixel(mx, my)));
    // Travel is faint orange somewhere along y = 180 (dashed: look along a short stretch).
    let orange = (0..20).any(|dx| {
        let p = img.get_pixel(mx + dx, my);
        p[0] > 240 && p[1] < 235 && p[2] < p[1] && p[1] > 120
    });
    assert!(orange, "travel drawn in faint orange");
}

#[test]
fn bad_widths_are_errors() {
    let machine = laser(Dialect::Grbl);
    let report = run("M2", &machine);
    assert!(sim::render_png(&report, &machine, 8, &sim::JobNames::default()).is_err());
    assert!(sim::render_png(&report, &machine, 100_000, &sim::JobNames::default()).is_err());
    assert!(sim::render_png(&report, &machine, 16, &sim::JobNames::default()).is_ok());
}
