//! Reading one line of G-code into words.
//!
//! A line is: an optional block-delete `/` (rejected), words `LETTER NUMBER` with spaces
//! allowed anywhere (as rs274ngc allows), comments `( … )` (not nested) and `; …` to the end of
//! the line, and an optional checksum `*NN` (the XOR of every byte before the `*`, as Marlin
//! checks it). A line holding only `%` is a tape delimiter; a line starting with `$` is a GRBL
//! system command. Numbers are decimal without exponent (`1e3` reads as the words `1` and
//! `E3`), finite, and within ±[`MAX_NUMBER`].

use super::report::ViolationKind;

/// Largest magnitude accepted for a number, mm or mm/min or any other unit.
pub const MAX_NUMBER: f64 = 1e9;
/// Longest accepted number text, characters.
const MAX_NUMBER_CHARS: usize = 32;

/// One word: a letter (upper case) and its value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Word {
    /// The letter, upper case.
    pub letter: char,
    /// The number.
    pub value: f64,
}

/// What one line holds.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Line {
    /// Nothing but blanks and comments.
    Empty,
    /// A `%` tape delimiter.
    Percent,
    /// A GRBL `$` system command (the text after `$`).
    System(String),
    /// Words, in order.
    Words(Vec<Word>),
}

/// Why a line could not be read.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct LineError {
    /// What kind of problem.
    pub kind: ViolationKind,
    /// A readable message.
    pub message: String,
}

impl LineError {
    fn malformed(message: impl Into<String>) -> Self {
        LineError {
            kind: ViolationKind::Malformed,
            message: message.into(),
        }
    }
}

/// The text of a line that holds nothing but one comment (`; text` or `(text)`), trimmed;
/// `None` for any other line.
pub(crate) fn comment_only(raw: &str) -> Option<&str> {
    let t = raw.trim();
    if let Some(rest) = t.strip_prefix(';') {
        return Some(rest.trim());
    }
    let inner = t.strip_prefix('(')?.strip_suffix(')')?;
    (!inner.contains(['(', ')'])).then(|| inner.trim())
}

/// Reads one line.
pub(crate) fn parse_line(raw: &str) -> Result<Line, LineError> {
    let code = raw.split(';').next().unwrap_or("");
    let code = verify_checksum(code)?;
    let code = strip_parens(code)?;
    let trimmed = code.trim();
    if trimmed.is_empty() {
        return Ok(Line::Empty);
    }
    if trimmed == "%" {
        return Ok(Line::Percent);
    }
    if let Some(rest) = trimmed.strip_prefix('$') {
        return Ok(Line::System(rest.trim().to_string()));
    }
    if trimmed.starts_with('/') {
        return Err(LineError {
            kind: ViolationKind::Unsupported,
            message: "block delete `/` is not supported".into(),
        });
    }
    words(trimmed).map(Line::Words)
}

/// Checks and removes a trailing `*NN` checksum.
fn verify_checksum(code: &str) -> Result<&str, LineError> {
    let Some(star) = code.rfind('*') else {
        return Ok(code);
    };
    let (body, sum) = (&code[..star], code[star + 1..].trim());
    let given: u8 = sum
        .parse()
        .map_err(|_| LineError::malformed(format!("checksum `*{sum}` is not a number 0-255")))?;
    let actual = body.bytes().fold(0u8, |acc, b| acc ^ b);
    if given != actual {
        return Err(LineError {
            kind: ViolationKind::Checksum,
            message: format!("checksum {given} does not match the line (expected {actual})"),
        });
    }
    Ok(body)
}

/// Removes `( … )` comments; nested or unclosed parentheses are an error.
fn strip_parens(code: &str) -> Result<String, LineError> {
    let mut out = String::with_capacity(code.len());
    let mut in_comment = false;
    for c in code.chars() {
        match (c, in_comment) {
            ('(', true) => return Err(LineError::malformed("nested `(` in a comment")),
            ('(', false) => in_comment = true,
            (')', true) => in_comment = false,
            (')', false) => return Err(LineError::malformed("`)` without `(`")),
            (_, true) => {}
            (_, false) => out.push(c),
        }
    }
    if in_comment {
        return Err(LineError::malformed("comment `(` is not closed"));
    }
    Ok(out)
}

