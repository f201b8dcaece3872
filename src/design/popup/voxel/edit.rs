//! Editing a voxel card as the editor of Mitani, Suzuki & Uno (2003), §2.7 does, from two
//! orthogonal views: the front view (x across, z up: one row `(x, z)` per square, its depth
//! shown) and the side view of one x-slice (y across, z up: one cell per square).
//!
//! Every edit keeps the staircase constraint (eq. 4): adding cell `(x, y, z)` fills every
//! cell below and behind it in its slice, deleting it empties every cell above and in front
//! (§2.7). An edit that cannot be made is refused with the place named and the card left as
//! it was.

use serde::Deserialize;
use thiserror::Error;

use super::{VoxelCard, VoxelError};

/// One edit of a voxel card. Indices are cells: `x` along the fold, `y` out from the back
/// sheet, `z` up from the base.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize)]
#[serde(tag = "op", rename_all = "snake_case", deny_unknown_fields)]
pub enum VoxelEdit {
    /// Side view: adds cell (x, y, z) and every cell below and behind it (§2.7).
    Add {
        /// Column along the fold.
        x: usize,
        /// Depth index.
        y: usize,
        /// Height index.
        z: usize,
    },
    /// Side view: deletes cell (x, y, z) and every cell above and in front of it (§2.7).
    Delete {
        /// Column along the fold.
        x: usize,
        /// Depth index.
        y: usize,
        /// Height index.
        z: usize,
    },
    /// Front view: the row (x, z) stands out one cell further (adds the cell in front of
    /// its front face, as [`VoxelEdit::Add`]).
    PushOut {
        /// Column along the fold.
        x: usize,
        /// Height index.
        z: usize,
    },
    /// Front view: the row (x, z) stands out one cell less (deletes its front cell, as
    /// [`VoxelEdit::Delete`]).
    PushIn {
        /// Column along the fold.
        x: usize,
        /// Height index.
        z: usize,
    },
    /// Front view: the front face of row (x, z) becomes a window, or not (eq. 5).
    Window {
        /// Column along the fold.
        x: usize,
        /// Height index.
        z: usize,
        /// Window on or off.
        on: bool,
    },
    /// Front view: leaves out, or restores, the top face of row (x, z) (§3.3).
    OmitTop {
        /// Column along the fold.
        x: usize,
        /// Height index.
        z: usize,
        /// Left out or kept.
        on: bool,
    },
    /// A new size in cells; rows beyond it are dropped, depths beyond the new base depth cut
    /// back (the staircase still holds).
    Resize {
        /// Cells along the fold.
        nx: usize,
        /// Cells of base depth.
        ny: usize,
        /// Cells of back-sheet height.
        nz: usize,
    },
    /// A new cell size, millimetres.
    CellSize {
        /// Edge of one cell, mm.
        mm: f64,
    },
    /// A new margin of flat paper around the cells, millimetres.
    Margin {
        /// Margin, mm.
        mm: f64,
    },
}

/// Why an edit was refused; the card is unchanged.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum VoxelEditError {
    /// A cell or row outside the card.
    #[error("{what} is outside the {nx} × {ny} × {nz} card (x 0..{nx}, y 0..{ny}, z 0..{nz})")]
    Outside {
        /// The place asked for, in words.
        what: String,
        /// Cells along the fold.
        nx: usize,
        /// Cells of depth.
        ny: usize,
        /// Cells of height.
        nz: usize,
    },
    /// Pushing out a row already as deep as the base.
    #[error("row (x {x}, z {z}) already stands out the base's full depth of {ny} cells")]
    FullDepth {
        /// Column.
        x: usize,
        /// Height index.
        z: usize,
        /// The base depth.
        ny: usize,
    },
    /// Pushing in an empty row.
    #[error("row (x {x}, z {z}) is empty: nothing to push in")]
    Empty {
        /// Column.
        x: usize,
        /// Height index.
        z: usize,
    },
    /// The model refused (size, cell size or margin out of range).
    #[error(transparent)]
    Card(#[from] VoxelError),
}

/// What an edit changed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct EditChange {
    /// Voxels filled by the edit (the paper's rule fills below and behind).
    pub added: usize,
    /// Voxels emptied by the edit.
    pub removed: usize,
}

