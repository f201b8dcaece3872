//! What a built design reports: one typed line per fact, warning or note, with the numbers
//! as data. `Display` gives the words `foldcam` prints (some lines, such as the solver's
//! report, print over several text lines); the studio and tests read the fields.

use std::fmt;

use crate::design::folding::LayerProblem;
use crate::design::tessellation::measure::{
    CollisionSites, CurvatureAdvice, RimCrowding, SolveSummary, SurfaceFit, Violation,
};
use crate::design::tessellation::steps::FitReport;
use crate::design::tessellation::{TuckKind, TuckLayout};

/// One line of a design's report ([`super::Design::summary`]).
#[derive(Clone, Debug, PartialEq)]
pub enum SummaryLine {
    /// A voxel card that pops up (Mitani, Suzuki & Uno 2003).
    VoxelCard {
        /// The design file, as named.
        file: String,
        /// Cells across, deep and high.
        cells: [usize; 3],
        /// The edge of a cell, mm.
        cell_mm: f64,
        /// The sheet's width and height, mm.
        sheet_mm: [f64; 2],
    },
    /// A polygon card that pops up (Mitani & Suzuki 2004).
    PolygonCard {
        /// The design file, as named.
        file: String,
        /// Operations replayed.
        operations: usize,
        /// Faces of the card.
        faces: usize,
        /// The sheet's width, mm.
        width_mm: f64,
        /// The base's depth, mm.
        base_mm: f64,
        /// The back's height, mm.
        back_mm: f64,
    },
    /// A fold script's crease pattern (Miyazaki et al. 1992).
    FoldSequence {
        /// The script, as named.
        file: String,
        /// Steps folded.
        steps: usize,
        /// Faces of the folded state.
        faces: usize,
        /// Vertices of the crease pattern.
        vertices: usize,
        /// Edges of the crease pattern.
        edges: usize,
    },
    /// A layer-order problem of a fold script's last state.
    LayerWarning {
        /// The script, as named.
        file: String,
        /// The problem.
        problem: LayerProblem,
    },
    /// A paper craft's parts (Ōgaki 2016).
    PaperCraft {
        /// The design file, as named.
        file: String,
        /// Parts unfolded.
        parts: usize,
        /// Glue tabs placed.
        tabs: usize,
        /// Tabs left out (no room).
        tabs_left_out: usize,
        /// Sheets the parts were packed on.
        sheets: usize,
    },
    /// Cut lines whose edge labels found no room.
    UnlabelledCutLines(Vec<usize>),
    /// Only the first of several sheets is shown (the studio's view of a paper craft).
    FirstSheetOf(usize),
    /// A tessellation's pattern (Tachi 2014): the tucks and the solved mesh.
    Tessellated {
        /// The mesh file, as named.
        file: String,
        /// Gap layout of the tucks.
        layout: TuckLayout,
        /// Tuck structure.
        tuck: TuckKind,
        /// Face shrink of the result.
        shrink: f64,
        /// Vertices of the solved mesh.
        vertices: usize,
        /// Triangles of the solved mesh.
        triangles: usize,
        /// Its interior vertices.
        interior_vertices: usize,
    },
    /// How the solve went.
    Solve(Box<SolveSummary>),
    /// A limit the initial pattern cannot meet.
    CannotMeet(Violation),
    /// A condition the solve left unmet.
    Unmet(Violation),
    /// More input vertices leave the same condition unmet than are listed.
    MoreUnmet(usize),
    /// Where the folded form passes through itself.
    Collisions(Box<CollisionSites>),
    /// The input's rim crowding index (Tachi 2014, Fig. 14).
    Crowding(RimCrowding),
    /// The schedule stopped at a shrink whose only fault is crowding at the rim.
    CrowdedAtRim {
        /// The shrink it stopped at.
        shrink: f64,
    },
    /// The surface fit after solving.
    FitRounds(FitReport),
    /// The unfolded pattern has no overlaps.
    Unfolded {
        /// Largest relative difference between an edge's flat and folded length.
        max_length_error: f64,
    },
    /// How well the folded form stands for the input surface.
    SurfaceFit(SurfaceFit),
    /// What the input's curvature asks of the tucks.
    Curvature(CurvatureAdvice),
    /// The design was refused; nothing was written.
    NothingWritten {
        /// Why.
        reason: String,
    },
}

impl SummaryLine {
    /// Whether this line warns about the result (it is still written).
    pub fn is_warning(&self) -> bool {
        matches!(
            self,
            SummaryLine::LayerWarning { .. } | SummaryLine::UnlabelledCutLines(_)
        )
    }
}

