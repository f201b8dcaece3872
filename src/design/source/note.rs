//! What a build says while it runs ([`super::Progress::note`]): one typed note per event, the
//! numbers as data, `Display` the words `foldcam` prints on standard error (after
//! `foldcam: `; a warning's words begin with `warning: `).

use std::fmt;
use std::time::Duration;

use glam::DVec2;

use crate::design::estimate::Estimate;
use crate::design::tessellation::measure::{CurvatureAdvice, LadderEstimate, RimCrowding};

/// One note of a running build.
#[derive(Clone, Debug, PartialEq)]
pub enum BuildNote {
    /// A paper craft's design read (Ōgaki 2016).
    CraftParts {
        /// Cut lines drawn.
        cut_lines: usize,
        /// Patches placed by hand.
        placed: usize,
        /// Patches generated.
        generated: usize,
        /// Triangles of the mesh.
        triangles: usize,
    },
    /// Two generated paper-craft patches meet on a cut line with a gap.
    PatchGap {
        /// The patch.
        patch: usize,
        /// Its control points.
        control_points: usize,
        /// Its fit residual.
        fit_residual: f64,
        /// The patch it meets.
        other: usize,
        /// The cut line they meet on.
        cut_line: usize,
        /// The gap, mm.
        gap: f64,
        /// Whether the gap is over the design's tolerance (the patches cannot meet on one
        /// cylinder).
        over_tolerance: bool,
    },
    /// A mesh seen from the front as voxel cells (Mitani, Suzuki & Uno 2003).
    MeshAsCells {
        /// Faces of the mesh.
        faces: usize,
        /// Cells across, deep and high.
        cells: [usize; 3],
        /// How long it took.
        took: Duration,
    },
    /// A voxel card about to be built, with its estimate.
    BuildingCard {
        /// Cells across, deep and high.
        cells: [usize; 3],
        /// The estimate.
        estimate: Estimate,
    },
    /// Bumps smoothed away.
    BumpsRemoved {
        /// Cells changed.
        cells: u64,
        /// How long it took.
        took: Duration,
    },
    /// Overhangs filled and windows made.
    Overhangs {
        /// Voxels added under overhangs.
        added_cells: u64,
        /// Rows filled.
        filled_rows: usize,
        /// Candidate rows made windows.
        window_rows: usize,
        /// Candidate rows.
        window_candidates: usize,
        /// How long it took.
        took: Duration,
    },
    /// Thin top faces left out.
    ThinTops {
        /// Left out.
        omitted: usize,
        /// Found.
        thin_tops: usize,
        /// Pop-up checks made.
        checks: usize,
        /// Of which over the whole card.
        full_checks: usize,
        /// How long it took.
        took: Duration,
    },
    /// `--fit` added paper to a card that reached beyond its outline when shut.
    Fitted {
        /// The card's file, as named.
        file: String,
        /// How far it reached, mm.
        beyond_mm: f64,
        /// Where, mm on the closed card.
        at: DVec2,
        /// Paper added, mm.
        added_mm: f64,
        /// To what (e.g. "back sheet").
        to: String,
    },
    /// A card reaches beyond its outline when shut (a warning).
    ClosedOverhang {
        /// The card's file, as named.
        file: String,
        /// How far it reaches, mm.
        beyond_mm: f64,
        /// The outline's width and height, mm.
        outline_mm: [f64; 2],
        /// Where, mm on the closed card.
        at: DVec2,
    },
    /// A polygon card's operations replayed (Mitani & Suzuki 2004).
    Replaying {
        /// Operations.
        operations: usize,
    },
    /// A tessellation solve begins (Tachi 2014).
    Solving {
        /// The mesh's file, as named.
        file: String,
        /// Its faces.
        faces: usize,
        /// Largest fold angle, degrees.
        max_fold_deg: f64,
        /// Smallest vertex angle, degrees.
        min_vertex_angle_deg: f64,
    },
    /// How much a tessellation's schedule may solve, and how long it should take.
    SolveEstimate {
        /// Face shrinks tried per triangulation.
        shrinks: usize,
        /// Triangulations.
        passes: usize,
        /// The time from the solver's history.
        estimate: LadderEstimate,
        /// The time limit, if any.
        time_limit: Option<Duration>,
    },
    /// What the input's curvature asks of the tucks.
    Curvature(CurvatureAdvice),
    /// The input's rim crowding index, when crowded (Tachi 2014, Fig. 14).
    Crowding(RimCrowding),
    /// A coarser re-triangulation is solved first because of crowding.
    CoarserFirst {
        /// Its faces, about.
        faces: usize,
        /// The input's faces.
        input_faces: usize,
    },
    /// A face shrink gave no usable result.
    ShrinkRefused {
        /// The shrink.
        shrink: f64,
        /// Why.
        problem: String,
        /// Whether it was the last shrink of the ladder.
        last: bool,
    },
}

impl BuildNote {
    /// Whether the note warns about the result.
    pub fn is_warning(&self) -> bool {
        matches!(self, BuildNote::ClosedOverhang { .. })
    }
}

