//! Pen plotters: the profile's pen-up and pen-down lines with a dwell, no power words.

use super::super::number::fixed;
use super::Flavour;
use super::linuxcnc::paren_comment;
use crate::machine::{Dialect, DwellUnit, MachineProfile};

/// A pen (or drag knife) lifted and lowered by the profile's commands.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Pen {
    up: Vec<String>,
    down: Vec<String>,
    parenthesised: bool,
    grbl_style: bool,
    travel_feed: bool,
    end: Option<&'static str>,
}

impl Pen {
    /// The pen of `machine`: its commands, its delay as `G4 P` in its dwell unit, and its
    /// dialect's comments, travel feed and program end.
    pub fn new(machine: &MachineProfile) -> Self {
        let dwell = dwell(machine.pen_delay_s, machine.dwell_unit);
        let with_dwell = |lines: &[String]| lines.iter().cloned().chain(dwell.clone()).collect();
        Pen {
            up: with_dwell(&machine.pen_up),
            down: with_dwell(&machine.pen_down),
            parenthesised: machine.dialect == Dialect::LinuxCnc,
            grbl_style: matches!(machine.dialect, Dialect::Plotter | Dialect::Grbl),
            travel_feed: machine.dialect == Dialect::Marlin,
            end: (machine.dialect != Dialect::Marlin).then_some("M2"),
        }
    }
}

/// `G4 P…` for `seconds` in `unit`, or nothing for no delay.
pub fn dwell(seconds: f64, unit: DwellUnit) -> Option<String> {
    let value = match unit {
        DwellUnit::Seconds => seconds,
        DwellUnit::Milliseconds => seconds * 1000.0,
    };
    (value > 0.0).then(|| format!("G4 P{}", fixed(value, 3)))
}

impl Flavour for Pen {
    fn comment(&self, text: &str) -> String {
        if self.parenthesised {
            paren_comment(text)
        } else {
            format!("; {}", super::one_line(text))
        }
    }
    fn expectation(&self) -> Option<String> {
        self.grbl_style.then(|| {
            "expects GRBL laser mode off, $32=0: in laser mode G0 blanks the spindle output \
             that drives the pen"
                .to_string()
        })
    }
    fn uses_power(&self) -> bool {
        false
    }
    fn travel_sets_feed(&self) -> bool {
        self.travel_feed
    }
    fn start(&self) -> Vec<String> {
        self.up.clone()
    }
    fn tool_on(&self, _s: &str) -> Vec<String> {
        self.down.clone()
    }
    fn burn_word(&self, _s: &str) -> Option<String> {
        None
    }
    fn tool_off(&self) -> Vec<String> {
        self.up.clone()
    }
    fn finish(&self) -> Vec<String> {
        Vec::new()
    }
    fn program_end(&self) -> Option<&str> {
        self.end
    }
}
