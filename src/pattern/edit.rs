//! Edits of a planar crease pattern, as an interactive editor makes them: draw a crease,
//! delete one, change its assignment, move a vertex. Every edit leaves the pattern planar:
//! a new crease or a moved vertex goes through [`planarize()`](super::planarize()), which
//! merges it onto vertices it touches and splits the lines it crosses.
//!
//! Contract: the pattern given is planar (as [`planarize()`](super::planarize()) leaves it).
//! An edit that fails leaves the pattern as it was. Every edit may renumber vertices and
//! edges, so faces, the stacking order and per-element FOLD arrays kept from the file are
//! dropped (faces are traced again by whoever needs them).

use glam::DVec2;
use serde::{Deserialize, Serialize};

use super::{
    Assignment, CreasePattern, MAX_COORDINATE, PlanarizeError, PlanarizeOptions, PlanarizeReport,
    VertexId, planarize,
};

/// One edit of a crease pattern. Positions are in the pattern's unit (x right, y up).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "op", rename_all = "snake_case")]
pub enum Edit {
    /// Draws a crease from `from` to `to` with `assignment` and that assignment's
    /// fully-folded angle ([`Assignment::flat_folded_angle`]).
    Add {
        /// Start point.
        from: [f64; 2],
        /// End point.
        to: [f64; 2],
        /// FOLD letter of the new crease (M, V, F, B, C, U or J).
        assignment: char,
    },
    /// Deletes an edge; vertices no other edge uses go with it.
    Delete {
        /// The edge's index.
        edge: usize,
    },
    /// Gives an edge another assignment. A fold angle is kept in size when a mountain
    /// becomes a valley or back (its sign flips); otherwise it becomes the new assignment's
    /// fully-folded angle.
    Assign {
        /// The edge's index.
        edge: usize,
        /// FOLD letter.
        assignment: char,
    },
    /// Moves a vertex to a new position (onto another vertex or line: they join).
    Move {
        /// The vertex's index.
        vertex: usize,
        /// New position.
        to: [f64; 2],
    },
}

/// Why an edit was refused (the pattern is unchanged).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum EditError {
    /// No edge of that index.
    #[error("edge {index}: the pattern has {count} edges (0 to {})", count.saturating_sub(1))]
    NoSuchEdge {
        /// The index asked for.
        index: usize,
        /// How many edges there are.
        count: usize,
    },
    /// No vertex of that index.
    #[error("vertex {index}: the pattern has {count} vertices (0 to {})", count.saturating_sub(1))]
    NoSuchVertex {
        /// The index asked for.
        index: usize,
        /// How many vertices there are.
        count: usize,
    },
    /// Not a FOLD assignment letter.
    #[error("assignment {0:?}: expected one of M, V, F, B, C, U, J")]
    Assignment(char),
    /// A coordinate that is not finite or beyond [`MAX_COORDINATE`].
    #[error("position ({x}, {y}): coordinates must be finite and within ±{MAX_COORDINATE:e}")]
    Position {
        /// x.
        x: f64,
        /// y.
        y: f64,
    },
    /// A crease whose ends are closer than the merge tolerance.
    #[error("the crease has no length (its ends are closer than {tolerance:e})")]
    ZeroLength {
        /// The pattern's merge tolerance.
        tolerance: f64,
    },
    /// The last edge cannot be deleted (a pattern holds at least one).
    #[error("the pattern would hold no edges: the last edge stays")]
    LastEdge,
    /// Planarisation refused the result.
    #[error(transparent)]
    Planarize(#[from] PlanarizeError),
}

/// What an edit did to the rest of the pattern.
#[derive(Clone, Debug, PartialEq, Default, Serialize)]
pub struct EditReport {
    /// Vertices merged (a moved vertex or a crease end landing on a vertex).
    pub merged_vertices: usize,
    /// Crossings the new crease or the moved vertex's edges made.
    pub crossings: usize,
    /// Edges split by them.
    pub splits: usize,
    /// Edges removed because they came to have no length or lie on another edge.
    pub removed_edges: usize,
}

