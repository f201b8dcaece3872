//! Post-processors: from a [`FabPlan`]'s job to the files a machine or its software reads.
//!
//! - [`gcode()`]: G-code for GRBL 1.1 (laser mode), Marlin (laser, inline power), LinuxCNC and
//!   pen plotters; millimetres, absolute coordinates rounded to the machine's resolution. The
//!   dialect choices (how the laser is kept off on travel, how power is set without stopping)
//!   are documented in [`gcode`](mod@gcode).
//! - [`dxf()`]: DXF R2000 (`LWPOLYLINE`, `$INSUNITS` = 4, mm) by default or R12 (`LINE` and
//!   `POLYLINE` only), one named, coloured layer per operation.
//! - [`svg()`]: SVG in millimetres with one Inkscape layer per operation, hairline strokes in
//!   LightBurn layer colours (see [`LayerStyle`]).
//!
//! Every writer draws each stroke of each toolpath as one element (perforation dashes stay
//! separate dashes, except in the SVG's `dasharray` mode), validates its input first (no NaN
//! or infinity reaches a file; see [`PostError`]) and refuses a job with nothing to draw.

mod check;
mod dxf;
pub mod gcode;
pub(crate) mod layers;
pub(crate) mod lbrn;
mod number;
mod style;
mod svg;

pub use check::{MAX_COORD_MM, MAX_RESOLUTION_MM, MIN_RESOLUTION_MM};
pub use lbrn::{LbrnPerforation, PERFORATION_TOLERANCE_MM};
pub use style::{LayerStyle, layer_style};

use crate::fab::{FabPlan, Setup};
use crate::machine::{Bed, MachineProfile};

/// Why a file could not be written.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PostError {
    /// The machine takes no G-code (an output-only profile).
    #[error("machine {machine} takes no G-code (dialect file-only): write .dxf or .svg")]
    NoGcode {
        /// The profile name.
        machine: String,
    },
    /// The job has no stroke of any length (after rounding to the resolution, for G-code).
    #[error("job {job} has nothing to draw: every toolpath is empty or of zero length")]
    EmptyJob {
        /// The job name.
        job: String,
    },
    /// A coordinate is NaN, infinite or beyond ±1e9 mm.
    #[error(
        "job {job}, toolpath {path}, stroke {stroke}: a coordinate is not a finite number \
         within ±1e9 mm"
    )]
    BadCoordinate {
        /// The job name.
        job: String,
        /// Index of the toolpath in the job.
        path: usize,
        /// Index of the stroke in the toolpath.
        stroke: usize,
    },
    /// An operation setting cannot be written.
    #[error("settings for {op}: {key} = {value}: expected {expected}")]
    BadSetting {
        /// The operation name.
        op: &'static str,
        /// The setting, e.g. `power`.
        key: &'static str,
        /// Its value.
        value: f64,
        /// What was expected.
        expected: &'static str,
    },
    /// The bed has no usable size (SVG page).
    #[error("bed {width_mm} × {height_mm} mm: expected a finite, positive size")]
    BadBed {
        /// Bed width, mm.
        width_mm: f64,
        /// Bed depth, mm.
        height_mm: f64,
    },
    /// More layers than the output format holds.
    #[error(
        "job {job} needs {layers} layers; a LightBurn project holds at most {limit} (its colour \
         layers 00-29): give the calibration grid fewer values"
    )]
    TooManyLayers {
        /// The job name.
        job: String,
        /// Layers needed.
        layers: usize,
        /// Layers the format holds.
        limit: usize,
    },
    /// More distinct dash/gap pairs than a LightBurn project has layers, with LightBurn's
    /// perforation mode.
    #[error(
        "job {job} needs {layers} LightBurn layers with LightBurn's perforation mode (one per \
         distinct dash and gap of the creases); a project holds at most {limit} (its colour \
         layers 00-29): write the dashes as shapes instead (leave out --lightburn-perforation)"
    )]
    TooManyDashPatterns {
        /// The job name.
        job: String,
        /// Layers needed.
        layers: usize,
        /// Layers the format holds.
        limit: usize,
    },
    /// A machine profile value cannot be written.
    #[error("machine {machine}: {key} = {message}")]
    BadMachine {
        /// The profile name.
        machine: String,
        /// The profile key.
        key: &'static str,
        /// The value and what was expected.
        message: String,
    },
}

/// DXF flavour.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum DxfVersion {
    /// R2000 (AC1015): LWPOLYLINE, `$INSUNITS` = 4 (mm).
    #[default]
    R2000,
    /// R12 (AC1009): LINE and POLYLINE only.
    R12,
}

/// G-code for one job on `machine`, in the machine's dialect.
///
/// # Errors
/// [`PostError::NoGcode`] for a file-only machine; [`PostError::BadMachine`],
/// [`PostError::BadSetting`] or [`PostError::BadCoordinate`] for numbers that cannot be
/// written; [`PostError::EmptyJob`] when nothing is left to burn after rounding.
pub fn gcode(plan: &FabPlan, job: &Setup, machine: &MachineProfile) -> Result<String, PostError> {
    gcode::write(plan, job, machine)
}

/// DXF of one job, one layer per operation (and per settings override of the plan, see
/// [`layers`](mod@layers)), in machine coordinates (mm). Speeds and powers stay with the laser
/// software's layers.
///
/// # Errors
/// [`PostError::BadCoordinate`] or [`PostError::EmptyJob`].
pub fn dxf(plan: &FabPlan, job: &Setup, version: DxfVersion) -> Result<Vec<u8>, PostError> {
    check::job(job)?;
    dxf::write(plan, job, version)
}

/// LightBurn project (`.lbrn2`) of one job: one layer per operation with the material's
/// speed, power and passes, in drawing coordinates (mm, y up from the bed's front-left
/// corner). Perforations are the fitted dashes as shapes ([`LbrnPerforation::Dashes`]) or
/// paths for LightBurn's perforation mode, one layer per distinct dash/gap pair
/// ([`LbrnPerforation::LightBurn`]); see [`lbrn`](mod@lbrn) for the format and the LightBurn
/// versions it was compared with.
///
/// # Errors
/// [`PostError::BadCoordinate`], [`PostError::EmptyJob`], [`PostError::TooManyLayers`] or,
/// with LightBurn's perforation mode, [`PostError::TooManyDashPatterns`].
pub fn lbrn2(
    plan: &FabPlan,
    job: &Setup,
    machine: &MachineProfile,
    perforation: LbrnPerforation,
) -> Result<String, PostError> {
    check::job(job)?;
    lbrn::write(plan, job, machine, perforation)
}

/// SVG of one job on `bed`, one Inkscape layer per operation; `dasharray` draws perforations
/// as dashed strokes (for plotting) instead of separate dashes.
///
/// The page is the bed, 1 user unit = 1 mm, seen from above: machine y is flipped back to
/// SVG's downward y unless the bed's y already points that way (`bed.y_flipped`). Each layer
/// names its operation's speed, power and passes from `plan` in its `<desc>`.
///
/// # Errors
/// [`PostError::BadBed`], [`PostError::BadCoordinate`] or [`PostError::EmptyJob`].
pub fn svg(plan: &FabPlan, job: &Setup, bed: &Bed, dasharray: bool) -> Result<String, PostError> {
    check::job(job)?;
    svg::write(plan, job, bed, dasharray)
}
