//! What a DXF entity's layer name or colour means as a crease assignment.
//!
//! **Layer names** (case-insensitive; spaces, `-` and `_` ignored) win over colour:
//!
//! | layer name | assignment |
//! | --- | --- |
//! | `MOUNTAIN`, `MOUNTAINS`, `MOUNTAINLINE` (ORIPA), `M`, `MT` | mountain |
//! | `VALLEY`, `VALLEYS`, `VALLEYLINE` (ORIPA), `V`, `VL` | valley |
//! | `CUTLINE` (ORIPA's outline), `BOUNDARY`, `BORDER`, `OUTLINE`, `EDGE`, `B` | boundary |
//! | `CUT`, `CUTS`, `CUTTING`, `C` | cut |
//! | `FLAT`, `FACET`, `MARK`, `AUX`, `AUXILIARY`, `PLOT`, `F` | flat |
//! | `UNASSIGNED`, `CREASE`, `CREASES`, `FOLD`, `FOLDS`, `SCORE`, `PERFORATE`, `U` | unassigned |
//! | `JOIN`, `J` | join |
//!
//! ORIPA writes `MountainLine`, `ValleyLine` and `CutLine` (its outline, as `.cp` type 1) and
//! aux lines on `noname` with colour 0; foldcam's own machine DXFs write `CUT`, `PERFORATE`,
//! `SCORE`, `MARK` and `PLOT`, so they read back as cut, unassigned folds and flat lines.
//!
//! **Colours**, for other layers: the entity's true colour (group 420) or AutoCAD Color Index
//! (group 62), `BYLAYER` taking the layer's, `BYBLOCK` the inserting entity's. The index
//! colours mean: 1 red mountain, 5 blue valley, 3 green cut, 2 yellow flat, 6 magenta
//! unassigned, 7 (black on white, white on black) and 0 boundary; any other colour maps to
//! the nearest crease-palette colour (as in SVG) through its RGB value (indices 10–249 from
//! the standard hue wheel, approximately).

use crate::formats::svg::palette::{self, Rgb};
use crate::pattern::Assignment;

/// The assignment a layer name stands for, if it is one of the known names.
pub fn layer_assignment(name: &str) -> Option<Assignment> {
    let key: String = name
        .chars()
        .filter(|c| !matches!(c, ' ' | '-' | '_'))
        .collect::<String>()
        .to_ascii_uppercase();
    Some(match key.as_str() {
        "MOUNTAIN" | "MOUNTAINS" | "MOUNTAINLINE" | "M" | "MT" => Assignment::Mountain,
        "VALLEY" | "VALLEYS" | "VALLEYLINE" | "V" | "VL" => Assignment::Valley,
        "CUTLINE" | "BOUNDARY" | "BORDER" | "OUTLINE" | "EDGE" | "B" => Assignment::Boundary,
        "CUT" | "CUTS" | "CUTTING" | "C" => Assignment::Cut,
        "FLAT" | "FACET" | "MARK" | "AUX" | "AUXILIARY" | "PLOT" | "F" => Assignment::Flat,
        "UNASSIGNED" | "CREASE" | "CREASES" | "FOLD" | "FOLDS" | "SCORE" | "PERFORATE" | "U" => {
            Assignment::Unassigned
        }
        "JOIN" | "J" => Assignment::Join,
        _ => return None,
    })
}

/// The assignment of an AutoCAD Color Index (0–255; 0 is `BYBLOCK` left unresolved).
pub fn aci_assignment(index: u8) -> Assignment {
    match index {
        1 => Assignment::Mountain,
        5 => Assignment::Valley,
        3 => Assignment::Cut,
        2 => Assignment::Flat,
        6 => Assignment::Unassigned,
        0 | 7 => Assignment::Boundary,
        other => palette::nearest(aci_rgb(other)).assignment,
    }
}

/// The assignment of a true colour (`0xRRGGBB`), by the nearest palette colour.
pub fn rgb_assignment(rgb: u32) -> Assignment {
    let [_, r, g, b] = rgb.to_be_bytes();
    palette::nearest(Rgb(r, g, b)).assignment
}

/// The RGB value of an AutoCAD Color Index: the nine standard colours and the greys exactly,
/// indices 10–249 from the hue wheel (24 hues of 15°, five shades, even indices full
/// saturation and odd half), which is close to AutoCAD's table.
pub fn aci_rgb(index: u8) -> Rgb {
    const STANDARD: [Rgb; 10] = [
        Rgb(0, 0, 0),
        Rgb(255, 0, 0),
        Rgb(255, 255, 0),
        Rgb(0, 255, 0),
        Rgb(0, 255, 255),
        Rgb(0, 0, 255),
        Rgb(255, 0, 255),
        Rgb(255, 255, 255),
        Rgb(128, 128, 128),
        Rgb(192, 192, 192),
    ];
    const GREYS: [u8; 6] = [51, 91, 132, 173, 214, 255];
    match index {
        0..=9 => STANDARD[usize::from(index)],
        250..=255 => {
            let g = GREYS[usize::from(index - 250)];
            Rgb(g, g, g)
        }
        _ => {
            let hue = f64::from(index / 10 - 1) * 15.0;
            let shade = index % 10;
            let value = [1.0, 0.65, 0.5, 0.3, 0.15][usize::from(shade / 2)];
            let saturation = if shade.is_multiple_of(2) { 1.0 } else { 0.5 };
            hsv(hue, saturation, value)
        }
    }
}

/// An HSV colour (hue in degrees, saturation and value in 0..=1) as 8-bit RGB.
fn hsv(hue: f64, s: f64, v: f64) -> Rgb {
    let c = v * s;
    let h = hue / 60.0;
    let x = c * (1.0 - (h % 2.0 - 1.0).abs());
    let (r, g, b) = match h as u32 {
        0 => (c, x, 0.0),
        1 => (x, c, 0.0),
        2 => (0.0, c, x),
        3 => (0.0, x, c),
        4 => (x, 0.0, c),
        _ => (c, 0.0, x),
    };
    let m = v - c;
    let byte = |t: f64| ((t + m) * 255.0).round().clamp(0.0, 255.0) as u8;
    Rgb(byte(r), byte(g), byte(b))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layer_names_of_cad_programs_and_oripa() {
        assert_eq!(layer_assignment("MOUNTAIN"), Some(Assignment::Mountain));
        assert_eq!(layer_assignment("Valley_Folds"), None);
        assert_eq!(layer_assignment("valley-s"), Some(Assignment::Valley));
        assert_eq!(layer_assignment("MountainLine"), Some(Assignment::Mountain));
        assert_eq!(layer_assignment("CutLine"), Some(Assignment::Boundary));
        assert_eq!(layer_assignment("PERFORATE"), Some(Assignment::Unassigned));
        assert_eq!(layer_assignment("0"), None);
    }

    #[test]
    fn colour_indices_follow_the_documented_table() {
        assert_eq!(aci_assignment(1), Assignment::Mountain);
        assert_eq!(aci_assignment(5), Assignment::Valley);
        assert_eq!(aci_assignment(7), Assignment::Boundary);
        // 10 is full red, 170 full blue (hue 240°) on AutoCAD's wheel.
        assert_eq!(aci_rgb(10), Rgb(255, 0, 0));
        assert_eq!(aci_rgb(170), Rgb(0, 0, 255));
        assert_eq!(aci_assignment(170), Assignment::Valley);
        assert_eq!(rgb_assignment(0x00_00ff), Assignment::Valley);
        assert_eq!(rgb_assignment(0xdc_143c), Assignment::Mountain);
    }
}
