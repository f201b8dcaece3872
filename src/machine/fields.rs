//! Reading a TOML table key by key, with errors that name the file, the dotted key and the
//! value found.
//!
//! [`Fields`] wraps one table. Every getter marks its key as read; [`Fields::finish`] then
//! rejects any key that was never read, so a typo (`max_feed_mm_mim`) is an error, not a
//! silently ignored line. Numbers are checked finite and inside an inclusive range given by
//! the caller; TOML integers are accepted where a real number is expected.

use std::collections::BTreeSet;

use toml::{Table, Value};

use super::ProfileError;

/// Longest value quoted back in an error message, characters.
const MAX_QUOTED: usize = 60;

/// Longest command line accepted in a profile, characters.
const MAX_LINE: usize = 256;

/// One table being read: the source name, the dotted prefix of its keys, and the keys read.
pub(crate) struct Fields<'a> {
    source: &'a str,
    prefix: String,
    table: &'a Table,
    read: BTreeSet<&'a str>,
    asked: Vec<String>,
}

impl<'a> Fields<'a> {
    /// The top-level table of `source`.
    pub(crate) fn root(source: &'a str, table: &'a Table) -> Self {
        Fields {
            source,
            prefix: String::new(),
            table,
            read: BTreeSet::new(),
            asked: Vec::new(),
        }
    }

    /// The dotted name of `key` in this table (the empty key, legal in TOML, spelt `""`).
    pub(crate) fn path(&self, key: &str) -> String {
        let key = if key.is_empty() { "\"\"" } else { key };
        if self.prefix.is_empty() {
            key.to_string()
        } else {
            format!("{}.{key}", self.prefix)
        }
    }

    /// An error about `key` of this table.
    pub(crate) fn error(&self, key: &str, message: impl Into<String>) -> ProfileError {
        ProfileError {
            source_name: self.source.to_string(),
            key: self.path(key),
            message: message.into(),
        }
    }

    /// True when `key` is present (not marking it read).
    pub(crate) fn has(&self, key: &str) -> bool {
        self.table.contains_key(key)
    }

