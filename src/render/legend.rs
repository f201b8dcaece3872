//! The key every picture carries: text, a legend (what each colour and dash means), a scale
//! bar in millimetres, captions and numbered markers, drawn with the bitmap [`font`] into a
//! tiny-skia pixmap. One component, shared by the pattern preview, the toolpath picture of
//! the simulated machine, the fold-step sheet and the check rings, so every picture reads the
//! same way.
//!
//! **Sizes.** Text is drawn in font pixels of `font_px` image pixels each ([`font_px_for`]:
//! one per 240 pixels of image width, 1 to 4), so a 900-pixel picture has 21-pixel capitals.
//! A [`Key`] lays its items (an optional scale bar, then the legend entries) left to right in
//! rows that fit the width it is given, and [`Key::height`] says how tall the band is before
//! anything is drawn, so a renderer can size its image first.

use tiny_skia::{LineCap, Paint, PathBuilder, Pixmap, Rect, Stroke, StrokeDash, Transform};

use super::font;
use super::layout::{length_label, nice_length};

/// Colour of text and of the scale bar, RGBA.
pub const INK: [u8; 4] = [30, 30, 30, 255];
/// Background of a key band or caption, RGBA.
pub const PAPER: [u8; 4] = [255, 255, 255, 255];
/// Length of a legend entry's line sample, in font pixels.
const SWATCH_FONT_PX: f64 = 10.0;
/// Space between a sample and its label, and between entries, in font pixels.
const GAP_FONT_PX: f64 = 2.0;
/// Space between entries, in font pixels.
const ENTRY_GAP_FONT_PX: f64 = 5.0;
/// Height of one row of the key, in font pixels (a glyph and its spacing).
const ROW_FONT_PX: u32 = font::GLYPH_HEIGHT + 5;

/// The size of one font pixel for an image `width` pixels wide: 1 per 240 pixels, 1 to 4.
pub fn font_px_for(width: u32) -> u32 {
    (width / 240).clamp(1, 4)
}

/// Width and height of `text` in image pixels at `font_px`.
pub fn text_size(text: &str, font_px: u32) -> (u32, u32) {
    (
        font::text_width(text) * font_px,
        font::GLYPH_HEIGHT * font_px,
    )
}

/// A paint of one colour, anti-aliased.
pub(crate) fn paint(color: [u8; 4]) -> Paint<'static> {
    let mut p = Paint::default();
    p.set_color_rgba8(color[0], color[1], color[2], color[3]);
    p.anti_alias = true;
    p
}

/// Fills an axis-aligned rectangle (pixels), without anti-aliasing.
pub fn fill_rect(pixmap: &mut Pixmap, x: f64, y: f64, w: f64, h: f64, color: [u8; 4]) {
    if let Some(rect) = Rect::from_xywh(x as f32, y as f32, w as f32, h as f32) {
        let mut p = paint(color);
        p.anti_alias = false;
        pixmap.fill_rect(rect, &p, Transform::identity(), None);
    }
}

/// Draws `text` with its top-left corner at `(x, y)` pixels.
pub fn draw_text(pixmap: &mut Pixmap, x: f64, y: f64, text: &str, font_px: u32, color: [u8; 4]) {
    let fp = f64::from(font_px);
    font::for_each_dot(text, |col, row| {
        let (dx, dy) = (f64::from(col) * fp, f64::from(row) * fp);
        fill_rect(pixmap, x + dx, y + dy, fp, fp, color);
    });
}

/// Draws `text` on a paper-coloured box with a `pad`-pixel border, top-left at `(x, y)`;
/// returns the box's width and height.
pub fn draw_label(pixmap: &mut Pixmap, x: f64, y: f64, text: &str, font_px: u32) -> (f64, f64) {
    let (w, h) = text_size(text, font_px);
    let pad = f64::from(font_px);
    let (bw, bh) = (f64::from(w) + 2.0 * pad, f64::from(h) + 2.0 * pad);
    fill_rect(pixmap, x, y, bw, bh, PAPER);
    draw_text(pixmap, x + pad, y + pad, text, font_px, INK);
    (bw, bh)
}

/// The longest prefix of `text` that fits `max_px` pixels at `font_px`, with `…` when cut.
pub fn fit_text(text: &str, max_px: u32, font_px: u32) -> String {
    if text_size(text, font_px).0 <= max_px {
        return text.to_string();
    }
    let per_char = font::ADVANCE * font_px.max(1);
    let keep = (max_px / per_char).saturating_sub(1) as usize;
    let mut out: String = text.chars().take(keep).collect();
    out.push('…');
    out
}

/// What a legend entry's sample looks like.
#[derive(Clone, Debug, PartialEq)]
pub enum Swatch {
    /// A short line: colour (RGBA), width and dash pattern (on, off, … pixels; `None` solid).
    Line {
        /// Colour, RGBA.
        color: [u8; 4],
        /// Width, pixels.
        width: f32,
        /// Dash pattern, pixels.
        dash: Option<Vec<f32>>,
    },
    /// A ring, as drawn around a finding.
    Ring {
        /// Colour, RGBA.
        color: [u8; 4],
    },
}

