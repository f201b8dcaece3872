//! Marlin with `LASER_FEATURE`: inline power (`M3 S0 I1`), `S0` on every travel, no `M2`.

use super::Flavour;
use super::grbl::laser_on_word;
use crate::machine::LaserMode;

/// A Marlin laser with inline power.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MarlinLaser {
    mode: LaserMode,
}

impl MarlinLaser {
    /// A Marlin laser in `mode`.
    pub fn new(mode: LaserMode) -> Self {
        MarlinLaser { mode }
    }
}

impl Flavour for MarlinLaser {
    fn uses_power(&self) -> bool {
        true
    }
    fn start(&self) -> Vec<String> {
        vec![format!("{} S0 I1", laser_on_word(self.mode))]
    }
    fn travel_words(&self) -> &str {
        " S0"
    }
    fn travel_sets_feed(&self) -> bool {
        true
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
        None
    }
}
