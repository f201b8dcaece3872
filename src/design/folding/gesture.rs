//! A drag on the folded sheet seen from above — the interaction of Miyazaki, Yasuda, Yokoi &
//! Toriwaki (1992) as a pointer on a top view gives it — turned into one step of the fold
//! script ([`super::script`]), so that an interactive session is saved as a script that
//! replays exactly.
//!
//! **Picking.** The pointer names a point of the top view (x, y in millimetres): the vertex
//! whose projection lies nearest to it within the pick radius, the highest one (nearest the
//! eye, which looks down from +z) where several project together; when no vertex is that near,
//! the nearest point of an edge (a drag with `edge = true`). The face it belongs to is the
//! one [`Folding::plan_drag`] picks: the top face of the stack there.
//!
//! **The fold line** is the perpendicular bisector of the vertex's move (Fig. 3 of the
//! paper) with the paper's snapping rules ([`super::drag`]): the pointer's destination is taken
//! in the picked face's plane (straight below or above the pointer), which makes a bend.
//!
//! **The operations** of the paper's §2.1:
//! - *bend*: turn 180° about that line; `behind` (a mountain fold as seen from above) turns
//!   away from the eye. Written as a `drag` step.
//! - *fold up* by an angle: the same line, the vertex turned by the angle instead (towards the
//!   eye, or away with `behind`). Written as a `drag` step whose destination is that turned
//!   point in space (the drag rule gives back the same line and angle).
//! - *tuck in*: the symmetric tuck-in along that line, the picked vertex naming the moving
//!   side. Written as a `tuck` step.
//!
//! Every written point is the exact number the simulator used, so the step replays to the same
//! state ([`super::script::write_script`] writes numbers that read back exactly).

use glam::{DVec2, DVec3};

use super::drag::{Drag, Snap, Snapped};
use super::geometry::rotation_about;
use super::script::{DEFAULT_PICK_RADIUS, DragSpec, LineSpec, StepSpec};
use super::state::{Folding, State};
use super::{FoldError, Turn};

/// The pick radius written for a drag from a point of an edge, millimetres (at most half the
/// gesture's radius): small enough that replaying it finds the edge point, not a vertex.
pub const EDGE_PICK_RADIUS: f64 = 1e-3;

/// A plane seen this close to edge-on from above (|normal·z| below this) cannot take a
/// pointer's destination.
pub const EDGE_ON_COSINE: f64 = 1e-3;

/// What the drag does (the operations of Miyazaki et al. 1992, §2.1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Operation {
    /// Turn 180° about the fold line.
    Bend,
    /// Turn by this many degrees, in (0°, 180°).
    FoldUp {
        /// The fold angle, degrees.
        angle_deg: f64,
    },
    /// Tuck in symmetrically along the fold line.
    TuckIn,
}

/// A drag on the top view.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Gesture {
    /// Where the pointer went down, millimetres (x, y seen from above).
    pub from: DVec2,
    /// Where the pointer is (or was let go), millimetres.
    pub to: DVec2,
    /// How far from `from` a vertex may be picked, millimetres.
    pub pick_radius: f64,
    /// The operation.
    pub operation: Operation,
    /// Fold away from the eye (a mountain fold as seen from above) instead of towards it.
    pub behind: bool,
}

/// A gesture made into a step, with what the view shows of it.
#[derive(Clone, Debug, PartialEq)]
pub struct GesturePlan {
    /// The script step that makes the fold.
    pub step: StepSpec,
    /// Two points of the fold line, millimetres, in space.
    pub line: [DVec3; 2],
    /// The picked vertex and where it lands, millimetres.
    pub vertex: (DVec3, DVec3),
    /// The fold angle, degrees, positive towards the picked layer's normal (180 for a tuck-in).
    pub angle_deg: f64,
    /// The snapping rules that fired, in order.
    pub snapped: Vec<Snapped>,
}

