//! Deciding what a frame's coordinates are: a flat crease pattern or a folded state.
//!
//! - All z absent or 0: 2D coordinates.
//! - 3D but coplanar within 1e-7 of the extent: rotated onto xy ([`super::plane`]), with a
//!   warning.
//! - 3D and not coplanar: a folded state; it needs faces, which are unfolded
//!   ([`super::unfold`](mod@super::unfold)) into the crease pattern.
//! - Flat (2D or rotated) with `frame_classes` containing `foldedForm`, faces, and faces of
//!   both orientations (a flat-folded form: folding flips faces over): a folded state too,
//!   unfolded the same way. A `foldedForm` frame whose faces all face one way is read as the
//!   crease pattern it is (Origami Simulator labels its flat patterns `foldedForm`).
//!
//! Rotated 3D patterns whose faces all run clockwise get them reversed (see
//! [`reverse_clockwise_faces`]); 2D input keeps its faces exactly as written.
//!
//! When a frame is read as a crease pattern although it claimed `foldedForm` or `3D`, those
//! words in `frame_classes`/`frame_attributes` are replaced by `creasePattern`/`2D`, so the
//! written file describes what it holds. `frame_classes: ["creasePattern"]` alone is dropped:
//! the writer adds it by default.

use glam::{DVec2, DVec3};
use serde_json::{Map, Value};

use super::plane::fit_plane;
use super::raw::RawFrame;
use super::unfold::unfold;
use super::values::Key;
use crate::formats::{Finding, FindingKind, Imported, ParseError};
use crate::geom::polygon::signed_area;
use crate::geom::tolerance::RELATIVE;
use crate::pattern::{CreasePattern, Face, FoldedState, Metadata};

/// Relative distance from the best plane below which 3D coordinates count as flat.
const COPLANAR_TOLERANCE: f64 = 1e-7;

/// The pattern (and folded state) a frame describes; `meta` gets only the frame's extras and
/// derived keys.
pub(super) fn build(mut raw: RawFrame, frame: usize) -> Result<Imported, ParseError> {
    let mut warnings = Vec::new();
    if raw.edges_from_faces {
        warnings.push(FindingKind::EdgesFromFaces.warning(format!(
            "no edges_vertices: took the {} edges from the faces (B where one face, U where more)",
            raw.edges.len()
        )));
    }
    let flat: Option<Vec<DVec2>> = if !raw.is_3d {
        Some(raw.coords.iter().map(|p| p.truncate()).collect())
    } else if let Some(plane) = fit_plane(&raw.coords, COPLANAR_TOLERANCE) {
        warnings.push(FindingKind::PlaneRotated.warning(format!(
            "the 3D coordinates lie in one plane (normal {:.3}, {:.3}, {:.3}); rotated it onto the xy plane",
            plane.normal.x, plane.normal.y, plane.normal.z
        )));
        Some(raw.coords.iter().map(|&p| plane.project(p)).collect())
    } else {
        None
    };
    let flat_folded = match (&flat, &raw.faces) {
        (Some(pts), Some(faces)) => raw.folded_class && faces_flipped(pts, faces),
        _ => false,
    };
    match flat {
        Some(pts) if !flat_folded => {
            if raw.folded_class {
                let why = match raw.faces {
                    Some(_) => "the faces do not overlap",
                    None => "it has no faces to unfold",
                };
                warnings.push(FindingKind::NotFolded.warning(format!(
                    "frame_classes says foldedForm, but {why}: read as a crease pattern"
                )));
            }
            if raw.is_3d && reverse_clockwise_faces(&pts, &mut raw) {
                warnings.push(FindingKind::FacesReversed.warning(
                    "the faces ran clockwise in the rotated plane; reversed them (and faceOrders)",
                ));
            }
            Ok(as_pattern(raw, pts, warnings))
        }
        _ => as_folded(raw, warnings, frame),
    }
}

/// Signed areas of the faces' outer cycles, and the largest magnitude.
fn face_areas(pts: &[DVec2], faces: &[Face]) -> (Vec<f64>, f64) {
    let areas: Vec<f64> = faces
        .iter()
        .map(|f| signed_area(f.outer.iter().filter_map(|v| pts.get(v.index()).copied())))
        .collect();
    let largest = areas.iter().fold(0.0f64, |m, a| m.max(a.abs()));
    (areas, largest)
}