/// One line of a legend: a sample and what it means.
#[derive(Clone, Debug, PartialEq)]
pub struct LegendEntry {
    /// The sample.
    pub swatch: Swatch,
    /// What it means ("cut", "travel", "valley fold").
    pub label: String,
}

impl LegendEntry {
    /// A solid or dashed line sample.
    pub fn line(label: &str, color: [u8; 4], width: f32, dash: Option<Vec<f32>>) -> Self {
        LegendEntry {
            swatch: Swatch::Line { color, width, dash },
            label: label.to_string(),
        }
    }
}

/// A scale bar: a round length (1, 2 or 5 × 10^k units) no longer than `max_px` pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScaleBar {
    /// Pixels per unit of the drawing.
    pub px_per_unit: f64,
    /// The unit's label ("mm", "units").
    pub unit: &'static str,
    /// Longest bar, pixels.
    pub max_px: f64,
}

impl ScaleBar {
    /// The bar's length in units and in pixels; `None` when no round length fits.
    fn length(&self) -> Option<(f64, f64)> {
        let length = nice_length(self.max_px / self.px_per_unit)?;
        let px = length * self.px_per_unit;
        (px >= 2.0 && px.is_finite()).then_some((length, px))
    }

    /// Pixel width of the bar and its label at `font_px`.
    fn width(&self, font_px: u32) -> f64 {
        self.length().map_or(0.0, |(length, px)| {
            let label = length_label(length, self.unit);
            px + f64::from(font_px) * GAP_FONT_PX + f64::from(text_size(&label, font_px).0)
        })
    }

    /// Draws `|____| 10 mm` with its top-left at `(x, y)`.
    fn draw(&self, pixmap: &mut Pixmap, x: f64, y: f64, font_px: u32) {
        let Some((length, bar)) = self.length() else {
            return;
        };
        let fp = f64::from(font_px);
        let h = f64::from(font::GLYPH_HEIGHT) * fp;
        let thick = 2.0 * fp;
        fill_rect(pixmap, x, y, thick, h, INK);
        fill_rect(pixmap, x + bar - thick, y, thick, h, INK);
        fill_rect(pixmap, x, y + h - thick, bar, thick, INK);
        let label = length_label(length, self.unit);
        draw_text(pixmap, x + bar + GAP_FONT_PX * fp, y, &label, font_px, INK);
    }
}

/// A band under a picture: a scale bar and legend entries, left to right, wrapped in rows.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Key {
    /// The scale bar, first.
    pub scale_bar: Option<ScaleBar>,
    /// The legend entries, in order.
    pub entries: Vec<LegendEntry>,
}

/// Where one item of a key goes, pixels from the band's top-left.
struct Placed {
    x: f64,
    row: u32,
}

impl Key {
    /// Whether there is nothing to draw.
    pub fn is_empty(&self) -> bool {
        self.entries.is_empty() && self.scale_bar.and_then(|s| s.length()).is_none()
    }

    fn entry_width(entry: &LegendEntry, font_px: u32) -> f64 {
        let fp = f64::from(font_px);
        let label = f64::from(text_size(&entry.label, font_px).0);
        (SWATCH_FONT_PX + GAP_FONT_PX) * fp + label
    }

    /// Item widths in pixels: the scale bar's (when drawn), then each entry's.
    fn widths(&self, font_px: u32) -> Vec<f64> {
        let bar = self
            .scale_bar
            .filter(|s| s.length().is_some())
            .map(|s| s.width(font_px));
        bar.into_iter()
            .chain(self.entries.iter().map(|e| Key::entry_width(e, font_px)))
            .collect()
    }

    /// Places the items in rows no wider than `width` pixels (an item wider than a row gets a
    /// row of its own).
    fn place(&self, width: f64, font_px: u32) -> Vec<Placed> {
        let gap = ENTRY_GAP_FONT_PX * f64::from(font_px);
        let (mut x, mut row) = (0.0, 0);
        let mut out = Vec::new();
        for w in self.widths(font_px) {
            if x > 0.0 && x + w > width {
                x = 0.0;
                row += 1;
            }
            out.push(Placed { x, row });
            x += w + gap;
        }
        out
    }

    /// Height of the band for a drawing `width` pixels wide (inside its margins), pixels; 0
    /// when the key is empty.
    pub fn height(&self, width: u32, font_px: u32) -> u32 {
        if self.is_empty() {
            return 0;
        }
        let rows = self
            .place(f64::from(width), font_px)
            .last()
            .map_or(0, |p| p.row + 1);
        rows * ROW_FONT_PX * font_px + 2 * font_px
    }