impl Folding {
    /// The step a gesture makes on the current state, without making it.
    ///
    /// # Errors
    /// No vertex near the pointer, a face seen edge-on, a drag that defines no fold, a fold-up
    /// angle outside (0°, 180°), or anything [`Folding::plan_drag`] refuses. Whether the fold
    /// itself can be made is known only by applying the step
    /// ([`super::script::apply_step`]).
    pub fn plan_gesture(&self, g: &Gesture, snap: Snap) -> Result<GesturePlan, FoldError> {
        let finite = g.from.is_finite() && g.to.is_finite() && g.pick_radius.is_finite();
        if !finite {
            return Err(FoldError::NotFinite {
                what: "a drag point",
            });
        }
        let state = self.current();
        let (p, on_edge) = self.pick_from_above(state, g.from, g.pick_radius)?;
        // A vertex is found again within the default radius; an edge point within a radius
        // smaller than its distance from any vertex (no vertex lies within the gesture's).
        let pick = if on_edge {
            EDGE_PICK_RADIUS.min(g.pick_radius / 2.0)
        } else {
            DEFAULT_PICK_RADIUS
        };
        let probe = Drag {
            from: p,
            to: p,
            pick_radius: pick,
            mountain: false,
            snap,
            edge_points: on_edge,
        };
        let (_, face) = self.pick(state, &probe)?;
        let group = &state.groups[state.layers()[face].0];
        let n = group.normal;
        if n.z.abs() < EDGE_ON_COSINE {
            return Err(FoldError::BadDrag(
                "the picked face stands edge-on seen from above",
            ));
        }
        // The destination in the face's plane, straight below or above the pointer.
        let o = group.origin;
        let z = o.z - (n.x * (g.to.x - o.x) + n.y * (g.to.y - o.y)) / n.z;
        let q = DVec3::new(g.to.x, g.to.y, z);
        // Towards the eye is towards the normal when the normal faces up.
        let towards_eye = if n.z > 0.0 { 1.0 } else { -1.0 };
        let sign = if g.behind { -towards_eye } else { towards_eye };
        let bend = Drag {
            to: q,
            mountain: sign < 0.0,
            ..probe
        };
        let plan = self.plan_drag(&bend)?;
        let line = plan.fold.line;
        let drag_step = |to: DVec3, mountain: bool| StepSpec {
            drag: Some(DragSpec {
                from: p.to_array().to_vec(),
                to: to.to_array().to_vec(),
                mountain,
                pick: on_edge.then_some(pick),
                edge: on_edge,
            }),
            ..empty_step()
        };
        match g.operation {
            Operation::Bend => Ok(GesturePlan {
                step: drag_step(q, bend.mountain),
                line,
                vertex: plan.vertex,
                angle_deg: 180.0 * sign,
                snapped: plan.snapped,
            }),
            Operation::TuckIn => Ok(GesturePlan {
                step: StepSpec {
                    tuck: Some(LineSpec {
                        line: [line[0].to_array().to_vec(), line[1].to_array().to_vec()],
                        moving: p.to_array().to_vec(),
                        angle: None,
                        mountain: false,
                        layers: None,
                    }),
                    ..empty_step()
                },
                line,
                vertex: plan.vertex,
                angle_deg: 180.0,
                snapped: plan.snapped,
            }),
            Operation::FoldUp { angle_deg } => {
                if !angle_deg.is_finite() || angle_deg <= 0.0 || angle_deg >= 180.0 {
                    return Err(FoldError::BadAngle(angle_deg));
                }
                // Turn P about the snapped line by the angle: the drag rule finds that line
                // again (every point of it is as far from P as from the turned point).
                let dir = (line[1] - line[0]).normalize();
                let off = (p - line[0]) - dir * (p - line[0]).dot(dir);
                let m = off.normalize();
                let axis = m.cross(n);
                let to = rotation_about(line[0], axis, (sign * angle_deg).to_radians())
                    .transform_point3(p);
                let up = Drag {
                    to,
                    mountain: false,
                    ..bend
                };
                let lifted = self.plan_drag(&up)?;
                let mut snapped = plan.snapped;
                snapped.extend(lifted.snapped.iter().copied());
                let angle = match lifted.fold.turn {
                    Turn::Angle(a) => a,
                    Turn::Tuck => 180.0,
                };
                Ok(GesturePlan {
                    step: drag_step(to, false),
                    line: lifted.fold.line,
                    vertex: lifted.vertex,
                    angle_deg: angle,
                    snapped,
                })
            }
        }
    }

    /// The vertex whose projection on the x-y plane lies nearest to `at` within `radius`, or
    /// when there is none the point of an edge whose projection does (`true` then); of several
    /// there (within 100 × the tolerance), the highest.
    fn pick_from_above(
        &self,
        state: &State,
        at: DVec2,
        radius: f64,
    ) -> Result<(DVec3, bool), FoldError> {
        let near = self.tol * 100.0;
        let corners: Vec<DVec3> = state.faces.iter().flat_map(|f| self.corners(f)).collect();
        let highest = |points: Vec<DVec3>| {
            let distance = |c: &DVec3| c.truncate().distance(at);
            let nearest = points
                .iter()
                .map(distance)
                .filter(|d| *d <= radius)
                .min_by(f64::total_cmp)?;
            points
                .iter()
                .filter(|c| distance(c) <= nearest + near)
                .max_by(|a, b| a.z.total_cmp(&b.z))
                .copied()
        };
        if let Some(p) = highest(corners) {
            return Ok((p, false));
        }
        // The nearest point of each edge seen from above, lifted back onto the edge.
        let mut on_edges = Vec::new();
        for face in &state.faces {
            let c = self.corners(face);
            for i in 0..c.len() {
                let (a, b) = (c[i], c[(i + 1) % c.len()]);
                let d = (b - a).truncate();
                let len2 = d.length_squared();
                if len2 > near * near {
                    let t = ((at - a.truncate()).dot(d) / len2).clamp(0.0, 1.0);
                    on_edges.push(a + (b - a) * t);
                }
            }
        }
        highest(on_edges)
            .map(|p| (p, true))
            .ok_or(FoldError::NoVertexNear { tolerance: radius })
    }
}

