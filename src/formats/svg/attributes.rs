//! Checks of SVG attributes before usvg reads them.
//!
//! usvg is lenient: a coordinate it cannot parse (`x1="NaN"`) becomes 0, a transform whose
//! numbers overflow its `f32` (`scale(1e300)`) drops the element, and a root size that
//! overflows (`width="1e308mm"`) reads as "no valid size". None of that says which attribute
//! was wrong. So, before usvg:
//! - [`check_attribute_counts`] scans the raw text and refuses an element with more than
//!   [`MAX_ATTRIBUTES`] attributes (the XML parser's duplicate-attribute check is quadratic:
//!   100,000 attributes on one element took over a minute);
//! - [`check_values`] reads every geometric attribute (coordinates, sizes, `points`, `d`,
//!   `transform`, `viewBox`) as SVG numbers and lengths and refuses one that is not a number or
//!   whose magnitude exceeds [`MAX_NUMBER`], naming the element, its line, the attribute and
//!   the limit; a presentation attribute that cannot be parsed (`stroke-width`, `opacity`, …)
//!   is read as its default by usvg and gets a warning naming the element and line.
//!
//! Numbers follow SVG's grammar (`[+-]digits[.digits][e[+-]digits]`), which has no `NaN` or
//! `inf`; lengths may carry a unit (`px mm cm in pt pc em ex %`).

use usvg::roxmltree;

use crate::formats::{Finding, FindingKind, ParseError};

/// Most attributes on one element; real drawings use a few dozen.
pub const MAX_ATTRIBUTES: usize = 1000;

/// Largest magnitude of a number in a geometric attribute (user units, scale factors): beyond
/// it usvg's `f32` arithmetic overflows or coordinates leave
/// [`crate::pattern::MAX_COORDINATE`].
pub const MAX_NUMBER: f64 = 1e9;

/// The SVG namespace.
const SVG_NS: &str = "http://www.w3.org/2000/svg";

/// Attributes holding one length or coordinate.
const LENGTHS: &[&str] = &[
    "x", "y", "x1", "y1", "x2", "y2", "cx", "cy", "r", "rx", "ry", "width", "height",
];

/// Presentation attributes read leniently (a bad value gets a warning, not an error).
const LENIENT: &[&str] = &[
    "stroke-width",
    "stroke-opacity",
    "opacity",
    "stroke-dashoffset",
    "stroke-miterlimit",
];

/// Refuses an element with more than [`MAX_ATTRIBUTES`] attributes, by a linear scan of the
/// raw text (markup declarations, comments, CDATA and processing instructions skipped).
pub fn check_attribute_counts(text: &str) -> Result<(), ParseError> {
    let bytes = text.as_bytes();
    let mut i = 0;
    while let Some(offset) = bytes[i..].iter().position(|&b| b == b'<') {
        let start = i + offset;
        i = match bytes.get(start + 1) {
            Some(b'!') | Some(b'?') => skip_declaration(text, start),
            _ => scan_tag(text, start)?,
        };
    }
    Ok(())
}

/// The end of a comment, CDATA section, processing instruction or `<!DOCTYPE …[…]>`.
fn skip_declaration(text: &str, start: usize) -> usize {
    let rest = &text[start..];
    let close = |pat: &str| rest.find(pat).map_or(text.len(), |p| start + p + pat.len());
    if rest.starts_with("<!--") {
        return close("-->");
    }
    if rest.starts_with("<![CDATA[") {
        return close("]]>");
    }
    if rest.starts_with("<?") {
        return close("?>");
    }
    let mut depth = 0usize;
    let mut quote = None;
    for (k, b) in rest.bytes().enumerate().skip(1) {
        match (quote, b) {
            (Some(q), _) if b == q => quote = None,
            (Some(_), _) => {}
            (None, b'"' | b'\'') => quote = Some(b),
            (None, b'[') => depth += 1,
            (None, b']') => depth = depth.saturating_sub(1),
            (None, b'>') if depth == 0 => return start + k + 1,
            _ => {}
        }
    }
    text.len()
}

