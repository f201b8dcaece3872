//! Decoding a line's words into one block: which G and M codes it holds and its values.
//!
//! Recognised G codes: `G0 G1` (motion), `G4` (dwell), `G20 G21` (units), `G90 G91`
//! (distance mode), `G28` (go home, taken as a rapid to the bed origin through any given
//! point), and codes without effect on a two-axis laser or plotter, accepted and ignored:
//! `G17` (XY plane), `G40` (no cutter compensation), `G49` (no tool-length offset), `G54`
//! (first work offset, assumed zero), `G61 G61.1 G64` (path control), `G80` (no canned cycle),
//! `G94` (feed per minute). Rejected as unsupported: arcs `G2 G3`, the other planes, offsets
//! (`G10 G43 G53 G55`–`G59.3 G92`), inverse-time feed `G93`. Any other G code is unknown.
//!
//! Recognised M codes: `M3 M4 M5` (laser), `M2 M30` (end), `M0 M1` (pause), `M7 M8 M9`
//! (coolant, i.e. air assist: a stop, no other effect), on LinuxCNC the motion outputs
//! `M62 M63` (digital, synchronised with motion), `M64 M65` (digital, immediate), `M67`
//! (analog, synchronised) and `M68` (analog, immediate), and on Marlin `M400` (wait),
//! `M18 M84` (motors off) and `M106 M107` (fan: its `S` is the fan speed, not laser power).
//!
//! Letters: `N` (ignored), `G M X Y Z F S P`, and on LinuxCNC `E Q` (output number and
//! value of `M67`/`M68`). Any other letter is unknown. A letter given twice
//! (other than G and M), or two codes of one modal group, is malformed.

use super::parse::Word;
use super::report::ViolationKind;
use crate::geom::tolerance::RELATIVE;
use crate::machine::Dialect;

/// A G or M code in tenths (`G61.1` is 611).
pub(crate) type Code = u32;

/// The decoded words of one line.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Block {
    /// Motion: `Some(0)` rapid, `Some(1)` feed.
    pub motion: Option<u32>,
    /// `G4` present.
    pub dwell: bool,
    /// `G28` present.
    pub home: bool,
    /// `Some(true)` for `G20` (inches), `Some(false)` for `G21`.
    pub inches: Option<bool>,
    /// `Some(true)` for `G91` (relative), `Some(false)` for `G90`.
    pub relative: Option<bool>,
    /// Laser: `Some(3)`, `Some(4)`, `Some(5)`.
    pub spindle: Option<u32>,
    /// `M2` or `M30` present.
    pub end: bool,
    /// A code that makes the machine wait for motion to finish (`M0 M1 M400`).
    pub sync: bool,
    /// LinuxCNC motion output: `Some(62)` … `Some(68)`.
    pub output: Option<u32>,
    /// `M7`/`M8`/`M9` present (air assist: waits for motion).
    pub coolant: bool,
    /// E word (LinuxCNC analog output number).
    pub e: Option<f64>,
    /// Q word (LinuxCNC analog output value).
    pub q: Option<f64>,
    /// `M106`/`M107` present: `S` is a fan speed.
    pub fan: bool,
    /// `G64` present (`P` is a tolerance).
    pub blend: bool,
    /// Axis and value words.
    pub x: Option<f64>,
    /// Y word.
    pub y: Option<f64>,
    /// Z word.
    pub z: Option<f64>,
    /// F word.
    pub f: Option<f64>,
    /// S word.
    pub s: Option<f64>,
    /// P word.
    pub p: Option<f64>,
}

/// Why a block was rejected.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct BlockError {
    /// Kind of problem.
    pub kind: ViolationKind,
    /// What is wrong.
    pub message: String,
}

fn error(kind: ViolationKind, message: String) -> BlockError {
    BlockError { kind, message }
}

/// Decodes the words of one line for `dialect`.
pub(crate) fn decode(words: &[Word], dialect: Dialect) -> Result<Block, BlockError> {
    let mut b = Block::default();
    for w in words {
        match w.letter {
            'N' => {}
            'G' => g_code(&mut b, code(w)?)?,
            'M' => m_code(&mut b, code(w)?, dialect)?,
            'X' => set(&mut b.x, w)?,
            'Y' => set(&mut b.y, w)?,
            'Z' => set(&mut b.z, w)?,
            'F' => set(&mut b.f, w)?,
            'S' => set(&mut b.s, w)?,
            'P' => set(&mut b.p, w)?,
            // Marlin's `M3/M4 … I1` turns on inline laser power (power follows each move's
            // `S`), which is how this simulator models every laser already.
            'I' if dialect == Dialect::Marlin => {}
            'E' if dialect == Dialect::LinuxCnc => set(&mut b.e, w)?,
            'Q' if dialect == Dialect::LinuxCnc => set(&mut b.q, w)?,
            other => {
                return Err(error(
                    ViolationKind::UnknownWord,
                    format!("unknown word {other}{}", w.value),
                ));
            }
        }
    }
    Ok(b)
}

