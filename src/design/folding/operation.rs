//! The fold operations of Miyazaki et al. (1992) §2.1 — folding up by any angle, bending (180°) and tucking in (the
//! symmetric case) — and the list update of §4: moving-face search (§4.1, in `search`),
//! splitting the faces the fold line crosses (§4.2–4.3: each becomes two child cells of the
//! face tree), moving the vertices by the rotation (§4.4: here, composing each moving face's
//! rigid transform with the rotation) and the new face stack (§4.5).
//!
//! **Rotation.** The moving side turns about the fold line by the fold angle, positive towards
//! the group's normal: with `m` the in-plane unit vector from the line to the moving side and
//! `N` the normal, the axis is `k = m × N`, so that `m` turns towards `N`.
//!
//! **Stacks (§4.5).** A bend lands the moving faces in their own plane, reversed, on the side
//! they turn towards (on top for a turn towards `N`). A fold-up by another angle makes a new
//! group of the moving faces in their old order, unless their new plane is an existing group's,
//! where they go on the side they arrive from. A tuck-in turns the lower half of the moving
//! faces up and the upper half down by 180°: each half lands reversed next to where it was
//! hinged (the lower half just above its top face, the upper half just below its bottom face).

use glam::{DAffine3, DVec2, DVec3};

use super::FoldError;
use super::geometry::{Line2, contains_either, double_area, plane_basis, split_into};
use super::search::{Layer, Moving, Turning, moving_faces};
use super::small::{Neighbours, Ring};
use super::stack::{Hinge, check_tuck, land, tucked_stack};
use super::state::{CellId, FaceCell, Folding, LiveFace, MAX_FACES, Neighbour, State};
use crate::geom::Segment;
use crate::pattern::MAX_COORDINATE;

/// Smallest distance (model units) within which a fold's points count as lying in a layer's
/// plane, whatever the operation's tolerance: the points are typed in, to about six digits.
const MIN_PLANE_DISTANCE: f64 = 1e-6;

/// Which faces a fold starts from (rule ① of §4.1).
#[derive(Clone, Debug, PartialEq)]
pub enum Layers {
    /// Every face of the layer plane that reaches the moving side.
    All,
    /// The `n`-th face (1 = the outermost) at the `moving` point counted from the side the
    /// fold turns to (from the top for a turn towards the normal), plus what the search adds —
    /// so, by rule ③, the outer `n` layers there. For a tuck-in, the `n`-th from the top, with
    /// the faces joined to it beyond the line (rule ②) and those between (rule ④).
    Outer(usize),
    /// The `n`-th face (1 = the outermost) at the `moving` point counted from the back (the
    /// side away from the normal), whatever the turn, plus what the search adds.
    Back(usize),
    /// The given faces (indices into [`State::faces`]).
    Faces(Vec<usize>),
}

/// How far the moving side turns.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Turn {
    /// Folding up by an angle in degrees, positive towards the layer plane's normal (from +z
    /// for a flat model: valley as seen from above); ±180 is a bend.
    Angle(f64),
    /// Tucking in (symmetric, 180°).
    Tuck,
}

/// One fold: a line in a layer plane, the side that moves, the turn and the seed faces.
#[derive(Clone, Debug, PartialEq)]
pub struct Fold {
    /// Two distinct points of the fold line, millimetres; both must lie in one layer plane.
    pub line: [DVec3; 2],
    /// A point on the moving side (in the same plane, off the line).
    pub moving: DVec3,
    /// The turn.
    pub turn: Turn,
    /// The seed faces.
    pub layers: Layers,
}

/// What a fold did.
#[derive(Clone, Debug, PartialEq)]
pub struct FoldReport {
    /// Faces that moved.
    pub moved: usize,
    /// Faces the fold line split in two.
    pub split: usize,
    /// The fold angle applied, degrees (180 for a tuck-in).
    pub angle_deg: f64,
}

