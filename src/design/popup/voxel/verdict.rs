//! Whether a voxel card can be made, with every fault at its place: the unit cells of the
//! pattern at fault and the voxel faces they become, so an editor can mark them.
//!
//! Three faults, as `foldcam popup voxel` finds them:
//! - **no pop-up**: a vertical face (a front face, or a piece of the back sheet's plane cut
//!   free of the back sheet) not reached by both floods of Mitani, Suzuki & Uno (2003), §2.6
//!   ([`super::check_popup`]); the card is refused.
//! - **loose pieces**: pattern cells cut free on every side (windows and left-out tops can do
//!   it). Cells are joined across every line but a cut (Table 1); the part of largest area is
//!   the card, every other part falls out. The card is refused.
//! - **beyond the closed card**: folded shut (eq. 6 at θ = 180°), a face reaching beyond the
//!   closed card's outline ([`crate::design::popup::integrity::closed_overhang`]); the command
//!   warns (and `--fit` adds paper).

use glam::DVec2;

use super::check::{FrontCellProblem, check_popup};
use super::surface::{Line, Plane, Surface};
use super::{VoxelCard, crease_pattern, fold_card, open_transform};
use crate::design::popup::fit::CLOSED_SLACK_MM;
use crate::design::popup::integrity::closed_overhang;
use crate::pattern::PlanarizeError;

/// The voxel face (or sheet) a unit cell of the pattern lands on when the card stands at 90°.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum VoxelFace {
    /// The front face of voxel (x, y, z) (the plane y + 1).
    Front {
        /// Column.
        x: usize,
        /// Depth index of the voxel.
        y: usize,
        /// Height index.
        z: usize,
    },
    /// The top face of voxel (x, y, z) (the plane z + 1).
    Top {
        /// Column.
        x: usize,
        /// Depth index.
        y: usize,
        /// Height index of the voxel.
        z: usize,
    },
    /// The back sheet, in row z of column x.
    BackSheet {
        /// Column.
        x: usize,
        /// Height index.
        z: usize,
    },
    /// The base sheet, in cell y of column x.
    Base {
        /// Column.
        x: usize,
        /// Depth index.
        y: usize,
    },
}

impl std::fmt::Display for VoxelFace {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            VoxelFace::Front { x, y, z } => write!(f, "the front face of voxel ({x}, {y}, {z})"),
            VoxelFace::Top { x, y, z } => write!(f, "the top face of voxel ({x}, {y}, {z})"),
            VoxelFace::BackSheet { x, z } => write!(f, "the back sheet at x {x}, z {z}"),
            VoxelFace::Base { x, y } => write!(f, "the base at x {x}, y {y}"),
        }
    }
}

/// One unit cell of the pattern: column `x`, row `row` (row 0 is the base's front edge, row
/// `ny` the first above the central fold), and the face it becomes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct PatternCell {
    /// Column.
    pub x: usize,
    /// Pattern row.
    pub row: usize,
    /// Where it stands at 90°.
    pub face: VoxelFace,
}

/// A part of the pattern cut free on every side.
#[derive(Clone, Debug, PartialEq)]
pub struct LooseCells {
    /// Its cells, by column then row.
    pub cells: Vec<PatternCell>,
    /// Its area, mm².
    pub area_mm2: f64,
}

/// A pattern cell that, the card folded shut, lies beyond the closed card's outline.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BeyondCell {
    /// The cell.
    pub cell: PatternCell,
    /// How far its farthest corner reaches beyond the outline, mm.
    pub beyond_mm: f64,
}

/// Every fault of a card, each at its place.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct CardVerdict {
    /// Vertical faces that do not pop up (§2.6; see [`super::check_popup`]).
    pub popup: Vec<FrontCellProblem>,
    /// Parts that fall out when the card is cut, the largest first.
    pub loose: Vec<LooseCells>,
    /// Cells beyond the closed card, the farthest first.
    pub beyond: Vec<BeyondCell>,
}