/// The code of a G or M word in tenths; only one decimal is meaningful.
fn code(w: &Word) -> Result<Code, BlockError> {
    let tenths = w.value * 10.0;
    if w.value < 0.0 || (tenths - tenths.round()).abs() > RELATIVE || tenths > 100_000.0 {
        return Err(error(
            ViolationKind::UnknownWord,
            format!("unknown code {}{}", w.letter, w.value),
        ));
    }
    Ok(tenths.round() as Code)
}

fn set(slot: &mut Option<f64>, w: &Word) -> Result<(), BlockError> {
    if slot.is_some() {
        return Err(error(
            ViolationKind::Malformed,
            format!("word {} appears twice", w.letter),
        ));
    }
    *slot = Some(w.value);
    Ok(())
}

fn once<T: Copy>(slot: &mut Option<T>, value: T, group: &str) -> Result<(), BlockError> {
    if slot.is_some() {
        return Err(error(
            ViolationKind::Malformed,
            format!("two {group} codes on one line"),
        ));
    }
    *slot = Some(value);
    Ok(())
}

fn g_code(b: &mut Block, c: Code) -> Result<(), BlockError> {
    match c {
        0 | 10 => once(&mut b.motion, c / 10, "motion")?,
        40 => b.dwell = true,
        200 | 210 => once(&mut b.inches, c == 200, "units")?,
        900 | 910 => once(&mut b.relative, c == 910, "distance-mode")?,
        280 => b.home = true,
        640 => b.blend = true,
        170 | 400 | 490 | 540 | 610 | 611 | 800 | 940 => {}
        20 | 30 => {
            return Err(error(
                ViolationKind::Unsupported,
                format!("arc G{} is not supported: write arcs as lines", c / 10),
            ));
        }
        100 | 180 | 190 | 430 | 530 | 550..=593 | 920..=923 | 930 => {
            return Err(error(
                ViolationKind::Unsupported,
                format!("G{} is not supported by the simulator", show(c)),
            ));
        }
        _ => {
            return Err(error(
                ViolationKind::UnknownWord,
                format!("unknown code G{}", show(c)),
            ));
        }
    }
    Ok(())
}

fn m_code(b: &mut Block, c: Code, dialect: Dialect) -> Result<(), BlockError> {
    let marlin = dialect == Dialect::Marlin;
    match c {
        30 | 40 | 50 => once(&mut b.spindle, c / 10, "laser")?,
        20 | 300 => b.end = true,
        0 | 10 => b.sync = true,
        70 | 80 | 90 => b.coolant = true,
        620 | 630 | 640 | 650 | 670 | 680 if dialect == Dialect::LinuxCnc => {
            once(&mut b.output, c / 10, "motion output")?;
        }
        4000 if marlin => b.sync = true,
        180 | 840 if marlin => {}
        1060 | 1070 if marlin => b.fan = true,
        _ => {
            return Err(error(
                ViolationKind::UnknownWord,
                format!("unknown code M{}", show(c)),
            ));
        }
    }
    Ok(())
}

/// A code in tenths as written (`611` → `61.1`).
fn show(c: Code) -> String {
    if c.is_multiple_of(10) {
        (c / 10).to_string()
    } else {
        format!("{}.{}", c / 10, c % 10)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn words(s: &[(char, f64)]) -> Vec<Word> {
        s.iter()
            .map(|&(letter, value)| Word { letter, value })
            .collect()
    }

    #[test]
    fn decodes_a_feed_move() {
        let b = decode(
            &words(&[('G', 1.0), ('X', 2.0), ('F', 600.0), ('S', 10.0)]),
            Dialect::Grbl,
        )
        .unwrap();
        assert_eq!(
            (b.motion, b.x, b.f, b.s),
            (Some(1), Some(2.0), Some(600.0), Some(10.0))
        );
    }

    #[test]
    fn rejects_conflicts_and_unknowns() {
        let kind = |w: &[(char, f64)], d| decode(&words(w), d).unwrap_err().kind;
        assert_eq!(
            kind(&[('G', 0.0), ('G', 1.0)], Dialect::Grbl),
            ViolationKind::Malformed
        );
        assert_eq!(
            kind(&[('X', 0.0), ('X', 1.0)], Dialect::Grbl),
            ViolationKind::Malformed
        );
        assert_eq!(
            kind(&[('Q', 5.0)], Dialect::Grbl),
            ViolationKind::UnknownWord
        );
        assert_eq!(
            kind(&[('G', 2.0)], Dialect::Grbl),
            ViolationKind::Unsupported
        );
        assert_eq!(
            kind(&[('G', 92.0)], Dialect::Grbl),
            ViolationKind::Unsupported
        );
        assert_eq!(
            kind(&[('M', 400.0)], Dialect::Grbl),
            ViolationKind::UnknownWord
        );
        assert_eq!(
            kind(&[('G', 1.25)], Dialect::Grbl),
            ViolationKind::UnknownWord
        );
        assert!(decode(&words(&[('M', 400.0)]), Dialect::Marlin).is_ok());
        assert!(decode(&words(&[('G', 61.1)]), Dialect::LinuxCnc).is_ok());
    }
}