/// Applies `edit` to `card`; on error the card is as it was.
///
/// # Errors
/// [`VoxelEditError`] naming the place and the limit.
pub fn apply_edit(card: &mut VoxelCard, edit: &VoxelEdit) -> Result<EditChange, VoxelEditError> {
    let outside = |card: &VoxelCard, what: String| VoxelEditError::Outside {
        what,
        nx: card.nx(),
        ny: card.ny(),
        nz: card.nz(),
    };
    let row_in = |card: &VoxelCard, x: usize, z: usize| {
        if x < card.nx() && z < card.nz() {
            Ok(())
        } else {
            Err(outside(card, format!("row (x {x}, z {z})")))
        }
    };
    match *edit {
        VoxelEdit::Add { x, y, z } | VoxelEdit::Delete { x, y, z } => {
            if x >= card.nx() || y >= card.ny() || z >= card.nz() {
                return Err(outside(card, format!("cell ({x}, {y}, {z})")));
            }
            let before = slice_volume(card, x);
            if matches!(edit, VoxelEdit::Add { .. }) {
                card.add(x, y, z)?;
            } else {
                card.delete(x, y, z)?;
            }
            Ok(change(before, slice_volume(card, x)))
        }
        VoxelEdit::PushOut { x, z } => {
            row_in(card, x, z)?;
            let d = card.depth(x, z);
            if d >= card.ny() {
                return Err(VoxelEditError::FullDepth {
                    x,
                    z,
                    ny: card.ny(),
                });
            }
            apply_edit(card, &VoxelEdit::Add { x, y: d, z })
        }
        VoxelEdit::PushIn { x, z } => {
            row_in(card, x, z)?;
            match card.depth(x, z) {
                0 => Err(VoxelEditError::Empty { x, z }),
                d => apply_edit(card, &VoxelEdit::Delete { x, y: d - 1, z }),
            }
        }
        VoxelEdit::Window { x, z, on } => {
            row_in(card, x, z)?;
            card.set_hole(x, z, on)?;
            Ok(EditChange::default())
        }
        VoxelEdit::OmitTop { x, z, on } => {
            row_in(card, x, z)?;
            card.set_top_omitted(x, z, on)?;
            Ok(EditChange::default())
        }
        VoxelEdit::Resize { nx, ny, nz } => {
            let before = volume(card);
            let resized = resized(card, nx, ny, nz)?;
            *card = resized;
            Ok(change(before, volume(card)))
        }
        VoxelEdit::CellSize { mm } => {
            let mut next = VoxelCard::new(card.nx(), card.ny(), card.nz(), mm)?;
            next.set_margin_mm(card.margin_mm())?;
            copy_rows(card, &mut next);
            *card = next;
            Ok(EditChange::default())
        }
        VoxelEdit::Margin { mm } => {
            card.set_margin_mm(mm)?;
            Ok(EditChange::default())
        }
    }
}

/// `card` with another size: the rows that still fit, depths cut back to `ny`.
fn resized(card: &VoxelCard, nx: usize, ny: usize, nz: usize) -> Result<VoxelCard, VoxelError> {
    let mut next = VoxelCard::new(nx, ny, nz, card.cell_mm())?;
    next.set_margin_mm(card.margin_mm())?;
    copy_rows(card, &mut next);
    Ok(next)
}

/// Copies depths and flags of every row `to` has from `from` (depths cut back to `to`'s
/// base depth; a cut-back staircase is still one).
fn copy_rows(from: &VoxelCard, to: &mut VoxelCard) {
    for x in 0..to.nx().min(from.nx()) {
        // Bottom-up: each row is checked against the one below it, already set.
        for z in 0..to.nz().min(from.nz()) {
            let d = from.depth(x, z).min(to.ny());
            // In range and staircase by construction: these cannot fail.
            let _ = to.set_depth(x, z, d);
            let _ = to.set_hole(x, z, from.is_hole(x, z));
            let _ = to.set_top_omitted(x, z, from.is_top_omitted(x, z));
        }
    }
}

fn slice_volume(card: &VoxelCard, x: usize) -> usize {
    (0..card.nz()).map(|z| card.depth(x, z)).sum()
}

fn volume(card: &VoxelCard) -> usize {
    (0..card.nx()).map(|x| slice_volume(card, x)).sum()
}