impl CardVerdict {
    /// True when the card pops up and holds together (a card beyond its outline is still
    /// made, with a warning).
    pub fn makes_a_card(&self) -> bool {
        self.popup.is_empty() && self.loose.is_empty()
    }
}

/// The face pattern cell (x, row) of `surface` lands on (see the surface's module docs:
/// a vertical plane y0 maps the band `v ∈ [row − ny, row − ny + 1]` to `z = v + y0`, a
/// horizontal plane z0 to `y = z0 − v`).
pub fn face_of(surface: &Surface, x: usize, row: usize) -> VoxelFace {
    let v = row as i64 - surface.ny as i64;
    match surface.plane(x as i64, row as i64) {
        Plane::Vertical(0) => VoxelFace::BackSheet { x, z: v as usize },
        Plane::Vertical(y0) => VoxelFace::Front {
            x,
            y: y0 as usize - 1,
            z: (v + y0 as i64) as usize,
        },
        Plane::Horizontal(0) => VoxelFace::Base {
            x,
            y: (-v - 1) as usize,
        },
        Plane::Horizontal(z0) => VoxelFace::Top {
            x,
            y: (z0 as i64 - v - 1) as usize,
            z: z0 as usize - 1,
        },
    }
}

/// Checks `card` for all three faults (see the module docs).
///
/// # Errors
/// When the crease pattern cannot be made (needed for the closed card).
pub fn card_verdict(card: &VoxelCard) -> Result<CardVerdict, PlanarizeError> {
    let surface = Surface::new(card);
    Ok(CardVerdict {
        popup: check_popup(card).problems,
        loose: loose_cells(card, &surface),
        beyond: beyond_cells(card, &surface)?,
    })
}

/// Parts of the pattern joined across no line but cuts, all but the largest.
fn loose_cells(card: &VoxelCard, surface: &Surface) -> Vec<LooseCells> {
    let (nx, rows) = (surface.nx, surface.rows);
    let margin = card.margin_mm() > 0.0;
    // Node nx·rows is the margin (one flat piece around the cells) when there is one.
    let mut parent: Vec<usize> = (0..nx * rows + usize::from(margin)).collect();
    let id = |x: i64, r: i64| -> Option<usize> {
        if (0..nx as i64).contains(&x) && (0..rows as i64).contains(&r) {
            Some(x as usize * rows + r as usize)
        } else if margin {
            Some(nx * rows)
        } else {
            None
        }
    };
    for x in 0..=nx as i64 {
        for r in 0..=rows as i64 {
            if r < rows as i64 && surface.line_left(x, r) != Line::Cut {
                join(&mut parent, id(x - 1, r), id(x, r));
            }
            if x < nx as i64 && surface.line_below(x, r) != Line::Cut {
                join(&mut parent, id(x, r - 1), id(x, r));
            }
        }
    }
    let cell_area = card.cell_mm() * card.cell_mm();
    let (w, h) = card.sheet_mm();
    let mut parts: std::collections::BTreeMap<usize, LooseCells> = Default::default();
    for x in 0..nx {
        for row in 0..rows {
            let root = find(&mut parent, x * rows + row);
            let part = parts.entry(root).or_insert(LooseCells {
                cells: Vec::new(),
                area_mm2: 0.0,
            });
            part.area_mm2 += cell_area;
            part.cells.push(PatternCell {
                x,
                row,
                face: face_of(surface, x, row),
            });
        }
    }
    if margin {
        let root = find(&mut parent, nx * rows);
        let part = parts.entry(root).or_insert(LooseCells {
            cells: Vec::new(),
            area_mm2: 0.0,
        });
        part.area_mm2 += w * h - (nx * rows) as f64 * cell_area;
    }
    let mut all: Vec<LooseCells> = parts.into_values().collect();
    all.sort_by(|a, b| b.area_mm2.total_cmp(&a.area_mm2));
    all.into_iter().skip(1).collect()
}

