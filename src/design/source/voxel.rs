//! Voxel pop-up cards (Mitani, Suzuki & Uno 2003) from a design file: the text front view, a
//! height-map PNG, or a mesh seen from the front through the paper's section 3 conversion;
//! then the pop-up check, optional fitting, the crease pattern and the card's own checks —
//! what `foldcam popup voxel` does before it writes anything.

use std::path::Path;

use super::card::{card_holds, take_fit};
use super::note::BuildNote;
use super::summary::SummaryLine;
use super::{DesignFile, DesignKind, Progress, SourceError};
use crate::clock::Stopwatch;
use crate::design::popup::fit::fit_voxel_card;
use crate::design::popup::voxel::estimate::conversion_estimate;
use crate::design::popup::voxel::{
    ConvertOptions, ConvertReport, DepthField, DepthMap, MeshPlacement, UpAxis, VoxelCard,
    card_from_depths, check_popup, crease_pattern, depth_field_from_mesh, fold_card,
    parse_voxel_card,
};
use crate::limits;
use crate::mesh::PolyMesh;
use crate::pattern::{CreasePattern, FoldedState};

/// Most front faces listed when the card would not pop up.
const PROBLEMS_SHOWN: usize = 40;

/// How a height map or mesh becomes a card, and whether to fit the card; each default is
/// `foldcam popup voxel`'s.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VoxelOptions {
    /// Mesh: cells along the fold (Mitani, Suzuki & Uno 2003 used 80).
    pub resolution: usize,
    /// Mesh: which axis points up.
    pub up: UpAxis,
    /// Mesh: part of the model's depth, from its front, that stands out of the card.
    pub keep_depth: f64,
    /// Height map: depth of the base in cells (white = this far out); at least 1.
    pub depth: usize,
    /// Cell size, mm (default: `card_width` over the cells along the fold).
    pub cell_mm: Option<f64>,
    /// Width of the cells along the fold, mm.
    pub card_width: f64,
    /// Flat paper around the cells, mm.
    pub card_margin: f64,
    /// Side of the square element that removes small bumps, cells (odd; 1 = off).
    pub morphology: usize,
    /// Open windows under overhangs.
    pub windows: bool,
    /// Open a window only where the overhang stands out at least this part of the base depth.
    pub window_gap: f64,
    /// Leave out top faces at most this many columns wide where the card still pops up.
    pub thin_top: usize,
    /// Grow the margin until the card, folded shut, holds every face; refuse when it cannot.
    pub fit: bool,
    /// Most cells of the card's pattern, `nx × (ny + nz)`, checked before the card is built
    /// (the command line's [`limits::VOXEL_PATTERN_CELLS`]; the studio's is smaller).
    pub max_pattern_cells: usize,
}

impl Default for VoxelOptions {
    fn default() -> Self {
        VoxelOptions {
            resolution: 80,
            up: UpAxis::Z,
            keep_depth: 0.5,
            depth: 40,
            cell_mm: None,
            card_width: 160.0,
            card_margin: 10.0,
            morphology: 3,
            windows: true,
            window_gap: 0.25,
            thin_top: 1,
            fit: false,
            max_pattern_cells: limits::VOXEL_PATTERN_CELLS,
        }
    }
}

impl VoxelOptions {
    /// Refuses options outside the ranges of [`crate::limits`].
    ///
    /// # Errors
    /// [`SourceError::Option`] naming the option and its range.
    pub fn validate(&self) -> Result<(), SourceError> {
        let bad = |e: String, name: &str| SourceError::Option(format!("{name}: {e}"));
        limits::RESOLUTION
            .check(i64::try_from(self.resolution).unwrap_or(i64::MAX))
            .map_err(|e| bad(e, limits::RESOLUTION.option))?;
        if let Some(cell) = self.cell_mm {
            limits::CELL
                .check(cell)
                .map_err(|e| bad(e, &limits::CELL.name()))?;
        }
        limits::CARD_WIDTH
            .check(self.card_width)
            .map_err(|e| bad(e, &limits::CARD_WIDTH.name()))?;
        if self.depth == 0 {
            return Err(SourceError::Option(
                "--depth must be at least 1 cell".into(),
            ));
        }
        Ok(())
    }
}