impl Folding {
    /// Applies a fold as a new step. On error the state is unchanged.
    pub fn fold(&mut self, fold: &Fold, name: Option<String>) -> Result<FoldReport, FoldError> {
        let state = self.current();
        let (group, frame) = self.find_plane(state, fold)?;
        let to_plane =
            |p: DVec3| DVec2::new((p - frame.0).dot(frame.1), (p - frame.0).dot(frame.2));
        let line = Line2::through(to_plane(fold.line[0]), to_plane(fold.line[1]), self.tol)
            .ok_or(FoldError::DegenerateLine)?;
        let side = line.side(to_plane(fold.moving));
        if side.abs() <= self.tol {
            return Err(FoldError::SideOnLine);
        }
        let side = side.signum();
        let (angle, turning) = match fold.turn {
            Turn::Angle(a) => {
                if !a.is_finite() || a == 0.0 || a.abs() > 180.0 {
                    return Err(FoldError::BadAngle(a));
                }
                (a.to_radians(), Turning::Towards(a.signum()))
            }
            Turn::Tuck => (std::f64::consts::PI, Turning::Tuck),
        };
        let layer = Layer::new(self, state, group, frame, line, side);
        let seeds = self.seeds(&layer, fold, to_plane(fold.moving), turning);
        let search = moving_faces(self, state, &layer, &seeds, turning)?;
        let moving = &search.in_layer;
        if !moving.iter().any(|&m| m) {
            return Err(FoldError::LineMissesSheet(
                "no face reaches the moving side",
            ));
        }
        let whole_layer = (0..moving.len()).all(|i| moving[i] && layer.fixed_part(i).is_empty());
        if whole_layer && layer.stack.len() + search.carried.len() == state.faces.len() {
            return Err(FoldError::LineMissesSheet(
                "the whole paper lies on the moving side",
            ));
        }
        if turning == Turning::Tuck {
            check_tuck(&layer, moving, self.tol)?;
        }
        let split = (0..moving.len())
            .filter(|&i| moving[i] && !layer.fixed_part(i).is_empty())
            .count();
        if state.faces.len() + split > MAX_FACES {
            return Err(FoldError::TooManyFaces(MAX_FACES));
        }
        let hinge = layer_hinge(&layer, angle);
        let report = FoldReport {
            moved: moving.iter().filter(|&&m| m).count() + search.carried.len(),
            split,
            angle_deg: angle.to_degrees(),
        };
        let summary = summary(fold.turn, &report);
        // The next state: a copy with room for the new faces (and the face tree for their
        // cells), so that splitting does not reallocate.
        let mut faces = Vec::with_capacity(state.faces.len() + split);
        faces.extend_from_slice(&state.faces);
        let copy = State {
            faces,
            groups: state.groups.clone(),
        };
        self.cells.reserve(2 * split);
        let next = self.apply(copy, &layer, &search, &hinge, turning);
        self.push(name, summary, next);
        Ok(report)
    }

    /// The group whose plane holds the fold line, and its frame (origin, u, v).
    fn find_plane(
        &self,
        state: &State,
        fold: &Fold,
    ) -> Result<(usize, (DVec3, DVec3, DVec3)), FoldError> {
        let finite = |p: &DVec3| p.is_finite() && p.abs().max_element() <= MAX_COORDINATE;
        if !fold.line.iter().chain([&fold.moving]).all(finite) {
            return Err(FoldError::NotFinite {
                what: "a fold point",
            });
        }
        let group = state
            .groups
            .iter()
            .position(|g| {
                [fold.line[0], fold.line[1], fold.moving].iter().all(|p| {
                    (*p - g.origin).dot(g.normal).abs() <= self.tol.max(MIN_PLANE_DISTANCE)
                })
            })
            .ok_or(FoldError::NoLayer)?;
        let g = &state.groups[group];
        let (u, v) = plane_basis(g.normal);
        Ok((group, (g.origin, u, v)))
    }

    /// Stack positions of the seed faces.
    fn seeds(&self, layer: &Layer, fold: &Fold, at: DVec2, turning: Turning) -> Vec<usize> {
        let candidates = (0..layer.stack.len()).filter(|&i| !layer.moving_part(i).is_empty());
        match &fold.layers {
            Layers::All => candidates.collect(),
            Layers::Faces(faces) => (0..layer.stack.len())
                .filter(|&i| faces.contains(&layer.stack[i]))
                .collect(),
            Layers::Back(n) => candidates
                .filter(|&i| contains_either(layer.moving_part(i), at, self.tol))
                .nth(n.saturating_sub(1))
                .into_iter()
                .collect(),
            Layers::Outer(n) => {
                let under: Vec<usize> = candidates
                    .filter(|&i| contains_either(layer.moving_part(i), at, self.tol))
                    .collect();
                let k = n.saturating_sub(1);
                let from_top = under.len().checked_sub(k + 1).map(|i| under[i]);
                let from_bottom = under.get(k).copied();
                match turning {
                    Turning::Towards(s) if s > 0.0 => from_top.into_iter().collect(),
                    Turning::Towards(_) => from_bottom.into_iter().collect(),
                    Turning::Tuck => from_top.into_iter().collect(),
                }
            }
        }
    }