/// Splits code without comments into words.
fn words(code: &str) -> Result<Vec<Word>, LineError> {
    let chars: Vec<char> = code.chars().filter(|c| !c.is_whitespace()).collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let letter = chars[i].to_ascii_uppercase();
        if !letter.is_ascii_uppercase() {
            return Err(LineError::malformed(format!(
                "expected a letter, found `{}`",
                chars[i].escape_debug()
            )));
        }
        let start = i + 1;
        let mut end = start;
        while end < chars.len() && is_number_char(chars[end], end == start) {
            end += 1;
        }
        let text: String = chars[start..end].iter().collect();
        out.push(Word {
            letter,
            value: number(letter, &text)?,
        });
        i = end;
    }
    Ok(out)
}

fn is_number_char(c: char, first: bool) -> bool {
    c.is_ascii_digit() || c == '.' || (first && (c == '-' || c == '+'))
}

/// Reads the number of a word.
fn number(letter: char, text: &str) -> Result<f64, LineError> {
    if text.is_empty() {
        return Err(LineError::malformed(format!("word {letter} has no number")));
    }
    if text.len() > MAX_NUMBER_CHARS {
        return Err(LineError::malformed(format!(
            "the number of word {letter} is longer than {MAX_NUMBER_CHARS} characters"
        )));
    }
    let digits = text.trim_start_matches(['-', '+']);
    let valid = digits.chars().filter(|&c| c == '.').count() <= 1
        && digits.chars().any(|c| c.is_ascii_digit());
    let value: f64 = match valid {
        true => text.parse().ok(),
        false => None,
    }
    .ok_or_else(|| LineError::malformed(format!("`{letter}{text}` is not a number")))?;
    if !(value.is_finite() && value.abs() <= MAX_NUMBER) {
        return Err(LineError::malformed(format!(
            "`{letter}{text}` is out of range (±{MAX_NUMBER:e})"
        )));
    }
    Ok(value)
}

/// A line normalised for comparison with a profile's pen commands: comments removed, upper
/// case, no blanks.
pub(crate) fn normalize(raw: &str) -> String {
    let code = raw.split(';').next().unwrap_or("");
    strip_parens(code)
        .unwrap_or_default()
        .chars()
        .filter(|c| !c.is_whitespace())
        .map(|c| c.to_ascii_uppercase())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn w(letter: char, value: f64) -> Word {
        Word { letter, value }
    }

    #[test]
    fn words_comments_and_blanks() {
        let line = parse_line("n10 G1 X 1.5 (move) y-.5 ; tail").unwrap();
        let expected = vec![w('N', 10.0), w('G', 1.0), w('X', 1.5), w('Y', -0.5)];
        assert_eq!(line, Line::Words(expected));
        assert_eq!(parse_line("  ; only a comment").unwrap(), Line::Empty);
        assert_eq!(parse_line(" % ").unwrap(), Line::Percent);
        assert_eq!(parse_line("$32=1").unwrap(), Line::System("32=1".into()));
    }

    #[test]
    fn checksum_is_verified() {
        let body = "N1 G1 X1";
        let sum = body.bytes().fold(0u8, |a, b| a ^ b);
        assert!(parse_line(&format!("{body}*{sum}")).is_ok());
        let bad = parse_line(&format!("{body}*{}", sum.wrapping_add(1))).unwrap_err();
        assert_eq!(bad.kind, ViolationKind::Checksum);
    }

    #[test]
    fn malformed_numbers_are_errors() {
        for bad in ["G1 X", "G1 X1.2.3", "G1 X--1", "G1 X.", "G1 #1", "(a(b))"] {
            assert!(parse_line(bad).is_err(), "{bad}");
        }
        assert!(parse_line("G1 X1e5").is_ok(), "E is a word of its own");
        assert!(parse_line("G1 X99999999999").is_err());
    }

    #[test]
    fn normalize_for_pen_commands() {
        assert_eq!(normalize("m3 s30 (pen down)"), "M3S30");
    }
}