/// A voxel card that pops up, its crease pattern, and the card folded shut.
#[derive(Clone, Debug)]
pub struct VoxelDesign {
    /// The card (fitted when asked).
    pub card: VoxelCard,
    /// Its crease pattern (valleys +90°, mountains −90°, cuts).
    pub pattern: CreasePattern,
    /// The card folded shut (opening 0°).
    pub closed: FoldedState,
    /// What `foldcam popup voxel` prints when it has written the card.
    pub summary: Vec<SummaryLine>,
}

impl VoxelDesign {
    /// The card's folded state at an opening angle, degrees (0 shut, 90 standing).
    pub fn fold_at(&self, opening_deg: f64) -> FoldedState {
        fold_card(&self.card, &self.pattern, opening_deg).state
    }

    /// As one design (no folded state: the command writes the pattern alone).
    pub fn into_design(self, kind: DesignKind) -> super::Design {
        super::Design {
            kind,
            made: "voxel pop-up card (Mitani, Suzuki & Uno 2003)",
            pattern: self.pattern,
            folded: None,
            summary: self.summary,
            sheets: 1,
        }
    }
}

/// Reads or builds the card `file` describes: a mesh when `mesh` is given (already read from
/// the file), a height map for a `.png`, else the text format.
///
/// # Errors
/// Bad input naming the file and the place; bad options.
pub fn load_card(
    file: &DesignFile<'_>,
    mesh: Option<&PolyMesh>,
    options: &VoxelOptions,
    progress: &mut dyn Progress,
) -> Result<VoxelCard, SourceError> {
    options.validate()?;
    let at = |e: &dyn std::fmt::Display| SourceError::input(file.name, e);
    let is_png = file
        .name
        .to_string_lossy()
        .to_ascii_lowercase()
        .ends_with(".png");
    let field = if let Some(mesh) = mesh {
        let placement = MeshPlacement {
            up: options.up,
            resolution: options.resolution,
            keep_depth: options.keep_depth,
        };
        let started = Stopwatch::start();
        let (field, _) = depth_field_from_mesh(mesh, &placement).map_err(|e| at(&e))?;
        progress.note(BuildNote::MeshAsCells {
            faces: mesh.faces().len(),
            cells: [field.nx, field.ny, field.nz],
            took: started.elapsed(),
        });
        field
    } else if is_png {
        if options.depth == 0 {
            return Err(SourceError::Option(
                "--depth must be at least 1 cell".into(),
            ));
        }
        let image = image::load_from_memory_with_format(file.bytes, image::ImageFormat::Png)
            .map_err(|e| at(&e))?;
        let grey = image.to_luma16();
        let map = DepthMap {
            width: grey.width() as usize,
            height: grey.height() as usize,
            levels: grey.as_raw(),
        };
        DepthField::from_grey(map, options.depth).map_err(|e| at(&e))?
    } else {
        let card = parse_voxel_card(file.text()?).map_err(|e| at(&e))?;
        check_cells(file.name, [card.nx(), card.ny(), card.nz()], options)?;
        return Ok(card);
    };
    check_cells(file.name, [field.nx, field.ny, field.nz], options)?;
    card_from_field(file.name, &field, options, progress)
}

/// Refuses a card of `nx × ny × nz` cells whose pattern holds more cells than
/// [`VoxelOptions::max_pattern_cells`], before it is built.
pub fn check_cells(
    name: &Path,
    [nx, ny, nz]: [usize; 3],
    options: &VoxelOptions,
) -> Result<(), SourceError> {
    let cells = nx.saturating_mul(ny.saturating_add(nz));
    if cells > options.max_pattern_cells {
        return Err(SourceError::input(
            name,
            format!(
                "a card of {nx} × {ny} × {nz} cells has a crease pattern of {cells} cells, more \
                 than the {} built here (memory): give a lower resolution or a smaller card",
                options.max_pattern_cells
            ),
        ));
    }
    Ok(())
}

/// The conversion of section 3 (bump removal, filling under overhangs by eq. 7, windows,
/// thin tops) on a depth field, then the margin.
fn card_from_field(
    name: &Path,
    field: &DepthField,
    options: &VoxelOptions,
    progress: &mut dyn Progress,
) -> Result<VoxelCard, SourceError> {
    let cell_mm = options
        .cell_mm
        .unwrap_or(options.card_width / field.nx as f64);
    progress.note(BuildNote::BuildingCard {
        cells: [field.nx, field.ny, field.nz],
        estimate: conversion_estimate(field),
    });
    let convert = ConvertOptions {
        element: options.morphology,
        windows: options.windows,
        window_gap: options.window_gap,
        thin_top: options.thin_top,
    };
    progress.busy("building the card");
    let built = card_from_depths(field, cell_mm, &convert);
    progress.idle();
    let (mut card, report) = built.map_err(|e| SourceError::input(name, e))?;
    card.set_margin_mm(options.card_margin)
        .map_err(|e| SourceError::Option(format!("--card-margin: {e}")))?;
    conversion_notes(&report, progress);
    Ok(card)
}

