//! One job file from a plan, by kind: the bytes `foldcam cut` writes and the studio serves.
//!
//! G-code is read back by the simulated machine ([`super::run`], see [`check_gcode`]) before it is returned;
//! a violation refuses the job, so no caller can hand out a program the machine would reject.

use std::path::Path;

use crate::fab::{FabPlan, Job};
use crate::machine::MachineProfile;
use crate::post::{self, DxfVersion, PostError};

/// The kind of job file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JobKind {
    /// G-code (`.gcode`, `.nc`, `.ngc`, `.gc`), checked on the simulated machine.
    Gcode,
    /// DXF (`.dxf`), R2000 unless R12 is asked for.
    Dxf,
    /// SVG (`.svg`) on the machine's bed.
    Svg,
    /// LightBurn project (`.lbrn2`).
    Lbrn2,
}

impl JobKind {
    /// Extensions accepted, for messages.
    pub const EXTENSIONS: &'static str = ".gcode, .nc, .ngc, .dxf, .svg or .lbrn2";

    /// The kind for an extension (case-insensitive, without the dot), `None` if unknown.
    pub fn from_extension(ext: &str) -> Option<JobKind> {
        Some(match ext.to_ascii_lowercase().as_str() {
            "gcode" | "nc" | "ngc" | "gc" => JobKind::Gcode,
            "dxf" => JobKind::Dxf,
            "svg" => JobKind::Svg,
            "lbrn2" => JobKind::Lbrn2,
            _ => return None,
        })
    }

    /// The kind for a path's extension, `None` if unknown.
    pub fn from_path(path: &Path) -> Option<JobKind> {
        JobKind::from_extension(path.extension()?.to_str()?)
    }

    /// The usual extension (without the dot).
    pub fn extension(self) -> &'static str {
        match self {
            JobKind::Gcode => "gcode",
            JobKind::Dxf => "dxf",
            JobKind::Svg => "svg",
            JobKind::Lbrn2 => "lbrn2",
        }
    }
}

/// How to write the files that have choices.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct JobFileOptions {
    /// DXF R12 (LINE/POLYLINE) instead of R2000.
    pub r12: bool,
    /// SVG: perforations as dashed strokes instead of separate dashes.
    pub dasharray: bool,
}

/// Why a job file could not be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum JobFileError {
    /// The writer refused the job.
    #[error(transparent)]
    Post(#[from] PostError),
    /// The simulated machine could not read the program.
    #[error(transparent)]
    Sim(#[from] super::SimError),
    /// The simulated machine found problems in the program.
    #[error(
        "the simulated {machine} found {count} problem(s) in the job, first at line {line}: \
         {message}"
    )]
    Violations {
        /// The machine profile's name.
        machine: String,
        /// How many problems.
        count: usize,
        /// Line of the first problem.
        line: usize,
        /// The first problem.
        message: String,
    },
}

/// The bytes of one job of `plan` as a file of `kind` for `machine`.
///
/// # Errors
/// The writer's [`PostError`], or for G-code the simulated machine's refusal.
pub fn job_file(
    kind: JobKind,
    plan: &FabPlan,
    job: &Job,
    machine: &MachineProfile,
    options: JobFileOptions,
) -> Result<Vec<u8>, JobFileError> {
    Ok(match kind {
        JobKind::Gcode => {
            let text = post::gcode(plan, job, machine)?;
            check_gcode(&text, machine)?;
            text.into_bytes()
        }
        JobKind::Dxf => {
            let version = if options.r12 {
                DxfVersion::R12
            } else {
                DxfVersion::R2000
            };
            post::dxf(plan, job, version)?
        }
        JobKind::Svg => post::svg(plan, job, &machine.bed, options.dasharray)?.into_bytes(),
        JobKind::Lbrn2 => post::lbrn2(plan, job, machine)?.into_bytes(),
    })
}

/// Runs G-code `text` on the simulated `machine`.
///
/// # Errors
/// [`JobFileError::Sim`] if the machine cannot read it, [`JobFileError::Violations`] naming the
/// first violation if it breaks the machine's limits.
pub fn check_gcode(text: &str, machine: &MachineProfile) -> Result<(), JobFileError> {
    let report = super::run(text, machine)?;
    match report.violations.first() {
        Some(v) => Err(JobFileError::Violations {
            machine: machine.name.clone(),
            count: report.violation_count,
            line: v.line,
            message: v.message.clone(),
        }),
        None => Ok(()),
    }
}
