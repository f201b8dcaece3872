//! Paper craft (Ōgaki 2016) from a `.craft.toml` design and the mesh it names: cut lines on
//! the reference mesh, developable patches, parts with glue tabs packed onto sheets — what
//! `foldcam papercraft` does before it writes anything.
//!
//! The design names its mesh by a path relative to the design's folder; this module never
//! reads it: the caller finds the mesh (the command line beside the design, the studio among
//! the files given with it) and passes it in.

use std::path::{Path, PathBuf};

use super::note::BuildNote;
use super::summary::SummaryLine;
use super::{DesignFile, DesignKind, Progress, SourceError};
use crate::design::papercraft::design::{Design, Made, parse_design};
use crate::mesh::PolyMesh;
use crate::mesh::ReferenceMesh;

/// A design file read, before its mesh is found.
#[derive(Clone, Debug)]
pub struct ParsedCraft {
    /// The design file's name, as given.
    pub name: PathBuf,
    /// The design.
    pub design: Design,
}

impl ParsedCraft {
    /// The mesh path the design names (relative to the design's folder).
    pub fn mesh_name(&self) -> PathBuf {
        PathBuf::from(&self.design.mesh)
    }
}

/// Reads a design file.
///
/// # Errors
/// Bad input naming the file and the place.
pub fn parse(file: &DesignFile<'_>) -> Result<ParsedCraft, SourceError> {
    let design = parse_design(file.text()?).map_err(|e| SourceError::input(file.name, e))?;
    Ok(ParsedCraft {
        name: file.name.to_path_buf(),
        design,
    })
}

/// The parts and sheets of a paper craft.
#[derive(Clone, Debug)]
pub struct CraftDesign {
    /// The design as read.
    pub design: Design,
    /// What the chain made: parts, sheets (one crease pattern each: outlines cut, tab roots
    /// mountain folds, edge numbers flat lines), reports.
    pub made: Made,
    /// What `foldcam papercraft` prints once written.
    pub summary: Vec<SummaryLine>,
    /// What it notes once written (labels that found no room).
    pub late_notes: Vec<SummaryLine>,
}

impl CraftDesign {
    /// As one design: the first sheet.
    ///
    /// # Errors
    /// A design that made no sheet (no parts).
    pub fn into_design(mut self, name: &Path) -> Result<super::Design, SourceError> {
        let sheets = self.made.sheets.len();
        if sheets == 0 {
            return Err(SourceError::input(name, "the design makes no part to cut"));
        }
        let mut summary = self.late_notes;
        summary.append(&mut self.summary);
        if sheets > 1 {
            summary.push(SummaryLine::FirstSheetOf(sheets));
        }
        Ok(super::Design {
            kind: DesignKind::PaperCraft,
            made: "paper craft (Ōgaki 2016)",
            pattern: self.made.sheets.swap_remove(0),
            folded: None,
            summary,
            sheets,
        })
    }
}

/// Builds the parts of `parsed` on `mesh`, read from the file `mesh_name` (named in messages).
///
/// # Errors
/// Bad input naming the design or the mesh and the place.
pub fn build(
    parsed: ParsedCraft,
    mesh_name: &Path,
    mesh: &PolyMesh,
    progress: &mut dyn Progress,
) -> Result<CraftDesign, SourceError> {
    let ParsedCraft { name, design } = parsed;
    let reference = ReferenceMesh::new(mesh).map_err(|e| SourceError::input(mesh_name, e))?;
    progress.note(BuildNote::CraftParts {
        cut_lines: design.cut_lines.len(),
        placed: design.patches.len(),
        generated: design.auto_patches.len(),
        triangles: reference.triangle_count(),
    });
    progress.busy("building the parts");
    let made = design.build(&reference);
    progress.idle();
    let made = made.map_err(|e| SourceError::input(&name, e))?;
    for r in &made.auto {
        for &(q, e, gap) in &r.gaps {
            progress.note(BuildNote::PatchGap {
                patch: r.patch,
                control_points: r.control_points,
                fit_residual: r.fit_residual,
                other: q,
                cut_line: e,
                gap,
                over_tolerance: gap > design.tolerance,
            });
        }
    }
    let mut late_notes = Vec::new();
    if !made.unlabelled.is_empty() {
        late_notes.push(SummaryLine::UnlabelledCutLines(made.unlabelled.clone()));
    }
    let tabs: usize = made.parts.iter().map(|p| p.tabs.len()).sum();
    let dropped: usize = made.parts.iter().map(|p| p.dropped_tabs).sum();
    let summary = vec![SummaryLine::PaperCraft {
        file: name.display().to_string(),
        parts: made.parts.len(),
        tabs,
        tabs_left_out: dropped,
        sheets: made.sheets.len(),
    }];
    let mut made = made;
    for sheet in &mut made.sheets {
        super::title_from(sheet, &name);
    }
    Ok(CraftDesign {
        design,
        made,
        summary,
        late_notes,
    })
}
