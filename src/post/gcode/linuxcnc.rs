//! LinuxCNC (rs274ngc): the beam switched through the spindle (`M3 S…`/`M5`, an exact stop
//! at every switch) or through motion-synchronised outputs (`M62`/`M63 P<n>` digital,
//! `M67 E<n> Q<power>` analog) that change at the start of the next move without stopping.
//! Parenthesised comments. The profile's `blend_tolerance_mm` is written as `G64 P<mm>` after
//! the arming line (blending: LinuxCNC joins moves without stopping, leaving the path by at
//! most that much at a corner).

use super::super::number::fixed;
use super::{Flavour, one_line};
use crate::machine::LaserOutput;

/// Decimals of the printed `G64 P` tolerance (down to the 0.0001 mm profiles accept).
const TOLERANCE_DECIMALS: usize = 4;

/// A LinuxCNC laser.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinuxCncLaser {
    output: LaserOutput,
    number: u32,
    blend_tolerance_mm: Option<f64>,
}

impl LinuxCncLaser {
    /// A laser switched by `output` number `number` (`P` or `E`; unused for the spindle),
    /// blending within `blend_tolerance_mm` (`G64 P`) when given.
    pub fn new(output: LaserOutput, number: u32, blend_tolerance_mm: Option<f64>) -> Self {
        LinuxCncLaser {
            output,
            number,
            blend_tolerance_mm,
        }
    }
}

/// `text` as a LinuxCNC comment: parentheses cannot nest, so inner ones become brackets.
pub fn paren_comment(text: &str) -> String {
    let inner = one_line(text).replace('(', "[").replace(')', "]");
    format!("({inner})")
}

impl Flavour for LinuxCncLaser {
    fn comment(&self, text: &str) -> String {
        paren_comment(text)
    }
    fn expectation(&self) -> Option<String> {
        let n = self.number;
        Some(match self.output {
            LaserOutput::Spindle => "beam on the spindle output: LinuxCNC stops motion at every \
                                     M3/M5, set laser_output to digital or analog to switch \
                                     without stopping"
                .to_string(),
            LaserOutput::Digital => format!(
                "beam gated by motion.digital-out-{n:02} [M62/M63 P{n}, synchronised to motion], \
                 power is set on the source"
            ),
            LaserOutput::Analog => format!(
                "beam power on motion.analog-out-{n:02} [M67 E{n}, synchronised to motion], in S \
                 units, zero is off"
            ),
        })
    }
    fn uses_power(&self) -> bool {
        self.output != LaserOutput::Digital
    }
    fn start(&self) -> Vec<String> {
        let mut lines = vec![self.off_now()];
        if let Some(p) = self.blend_tolerance_mm {
            lines.push(format!("G64 P{}", fixed(p, TOLERANCE_DECIMALS)));
        }
        lines
    }
    fn tool_on(&self, s: &str) -> Vec<String> {
        let n = self.number;
        vec![match self.output {
            LaserOutput::Spindle => format!("M3 S{s}"),
            LaserOutput::Digital => format!("M62 P{n}"),
            LaserOutput::Analog => format!("M67 E{n} Q{s}"),
        }]
    }
    fn burn_word(&self, _s: &str) -> Option<String> {
        None
    }
    fn tool_off(&self) -> Vec<String> {
        let n = self.number;
        vec![match self.output {
            LaserOutput::Spindle => "M5".to_string(),
            LaserOutput::Digital => format!("M63 P{n}"),
            LaserOutput::Analog => format!("M67 E{n} Q0"),
        }]
    }
    fn finish(&self) -> Vec<String> {
        // A synchronised off takes effect at the next move; none follows the last stroke, so
        // the immediate form (which waits for motion to finish) makes sure.
        match self.output {
            LaserOutput::Spindle => Vec::new(),
            _ => vec![self.off_now()],
        }
    }
    fn program_end(&self) -> Option<&str> {
        Some("M2")
    }
}

impl LinuxCncLaser {
    /// The output off at once (after motion finishes): `M5`, `M65 P<n>` or `M68 E<n> Q0`.
    fn off_now(&self) -> String {
        let n = self.number;
        match self.output {
            LaserOutput::Spindle => "M5".to_string(),
            LaserOutput::Digital => format!("M65 P{n}"),
            LaserOutput::Analog => format!("M68 E{n} Q0"),
        }
    }
}