/// Every text line of what `items` print, in order (an item may print several): the
/// studio's list of a design's summary lines or build notes.
pub(crate) fn text_lines<T: fmt::Display>(items: &[T]) -> Vec<String> {
    items
        .iter()
        .flat_map(|item| {
            item.to_string()
                .lines()
                .map(str::to_string)
                .collect::<Vec<_>>()
        })
        .collect()
}

impl fmt::Display for SummaryLine {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let lines = |f: &mut fmt::Formatter<'_>, v: Vec<String>| write!(f, "{}", v.join("\n"));
        match self {
            SummaryLine::VoxelCard {
                file,
                cells: [x, y, z],
                cell_mm,
                sheet_mm: [w, h],
            } => write!(
                f,
                "{file}: {x} × {y} × {z} cells of {cell_mm:.3} mm, sheet {w:.1} × {h:.1} mm, \
                 pops up"
            ),
            SummaryLine::PolygonCard {
                file,
                operations,
                faces,
                width_mm: w,
                base_mm: d,
                back_mm: h,
            } => write!(
                f,
                "{file}: {operations} operations, {faces} faces, sheet {w:.1} × {:.1} mm \
                 (base {d:.1}, back {h:.1}), pops up",
                d + h
            ),
            SummaryLine::FoldSequence {
                file,
                steps,
                faces,
                vertices,
                edges,
            } => write!(
                f,
                "{file}: {steps} steps, {faces} faces, crease pattern of {vertices} vertices \
                 and {edges} edges"
            ),
            SummaryLine::LayerWarning { file, problem } => write!(f, "{file}: warning: {problem}"),
            SummaryLine::PaperCraft {
                file,
                parts,
                tabs,
                tabs_left_out,
                sheets,
            } => write!(
                f,
                "{file}: {parts} parts, {tabs} tabs ({tabs_left_out} left out), {sheets} sheet(s)"
            ),
            SummaryLine::UnlabelledCutLines(cut_lines) => write!(
                f,
                "no room for the edge labels of cut lines {cut_lines:?} (lower label_height)"
            ),
            SummaryLine::FirstSheetOf(sheets) => write!(
                f,
                "showing sheet 1 of {sheets} (`foldcam papercraft` writes sheet n > 1 to \
                 NAME-n.EXT)"
            ),
            SummaryLine::Tessellated {
                file,
                layout,
                tuck,
                shrink,
                vertices,
                triangles,
                interior_vertices,
            } => write!(
                f,
                "{file}: {layout} layout, {tuck} tucks, shrink {shrink}, {vertices} vertices, \
                 {triangles} triangles, {interior_vertices} interior vertices"
            ),
            SummaryLine::Solve(s) => write!(f, "{s}"),
            SummaryLine::CannotMeet(v) => write!(f, "  cannot meet the limits: {}", v.describe()),
            SummaryLine::Unmet(v) => write!(f, "  unmet: {}", v.describe()),
            SummaryLine::MoreUnmet(n) => write!(f, "  ... and {n} more input vertices"),
            SummaryLine::Collisions(sites) => lines(f, sites.describe()),
            SummaryLine::Crowding(c) => lines(f, c.describe()),
            SummaryLine::CrowdedAtRim { shrink } => write!(
                f,
                "stopped at shrink {shrink}: every limit is met but the tucks near the edge \
                 collide, which a smaller shrink did not fix on such meshes"
            ),
            SummaryLine::FitRounds(fit) => write!(
                f,
                "surface fit: distance {:.4e} -> {:.4e} in {} rounds",
                fit.initial, fit.last, fit.accepted
            ),
            SummaryLine::Unfolded { max_length_error } => write!(
                f,
                "unfolded: no overlaps, edge lengths match 3D within {max_length_error:.1e} \
                 (relative)"
            ),
            SummaryLine::SurfaceFit(fit) => write!(f, "{}", fit.describe()),
            SummaryLine::Curvature(advice) => lines(f, advice.describe()),
            SummaryLine::NothingWritten { reason } => write!(f, "nothing written: {reason}"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_card_line_prints_its_numbers_and_texts_split_multi_line_entries() {
        let card = SummaryLine::VoxelCard {
            file: "house.voxel.txt".into(),
            cells: [4, 3, 5],
            cell_mm: 2.5,
            sheet_mm: [10.0, 20.0],
        };
        assert_eq!(
            card.to_string(),
            "house.voxel.txt: 4 × 3 × 5 cells of 2.500 mm, sheet 10.0 × 20.0 mm, pops up"
        );
        assert!(!card.is_warning());
        let unlabelled = SummaryLine::UnlabelledCutLines(vec![3, 7]);
        assert!(unlabelled.is_warning());
        let texts = text_lines(&[
            card,
            SummaryLine::NothingWritten {
                reason: "a\nb".into(),
            },
        ]);
        assert_eq!(texts.len(), 3, "{texts:?}");
        assert_eq!(texts[2], "b");
    }
}
