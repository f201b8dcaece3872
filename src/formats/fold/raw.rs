//! One frame's keys parsed into typed arrays, checked element by element.
//!
//! Coordinates come out as 3D points in the model's unit (millimetres, or units for a
//! unitless frame); whether they are a crease pattern or a folded state is decided later
//! ([`super::shape`]). Every per-element array must match the length of the elements it
//! describes, every id must exist, every number must be finite and in its range.

use glam::DVec3;
use serde_json::{Map, Value};

use super::values::{Key, array, describe, index, number, same_length, strings};
use super::{DERIVED_KEYS, HOLES_KEY, UNKNOWN_ANGLE_KEY, units};
use crate::formats::ParseError;
use crate::pattern::{Assignment, Edge, Face, FaceId, MAX_COORDINATE, Units, VertexId};

const COORDS: &str = "vertices_coords";
const EDGES: &str = "edges_vertices";
const ASSIGNMENT: &str = "edges_assignment";
const ANGLE: &str = "edges_foldAngle";
const FACES: &str = "faces_vertices";
const ORDERS: &str = "faceOrders";

/// Frame keys mapped onto the model (everything else is kept verbatim).
const CONSUMED: [&str; 9] = [
    COORDS,
    EDGES,
    ASSIGNMENT,
    ANGLE,
    FACES,
    ORDERS,
    HOLES_KEY,
    UNKNOWN_ANGLE_KEY,
    units::UNIT_KEY,
];

/// Frame-level descriptive keys taken into the model's metadata.
pub(super) const FRAME_TEXT_KEYS: [&str; 3] = ["frame_title", "frame_author", "frame_description"];

/// A frame's content in model types.
#[derive(Clone, Debug, Default)]
pub(super) struct RawFrame {
    /// Vertex positions in the model's unit; z = 0 where the file gave two coordinates.
    pub coords: Vec<DVec3>,
    /// Some vertex has a non-zero z.
    pub is_3d: bool,
    /// The frame's units.
    pub units: Units,
    /// Edges with assignments and fold angles.
    pub edges: Vec<Edge>,
    /// The edges were derived from the faces (the frame had no `edges_vertices`).
    pub edges_from_faces: bool,
    /// Faces, when the frame has `faces_vertices`.
    pub faces: Option<Vec<Face>>,
    /// `faceOrders`.
    pub face_orders: Vec<(FaceId, FaceId, i8)>,
    /// `frame_classes` contains `foldedForm`.
    pub folded_class: bool,
    /// Derived keys present, in [`DERIVED_KEYS`] order.
    pub derived: Vec<String>,
    /// Keys not interpreted, in file order (includes `frame_title` etc.; the reader takes
    /// those out).
    pub extra: Map<String, Value>,
}

/// Parses the (resolved) properties of frame `frame`.
pub(super) fn parse_frame(map: &Map<String, Value>, frame: usize) -> Result<RawFrame, ParseError> {
    let (units, factor) = units::parse_unit(map.get(units::UNIT_KEY), frame)?;
    let coords = match map.get(COORDS) {
        Some(v) => parse_coords(v, factor, Key::new(frame, COORDS))?,
        None => Vec::new(),
    };
    let faces = parse_all_faces(map, coords.len(), frame)?;
    let (edges, edges_from_faces) = parse_all_edges(map, coords.len(), faces.as_deref(), frame)?;
    let face_count = faces.as_ref().map_or(0, Vec::len);
    let face_orders = match map.get(ORDERS) {
        Some(v) => parse_orders(v, face_count, Key::new(frame, ORDERS))?,
        None => Vec::new(),
    };
    let derived = check_derived(map, [coords.len(), edges.len(), face_count], frame)?;
    let extra = map
        .iter()
        .filter(|(k, _)| !CONSUMED.contains(&k.as_str()) && !DERIVED_KEYS.contains(&k.as_str()))
        .map(|(k, v)| (k.clone(), v.clone()))
        .collect();
    Ok(RawFrame {
        is_3d: coords.iter().any(|p| p.z != 0.0),
        coords,
        units,
        edges,
        edges_from_faces,
        faces,
        face_orders,
        folded_class: strings(map.get("frame_classes")).contains(&"foldedForm"),
        derived,
        extra,
    })
}

