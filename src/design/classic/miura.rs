//! Miura-ori: parallelogram cells between straight pleat lines (along x) and zigzag lines
//! (along y).
//!
//! Vertex `(i, j)` sits at `(i·a + o_j, j·b)` with `o_j = 0` on even rows and `d` (the shear)
//! on odd rows. Zigzag column `i` is a single crease line whose assignment alternates with `i`;
//! each row segment takes the assignment that makes its end vertices 3-to-1 (Maekawa), which
//! is also the crease between the two smallest sectors, as flat folding requires.

use glam::DVec2;

use super::{ClassicError, count, finish, positive};
use crate::pattern::{Assignment, CreasePattern};

/// Parameters of a Miura-ori sheet.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MiuraOri {
    /// Cells along x.
    pub columns: usize,
    /// Cells along y.
    pub rows: usize,
    /// Cell width along the straight pleats, mm.
    pub width: f64,
    /// Cell height between pleats, mm.
    pub height: f64,
    /// Horizontal offset of odd rows (the zigzag's amplitude), mm; 0 gives a square grid.
    pub shear: f64,
}

impl Default for MiuraOri {
    fn default() -> Self {
        MiuraOri {
            columns: 8,
            rows: 8,
            width: 20.0,
            height: 16.0,
            shear: 6.0,
        }
    }
}

impl MiuraOri {
    /// Builds the pattern.
    pub fn build(&self) -> Result<CreasePattern, ClassicError> {
        let cols = count("columns", self.columns, 1 << 14)?;
        let rows = count("rows", self.rows, 1 << 14)?;
        let a = positive("width", self.width)?;
        let b = positive("height", self.height)?;
        if !self.shear.is_finite() || self.shear.abs() >= a {
            return Err(ClassicError {
                parameter: "shear",
                value: self.shear,
                expected: "must be finite and smaller in size than the cell width",
            });
        }
        let mut cp = CreasePattern::new();
        cp.vertices.reserve((cols + 1) * (rows + 1));
        cp.edges.reserve(2 * (cols + 1) * (rows + 1));
        let vid = |i: usize, j: usize| crate::pattern::VertexId::new(j * (cols + 1) + i);
        for j in 0..=rows {
            let o = if j % 2 == 1 { self.shear } else { 0.0 };
            for i in 0..=cols {
                cp.add_vertex(DVec2::new(i as f64 * a + o, j as f64 * b));
            }
        }
        let column_kind = |i: usize| {
            if i.is_multiple_of(2) {
                Assignment::Mountain
            } else {
                Assignment::Valley
            }
        };
        for j in 0..=rows {
            for i in 0..cols {
                let kind = if j == 0 || j == rows {
                    Assignment::Boundary
                } else if j % 2 == 0 {
                    column_kind(i + 1)
                } else {
                    column_kind(i)
                };
                cp.add_edge(vid(i, j), vid(i + 1, j), kind);
            }
        }
        for j in 0..rows {
            for i in 0..=cols {
                let kind = if i == 0 || i == cols {
                    Assignment::Boundary
                } else {
                    column_kind(i)
                };
                cp.add_edge(vid(i, j), vid(i, j + 1), kind);
            }
        }
        let title = format!("Miura-ori {cols}×{rows}");
        finish(cp, title)
    }
}

/// A square grid of `n × n` cells of side `pitch` mm, assigned like a Miura-ori without shear
/// (every interior vertex 3-to-1, so locally flat-foldable): `2n(n+1)` edges. Used by the
/// benchmarks as the million-edge case (n = 707).
pub fn grid(n: usize, pitch: f64) -> Result<CreasePattern, ClassicError> {
    MiuraOri {
        columns: n,
        rows: n,
        width: pitch,
        height: pitch,
        shear: 0.0,
    }
    .build()
}