    /// The value of `key`, if present, marking it read.
    fn get(&mut self, key: &str) -> Option<&'a Value> {
        self.asked.push(key.to_string());
        let (name, value) = self.table.get_key_value(key)?;
        self.read.insert(name.as_str());
        Some(value)
    }

    /// The value of `key`, or a "missing" error saying what was `expected`.
    fn require(&mut self, key: &str, expected: &str) -> Result<&'a Value, ProfileError> {
        self.get(key).ok_or_else(|| self.missing(key, expected))
    }

    /// A "missing" error, pointing at a present key that looks like a misspelling of `key`.
    fn missing(&self, key: &str, expected: &str) -> ProfileError {
        let lookalike = self
            .table
            .keys()
            .find(|k| k.as_str() != key && looks_like(k, key));
        let hint = lookalike.map_or(String::new(), |k| format!(" (is `{k}` a misspelling?)"));
        self.error(key, format!("missing; expected {expected}{hint}"))
    }

    /// A wrong-type or out-of-range error quoting `value`.
    fn bad(&self, key: &str, expected: &str, value: &Value) -> ProfileError {
        self.error(key, format!("expected {expected}, got {}", quote(value)))
    }

    /// The sub-table `key`.
    pub(crate) fn table(&mut self, key: &str) -> Result<Fields<'a>, ProfileError> {
        let value = self.require(key, "a table")?;
        self.as_table(key, value)
    }

    /// The sub-table `key`, if present.
    pub(crate) fn opt_table(&mut self, key: &str) -> Result<Option<Fields<'a>>, ProfileError> {
        self.get(key).map(|v| self.as_table(key, v)).transpose()
    }

    fn as_table(&self, key: &str, value: &'a Value) -> Result<Fields<'a>, ProfileError> {
        let table = value
            .as_table()
            .ok_or_else(|| self.bad(key, "a table", value))?;
        Ok(Fields {
            source: self.source,
            prefix: self.path(key),
            table,
            read: BTreeSet::new(),
            asked: Vec::new(),
        })
    }

    /// The real number `key`, finite and within `lo..=hi` (`unit` names the unit in errors).
    pub(crate) fn number(
        &mut self,
        key: &str,
        lo: f64,
        hi: f64,
        unit: &str,
    ) -> Result<f64, ProfileError> {
        let expected = format!("a number from {lo} to {hi} {unit}");
        let value = self.require(key, &expected)?;
        self.check_number(key, value, lo, hi, &expected)
    }

    /// The real number `key`, within the range of `limit` (the range and message the command
    /// line uses for the same setting).
    pub(crate) fn limited(
        &mut self,
        key: &str,
        limit: &crate::limits::Limit,
    ) -> Result<f64, ProfileError> {
        let expected = limit.expected();
        let value = self.require(key, &expected)?;
        self.check_number(key, value, limit.min, limit.max, &expected)
    }

    /// The whole number `key`, within the range of `limit`.
    pub(crate) fn counted(
        &mut self,
        key: &str,
        limit: &crate::limits::CountLimit,
    ) -> Result<u64, ProfileError> {
        let hi = i64::try_from(limit.max).unwrap_or(i64::MAX);
        let lo = i64::try_from(limit.min).unwrap_or(i64::MAX);
        self.integer(key, lo, hi).map(|v| v as u64)
    }

    fn check_number(
        &self,
        key: &str,
        value: &Value,
        lo: f64,
        hi: f64,
        expected: &str,
    ) -> Result<f64, ProfileError> {
        let x = match value {
            Value::Float(x) => *x,
            Value::Integer(i) => *i as f64,
            _ => return Err(self.bad(key, expected, value)),
        };
        if x.is_finite() && x >= lo && x <= hi {
            Ok(x)
        } else {
            Err(self.bad(key, expected, value))
        }
    }

    /// The whole number `key`, within `lo..=hi`.
    pub(crate) fn integer(&mut self, key: &str, lo: i64, hi: i64) -> Result<i64, ProfileError> {
        let expected = format!("a whole number from {lo} to {hi}");
        let value = self.require(key, &expected)?;
        match value {
            Value::Integer(i) if (lo..=hi).contains(i) => Ok(*i),
            _ => Err(self.bad(key, &expected, value)),
        }
    }

    /// The string `key`: one line of at most 256 characters without control characters
    /// (safe to copy into a G-code comment or a file header).
    pub(crate) fn text_line(&mut self, key: &str) -> Result<String, ProfileError> {
        let value = self.require(key, "a single-line string")?;
        self.line(key, value)
    }

    /// The string `key`, one of `choices` (its position in `choices`).
    pub(crate) fn choice(&mut self, key: &str, choices: &[&str]) -> Result<usize, ProfileError> {
        let expected = one_of(choices);
        let value = self.require(key, &expected)?;
        self.check_choice(key, value, choices)
    }

    /// Like [`Fields::choice`], but `None` when the key is absent.
    pub(crate) fn opt_choice(
        &mut self,
        key: &str,
        choices: &[&str],
    ) -> Result<Option<usize>, ProfileError> {
        self.get(key)
            .map(|v| self.check_choice(key, v, choices))
            .transpose()
    }

    fn check_choice(
        &self,
        key: &str,
        value: &Value,
        choices: &[&str],
    ) -> Result<usize, ProfileError> {
        let found = value
            .as_str()
            .and_then(|s| choices.iter().position(|c| *c == s));
        found.ok_or_else(|| self.bad(key, &one_of(choices), value))
    }

    /// The boolean `key`, or `default` when absent.
    pub(crate) fn bool_or(&mut self, key: &str, default: bool) -> Result<bool, ProfileError> {
        match self.get(key) {
            None => Ok(default),
            Some(v) => v.as_bool().ok_or_else(|| self.bad(key, "true or false", v)),
        }
    }

    /// The array of command lines `key` (empty when absent): single lines of printable text.
    pub(crate) fn lines(&mut self, key: &str) -> Result<Vec<String>, ProfileError> {
        let Some(value) = self.get(key) else {
            return Ok(Vec::new());
        };
        let expected = "an array of single-line strings";
        let items = value
            .as_array()
            .ok_or_else(|| self.bad(key, expected, value))?;
        items
            .iter()
            .enumerate()
            .map(|(i, item)| self.line(&format!("{key}[{i}]"), item))
            .collect()
    }

    fn line(&self, key: &str, item: &Value) -> Result<String, ProfileError> {
        let expected =
            format!("a string of at most {MAX_LINE} characters without control characters");
        match item.as_str() {
            Some(s) if s.chars().count() <= MAX_LINE && !s.chars().any(char::is_control) => {
                Ok(s.to_string())
            }
            _ => Err(self.bad(key, &expected, item)),
        }
    }

    /// Ends reading this table: any key not read is an error naming it.
    pub(crate) fn finish(self) -> Result<(), ProfileError> {
        let unknown = self
            .table
            .iter()
            .find(|(k, _)| !self.read.contains(k.as_str()));
        let Some((key, value)) = unknown else {
            return Ok(());
        };
        let known = self.asked.join(", ");
        let message = format!(
            "unknown key (set to {}); the keys here are: {known}",
            quote(value)
        );
        Err(self.error(key, message))
    }
}

/// True when `a` and `b` differ by at most two edits (insertions, deletions, substitutions).
fn looks_like(a: &str, b: &str) -> bool {
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    if a.len().abs_diff(b.len()) > 2 || a.len() > MAX_LINE || b.len() > MAX_LINE {
        return false;
    }
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.iter().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let substitution = diagonal + usize::from(ca != cb);
            diagonal = row[j + 1];
            row[j + 1] = substitution.min(row[j] + 1).min(row[j + 1] + 1);
        }
    }
    row[b.len()] <= 2
}

/// "one of `a`, `b`, `c`".
fn one_of(choices: &[&str]) -> String {
    let quoted: Vec<String> = choices.iter().map(|c| format!("\"{c}\"")).collect();
    format!("one of {}", quoted.join(", "))
}

/// A value as written in TOML, cut short when long.
fn quote(value: &Value) -> String {
    let text = match value {
        Value::Table(_) => "a table".to_string(),
        other => other.to_string(),
    };
    if text.chars().count() <= MAX_QUOTED {
        return text;
    }
    let short: String = text.chars().take(MAX_QUOTED).collect();
    format!("{short}…")
}

#[cfg(test)]
mod tests {
    use super::looks_like;

    #[test]
    fn misspellings_look_alike() {
        assert!(looks_like("max_feed_mm_mim", "max_feed_mm_min"));
        assert!(looks_like("widht_mm", "width_mm"));
        assert!(looks_like("dialekt", "dialect"));
        assert!(!looks_like("vertex_clearance", "vertex_clearance_mm"));
        assert!(!looks_like("kind", "bed"));
    }
}