/// `faces_vertices` with the holes of [`HOLES_KEY`].
fn parse_all_faces(
    map: &Map<String, Value>,
    n: usize,
    frame: usize,
) -> Result<Option<Vec<Face>>, ParseError> {
    let Some(v) = map.get(FACES) else {
        return Ok(None);
    };
    let mut faces = parse_faces(v, n, Key::new(frame, FACES))?;
    if let Some(h) = map.get(HOLES_KEY) {
        parse_holes(h, n, &mut faces, Key::new(frame, HOLES_KEY))?;
    }
    Ok(Some(faces))
}

/// `edges_vertices` (or the faces' edges when it is missing) with assignments and fold
/// angles; the flag tells whether the edges came from the faces.
fn parse_all_edges(
    map: &Map<String, Value>,
    n: usize,
    faces: Option<&[Face]>,
    frame: usize,
) -> Result<(Vec<Edge>, bool), ParseError> {
    let (mut edges, from_faces) = match (map.get(EDGES), faces) {
        (Some(v), _) => (parse_edges(v, n, Key::new(frame, EDGES))?, false),
        (None, faces) => {
            refuse_orphans(map, frame)?;
            let derived = faces.map(edges_of_faces).unwrap_or_default();
            let from_faces = !derived.is_empty();
            (derived, from_faces)
        }
    };
    if let Some(v) = map.get(ASSIGNMENT) {
        parse_assignments(v, &mut edges, Key::new(frame, ASSIGNMENT))?;
    }
    if let Some(v) = map.get(ANGLE) {
        parse_angles(v, &mut edges, Key::new(frame, ANGLE))?;
    }
    if let Some(v) = map.get(UNKNOWN_ANGLE_KEY) {
        parse_unknown_angles(v, &mut edges, Key::new(frame, UNKNOWN_ANGLE_KEY))?;
    }
    Ok((edges, from_faces))
}

/// `vertices_coords`: 2 or 3 finite numbers per vertex, scaled by `factor`, within
/// [`MAX_COORDINATE`].
fn parse_coords(v: &Value, factor: f64, key: Key) -> Result<Vec<DVec3>, ParseError> {
    let list = array(v, key, &[])?;
    let mut out = Vec::with_capacity(list.len());
    for (i, c) in list.iter().enumerate() {
        let comps = array(c, key, &[i])?;
        if !(2..=3).contains(&comps.len()) {
            return Err(key.err(
                &[i],
                format!("a vertex needs 2 or 3 coordinates, found {}", comps.len()),
            ));
        }
        let mut xyz = [0.0; 3];
        for (j, x) in comps.iter().enumerate() {
            let value = number(x, key, &[i, j])? * factor;
            if !value.is_finite() || value.abs() > MAX_COORDINATE {
                return Err(key.err(
                    &[i, j],
                    format!("coordinate {value:e} is beyond the limit of ±{MAX_COORDINATE:e}"),
                ));
            }
            xyz[j] = value;
        }
        out.push(DVec3::from_array(xyz));
    }
    Ok(out)
}

/// `edges_vertices`: two distinct existing vertices per edge; assignment `U`, no angle.
fn parse_edges(v: &Value, n: usize, key: Key) -> Result<Vec<Edge>, ParseError> {
    let list = array(v, key, &[])?;
    let mut out = Vec::with_capacity(list.len());
    for (i, e) in list.iter().enumerate() {
        let ends = array(e, key, &[i])?;
        if ends.len() != 2 {
            return Err(key.err(
                &[i],
                format!("an edge joins exactly 2 vertices, found {}", ends.len()),
            ));
        }
        let a = index(&ends[0], n, "vertex", key, &[i, 0])?;
        let b = index(&ends[1], n, "vertex", key, &[i, 1])?;
        if a == b {
            return Err(key.err(&[i], format!("the edge joins vertex {a} to itself")));
        }
        out.push(Edge::new(VertexId(a), VertexId(b), Assignment::Unassigned));
    }
    Ok(out)
}

