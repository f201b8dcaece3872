//! The key every picture carries: text, a legend (what each colour and dash means), a scale
//! bar in millimetres, captions and numbered markers, drawn with the bitmap [`font`] into a
//! tiny-skia pixmap. One component, shared by the pattern preview, the toolpath picture of
//! the simulated machine, the fold-step sheet and the check rings, so every picture reads the
//! same way.
//!
//! **Sizes.** Text is drawn in font pixels of `font_px` image pixels each ([`font_px_for`]:
//! one per 240 pixels of image width, 1 to 4), so a 900-pixel picture has 21-pixel capitals.
//! A [`Key`] starts with an optional caption (what the picture shows, wrapped in up to three
//! rows), then lays its items
//! (an optional scale bar, an optional colour scale, then the legend entries) left to right in
//! rows that fit the width it is given, and [`Key::height`] says how tall the band is before
//! anything is drawn, so a renderer can size its image first. [`title_height`] and
//! [`draw_title`] draw a one-line title above a picture, and [`png_with_text`] encodes a
//! picture as PNG with its title or caption stored as text too.

use tiny_skia::{LineCap, Paint, PathBuilder, Pixmap, Rect, Stroke, StrokeDash, Transform};

use super::RenderError;
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
    /// A filled box with a thin dark border, as a sample of a surface's colour (the paper's
    /// front or back in a 3D view).
    Fill {
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

    /// A filled box sample.
    pub fn fill(label: &str, color: [u8; 4]) -> Self {
        LegendEntry {
            swatch: Swatch::Fill { color },
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

/// Length of a colour scale's gradient, in font pixels.
const GRADIENT_FONT_PX: f64 = 40.0;

/// A colour scale: what the colours of [`super::heat_color`] measure, as a gradient from the
/// scale's low end (blue) to its high end (red), labelled `label low [gradient] high unit`.
#[derive(Clone, Debug, PartialEq)]
pub struct ColourScale {
    /// What the colours measure ("bar strain").
    pub label: String,
    /// The value at the blue end, in `unit`.
    pub low: f64,
    /// The value at the red end, in `unit` (values above it are drawn red too).
    pub high: f64,
    /// The unit of `low` and `high` ("%").
    pub unit: String,
}

impl ColourScale {
    /// The texts before and after the gradient.
    fn texts(&self) -> (String, String) {
        (
            format!("{} {}", self.label, short_number(self.low)),
            format!("{} {}", short_number(self.high), self.unit),
        )
    }

    /// Pixel width at `font_px`.
    fn width(&self, font_px: u32) -> f64 {
        let fp = f64::from(font_px);
        let (before, after) = self.texts();
        let text = f64::from(text_size(&before, font_px).0 + text_size(&after, font_px).0);
        text + (GRADIENT_FONT_PX + 2.0 * GAP_FONT_PX) * fp
    }

    /// Draws the scale with its top-left at `(x, y)`.
    fn draw(&self, pixmap: &mut Pixmap, x: f64, y: f64, font_px: u32) {
        let fp = f64::from(font_px);
        let (before, after) = self.texts();
        draw_text(pixmap, x, y, &before, font_px, INK);
        let gx = x + f64::from(text_size(&before, font_px).0) + GAP_FONT_PX * fp;
        let len = (GRADIENT_FONT_PX * fp).round();
        let h = f64::from(font::GLYPH_HEIGHT) * fp;
        let steps = len as u32;
        for i in 0..steps {
            let t = f64::from(i) / f64::from(steps.saturating_sub(1).max(1));
            let [r, g, b] = super::heat_color(t, 1.0);
            fill_rect(pixmap, gx + f64::from(i), y, 1.0, h, [r, g, b, 255]);
        }
        let ax = gx + len + GAP_FONT_PX * fp;
        draw_text(pixmap, ax, y, &after, font_px, INK);
    }
}

/// A number in at most three significant digits, without trailing zeros ("0", "0.018",
/// "12.5", "1500").
pub fn short_number(v: f64) -> String {
    if !v.is_finite() {
        return "?".to_string();
    }
    if v == 0.0 {
        return "0".to_string();
    }
    let digits = 2 - v.abs().log10().floor() as i32;
    let decimals = digits.clamp(0, 12) as usize;
    let text = format!("{v:.decimals$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}

/// A band under a picture: an optional caption row, then a scale bar, a colour scale and
/// legend entries, left to right, wrapped in rows.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Key {
    /// What the picture shows, in rows of its own above the items (wrapped at spaces to the
    /// band's width, at most three rows, cut with `…` beyond).
    pub caption: Option<String>,
    /// The scale bar, first.
    pub scale_bar: Option<ScaleBar>,
    /// The colour scale, after the scale bar.
    pub colour_scale: Option<ColourScale>,
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
        self.entries.is_empty()
            && self.caption.is_none()
            && self.colour_scale.is_none()
            && self.scale_bar.and_then(|s| s.length()).is_none()
    }

    /// The caption's lines, wrapped at spaces to `width` pixels
    /// ([`super::step_sheet::wrap_caption`]: at most three, the last cut with `…`).
    fn caption_lines(&self, width: u32, font_px: u32) -> Vec<String> {
        self.caption
            .as_deref()
            .map(|c| super::step_sheet::wrap_caption(c, width, font_px))
            .unwrap_or_default()
    }

    fn entry_width(entry: &LegendEntry, font_px: u32) -> f64 {
        let fp = f64::from(font_px);
        let label = f64::from(text_size(&entry.label, font_px).0);
        (SWATCH_FONT_PX + GAP_FONT_PX) * fp + label
    }

    /// Item widths in pixels: the scale bar's (when drawn), the colour scale's, then each
    /// entry's.
    fn widths(&self, font_px: u32) -> Vec<f64> {
        let bar = self
            .scale_bar
            .filter(|s| s.length().is_some())
            .map(|s| s.width(font_px));
        let colours = self.colour_scale.as_ref().map(|c| c.width(font_px));
        bar.into_iter()
            .chain(colours)
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
        let caption = self.caption_lines(width, font_px).len() as u32;
        (rows + caption) * ROW_FONT_PX * font_px + 2 * font_px
    }

    /// Draws the key with its top-left corner at `(x, y)`, within `width` pixels.
    pub fn draw(&self, pixmap: &mut Pixmap, x: f64, y: f64, width: u32, font_px: u32) {
        let fp = f64::from(font_px);
        let row_h = f64::from(ROW_FONT_PX) * fp;
        let placed = self.place(f64::from(width), font_px);
        let mut items = placed.iter();
        let caption = self.caption_lines(width, font_px);
        for (i, line) in caption.iter().enumerate() {
            let row_y = y + fp + i as f64 * row_h;
            draw_text(pixmap, x, row_y, line, font_px, INK);
        }
        let first = caption.len() as f64 * row_h;
        let top = |p: &Placed| y + fp + first + f64::from(p.row) * row_h;
        let bar = self.scale_bar.filter(|s| s.length().is_some());
        if let Some((bar, p)) = bar.and_then(|b| items.next().map(|p| (b, p))) {
            bar.draw(pixmap, x + p.x, top(p), font_px);
        }
        if let Some((scale, p)) =
            (self.colour_scale.as_ref()).and_then(|c| items.next().map(|p| (c, p)))
        {
            scale.draw(pixmap, x + p.x, top(p), font_px);
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
        Swatch::Fill { color } => {
            let h = f64::from(font::GLYPH_HEIGHT) * fp;
            fill_rect(pixmap, x, y, len, h, INK);
            fill_rect(pixmap, x + 1.0, y + 1.0, len - 2.0, h - 2.0, *color);
        }
    }
}

/// The font pixel size and lines of a title `width` pixels wide: the largest size up to
/// `font_px` at which every word fits the width (1 if none does), wrapped at spaces, at
/// most three lines ([`super::step_sheet::wrap_caption`]).
fn title_lines(title: &str, width: u32, font_px: u32) -> (u32, Vec<String>) {
    let fits = |fp: u32| {
        title
            .split_whitespace()
            .all(|w| text_size(w, fp).0 <= width)
    };
    let fp = (1..=font_px.max(1)).rev().find(|&fp| fits(fp)).unwrap_or(1);
    (fp, super::step_sheet::wrap_caption(title, width, fp))
}

/// Height of the band [`draw_title`] draws `title` in, `width` pixels wide with font pixels
/// of at most `font_px`, pixels: a font pixel of space, then the title's rows ([`Key`]'s row
/// height), the last without its spacing below.
pub fn title_height(title: &str, width: u32, font_px: u32) -> u32 {
    let (fp, lines) = title_lines(title, width, font_px);
    let rows = lines.len() as u32;
    if rows == 0 {
        return 0;
    }
    fp + rows * ROW_FONT_PX * fp - (ROW_FONT_PX - font::GLYPH_HEIGHT) * fp
}

/// Draws `title` wrapped to `width` pixels with the top of its band at `(x, y)` (see
/// [`title_height`]).
pub fn draw_title(pixmap: &mut Pixmap, x: f64, y: f64, title: &str, width: u32, font_px: u32) {
    let (font_px, lines) = title_lines(title, width, font_px);
    let fp = f64::from(font_px);
    let row_h = f64::from(ROW_FONT_PX) * fp;
    for (i, line) in lines.iter().enumerate() {
        draw_text(pixmap, x, y + fp + i as f64 * row_h, line, font_px, INK);
    }
}

/// Encodes `pixmap` as PNG bytes with a `tEXt` chunk per `(keyword, text)` after the header
/// (keywords of 1 to 79 Latin-1 characters, e.g. "Title" or "Description"; characters outside
/// Latin-1 are stored as `?`), so a picture's title or caption can be read by programs too.
pub fn png_with_text(pixmap: &Pixmap, texts: &[(&str, &str)]) -> Result<Vec<u8>, RenderError> {
    let png = pixmap
        .encode_png()
        .map_err(|e| RenderError::Encode(e.to_string()))?;
    // The signature (8 bytes) and the IHDR chunk (4 length + 4 type + 13 data + 4 CRC).
    const AFTER_HEADER: usize = 8 + 25;
    if png.len() < AFTER_HEADER || &png[12..16] != b"IHDR" {
        return Err(RenderError::Encode("no PNG header".into()));
    }
    let latin1 = |s: &str| -> Vec<u8> {
        s.chars()
            .map(|c| u8::try_from(u32::from(c)).unwrap_or(b'?'))
            .collect()
    };
    let mut out = png[..AFTER_HEADER].to_vec();
    for (keyword, text) in texts {
        let key = latin1(keyword);
        if key.is_empty() || key.len() > 79 {
            return Err(RenderError::Encode(format!(
                "bad PNG text keyword {keyword:?}"
            )));
        }
        let mut body = b"tEXt".to_vec();
        body.extend(key);
        body.push(0);
        body.extend(
            latin1(text)
                .into_iter()
                .map(|b| if b == 0 { b'?' } else { b }),
        );
        let len = u32::try_from(body.len() - 4)
            .map_err(|_| RenderError::Encode("PNG text too long".into()))?;
        out.extend(len.to_be_bytes());
        out.extend(&body);
        out.extend(crc32(&body).to_be_bytes());
    }
    out.extend(&png[AFTER_HEADER..]);
    Ok(out)
}

/// The CRC-32 (ISO-HDLC, reflected polynomial 0xEDB88320) PNG chunks end with.
fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = u32::MAX;
    for &b in bytes {
        crc ^= u32::from(b);
        for _ in 0..8 {
            let mask = (crc & 1).wrapping_neg();
            crc = (crc >> 1) ^ (0xEDB8_8320 & mask);
        }
    }
    !crc
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
            entries: (0..6)
                .map(|i| LegendEntry::line(&format!("entry {i}"), INK, 2.0, None))
                .collect(),
            ..Key::default()
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
    fn a_caption_takes_rows_of_its_own() {
        let key = Key {
            caption: Some("opened to 90°".into()),
            entries: vec![LegendEntry::fill("paper", [200, 200, 200, 255])],
            ..Key::default()
        };
        assert_eq!(key.height(10_000, 1), 2 * ROW_FONT_PX + 2);
        // Wrapped at its space when the band is narrower than the caption.
        let narrow = text_size("opened to", 1).0 + 2;
        assert_eq!(key.height(narrow, 1), 3 * ROW_FONT_PX + 2);
    }

    #[test]
    fn short_numbers_keep_three_significant_digits() {
        assert_eq!(short_number(0.0), "0");
        assert_eq!(short_number(0.0183), "0.0183");
        assert_eq!(short_number(1.0), "1");
        assert_eq!(short_number(12.54), "12.5");
        assert_eq!(short_number(1500.0), "1500");
    }

    #[test]
    fn png_text_chunks_are_read_back_by_a_decoder() {
        let mut pixmap = Pixmap::new(20, 10).expect("pixmap");
        pixmap.fill(tiny_skia::Color::WHITE);
        let png = png_with_text(&pixmap, &[("Title", "m.gcode on grbl-diode, 90°")]).expect("png");
        // The check value of the CRC-32 of "123456789".
        assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
        let img = image::load_from_memory(&png).expect("a valid PNG");
        assert_eq!(img.width(), 20);
        let at = png
            .windows(4)
            .position(|w| w == b"tEXt")
            .expect("a text chunk");
        assert!(png[at..].starts_with(b"tEXtTitle\0m.gcode on grbl-diode, 90\xb0"));
    }

    #[test]
    fn a_title_shrinks_until_its_longest_word_fits() {
        let title = "job a-long-file-name.gcode, machine grbl-diode";
        let word = text_size("a-long-file-name.gcode,", 1).0;
        // Room for the file name at one font pixel, not at two: one size smaller.
        let (fp, lines) = title_lines(title, word + 4, 2);
        assert_eq!(fp, 1);
        assert!(lines.iter().any(|l| l.contains("a-long-file-name.gcode")));
        assert!(lines.iter().all(|l| !l.contains('…')));
        let (fp, lines) = title_lines(title, 10_000, 3);
        assert_eq!((fp, lines.len()), (3, 1));
        assert_eq!(title_height(title, 10_000, 3), 3 + 7 * 3);
    }

    #[test]
    fn long_text_is_cut_with_an_ellipsis() {
        let cut = fit_text("fold along the diagonal", 60, 1);
        assert!(cut.ends_with('…'));
        assert!(text_size(&cut, 1).0 <= 60);
        assert_eq!(fit_text("short", 60, 1), "short");
    }
}
