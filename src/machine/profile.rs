//! Machine profiles: what a machine is and how it wants its G-code.
//!
//! All lengths are millimetres, feeds mm/min, acceleration mm/s², times seconds, power in the
//! machine's own `S` units ([`PowerRange`]). Values are validated where they are read
//! (`machines/*.toml`, see the `machine` module); the types here trust them.
//!
//! Machine coordinates: the machine's origin sits at [`Bed::origin`]; machine +x points right
//! (seen from above, the front edge of the bed nearest the operator), machine +y points to the
//! back, or to the front when [`Bed::y_flipped`]. The work area is the bed rectangle; for an
//! origin on the right or back corner without a flip, its machine coordinates are negative,
//! as on GRBL machines that home to the far corner.

use glam::{DAffine2, DVec2};
use serde::Serialize;

use super::Operation;
use super::control::MachineControl;
use crate::geom::tolerance::RELATIVE;

/// What the machine does to the sheet.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum MachineKind {
    /// A laser cutter (diode, CO2 or fiber).
    Laser,
    /// A pen plotter.
    Plotter,
    /// A drag-knife cutter.
    DragKnife,
}

/// The output language.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum Dialect {
    /// GRBL 1.1 (laser mode `$32=1`).
    Grbl,
    /// Marlin with a laser.
    Marlin,
    /// LinuxCNC (rs274ngc).
    LinuxCnc,
    /// GRBL-style pen plotter (pen up/down commands, no laser power).
    Plotter,
    /// No G-code: DXF/SVG for LightBurn, RDWorks, EzCad.
    FileOnly,
}

/// A corner of the bed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum Corner {
    /// x right, y up from the front-left corner.
    BottomLeft,
    /// Origin at the back-left corner.
    TopLeft,
    /// Origin at the front-right corner.
    BottomRight,
    /// Origin at the back-right corner.
    TopRight,
}

/// The bed: size and where its origin is.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Bed {
    /// Width along x, mm.
    pub width_mm: f64,
    /// Depth along y, mm.
    pub height_mm: f64,
    /// Where the machine's (0, 0) is.
    pub origin: Corner,
    /// True when machine +y points the opposite way to the drawing's +y (y up).
    pub y_flipped: bool,
}

/// How laser power follows speed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum LaserMode {
    /// `M4`: power scaled with actual speed (GRBL dynamic mode).
    Dynamic,
    /// `M3`: constant power.
    Constant,
}

/// Unit of `G4 P`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum DwellUnit {
    /// GRBL, LinuxCNC.
    Seconds,
    /// Marlin.
    Milliseconds,
}

/// The range of the spindle/laser `S` word.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PowerRange {
    /// `S` for laser off (GRBL `$31`).
    pub min: f64,
    /// `S` for full power (GRBL `$30`).
    pub max: f64,
}

/// A machine, as loaded from `machines/NAME.toml`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MachineProfile {
    /// Short name (the file stem).
    pub name: String,
    /// Readable description.
    pub description: String,
    /// Laser, plotter or drag knife.
    pub kind: MachineKind,
    /// Output dialect.
    pub dialect: Dialect,
    /// Bed and origin.
    pub bed: Bed,
    /// Fastest feed, mm/min (cutting and travel).
    pub max_feed_mm_min: f64,
    /// Travel (G0) feed used for time estimates, mm/min.
    pub travel_feed_mm_min: f64,
    /// Acceleration, mm/s².
    pub acceleration_mm_s2: f64,
    /// GRBL junction deviation, mm.
    pub junction_deviation_mm: f64,
    /// `S` range.
    pub power: PowerRange,
    /// M3 or M4.
    pub laser_mode: LaserMode,
    /// G4 P unit.
    pub dwell_unit: DwellUnit,
    /// Coordinates are rounded to this, mm (e.g. 0.001).
    pub resolution_mm: f64,
    /// Plotter pen-up command lines.
    pub pen_up: Vec<String>,
    /// Plotter pen-down command lines.
    pub pen_down: Vec<String>,
    /// Wait after pen up/down, seconds.
    pub pen_delay_s: f64,
    /// Lines written before the job.
    pub preamble: Vec<String>,
    /// Lines written after the job.
    pub postamble: Vec<String>,
    /// Beam switching, air assist and pen changes ([`MachineControl`]).
    pub control: MachineControl,
}