fn find(parent: &mut [usize], mut i: usize) -> usize {
    while parent[i] != i {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    i
}

fn join(parent: &mut [usize], a: Option<usize>, b: Option<usize>) {
    if let (Some(a), Some(b)) = (a, b) {
        let (ra, rb) = (find(parent, a), find(parent, b));
        if ra != rb {
            parent[ra.max(rb)] = ra.min(rb);
        }
    }
}

/// Cells whose corners, the card folded shut, lie beyond the closed outline of
/// [`closed_overhang`] by more than [`CLOSED_SLACK_MM`].
fn beyond_cells(card: &VoxelCard, surface: &Surface) -> Result<Vec<BeyondCell>, PlanarizeError> {
    let cp = crease_pattern(card)?;
    let closed = fold_card(card, &cp, 0.0).state;
    let Some(overhang) = closed_overhang(&closed) else {
        return Ok(Vec::new());
    };
    if overhang.beyond_mm <= CLOSED_SLACK_MM {
        return Ok(Vec::new());
    }
    let (lo, hi) = overhang.outline;
    let s = card.cell_mm();
    let mut out = Vec::new();
    for x in 0..surface.nx {
        for row in 0..surface.rows {
            let plane = surface.plane(x as i64, row as i64);
            let v0 = row as f64 - surface.ny as f64;
            let mut worst: f64 = 0.0;
            for (du, dv) in [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)] {
                let p = open_transform(plane.to_card(x as f64 + du, v0 + dv).into(), 0.0) * s;
                let p = DVec2::new(p.x, p.y);
                worst = worst.max((lo - p).max(p - hi).max(DVec2::ZERO).length());
            }
            if worst > CLOSED_SLACK_MM {
                out.push(BeyondCell {
                    cell: PatternCell {
                        x,
                        row,
                        face: face_of(surface, x, row),
                    },
                    beyond_mm: worst,
                });
            }
        }
    }
    out.sort_by(|a, b| b.beyond_mm.total_cmp(&a.beyond_mm));
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::design::popup::integrity::loose_pieces;
    use crate::test_rng::TestRng;

    /// A card built from front-view depths, top row first (as the text format).
    fn card(rows: &[&[usize]], ny: usize, margin: f64) -> VoxelCard {
        let nz = rows.len() + 2;
        let mut c = VoxelCard::new(rows[0].len(), ny, nz, 4.0).unwrap();
        c.set_margin_mm(margin).unwrap();
        for (i, row) in rows.iter().enumerate().rev() {
            for (x, &d) in row.iter().enumerate() {
                c.set_depth(x, rows.len() - 1 - i, d).unwrap();
            }
        }
        c
    }

    #[test]
    fn a_good_card_has_no_fault() {
        let c = card(&[&[0, 2, 2, 0], &[0, 2, 2, 0]], 4, 5.0);
        let v = card_verdict(&c).unwrap();
        assert!(v.makes_a_card() && v.beyond.is_empty(), "{v:?}");
    }

    #[test]
    fn pattern_cells_name_the_faces_they_stand_on() {
        // One voxel (1, 0, 0) in a 3 × 2 × 2 card: column 1 reads, bottom-up, base cell y 1,
        // the voxel's front face, its top face, back sheet row 1.
        let mut c = VoxelCard::new(3, 2, 2, 5.0).unwrap();
        c.add(1, 0, 0).unwrap();
        let s = Surface::new(&c);
        let faces: Vec<VoxelFace> = (0..4).map(|r| face_of(&s, 1, r)).collect();
        assert_eq!(
            faces,
            [
                VoxelFace::Base { x: 1, y: 1 },
                VoxelFace::Front { x: 1, y: 0, z: 0 },
                VoxelFace::Top { x: 1, y: 0, z: 0 },
                VoxelFace::BackSheet { x: 1, z: 1 },
            ]
        );
        assert_eq!(face_of(&s, 0, 1), VoxelFace::Base { x: 0, y: 0 });
        assert_eq!(face_of(&s, 0, 2), VoxelFace::BackSheet { x: 0, z: 0 });
    }

    /// Cards with random staircases, windows and left-out tops: the loose parts found on the
    /// cells have the count and areas of the loose pieces found on the planarised crease
    /// pattern (`integrity::loose_pieces`, faces traced anew), and the farthest cell beyond
    /// the closed card reaches as far as `closed_overhang` measures on the folded state.
    #[test]
    fn cells_agree_with_the_crease_pattern_checks() {
        let mut rng = TestRng::new(22);
        let mut below = |n: usize| ((rng.unit() * n as f64) as usize).min(n - 1);
        let (mut loose_seen, mut beyond_seen) = (0, 0);
        for _ in 0..300 {
            let (nx, ny, nz) = (below(4) + 2, below(4) + 2, below(4) + 2);
            let mut c = VoxelCard::new(nx, ny, nz, 3.0).unwrap();
            c.set_margin_mm([0.0, 2.0][below(2)]).unwrap();
            for x in 0..nx {
                let mut d = below(ny + 1);
                for z in 0..nz {
                    c.set_depth(x, z, d).unwrap();
                    c.set_hole(x, z, below(4) == 0).unwrap();
                    c.set_top_omitted(x, z, below(5) == 0).unwrap();
                    d = below(d + 1);
                }
            }
            let v = card_verdict(&c).unwrap();
            let cp = crease_pattern(&c).unwrap();
            let pieces = loose_pieces(&cp);
            assert_eq!(
                v.loose.len(),
                pieces.len(),
                "{}",
                super::super::format_voxel_card(&c)
            );
            for (a, b) in v.loose.iter().zip(&pieces) {
                assert!((a.area_mm2 - b.area_mm2).abs() < 1e-6, "{a:?} vs {b:?}");
            }
            loose_seen += usize::from(!v.loose.is_empty());
            let closed = fold_card(&c, &cp, 0.0).state;
            let measured = closed_overhang(&closed).map_or(0.0, |o| o.beyond_mm);
            let ours = v.beyond.first().map_or(0.0, |b| b.beyond_mm);
            if measured > CLOSED_SLACK_MM {
                beyond_seen += 1;
                assert!((ours - measured).abs() < 1e-6, "{ours} vs {measured}");
            } else {
                assert!(v.beyond.is_empty());
            }
        }
        // The random cards reached both faults (else this test checked nothing).
        assert!(
            loose_seen > 0 && beyond_seen > 0,
            "{loose_seen} {beyond_seen}"
        );
    }

    #[test]
    fn a_tall_step_reaches_beyond_the_closed_card_where_y_plus_z_is_too_large() {
        // A 1 mm margin: folded shut, the outline reaches max(ny, nz) cells (+ the margin)
        // from the fold; a face corner at (y, z) lands y + z cells from it (eq. 6 at
        // θ = 180°).
        let c = card(&[&[0, 3, 0], &[0, 3, 0], &[0, 3, 0]], 3, 1.0);
        let v = card_verdict(&c).unwrap();
        let limit = c.ny().max(c.nz()) as f64 + 1.0 / c.cell_mm();
        let mut expected = Vec::new();
        for z in 0..c.nz() {
            for y in 0..c.depth(1, z) {
                let exposed_front = y + 1 == c.depth(1, z);
                let exposed_top = c.depth(1, z + 1) <= y;
                // The far corner of either face is (y + 1, z + 1).
                if (y + z + 2) as f64 > limit {
                    if exposed_front {
                        expected.push(VoxelFace::Front { x: 1, y, z });
                    }
                    if exposed_top {
                        expected.push(VoxelFace::Top { x: 1, y, z });
                    }
                }
            }
        }
        let mut got: Vec<VoxelFace> = v.beyond.iter().map(|b| b.cell.face).collect();
        got.sort_by_key(|f| format!("{f:?}"));
        expected.sort_by_key(|f| format!("{f:?}"));
        assert!(!expected.is_empty());
        assert_eq!(got, expected);
    }
}