/// When every face (of non-negligible area) runs clockwise, reverses all face cycles and
/// flips the `faceOrders` signs (the normals flip), so the faces run counter-clockwise as
/// the model expects. Used for rotated 3D input: Origami Simulator traces faces in its
/// y-down x–z frame, so they run clockwise once the drawing is turned y-up.
fn reverse_clockwise_faces(pts: &[DVec2], raw: &mut RawFrame) -> bool {
    let Some(faces) = raw.faces.as_mut() else {
        return false;
    };
    let (areas, largest) = face_areas(pts, faces);
    let eps = RELATIVE * largest;
    if largest == 0.0 || areas.iter().any(|&a| a > eps) {
        return false;
    }
    for f in faces.iter_mut() {
        f.outer.reverse();
        f.holes.iter_mut().for_each(|h| h.reverse());
    }
    for order in &mut raw.face_orders {
        order.2 = -order.2;
    }
    true
}

/// Whether the faces (with at least one of non-negligible area) have both orientations.
fn faces_flipped(pts: &[DVec2], faces: &[Face]) -> bool {
    let (areas, largest) = face_areas(pts, faces);
    let eps = RELATIVE * largest;
    areas.iter().any(|&a| a > eps) && areas.iter().any(|&a| a < -eps)
}

/// A crease pattern with the given flat positions.
fn as_pattern(raw: RawFrame, vertices: Vec<DVec2>, findings: Vec<Finding>) -> Imported {
    let renamed = raw.folded_class || raw.is_3d;
    let mut extra = raw.extra;
    normalize_classes(&mut extra, renamed);
    let pattern = CreasePattern {
        vertices,
        edges: raw.edges,
        faces: raw.faces,
        face_orders: raw.face_orders,
        units: raw.units,
        meta: Metadata {
            frame_extra: extra,
            derived_keys: raw.derived,
            ..Metadata::default()
        },
    };
    Imported {
        pattern,
        folded: None,
        findings,
    }
}

/// A folded state and its unfolding.
fn as_folded(
    raw: RawFrame,
    mut warnings: Vec<Finding>,
    frame: usize,
) -> Result<Imported, ParseError> {
    let faces = match &raw.faces {
        Some(f) if !f.is_empty() => f,
        _ => {
            return Err(Key::new(frame, "faces_vertices").err(
                &[],
                "missing: the vertices are not in one plane, so this is a folded state, and \
                 unfolding it into a crease pattern needs its faces",
            ));
        }
    };
    let unfolding = unfold(&raw.coords, faces);
    warnings.push(FindingKind::Unfolded.warning(format!(
        "the frame is a folded state: unfolded its {} faces into the crease pattern",
        faces.len()
    )));
    warnings.extend(unfolding.warnings);
    let positions: Vec<DVec3> = raw.coords.clone();
    let folded = FoldedState {
        positions,
        edges: raw.edges.clone(),
        faces: raw.faces.clone(),
        face_orders: raw.face_orders.clone(),
    };
    let mut imported = as_pattern(raw, unfolding.vertices, warnings);
    imported.folded = Some(folded);
    Ok(imported)
}

/// Replaces `foldedForm`/`3D` by `creasePattern`/`2D` when `renamed`, and drops
/// `frame_classes` when it says only `creasePattern`.
fn normalize_classes(extra: &mut Map<String, Value>, renamed: bool) {
    if renamed {
        rename_word(extra, "frame_classes", "foldedForm", "creasePattern");
        rename_word(extra, "frame_attributes", "3D", "2D");
    }
    if extra.get("frame_classes") == Some(&Value::from(vec!["creasePattern"])) {
        extra.shift_remove("frame_classes");
    }
}

/// Replaces the string `from` by `to` in the array at `key` (once: duplicates dropped).
fn rename_word(extra: &mut Map<String, Value>, key: &str, from: &str, to: &str) {
    let Some(Value::Array(list)) = extra.get_mut(key) else {
        return;
    };
    if !list.iter().any(|v| v == from) {
        return;
    }
    let has_to = list.iter().any(|v| v == to);
    let mut out = Vec::with_capacity(list.len());
    for v in list.drain(..) {
        if v == from {
            if !has_to && !out.iter().any(|o: &Value| o == to) {
                out.push(Value::from(to));
            }
        } else {
            out.push(v);
        }
    }
    *list = out;
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn renames_folded_words() {
        let mut m = json!({"frame_classes": ["foldedForm"], "frame_attributes": ["3D", "x:y"]})
            .as_object()
            .cloned()
            .unwrap_or_default();
        normalize_classes(&mut m, true);
        assert!(!m.contains_key("frame_classes"));
        assert_eq!(m["frame_attributes"], json!(["2D", "x:y"]));
    }
}