/// Slack when testing whether a point lies on the bed, mm (absorbs rounding in transforms).
const BED_SLACK_MM: f64 = 1e-6;

impl MachineKind {
    /// Every kind.
    pub const ALL: [MachineKind; 3] = [
        MachineKind::Laser,
        MachineKind::Plotter,
        MachineKind::DragKnife,
    ];

    /// Name used in profiles: `laser`, `plotter`, `drag-knife`.
    pub fn name(self) -> &'static str {
        match self {
            MachineKind::Laser => "laser",
            MachineKind::Plotter => "plotter",
            MachineKind::DragKnife => "drag-knife",
        }
    }
}

impl Dialect {
    /// Every dialect.
    pub const ALL: [Dialect; 5] = [
        Dialect::Grbl,
        Dialect::Marlin,
        Dialect::LinuxCnc,
        Dialect::Plotter,
        Dialect::FileOnly,
    ];

    /// Name used in profiles: `grbl`, `marlin`, `linuxcnc`, `plotter`, `file-only`.
    pub fn name(self) -> &'static str {
        match self {
            Dialect::Grbl => "grbl",
            Dialect::Marlin => "marlin",
            Dialect::LinuxCnc => "linuxcnc",
            Dialect::Plotter => "plotter",
            Dialect::FileOnly => "file-only",
        }
    }

    /// The unit of `G4 P` in this dialect: milliseconds on Marlin, seconds elsewhere (GRBL,
    /// LinuxCNC and the GRBL-style plotter firmware).
    pub fn dwell_unit(self) -> DwellUnit {
        match self {
            Dialect::Marlin => DwellUnit::Milliseconds,
            _ => DwellUnit::Seconds,
        }
    }
}

impl Corner {
    /// Every corner.
    pub const ALL: [Corner; 4] = [
        Corner::BottomLeft,
        Corner::TopLeft,
        Corner::BottomRight,
        Corner::TopRight,
    ];

    /// Name used in profiles: `bottom-left` (front left), `top-left`, `bottom-right`,
    /// `top-right`.
    pub fn name(self) -> &'static str {
        match self {
            Corner::BottomLeft => "bottom-left",
            Corner::TopLeft => "top-left",
            Corner::BottomRight => "bottom-right",
            Corner::TopRight => "top-right",
        }
    }

    /// True for the two corners on the right.
    pub fn is_right(self) -> bool {
        matches!(self, Corner::BottomRight | Corner::TopRight)
    }

    /// True for the two corners at the back (top of the drawing).
    pub fn is_top(self) -> bool {
        matches!(self, Corner::TopLeft | Corner::TopRight)
    }
}

impl LaserMode {
    /// Every mode.
    pub const ALL: [LaserMode; 2] = [LaserMode::Dynamic, LaserMode::Constant];

    /// Name used in profiles: `dynamic` (`M4`) or `constant` (`M3`).
    pub fn name(self) -> &'static str {
        match self {
            LaserMode::Dynamic => "dynamic",
            LaserMode::Constant => "constant",
        }
    }

    /// The command that turns the laser on in this mode: `M4` or `M3`.
    pub fn command(self) -> &'static str {
        match self {
            LaserMode::Dynamic => "M4",
            LaserMode::Constant => "M3",
        }
    }
}

impl DwellUnit {
    /// Every unit.
    pub const ALL: [DwellUnit; 2] = [DwellUnit::Seconds, DwellUnit::Milliseconds];

    /// Name used in profiles: `seconds` or `milliseconds`.
    pub fn name(self) -> &'static str {
        match self {
            DwellUnit::Seconds => "seconds",
            DwellUnit::Milliseconds => "milliseconds",
        }
    }

    /// The `G4 P` value for a dwell of `seconds`.
    pub fn p_value(self, seconds: f64) -> f64 {
        match self {
            DwellUnit::Seconds => seconds,
            DwellUnit::Milliseconds => seconds * 1000.0,
        }
    }
}