    /// The state after the fold: faces split and moved, carried faces moved, stacks updated.
    fn apply(
        &mut self,
        mut state: State,
        layer: &Layer,
        search: &Moving,
        hinge: &Hinge,
        turning: Turning,
    ) -> State {
        let moving = &search.in_layer;
        let rotation = hinge.motion();
        let step = self.steps.len();
        let carried = carry(&mut state, &search.carried, rotation);
        let mut scratch = (Vec::with_capacity(16), Vec::with_capacity(16));
        // Stack of the folded group after splitting, bottom first.
        // Entries: (face, moving?, stack position before the fold).
        let mut stack: Vec<(usize, bool, usize)> = Vec::with_capacity(layer.stack.len() * 2);
        for (i, &f) in layer.stack.iter().enumerate() {
            if !moving[i] {
                stack.push((f, false, i));
                continue;
            }
            if layer.fixed_part(i).is_empty() {
                let t = state.faces[f].transform;
                state.faces[f].transform = rotation * t;
                stack.push((f, true, i));
                continue;
            }
            let g = self.split(&mut state, f, layer, step, rotation, &mut scratch);
            stack.push((f, false, i));
            stack.push((g, true, i));
        }
        let block: Vec<usize> = stack.iter().filter(|s| s.1).map(|s| s.0).collect();
        let group = &mut state.groups[layer.group];
        match turning {
            Turning::Tuck => group.stack = tucked_stack(&stack),
            Turning::Towards(_) => {
                group.stack = stack.iter().filter(|s| !s.1).map(|s| s.0).collect();
                let old = (group.origin, group.normal);
                let arrival = hinge.arrival(rotation.transform_vector3(hinge.outward));
                land(&mut state.groups, old, block, rotation, arrival, self.tol);
            }
        }
        for (plane, block) in carried {
            let centre = self.centre(&state, &block);
            let arrival = hinge.arrival(centre - hinge.point);
            land(&mut state.groups, plane, block, rotation, arrival, self.tol);
        }
        state.groups.retain(|g| !g.stack.is_empty());
        state
    }

    /// The mean of the corners of `faces`, in space.
    fn centre(&self, state: &State, faces: &[usize]) -> DVec3 {
        let corners: Vec<DVec3> = faces
            .iter()
            .flat_map(|&f| self.corners(&state.faces[f]))
            .collect();
        corners.iter().sum::<DVec3>() / corners.len().max(1) as f64
    }

    /// Splits face `f` along the fold line: `f` keeps the stationary part, a new face (returned)
    /// takes the moving part, turned by `rotation`. Updates the face tree and neighbours.
    fn split(
        &mut self,
        state: &mut State,
        f: usize,
        layer: &Layer,
        step: usize,
        rotation: DAffine3,
        scratch: &mut (Vec<DVec2>, Vec<DVec2>),
    ) -> usize {
        let neighbours = std::mem::take(&mut state.faces[f].neighbours);
        let face = state.faces[f].clone();
        let inverse = face.transform.inverse();
        let from_plane = |p: DVec2| layer.origin + layer.u * p.x + layer.v * p.y;
        let a = inverse
            .transform_point3(from_plane(layer.line.point))
            .truncate();
        let b = inverse
            .transform_point3(from_plane(layer.line.point + layer.line.dir))
            .truncate();
        let sheet_line = Line2::through(a, b, 0.0).unwrap_or(layer.line);
        let probe = from_plane(layer.line.point + layer.line.dir.perp() * layer.side);
        let sheet_side = sheet_line
            .side(inverse.transform_point3(probe).truncate())
            .signum();
        let polygon = self.polygon(&face);
        let (left, right) = (&mut scratch.0, &mut scratch.1);
        left.clear();
        right.clear();
        split_into(polygon, &sheet_line, self.tol, left, right);
        let (fixed, moved) = if sheet_side > 0.0 {
            (ccw(right), ccw(left))
        } else {
            (ccw(left), ccw(right))
        };
        let parent = Some(face.cell);
        let fixed_cell = self.new_cell(FaceCell {
            parent,
            polygon: fixed,
            step,
        });
        let moved_cell = self.new_cell(FaceCell {
            parent,
            polygon: moved,
            step,
        });
        let g = state.faces.len();
        state.faces.push(LiveFace {
            cell: moved_cell,
            transform: rotation * face.transform,
            neighbours: Neighbours::new(),
        });
        state.faces[f].cell = fixed_cell;
        // A neighbour keeps, with each child, the part of its shared edge on that child's side.
        for &n in neighbours.iter() {
            let k = n.face;
            state.faces[k].neighbours.retain(|m| m.face != f);
            let Segment { a: p, b: q } = n.edge;
            let (sp, sq) = (
                sheet_side * sheet_line.side(p),
                sheet_side * sheet_line.side(q),
            );
            for (child, sign) in [(f, -1.0), (g, 1.0)] {
                if let Some(edge) = segment_part(p, q, sign * sp, sign * sq, self.tol) {
                    state.faces[child]
                        .neighbours
                        .push(Neighbour { face: k, edge });
                    state.faces[k]
                        .neighbours
                        .push(Neighbour { face: child, edge });
                }
            }
        }
        let mut cut = self.cells[fixed_cell.index()]
            .polygon
            .iter()
            .copied()
            .filter(|&p| sheet_line.side(p).abs() <= self.tol);
        if let (Some(p), Some(q)) = (cut.next(), cut.next()) {
            state.faces[f].neighbours.push(Neighbour {
                face: g,
                edge: Segment::new(p, q),
            });
            state.faces[g].neighbours.push(Neighbour {
                face: f,
                edge: Segment::new(p, q),
            });
        }
        g
    }

