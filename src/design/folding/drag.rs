//! The paper's interaction (Miyazaki et al. 1992, §2.3): pick a vertex and move it.
//!
//! **Picking** (§2.3 3): the vertex nearest the start point within a radius; of the faces
//! holding it, the one nearest the eye (the eye looks down from +z: the top face of the
//! stack, the stack of the plane facing the eye most squarely).
//!
//! **Fold line and angle** (§2.3 1, Fig. 3): the picked vertex `P` moves to `Q`; the fold line
//! is where the plane equidistant from `P` and `Q` (normal `Q − P` through their midpoint) cuts
//! the face's plane, and the fold angle is twice the angle between the two planes —
//! computed as the signed angle that turns `P` into `Q` about that line (the same number: the
//! rotation by twice the plane angle is the product of the reflections in the two planes, which
//! maps `P`, lying in the face's plane, to its mirror image `Q`). When `Q` lies in the face's
//! plane the angle is 180° and the direction (valley or mountain) is given by the caller.
//!
//! **Snapping** (§2.3 4), each with its own tolerance (0 disables it), in this order:
//! 1. the destination snaps to a vertex closer than `vertex`;
//! 2. edge onto edge (bends only): when a moving edge of the picked face lands with both ends
//!    within `edge` of another edge's line, the fold line becomes the bisector of the two lines
//!    that maps one onto the other;
//! 3. fold line through two vertices: when two vertices lie within `line` of the fold line, it
//!    is moved to pass through them;
//! 4. the fold angle snaps to a multiple of 30° or 45° (so also 60°) when within `angle_deg`.
//!
//! Deviation: edge-onto-edge snapping is applied to bends (180°) only, where "on the same line"
//! is a plane condition; after snapping, the destination is the image of `P` under the snapped
//! fold rather than the raw drag point.

use glam::{DVec2, DVec3};

use super::FoldError;
use super::geometry::{Line2, plane_basis, rotation_about};
use super::operation::{Fold, FoldReport, Layers, Turn};
use super::snap::{edge_onto_edge, snap_angle, through_two};
use super::state::{Folding, State};
use crate::geom::Segment;
use crate::geom::tolerance::RELATIVE;
use crate::pattern::MAX_COORDINATE;

/// Snapping tolerances of §2.3 4); zero disables a rule.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Snap {
    /// Destination to a vertex, millimetres.
    pub vertex: f64,
    /// Edge onto edge, millimetres.
    pub edge: f64,
    /// Fold line through two vertices, millimetres.
    pub line: f64,
    /// Fold angle to multiples of 30° and 45°, degrees.
    pub angle_deg: f64,
}

impl Default for Snap {
    fn default() -> Self {
        Snap {
            vertex: 1.0,
            edge: 1.0,
            line: 1.0,
            angle_deg: 3.0,
        }
    }
}

/// A drag of a vertex.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Drag {
    /// Near the vertex to pick, millimetres.
    pub from: DVec3,
    /// Where to move it, millimetres.
    pub to: DVec3,
    /// Pick radius around `from`, millimetres.
    pub pick_radius: f64,
    /// For a move within the face's plane (a bend): fold away from the normal (mountain)
    /// instead of towards it (valley).
    pub mountain: bool,
    /// Snapping tolerances.
    pub snap: Snap,
    /// When no vertex lies within `pick_radius` of `from`, pick the nearest point of a face's
    /// edge within that radius instead (of the faces whose edge holds it, the one nearest the
    /// eye). An extension of the paper's vertex picking.
    pub edge_points: bool,
}

/// A snapping rule that fired.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Snapped {
    /// The destination moved onto a vertex.
    Vertex,
    /// The fold line was turned to lay an edge onto another.
    EdgeOntoEdge,
    /// The fold line was moved through two vertices.
    LineThroughVertices,
    /// The fold angle snapped to this many degrees.
    Angle(f64),
}

/// A drag turned into a fold.
#[derive(Clone, Debug, PartialEq)]
pub struct DragPlan {
    /// The fold to apply.
    pub fold: Fold,
    /// Where the picked vertex was and where it lands, millimetres.
    pub vertex: (DVec3, DVec3),
    /// The snapping rules that fired, in order.
    pub snapped: Vec<Snapped>,
}

/// The plane frame of a group: origin and in-plane axes.
struct Frame {
    origin: DVec3,
    u: DVec3,
    v: DVec3,
    normal: DVec3,
}

