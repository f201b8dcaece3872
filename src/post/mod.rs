//! PLACEHOLDER (post work): writers from a plan to machine files.

use crate::fab::{FabPlan, Job};
use crate::machine::MachineProfile;

/// Why a file could not be written.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PostError {
    /// The machine takes no G-code (an output-only profile).
    #[error("machine {machine} takes no G-code (dialect file-only): write .dxf or .svg")]
    NoGcode {
        /// The profile name.
        machine: String,
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

/// G-code for one job on `machine`.
pub fn gcode(_plan: &FabPlan, _job: &Job, _machine: &MachineProfile) -> Result<String, PostError> {
    todo!()
}

/// DXF of one job, one layer per operation.
pub fn dxf(_plan: &FabPlan, _job: &Job, _version: DxfVersion) -> Vec<u8> {
    todo!()
}

/// SVG of one job, one Inkscape layer per operation; `dasharray` draws perforations as dashed
/// strokes (for plotting) instead of separate dashes.
pub fn svg(_plan: &FabPlan, _job: &Job, _dasharray: bool) -> String {
    todo!()
}
