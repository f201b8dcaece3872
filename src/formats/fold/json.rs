//! Compact, readable JSON layout for FOLD files.
//!
//! A value whose one-line form fits in [`WIDTH`] columns (counted from its indentation) is
//! written on one line; otherwise objects get one key per line and arrays one element per
//! line, except arrays of scalars, which are packed several per line. Scalars are written by
//! serde_json (escaped strings; numbers in shortest round-trip form), so parsing the output
//! gives back the same values.

use serde_json::{Map, Value};

/// Target line width.
const WIDTH: usize = 100;

/// Indentation step.
const INDENT: usize = 2;

/// The layout of `value` as text, with a trailing newline.
pub(super) fn to_text(value: &Value) -> String {
    let mut out = String::new();
    write_value(&mut out, value, 0);
    out.push('\n');
    out
}

fn write_value(out: &mut String, v: &Value, indent: usize) {
    let room = WIDTH.saturating_sub(indent);
    if fits(v, room) {
        write_compact(out, v);
        return;
    }
    match v {
        Value::Object(map) => write_object(out, map, indent),
        Value::Array(list) if list.iter().all(is_scalar) => write_packed(out, list, indent),
        Value::Array(list) => write_lines(out, list, indent),
        scalar => write_compact(out, scalar),
    }
}

fn write_object(out: &mut String, map: &Map<String, Value>, indent: usize) {
    out.push('{');
    for (i, (k, v)) in map.iter().enumerate() {
        out.push_str(if i == 0 { "\n" } else { ",\n" });
        push_indent(out, indent + INDENT);
        write_compact(out, &Value::String(k.clone()));
        out.push_str(": ");
        write_value(out, v, indent + INDENT);
    }
    out.push('\n');
    push_indent(out, indent);
    out.push('}');
}

fn write_lines(out: &mut String, list: &[Value], indent: usize) {
    out.push('[');
    for (i, v) in list.iter().enumerate() {
        out.push_str(if i == 0 { "\n" } else { ",\n" });
        push_indent(out, indent + INDENT);
        write_value(out, v, indent + INDENT);
    }
    out.push('\n');
    push_indent(out, indent);
    out.push(']');
}

/// Scalars several per line.
fn write_packed(out: &mut String, list: &[Value], indent: usize) {
    out.push('[');
    let mut line = WIDTH;
    for (i, v) in list.iter().enumerate() {
        let text = scalar_text(v);
        if i > 0 {
            out.push(',');
        }
        if line + text.len() + 2 > WIDTH {
            out.push('\n');
            push_indent(out, indent + INDENT);
            line = indent + INDENT;
        } else {
            out.push(' ');
            line += 1;
        }
        out.push_str(&text);
        line += text.len() + 1;
    }
    out.push('\n');
    push_indent(out, indent);
    out.push(']');
}

fn push_indent(out: &mut String, n: usize) {
    out.extend(std::iter::repeat_n(' ', n));
}

fn is_scalar(v: &Value) -> bool {
    !matches!(v, Value::Array(_) | Value::Object(_))
}

fn scalar_text(v: &Value) -> String {
    serde_json::to_string(v).unwrap_or_else(|_| "null".into())
}

/// One-line form, with a space after commas and colons.
fn write_compact(out: &mut String, v: &Value) {
    match v {
        Value::Array(list) => {
            out.push('[');
            for (i, x) in list.iter().enumerate() {
                if i > 0 {
                    out.push_str(", ");
                }
                write_compact(out, x);
            }
            out.push(']');
        }
        Value::Object(map) => {
            out.push('{');
            for (i, (k, x)) in map.iter().enumerate() {
                if i > 0 {
                    out.push_str(", ");
                }
                out.push_str(&scalar_text(&Value::String(k.clone())));
                out.push_str(": ");
                write_compact(out, x);
            }
            out.push('}');
        }
        scalar => out.push_str(&scalar_text(scalar)),
    }
}

/// Whether the one-line form of `v` is at most `room` characters (stops counting early).
fn fits(v: &Value, room: usize) -> bool {
    compact_len(v, room).is_some()
}

/// Length of the one-line form, `None` once it exceeds `limit`.
fn compact_len(v: &Value, limit: usize) -> Option<usize> {
    let len = match v {
        Value::Array(list) => {
            let mut total = 2 + 2 * list.len().saturating_sub(1);
            for x in list {
                total += compact_len(x, limit.checked_sub(total)?)?;
            }
            total
        }
        Value::Object(map) => {
            let mut total = 2 + 2 * map.len().saturating_sub(1);
            for (k, x) in map {
                total += k.len() + 4;
                total += compact_len(x, limit.checked_sub(total)?)?;
            }
            total
        }
        scalar => scalar_text(scalar).len(),
    };
    (len <= limit).then_some(len)
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn output_parses_back_to_the_same_value() {
        let v = json!({
            "a": [[0.1, 2e-300], [3, -0.0]],
            "long": (0..200).collect::<Vec<_>>(),
            "nested": {"x": [{"deep": ["é\"\n", null, true]}], "y": (0..50).map(|i| vec![i; 3]).collect::<Vec<_>>()}
        });
        let text = to_text(&v);
        let back: Value = serde_json::from_str(&text).unwrap_or_default();
        assert_eq!(back, v);
        assert!(text.lines().all(|l| l.len() <= WIDTH + 20), "{text}");
    }
}
