//! The triangulations a [`Schedule::Ladder`](super::Schedule::Ladder) solves on, in order, each built before the first solve:
//! the input's own triangles, a near-regular re-triangulation ([`remesh`]) with as many faces,
//! and, when the input's rim crowding index ([`crowding`](super::crowding)) predicts the
//! tucks near the sheet's edge to run into each other, a coarser re-triangulation with the
//! face count that index allows ([`RimCrowding::faces_for_limit`]), tried first.
//!
//! Why the coarser one first (release build, stainless limits 165°/30°,
//! `tessellation_modes cap 12 13 60 100 MODE`, the 2,028-face 60° cap, crowding index 18.3 on
//! its re-triangulation): before, truncated stars ended with the tucks colliding at the rim
//! after 22 s and star tucks ran all twelve solves without converging for 275 s; every cap
//! measured over the limit collided at every shrink of the ladder (see
//! [`crowding`](super::crowding)), so the solves at the input's face count are tried only
//! when the coarser triangulation gives no usable result. Building every triangulation up
//! front lets a progress display name each solve by the triangles it runs on, also when a
//! re-triangulation cannot be built (it is left out of the passes, not skipped unheard).

use super::crowding::{RimCrowding, rim_crowding_of};
use super::pipeline::{Remesh, disk, remesh_order};
use super::remesh::{RemeshReport, remesh};
use super::{Limits, TessError};
use crate::mesh::PolyMesh;

/// Which triangles a [`Pass`] solves on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Triangulation {
    /// The input's own triangles.
    Input,
    /// A near-regular re-triangulation of the same surface asked for with `faces` faces (the
    /// input's count unless the schedule names one).
    Remeshed {
        /// Faces asked for.
        faces: usize,
    },
    /// A near-regular re-triangulation with fewer faces than the input, `faces` as the
    /// input's rim crowding index allows ([`RimCrowding::faces_for_limit`]).
    Coarser {
        /// Faces asked for.
        faces: usize,
    },
}

impl Triangulation {
    /// Words for a progress line: "the input's triangles", "the re-triangulation", "the
    /// coarser re-triangulation (606 faces)".
    pub fn describe(&self) -> String {
        match self {
            Triangulation::Input => "the input's triangles".into(),
            Triangulation::Remeshed { .. } => "the re-triangulation".into(),
            Triangulation::Coarser { faces } => {
                format!("the coarser re-triangulation ({faces} faces)")
            }
        }
    }
}

/// One pass of a schedule (every shrink of it on one triangulation), built.
#[derive(Clone, Debug)]
pub struct Pass {
    /// Which triangles.
    pub triangulation: Triangulation,
    /// The re-triangulated mesh and what changed; `None` on the input's own triangles.
    pub mesh: Option<(PolyMesh, RemeshReport)>,
}