impl Frame {
    fn to_plane(&self, p: DVec3) -> DVec2 {
        DVec2::new((p - self.origin).dot(self.u), (p - self.origin).dot(self.v))
    }
    fn in_space(&self, p: DVec2) -> DVec3 {
        self.origin + self.u * p.x + self.v * p.y
    }
}

impl Folding {
    /// Applies a drag as a new step (see the module docs). On error nothing changes.
    pub fn drag(
        &mut self,
        drag: &Drag,
        name: Option<String>,
    ) -> Result<(DragPlan, FoldReport), FoldError> {
        let plan = self.plan_drag(drag)?;
        let report = self.fold(&plan.fold, name)?;
        Ok((plan, report))
    }

    /// The fold a drag makes, without applying it.
    pub fn plan_drag(&self, drag: &Drag) -> Result<DragPlan, FoldError> {
        let finite = |p: DVec3| p.is_finite() && p.abs().max_element() <= MAX_COORDINATE;
        if !finite(drag.from) || !finite(drag.to) || !drag.pick_radius.is_finite() {
            return Err(FoldError::NotFinite {
                what: "a drag point",
            });
        }
        let state = self.current();
        let (p, face) = self.pick(state, drag)?;
        let mut snapped = Vec::new();
        let mut q = drag.to;
        if let Some(v) = self.nearest_vertex(state, q, drag.snap.vertex, Some(p)) {
            q = v;
            snapped.push(Snapped::Vertex);
        }
        let layers = state.layers();
        let group = &state.groups[layers[face].0];
        let (u, v) = plane_basis(group.normal);
        let frame = Frame {
            origin: group.origin,
            u,
            v,
            normal: group.normal,
        };
        let (mut line, mut angle) = self.bisector(&frame, p, q, drag.mountain)?;
        let vertices = self.plane_vertices(state, layers[face].0, &frame);
        if angle.abs() == 180.0 && drag.snap.edge > 0.0 {
            let edges = self.plane_edges(state, layers[face].0, &frame);
            let own = self.face_edges(state, face, &frame);
            if let Some(l) = edge_onto_edge(
                &line,
                &frame.to_plane(p),
                &own,
                &edges,
                drag.snap.edge,
                self.tol,
            ) {
                line = l;
                snapped.push(Snapped::EdgeOntoEdge);
            }
        }
        if let Some(l) = through_two(&line, &vertices, drag.snap.line, self.tol) {
            line = l;
            snapped.push(Snapped::LineThroughVertices);
        }
        if let Some(a) = snap_angle(angle, drag.snap.angle_deg) {
            angle = a;
            snapped.push(Snapped::Angle(a));
        }
        let pp = frame.to_plane(p);
        if line.side(pp).abs() <= self.tol {
            return Err(FoldError::SideOnLine);
        }
        let fold = Fold {
            line: [
                frame.in_space(line.point),
                frame.in_space(line.point + line.dir),
            ],
            moving: p,
            turn: Turn::Angle(angle),
            layers: Layers::Faces(vec![face]),
        };
        let outward =
            frame.normal.cross(frame.in_space(line.dir) - frame.origin) * line.side(pp).signum();
        let axis = outward.cross(frame.normal);
        let landed = rotation_about(fold.line[0], axis, angle.to_radians()).transform_point3(p);
        Ok(DragPlan {
            fold,
            vertex: (p, landed),
            snapped,
        })
    }

    /// The picked vertex and its face nearest the eye (looking down from +z).
    pub(super) fn pick(&self, state: &State, drag: &Drag) -> Result<(DVec3, usize), FoldError> {
        let none = FoldError::NoVertexNear {
            tolerance: drag.pick_radius,
        };
        let (p, on_edge) = match self.nearest_vertex(state, drag.from, drag.pick_radius, None) {
            Some(p) => (p, false),
            None if drag.edge_points => (
                self.nearest_edge_point(state, drag.from, drag.pick_radius)
                    .ok_or(none)?,
                true,
            ),
            None => return Err(none),
        };
        let layers = state.layers();
        let near = self.tol * 100.0;
        let eye = |f: usize| {
            let (g, pos) = layers[f];
            let n = state.groups[g].normal;
            let facing = (n.z.abs() * 1e6).round();
            (
                facing,
                if n.z >= 0.0 {
                    pos as f64
                } else {
                    -(pos as f64)
                },
            )
        };
        (0..state.faces.len())
            .filter(|&f| {
                let c = self.corners(&state.faces[f]);
                if on_edge {
                    (0..c.len()).any(|i| on_segment(p, c[i], c[(i + 1) % c.len()]).1 <= near)
                } else {
                    c.iter().any(|c| c.distance(p) <= near)
                }
            })
            .max_by(|&a, &b| {
                eye(a)
                    .partial_cmp(&eye(b))
                    .unwrap_or(std::cmp::Ordering::Equal)
            })
            .map(|f| (p, f))
            .ok_or(FoldError::NoVertexNear {
                tolerance: drag.pick_radius,
            })
    }

