//! Machine-job file formats, chosen by extension, and the file names of jobs: multi-job plans
//! (`NAME.JOB.EXT`) and jobs named by what they are (`PATTERN.MACHINE.MATERIAL.EXT`).

use std::path::{Path, PathBuf};

use crate::fab::FabPlan;
use crate::machine::{Dialect, MachineProfile, Material};
use crate::post::{DxfVersion, LbrnPerforation};

/// A machine-job file format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JobFormat {
    /// G-code in the machine's dialect (`.gcode`, `.nc`, `.ngc`, `.gc`).
    Gcode,
    /// DXF, R2000 or R12 (`.dxf`).
    Dxf(DxfVersion),
    /// Layered SVG (`.svg`); `dasharray` draws perforations as dashed strokes for plotting.
    Svg {
        /// Perforations as one dashed stroke instead of dashes.
        dasharray: bool,
    },
    /// LightBurn project, one layer per operation (`.lbrn2`).
    Lbrn2 {
        /// Perforations as dash shapes (the default) or LightBurn's perforation mode.
        perforation: LbrnPerforation,
    },
}

/// The extensions [`JobFormat::from_path`] knows, for messages.
pub const JOB_EXTENSIONS: &str = ".gcode, .nc, .ngc, .gc, .dxf, .svg or .lbrn2";

impl JobFormat {
    /// The format an extension asks for (case-insensitive, without the dot), DXF as R2000
    /// SVG with dashes and LightBurn projects with dash shapes; `None` for any other extension.
    pub fn from_extension(ext: &str) -> Option<JobFormat> {
        Some(match ext.to_ascii_lowercase().as_str() {
            "gcode" | "nc" | "ngc" | "gc" => JobFormat::Gcode,
            "dxf" => JobFormat::Dxf(DxfVersion::R2000),
            "svg" => JobFormat::Svg { dasharray: false },
            "lbrn2" => JobFormat::Lbrn2 {
                perforation: LbrnPerforation::Dashes,
            },
            _ => return None,
        })
    }

    /// The format a file name asks for by its extension (see [`JobFormat::from_extension`]).
    pub fn from_path(path: &Path) -> Option<JobFormat> {
        JobFormat::from_extension(path.extension()?.to_str()?)
    }

    /// The usual extension (without the dot).
    pub fn extension(self) -> &'static str {
        match self {
            JobFormat::Gcode => "gcode",
            JobFormat::Dxf(_) => "dxf",
            JobFormat::Svg { .. } => "svg",
            JobFormat::Lbrn2 { .. } => "lbrn2",
        }
    }
}

/// One path per job of `plan`: `output` itself for a single job, else `NAME.JOB.EXT` (e.g.
/// `card.front.gcode`, `card.back.gcode`).
pub fn job_paths(output: &Path, plan: &FabPlan) -> Vec<PathBuf> {
    if plan.jobs.len() <= 1 {
        return vec![output.to_path_buf()];
    }
    let stem = output
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let ext = output
        .extension()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    plan.jobs
        .iter()
        .map(|j| output.with_file_name(format!("{stem}.{}.{ext}", j.name)))
        .collect()
}

/// The file name of a job of `pattern` on `machine` in `material`:
/// `PATTERN.MACHINE.MATERIAL.EXT` (the profiles' names), with the job's name before the
/// extension when the plan has several (`card.grbl-diode.card-300gsm.back.gcode`); G-code for
/// LinuxCNC ends in `.ngc`, LinuxCNC's own. What the demo writes and the studio offers for
/// download.
///
/// ```
/// use foldcam::job::{JobFormat, job_file_name};
/// use foldcam::machine::{load_machine, load_material};
/// let (diode, card) = (load_machine("grbl-diode")?, load_material("card-300gsm")?);
/// let name = job_file_name("miura-ori", &diode, &card, None, JobFormat::Gcode);
/// assert_eq!(name, "miura-ori.grbl-diode.card-300gsm.gcode");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn job_file_name(
    pattern: &str,
    machine: &MachineProfile,
    material: &Material,
    job: Option<&str>,
    format: JobFormat,
) -> String {
    let job = job.map_or(String::new(), |j| format!(".{j}"));
    let ext = match (format, machine.dialect) {
        (JobFormat::Gcode, Dialect::LinuxCnc) => "ngc",
        _ => format.extension(),
    };
    format!("{pattern}.{}.{}{job}.{ext}", machine.name, material.name)
}

#[cfg(test)]
mod table_tests {
    /// Every extension the help and messages list is one the job writers take.
    #[test]
    fn the_listed_job_extensions_are_the_ones_written() {
        let listed = super::JOB_EXTENSIONS.replace(" or ", ", ");
        for e in listed.split(", ") {
            let e = e.trim_start_matches('.');
            assert!(super::JobFormat::from_extension(e).is_some(), "{e}");
        }
    }
}
