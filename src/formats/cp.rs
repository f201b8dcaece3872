//! ORIPA crease-pattern line lists (`.cp`).
//!
//! A `.cp` file holds one line segment per text line, five whitespace-separated fields:
//! `type x0 y0 x1 y1`. Types, as ORIPA defines them and as other editors (Oriedita, Box
//! Pleating Studio, Flat-Folder) extend them:
//!
//! | type | ORIPA meaning | read as | written for |
//! | --- | --- | --- | --- |
//! | 1 | cut line (the sheet's outline) | boundary `B` | boundary `B`, cut `C` |
//! | 2 | mountain | mountain `M` | mountain `M` |
//! | 3 | valley | valley `V` | valley `V` |
//! | 4 | auxiliary (later editors) | flat `F` | flat `F` |
//! | 0, other | none / auxiliary | flat `F` (types beyond 0–4 with a warning) | unassigned `U`, join `J` |
//!
//! ORIPA itself reads every type other than 1, 2 and 3 as an auxiliary line, which is what
//! flat means here. The format has no unassigned, cut or join lines and no fold angles, so a
//! round trip turns `C` into `B`, `U` and `J` into `F`, and drops fold angles, faces and
//! metadata. Writing flat lines as 4 and unassigned ones as 0 keeps the distinction for
//! readers that make it (Flat-Folder reads 0 as unassigned and 4 as flat).
//!
//! Coordinates: ORIPA draws the file's coordinates on screen unflipped, so its y axis points
//! down, like SVG; the reader negates y to get the pattern's y-up frame without mirroring,
//! and the writer negates it back. ORIPA's default sheet is 400 units wide, spanning
//! −200..200 on both axes; the coordinates carry no physical unit, so patterns read are
//! [`Units::Unitless`] (give them a size with `--size` or `--scale`); a pattern in millimetres
//! is written with its millimetre numbers. Numbers are written with
//! the shortest decimal form that parses back to the same `f64`, so a round trip is exact.
//!
//! The reader refuses lines with the wrong number of fields, a non-integer type, a number it
//! cannot parse, a value that is not finite or beyond [`MAX_COORDINATE`], and files without a
//! single line; it drops zero-length lines with a warning and planarises the result (shared
//! endpoints merged, crossings split).

use std::fmt::Write as _;

use glam::DVec2;

use super::{FindingKind, Imported, ParseError};
use crate::pattern::{Assignment, CreasePattern, MAX_COORDINATE, Units};

/// Most lines read from one file; larger files are refused with an error.
pub const MAX_LINES: usize = 10_000_000;

/// The ORIPA line type read for a type number (see the module table).
pub fn assignment_of(line_type: i64) -> Assignment {
    match line_type {
        1 => Assignment::Boundary,
        2 => Assignment::Mountain,
        3 => Assignment::Valley,
        _ => Assignment::Flat,
    }
}

/// The ORIPA line type written for an assignment (see the module table).
pub fn type_of(assignment: Assignment) -> u8 {
    match assignment {
        Assignment::Boundary | Assignment::Cut => 1,
        Assignment::Mountain => 2,
        Assignment::Valley => 3,
        Assignment::Flat => 4,
        Assignment::Unassigned | Assignment::Join => 0,
    }
}

/// Parses a `.cp` file's text into a planarised, unitless pattern (y up).
///
/// # Errors
/// A [`ParseError`] naming the line for a malformed line, and `file` when no line remains.
pub fn read_str(text: &str) -> Result<Imported, ParseError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut pattern = CreasePattern {
        units: Units::Unitless,
        ..CreasePattern::default()
    };
    let mut zero_length = Vec::new();
    let mut unusual: Vec<(usize, i64)> = Vec::new();
    for (index, line) in text.lines().enumerate() {
        let number = index + 1;
        let Some((line_type, a, b)) = parse_line(line)
            .map_err(|message| ParseError::new(format!("line {number}"), message))?
        else {
            continue;
        };
        if !KNOWN_TYPES.contains(&line_type) {
            unusual.push((number, line_type));
        }
        let assignment = assignment_of(line_type);
        if a == b {
            zero_length.push(number);
            continue;
        }
        if pattern.edges.len() >= MAX_LINES {
            return Err(ParseError::new(
                format!("line {number}"),
                format!("the file has more than {MAX_LINES} lines, the most read"),
            ));
        }
        pattern.add_segment(a, b, assignment);
    }
    if pattern.edges.is_empty() {
        let message = if zero_length.is_empty() {
            "no lines: a .cp file lists one line per row as `type x0 y0 x1 y1`".to_string()
        } else {
            "no lines of non-zero length".to_string()
        };
        return Err(ParseError::new("file", message));
    }
    let mut warnings = Vec::new();
    if !zero_length.is_empty() {
        warnings.push(FindingKind::ZeroLengthLines.warning(zero_length_warning(&zero_length)));
    }
    if let Some(&(first, line_type)) = unusual.first() {
        warnings.push(FindingKind::UnknownLineType.warning(format!(
            "{} line(s) of a type other than 0-4 (the first: line {first}, type {line_type}) \
             were read as auxiliary lines (flat), as ORIPA reads them",
            unusual.len()
        )));
    }
    super::finish_drawing(pattern, None, None, "lying", warnings)
}