fn conversion_notes(r: &ConvertReport, progress: &mut dyn Progress) {
    progress.note(BuildNote::BumpsRemoved {
        cells: r.smoothed_cells,
        took: r.smoothing_time,
    });
    progress.note(BuildNote::Overhangs {
        added_cells: r.added_cells,
        filled_rows: r.filled_rows,
        window_rows: r.window_rows,
        window_candidates: r.window_candidates,
        took: r.constraint_time,
    });
    progress.note(BuildNote::ThinTops {
        omitted: r.tops_omitted,
        thin_tops: r.thin_tops,
        checks: r.checks,
        full_checks: r.full_checks,
        took: r.thin_top_time,
    });
}

/// Checks, fits (when asked) and creases a loaded card. `converted` says whether the card
/// came from a mesh or height map (the refusal then suggests other conversion options).
///
/// # Errors
/// [`SourceError::NotMade`] when the card would not pop up, loses a piece or (with `fit`)
/// cannot be fitted; bad input when the crease pattern cannot be made.
pub fn finish_card(
    name: &Path,
    card: VoxelCard,
    converted: bool,
    options: &VoxelOptions,
    progress: &mut dyn Progress,
) -> Result<VoxelDesign, SourceError> {
    let report = check_popup(&card);
    if !report.passed() {
        let mut lines = vec![format!(
            "{}: the card would not pop up: Mitani, Suzuki & Uno (2003) require every vertical \
             face to be joined by folds to both the back sheet and the base",
            name.display()
        )];
        lines.extend(
            report
                .problems
                .iter()
                .take(PROBLEMS_SHOWN)
                .map(|p| format!("  {}", p.describe_at(card.cell_mm()))),
        );
        if report.problems.len() > PROBLEMS_SHOWN {
            lines.push(format!(
                "  … and {} more vertical faces",
                report.problems.len() - PROBLEMS_SHOWN
            ));
        }
        if converted {
            lines.push(format!(
                "  try: a smaller --morphology (now {}; 3 is the paper's, 1 turns bump removal \
                 off), another --resolution (now {}), or --thin-top 0",
                options.morphology, options.resolution
            ));
        }
        return Err(SourceError::NotMade { lines });
    }
    let card = if options.fit {
        take_fit(name, fit_voxel_card(&card), "margin", progress)?
    } else {
        card
    };
    let mut pattern = crease_pattern(&card).map_err(|e| SourceError::input(name, e))?;
    super::title_from(&mut pattern, name);
    let closed = fold_card(&card, &pattern, 0.0).state;
    let hint = "try another --resolution, a larger --thin-top (or 0 to keep every top), or a \
                smaller --morphology";
    card_holds(
        name,
        &pattern,
        &closed,
        options.fit,
        hint,
        |_| true,
        progress,
    )?;
    let (w, h) = card.sheet_mm();
    let summary = vec![SummaryLine::VoxelCard {
        file: name.display().to_string(),
        cells: [card.nx(), card.ny(), card.nz()],
        cell_mm: card.cell_mm(),
        sheet_mm: [w, h],
    }];
    Ok(VoxelDesign {
        card,
        pattern,
        closed,
        summary,
    })
}

/// [`load_card`] then [`finish_card`]: the whole of `foldcam popup voxel` but the writing.
///
/// # Errors
/// As the two steps.
pub fn build(
    file: &DesignFile<'_>,
    mesh: Option<&PolyMesh>,
    options: &VoxelOptions,
    progress: &mut dyn Progress,
) -> Result<VoxelDesign, SourceError> {
    // Everything but the text format went through the conversion.
    let converted = mesh.is_some()
        || !file
            .name
            .to_string_lossy()
            .to_ascii_lowercase()
            .ends_with(".txt");
    let card = load_card(file, mesh, options, progress)?;
    finish_card(file.name, card, converted, options, progress)
}
