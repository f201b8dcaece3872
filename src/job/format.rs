//! Machine-job file formats, chosen by extension, and the file names of multi-job plans.

use std::path::{Path, PathBuf};

use crate::fab::FabPlan;
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