    /// The point of a face's edge nearest `at` within `radius`.
    fn nearest_edge_point(&self, state: &State, at: DVec3, radius: f64) -> Option<DVec3> {
        state
            .faces
            .iter()
            .flat_map(|f| {
                let c = self.corners(f);
                (0..c.len())
                    .map(|i| on_segment(at, c[i], c[(i + 1) % c.len()]))
                    .collect::<Vec<_>>()
            })
            .filter(|(_, d)| *d <= radius)
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(p, _)| p)
    }

    /// The vertex nearest `at` within `radius` (excluding points at `except`).
    fn nearest_vertex(
        &self,
        state: &State,
        at: DVec3,
        radius: f64,
        except: Option<DVec3>,
    ) -> Option<DVec3> {
        let near = self.tol * 100.0;
        state
            .faces
            .iter()
            .flat_map(|f| self.corners(f))
            .filter(|c| except.is_none_or(|e| c.distance(e) > near))
            .map(|c| (c.distance(at), c))
            .filter(|(d, _)| *d <= radius)
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .map(|(_, c)| c)
    }

    /// Fold line (plane coordinates) and signed angle (degrees, positive towards the normal)
    /// turning `p` into `q` (Fig. 3).
    fn bisector(
        &self,
        frame: &Frame,
        p: DVec3,
        q: DVec3,
        mountain: bool,
    ) -> Result<(Line2, f64), FoldError> {
        let w = q - p;
        if w.length() <= self.tol {
            return Err(FoldError::BadDrag("the vertex does not move"));
        }
        let dir = frame.normal.cross(w);
        if dir.length() <= RELATIVE * w.length() {
            return Err(FoldError::BadDrag("the move is perpendicular to the paper"));
        }
        let dir = dir.normalize();
        let mid = (p + q) * 0.5;
        let x0 = mid - frame.normal * (mid - frame.origin).dot(frame.normal);
        let w_in = w - frame.normal * w.dot(frame.normal);
        let x = x0 + w_in * ((mid - x0).dot(w) / w_in.dot(w));
        let line = Line2::through(frame.to_plane(x), frame.to_plane(x + dir), 0.0)
            .ok_or(FoldError::DegenerateLine)?;
        let perp = |a: DVec3| (a - x) - dir * (a - x).dot(dir);
        let (vp, vq) = (perp(p), perp(q));
        let phi = dir.dot(vp.cross(vq)).atan2(vp.dot(vq));
        // The operation turns about k = m × N (m towards the moving side): convert.
        let m = perp(p).normalize_or_zero();
        let k = m.cross(frame.normal);
        let mut angle = (if k.dot(dir) >= 0.0 { phi } else { -phi }).to_degrees();
        if (q - frame.origin).dot(frame.normal).abs() <= self.tol {
            angle = if mountain { -180.0 } else { 180.0 };
        }
        Ok((line, angle))
    }

    fn plane_vertices(&self, state: &State, group: usize, frame: &Frame) -> Vec<DVec2> {
        state.groups[group]
            .stack
            .iter()
            .flat_map(|&f| self.corners(&state.faces[f]))
            .map(|c| frame.to_plane(c))
            .collect()
    }

    fn face_edges(&self, state: &State, face: usize, frame: &Frame) -> Vec<Segment> {
        let c: Vec<DVec2> = self
            .corners(&state.faces[face])
            .iter()
            .map(|&p| frame.to_plane(p))
            .collect();
        (0..c.len())
            .map(|i| Segment::new(c[i], c[(i + 1) % c.len()]))
            .collect()
    }

    fn plane_edges(&self, state: &State, group: usize, frame: &Frame) -> Vec<Segment> {
        state.groups[group]
            .stack
            .iter()
            .flat_map(|&f| self.face_edges(state, f, frame))
            .collect()
    }
}

/// The point of segment `a`–`b` nearest `p`, and its distance from `p`.
pub(super) fn on_segment(p: DVec3, a: DVec3, b: DVec3) -> (DVec3, f64) {
    let d = b - a;
    let len2 = d.length_squared();
    let t = if len2 > 0.0 {
        ((p - a).dot(d) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let q = a + d * t;
    (q, q.distance(p))
}
