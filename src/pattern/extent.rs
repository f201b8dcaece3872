//! Whether a pattern has a sheet at all: a drawing whose vertices all coincide (it cleans to
//! nothing) or all lie on one straight line (lines, no area) has nothing to fold, and a check
//! of it would pass vacuously. Commands refuse such a pattern where it enters.

use crate::geom::tolerance::RELATIVE;

use super::CreasePattern;

/// Why a pattern has no sheet.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum Degenerate {
    /// No edge of non-zero length: the vertices all coincide, or there are none.
    #[error(
        "the pattern has no extent: its vertices all coincide (or there are none), so it holds \
         no line of non-zero length"
    )]
    NoExtent,
    /// Every vertex lies on one straight line.
    #[error(
        "all {vertices} vertices of the pattern lie on one straight line: it has lines but no \
         sheet to fold"
    )]
    Collinear {
        /// Vertices of the pattern.
        vertices: usize,
    },
}

impl CreasePattern {
    /// Whether the pattern has no sheet (see [`Degenerate`]): `None` for a pattern with area.
    /// A vertex counts as on the line through the two farthest-apart vertices found when it
    /// lies within [`RELATIVE`] of that line's length from it.
    pub fn degeneracy(&self) -> Option<Degenerate> {
        let has_length = self.edges.iter().any(|e| {
            let [a, b] = e.vertices.map(|v| self.position(v));
            a != b
        });
        let Some(&a) = self.vertices.first() else {
            return Some(Degenerate::NoExtent);
        };
        if !has_length {
            return Some(Degenerate::NoExtent);
        }
        // The vertex farthest from the first, then the one farthest from that: a diameter
        // within a factor of two, long enough to measure every offset against.
        let farthest = |from: glam::DVec2| {
            self.vertices
                .iter()
                .copied()
                .max_by(|p, q| {
                    from.distance_squared(*p)
                        .total_cmp(&from.distance_squared(*q))
                })
                .unwrap_or(from)
        };
        let b = farthest(a);
        let c = farthest(b);
        let axis = c - b;
        let length = axis.length();
        if length == 0.0 {
            return Some(Degenerate::NoExtent);
        }
        let on_line = self
            .vertices
            .iter()
            .all(|&p| (axis.perp_dot(p - b) / length).abs() <= RELATIVE * length);
        on_line.then_some(Degenerate::Collinear {
            vertices: self.vertices.len(),
        })
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec2;

    use super::*;
    use crate::pattern::Assignment;

    #[test]
    fn coincident_and_collinear_patterns_have_no_sheet_and_a_square_has_one() {
        let mut cp = CreasePattern::new();
        assert_eq!(cp.degeneracy(), Some(Degenerate::NoExtent));
        let p = DVec2::new(5.0, 5.0);
        cp.add_segment(p, p, Assignment::Boundary);
        assert_eq!(cp.degeneracy(), Some(Degenerate::NoExtent));
        let mut line = CreasePattern::new();
        for x in 0..7 {
            let x = f64::from(x);
            line.add_segment(
                DVec2::new(x, 2.0 * x),
                DVec2::new(x + 1.0, 2.0 * x + 2.0),
                Assignment::Boundary,
            );
        }
        assert!(matches!(
            line.degeneracy(),
            Some(Degenerate::Collinear { .. })
        ));
        // A sliver a millionth as wide as it is long still has area.
        let mut sliver = line.clone();
        sliver.add_segment(
            DVec2::new(0.0, 0.0),
            DVec2::new(1e-6, 0.0),
            Assignment::Boundary,
        );
        assert_eq!(sliver.degeneracy(), None);
        let mut square = CreasePattern::new();
        let c = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)].map(|(x, y)| DVec2::new(x, y));
        for k in 0..4 {
            square.add_segment(c[k], c[(k + 1) % 4], Assignment::Boundary);
        }
        assert_eq!(square.degeneracy(), None);
    }
}