/// Edges of the faces' cycles, each vertex pair once: `B` with one face, `U` with more.
fn edges_of_faces(faces: &[Face]) -> Vec<Edge> {
    let mut seen: std::collections::HashMap<(VertexId, VertexId), usize> = Default::default();
    let mut edges: Vec<Edge> = Vec::new();
    let mut uses: Vec<usize> = Vec::new();
    for f in faces {
        for cycle in std::iter::once(&f.outer).chain(&f.holes) {
            for (i, &a) in cycle.iter().enumerate() {
                let b = cycle[(i + 1) % cycle.len()];
                if a == b {
                    continue;
                }
                let slot = *seen.entry((a.min(b), a.max(b))).or_insert_with(|| {
                    edges.push(Edge::new(a, b, Assignment::Boundary));
                    uses.push(0);
                    edges.len() - 1
                });
                uses[slot] += 1;
            }
        }
    }
    for (e, &u) in edges.iter_mut().zip(&uses) {
        if u > 1 {
            e.assignment = Assignment::Unassigned;
        }
    }
    edges
}

/// Edge properties without `edges_vertices` cannot be matched to edges.
fn refuse_orphans(map: &Map<String, Value>, frame: usize) -> Result<(), ParseError> {
    match [ASSIGNMENT, ANGLE].iter().find(|k| map.contains_key(**k)) {
        Some(k) => Err(Key::new(frame, k).err(
            &[],
            "present without \"edges_vertices\": the values cannot be matched to edges",
        )),
        None => Ok(()),
    }
}

/// `edges_assignment`: one FOLD letter per edge (either case).
fn parse_assignments(v: &Value, edges: &mut [Edge], key: Key) -> Result<(), ParseError> {
    let list = array(v, key, &[])?;
    same_length(list.len(), edges.len(), key, EDGES)?;
    for (i, (a, e)) in list.iter().zip(edges.iter_mut()).enumerate() {
        let letter = a
            .as_str()
            .ok_or_else(|| key.err(&[i], format!("expected a letter, found {}", describe(a))))?;
        e.assignment = letter
            .parse()
            .map_err(|err| key.err(&[i], format!("{err}")))?;
    }
    Ok(())
}

/// `edges_foldAngle`: degrees in [−180, 180] or `null` (unknown) per edge.
fn parse_angles(v: &Value, edges: &mut [Edge], key: Key) -> Result<(), ParseError> {
    let list = array(v, key, &[])?;
    same_length(list.len(), edges.len(), key, EDGES)?;
    for (i, (a, e)) in list.iter().zip(edges.iter_mut()).enumerate() {
        if a.is_null() {
            continue;
        }
        let deg = number(a, key, &[i])?;
        if !(-180.0..=180.0).contains(&deg) {
            return Err(key.err(
                &[i],
                format!("fold angle {deg} is outside [-180, 180] degrees"),
            ));
        }
        e.fold_angle = Some(deg);
    }
    Ok(())
}

/// [`UNKNOWN_ANGLE_KEY`]: edge ids whose `edges_foldAngle` entry is a placeholder.
fn parse_unknown_angles(v: &Value, edges: &mut [Edge], key: Key) -> Result<(), ParseError> {
    for (i, id) in array(v, key, &[])?.iter().enumerate() {
        let e = index(id, edges.len(), "edge", key, &[i])?;
        if let Some(edge) = edges.get_mut(e as usize) {
            edge.fold_angle = None;
        }
    }
    Ok(())
}