    fn new_cell(&mut self, cell: FaceCell) -> CellId {
        self.cells.push(cell);
        CellId((self.cells.len() - 1) as u32)
    }
}

/// The part of segment `p`–`q` where the signed distances (`sp`, `sq` at the ends, linear
/// along it) are not below −`tol`, if longer than `tol`.
fn segment_part(p: DVec2, q: DVec2, sp: f64, sq: f64, tol: f64) -> Option<Segment> {
    if sp < -tol && sq < -tol {
        return None;
    }
    let cross = |s: f64, t: f64, a: DVec2, b: DVec2| {
        if s >= -tol {
            a
        } else {
            a + (b - a) * (s / (s - t))
        }
    };
    let (a, b) = (cross(sp, sq, p, q), cross(sq, sp, q, p));
    (a.distance(b) > tol).then_some(Segment::new(a, b))
}

/// The polygon counter-clockwise, as a face-tree ring.
fn ccw(poly: &[DVec2]) -> Ring {
    if double_area(poly) < 0.0 {
        poly.iter().rev().copied().collect()
    } else {
        Ring::from(poly)
    }
}

/// Moves the carried faces (faces of other groups) by `rotation` and takes them out of their
/// groups' stacks: returns, per group that lost faces, its plane (origin, normal) before the
/// fold and the carried faces in its stack order. Emptied groups stay, empty, until the end.
fn carry(
    state: &mut State,
    carried: &[usize],
    rotation: DAffine3,
) -> Vec<((DVec3, DVec3), Vec<usize>)> {
    if carried.is_empty() {
        return Vec::new();
    }
    let mut is_carried = vec![false; state.faces.len()];
    for &c in carried {
        is_carried[c] = true;
        let t = state.faces[c].transform;
        state.faces[c].transform = rotation * t;
    }
    let mut out = Vec::new();
    for group in &mut state.groups {
        if !group.stack.iter().any(|&f| is_carried[f]) {
            continue;
        }
        let (block, kept): (Vec<usize>, Vec<usize>) =
            group.stack.iter().partition(|&&f| is_carried[f]);
        if !block.is_empty() {
            group.stack = kept;
            out.push(((group.origin, group.normal), block));
        }
    }
    out
}

/// The turn of the moving side by `angle` radians (positive towards the normal).
fn layer_hinge(layer: &Layer, angle: f64) -> Hinge {
    let point = layer.origin + layer.u * layer.line.point.x + layer.v * layer.line.point.y;
    let dir = layer.u * layer.line.dir.x + layer.v * layer.line.dir.y;
    let outward = layer.normal.cross(dir) * layer.side;
    Hinge {
        point,
        axis: outward.cross(layer.normal),
        angle,
        outward,
    }
}

fn summary(turn: Turn, r: &FoldReport) -> String {
    let kind = match turn {
        Turn::Tuck => "tuck-in".to_string(),
        Turn::Angle(a) if a.abs() == 180.0 => {
            format!("bend ({})", if a > 0.0 { "valley" } else { "mountain" })
        }
        Turn::Angle(a) => format!("fold up by {a}°"),
    };
    format!("{kind}: {} faces moved, {} split", r.moved, r.split)
}
