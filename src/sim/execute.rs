//! The simulated machine: modal state, and what each block does to it.
//!
//! Order within a line follows rs274ngc: units and distance mode, feed, power, laser state,
//! dwell, home, motion, program end. A line with any unknown, unsupported or malformed word is
//! rejected whole (as GRBL and LinuxCNC reject it) and only flagged. Other violations are
//! flagged and the line still runs the way the firmware would run it: a feed above the
//! maximum is capped, `S` is clamped to the range, a feed move without `F` runs at the
//! maximum feed, a move off the bed goes there.

use glam::DVec2;

use super::block::Block;
use super::report::{Burn, SimReport, Travel, ViolationKind};
use crate::geom::tolerance::RELATIVE;
use crate::machine::motion::{Kinematics, Move, Timeline};
use crate::machine::{Dialect, DwellUnit, LaserOutput, MachineProfile};

const MM_PER_INCH: f64 = 25.4;

/// The state of the laser output (`M3`/`M4`/`M5`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Laser {
    Off,
    Constant,
    Dynamic,
}

/// The simulated machine.
pub(crate) struct Machine<'a> {
    profile: &'a MachineProfile,
    /// Pen tool (plotter, drag knife) rather than laser.
    pen_tool: bool,
    pos: DVec2,
    inches: bool,
    relative: bool,
    rapid: bool,
    feed: Option<f64>,
    power: f64,
    laser: Laser,
    pen_down: bool,
    /// The tool burned at the end of the last event (for counting pierces).
    lit: bool,
    /// LinuxCNC motion outputs: the profile's digital output and analog value (`S` units).
    digital_out: bool,
    analog_out: f64,
    /// Synchronised output changes waiting for the next move (`M62`/`M63`, `M67`).
    pending_digital: Option<bool>,
    pending_analog: Option<f64>,
    /// A synchronised output change (any output number) waits for the next move, which
    /// carries it ([`Move::sync`]).
    pending_sync: bool,
    /// Moves since the last stop.
    timeline: Timeline,
    /// `M2`/`M30` seen.
    pub ended: bool,
    /// What was found so far.
    pub report: SimReport,
    /// The profile's pen commands.
    pub(super) pens: super::PenCommands,
}

impl<'a> Machine<'a> {
    /// A machine at rest at the origin, millimetres, absolute, laser off, pen up.
    pub fn new(profile: &'a MachineProfile) -> Self {
        Machine {
            profile,
            pen_tool: profile.pen_tool(),
            pos: DVec2::ZERO,
            inches: false,
            relative: false,
            rapid: true,
            feed: None,
            power: 0.0,
            laser: Laser::Off,
            pen_down: false,
            lit: false,
            digital_out: false,
            analog_out: 0.0,
            pending_digital: None,
            pending_analog: None,
            pending_sync: false,
            timeline: Timeline::new(Kinematics::of(profile), DVec2::ZERO),
            ended: false,
            report: SimReport::new(&profile.name, profile.dialect, profile.power),
            pens: super::PenCommands::of(profile),
        }
    }

    /// Runs one decoded block from line `line`.
    pub fn execute(&mut self, line: usize, b: &Block) {
        if let Some(i) = b.inches {
            self.inches = i;
        }
        if let Some(r) = b.relative {
            self.relative = r;
        }
        if let Some(f) = b.f {
            self.set_feed(line, f);
        }
        // M106's S is a fan speed, Marlin's G4 S a dwell time.
        let s_is_power = !(b.fan || (b.dwell && self.marlin()));
        if let Some(s) = b.s.filter(|_| s_is_power) {
            self.set_power(line, s);
        }
        if let Some(m) = b.spindle {
            self.set_laser(m);
        }
        if b.coolant {
            self.stop();
        }
        if let Some(m) = b.output {
            self.set_output(line, m, b);
        }
        if b.dwell {
            self.dwell(line, b);
        } else if b.p.is_some() && !b.blend && !b.fan && b.output.is_none() {
            let msg = "P without G4 or G64 has no meaning here";
            self.report.flag(line, ViolationKind::UnknownWord, msg);
        }
        if b.sync {
            self.stop();
        }
        self.motion(line, b);
        if b.end {
            self.end();
        }
    }

    /// Changes the pen state (a profile pen command); a stop.
    pub fn set_pen(&mut self, down: bool) {
        self.stop();
        self.pen_down = down;
        if !down {
            self.lit = false;
        }
    }

    /// Finishes the run: times the last moves and flags a tool left on.
    pub fn finish(mut self, last_line: usize) -> SimReport {
        if !self.ended && self.tool_on(false) {
            let msg = format!(
                "the program ends with the {} and no M2/M30",
                self.tool_state()
            );
            self.report.flag(last_line, ViolationKind::ToolLeftOn, msg);
        }
        self.stop();
        self.report.end_position = self.pos;
        self.report.total_by_power();
        self.report
    }

    /// Brings the machine to rest: times the moves since the last stop.
    pub fn stop(&mut self) {
        self.report.time_s += self.timeline.stop();
    }