/// One cycle of vertex ids, at least `min` long.
fn parse_cycle(
    v: &Value,
    n: usize,
    min: usize,
    key: Key,
    path: &[usize],
) -> Result<Vec<VertexId>, ParseError> {
    let list = array(v, key, path)?;
    if list.len() < min {
        return Err(key.err(
            path,
            format!("needs at least {min} vertices, found {}", list.len()),
        ));
    }
    let mut sub = path.to_vec();
    sub.push(0);
    let last = sub.len() - 1;
    let mut out = Vec::with_capacity(list.len());
    for (j, x) in list.iter().enumerate() {
        sub[last] = j;
        out.push(VertexId(index(x, n, "vertex", key, &sub)?));
    }
    // A vertex repeated next to itself is a zero-length side; too few distinct vertices
    // leave no area (`[0, 0, 0]`).
    if let Some(j) = (0..out.len()).find(|&j| out[j] == out[(j + 1) % out.len()]) {
        return Err(key.err(
            path,
            format!(
                "vertex {} follows itself (at positions {j} and {}): a degenerate cycle",
                out[j].0,
                (j + 1) % out.len()
            ),
        ));
    }
    let mut distinct: Vec<VertexId> = out.clone();
    distinct.sort_unstable();
    distinct.dedup();
    if distinct.len() < min {
        return Err(key.err(
            path,
            format!(
                "needs at least {min} distinct vertices, found {}: a degenerate cycle",
                distinct.len()
            ),
        ));
    }
    Ok(out)
}

/// `faces_vertices`: a cycle of at least 3 existing vertices per face.
fn parse_faces(v: &Value, n: usize, key: Key) -> Result<Vec<Face>, ParseError> {
    let list = array(v, key, &[])?;
    list.iter()
        .enumerate()
        .map(|(i, f)| parse_cycle(f, n, 3, key, &[i]).map(Face::simple))
        .collect()
}

/// [`HOLES_KEY`]: per face, a list of hole cycles of at least 2 vertices.
fn parse_holes(v: &Value, n: usize, faces: &mut [Face], key: Key) -> Result<(), ParseError> {
    let list = array(v, key, &[])?;
    same_length(list.len(), faces.len(), key, FACES)?;
    for (i, (holes, face)) in list.iter().zip(faces.iter_mut()).enumerate() {
        let holes = array(holes, key, &[i])?;
        for (j, h) in holes.iter().enumerate() {
            face.holes.push(parse_cycle(h, n, 2, key, &[i, j])?);
        }
    }
    Ok(())
}

/// `faceOrders`: triples `[f, g, s]` of existing faces and s ∈ {−1, 0, 1}.
fn parse_orders(
    v: &Value,
    face_count: usize,
    key: Key,
) -> Result<Vec<(FaceId, FaceId, i8)>, ParseError> {
    let list = array(v, key, &[])?;
    let mut out = Vec::with_capacity(list.len());
    for (i, t) in list.iter().enumerate() {
        let t = array(t, key, &[i])?;
        if t.len() != 3 {
            return Err(key.err(
                &[i],
                format!("expected [f, g, s], found {} entries", t.len()),
            ));
        }
        let f = index(&t[0], face_count, "face", key, &[i, 0])?;
        let g = index(&t[1], face_count, "face", key, &[i, 1])?;
        let s = match t[2].as_i64() {
            Some(s @ -1..=1) => s as i8,
            _ => {
                return Err(key.err(
                    &[i, 2],
                    format!("expected -1, 0 or 1, found {}", describe(&t[2])),
                ));
            }
        };
        out.push((FaceId(f), FaceId(g), s));
    }
    Ok(out)
}

/// The derived keys present; each must be an array as long as its elements.
fn check_derived(
    map: &Map<String, Value>,
    [nv, ne, nf]: [usize; 3],
    frame: usize,
) -> Result<Vec<String>, ParseError> {
    let mut present = Vec::new();
    for name in DERIVED_KEYS {
        let Some(v) = map.get(name) else { continue };
        let key = Key::new(frame, name);
        let (expected, owner) = match name.split('_').next() {
            Some("vertices") => (nv, COORDS),
            Some("edges") => (ne, EDGES),
            _ => (nf, FACES),
        };
        same_length(array(v, key, &[])?.len(), expected, key, owner)?;
        present.push(name.to_string());
    }
    Ok(present)
}
