//! A tiny 5 × 7 bitmap font for scale-bar labels.
//!
//! It covers exactly what the labels need: the digits, `.`, `-`, space and the letters of
//! "mm" and "units" (`m u n i t s`). Each glyph is seven rows of five bits, the most
//! significant of the five being the leftmost column; glyphs advance by six columns (one
//! column of spacing). Characters outside the set draw as an empty box, so a missing glyph is
//! visible rather than silently dropped. The glyphs were drawn for this crate.

/// Glyph height in font pixels.
pub const GLYPH_HEIGHT: u32 = 7;
/// Glyph width in font pixels.
pub const GLYPH_WIDTH: u32 = 5;
/// Horizontal advance per character in font pixels.
pub const ADVANCE: u32 = 6;

/// The rows of a glyph (bit 4 = leftmost column), or `None` if the font lacks it.
pub fn glyph(c: char) -> Option<[u8; 7]> {
    Some(match c {
        '0' => [0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E],
        '1' => [0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E],
        '2' => [0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F],
        '3' => [0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E],
        '4' => [0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02],
        '5' => [0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E],
        '6' => [0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E],
        '7' => [0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08],
        '8' => [0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E],
        '9' => [0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C],
        '.' => [0x00, 0x00, 0x00, 0x00, 0x00, 0x0C, 0x0C],
        '-' => [0x00, 0x00, 0x00, 0x1F, 0x00, 0x00, 0x00],
        ' ' => [0x00; 7],
        'm' => [0x00, 0x00, 0x1A, 0x15, 0x15, 0x15, 0x15],
        'u' => [0x00, 0x00, 0x11, 0x11, 0x11, 0x13, 0x0D],
        'n' => [0x00, 0x00, 0x16, 0x19, 0x11, 0x11, 0x11],
        'i' => [0x04, 0x00, 0x0C, 0x04, 0x04, 0x04, 0x0E],
        't' => [0x08, 0x08, 0x1C, 0x08, 0x08, 0x09, 0x06],
        's' => [0x00, 0x00, 0x0F, 0x10, 0x0E, 0x01, 0x1E],
        _ => return None,
    })
}

/// The glyph for `c`, or a hollow box for characters outside the font.
pub fn glyph_or_box(c: char) -> [u8; 7] {
    glyph(c).unwrap_or([0x1F, 0x11, 0x11, 0x11, 0x11, 0x11, 0x1F])
}

/// Width of `text` in font pixels (no trailing spacing).
pub fn text_width(text: &str) -> u32 {
    let n = text.chars().count() as u32;
    if n == 0 { 0 } else { n * ADVANCE - 1 }
}

/// Calls `dot(column, row)` for every set pixel of `text`, in font pixels from the top-left.
pub fn for_each_dot(text: &str, mut dot: impl FnMut(u32, u32)) {
    for (i, c) in text.chars().enumerate() {
        let rows = glyph_or_box(c);
        for (row, bits) in rows.iter().enumerate() {
            for col in 0..GLYPH_WIDTH {
                if bits & (0x10 >> col) != 0 {
                    dot(i as u32 * ADVANCE + col, row as u32);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn label_characters_are_covered_and_fit_five_columns() {
        for c in "0123456789.- munits".chars() {
            let g = glyph(c).expect("glyph");
            assert!(g.iter().all(|&r| r < 0x20), "{c}");
        }
        assert!(glyph('x').is_none());
    }

    #[test]
    fn dots_stay_inside_the_text_box() {
        let text = "10 mm";
        let w = text_width(text);
        let mut count = 0;
        for_each_dot(text, |x, y| {
            assert!(x < w && y < GLYPH_HEIGHT);
            count += 1;
        });
        assert!(count > 20);
    }
}
