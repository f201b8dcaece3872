//! Waterbomb bases: a square with both diagonals (valley) and the horizontal midline
//! (mountain), and a tessellation of such squares on a grid.
//!
//! A single base's centre has degree 6 (4 valleys, 2 mountains; sectors 45°, 90°, 45° twice).
//! In the tessellation the squares' outlines are creases too: horizontal outlines mountain;
//! each vertical outline mountain on its lower half and valley on its upper half, which makes
//! every interior vertex flat-foldable: grid corners have degree 8 (5 valleys, 3 mountains,
//! 45° sectors) and the midline ends have degree 4 (3 mountains, 1 valley, 90° sectors).

use glam::DVec2;

use super::{ClassicError, count, finish, positive};
use crate::pattern::{Assignment, CreasePattern};

/// Parameters of a grid of waterbomb bases.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Waterbomb {
    /// Bases along x.
    pub columns: usize,
    /// Bases along y.
    pub rows: usize,
    /// Side of one base, mm.
    pub size: f64,
}

impl Default for Waterbomb {
    fn default() -> Self {
        Waterbomb {
            columns: 4,
            rows: 4,
            size: 40.0,
        }
    }
}

impl Waterbomb {
    /// Builds the pattern.
    pub fn build(&self) -> Result<CreasePattern, ClassicError> {
        let nx = count("columns", self.columns, 1 << 12)?;
        let ny = count("rows", self.rows, 1 << 12)?;
        let s = positive("size", self.size)?;
        let mut cp = CreasePattern::new();
        let p = |i: usize, j: usize| DVec2::new(i as f64 * s, j as f64 * s);
        for j in 0..ny {
            for i in 0..nx {
                let (c0, c2) = (p(i, j), p(i + 1, j + 1));
                let (c1, c3) = (p(i + 1, j), p(i, j + 1));
                let centre = 0.5 * (c0 + c2);
                for c in [c0, c1, c2, c3] {
                    cp.add_segment(centre, c, Assignment::Valley);
                }
                let mid_l = DVec2::new(c0.x, centre.y);
                let mid_r = DVec2::new(c1.x, centre.y);
                cp.add_segment(mid_l, centre, Assignment::Mountain);
                cp.add_segment(centre, mid_r, Assignment::Mountain);
            }
        }
        for j in 0..=ny {
            let kind = outline(j == 0 || j == ny, Assignment::Mountain);
            cp.add_segment(p(0, j), p(nx, j), kind);
        }
        for i in 0..=nx {
            let edge = i == 0 || i == nx;
            for j in 0..ny {
                let mid = DVec2::new(i as f64 * s, (j as f64 + 0.5) * s);
                cp.add_segment(p(i, j), mid, outline(edge, Assignment::Mountain));
                cp.add_segment(mid, p(i, j + 1), outline(edge, Assignment::Valley));
            }
        }
        finish(cp, format!("Waterbomb bases {nx}×{ny}"))
    }
}

fn outline(on_edge: bool, inner: Assignment) -> Assignment {
    if on_edge { Assignment::Boundary } else { inner }
}

/// A single waterbomb base on a square of side `size` mm.
pub fn waterbomb_base(size: f64) -> Result<CreasePattern, ClassicError> {
    let mut cp = Waterbomb {
        columns: 1,
        rows: 1,
        size,
    }
    .build()?;
    cp.meta.title = Some("Waterbomb base".into());
    Ok(cp)
}
