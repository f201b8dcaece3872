//! The SVG writer: one `<line>` per edge in Origami Simulator's colours, grouped by
//! assignment.
//!
//! Layout of the output:
//! - `width`/`height` in millimetres (`"…mm"`) and a `viewBox` fitted to the pattern's bounds
//!   without margin, so one user unit is one millimetre. Unitless patterns get plain numbers
//!   (user units, which readers take as CSS pixels).
//! - y is negated (the pattern's y points up, SVG's down); the reader negates it back and
//!   keeps the user-space origin, so coordinates survive a round trip.
//! - every `<line>` is a direct child of `<svg>`, because Origami Simulator reads only the
//!   root's children (it asks users to "ungroup all"): lines come sorted by assignment, each
//!   run after a comment naming it, each line with `class="mountain"` (etc.) so stylesheets
//!   and scripts can still select a kind. Every line carries its own `stroke` (Origami
//!   Simulator reads colours and opacities from the line itself) and, for mountain and valley
//!   lines with a known fold angle below 180°, `stroke-opacity` = |angle| / 180. The root
//!   carries `fill="none"` and a stroke width of 1/500 of the larger side, for display.
//! - Join edges (`J`) have no palette colour and are written as unassigned (magenta).
//!
//! Numbers: coordinates are rounded to a step of 10^(⌊log10 E⌋ − 10), E the larger side of the
//! bounds, so the rounding error is at most 5e-11 · E (well inside the 1e-9 · E promised for a
//! round trip), with trailing zeros dropped; opacities get ten decimals (1e-8 degrees).

use std::fmt::Write as _;

use glam::DVec2;

use super::palette::{colour_of, opacity_of};
use crate::pattern::{Assignment, CreasePattern, Units};

/// Renders a pattern as an Origami Simulator crease-pattern SVG.
pub fn write_string(pattern: &CreasePattern) -> String {
    let frame = Frame::of(pattern);
    let mut out = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    let unit = if pattern.units == Units::Millimetres {
        "mm"
    } else {
        ""
    };
    let _ = writeln!(
        out,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"{w}{unit}\" \
         height=\"{h}{unit}\" viewBox=\"{x} {y} {w} {h}\" fill=\"none\" \
         stroke-width=\"{sw}\" stroke-linecap=\"round\">",
        w = frame.num(frame.size.x),
        h = frame.num(frame.size.y),
        x = frame.num(frame.min.x),
        y = frame.num(frame.min.y),
        sw = frame.num(frame.size.max_element() / 500.0),
    );
    if let Some(title) = &pattern.meta.title {
        let _ = writeln!(out, "<title>{}</title>", escape(title));
    }
    if let Some(desc) = &pattern.meta.description {
        let _ = writeln!(out, "<desc>{}</desc>", escape(desc));
    }
    for assignment in Assignment::ALL {
        write_kind(&mut out, pattern, &frame, assignment);
    }
    out.push_str("</svg>\n");
    out
}

/// The bounds written as the viewBox (in SVG's y-down user units) and the number format.
struct Frame {
    min: DVec2,
    size: DVec2,
    decimals: usize,
}

impl Frame {
    fn of(pattern: &CreasePattern) -> Frame {
        let (lo, hi) = pattern.bounds().unwrap_or((DVec2::ZERO, DVec2::ONE));
        // SVG's y runs down: the pattern's top edge (max y) is the viewBox's first row.
        let (min, max) = (DVec2::new(lo.x, -hi.y), DVec2::new(hi.x, -lo.y));
        let extent = (max - min).max_element();
        let extent = if extent > 0.0 && extent.is_finite() {
            extent
        } else {
            1.0
        };
        // A line-shaped pattern still needs a non-zero viewBox side, and not a sliver: usvg
        // resolves coordinates in f32, and a viewBox a thousand times wider than tall costs
        // about 1e-5 of the extent in precision (seen as drift on repeated round trips).
        let size = (max - min).max(DVec2::splat(extent * 0.1));
        let center = (min + max) / 2.0;
        let min = DVec2::new(
            if max.x > min.x {
                min.x
            } else {
                center.x - size.x / 2.0
            },
            if max.y > min.y {
                min.y
            } else {
                center.y - size.y / 2.0
            },
        );
        let magnitude = extent.log10().floor() as i64;
        let decimals = (10 - magnitude).clamp(0, 20) as usize;
        Frame {
            min,
            size,
            decimals,
        }
    }