fn empty_step() -> StepSpec {
    StepSpec {
        name: None,
        bend: None,
        fold: None,
        tuck: None,
        drag: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::design::folding::crease::crease_pattern;
    use crate::design::folding::script::{
        Script, SheetSpec, SnapSpec, apply_step, parse_script, run_script, write_script,
    };
    use crate::pattern::{Assignment, CreasePattern};

    const SIDE: f64 = 150.0;

    fn square() -> Folding {
        Folding::new(&[
            DVec2::ZERO,
            DVec2::new(SIDE, 0.0),
            DVec2::new(SIDE, SIDE),
            DVec2::new(0.0, SIDE),
        ])
        .unwrap()
    }

    fn gesture(from: [f64; 2], to: [f64; 2], operation: Operation) -> Gesture {
        Gesture {
            from: DVec2::from(from),
            to: DVec2::from(to),
            pick_radius: 3.0,
            operation,
            behind: false,
        }
    }

    /// Applies gestures one after the other; returns the folding and the steps made.
    /// The steps written as a script on the square sheet, read back and run.
    fn replay(steps: Vec<StepSpec>) -> Folding {
        let script = Script {
            title: None,
            sheet: SheetSpec {
                square: Some(SIDE),
                rectangle: None,
                polygon: None,
            },
            snap: SnapSpec::default(),
            steps,
        };
        run_script(&parse_script(&write_script(&script)).unwrap()).unwrap()
    }

    fn perform(gestures: &[Gesture]) -> (Folding, Vec<StepSpec>) {
        let mut f = square();
        let mut steps = Vec::new();
        for g in gestures {
            let plan = f.plan_gesture(g, Snap::default()).expect("plan");
            apply_step(&mut f, &plan.step, Snap::default()).expect("fold");
            steps.push(plan.step);
        }
        (f, steps)
    }

    /// The fold lines of a pattern as (ends rounded to 1e-6 mm, sorted; assignment), sorted.
    fn folds(cp: &CreasePattern) -> Vec<([[i64; 2]; 2], Assignment)> {
        let key = |p: DVec2| [(p.x * 1e6).round() as i64, (p.y * 1e6).round() as i64];
        let mut out: Vec<_> = cp
            .edges
            .iter()
            .filter(|e| e.assignment.is_fold())
            .map(|e| {
                let mut ends = [
                    key(cp.vertices[e.vertices[0].index()]),
                    key(cp.vertices[e.vertices[1].index()]),
                ];
                ends.sort();
                (ends, e.assignment)
            })
            .collect();
        out.sort();
        out
    }

    #[test]
    fn a_corner_dragged_onto_the_opposite_corner_folds_along_the_diagonal() {
        // The pointer misses both corners by a little: vertex snapping puts it on them.
        let (f, _) = perform(&[gesture([149.2, 150.4], [0.5, -0.3], Operation::Bend)]);
        let cp = crease_pattern(&f).pattern;
        let creases = folds(&cp);
        assert_eq!(creases.len(), 1, "{creases:?}");
        let ([a, b], assignment) = creases[0];
        assert_eq!(assignment, Assignment::Valley);
        // The other diagonal, from (150, 0) to (0, 150): length side·√2.
        assert_eq!([a, b], [[0, 150_000_000], [150_000_000, 0]]);
        let length = ((a[0] - b[0]) as f64).hypot((a[1] - b[1]) as f64) * 1e-6;
        assert!((length - SIDE * 2f64.sqrt()).abs() < 1e-5);
    }

    #[test]
    fn folding_in_half_is_not_snapped_onto_an_edge_the_fold_line_crosses() {
        // The fold line y = 75 crosses the sides x = 0 and x = 150 at right angles: their
        // moving halves land on their own lines, which must not count as an edge-onto-edge snap.
        let (f, _) = perform(&[gesture([0.0, 150.0], [0.0, 0.0], Operation::Bend)]);
        let creases = folds(&crease_pattern(&f).pattern);
        assert_eq!(
            creases,
            vec![(
                [[0, 75_000_000], [150_000_000, 75_000_000]],
                Assignment::Valley
            )]
        );
    }

    #[test]
    fn behind_folds_a_mountain_and_fold_up_turns_by_the_angle() {
        let mut g = gesture([150.0, 150.0], [0.0, 0.0], Operation::Bend);
        g.behind = true;
        let (f, _) = perform(&[g]);
        let creases = folds(&crease_pattern(&f).pattern);
        assert_eq!(creases.len(), 1);
        assert_eq!(creases[0].1, Assignment::Mountain);
        let up = gesture(
            [150.0, 0.0],
            [0.0, 0.0],
            Operation::FoldUp { angle_deg: 90.0 },
        );
        let (f, _) = perform(&[up]);
        let cp = crease_pattern(&f).pattern;
        let crease: Vec<_> = cp.edges.iter().filter(|e| e.assignment.is_fold()).collect();
        assert_eq!(crease.len(), 1);
        assert!((crease[0].fold_angle.unwrap() - 90.0).abs() < 1e-9);
        // The corner (150, 0) stands straight up above the line x = 75, towards the eye.
        let moved = f
            .current()
            .faces
            .iter()
            .flat_map(|face| f.corners(face))
            .any(|c| c.distance(DVec3::new(75.0, 0.0, 75.0)) < 1e-9);
        assert!(moved);
    }

    #[test]
    fn gestures_give_the_preliminary_base_of_the_example_script() {
        // Fold the diagonal, then tuck each sharp corner onto the right angle's corner: the
        // perpendicular bisectors are the midlines, as in examples/folding/preliminary-base.toml.
        let (f, steps) = perform(&[
            gesture([150.0, 150.0], [0.0, 0.0], Operation::Bend),
            gesture([150.0, 0.0], [0.0, 0.0], Operation::TuckIn),
            gesture([0.0, 150.0], [0.0, 0.0], Operation::TuckIn),
        ]);
        let example = parse_script(include_str!(
            "../../../examples/folding/preliminary-base.toml"
        ))
        .unwrap();
        let expected = folds(&crease_pattern(&run_script(&example).unwrap()).pattern);
        assert_eq!(folds(&crease_pattern(&f).pattern), expected);
        // The written script replays to the same pattern.
        let replayed = replay(steps);
        assert_eq!(
            crease_pattern(&replayed).pattern,
            crease_pattern(&f).pattern
        );
    }

    #[test]
    fn a_fold_up_replays_from_its_written_step() {
        let (f, steps) = perform(&[gesture(
            [150.0, 150.0],
            [20.0, 31.0],
            Operation::FoldUp { angle_deg: 75.0 },
        )]);
        let replayed = replay(steps);
        assert_eq!(replayed.current(), f.current());
    }

    #[test]
    fn an_edge_point_dragged_down_folds_the_sheet_in_half() {
        // The middle of the top side, no vertex within reach: the edge point moves to the
        // middle of the bottom side and the fold line is the midline y = 75.
        let (f, steps) = perform(&[gesture([75.4, 150.3], [75.0, 0.0], Operation::Bend)]);
        let creases = folds(&crease_pattern(&f).pattern);
        assert_eq!(
            creases,
            vec![(
                [[0, 75_000_000], [150_000_000, 75_000_000]],
                Assignment::Valley
            )]
        );
        let drag = steps[0].drag.as_ref().unwrap();
        assert!(drag.edge && drag.from[1] == SIDE, "{drag:?}");
        let replayed = replay(steps);
        assert_eq!(replayed.current(), f.current());
    }

    #[test]
    fn bad_gestures_are_refused() {
        let f = square();
        let far = gesture([75.0, 75.0], [0.0, 0.0], Operation::Bend);
        // (75, 75) is far from every edge too.
        assert!(matches!(
            f.plan_gesture(&far, Snap::default()),
            Err(FoldError::NoVertexNear { .. })
        ));
        let flat = gesture(
            [150.0, 150.0],
            [0.0, 0.0],
            Operation::FoldUp { angle_deg: 180.0 },
        );
        assert!(matches!(
            f.plan_gesture(&flat, Snap::default()),
            Err(FoldError::BadAngle(_))
        ));
        let still = gesture([150.0, 150.0], [150.0, 150.0], Operation::Bend);
        assert!(matches!(
            f.plan_gesture(&still, Snap::default()),
            Err(FoldError::BadDrag(_))
        ));
    }
}