fn change(before: usize, after: usize) -> EditChange {
    EditChange {
        added: after.saturating_sub(before),
        removed: before.saturating_sub(after),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn card() -> VoxelCard {
        VoxelCard::new(5, 4, 6, 5.0).unwrap()
    }

    /// Counts filled cells one by one through `cell` (not through the depths).
    fn filled(card: &VoxelCard) -> usize {
        let mut n = 0;
        for x in 0..card.nx() {
            for y in 0..card.ny() {
                for z in 0..card.nz() {
                    n += usize::from(card.cell(x, y, z));
                }
            }
        }
        n
    }

    #[test]
    fn adding_a_cell_fills_the_box_below_and_behind_it() {
        let mut c = card();
        let got = apply_edit(&mut c, &VoxelEdit::Add { x: 2, y: 2, z: 3 }).unwrap();
        // §2.7: (y + 1)(z + 1) cells of the slice, nothing elsewhere.
        assert_eq!(
            got,
            EditChange {
                added: 12,
                removed: 0
            }
        );
        assert_eq!(filled(&c), 12);
        assert!(c.cell(2, 0, 0) && c.cell(2, 2, 3) && !c.cell(2, 3, 3) && !c.cell(2, 0, 4));
        assert!(!c.cell(1, 0, 0) && !c.cell(3, 0, 0));
        assert!(c.is_staircase());
    }

    #[test]
    fn deleting_a_cell_empties_the_box_above_and_in_front_of_it() {
        let mut c = card();
        apply_edit(&mut c, &VoxelEdit::Add { x: 1, y: 3, z: 5 }).unwrap();
        assert_eq!(filled(&c), 24);
        let got = apply_edit(&mut c, &VoxelEdit::Delete { x: 1, y: 1, z: 2 }).unwrap();
        // Rows z = 2..=5 keep y = 0 only: 4 × 3 cells go.
        assert_eq!(
            got,
            EditChange {
                added: 0,
                removed: 12
            }
        );
        assert_eq!(filled(&c), 12);
        assert!(c.cell(1, 0, 5) && !c.cell(1, 1, 2) && c.cell(1, 3, 1));
    }

    #[test]
    fn the_front_view_pushes_rows_out_and_in_one_cell_at_a_time() {
        let mut c = card();
        for _ in 0..3 {
            apply_edit(&mut c, &VoxelEdit::PushOut { x: 0, z: 2 }).unwrap();
        }
        assert_eq!((c.depth(0, 2), c.depth(0, 0), c.depth(0, 3)), (3, 3, 0));
        apply_edit(&mut c, &VoxelEdit::PushIn { x: 0, z: 0 }).unwrap();
        // The row above cannot stand out further than the row below it (eq. 4).
        assert_eq!((c.depth(0, 0), c.depth(0, 2)), (2, 2));
        apply_edit(&mut c, &VoxelEdit::PushOut { x: 0, z: 0 }).unwrap();
        apply_edit(&mut c, &VoxelEdit::PushOut { x: 0, z: 0 }).unwrap();
        let full = apply_edit(&mut c, &VoxelEdit::PushOut { x: 0, z: 0 }).unwrap_err();
        assert_eq!(full, VoxelEditError::FullDepth { x: 0, z: 0, ny: 4 });
        let empty = apply_edit(&mut c, &VoxelEdit::PushIn { x: 4, z: 0 }).unwrap_err();
        assert!(empty.to_string().contains("(x 4, z 0)"), "{empty}");
    }

    #[test]
    fn refused_edits_name_the_place_and_leave_the_card() {
        let mut c = card();
        apply_edit(&mut c, &VoxelEdit::Add { x: 1, y: 1, z: 1 }).unwrap();
        let before = c.clone();
        for edit in [
            VoxelEdit::Add { x: 5, y: 0, z: 0 },
            VoxelEdit::Delete { x: 0, y: 4, z: 0 },
            VoxelEdit::Window {
                x: 0,
                z: 6,
                on: true,
            },
            VoxelEdit::Resize {
                nx: 0,
                ny: 4,
                nz: 4,
            },
            VoxelEdit::CellSize { mm: -1.0 },
            VoxelEdit::Margin { mm: f64::NAN },
        ] {
            assert!(apply_edit(&mut c, &edit).is_err(), "{edit:?}");
            assert_eq!(c, before, "{edit:?}");
        }
        let e = apply_edit(&mut c, &VoxelEdit::Add { x: 5, y: 0, z: 0 }).unwrap_err();
        assert_eq!(
            e.to_string(),
            "cell (5, 0, 0) is outside the 5 × 4 × 6 card (x 0..5, y 0..4, z 0..6)"
        );
    }

    #[test]
    fn resizing_keeps_what_fits_and_stays_a_staircase() {
        let mut c = card();
        apply_edit(&mut c, &VoxelEdit::Add { x: 4, y: 3, z: 5 }).unwrap();
        apply_edit(
            &mut c,
            &VoxelEdit::Window {
                x: 4,
                z: 1,
                on: true,
            },
        )
        .unwrap();
        let got = apply_edit(
            &mut c,
            &VoxelEdit::Resize {
                nx: 6,
                ny: 2,
                nz: 3,
            },
        )
        .unwrap();
        // 4 × 6 cells become 2 × 3.
        assert_eq!(
            got,
            EditChange {
                added: 0,
                removed: 18
            }
        );
        assert_eq!((c.nx(), c.ny(), c.nz()), (6, 2, 3));
        assert_eq!(c.depth(4, 0), 2);
        assert!(c.is_hole(4, 1) && c.is_staircase());
        apply_edit(&mut c, &VoxelEdit::CellSize { mm: 2.5 }).unwrap();
        assert_eq!((c.cell_mm(), c.depth(4, 2)), (2.5, 2));
    }

    #[test]
    fn edits_read_from_json_as_the_studio_sends_them() {
        let e: VoxelEdit = serde_json::from_str(r#"{"op": "push_out", "x": 1, "z": 2}"#).unwrap();
        assert_eq!(e, VoxelEdit::PushOut { x: 1, z: 2 });
        let bad = serde_json::from_str::<VoxelEdit>(r#"{"op": "add", "x": 1, "z": 2}"#);
        assert!(bad.unwrap_err().to_string().contains("missing field `y`"));
    }
}
