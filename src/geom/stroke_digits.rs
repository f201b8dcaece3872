//! Single-stroke digits: a seven-segment font for labels a machine engraves, marks or plots
//! (the cells of a calibration grid), drawn for this crate.
//!
//! A digit is `h` tall and `0.5 h` wide, its segments the usual seven (a top, b/c right,
//! d bottom, e/f left, g middle); characters advance by [`ADVANCE`] `h`. Besides `0`–`9` the
//! font has `-` (the middle segment), `.` (a short upright tick at the foot, `0.15 h` tall, so
//! a laser burns a visible mark rather than a dot of zero length) and the space. Lit segments
//! are chained into polylines where they meet (an `8` is one closed loop and the middle bar),
//! so a label needs few tool-on events. Coordinates are millimetres, y up, the text's
//! lower-left corner at the given origin.

use glam::DVec2;

/// Horizontal advance per character, in units of the height.
pub const ADVANCE: f64 = 0.8;
/// Width of a digit, in units of the height.
pub const DIGIT_WIDTH: f64 = 0.5;
/// Height of the decimal point's tick, in units of the height.
const POINT_TICK: f64 = 0.15;

/// Seven-segment corners: (0,0) bottom left … (1,2) top right, in digit widths and halves of
/// the height.
const SEGMENTS: [[(u8, u8); 2]; 7] = [
    [(0, 2), (1, 2)], // a: top
    [(1, 2), (1, 1)], // b: top right
    [(1, 1), (1, 0)], // c: bottom right
    [(1, 0), (0, 0)], // d: bottom
    [(0, 0), (0, 1)], // e: bottom left
    [(0, 1), (0, 2)], // f: top left
    [(0, 1), (1, 1)], // g: middle
];

/// Which segments (a…g as bits 0…6) each digit lights.
const DIGITS: [u8; 10] = [
    0b011_1111, 0b000_0110, 0b101_1011, 0b100_1111, 0b110_0110, 0b110_1101, 0b111_1101, 0b000_0111,
    0b111_1111, 0b110_1111,
];

/// Width of `text` at height `height`, mm: the advance of every character but the last, plus
/// the last one's width.
pub fn text_width(text: &str, height: f64) -> f64 {
    let n = text.chars().count();
    if n == 0 {
        return 0.0;
    }
    (n - 1) as f64 * ADVANCE * height + DIGIT_WIDTH * height
}

/// The strokes of `text`, `height` mm tall, its lower-left corner at `origin`; `Err` with the
/// first character the font lacks (see `supports`).
pub fn text_strokes(text: &str, origin: DVec2, height: f64) -> Result<Vec<Vec<DVec2>>, char> {
    let mut out = Vec::new();
    for (i, c) in text.chars().enumerate() {
        let at = origin + DVec2::new(i as f64 * ADVANCE * height, 0.0);
        out.extend(char_strokes(c, at, height)?);
    }
    Ok(out)
}

/// The strokes of one character at `at`.
fn char_strokes(c: char, at: DVec2, h: f64) -> Result<Vec<Vec<DVec2>>, char> {
    let corner =
        |(x, y): (u8, u8)| at + DVec2::new(f64::from(x) * DIGIT_WIDTH * h, f64::from(y) * h / 2.0);
    let lit: u8 = match c {
        '0'..='9' => DIGITS[c as usize - '0' as usize],
        '-' => 1 << 6,
        ' ' => 0,
        '.' => {
            let x = at.x + DIGIT_WIDTH * h / 2.0;
            return Ok(vec![vec![
                DVec2::new(x, at.y),
                DVec2::new(x, at.y + POINT_TICK * h),
            ]]);
        }
        other => return Err(other),
    };
    let segments: Vec<[DVec2; 2]> = (0..7)
        .filter(|k| lit & (1 << k) != 0)
        .map(|k| [corner(SEGMENTS[k][0]), corner(SEGMENTS[k][1])])
        .collect();
    Ok(chain(segments))
}

/// Joins segments that meet end to start (or end to end, reversed) into polylines, greedily
/// in the given order.
fn chain(mut segments: Vec<[DVec2; 2]>) -> Vec<Vec<DVec2>> {
    let mut out: Vec<Vec<DVec2>> = Vec::new();
    while !segments.is_empty() {
        let [a, b] = segments.remove(0);
        let mut line = vec![a, b];
        loop {
            let end = line[line.len() - 1];
            let Some(k) = segments.iter().position(|s| s[0] == end || s[1] == end) else {
                break;
            };
            let [p, q] = segments.remove(k);
            line.push(if p == end { q } else { p });
        }
        out.push(line);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn length(strokes: &[Vec<DVec2>]) -> f64 {
        strokes
            .iter()
            .flat_map(|s| s.windows(2))
            .map(|w| w[0].distance(w[1]))
            .sum()
    }

    #[test]
    fn eight_is_a_loop_and_a_bar_of_the_seven_segments_length() {
        let s = text_strokes("8", DVec2::ZERO, 2.0).unwrap();
        assert_eq!(s.len(), 2);
        // Three bars of 0.5 h and four uprights of h/2, h = 2 mm.
        assert!((length(&s) - (3.0 * 1.0 + 4.0 * 1.0)).abs() < 1e-12);
        assert_eq!(s[0].first(), s[0].last());
    }

    #[test]
    fn one_is_the_right_uprights_and_text_advances() {
        let s = text_strokes("11", DVec2::new(10.0, 5.0), 4.0).unwrap();
        assert_eq!(s.len(), 2);
        assert_eq!(
            s[0],
            vec![
                DVec2::new(12.0, 9.0),
                DVec2::new(12.0, 7.0),
                DVec2::new(12.0, 5.0)
            ]
        );
        assert!((s[1][0].x - (12.0 + ADVANCE * 4.0)).abs() < 1e-12);
        assert!((text_width("11", 4.0) - (ADVANCE * 4.0 + 2.0)).abs() < 1e-12);
    }

    #[test]
    fn unknown_characters_are_refused_and_spaces_draw_nothing() {
        assert_eq!(text_strokes("1x", DVec2::ZERO, 1.0), Err('x'));
        assert!(text_strokes(" ", DVec2::ZERO, 1.0).unwrap().is_empty());
        let point = text_strokes(".", DVec2::ZERO, 1.0).unwrap();
        assert!((length(&point) - POINT_TICK).abs() < 1e-12);
    }
}