    /// Draws the key with its top-left corner at `(x, y)`, within `width` pixels.
    pub fn draw(&self, pixmap: &mut Pixmap, x: f64, y: f64, width: u32, font_px: u32) {
        let fp = f64::from(font_px);
        let row_h = f64::from(ROW_FONT_PX) * fp;
        let placed = self.place(f64::from(width), font_px);
        let mut items = placed.iter();
        let top = |p: &Placed| y + fp + f64::from(p.row) * row_h;
        let bar = self.scale_bar.filter(|s| s.length().is_some());
        if let Some((bar, p)) = bar.and_then(|b| items.next().map(|p| (b, p))) {
            bar.draw(pixmap, x + p.x, top(p), font_px);
        }
        for (entry, p) in self.entries.iter().zip(items) {
            let (ex, ey) = (x + p.x, top(p));
            draw_swatch(pixmap, &entry.swatch, ex, ey, font_px);
            let lx = ex + (SWATCH_FONT_PX + GAP_FONT_PX) * fp;
            draw_text(pixmap, lx, ey, &entry.label, font_px, INK);
        }
    }
}

/// Draws a sample `SWATCH_FONT_PX` font pixels long, centred on the text line at `(x, y)`.
fn draw_swatch(pixmap: &mut Pixmap, swatch: &Swatch, x: f64, y: f64, font_px: u32) {
    let fp = f64::from(font_px);
    let len = SWATCH_FONT_PX * fp;
    match swatch {
        Swatch::Line { color, width, dash } => {
            // Whole pixels: at least two, so a faint line's colour can still be seen in the
            // key, centred so that it covers whole rows (no lighter anti-aliased edges).
            let width = width.round().max(2.0);
            let half_odd = if width as u32 % 2 == 1 { 0.5 } else { 0.0 };
            let mid = (y + f64::from(font::GLYPH_HEIGHT) * fp / 2.0).floor() + half_odd;
            let mut pb = PathBuilder::new();
            pb.move_to(x as f32, mid as f32);
            pb.line_to((x + len) as f32, mid as f32);
            let stroke = Stroke {
                width,
                line_cap: LineCap::Butt,
                dash: dash.clone().and_then(|d| StrokeDash::new(d, 0.0)),
                ..Stroke::default()
            };
            if let Some(path) = pb.finish() {
                pixmap.stroke_path(&path, &paint(*color), &stroke, Transform::identity(), None);
            }
        }
        Swatch::Ring { color } => {
            let mid = y + f64::from(font::GLYPH_HEIGHT) * fp / 2.0;
            let r = 3.0 * fp;
            let mut pb = PathBuilder::new();
            pb.push_circle((x + len / 2.0) as f32, mid as f32, r as f32);
            let stroke = Stroke {
                width: fp.max(2.0) as f32,
                ..Stroke::default()
            };
            if let Some(path) = pb.finish() {
                pixmap.stroke_path(&path, &paint(*color), &stroke, Transform::identity(), None);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ink_columns(pixmap: &Pixmap) -> Vec<u32> {
        let w = pixmap.width();
        let mut cols: Vec<u32> = pixmap
            .pixels()
            .iter()
            .enumerate()
            .filter(|(_, p)| p.red() < 128 && p.alpha() == 255)
            .map(|(i, _)| i as u32 % w)
            .collect();
        cols.sort_unstable();
        cols.dedup();
        cols
    }

    #[test]
    fn text_is_drawn_where_its_size_says() {
        let mut pixmap = Pixmap::new(200, 40).expect("pixmap");
        pixmap.fill(tiny_skia::Color::WHITE);
        // "M" has ink in its outer columns at both ends of the text.
        draw_text(&mut pixmap, 10.0, 5.0, "Mom M", 2, INK);
        let cols = ink_columns(&pixmap);
        let (w, _) = text_size("Mom M", 2);
        assert_eq!(cols.first(), Some(&10));
        assert_eq!(cols.last(), Some(&(10 + w - 1)));
    }

    #[test]
    fn entries_wrap_into_rows_that_fit() {
        let key = Key {
            scale_bar: None,
            entries: (0..6)
                .map(|i| LegendEntry::line(&format!("entry {i}"), INK, 2.0, None))
                .collect(),
        };
        let one = Key::entry_width(&key.entries[0], 1);
        let gap = ENTRY_GAP_FONT_PX;
        // Room for exactly two entries per row.
        let width = (2.0 * one + gap + 1.0) as u32;
        assert_eq!(key.height(width, 1), 3 * ROW_FONT_PX + 2);
        assert_eq!(key.height(10_000, 1), ROW_FONT_PX + 2);
        assert_eq!(Key::default().height(500, 2), 0);
    }

    #[test]
    fn long_text_is_cut_with_an_ellipsis() {
        let cut = fit_text("fold along the diagonal", 60, 1);
        assert!(cut.ends_with('…'));
        assert!(text_size(&cut, 1).0 <= 60);
        assert_eq!(fit_text("short", 60, 1), "short");
    }
}