    fn marlin(&self) -> bool {
        self.profile.dialect == Dialect::Marlin
    }

    fn set_feed(&mut self, line: usize, f: f64) {
        let f = if self.inches { f * MM_PER_INCH } else { f };
        if f <= 0.0 {
            self.report.flag(
                line,
                ViolationKind::Malformed,
                format!("feed F{f} is not positive"),
            );
            return;
        }
        let max = self.profile.max_feed_mm_min;
        if f > max {
            let msg = format!("feed {f} mm/min is above the machine's maximum {max} mm/min");
            self.report.flag(line, ViolationKind::FeedTooHigh, msg);
        }
        self.feed = Some(f);
    }

    fn set_power(&mut self, line: usize, s: f64) {
        let range = self.profile.power;
        if !self.pen_tool && !(range.min..=range.max).contains(&s) {
            let msg = format!(
                "power S{s} is outside the range {} to {}",
                range.min, range.max
            );
            self.report.flag(line, ViolationKind::PowerOutOfRange, msg);
        }
        self.power = if self.pen_tool {
            s
        } else {
            s.clamp(range.min, range.max)
        };
        if !self.tool_on(false) {
            self.lit = false;
        }
    }

    /// `M3`/`M4`/`M5`: a stop on every dialect (the laser output switches between moves).
    fn set_laser(&mut self, m: u32) {
        self.stop();
        self.laser = match m {
            3 => Laser::Constant,
            4 => Laser::Dynamic,
            _ => Laser::Off,
        };
        self.lit = false;
    }

    /// Whether the tool marks the sheet during a move (`rapid`) or in a feed move / at rest.
    fn tool_on(&self, rapid: bool) -> bool {
        if self.pen_tool {
            return self.pen_down;
        }
        let spindle = self.laser != Laser::Off && self.power > self.profile.power.min;
        let on = spindle || self.output_on();
        // GRBL's laser mode blanks the output during G0; Marlin and LinuxCNC do not.
        on && !(rapid && self.profile.dialect == Dialect::Grbl)
    }

    fn dwell(&mut self, line: usize, b: &Block) {
        self.stop();
        let seconds = match (b.p, b.s.filter(|_| self.marlin())) {
            (Some(p), _) => match self.profile.dwell_unit {
                DwellUnit::Seconds => p,
                DwellUnit::Milliseconds => p / 1000.0,
            },
            (None, Some(s)) => s,
            (None, None) => 0.0,
        };
        if seconds < 0.0 {
            self.report
                .flag(line, ViolationKind::Malformed, "negative dwell");
            return;
        }
        self.report.dwell_s += seconds;
        self.report.time_s += seconds;
        // GRBL's laser mode keeps M3 on at rest and turns M4 off (power follows speed).
        let grbl_dynamic = self.profile.dialect == Dialect::Grbl && self.laser == Laser::Dynamic;
        if !self.pen_tool && self.tool_on(false) && !grbl_dynamic {
            self.report.lit_dwell_s += seconds;
        }
    }

    fn motion(&mut self, line: usize, b: &Block) {
        if let Some(m) = b.motion {
            self.rapid = m == 0;
        }
        if b.home {
            if let Some(via) = self.target(b) {
                self.travel_to(line, via, true);
            }
            self.travel_to(line, DVec2::ZERO, true);
            return;
        }
        if b.dwell {
            return;
        }
        if let Some(to) = self.target(b) {
            let rapid = self.rapid;
            self.travel_to(line, to, rapid);
        }
    }

    /// The XY target of a block's axis words, `None` without X or Y.
    fn target(&self, b: &Block) -> Option<DVec2> {
        if b.x.is_none() && b.y.is_none() {
            return None;
        }
        let scale = if self.inches { MM_PER_INCH } else { 1.0 };
        let axis = |word: Option<f64>, current: f64| match (word, self.relative) {
            (Some(v), true) => current + v * scale,
            (Some(v), false) => v * scale,
            (None, _) => current,
        };
        Some(DVec2::new(axis(b.x, self.pos.x), axis(b.y, self.pos.y)))
    }

    fn travel_to(&mut self, line: usize, to: DVec2, rapid: bool) {
        self.check_bed(line, to);
        let feed = match (rapid, self.feed) {
            (true, _) => self.profile.travel_feed_mm_min,
            (false, Some(f)) => f.min(self.profile.max_feed_mm_min),
            (false, None) => {
                let msg = "feed move before any F (GRBL and LinuxCNC reject it): timed at the maximum feed";
                self.report.flag(line, ViolationKind::MissingFeed, msg);
                self.feed = Some(self.profile.max_feed_mm_min);
                self.profile.max_feed_mm_min
            }
        };
        self.apply_pending();
        self.record(line, to, rapid, feed);
        self.timeline.push(Move {
            to,
            feed_mm_min: feed,
            rapid,
            sync: std::mem::take(&mut self.pending_sync),
        });
        self.pos = to;
    }