impl Bed {
    /// Drawing coordinates (origin at the front-left corner of the bed, x right, y to the
    /// back, mm) to machine coordinates, by the origin corner and the y flip.
    pub fn to_machine(&self) -> DAffine2 {
        let x0 = if self.origin.is_right() {
            self.width_mm
        } else {
            0.0
        };
        let y0 = if self.origin.is_top() {
            self.height_mm
        } else {
            0.0
        };
        let sy = if self.y_flipped { -1.0 } else { 1.0 };
        DAffine2::from_scale(DVec2::new(1.0, sy)) * DAffine2::from_translation(DVec2::new(-x0, -y0))
    }

    /// True when the machine point `p` (mm) lies on the bed, edges included (within 1e-6 mm).
    pub fn contains(&self, p: DVec2) -> bool {
        let d = self.to_machine().inverse().transform_point2(p);
        let inside = |v: f64, len: f64| v >= -BED_SLACK_MM && v <= len + BED_SLACK_MM;
        inside(d.x, self.width_mm) && inside(d.y, self.height_mm)
    }
}

impl PowerRange {
    /// The `S` value for `fraction` of full power: `min + fraction·(max − min)`, with the
    /// fraction clamped to 0..=1 and a NaN fraction taken as 0 (laser off).
    pub fn to_s(&self, fraction: f64) -> f64 {
        let f = if fraction.is_nan() {
            0.0
        } else {
            fraction.clamp(0.0, 1.0)
        };
        self.min + f * (self.max - self.min)
    }
}

impl MachineProfile {
    /// A laser profile built in code rather than read from TOML, with GRBL's factory
    /// defaults: 6000 mm/min, 1000 mm/s², 0.01 mm junction deviation, `S` 0–1000, `M4`
    /// dynamic power, the dialect's dwell unit, 0.001 mm resolution, no preamble or postamble.
    /// Change fields with struct-update syntax.
    pub fn generic_laser(dialect: Dialect, bed: Bed) -> MachineProfile {
        MachineProfile {
            name: format!("generic-{}", dialect.name()),
            description: "generic laser".into(),
            kind: MachineKind::Laser,
            dialect,
            bed,
            max_feed_mm_min: 6000.0,
            travel_feed_mm_min: 6000.0,
            acceleration_mm_s2: 1000.0,
            junction_deviation_mm: 0.01,
            power: PowerRange {
                min: 0.0,
                max: 1000.0,
            },
            laser_mode: LaserMode::Dynamic,
            dwell_unit: dialect.dwell_unit(),
            resolution_mm: 0.001,
            pen_up: Vec::new(),
            pen_down: Vec::new(),
            pen_delay_s: 0.0,
            preamble: Vec::new(),
            postamble: Vec::new(),
            control: MachineControl::default(),
        }
    }

    /// The `S` value for `fraction` (0..=1) of full power; see [`PowerRange::to_s`].
    pub fn power_to_s(&self, fraction: f64) -> f64 {
        self.power.to_s(fraction)
    }

    /// The `G4 P` value for a dwell of `seconds` in this machine's [`DwellUnit`].
    pub fn dwell_p(&self, seconds: f64) -> f64 {
        self.dwell_unit.p_value(seconds)
    }

    /// `mm` rounded to the machine's coordinate resolution.
    pub fn round_mm(&self, mm: f64) -> f64 {
        (mm / self.resolution_mm).round() * self.resolution_mm
    }

    /// Decimal places needed to write coordinates at the machine's resolution (0.001 → 3).
    pub fn decimals(&self) -> usize {
        let places = -self.resolution_mm.log10() - RELATIVE;
        places.ceil().clamp(0.0, 9.0) as usize
    }

    /// True when the machine writes G-code (every dialect but `file-only`).
    pub fn emits_gcode(&self) -> bool {
        self.dialect != Dialect::FileOnly
    }

    /// True when this kind of machine can carry out `op`: a laser marks, scores, perforates
    /// and cuts; a plotter plots, marks (a second pen) and perforates (draws
    /// the dashes); a drag knife scores, perforates and cuts.
    pub fn supports(&self, op: Operation) -> bool {
        match self.kind {
            MachineKind::Laser => op != Operation::Plot,
            MachineKind::Plotter => {
                matches!(op, Operation::Plot | Operation::Mark | Operation::Perforate)
            }
            MachineKind::DragKnife => {
                matches!(op, Operation::Score | Operation::Perforate | Operation::Cut)
            }
        }
    }
}