impl From<&PlanarizeReport> for EditReport {
    fn from(r: &PlanarizeReport) -> EditReport {
        EditReport {
            merged_vertices: r.merged_vertices,
            crossings: r.crossings,
            splits: r.splits,
            removed_edges: r.zero_length_removed + r.duplicates_removed,
        }
    }
}

fn point(p: [f64; 2]) -> Result<DVec2, EditError> {
    let q = DVec2::new(p[0], p[1]);
    if q.is_finite() && q.abs().max_element() <= MAX_COORDINATE {
        Ok(q)
    } else {
        Err(EditError::Position { x: p[0], y: p[1] })
    }
}

fn assignment(letter: char) -> Result<Assignment, EditError> {
    Assignment::from_letter(letter).ok_or(EditError::Assignment(letter))
}

fn edge_index(cp: &CreasePattern, index: usize) -> Result<usize, EditError> {
    if index < cp.edges.len() {
        Ok(index)
    } else {
        Err(EditError::NoSuchEdge {
            index,
            count: cp.edges.len(),
        })
    }
}

/// Applies `edit` to the planar pattern `cp` with the merge tolerance `tolerance` (the
/// pattern's unit; `None` picks planarisation's default,
/// [`super::planarize::RELATIVE_TOLERANCE`] of the bounding-box diagonal).
///
/// # Errors
/// [`EditError`] naming the element or number refused; `cp` is then unchanged.
pub fn apply(
    cp: &mut CreasePattern,
    edit: &Edit,
    tolerance: Option<f64>,
) -> Result<EditReport, EditError> {
    let mut next = cp.clone();
    let report = apply_to(&mut next, edit, tolerance)?;
    *cp = next;
    Ok(report)
}

