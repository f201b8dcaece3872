//! The Yoshimura (diamond) pattern: horizontal mountain lines and valley diagonals forming
//! isosceles triangles, the buckling pattern of an axially crushed cylinder.
//!
//! Interior vertices have degree 6 (2 mountains, 4 valleys) with sectors β, 180°−2β, β
//! repeated, β the triangles' base angle, so Kawasaki and Maekawa hold.

use glam::DVec2;

use super::{ClassicError, count, finish, positive};
use crate::pattern::{Assignment, CreasePattern};

/// Parameters of a Yoshimura sheet.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Yoshimura {
    /// Triangles along each line.
    pub columns: usize,
    /// Rows of triangles.
    pub rows: usize,
    /// Triangle base, mm.
    pub width: f64,
    /// Row height, mm.
    pub height: f64,
}

impl Default for Yoshimura {
    fn default() -> Self {
        Yoshimura {
            columns: 8,
            rows: 6,
            width: 20.0,
            height: 10.0,
        }
    }
}

impl Yoshimura {
    /// Builds the pattern.
    pub fn build(&self) -> Result<CreasePattern, ClassicError> {
        let n = count("columns", self.columns, 1 << 14)?;
        let rows = count("rows", self.rows, 1 << 14)?;
        let w = positive("width", self.width)?;
        let h = positive("height", self.height)?;
        let span = n as f64 * w;
        let mut cp = CreasePattern::new();
        // Points on each horizontal line: even lines at i·w, odd lines at (i + ½)·w plus the two
        // sheet edges; drawn as separate segments, merged by planarisation.
        let xs = |j: usize| -> Vec<f64> {
            if j.is_multiple_of(2) {
                (0..=n).map(|i| i as f64 * w).collect()
            } else {
                let mut v = vec![0.0];
                v.extend((0..n).map(|i| (i as f64 + 0.5) * w));
                v.push(span);
                v
            }
        };
        for j in 0..=rows {
            let y = j as f64 * h;
            let kind = if j == 0 || j == rows {
                Assignment::Boundary
            } else {
                Assignment::Mountain
            };
            for pair in xs(j).windows(2) {
                cp.add_segment(DVec2::new(pair[0], y), DVec2::new(pair[1], y), kind);
            }
        }
        for j in 0..rows {
            let (y0, y1) = (j as f64 * h, (j + 1) as f64 * h);
            // Diagonals join each lattice point to the nearest points of the next line.
            let (lo, hi) = if j % 2 == 0 { (y0, y1) } else { (y1, y0) };
            for i in 0..=n {
                let x = i as f64 * w;
                for dx in [-0.5 * w, 0.5 * w] {
                    if (0.0..=span).contains(&(x + dx)) {
                        let to = DVec2::new(x + dx, hi);
                        cp.add_segment(DVec2::new(x, lo), to, Assignment::Valley);
                    }
                }
            }
            cp.add_segment(
                DVec2::new(0.0, y0),
                DVec2::new(0.0, y1),
                Assignment::Boundary,
            );
            cp.add_segment(
                DVec2::new(span, y0),
                DVec2::new(span, y1),
                Assignment::Boundary,
            );
        }
        finish(cp, format!("Yoshimura {n}×{rows}"))
    }
}