/// The passes of a ladder re-triangulating as `remesh` says (with `remesh_faces` faces,
/// `None`: the input's count) on `mesh` with `limits`, in the order they are solved:
/// [`Triangulation::Coarser`] first when `remesh` is [`Remesh::Auto`] without a face count
/// and the input is [`crowded`](RimCrowding::crowded), then the order of
/// [`remesh_order`]. A re-triangulation that cannot be built is left out, with the
/// input's crowding returned alongside.
///
/// # Errors
/// When `mesh` is not a disk, or no pass can be built (the first re-triangulation's error).
pub(crate) fn scheduled_passes(
    mesh: &PolyMesh,
    limits: &Limits,
    remesh_as: Remesh,
    remesh_faces: Option<usize>,
) -> Result<(Vec<Pass>, RimCrowding), TessError> {
    let he = disk(mesh)?;
    let crowding = rim_crowding_of(mesh, &he);
    let own = mesh.faces().len();
    let mut wanted = Vec::new();
    if remesh_as == Remesh::Auto && remesh_faces.is_none() && crowding.crowded() {
        wanted.push(Triangulation::Coarser {
            faces: crowding.faces_for_limit(),
        });
    }
    for &remeshed in remesh_order(remesh_as, mesh, limits) {
        wanted.push(if remeshed {
            Triangulation::Remeshed {
                faces: remesh_faces.unwrap_or(own),
            }
        } else {
            Triangulation::Input
        });
    }
    let mut passes = Vec::new();
    let mut failure = None;
    for triangulation in wanted {
        let faces = match triangulation {
            Triangulation::Input => {
                passes.push(Pass {
                    triangulation,
                    mesh: None,
                });
                continue;
            }
            Triangulation::Remeshed { faces } | Triangulation::Coarser { faces } => faces,
        };
        match remesh(mesh, faces) {
            Ok(built) => passes.push(Pass {
                triangulation,
                mesh: Some(built),
            }),
            Err(e) => {
                failure.get_or_insert(e);
            }
        }
    }
    match (passes.is_empty(), failure) {
        (true, Some(e)) => Err(e),
        (true, None) => Err(TessError::BadParameter("nothing to try".into())),
        (false, _) => Ok((passes, crowding)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::design::tessellation::samples::spherical_cap;

    fn stainless() -> Limits {
        Limits::from_degrees(165.0, 30.0)
    }

    /// A crowded cap (60°, 9 rings: measured colliding, index over the limit) gets the
    /// coarser re-triangulation first, with the face count of the crowding advice, and
    /// fewer faces than the input; a clean one (60°, 6 rings) does not; neither does a
    /// schedule that names its face count or keeps the input's triangles.
    #[test]
    fn a_crowded_input_is_coarsened_first() {
        let crowded = spherical_cap(12, 9, 60.0, 100.0);
        let (passes, c) = scheduled_passes(&crowded, &stainless(), Remesh::Auto, None).unwrap();
        assert!(c.crowded(), "{}", c.index());
        let Triangulation::Coarser { faces } = passes[0].triangulation else {
            panic!("{:?}", passes[0].triangulation)
        };
        assert_eq!(faces, c.faces_for_limit());
        let built = passes[0].mesh.as_ref().unwrap();
        assert!(built.0.faces().len() < crowded.faces().len());
        assert_eq!(
            built.1.faces,
            [crowded.faces().len(), built.0.faces().len()]
        );
        // The other passes follow as the schedule orders them (sharp pole: remeshed first).
        let rest: Vec<_> = passes[1..].iter().map(|p| p.triangulation).collect();
        assert_eq!(
            rest,
            [
                Triangulation::Remeshed {
                    faces: crowded.faces().len()
                },
                Triangulation::Input
            ]
        );
        let clean = spherical_cap(12, 6, 60.0, 100.0);
        let (passes, c) = scheduled_passes(&clean, &stainless(), Remesh::Auto, None).unwrap();
        assert!(!c.crowded());
        assert_eq!(passes.len(), 2);
        assert!(
            passes
                .iter()
                .all(|p| !matches!(p.triangulation, Triangulation::Coarser { .. }))
        );
        for schedule in [(Remesh::Auto, Some(500)), (Remesh::Never, None)] {
            let (passes, _) =
                scheduled_passes(&crowded, &stainless(), schedule.0, schedule.1).unwrap();
            assert!(
                passes
                    .iter()
                    .all(|p| !matches!(p.triangulation, Triangulation::Coarser { .. })),
                "{schedule:?}"
            );
        }
    }

    /// A re-triangulation that cannot be built (fewer faces than `remesh` accepts) is left
    /// out; when it is all the schedule asks for, its error is returned.
    #[test]
    fn a_re_triangulation_that_cannot_be_built_is_left_out() {
        let tiny = spherical_cap(12, 1, 10.0, 100.0);
        let faces = Some(crate::design::tessellation::remesh::MIN_FACES - 1);
        let (passes, _) = scheduled_passes(&tiny, &stainless(), Remesh::Auto, faces).unwrap();
        let kinds: Vec<_> = passes.iter().map(|p| p.triangulation).collect();
        assert_eq!(kinds, [Triangulation::Input]);
        assert!(scheduled_passes(&tiny, &stainless(), Remesh::Only, faces).is_err());
    }
}
