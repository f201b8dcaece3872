//! Marlin with `LASER_FEATURE`: GRBL's inline-power scheme ([`GrblLaser`]) armed with
//! `M3 S0 I1`, with the travel feed written on every `G0` and no `M2`.

use super::Flavour;
use super::grbl::GrblLaser;
use crate::machine::LaserMode;

/// A Marlin laser with inline power.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MarlinLaser {
    mode: LaserMode,
    /// Everything Marlin's inline mode shares with GRBL's laser mode.
    inline: GrblLaser,
}

impl MarlinLaser {
    /// A Marlin laser in `mode`.
    pub fn new(mode: LaserMode) -> Self {
        MarlinLaser {
            mode,
            inline: GrblLaser::new(mode),
        }
    }
}

impl Flavour for MarlinLaser {
    fn expectation(&self) -> Option<String> {
        Some(
            "expects Marlin with LASER_FEATURE: 2.1 reads M3 I as continuous inline power; \
             2.0.x also needs LASER_POWER_INLINE and LASER_MOVE_POWER"
                .to_string(),
        )
    }
    fn uses_power(&self) -> bool {
        self.inline.uses_power()
    }
    fn start(&self) -> Vec<String> {
        vec![format!("{} S0 I1", self.mode.command())]
    }
    fn travel_words(&self) -> &str {
        self.inline.travel_words()
    }
    fn travel_sets_feed(&self) -> bool {
        true
    }
    fn tool_on(&self, s: &str) -> Vec<String> {
        self.inline.tool_on(s)
    }
    fn burn_word(&self, s: &str) -> Option<String> {
        self.inline.burn_word(s)
    }
    fn tool_off(&self) -> Vec<String> {
        self.inline.tool_off()
    }
    fn finish(&self) -> Vec<String> {
        self.inline.finish()
    }
    fn program_end(&self) -> Option<&str> {
        None
    }
}
