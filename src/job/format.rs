//! Machine-job file formats, chosen by extension, and the file names of multi-job plans.

use std::path::{Path, PathBuf};

use crate::fab::FabPlan;
use crate::post::DxfVersion;

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
    Lbrn2,
}

/// The extensions [`JobFormat::from_path`] knows, for messages.
pub const JOB_EXTENSIONS: &str = ".gcode, .nc, .ngc, .gc, .dxf, .svg or .lbrn2";

impl JobFormat {
    /// The format a file name asks for (case-insensitive extension), DXF as R2000 and SVG
    /// with dashes; `None` for any other extension.
    pub fn from_path(path: &Path) -> Option<JobFormat> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase)?;
        Some(match ext.as_str() {
            "gcode" | "nc" | "ngc" | "gc" => JobFormat::Gcode,
            "dxf" => JobFormat::Dxf(DxfVersion::R2000),
            "svg" => JobFormat::Svg { dasharray: false },
            "lbrn2" => JobFormat::Lbrn2,
            _ => return None,
        })
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
