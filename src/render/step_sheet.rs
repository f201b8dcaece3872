//! A sheet of pictures, one per folding step, each with its caption, all at one scale.
//!
//! The panels share one camera and one framing, fitted to the union of every state's drawn
//! vertices (as the frames of an animation do, [`super::view3d`]), so a model that gets
//! smaller as it is folded is seen getting smaller. Panels are square, `view.width` pixels,
//! up to [`COLUMNS`] to a row, with the caption under each: its lines (split at `\n`) wrapped
//! at word boundaries to the panel's width, at most [`MAX_CAPTION_LINES`] of them, drawn with
//! the shared key component ([`super::legend`]).

use image::RgbaImage;
use tiny_skia::{Color, Pixmap};

use super::legend::{self, INK, draw_text, fill_rect, fit_text, text_size};
use super::shade::{draw_state, pixmap_to_rgba};
use super::view3d::{Framing, View3d};
use super::{MAX_SIZE, RenderError};
use crate::pattern::FoldedState;

/// Most panels in a row.
pub const COLUMNS: u32 = 4;
/// Most lines of one caption.
pub const MAX_CAPTION_LINES: usize = 3;
/// Colour of the thin line between panels, RGBA.
const RULE: [u8; 4] = [200, 200, 200, 255];

/// The caption's font pixel size for panels `width` pixels wide: at least 2, else that of
/// [`legend::font_px_for`].
pub fn caption_font_px(width: u32) -> u32 {
    legend::font_px_for(width).max(2)
}

/// `text` split at `\n` and wrapped at spaces to lines of at most `max_px` pixels, at most
/// [`MAX_CAPTION_LINES`] lines (the last cut with `…` when more would follow).
pub fn wrap_caption(text: &str, max_px: u32, font_px: u32) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for paragraph in text.split('\n') {
        let mut line = String::new();
        for word in paragraph.split_whitespace() {
            let candidate = if line.is_empty() {
                word.to_string()
            } else {
                format!("{line} {word}")
            };
            if line.is_empty() || text_size(&candidate, font_px).0 <= max_px {
                line = candidate;
            } else {
                lines.push(std::mem::replace(&mut line, word.to_string()));
            }
        }
        lines.push(line);
    }
    if lines.len() > MAX_CAPTION_LINES {
        lines.truncate(MAX_CAPTION_LINES);
        if let Some(last) = lines.last_mut() {
            last.push_str(" …");
        }
    }
    lines
        .into_iter()
        .map(|l| fit_text(&l, max_px, font_px))
        .collect()
}

/// Draws one panel per state with `captions[i]` under panel `i` (missing captions are
/// empty), as an RGBA image.
pub fn step_sheet_rgba(
    states: &[FoldedState],
    captions: &[String],
    view: &View3d,
) -> Result<RgbaImage, RenderError> {
    if states.is_empty() {
        return Err(RenderError::NoFrames);
    }
    let side = view.width;
    // The panels carry captions of their own, no key band.
    let view = View3d {
        height: Some(side),
        key: None,
        ..view.clone()
    };
    let (camera, framing) = Framing::fit(states, &view)?;
    let font_px = caption_font_px(side);
    let pad = 2 * font_px;
    let wrapped: Vec<Vec<String>> = (0..states.len())
        .map(|i| {
            let text = captions.get(i).map_or("", String::as_str);
            wrap_caption(text, side.saturating_sub(2 * pad), font_px)
        })
        .collect();
    let lines = wrapped.iter().map(Vec::len).max().unwrap_or(0) as u32;
    let line_h = (legend::text_size("A", font_px).1) + 2 * font_px;
    let band = lines * line_h + 2 * pad;
    let cols = (states.len() as u32).clamp(1, COLUMNS);
    let rows = (states.len() as u32).div_ceil(cols);
    let (width, height) = (side * cols, (side + band) * rows);
    if width > MAX_SIZE || height > MAX_SIZE {
        return Err(RenderError::Option {
            name: "width",
            value: side.to_string(),
            expected: "a panel width whose sheet stays within 16384 pixels each way",
        });
    }
    let mut sheet = Pixmap::new(width, height).ok_or(RenderError::Allocation { width, height })?;
    sheet.fill(Color::WHITE);
    for (i, state) in states.iter().enumerate() {
        let (c, r) = (i as u32 % cols, i as u32 / cols);
        let (x, y) = (c * side, r * (side + band));
        let panel = draw_state(state, &view, &camera, &framing)?;
        sheet.draw_pixmap(
            x as i32,
            y as i32,
            panel.as_ref(),
            &tiny_skia::PixmapPaint::default(),
            tiny_skia::Transform::identity(),
            None,
        );
        for (k, line) in wrapped[i].iter().enumerate() {
            let ty = y + side + pad + k as u32 * line_h;
            draw_text(
                &mut sheet,
                f64::from(x + pad),
                f64::from(ty),
                line,
                font_px,
                INK,
            );
        }
        // Thin rules between panels.
        fill_rect(
            &mut sheet,
            f64::from(x),
            f64::from(y),
            1.0,
            f64::from(side + band),
            RULE,
        );
        fill_rect(
            &mut sheet,
            f64::from(x),
            f64::from(y),
            f64::from(side),
            1.0,
            RULE,
        );
    }
    pixmap_to_rgba(sheet)
}

/// As [`step_sheet_rgba`], as PNG bytes.
pub fn step_sheet_png(
    states: &[FoldedState],
    captions: &[String],
    view: &View3d,
) -> Result<Vec<u8>, RenderError> {
    let image = step_sheet_rgba(states, captions, view)?;
    let mut bytes = std::io::Cursor::new(Vec::new());
    image
        .write_to(&mut bytes, image::ImageFormat::Png)
        .map_err(|e| RenderError::Encode(e.to_string()))?;
    Ok(bytes.into_inner())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn captions_wrap_at_words_and_stop_at_three_lines() {
        let lines = wrap_caption("Step 4: tuck-in\nfront: right kite tucked in", 100, 1);
        assert_eq!(lines[0], "Step 4: tuck-in");
        assert!(lines.len() >= 2);
        assert!(lines.iter().all(|l| text_size(l, 1).0 <= 100));
        let long = "a b c d e f g h i j k l m n o p q r s t u v w x y z".repeat(4);
        let cut = wrap_caption(&long, 60, 1);
        assert_eq!(cut.len(), MAX_CAPTION_LINES);
        assert!(cut[2].ends_with('…'));
    }
}
