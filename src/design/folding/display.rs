//! Display copies of the steps, for previews only: every face gets its own vertices, and the
//! layers of a stack are spread apart along the group normal so that all of them can be seen.

use glam::DVec2;

use super::crease::fold_angle;
use super::geometry::Line2;
use super::state::{Folding, State, contact};
use crate::geom::Segment;
use crate::geom::tolerance::ANGLE_DEG;
use crate::pattern::{Assignment, Edge, Face, FoldedState, VertexId};

/// One folded state per step (0 = the flat sheet), layers `gap_mm` apart (centred on their
/// plane). The states are for drawing: their vertices are not shared between faces.
pub fn display_states(folding: &Folding, gap_mm: f64) -> Vec<FoldedState> {
    folding
        .steps()
        .iter()
        .map(|s| display_state(folding, &s.state, gap_mm))
        .collect()
}

/// One caption per step, for pictures: `Step N: what it did` (the operation, as the step's
/// summary names it: "bend (valley)", "tuck-in", "fold up by 90°"; step 0 is the flat sheet),
/// then the script's name for the step on a second line when it has one.
pub fn step_captions(folding: &Folding) -> Vec<String> {
    folding
        .steps()
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let what = s.summary.split(':').next().unwrap_or("").trim();
            match &s.name {
                Some(name) if !name.trim().is_empty() => format!("Step {i}: {what}\n{name}"),
                _ => format!("Step {i}: {what}"),
            }
        })
        .collect()
}

fn display_state(folding: &Folding, state: &State, gap_mm: f64) -> FoldedState {
    let layers = state.layers();
    let mut out = FoldedState {
        faces: Some(Vec::new()),
        ..FoldedState::default()
    };
    for (f, face) in state.faces.iter().enumerate() {
        let (g, pos) = layers[f];
        let group = &state.groups[g];
        let lift = group.normal * gap_mm * (pos as f64 - (group.stack.len() as f64 - 1.0) / 2.0);
        let polygon = folding.polygon(face);
        let first = out.positions.len();
        out.positions.extend(
            polygon
                .iter()
                .map(|p| face.transform.transform_point3(p.extend(0.0)) + lift),
        );
        let n = polygon.len();
        let ids: Vec<VertexId> = (0..n).map(|i| VertexId((first + i) as u32)).collect();
        for i in 0..n {
            let a = edge_kind(folding, state, f, polygon[i], polygon[(i + 1) % n]);
            out.edges.push(Edge::new(ids[i], ids[(i + 1) % n], a));
        }
        if let Some(faces) = out.faces.as_mut() {
            faces.push(Face::simple(ids));
        }
    }
    out
}

/// Boundary for an edge on no other face, otherwise the crease's current kind.
fn edge_kind(folding: &Folding, state: &State, f: usize, a: DVec2, b: DVec2) -> Assignment {
    let tol = folding.tolerance();
    let Some(edge) = Line2::through(a, b, tol) else {
        return Assignment::Boundary;
    };
    for k in state.faces[f].neighbours.iter().map(|n| n.face) {
        let Some(Segment { a: p, b: q }) = contact(&[a, b], folding.polygon(&state.faces[k]), tol)
        else {
            continue;
        };
        if edge.side(p).abs() > tol || p.distance(q) <= tol {
            continue;
        }
        let angle = fold_angle(state, f, k, b - a);
        return if angle.abs() < ANGLE_DEG {
            Assignment::Flat
        } else if angle > 0.0 {
            Assignment::Valley
        } else {
            Assignment::Mountain
        };
    }
    Assignment::Boundary
}

/// The length of the sheet's longer bounding-box side, millimetres.
pub fn sheet_size(folding: &Folding) -> f64 {
    let (lo, hi) = folding.sheet().iter().fold(
        (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    );
    (hi - lo).max_element()
}

/// One face of a step as a view from above draws it.
#[derive(Clone, Debug, PartialEq)]
pub struct TopFace {
    /// The face's corners in space, millimetres (where the paper is, not spread).
    pub corners: Vec<glam::DVec3>,
    /// How far the face is drawn off its plane to show the layer order: the layer's place in
    /// its stack from the middle, in layers, counted towards the eye (positive above).
    pub layer: f64,
    /// The sheet's front (its +z side when flat) faces the eye.
    pub front_up: bool,
}

/// The faces of step `step` (0 = the flat sheet) in the order a view from +z paints them,
/// bottom first: by the height of their centres once each layer is lifted `gap_mm` per
/// place in its stack (so the stack order decides between coplanar layers).
///
/// # Panics
/// When `step` is beyond the last step.
pub fn faces_from_above(folding: &Folding, step: usize, gap_mm: f64) -> Vec<TopFace> {
    let state = &folding.steps()[step].state;
    let layers = state.layers();
    let mut faces: Vec<(f64, TopFace)> = state
        .faces
        .iter()
        .enumerate()
        .map(|(f, face)| {
            let (g, pos) = layers[f];
            let group = &state.groups[g];
            let place = pos as f64 - (group.stack.len() as f64 - 1.0) / 2.0;
            let up = if group.normal.z >= 0.0 { 1.0 } else { -1.0 };
            let corners = folding.corners(face);
            let centre = corners.iter().sum::<glam::DVec3>() / corners.len().max(1) as f64;
            let height = centre.z + group.normal.z * gap_mm * place;
            let top = TopFace {
                corners,
                layer: place * up,
                front_up: state.face_normal(f).z > 0.0,
            };
            (height, top)
        })
        .collect();
    faces.sort_by(|a, b| a.0.total_cmp(&b.0));
    faces.into_iter().map(|(_, f)| f).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::design::folding::script::{parse_script, run_script};

    #[test]
    fn the_flap_folded_over_is_painted_last_and_shows_its_back() {
        let script = parse_script(
            "[sheet]\nsquare = 100\n[[step]]\nbend = { line = [[0, 50], [100, 50]], moving = [50, 90] }\n",
        )
        .unwrap();
        let f = run_script(&script).unwrap();
        let flat = faces_from_above(&f, 0, 0.5);
        assert_eq!(flat.len(), 1);
        assert!(flat[0].front_up);
        let folded = faces_from_above(&f, 1, 0.5);
        assert_eq!(folded.len(), 2);
        // Bottom: the half that stayed, front up; top: the half turned over onto it.
        assert!(folded[0].front_up && !folded[1].front_up);
        assert!(folded[0].layer < folded[1].layer);
        for face in &folded {
            assert!(
                face.corners
                    .iter()
                    .all(|c| c.y <= 50.0 + 1e-9 && c.z.abs() < 1e-9)
            );
        }
    }
}
