//! Editing a polygon pop-up design as the interactive editor of Mitani & Suzuki (2004) does:
//! faces and openings are added, moved, resized and removed, and every edit gives a new
//! [`Design`] whose operations (§3.1) are replayed from the blank card — each face is the
//! paper's regularised difference on the pattern (§3.2, eq. 5), each opening its equivalent
//! face (§3.3, eq. 6) — so the pattern condition (eq. 4) holds after every edit.
//!
//! An edit the model refuses (a plane outside the card, an outline with no area on the
//! sheet) is an [`EditError`] naming the operation; an edit that the model takes but after
//! which the card no longer pops up is not refused: [`findings`] says which faces fail the
//! check of §3.6 and why, in words, with the operation that made each face and its outline
//! on the pattern.
//!
//! Coordinates are the design file's: on a vertical plane (y = `at`) a polygon's points are
//! `(x, z)`, on a horizontal plane (z = `at`) they are `(x, y)`, millimetres (or grid units
//! for an operation written with `units = "grid"`; an edited operation is rewritten in
//! millimetres). [`write_design`] writes a design back as the `.popup.toml` text
//! `foldcam popup poly` reads.

use std::fmt::Write as _;

use glam::DVec2;
use thiserror::Error;

use super::check::PopupReport;
use super::design::{Add, Design, DesignError, Operation, PlaneName, Units};
use super::lines::PieceId;
use super::model::{Plane, PolygonCard};
use crate::design::popup::problem::PopupProblem;

/// Smallest side (mm) of the box a resized outline is fitted into.
pub const MIN_RESIZE_MM: f64 = 0.1;

/// One edit of a design. Operations are numbered from 1 in file order (face `n + 1` of the
/// card is operation `n`).
#[derive(Clone, Debug, PartialEq)]
pub enum Edit {
    /// Appends an operation: a new face or opening on its reference plane.
    Add(Operation),
    /// Moves operation `operation` by `by = (dx, dy, dz)` in card space, millimetres: a
    /// vertical plane moves by `dy` and its outline by `(dx, dz)`, a horizontal plane by
    /// `dz` and its outline by `(dx, dy)`.
    Move {
        /// 1-based operation number.
        operation: usize,
        /// Card-space translation, millimetres.
        by: [f64; 3],
    },
    /// Fits operation `operation`'s outline into the box `lo..hi` on its plane (x and the
    /// plane's second coordinate, millimetres): each axis is scaled from the outline's own
    /// bounding box, so a rectangle becomes exactly that box and a slanted outline keeps its
    /// shape.
    Resize {
        /// 1-based operation number.
        operation: usize,
        /// Lower corner on the plane, millimetres.
        lo: [f64; 2],
        /// Upper corner on the plane, millimetres.
        hi: [f64; 2],
    },
    /// Removes an operation; the later ones are replayed without it.
    Remove {
        /// 1-based operation number.
        operation: usize,
    },
}

/// Why an edit is refused.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum EditError {
    /// The edit names an operation the design does not have.
    #[error("there is no operation {operation}: the design has {count}")]
    NoOperation {
        /// The 1-based number given.
        operation: usize,
        /// How many operations the design has.
        count: usize,
    },
    /// A move or a box is not finite.
    #[error("operation {operation}: the {what} is not a finite number of millimetres")]
    NotFinite {
        /// The 1-based operation number.
        operation: usize,
        /// "move" or "box".
        what: &'static str,
    },
    /// The box of a resize is smaller than [`MIN_RESIZE_MM`] on a side, or the outline has
    /// no extent on an axis to scale.
    #[error(
        "operation {operation}: the outline would be {width} × {height} mm; each side must be \
         at least {MIN_RESIZE_MM} mm"
    )]
    TooSmall {
        /// The 1-based operation number.
        operation: usize,
        /// Extent along x, millimetres.
        width: f64,
        /// Extent along the plane's second coordinate, millimetres.
        height: f64,
    },
    /// The design after the edit cannot be replayed (the message names the operation).
    #[error(transparent)]
    Replay(#[from] DesignError),
}