/// Counts the attributes of the tag opening at `start` (`=` outside quotes); returns the
/// position after it.
fn scan_tag(text: &str, start: usize) -> Result<usize, ParseError> {
    let mut count = 0usize;
    let mut quote = None;
    for (k, &b) in text.as_bytes().iter().enumerate().skip(start + 1) {
        match (quote, b) {
            (Some(q), _) if b == q => quote = None,
            (Some(_), _) => {}
            (None, b'"' | b'\'') => quote = Some(b),
            (None, b'=') => {
                count += 1;
                if count > MAX_ATTRIBUTES {
                    let line = text[..start].bytes().filter(|&c| c == b'\n').count() + 1;
                    let name: String = text[start + 1..]
                        .chars()
                        .take_while(|c| !c.is_whitespace() && *c != '>' && *c != '/')
                        .take(40)
                        .collect();
                    return Err(ParseError::new(
                        format!("line {line}"),
                        format!(
                            "<{name}> has more than {MAX_ATTRIBUTES} attributes, the most the \
                             SVG reader accepts on one element"
                        ),
                    ));
                }
            }
            (None, b'>') => return Ok(k + 1),
            _ => {}
        }
    }
    Ok(text.len())
}

/// Checks the geometric attributes of every element (see the module docs); returns warnings
/// for presentation attributes that could not be parsed.
pub fn check_values(doc: &roxmltree::Document) -> Result<Vec<Finding>, ParseError> {
    let mut warnings = Vec::new();
    let svg = |n: &roxmltree::Node| {
        n.is_element() && matches!(n.tag_name().namespace(), None | Some(SVG_NS))
    };
    for node in doc.descendants().filter(svg) {
        // Text positions are lists of lengths; text is not read anyway.
        let text = matches!(node.tag_name().name(), "text" | "tspan" | "textPath");
        for attr in node.attributes() {
            let (name, value) = (attr.name(), attr.value());
            if attr.namespace().is_some() {
                continue;
            }
            let problem = if LENGTHS.contains(&name) && !text {
                length(value, name)
            } else if name == "points" || (name == "viewBox" && node.tag_name().name() == "svg") {
                numbers(value)
            } else if name == "d" && value.trim() != "none" {
                path_data(value)
            } else if name == "transform" {
                transform(value)
            } else if LENIENT.contains(&name) {
                let keyword = matches!(value.trim(), "inherit" | "initial" | "unset");
                if let Err(why) =
                    length(value, name).or_else(|e| if keyword { Ok(()) } else { Err(e) })
                {
                    warnings.push(FindingKind::UnreadableAttribute.warning(format!(
                        "{}: {name}=\"{}\" could not be read ({why}); its default was used",
                        element_at(doc, node),
                        short(value)
                    )));
                }
                Ok(())
            } else {
                Ok(())
            };
            if let Err(why) = problem {
                return Err(ParseError::new(
                    element_at(doc, node),
                    format!("{name}=\"{}\": {why}", short(value)),
                ));
            }
        }
    }
    Ok(warnings)
}

/// `line N, <tag>` for messages.
fn element_at(doc: &roxmltree::Document, node: roxmltree::Node) -> String {
    let pos = doc.text_pos_at(node.range().start);
    format!("line {}, <{}>", pos.row, node.tag_name().name())
}

/// The value cut to 60 characters for a message.
fn short(value: &str) -> String {
    if value.chars().count() <= 60 {
        value.to_string()
    } else {
        let cut: String = value.chars().take(60).collect();
        format!("{cut}…")
    }
}

/// One SVG number at the start of `s`: its value and length in bytes.
fn number_at(s: &[u8]) -> Option<(f64, usize)> {
    let mut k = 0;
    if matches!(s.first(), Some(b'+' | b'-')) {
        k += 1;
    }
    let int = s[k..].iter().take_while(|b| b.is_ascii_digit()).count();
    k += int;
    let mut frac = 0;
    if s.get(k) == Some(&b'.') {
        frac = s[k + 1..].iter().take_while(|b| b.is_ascii_digit()).count();
        if frac > 0 || int > 0 {
            k += 1 + frac;
        }
    }
    if int == 0 && frac == 0 {
        return None;
    }
    if matches!(s.get(k), Some(b'e' | b'E')) {
        let mut e = k + 1;
        if matches!(s.get(e), Some(b'+' | b'-')) {
            e += 1;
        }
        let digits = s[e..].iter().take_while(|b| b.is_ascii_digit()).count();
        if digits > 0 {
            k = e + digits;
        }
    }
    let text = std::str::from_utf8(&s[..k]).ok()?;
    Some((text.parse().ok()?, k))
}

