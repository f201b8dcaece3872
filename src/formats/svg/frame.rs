//! The mapping from usvg's canvas (CSS pixels, y down) to the pattern frame (millimetres,
//! y up).
//!
//! usvg resolves every length into CSS pixels at 96 dpi and folds the root `viewBox` mapping
//! into the absolute transforms, so a point arrives as `R · u`, where `u` is in the root's
//! user units and `R` is the viewBox transform (a scale `s` per axis plus a translation `t`,
//! from `viewBox`, `preserveAspectRatio` and the width and height). The reader undoes the
//! translation only: `p_mm = (R·u − t) / (96/25.4)`, then negates y. So a user unit of a file
//! sized in millimetres (`width="210mm"` with `viewBox="0 0 210 297"`) is one millimetre, the
//! user-space origin stays the pattern origin whatever the viewBox, and a file written by
//! [`super::write_string`] (whose viewBox is fitted to the pattern's bounds) reads back to the
//! same coordinates. Files without a physical size count a user unit as one CSS pixel
//! (25.4/96 mm), as browsers and Inkscape do.
//!
//! A `transform` on the root `<svg>` element (an SVG 2 feature) is applied by usvg but not
//! undone here: the pattern then keeps that transform's offset.

use glam::{DAffine2, DVec2};
use usvg::roxmltree;

/// CSS pixels per millimetre (96 per inch).
pub const PX_PER_MM: f64 = 96.0 / 25.4;

/// The affine map from usvg canvas pixels to pattern millimetres (y up) for a root `<svg>`
/// element and the canvas size usvg computed.
pub fn canvas_to_pattern(svg: roxmltree::Node, canvas: (f64, f64)) -> DAffine2 {
    let origin = user_origin(svg, canvas);
    DAffine2::from_scale(DVec2::new(1.0, -1.0) / PX_PER_MM) * DAffine2::from_translation(-origin)
}

/// Where the root's user-space origin lands on the canvas, in pixels.
fn user_origin(svg: roxmltree::Node, (width, height): (f64, f64)) -> DVec2 {
    let Some([vx, vy, vw, vh]) = svg.attribute("viewBox").and_then(parse_view_box) else {
        return DVec2::ZERO;
    };
    let (mut sx, mut sy) = (width / vw, height / vh);
    let aspect = parse_aspect(svg.attribute("preserveAspectRatio").unwrap_or(""));
    if let Some(align) = aspect.align {
        let s = if aspect.slice { sx.max(sy) } else { sx.min(sy) };
        (sx, sy) = (s, s);
        let free = DVec2::new(width - vw * s, height - vh * s);
        return DVec2::new(-vx * sx, -vy * sy) + free * align;
    }
    DVec2::new(-vx * sx, -vy * sy)
}

/// Parses `viewBox="x y w h"` (whitespace or comma separated); `None` when malformed or
/// empty, as SVG then ignores it.
pub fn parse_view_box(text: &str) -> Option<[f64; 4]> {
    let mut numbers = text
        .split(|c: char| c.is_whitespace() || c == ',')
        .filter(|t| !t.is_empty())
        .map(str::parse::<f64>);
    let mut out = [0.0; 4];
    for slot in &mut out {
        *slot = numbers.next()?.ok()?;
    }
    let valid = numbers.next().is_none()
        && out.iter().all(|v| v.is_finite())
        && out[2] > 0.0
        && out[3] > 0.0;
    valid.then_some(out)
}

/// `preserveAspectRatio`, reduced to what the mapping needs.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Aspect {
    /// Fractions (0, ½, 1) of the free space placed before the content on each axis, or
    /// `None` for `none` (non-uniform scaling).
    align: Option<DVec2>,
    /// `slice` rather than `meet`.
    slice: bool,
}

/// Parses `preserveAspectRatio`; malformed values fall back to the default `xMidYMid meet`.
fn parse_aspect(text: &str) -> Aspect {
    let default = Aspect {
        align: Some(DVec2::splat(0.5)),
        slice: false,
    };
    let mut tokens = text.split_whitespace().peekable();
    if tokens.peek() == Some(&"defer") {
        tokens.next();
    }
    let align = match tokens.next() {
        None => return default,
        Some("none") => None,
        Some(a) => match align_fractions(a) {
            Some(f) => Some(f),
            None => return default,
        },
    };
    let slice = match tokens.next() {
        None | Some("meet") => false,
        Some("slice") => true,
        Some(_) => return default,
    };
    Aspect { align, slice }
}

/// `xMinYMid` → (0, ½) and so on.
fn align_fractions(token: &str) -> Option<DVec2> {
    let fraction = |s: &str| match s {
        "Min" => Some(0.0),
        "Mid" => Some(0.5),
        "Max" => Some(1.0),
        _ => None,
    };
    let rest = token.strip_prefix('x')?;
    let (x, y) = rest.split_once('Y')?;
    Some(DVec2::new(fraction(x)?, fraction(y)?))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn origin_of(svg_attrs: &str, canvas: (f64, f64)) -> DVec2 {
        let text = format!("<svg xmlns=\"http://www.w3.org/2000/svg\" {svg_attrs}/>");
        let doc = roxmltree::Document::parse(&text).expect("test XML parses");
        user_origin(doc.root_element(), canvas)
    }

    #[test]
    fn view_box_parsing() {
        assert_eq!(parse_view_box("0 0 10 20"), Some([0.0, 0.0, 10.0, 20.0]));
        assert_eq!(parse_view_box("-1,-2, 3 4"), Some([-1.0, -2.0, 3.0, 4.0]));
        assert_eq!(parse_view_box("0 0 0 20"), None);
        assert_eq!(parse_view_box("0 0 10"), None);
        assert_eq!(parse_view_box("0 0 10 20 5"), None);
        assert_eq!(parse_view_box("a b c d"), None);
    }

    #[test]
    fn origin_undoes_the_view_box_offset() {
        // 1 user unit = 2 px; viewBox starts at (5, -10): origin lands at (-10, 20).
        let o = origin_of("viewBox=\"5 -10 50 50\"", (100.0, 100.0));
        assert_eq!(o, DVec2::new(-10.0, 20.0));
        assert_eq!(origin_of("", (100.0, 100.0)), DVec2::ZERO);
    }

    #[test]
    fn aspect_alignment_shifts_the_origin() {
        // Canvas 200×100, viewBox 100×100: uniform scale 1, 100 px free on x.
        let mid = origin_of("viewBox=\"0 0 100 100\"", (200.0, 100.0));
        assert_eq!(mid, DVec2::new(50.0, 0.0));
        let min = origin_of(
            "viewBox=\"0 0 100 100\" preserveAspectRatio=\"xMinYMax meet\"",
            (200.0, 100.0),
        );
        assert_eq!(min, DVec2::ZERO);
        let none = origin_of(
            "viewBox=\"10 0 100 100\" preserveAspectRatio=\"none\"",
            (200.0, 100.0),
        );
        assert_eq!(none, DVec2::new(-20.0, 0.0));
    }

    #[test]
    fn aspect_parsing() {
        assert_eq!(parse_aspect("bogus"), parse_aspect(""));
        let a = parse_aspect("defer xMaxYMin slice");
        assert_eq!(a.align, Some(DVec2::new(1.0, 0.0)));
        assert!(a.slice);
        assert_eq!(parse_aspect("none").align, None);
    }
}