/// Applies `edit` to `design` and replays the result (§3.1), returning the edited design.
///
/// # Errors
/// [`EditError`] naming the operation when the edit or the replay is refused; `design` is
/// left as it was.
pub fn apply_edit(design: &Design, edit: &Edit) -> Result<Design, EditError> {
    let mut next = design.clone();
    match edit {
        Edit::Add(op) => next.operations.push(op.clone()),
        Edit::Move { operation, by } => {
            let op = operation_mut(&mut next, *operation)?;
            if !by.iter().all(|v| v.is_finite()) {
                return Err(EditError::NotFinite {
                    operation: *operation,
                    what: "move",
                });
            }
            let [dx, dy, dz] = *by;
            let (d_at, d_w) = match op.plane {
                PlaneName::Vertical => (dy, dz),
                PlaneName::Horizontal => (dz, dy),
            };
            op.at += d_at;
            for p in &mut op.polygon {
                p[0] += dx;
                p[1] += d_w;
            }
        }
        Edit::Resize { operation, lo, hi } => {
            let op = operation_mut(&mut next, *operation)?;
            if !lo.iter().chain(hi).all(|v| v.is_finite()) {
                return Err(EditError::NotFinite {
                    operation: *operation,
                    what: "box",
                });
            }
            let (old_lo, old_hi) = outline_box(op);
            let (width, height) = (hi[0] - lo[0], hi[1] - lo[1]);
            let flat = (0..2).any(|k| old_hi[k] - old_lo[k] <= 0.0);
            if width < MIN_RESIZE_MM || height < MIN_RESIZE_MM || flat {
                return Err(EditError::TooSmall {
                    operation: *operation,
                    width,
                    height,
                });
            }
            for p in &mut op.polygon {
                for k in 0..2 {
                    let s = (p[k] - old_lo[k]) / (old_hi[k] - old_lo[k]);
                    // The box's own sides exactly, not the scaled sum's rounding.
                    p[k] = if s == 0.0 {
                        lo[k]
                    } else if s == 1.0 {
                        hi[k]
                    } else {
                        lo[k] + s * (hi[k] - lo[k])
                    };
                }
            }
        }
        Edit::Remove { operation } => {
            operation_mut(&mut next, *operation)?;
            next.operations.remove(operation - 1);
        }
    }
    next.build()?;
    Ok(next)
}

/// The bounding box of an operation's outline on its plane, millimetres: `(lo, hi)`.
pub fn outline_box(op: &Operation) -> ([f64; 2], [f64; 2]) {
    op.polygon.iter().fold(
        ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]),
        |(lo, hi), p| {
            (
                [lo[0].min(p[0]), lo[1].min(p[1])],
                [hi[0].max(p[0]), hi[1].max(p[1])],
            )
        },
    )
}

/// Operation `number` (1-based) rewritten in millimetres, for editing.
fn operation_mut(design: &mut Design, number: usize) -> Result<&mut Operation, EditError> {
    let count = design.operations.len();
    let grid = design.card.grid;
    let op = number
        .checked_sub(1)
        .and_then(|i| design.operations.get_mut(i))
        .ok_or(EditError::NoOperation {
            operation: number,
            count,
        })?;
    if op.units == Units::Grid {
        let scale = grid
            .filter(|g| g.is_finite() && *g > 0.0)
            .ok_or(DesignError::NoGrid(number))?;
        op.at *= scale;
        for p in &mut op.polygon {
            p[0] *= scale;
            p[1] *= scale;
        }
        op.units = Units::Mm;
    }
    Ok(op)
}

/// A vertical face piece that does not stand up, told at its place.
#[derive(Clone, Debug, PartialEq)]
pub struct Finding {
    /// The piece of the card's face.
    pub piece: PieceId,
    /// The operation that made the face (1-based); `None` for the back sheet.
    pub operation: Option<usize>,
    /// The face's plane.
    pub plane: Plane,
    /// What is wrong.
    pub problem: PopupProblem,
    /// The piece's outline on the pattern, millimetres: its outer ring, then its holes.
    pub outline: Vec<Vec<DVec2>>,
    /// The finding in a maker's words: which face, what is wrong, what would mend it.
    pub words: String,
}