/// Refuses a number beyond [`MAX_NUMBER`].
fn bounded(value: f64, text: &[u8]) -> Result<(), String> {
    if value.is_finite() && value.abs() <= MAX_NUMBER {
        Ok(())
    } else {
        Err(format!(
            "the number {} is beyond ±{MAX_NUMBER:e}, the largest the SVG reader accepts",
            String::from_utf8_lossy(text)
        ))
    }
}

/// One length: a number with an optional unit (or `auto` for sizes).
fn length(value: &str, name: &str) -> Result<(), String> {
    let v = value.trim();
    if v == "auto" && matches!(name, "width" | "height" | "rx" | "ry") {
        return Ok(());
    }
    let Some((x, k)) = number_at(v.as_bytes()) else {
        return Err("not a number".into());
    };
    bounded(x, &v.as_bytes()[..k])?;
    let unit = v[k..].trim();
    const UNITS: [&str; 10] = ["", "px", "mm", "cm", "in", "pt", "pc", "em", "ex", "%"];
    if UNITS.contains(&unit) {
        Ok(())
    } else {
        Err(format!("not a length (unknown unit \"{}\")", short(unit)))
    }
}

/// A list of numbers separated by blanks or commas.
fn numbers(value: &str) -> Result<(), String> {
    let s = value.as_bytes();
    let mut k = 0;
    while k < s.len() {
        if s[k].is_ascii_whitespace() || s[k] == b',' {
            k += 1;
            continue;
        }
        let Some((x, n)) = number_at(&s[k..]) else {
            return Err(format!("not a list of numbers (at character {})", k + 1));
        };
        bounded(x, &s[k..k + n])?;
        k += n;
    }
    Ok(())
}

/// Path data: command letters and numbers.
fn path_data(value: &str) -> Result<(), String> {
    const COMMANDS: &[u8] = b"MmZzLlHhVvCcSsQqTtAa";
    let s = value.as_bytes();
    let mut k = 0;
    while k < s.len() {
        let b = s[k];
        if b.is_ascii_whitespace() || b == b',' || COMMANDS.contains(&b) {
            k += 1;
            continue;
        }
        let Some((x, n)) = number_at(&s[k..]) else {
            return Err(format!("not path data (at character {})", k + 1));
        };
        bounded(x, &s[k..k + n])?;
        k += n;
    }
    Ok(())
}

/// A transform list: `name(numbers)` items.
fn transform(value: &str) -> Result<(), String> {
    const NAMES: [&str; 6] = ["matrix", "translate", "scale", "rotate", "skewX", "skewY"];
    let mut rest = value.trim();
    while !rest.is_empty() {
        rest = rest.trim_start_matches(|c: char| c.is_whitespace() || c == ',');
        if rest.is_empty() {
            break;
        }
        let open = rest.find('(').ok_or("not a transform list")?;
        let name = rest[..open].trim();
        if !NAMES.contains(&name) {
            return Err(format!("unknown transform \"{}\"", short(name)));
        }
        let close = rest
            .find(')')
            .ok_or("a transform without its closing bracket")?;
        if close < open {
            return Err("not a transform list".into());
        }
        numbers(&rest[open + 1..close])?;
        rest = &rest[close + 1..];
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_follow_the_svg_grammar() {
        assert_eq!(number_at(b"1.5e3x"), Some((1500.0, 5)));
        assert_eq!(number_at(b"-.5"), Some((-0.5, 3)));
        assert_eq!(number_at(b"NaN"), None);
        assert_eq!(number_at(b"inf"), None);
        assert!(length("10mm", "x").is_ok());
        assert!(length("50%", "width").is_ok());
        assert!(length("NaN", "x1").is_err());
        assert!(length("1e308mm", "width").is_err());
        assert!(transform("translate(10, 20) scale(2)").is_ok());
        assert!(transform("scale(1e300)").is_err());
        assert!(path_data("M0,0 L10 10 h-5z").is_ok());
        assert!(path_data("M0,0 L NaN 10").is_err());
    }

    #[test]
    fn attribute_counts_skip_comments_and_quoted_equals() {
        assert!(check_attribute_counts("<svg a='x=y'><!-- = = = --></svg>").is_ok());
        let many: String = (0..=MAX_ATTRIBUTES).map(|i| format!(" a{i}='1'")).collect();
        let text = format!("<svg>\n<line{many}/></svg>");
        let err = check_attribute_counts(&text).unwrap_err();
        assert_eq!(err.place, "line 2");
        assert!(err.message.contains("<line>"), "{}", err.message);
    }
}
