//! GRBL 1.1 in laser mode (`$32=1`): arm once, power inline, `S0` on every travel.

use super::Flavour;
use crate::machine::LaserMode;

/// A GRBL laser.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GrblLaser {
    mode: LaserMode,
}

impl GrblLaser {
    /// A GRBL laser in `mode`.
    pub fn new(mode: LaserMode) -> Self {
        GrblLaser { mode }
    }
}

impl Flavour for GrblLaser {
    fn expectation(&self) -> Option<String> {
        Some(
            "expects GRBL laser mode $32=1 (G0 blanks the beam, S changes without stopping); \
             S scales between $31 and $30"
                .to_string(),
        )
    }
    fn uses_power(&self) -> bool {
        true
    }
    fn start(&self) -> Vec<String> {
        vec![format!("{} S0", self.mode.command())]
    }
    fn travel_words(&self) -> &str {
        " S0"
    }
    fn tool_on(&self, _s: &str) -> Vec<String> {
        Vec::new()
    }
    fn burn_word(&self, s: &str) -> Option<String> {
        Some(format!("S{s}"))
    }
    fn tool_off(&self) -> Vec<String> {
        Vec::new()
    }
    fn finish(&self) -> Vec<String> {
        vec!["M5".into()]
    }
    fn program_end(&self) -> Option<&str> {
        Some("M2")
    }
}