/// The failing faces of `report` (the check of §3.6 on `card`), each with its operation, its
/// outline on the pattern and a sentence a maker can act on.
pub fn findings(card: &PolygonCard, report: &PopupReport) -> Vec<Finding> {
    report
        .problems
        .iter()
        .map(|p| {
            let face = &card.faces()[p.piece.face];
            let operation = p.piece.face.checked_sub(1).filter(|&n| n >= 1);
            let outline = face
                .polygon_mm()
                .into_iter()
                .nth(p.piece.shape)
                .unwrap_or_default();
            let name = match operation {
                Some(n) => format!(
                    "the vertical face of operation {n} (y = {} mm)",
                    round_mm(p.plane.t_mm())
                ),
                None => "the back sheet".into(),
            };
            let pieces = face.polygon.len();
            let part = if pieces > 1 {
                format!(", part {} of {pieces},", p.piece.shape + 1)
            } else {
                String::new()
            };
            let mend = match p.problem {
                PopupProblem::Floating => {
                    "no fold joins it to the back or the base sheet; let it meet a face that \
                     stands, along a fold"
                }
                PopupProblem::HeldFromBackOnly => {
                    "it hangs from above but nothing joins it to the base sheet, so opening the \
                     card does not push it up; let it reach the base, or put a horizontal face \
                     under it that does"
                }
                PopupProblem::HeldFromBaseOnly => {
                    "it stands on the base but nothing joins it to the back sheet, so opening \
                     the card does not pull it up; put a horizontal face on top of it that \
                     reaches the back sheet or a face joined to it"
                }
            };
            Finding {
                piece: p.piece,
                operation,
                plane: p.plane,
                problem: p.problem,
                outline,
                words: format!("{name}{part} {}: {mend}", p.problem.describe()),
            }
        })
        .collect()
}

/// Millimetres shown to 0.01 mm, without trailing zeros.
fn round_mm(v: f64) -> f64 {
    (v * 100.0).round() / 100.0
}