    /// A coordinate with the frame's precision, trailing zeros removed.
    fn num(&self, v: f64) -> String {
        trim_number(format!("{:.*}", self.decimals, v))
    }
}

/// Drops trailing zeros (and a bare trailing point) from a fixed-point number; `-0` → `0`.
fn trim_number(mut s: String) -> String {
    if s.contains('.') {
        let keep = s.trim_end_matches('0').trim_end_matches('.').len();
        s.truncate(keep);
    }
    if s == "-0" {
        s.remove(0);
    }
    s
}

fn write_kind(out: &mut String, pattern: &CreasePattern, frame: &Frame, assignment: Assignment) {
    let mut edges = pattern
        .edges
        .iter()
        .filter(|e| e.assignment == assignment)
        .peekable();
    if edges.peek().is_none() {
        return;
    }
    let colour = colour_of(assignment).hex();
    let name = assignment.name();
    let _ = writeln!(out, "<!-- {name} -->");
    for edge in edges {
        let [a, b] = edge.vertices.map(|v| pattern.position(v));
        let _ = write!(
            out,
            "<line class=\"{name}\" x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{colour}\"",
            frame.num(a.x),
            frame.num(-a.y),
            frame.num(b.x),
            frame.num(-b.y)
        );
        let opacity = opacity_of(edge.assignment, edge.fold_angle);
        if opacity < 1.0 {
            let _ = write!(
                out,
                " stroke-opacity=\"{}\"",
                trim_number(format!("{opacity:.10}"))
            );
        }
        out.push_str("/>\n");
    }
}

/// Escapes text for XML content and attribute values (also used by the job SVG writer).
pub(crate) fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            // XML 1.0 cannot hold other control characters at all.
            c if c.is_control() && !matches!(c, '\n' | '\r' | '\t') => {}
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_trimmed() {
        assert_eq!(trim_number("1.2500".into()), "1.25");
        assert_eq!(trim_number("3.000".into()), "3");
        assert_eq!(trim_number("-0.000".into()), "0");
        assert_eq!(trim_number("120".into()), "120");
    }

    #[test]
    fn precision_follows_the_extent() {
        let mut cp = CreasePattern::new();
        cp.add_segment(DVec2::ZERO, DVec2::new(200.0, 100.0), Assignment::Valley);
        let f = Frame::of(&cp);
        assert_eq!(f.decimals, 8);
        let x = 123.456_789_012_345_67;
        let back: f64 = f.num(x).parse().unwrap_or(f64::NAN);
        assert!((back - x).abs() <= 5e-11 * 200.0);
    }

    #[test]
    fn degenerate_bounds_get_a_viewbox() {
        let mut cp = CreasePattern::new();
        cp.add_segment(DVec2::ZERO, DVec2::new(0.0, 50.0), Assignment::Mountain);
        let f = Frame::of(&cp);
        assert!(f.size.x > 0.0 && f.size.y == 50.0);
        assert!((f.min.x + f.size.x / 2.0).abs() < 1e-12);
    }

    #[test]
    fn an_empty_pattern_is_still_an_svg() {
        let text = write_string(&CreasePattern::new());
        let doc = usvg::roxmltree::Document::parse(&text).expect("well-formed");
        assert_eq!(doc.root_element().attribute("viewBox"), Some("0 -1 1 1"));
    }

    #[test]
    fn escaping() {
        assert_eq!(escape("a<b & \"c\"\u{1}"), "a&lt;b &amp; &quot;c&quot;");
    }
}
