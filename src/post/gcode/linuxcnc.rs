//! LinuxCNC (rs274ngc): `M3 S…` before and `M5` after every stroke, parenthesised comments.

use super::{Flavour, one_line};

/// A LinuxCNC laser switched through the spindle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LinuxCncLaser;

/// `text` as a LinuxCNC comment: parentheses cannot nest, so inner ones become brackets.
pub fn paren_comment(text: &str) -> String {
    let inner = one_line(text).replace('(', "[").replace(')', "]");
    format!("({inner})")
}

impl Flavour for LinuxCncLaser {
    fn comment(&self, text: &str) -> String {
        paren_comment(text)
    }
    fn uses_power(&self) -> bool {
        true
    }
    fn start(&self) -> Vec<String> {
        vec!["M5".into()]
    }
    fn tool_on(&self, s: &str) -> Vec<String> {
        vec![format!("M3 S{s}")]
    }
    fn burn_word(&self, _s: &str) -> Option<String> {
        None
    }
    fn tool_off(&self) -> Vec<String> {
        vec!["M5".into()]
    }
    fn finish(&self) -> Vec<String> {
        Vec::new()
    }
    fn program_end(&self) -> Option<&str> {
        Some("M2")
    }
}