fn apply_to(
    cp: &mut CreasePattern,
    edit: &Edit,
    tolerance: Option<f64>,
) -> Result<EditReport, EditError> {
    // Every edit may renumber: nothing per element survives it.
    cp.faces = None;
    cp.face_orders.clear();
    cp.meta.drop_per_element_extras();
    let options = PlanarizeOptions {
        tolerance,
        faces: false,
    };
    match *edit {
        Edit::Add {
            from,
            to,
            assignment: letter,
        } => {
            let a = assignment(letter)?;
            let (p, q) = (point(from)?, point(to)?);
            let e = cp.add_segment(p, q, a);
            cp.edges[e.index()].fold_angle = a.flat_folded_angle();
            let tol = tolerance.unwrap_or_else(|| super::planarize::default_tolerance(cp));
            if p.distance(q) <= tol {
                return Err(EditError::ZeroLength { tolerance: tol });
            }
            Ok(EditReport::from(&planarize(cp, &options)?))
        }
        Edit::Delete { edge } => {
            let i = edge_index(cp, edge)?;
            if cp.edges.len() == 1 {
                return Err(EditError::LastEdge);
            }
            cp.edges.remove(i);
            Ok(EditReport::from(&planarize(cp, &options)?))
        }
        Edit::Assign {
            edge,
            assignment: letter,
        } => {
            let i = edge_index(cp, edge)?;
            let a = assignment(letter)?;
            let e = &mut cp.edges[i];
            let swap = matches!(
                (e.assignment, a),
                (Assignment::Mountain, Assignment::Valley)
                    | (Assignment::Valley, Assignment::Mountain)
            );
            e.fold_angle = match e.fold_angle {
                Some(angle) if swap => Some(-angle),
                Some(angle) if e.assignment == a => Some(angle),
                _ => a.flat_folded_angle(),
            };
            e.assignment = a;
            Ok(EditReport::default())
        }
        Edit::Move { vertex, to } => {
            if vertex >= cp.vertices.len() {
                return Err(EditError::NoSuchVertex {
                    index: vertex,
                    count: cp.vertices.len(),
                });
            }
            cp.vertices[VertexId::new(vertex).index()] = point(to)?;
            Ok(EditReport::from(&planarize(cp, &options)?))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The unit square with both diagonals as valleys (a planar X: five vertices).
    fn square_x() -> CreasePattern {
        let mut cp = CreasePattern::new();
        let c = [(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)].map(|(x, y)| DVec2::new(x, y));
        for k in 0..4 {
            cp.add_segment(c[k], c[(k + 1) % 4], Assignment::Boundary);
        }
        cp.add_segment(c[0], c[2], Assignment::Valley);
        cp.add_segment(c[1], c[3], Assignment::Valley);
        planarize(&mut cp, &PlanarizeOptions::default()).unwrap();
        cp
    }

    fn count(cp: &CreasePattern, a: Assignment) -> usize {
        cp.edges.iter().filter(|e| e.assignment == a).count()
    }

    #[test]
    fn a_crease_across_the_x_splits_it_at_the_centre() {
        let mut cp = square_x();
        assert_eq!((cp.vertices.len(), cp.edges.len()), (5, 8));
        // A horizontal mountain through the centre, ending on the two sides.
        let r = apply(
            &mut cp,
            &Edit::Add {
                from: [0.0, 5.0],
                to: [10.0, 5.0],
                assignment: 'M',
            },
            None,
        )
        .unwrap();
        // The crease meets the centre vertex (a split, not a crossing) and splits both sides.
        assert_eq!((cp.vertices.len(), cp.edges.len()), (7, 12));
        assert_eq!(count(&cp, Assignment::Mountain), 2);
        assert_eq!(r.splits, 3);
        assert!(
            cp.edges
                .iter()
                .all(|e| e.assignment != Assignment::Mountain || e.fold_angle == Some(-180.0))
        );
    }

    #[test]
    fn delete_assign_and_move_keep_the_pattern_planar() {
        let mut cp = square_x();
        let centre = cp
            .vertices
            .iter()
            .position(|p| *p == DVec2::new(5.0, 5.0))
            .unwrap();
        let diagonal = cp
            .edges
            .iter()
            .position(|e| e.assignment == Assignment::Valley)
            .unwrap();
        apply(
            &mut cp,
            &Edit::Assign {
                edge: diagonal,
                assignment: 'M',
            },
            None,
        )
        .unwrap();
        assert_eq!(count(&cp, Assignment::Mountain), 1);
        apply(&mut cp, &Edit::Delete { edge: diagonal }, None).unwrap();
        assert_eq!((cp.vertices.len(), cp.edges.len()), (5, 7));
        // Moving the centre onto the corner (0, 0): it merges, and the diagonal piece to that
        // corner has no length any more.
        apply(
            &mut cp,
            &Edit::Move {
                vertex: centre,
                to: [0.0, 0.0],
            },
            None,
        )
        .unwrap();
        assert_eq!(cp.vertices.len(), 4);
        assert!(cp.edges.iter().all(|e| e.vertices[0] != e.vertices[1]));
    }

    #[test]
    fn refused_edits_change_nothing() {
        let mut cp = square_x();
        let before = cp.clone();
        let bad = [
            Edit::Delete { edge: 8 },
            Edit::Assign {
                edge: 0,
                assignment: 'Q',
            },
            Edit::Move {
                vertex: 5,
                to: [0.0, 0.0],
            },
            Edit::Move {
                vertex: 0,
                to: [f64::NAN, 0.0],
            },
            Edit::Add {
                from: [1.0, 1.0],
                to: [1.0, 1.0],
                assignment: 'V',
            },
        ];
        for edit in &bad {
            assert!(apply(&mut cp, edit, None).is_err(), "{edit:?}");
            assert_eq!(cp, before);
        }
    }
}
