//! Finding the line of a dotted key in a TOML text, so errors can say where to look.
//!
//! Keys are walked segment by segment (`settings.cut.speed_mm_min`, `pen.up[1]`) through the
//! spanned parse of the text. A key whose segments contain dots of their own (quoted keys) or
//! that is missing from the text has no line; the error then names the key alone.

use toml::Spanned;
use toml::de::{DeTable, DeValue};

/// The 1-based line where `key` (or its value) is written in `text`, if it can be found.
pub(crate) fn line_of(text: &str, key: &str) -> Option<usize> {
    let root = DeTable::parse(text).ok()?;
    let mut span = root.span();
    let mut table = root.get_ref();
    let mut current: Option<&Spanned<DeValue>> = None;
    for segment in key.split('.') {
        let (name, indices) = split_indices(segment)?;
        if let Some(value) = current {
            table = match value.get_ref() {
                DeValue::Table(t) => t,
                _ => return None,
            };
        }
        let (found_key, mut value) = table.iter().find(|(k, _)| k.get_ref().as_ref() == name)?;
        span = found_key.span();
        for i in indices {
            value = match value.get_ref() {
                DeValue::Array(items) => items.get(i)?,
                _ => return None,
            };
            span = value.span();
        }
        current = Some(value);
    }
    Some(text.get(..span.start)?.matches('\n').count() + 1)
}

/// `name[1][2]` → (`name`, [1, 2]).
fn split_indices(segment: &str) -> Option<(&str, Vec<usize>)> {
    let mut parts = segment.split('[');
    let name = parts.next()?;
    let indices = parts
        .map(|p| p.strip_suffix(']')?.parse().ok())
        .collect::<Option<Vec<_>>>()?;
    Some((name, indices))
}

#[cfg(test)]
mod tests {
    use super::*;

    const TEXT: &str = "a = 1\n\n[bed]\nwidth_mm = 3\nlist = [\n  \"x\",\n  \"y\",\n]\n";

    #[test]
    fn keys_are_found_on_their_lines() {
        assert_eq!(line_of(TEXT, "a"), Some(1));
        assert_eq!(line_of(TEXT, "bed"), Some(3));
        assert_eq!(line_of(TEXT, "bed.width_mm"), Some(4));
        assert_eq!(line_of(TEXT, "bed.list[1]"), Some(7));
    }

    #[test]
    fn missing_keys_have_no_line() {
        assert_eq!(line_of(TEXT, "bed.depth_mm"), None);
        assert_eq!(line_of(TEXT, "a.b"), None);
        assert_eq!(line_of(TEXT, "bed.list[9]"), None);
        assert_eq!(line_of("= =", "a"), None);
    }
}
