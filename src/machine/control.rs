//! How a machine switches its tool and its air, and what that costs in time.
//!
//! These are the profile keys that decide the *semantics* of a job rather than its geometry;
//! the G-code writer (`post::gcode`), the plan's time estimate (`fab::timing`) and the
//! simulated machine (`sim`) all read them from here, so the three agree.
//!
//! Facts the choices rest on (from the firmware documentation):
//! - GRBL 1.1 (`$32=1` laser mode) and Marlin's inline laser power change `S` without
//!   stopping; switching `M3`/`M4`/`M5` waits for the planner to empty (GRBL's
//!   `spindle_sync`, Marlin's `planner.synchronize()`).
//! - LinuxCNC waits for motion to stop before every spindle word (`M3`/`M5`), so a beam
//!   switched through the spindle makes every perforation dash an exact stop. The
//!   motion-synchronised outputs `M62`/`M63 P<n>` (digital) and `M67 E<n> Q<v>` (analog)
//!   change at the start of the next move without stopping; the immediate forms
//!   `M64`/`M65`/`M68` wait for motion first.
//! - Coolant words (`M7` mist, `M8` flood, `M9` off), used for air assist, wait for motion on
//!   GRBL, Marlin and LinuxCNC alike.
//! - A pen command (a servo or solenoid through the spindle output) is a stop, followed by
//!   the profile's pen delay.

use serde::Serialize;

use super::Operation;
use super::profile::{Dialect, MachineKind, MachineProfile};

/// How a LinuxCNC laser's beam is switched (the profile key `laser_output`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Default)]
pub enum LaserOutput {
    /// `M3 S<power>` before and `M5` after each stroke: every switch is an exact stop.
    #[default]
    Spindle,
    /// `M62 P<n>` / `M63 P<n>`: a digital output gating the beam, synchronised to motion;
    /// power is whatever the source is set to.
    Digital,
    /// `M67 E<n> Q<power>` / `M67 E<n> Q0`: an analog output carrying the power (in the
    /// profile's `S` units), synchronised to motion.
    Analog,
}

impl LaserOutput {
    /// Every output kind.
    pub const ALL: [LaserOutput; 3] = [
        LaserOutput::Spindle,
        LaserOutput::Digital,
        LaserOutput::Analog,
    ];

    /// Name used in profiles: `spindle`, `digital`, `analog`.
    pub fn name(self) -> &'static str {
        match self {
            LaserOutput::Spindle => "spindle",
            LaserOutput::Digital => "digital",
            LaserOutput::Analog => "analog",
        }
    }
}

/// Air assist switched per operation with coolant words (profile keys `air_assist` and
/// `air_assist_operations`).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct AirAssist {
    /// The word that turns the air on: `M7` (mist) or `M8` (flood); `M9` turns it off.
    pub on: &'static str,
    /// The operations that run with the air on.
    pub operations: Vec<Operation>,
}

/// The word that turns air assist off.
pub const AIR_OFF: &str = "M9";

/// The shop-floor keys of a machine profile, all optional.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MachineControl {
    /// LinuxCNC: how the beam is switched.
    pub laser_output: LaserOutput,
    /// LinuxCNC: the output number, `P` of `M62`/`M63` or `E` of `M67`/`M68`.
    pub output_number: u32,
    /// Air assist, if the machine has it wired to a coolant output.
    pub air_assist: Option<AirAssist>,
    /// Plotters: the lines written between layers (a pen change), by default `M0` (pause
    /// until the operator resumes).
    pub pen_change: Vec<String>,
    /// LinuxCNC: the path tolerance of `G64 P<tolerance>`, mm (how far a blended corner may
    /// leave the programmed path), written after the arming line; `None` writes no `G64`.
    pub blend_tolerance_mm: Option<f64>,
    /// GRBL's step idle delay (`$1`), s: each time motion comes to rest with nothing queued
    /// (before a spindle or pen word, a dwell, a pause), GRBL holds the steppers this long
    /// (`st_go_idle` in `stepper.c`) before it runs the next line. 0 when not set.
    pub step_idle_delay_s: f64,
}

impl Default for MachineControl {
    fn default() -> Self {
        MachineControl {
            laser_output: LaserOutput::Spindle,
            output_number: 0,
            air_assist: None,
            pen_change: vec!["M0".to_string()],
            blend_tolerance_mm: None,
            step_idle_delay_s: 0.0,
        }
    }
}

/// What switching the tool on or off costs on a machine.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SwitchCost {
    /// The machine comes to rest before the switch (an exact stop).
    pub stops: bool,
    /// Seconds waited after the switch (pen delay).
    pub dwell_s: f64,
}

impl MachineProfile {
    /// True when the tool is a pen or knife lifted and lowered by the profile's commands.
    pub fn pen_tool(&self) -> bool {
        self.kind != MachineKind::Laser || self.dialect == Dialect::Plotter
    }

    /// What switching the tool costs (see the module docs): pens and LinuxCNC spindle words
    /// stop; GRBL's and Marlin's inline power and LinuxCNC's synchronised outputs do not.
    pub fn switch_cost(&self) -> SwitchCost {
        if self.pen_tool() {
            return SwitchCost {
                stops: true,
                dwell_s: self.pen_delay_s,
            };
        }
        let stops =
            self.dialect == Dialect::LinuxCnc && self.control.laser_output == LaserOutput::Spindle;
        SwitchCost {
            stops,
            dwell_s: 0.0,
        }
    }

    /// True when the travel between two burns of one run (the dashes of a perforation, the
    /// strokes of one chain, within a pass) is written as a feed move (`G1` at the travel feed,
    /// the beam off) rather than a rapid: LinuxCNC lasers on a synchronised output. LinuxCNC's
    /// trajectory planner cannot blend a rapid into a feed move (an exact stop at every
    /// `G0`↔`G1` switch, see [`crate::machine::motion::Kinematics::stops_between_rapid_and_feed`]),
    /// so a `G0` between two dashes would stop twice; `G1` blends. A spindle-switched beam stops
    /// at every switch anyway and keeps `G0`.
    pub fn links_burns_with_feed_moves(&self) -> bool {
        self.kind == MachineKind::Laser
            && self.dialect == Dialect::LinuxCnc
            && !self.switch_cost().stops
    }

    /// True when air assist is on during `op` (never without air assist in the profile).
    pub fn air_for(&self, op: Operation) -> bool {
        self.control
            .air_assist
            .as_ref()
            .is_some_and(|a| a.operations.contains(&op))
    }

    /// True when a G-code job pauses for a pen change between operations (plotters).
    pub fn pauses_between_layers(&self) -> bool {
        self.kind == MachineKind::Plotter && !self.control.pen_change.is_empty()
    }
}

impl MachineProfile {
    /// The settings `op` runs with on this machine: a plotter's pen draws every operation at
    /// the material's `plot` speed and passes; other machines use the operation's own.
    pub fn settings_for(
        &self,
        settings: &super::SettingsByOperation,
        op: Operation,
    ) -> super::OperationSettings {
        if self.kind == MachineKind::Plotter {
            settings.get(Operation::Plot)
        } else {
            settings.get(op)
        }
    }
}