/// Writes `design` as the `.popup.toml` text `foldcam popup poly` reads; [`parse_design`]
/// of the text gives `design` back.
///
/// [`parse_design`]: super::design::parse_design
pub fn write_design(design: &Design) -> String {
    let c = &design.card;
    let mut out = String::from(
        "# A polygon pop-up card (Mitani & Suzuki 2004), saved by the foldcam studio.\n[card]\n",
    );
    // `{:?}` writes the shortest text that reads back to the same f64, with a decimal point.
    let _ = writeln!(out, "width = {:?}", c.width);
    let _ = writeln!(out, "depth = {:?}", c.depth);
    let _ = writeln!(out, "height = {:?}", c.height);
    if let Some(g) = c.grid {
        let _ = writeln!(out, "grid = {g:?}");
    }
    for op in &design.operations {
        out.push_str("\n[[operation]]\n");
        let plane = match op.plane {
            PlaneName::Vertical => "vertical",
            PlaneName::Horizontal => "horizontal",
        };
        let _ = writeln!(out, "plane = \"{plane}\"");
        let _ = writeln!(out, "at = {:?}", op.at);
        let points: Vec<String> = op
            .polygon
            .iter()
            .map(|p| format!("[{:?}, {:?}]", p[0], p[1]))
            .collect();
        let _ = writeln!(out, "polygon = [{}]", points.join(", "));
        if op.add == Add::Opening {
            out.push_str("add = \"opening\"\n");
        }
        if op.units == Units::Grid {
            out.push_str("units = \"grid\"\n");
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::super::check::check_popup;
    use super::super::crease::crease_pattern;
    use super::super::design::{CardSize, parse_design};
    use super::*;
    use crate::pattern::Assignment;

    fn rect(x0: f64, w0: f64, x1: f64, w1: f64) -> Vec<[f64; 2]> {
        vec![[x0, w0], [x1, w0], [x1, w1], [x0, w1]]
    }

    fn op(plane: PlaneName, at: f64, polygon: Vec<[f64; 2]>) -> Operation {
        Operation {
            plane,
            at,
            polygon,
            add: Add::Face,
            units: Units::Mm,
        }
    }

    fn blank() -> Design {
        Design {
            card: CardSize {
                width: 120.0,
                depth: 60.0,
                height: 80.0,
                grid: Some(5.0),
            },
            operations: Vec::new(),
        }
    }

    /// A box 40 mm wide standing 30 mm in front of the back sheet, 20 mm high: a wall at
    /// y = 30 from z = 0 to 20 and a roof at z = 20 from y = 0 to 30.
    fn boxed() -> Design {
        let mut d = apply_edit(
            &blank(),
            &Edit::Add(op(PlaneName::Vertical, 30.0, rect(40.0, 0.0, 80.0, 20.0))),
        )
        .unwrap();
        d = apply_edit(
            &d,
            &Edit::Add(op(PlaneName::Horizontal, 20.0, rect(40.0, 0.0, 80.0, 30.0))),
        )
        .unwrap();
        d
    }

    /// The folds of a design's pattern: (v of the line, assignment, x extent), sorted.
    fn folds(d: &Design) -> Vec<(i64, bool, i64, i64)> {
        let card = d.build().unwrap();
        let cp = crease_pattern(&card).unwrap();
        let um = |v: f64| (v * 1000.0).round() as i64;
        let mut out: Vec<_> = cp
            .edges
            .iter()
            .filter(|e| matches!(e.assignment, Assignment::Mountain | Assignment::Valley))
            .map(|e| {
                let (a, b) = (cp.position(e.vertices[0]), cp.position(e.vertices[1]));
                (
                    um(a.y),
                    e.assignment == Assignment::Mountain,
                    um(a.x.min(b.x)),
                    um(a.x.max(b.x)),
                )
            })
            .collect();
        out.sort();
        out.dedup();
        out
    }

    #[test]
    fn a_box_pops_up_and_folds_where_eq_1_puts_its_edges() {
        let d = boxed();
        assert!(check_popup(&d.build().unwrap()).passed());
        // Eq. 1, v = z − y, by hand: roof meets back sheet at (y 0, z 20) → v = 20; roof meets
        // wall at (30, 20) → v = −10; wall meets base at (30, 0) → v = −30; the central fold
        // under the box is covered. Folds only where the box is, x from 40 to 80 mm.
        let lines: Vec<i64> = folds(&d).iter().map(|f| f.0).collect();
        assert_eq!(lines, vec![-30_000, -10_000, 0, 0, 20_000]);
        let box_folds: Vec<_> = folds(&d).into_iter().filter(|f| f.0 != 0).collect();
        assert!(box_folds.iter().all(|f| (f.2, f.3) == (40_000, 80_000)));
    }

    #[test]
    fn moving_along_the_fold_shifts_every_fold_by_the_move() {
        let d = boxed();
        let moved = apply_edit(
            &apply_edit(
                &d,
                &Edit::Move {
                    operation: 1,
                    by: [15.0, 0.0, 0.0],
                },
            )
            .unwrap(),
            &Edit::Move {
                operation: 2,
                by: [15.0, 0.0, 0.0],
            },
        )
        .unwrap();
        let shift = |f: &(i64, bool, i64, i64)| {
            if f.0 == 0 {
                None
            } else {
                Some((f.0, f.1, f.2 + 15_000, f.3 + 15_000))
            }
        };
        let expect: Vec<_> = folds(&d).iter().filter_map(shift).collect();
        let got: Vec<_> = folds(&moved).into_iter().filter(|f| f.0 != 0).collect();
        assert_eq!(got, expect);
    }

    #[test]
    fn moving_the_wall_alone_off_its_roof_is_found_at_the_wall() {
        let d = boxed();
        let moved = apply_edit(
            &d,
            &Edit::Move {
                operation: 1,
                by: [0.0, 10.0, 0.0],
            },
        )
        .unwrap();
        assert_eq!(moved.operations[0].at, 40.0);
        let card = moved.build().unwrap();
        let found = findings(&card, &check_popup(&card));
        // The wall (y = 40) now stands on the base with nothing reaching it from the back
        // sheet: the roof ends 10 mm behind it.
        assert!(!found.is_empty());
        let wall: Vec<_> = found.iter().filter(|f| f.operation == Some(1)).collect();
        assert_eq!(wall.len(), 1, "{found:?}");
        assert_eq!(wall[0].problem, PopupProblem::HeldFromBaseOnly);
        assert!(wall[0].words.contains("operation 1 (y = 40 mm)"));
        assert!(wall[0].words.contains("back sheet"));
        // Its outline on the pattern: x 40..80, v = z − y from −40 to −20 (eq. 1).
        let xs: Vec<f64> = wall[0].outline[0].iter().map(|p| p.x).collect();
        let vs: Vec<f64> = wall[0].outline[0].iter().map(|p| p.y).collect();
        let span = |v: &[f64]| {
            (
                v.iter().copied().fold(f64::INFINITY, f64::min),
                v.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            )
        };
        assert_eq!(span(&xs), (40.0, 80.0));
        assert_eq!(span(&vs), (-40.0, -20.0));
    }

    #[test]
    fn resizing_fits_the_outline_into_the_box() {
        let d = boxed();
        let sized = apply_edit(
            &d,
            &Edit::Resize {
                operation: 2,
                lo: [30.0, 0.0],
                hi: [90.0, 30.0],
            },
        )
        .unwrap();
        assert_eq!(sized.operations[1].polygon, rect(30.0, 0.0, 90.0, 30.0));
        // A slanted outline keeps its shape: its middle point stays in the middle.
        let gable = op(
            PlaneName::Vertical,
            30.0,
            vec![
                [40.0, 0.0],
                [80.0, 0.0],
                [80.0, 20.0],
                [60.0, 30.0],
                [40.0, 20.0],
            ],
        );
        let g = apply_edit(&blank(), &Edit::Add(gable)).unwrap();
        let g = apply_edit(
            &g,
            &Edit::Resize {
                operation: 1,
                lo: [20.0, 0.0],
                hi: [100.0, 60.0],
            },
        )
        .unwrap();
        assert_eq!(g.operations[0].polygon[3], [60.0, 60.0]);
        assert_eq!(g.operations[0].polygon[2], [100.0, 40.0]);
        // Lowering the wall under its roof: the wall no longer reaches the roof.
        let low = apply_edit(
            &d,
            &Edit::Resize {
                operation: 1,
                lo: [40.0, 0.0],
                hi: [80.0, 10.0],
            },
        )
        .unwrap();
        let card = low.build().unwrap();
        let found = findings(&card, &check_popup(&card));
        assert!(found.iter().any(|f| f.operation == Some(1)), "{found:?}");
        let err = apply_edit(
            &d,
            &Edit::Resize {
                operation: 1,
                lo: [40.0, 0.0],
                hi: [40.05, 10.0],
            },
        )
        .unwrap_err();
        assert!(matches!(err, EditError::TooSmall { operation: 1, .. }));
    }

    #[test]
    fn refusals_name_the_operation() {
        let d = boxed();
        let err = apply_edit(
            &d,
            &Edit::Move {
                operation: 1,
                by: [0.0, 40.0, 0.0],
            },
        )
        .unwrap_err();
        // The wall at y = 70 is beyond the 60 mm base.
        let text = err.to_string();
        assert!(text.starts_with("operation 1: "), "{text}");
        assert!(text.contains("70"), "{text}");
        let err = apply_edit(&d, &Edit::Remove { operation: 3 }).unwrap_err();
        assert_eq!(
            err,
            EditError::NoOperation {
                operation: 3,
                count: 2
            }
        );
        let err = apply_edit(
            &d,
            &Edit::Move {
                operation: 2,
                by: [f64::NAN, 0.0, 0.0],
            },
        )
        .unwrap_err();
        assert!(matches!(err, EditError::NotFinite { operation: 2, .. }));
    }

    #[test]
    fn removing_the_roof_leaves_the_wall_held_from_the_base_only() {
        let d = apply_edit(&boxed(), &Edit::Remove { operation: 2 }).unwrap();
        assert_eq!(d.operations.len(), 1);
        let card = d.build().unwrap();
        let found = findings(&card, &check_popup(&card));
        assert_eq!(found.len(), 1);
        assert_eq!(found[0].problem, PopupProblem::HeldFromBaseOnly);
    }

    #[test]
    fn an_edited_grid_operation_is_rewritten_in_millimetres() {
        let text = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/examples/popup/house-door.popup.toml"
        ))
        .unwrap();
        let d = parse_design(&text).unwrap();
        let moved = apply_edit(
            &d,
            &Edit::Move {
                operation: 1,
                by: [0.0, 5.0, 0.0],
            },
        )
        .unwrap();
        // at = 6 grid units of 5 mm, moved 5 mm: 35 mm; the outline 7..17 × 0..6 units.
        assert_eq!(moved.operations[0].units, Units::Mm);
        assert_eq!(moved.operations[0].at, 35.0);
        assert_eq!(moved.operations[0].polygon, rect(35.0, 0.0, 85.0, 30.0));
        // The untouched operations keep their units.
        assert_eq!(moved.operations[1].units, Units::Grid);
    }

    #[test]
    fn a_written_design_reads_back_the_same() {
        let text = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/examples/popup/house-door.popup.toml"
        ))
        .unwrap();
        let mut d = parse_design(&text).unwrap();
        d = apply_edit(
            &d,
            &Edit::Resize {
                operation: 4,
                lo: [38.1, 15.0],
                hi: [47.3, 24.7],
            },
        )
        .unwrap();
        let back = parse_design(&write_design(&d)).unwrap();
        assert_eq!(back, d);
        let card = back.build().unwrap();
        assert_eq!(card, d.build().unwrap());
    }
}