/// The types ORIPA and later editors define (see the module table); others are read as
/// auxiliary lines with a warning.
const KNOWN_TYPES: std::ops::RangeInclusive<i64> = 0..=4;

/// One text line: `None` when blank, else the line type and the two end points (y up).
fn parse_line(line: &str) -> Result<Option<(i64, DVec2, DVec2)>, String> {
    let fields: Vec<&str> = line.split_whitespace().collect();
    if fields.is_empty() {
        return Ok(None);
    }
    let [kind, x0, y0, x1, y1] = fields[..] else {
        return Err(format!(
            "expected 5 fields `type x0 y0 x1 y1`, found {}",
            fields.len()
        ));
    };
    let line_type: i64 = kind.parse().map_err(|_| {
        format!(
            "line type {kind:?} is not an integer (1 cut, 2 mountain, 3 valley; 0, 4 and any \
             other whole number an auxiliary line, read as flat)"
        )
    })?;
    let a = DVec2::new(coordinate("x0", x0)?, -coordinate("y0", y0)?);
    let b = DVec2::new(coordinate("x1", x1)?, -coordinate("y1", y1)?);
    Ok(Some((line_type, a, b)))
}

/// One coordinate field, finite and within ±[`MAX_COORDINATE`].
fn coordinate(name: &str, field: &str) -> Result<f64, String> {
    let value: f64 = field
        .parse()
        .map_err(|_| format!("{name} {field:?} is not a number"))?;
    if !value.is_finite() {
        return Err(format!("{name} is {field:?}, not a finite number"));
    }
    if value.abs() > MAX_COORDINATE {
        return Err(format!(
            "{name} = {field} lies beyond ±{MAX_COORDINATE:e}, the largest coordinate accepted"
        ));
    }
    Ok(value)
}

fn zero_length_warning(lines: &[usize]) -> String {
    let shown: Vec<String> = lines.iter().take(5).map(usize::to_string).collect();
    let more = if lines.len() > shown.len() {
        ", …"
    } else {
        ""
    };
    format!(
        "{} zero-length line(s) were dropped (line {}{more})",
        lines.len(),
        shown.join(", ")
    )
}

/// Renders a pattern as a `.cp` line list (one line per edge, y negated, see the module
/// documentation for the type numbers and what they lose).
pub fn write_string(pattern: &CreasePattern) -> String {
    let mut out = String::with_capacity(pattern.edges.len() * 48);
    for edge in &pattern.edges {
        let [a, b] = edge.vertices.map(|v| pattern.position(v));
        let _ = writeln!(
            out,
            "{} {} {} {} {}",
            type_of(edge.assignment),
            number(a.x),
            number(-a.y),
            number(b.x),
            number(-b.y)
        );
    }
    out
}

/// The shortest decimal that parses back to `v` (never exponent notation, which old readers
/// may not take), with `-0` written as `0`.
fn number(v: f64) -> String {
    format!("{}", v + 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn types_map_both_ways() {
        for a in Assignment::ALL {
            let back = assignment_of(i64::from(type_of(a)));
            let expected = match a {
                Assignment::Cut => Assignment::Boundary,
                Assignment::Unassigned | Assignment::Join => Assignment::Flat,
                other => other,
            };
            assert_eq!(back, expected, "{a:?}");
        }
        assert_eq!(assignment_of(-7), Assignment::Flat);
    }

    #[test]
    fn lines_parse_with_y_negated() {
        let parsed = parse_line(" 2\t-200 0.5  1e2 200 ").ok().flatten();
        let (t, p, q) = parsed.unwrap_or((-1, DVec2::NAN, DVec2::NAN));
        assert_eq!(assignment_of(t), Assignment::Mountain);
        assert_eq!(p, DVec2::new(-200.0, -0.5));
        assert_eq!(q, DVec2::new(100.0, -200.0));
        assert_eq!(parse_line("   "), Ok(None));
    }

    #[test]
    fn bad_lines_say_why() {
        let err = |s: &str| parse_line(s).err().unwrap_or_default();
        assert!(err("2 0 0 1").contains("expected 5 fields"));
        assert!(err("M 0 0 1 1").contains("not an integer"));
        assert!(err("2 0 zero 1 1").contains("y0"));
        assert!(err("2 0 0 inf 1").contains("finite"));
        assert!(err("2 0 0 1 1e10").contains("beyond"));
    }

    #[test]
    fn numbers_round_trip_exactly() {
        for v in [0.1 + 0.2, -1.0 / 3.0, 1e-20, 123456789.123, -0.0] {
            let s = number(v);
            assert!(!s.contains('e') && s != "-0", "{s}");
            assert_eq!(s.parse::<f64>().ok(), Some(v + 0.0));
        }
    }
}
