//! What a profile's own command lines (preamble, postamble, pen commands) do to a job's
//! time: moves, dwells and stops. A small reader for the plan's estimate; the simulated
//! machine reads whole programs with its own parser (`sim`).
//!
//! Recognised: `G0`/`G1` with `X`/`Y` (absolute, millimetres, the feed of `F` or the
//! machine's maximum), `G28` (rapid to the origin), `G4 P` (dwell in the profile's unit),
//! and the words that wait for motion: `M0 M1 M2 M30 M3 M4 M5 M7 M8 M9 M400 M64 M65 M68` and
//! GRBL `$` commands. Everything else takes no time.

use glam::DVec2;

use super::profile::{DwellUnit, MachineProfile};

/// What one command line does to the time.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Effect {
    /// A straight move to `to` (mm), rapid or at `feed_mm_min`.
    Move {
        /// Target, machine coordinates, mm.
        to: DVec2,
        /// Rapid (travel feed).
        rapid: bool,
        /// Feed of a `G1`, mm/min.
        feed_mm_min: f64,
    },
    /// Wait for motion to finish, then `seconds`.
    Dwell(f64),
    /// Wait for motion to finish.
    Stop,
}

/// The effects of `lines` run from `at` on `machine`.
pub fn effects(lines: &[String], at: DVec2, machine: &MachineProfile) -> Vec<Effect> {
    let mut out = Vec::new();
    let mut pos = at;
    let mut rapid = true;
    let mut feed = machine.max_feed_mm_min;
    for line in lines {
        let words = words(line);
        if line.trim_start().starts_with('$') {
            out.push(Effect::Stop);
            continue;
        }
        let (mut x, mut y, mut p, mut dwell, mut home) = (None, None, None, false, false);
        let mut stop = false;
        for (letter, value) in words {
            match letter {
                'G' if value == 0.0 || value == 1.0 => rapid = value == 0.0,
                'G' if value == 4.0 => dwell = true,
                'G' if value == 28.0 => home = true,
                'M' if [0.0, 1.0, 2.0, 30.0, 3.0, 4.0, 5.0, 7.0, 8.0, 9.0, 400.0]
                    .contains(&value)
                    || (64.0..=65.0).contains(&value)
                    || value == 68.0 =>
                {
                    stop = true;
                }
                'X' => x = Some(value),
                'Y' => y = Some(value),
                'F' if value > 0.0 => feed = value,
                'P' => p = Some(value),
                _ => {}
            }
        }
        if stop {
            out.push(Effect::Stop);
        }
        if dwell {
            let s = p.unwrap_or(0.0).max(0.0);
            let seconds = match machine.dwell_unit {
                DwellUnit::Seconds => s,
                DwellUnit::Milliseconds => s / 1000.0,
            };
            out.push(Effect::Dwell(seconds));
            continue;
        }
        if home {
            pos = DVec2::ZERO;
            out.push(Effect::Move {
                to: pos,
                rapid: true,
                feed_mm_min: feed,
            });
            continue;
        }
        if x.is_some() || y.is_some() {
            pos = DVec2::new(x.unwrap_or(pos.x), y.unwrap_or(pos.y));
            out.push(Effect::Move {
                to: pos,
                rapid,
                feed_mm_min: feed,
            });
        }
    }
    out
}

/// A G-code line compared loosely: comments (`;…`, `(…)`) and blanks removed, upper case.
pub fn normalize(line: &str) -> String {
    let mut out = String::new();
    let mut depth = 0;
    for c in line.chars() {
        match c {
            ';' if depth == 0 => break,
            '(' => depth += 1,
            ')' if depth > 0 => depth -= 1,
            _ if depth == 0 && !c.is_whitespace() => out.push(c.to_ascii_uppercase()),
            _ => {}
        }
    }
    out
}

/// The letter–number words of a G-code line, comments (`;…`, `(…)`) removed.
fn words(line: &str) -> Vec<(char, f64)> {
    let text = normalize(line);
    let mut out = Vec::new();
    let mut chars = text.char_indices().peekable();
    while let Some((i, c)) = chars.next() {
        if !c.is_ascii_alphabetic() {
            continue;
        }
        let start = i + 1;
        let mut end = start;
        while let Some(&(j, d)) = chars.peek() {
            if d.is_ascii_digit() || d == '.' || d == '-' || d == '+' {
                end = j + d.len_utf8();
                chars.next();
            } else {
                break;
            }
        }
        if let Ok(v) = text[start..end].parse::<f64>() {
            out.push((c, v));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::machine::{Bed, Corner, Dialect};

    #[test]
    fn reads_moves_dwells_and_stops() {
        let bed = Bed {
            width_mm: 100.0,
            height_mm: 100.0,
            origin: Corner::BottomLeft,
            y_flipped: false,
        };
        let m = MachineProfile::generic_laser(Dialect::Marlin, bed);
        let lines: Vec<String> = [
            "G0 X10 Y5 (park)",
            "g4 p250",
            "M5 ; off",
            "G1 X20 F600",
            "G21",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect();
        let e = effects(&lines, DVec2::ZERO, &m);
        assert_eq!(
            e,
            vec![
                Effect::Move {
                    to: DVec2::new(10.0, 5.0),
                    rapid: true,
                    feed_mm_min: 6000.0
                },
                Effect::Dwell(0.25),
                Effect::Stop,
                Effect::Move {
                    to: DVec2::new(20.0, 5.0),
                    rapid: false,
                    feed_mm_min: 600.0
                },
            ]
        );
    }
}