impl fmt::Display for BuildNote {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BuildNote::CraftParts {
                cut_lines,
                placed,
                generated,
                triangles,
            } => write!(
                f,
                "{cut_lines} cut lines, {placed} placed and {generated} generated patches on a \
                 mesh of {triangles} triangles"
            ),
            BuildNote::PatchGap {
                patch,
                control_points,
                fit_residual,
                other,
                cut_line,
                gap,
                over_tolerance,
            } => write!(
                f,
                "patch {patch} ({control_points} control points, fit residual \
                 {fit_residual:.2e}) meets patch {other} on cut line {cut_line} with a gap of \
                 {gap:.2e}{}",
                if *over_tolerance {
                    " (above the tolerance: the patches cannot meet on one cylinder)"
                } else {
                    ""
                }
            ),
            BuildNote::MeshAsCells {
                faces,
                cells: [x, y, z],
                took,
            } => write!(
                f,
                "{faces} faces seen from the front as {x} × {y} × {z} cells in {took:.1?}"
            ),
            BuildNote::BuildingCard {
                cells: [x, y, z],
                estimate,
            } => write!(
                f,
                "building a card of {x} × {y} × {z} cells: {estimate} (estimated)"
            ),
            BuildNote::BumpsRemoved { cells, took } => {
                write!(f, "bumps removed ({cells} cells changed) in {took:.1?}")
            }
            BuildNote::Overhangs {
                added_cells,
                filled_rows,
                window_rows,
                window_candidates,
                took,
            } => write!(
                f,
                "filling under overhangs added {added_cells} voxels in {filled_rows} rows; \
                 {window_rows} of {window_candidates} candidate rows became windows; {took:.1?}"
            ),
            BuildNote::ThinTops {
                omitted,
                thin_tops,
                checks,
                full_checks,
                took,
            } => write!(
                f,
                "{omitted} of {thin_tops} thin top faces left out; {checks} pop-up checks \
                 ({full_checks} over the whole card); {took:.1?}"
            ),
            BuildNote::Fitted {
                file,
                beyond_mm,
                at,
                added_mm,
                to,
            } => write!(
                f,
                "{file}: folded shut, the card reached {beyond_mm:.1} mm beyond its outline (at \
                 x = {:.1}, y = {:.1} mm of the closed card); --fit added {added_mm:.0} mm to \
                 the {to}",
                at.x, at.y
            ),
            BuildNote::ClosedOverhang {
                file,
                beyond_mm,
                outline_mm: [w, h],
                at,
            } => write!(
                f,
                "warning: {}; --fit adds the paper it needs",
                closed_overhang_text(file, *beyond_mm, [*w, *h], *at)
            ),
            BuildNote::Replaying { operations } => write!(f, "replaying {operations} operations"),
            BuildNote::Solving {
                file,
                faces,
                max_fold_deg,
                min_vertex_angle_deg,
            } => write!(
                f,
                "{file}: {faces} faces; solving (fold <= {max_fold_deg:.1} deg, vertex angle \
                 >= {min_vertex_angle_deg:.1} deg)"
            ),
            BuildNote::SolveEstimate {
                shrinks,
                passes,
                estimate,
                time_limit,
            } => {
                write!(
                    f,
                    "estimate: up to {} solve(s): {shrinks} face shrink(s) on {passes} \
                     triangulation(s), a colliding one solved once more with the stiffer \
                     outline; {estimate}",
                    passes * shrinks
                )?;
                if let Some(limit) = time_limit {
                    write!(
                        f,
                        "; the time limit stops it after {:.0} s (--time-limit)",
                        limit.as_secs_f64()
                    )?;
                }
                Ok(())
            }
            BuildNote::Curvature(advice) => write!(f, "{}", advice.describe().join("\n")),
            BuildNote::Crowding(c) => write!(f, "{}", c.describe().join("\n")),
            BuildNote::CoarserFirst { faces, input_faces } => write!(
                f,
                "rim crowding: solving a coarser re-triangulation (about {faces} faces) first; \
                 the input's {input_faces} faces only if it gives no usable result"
            ),
            BuildNote::ShrinkRefused {
                shrink,
                problem,
                last,
            } => write!(
                f,
                "shrink {shrink}: {problem}; {}",
                if *last {
                    "no shrink worked on these triangles"
                } else {
                    "trying a smaller shrink"
                }
            ),
        }
    }
}

/// A card that reaches beyond its outline when shut, in words (shared by the warning and
/// the refusal with `--fit`).
pub(crate) fn closed_overhang_text(
    file: &str,
    beyond_mm: f64,
    outline: [f64; 2],
    at: DVec2,
) -> String {
    format!(
        "{file}: folded shut, the card reaches {beyond_mm:.1} mm beyond its {:.1} × {:.1} mm \
         outline (at x = {:.1}, y = {:.1} mm of the closed card)",
        outline[0], outline[1], at.x, at.y
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_note_keeps_its_numbers_and_says_them_as_the_command_prints_them() {
        let refused = BuildNote::ShrinkRefused {
            shrink: 0.8,
            problem: "3 pairs cross".into(),
            last: false,
        };
        assert_eq!(
            refused.to_string(),
            "shrink 0.8: 3 pairs cross; trying a smaller shrink"
        );
        let last = BuildNote::ShrinkRefused {
            shrink: 0.5,
            problem: "3 pairs cross".into(),
            last: true,
        };
        assert!(
            last.to_string()
                .ends_with("no shrink worked on these triangles")
        );
        let overhang = BuildNote::ClosedOverhang {
            file: "card.voxel.txt".into(),
            beyond_mm: 2.5,
            outline_mm: [100.0, 80.0],
            at: DVec2::new(10.0, 5.0),
        };
        assert!(overhang.is_warning() && !refused.is_warning());
        assert_eq!(
            overhang.to_string(),
            "warning: card.voxel.txt: folded shut, the card reaches 2.5 mm beyond its 100.0 × \
             80.0 mm outline (at x = 10.0, y = 5.0 mm of the closed card); --fit adds the paper \
             it needs"
        );
    }
}
