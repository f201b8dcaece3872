//! Machine profiles.

use serde::Serialize;

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
}