    fn record(&mut self, line: usize, to: DVec2, rapid: bool, feed: f64) {
        let from = self.pos;
        let burning = self.tool_on(rapid);
        if from == to {
            return;
        }
        if burning {
            if rapid {
                self.flag_lit_travel(line);
            }
            if !self.lit {
                self.report.pierces += 1;
            }
            let power = self.beam_power();
            let feed_mm_min = feed;
            let burn = Burn {
                line,
                from,
                to,
                power,
                feed_mm_min,
            };
            self.report.add_burn(burn);
        } else {
            self.report.add_travel(Travel { line, from, to });
        }
        self.lit = burning;
    }

    /// A LinuxCNC motion output word (`M62`–`M68`). Only the profile's output number
    /// (`output_number`, of the kind `laser_output` names) drives the beam; the others are
    /// read and ignored. Immediate forms (`M64 M65 M68`) wait for motion; synchronised ones
    /// (`M62 M63 M67`) change at the start of the next move.
    fn set_output(&mut self, line: usize, m: u32, b: &super::block::Block) {
        let ours = f64::from(self.profile.control.output_number);
        let number = if matches!(m, 67 | 68) { b.e } else { b.p };
        let Some(number) = number else {
            let letter = if matches!(m, 67 | 68) { 'E' } else { 'P' };
            let msg = format!("M{m} needs {letter}, the output number");
            self.report.flag(line, ViolationKind::Malformed, msg);
            return;
        };
        let value = if matches!(m, 67 | 68) {
            let Some(q) = b.q else {
                let msg = format!("M{m} needs Q, the output value");
                self.report.flag(line, ViolationKind::Malformed, msg);
                return;
            };
            let range = self.profile.power;
            if !(range.min..=range.max).contains(&q) && q != 0.0 {
                let msg = format!(
                    "power Q{q} is outside the range {} to {}",
                    range.min, range.max
                );
                self.report.flag(line, ViolationKind::PowerOutOfRange, msg);
            }
            q.clamp(0.0, range.max)
        } else {
            0.0
        };
        if matches!(m, 62 | 63 | 67) {
            self.pending_sync = true;
        }
        if number != ours {
            return;
        }
        match m {
            62 | 63 => self.pending_digital = Some(m == 62),
            64 | 65 => {
                self.stop();
                self.pending_digital = None;
                self.digital_out = m == 64;
            }
            67 => self.pending_analog = Some(value),
            _ => {
                self.stop();
                self.pending_analog = None;
                self.analog_out = value;
            }
        }
        if !self.tool_on(false) {
            self.lit = false;
        }
    }

    /// Synchronised output changes take effect as the next move starts.
    fn apply_pending(&mut self) {
        if let Some(d) = self.pending_digital.take() {
            self.digital_out = d;
        }
        if let Some(a) = self.pending_analog.take() {
            self.analog_out = a;
        }
        if !self.tool_on(false) {
            self.lit = false;
        }
    }

    /// The beam is on through the profile's LinuxCNC motion output.
    fn output_on(&self) -> bool {
        if self.profile.dialect != Dialect::LinuxCnc {
            return false;
        }
        match self.profile.control.laser_output {
            LaserOutput::Spindle => false,
            LaserOutput::Digital => self.digital_out,
            LaserOutput::Analog => self.analog_out > self.profile.power.min,
        }
    }

    /// The power a burn carries: 0 for a pen, the analog output or full power (a digital
    /// gate) for a LinuxCNC motion output, else `S`.
    fn beam_power(&self) -> f64 {
        if self.pen_tool {
            0.0
        } else if self.output_on() {
            match self.profile.control.laser_output {
                LaserOutput::Analog => self.analog_out,
                _ => self.profile.power.max,
            }
        } else {
            self.power
        }
    }

    fn flag_lit_travel(&mut self, line: usize) {
        let msg = format!(
            "rapid move with the {}: it marks the sheet",
            self.tool_state()
        );
        self.report.flag(line, ViolationKind::LitTravel, msg);
    }

    /// "pen down" or "laser on", for messages.
    fn tool_state(&self) -> &'static str {
        if self.pen_tool {
            "pen down"
        } else {
            "laser on"
        }
    }

    fn check_bed(&mut self, line: usize, p: DVec2) {
        let bed = self.profile.bed;
        let eps = self.profile.resolution_mm.max(0.0) / 2.0 + RELATIVE;
        let inside = (-eps..=bed.width_mm + eps).contains(&p.x)
            && (-eps..=bed.height_mm + eps).contains(&p.y);
        if !inside {
            let msg = format!(
                "move to ({:.3}, {:.3}) is outside the bed {} × {} mm",
                p.x, p.y, bed.width_mm, bed.height_mm
            );
            self.report.flag(line, ViolationKind::OutOfBed, msg);
        }
    }

    /// `M2`/`M30`: stop, laser off, absolute mode; the caller ignores the rest of the text.
    fn end(&mut self) {
        self.stop();
        self.laser = Laser::Off;
        self.relative = false;
        self.lit = false;
        self.ended = true;
    }
}
