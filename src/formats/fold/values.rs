//! Typed access to JSON values with errors that name the key and index.
//!
//! Places read `key "edges_vertices"[3][1]` in the key frame and
//! `frame 2, key "vertices_coords"[0]` in other frames. Place strings are built only when an
//! error is reported, so reading large arrays costs no allocation per element.

use serde_json::Value;

use crate::formats::ParseError;

/// Largest number of elements in one array: ids are `u32`.
pub(super) const MAX_ELEMENTS: usize = u32::MAX as usize;

/// A key of one frame, for error places.
#[derive(Clone, Copy, Debug)]
pub(super) struct Key<'a> {
    /// Frame index (0 is the key frame).
    pub frame: usize,
    /// The key's name.
    pub name: &'a str,
}

impl<'a> Key<'a> {
    /// The key `name` of frame `frame`.
    pub fn new(frame: usize, name: &'a str) -> Self {
        Key { frame, name }
    }

    /// The place of the element at `path` under this key.
    pub fn place(&self, path: &[usize]) -> String {
        let mut s = if self.frame == 0 {
            format!("key {:?}", self.name)
        } else {
            format!("frame {}, key {:?}", self.frame, self.name)
        };
        for i in path {
            s.push_str(&format!("[{i}]"));
        }
        s
    }

    /// An error at the element at `path`.
    pub fn err(&self, path: &[usize], message: impl Into<String>) -> ParseError {
        ParseError::new(self.place(path), message)
    }
}

/// A short description of a JSON value for error messages.
pub(super) fn describe(v: &Value) -> String {
    match v {
        Value::Null => "null".into(),
        Value::Bool(b) => format!("{b}"),
        Value::Number(n) => format!("the number {n}"),
        Value::String(s) if s.chars().count() > 40 => "a long string".into(),
        Value::String(s) => format!("the string {s:?}"),
        Value::Array(a) => format!("an array of {} elements", a.len()),
        Value::Object(_) => "an object".into(),
    }
}

/// The value as an array, capped at [`MAX_ELEMENTS`].
pub(super) fn array<'v>(v: &'v Value, key: Key, path: &[usize]) -> Result<&'v [Value], ParseError> {
    match v {
        Value::Array(a) => {
            check_count(a.len(), MAX_ELEMENTS, key)?;
            Ok(a)
        }
        other => Err(key.err(
            path,
            format!("expected an array, found {}", describe(other)),
        )),
    }
}

/// Refuses arrays longer than `limit` (ids are `u32`).
pub(super) fn check_count(len: usize, limit: usize, key: Key) -> Result<(), ParseError> {
    if len > limit {
        return Err(key.err(
            &[],
            format!("{len} elements, more than the limit of {limit}"),
        ));
    }
    Ok(())
}

/// The value as a finite number.
pub(super) fn number(v: &Value, key: Key, path: &[usize]) -> Result<f64, ParseError> {
    match v.as_f64() {
        Some(x) if x.is_finite() => Ok(x),
        Some(x) => Err(key.err(path, format!("the number {x} is not finite"))),
        None => Err(key.err(path, format!("expected a number, found {}", describe(v)))),
    }
}

/// The value as an id below `count` (`what` names the kind: "vertex", "face").
pub(super) fn index(
    v: &Value,
    count: usize,
    what: &str,
    key: Key,
    path: &[usize],
) -> Result<u32, ParseError> {
    let i = integer(v, what, key, path)?;
    if i >= count as u64 {
        let range = match count {
            0 => format!("there are no {what} ids here"),
            n => format!("{what} ids run from 0 to {}", n - 1),
        };
        return Err(key.err(path, format!("{what} {i} does not exist ({range})")));
    }
    u32::try_from(i).map_err(|_| key.err(path, format!("{what} {i} exceeds the id limit")))
}

/// The value as a non-negative integer (integral floats such as `3.0` accepted).
fn integer(v: &Value, what: &str, key: Key, path: &[usize]) -> Result<u64, ParseError> {
    if let Some(i) = v.as_u64() {
        return Ok(i);
    }
    let bad = |m: String| key.err(path, m);
    match v.as_f64() {
        Some(x) if x < 0.0 => Err(bad(format!("negative {what} id {x}"))),
        Some(x) if x.fract() != 0.0 || !x.is_finite() => {
            Err(bad(format!("{what} id {x} is not a whole number")))
        }
        Some(x) if x < 2f64.powi(53) => Ok(x as u64),
        Some(x) => Err(bad(format!("{what} id {x} is too large"))),
        None => Err(bad(format!(
            "expected a {what} id (an integer), found {}",
            describe(v)
        ))),
    }
}

/// Checks that a per-element array has the length of the elements it describes.
pub(super) fn same_length(
    len: usize,
    expected: usize,
    key: Key,
    owner: &str,
) -> Result<(), ParseError> {
    if len != expected {
        return Err(key.err(
            &[],
            format!(
                "has {len} entries but {owner} has {expected}: the arrays must have the same length"
            ),
        ));
    }
    Ok(())
}

/// A JSON number for `x`: integral values as integers (shorter, and read back exactly),
/// others in shortest round-trip form; non-finite values (never in a valid pattern) as null.
pub(super) fn num(x: f64) -> Value {
    if x.fract() == 0.0 && x.abs() < 1e15 && !(x == 0.0 && x.is_sign_negative()) {
        Value::from(x as i64)
    } else {
        serde_json::Number::from_f64(x).map_or(Value::Null, Value::Number)
    }
}

/// Strings of a `frame_classes`/`frame_attributes`-like value (non-strings skipped).
pub(super) fn strings(v: Option<&Value>) -> Vec<&str> {
    v.and_then(Value::as_array)
        .map(|a| a.iter().filter_map(Value::as_str).collect())
        .unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn count_limit_names_the_key() {
        let key = Key::new(0, "edges_vertices");
        let err = check_count(11, 10, key).unwrap_err();
        assert_eq!(err.place, "key \"edges_vertices\"");
        assert!(err.message.contains("limit of 10"), "{}", err.message);
        assert!(check_count(10, 10, key).is_ok());
    }

    #[test]
    fn indices_reject_bad_values() {
        let key = Key::new(2, "faces_vertices");
        for (v, needle) in [
            (serde_json::json!(-1), "negative"),
            (serde_json::json!(1.5), "whole"),
            (serde_json::json!(7), "does not exist"),
            (serde_json::json!("3"), "expected a vertex id"),
        ] {
            let err = index(&v, 5, "vertex", key, &[4, 1]).unwrap_err();
            assert_eq!(err.place, "frame 2, key \"faces_vertices\"[4][1]");
            assert!(err.message.contains(needle), "{}", err.message);
        }
        assert_eq!(index(&serde_json::json!(4.0), 5, "vertex", key, &[]), Ok(4));
    }

    #[test]
    fn numbers_written_shortest() {
        assert_eq!(num(3.0).to_string(), "3");
        assert_eq!(num(-0.0).to_string(), "-0.0");
        assert_eq!(num(0.1).to_string(), "0.1");
        assert_eq!(num(f64::NAN), Value::Null);
    }
}
