//! Loading an input pattern for a subcommand: read, report warnings, planarise.

use std::path::Path;

use anyhow::Result;
use foldcam::formats::{self, Imported};
use foldcam::pattern::{PlanarizeOptions, PlanarizeReport, Units, planarize};

/// Reads `path`, prints the reader's warnings to stderr, and returns the import.
pub fn load(path: &Path) -> Result<Imported> {
    let imported = formats::load(path)?;
    for w in &imported.warnings {
        eprintln!("foldcam: warning: {}: {w}", path.display());
    }
    Ok(imported)
}

/// Planarises the pattern in place and says on stderr what changed, if anything.
pub fn clean(path: &Path, imported: &mut Imported, tolerance: Option<f64>) -> PlanarizeReport {
    let report = planarize(
        &mut imported.pattern,
        &PlanarizeOptions {
            tolerance,
            faces: false,
        },
    );
    if !report.unchanged() {
        eprintln!(
            "foldcam: {}: cleaned the drawing: {} vertices merged, {} crossings, {} edge splits, \
             {} zero-length and {} duplicate edges removed",
            path.display(),
            report.merged_vertices,
            report.crossings,
            report.splits,
            report.zero_length_removed,
            report.duplicates_removed
        );
    }
    report
}

/// The unit label of a pattern for messages.
pub fn unit_label(units: Units) -> &'static str {
    match units {
        Units::Millimetres => "mm",
        Units::Unitless => "units",
    }
}
