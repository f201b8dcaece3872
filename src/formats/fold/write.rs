//! Writing a pattern (and its folded state) as FOLD 1.2.

use serde_json::{Map, Value};

use super::frames::FRAMES_KEY;
use super::units::unit_name;
use super::values::{num, strings};
use super::{
    CREATOR, DERIVED_KEYS, HOLES_KEY, SOURCE_CREATOR_KEY, SPEC_VERSION, UNKNOWN_ANGLE_KEY, derived,
    json,
};
use crate::pattern::vertex_fan::VertexFans;
use crate::pattern::{CreasePattern, Edge, Face, FaceId, FoldedState, Metadata};

/// Renders a pattern as a FOLD 1.2 file (see the [module docs](super) for the layout).
///
/// With a folded state, the pattern is the key frame and the folded state a `file_frames`
/// entry `{frame_classes: ["foldedForm"], frame_parent: 0, frame_inherit: true,
/// vertices_coords: [[x, y, z], …]}`, plus the edge, face and `faceOrders` keys where they
/// differ from the pattern's. If the pattern's extras already hold a `file_frames`, the
/// folded frame replaces the first entry of that same shape (a folded state written earlier,
/// so that read → write round trips do not pile up copies) or is appended.
///
/// A pattern without faces gets them ([`super::faces::with_faces`]): traced when it is
/// planar, else planarised first (unless a folded state is written with it).
pub fn write_string(pattern: &CreasePattern, folded: Option<&FoldedState>) -> String {
    let pattern = &*super::faces::with_faces(pattern, folded.is_none());
    let mut root = Map::new();
    write_file_keys(&mut root, &pattern.meta);
    write_frame(&mut root, pattern);
    if let Some(f) = folded {
        add_folded_frame(&mut root, pattern, f);
    }
    json::to_text(&Value::Object(root))
}

/// Renders a pattern with a sequence of folded states as FOLD 1.2: the pattern is the key
/// frame and each state a `file_frames` entry shaped as by [`write_string`], in order (any
/// `file_frames` kept from an input are replaced).
pub fn write_string_frames(pattern: &CreasePattern, folded: &[FoldedState]) -> String {
    let pattern = &*super::faces::with_faces(pattern, false);
    let mut root = Map::new();
    write_file_keys(&mut root, &pattern.meta);
    write_frame(&mut root, pattern);
    let frames = folded
        .iter()
        .map(|f| Value::Object(folded_frame(pattern, f)))
        .collect();
    root.insert(FRAMES_KEY.into(), Value::Array(frames));
    json::to_text(&Value::Object(root))
}

/// Renders a folded state as a FOLD 1.2 file whose key frame is the folded form, the shape
/// in which Origami Simulator saves a simulation: `frame_classes: ["foldedForm"]`,
/// `frame_attributes: ["3D"]`, 3D `vertices_coords` (the pattern's length unit), the folded
/// state's edges and faces (written as by [`write_string`]'s folded frame, so edges keep the
/// pattern's assignments and fold angles unless the folded state has its own). `pattern`
/// gives the file's descriptive keys, its unit and, when the folded state shares its
/// topology, the derived keys. Nothing else rides along: no `file_frames`. A reader that
/// unfolds a folded form (foldcam's own) gets the crease pattern back.
pub fn write_folded_string(pattern: &CreasePattern, folded: &FoldedState) -> String {
    let pattern = &*super::faces::with_faces(pattern, false);
    let mut root = Map::new();
    write_file_keys(&mut root, &pattern.meta);
    root.remove(FRAMES_KEY);
    let mut key = Map::new();
    write_frame(&mut key, pattern);
    let same_topology = folded.positions.len() == pattern.vertices.len()
        && folded.edges == pattern.edges
        && folded.faces == pattern.faces;
    if !same_topology {
        for k in DERIVED_KEYS {
            key.remove(k);
        }
    }
    for (k, v) in folded_frame(pattern, folded) {
        if k != "frame_parent" && k != "frame_inherit" {
            key.insert(k, v);
        }
    }
    key.insert("frame_attributes".into(), Value::from(vec!["3D"]));
    key.remove(FRAMES_KEY);
    for (k, v) in key {
        root.insert(k, v);
    }
    json::to_text(&Value::Object(root))
}

/// The descriptive keys: file-level where the file level has room, frame-level otherwise.
const TEXT_KEYS: [(&str, &str); 3] = [
    ("file_title", "frame_title"),
    ("file_author", "frame_author"),
    ("file_description", "frame_description"),
];

fn texts(meta: &Metadata) -> [&Option<String>; 3] {
    [&meta.title, &meta.author, &meta.description]
}

/// `file_spec`, `file_creator`, titles and the file-level extras (in order).
fn write_file_keys(root: &mut Map<String, Value>, meta: &Metadata) {
    root.insert("file_spec".into(), Value::from(SPEC_VERSION));
    root.insert("file_creator".into(), Value::from(CREATOR));
    if let Some(c) = meta.creator.as_ref().filter(|c| c.as_str() != CREATOR) {
        root.insert(SOURCE_CREATOR_KEY.into(), Value::from(c.as_str()));
    }
    for ((file_key, _), text) in TEXT_KEYS.iter().zip(texts(meta)) {
        if let Some(t) = text
            .as_ref()
            .filter(|_| !meta.file_extra.contains_key(*file_key))
        {
            root.insert((*file_key).into(), Value::from(t.as_str()));
        }
    }
    for (k, v) in &meta.file_extra {
        if !root.contains_key(k) {
            root.insert(k.clone(), v.clone());
        }
    }
}

/// The key frame: metadata, classes, unit, geometry, derived keys, then the frame extras in
/// their order.
fn write_frame(root: &mut Map<String, Value>, cp: &CreasePattern) {
    let meta = &cp.meta;
    let mut frame = Map::new();
    for ((file_key, frame_key), text) in TEXT_KEYS.iter().zip(texts(meta)) {
        if let Some(t) = text
            .as_ref()
            .filter(|_| meta.file_extra.contains_key(*file_key))
        {
            frame.insert((*frame_key).into(), Value::from(t.as_str()));
        }
    }
    if !meta.frame_extra.contains_key("frame_classes") {
        frame.insert("frame_classes".into(), Value::from(vec!["creasePattern"]));
    }
    frame.insert("frame_unit".into(), Value::from(unit_name(cp.units)));
    let coords = cp
        .vertices
        .iter()
        .map(|p| Value::from(vec![num(p.x), num(p.y)]));
    frame.insert("vertices_coords".into(), Value::Array(coords.collect()));
    write_edges(&mut frame, &cp.edges);
    write_faces(&mut frame, cp.faces.as_deref(), &cp.face_orders);
    write_derived(&mut frame, cp);
    extend_new(&mut frame, meta.frame_extra.iter());
    extend_new(root, frame.iter());
}

/// Inserts the entries whose keys are not yet present.
fn extend_new<'a>(
    map: &mut Map<String, Value>,
    entries: impl Iterator<Item = (&'a String, &'a Value)>,
) {
    for (k, v) in entries {
        if !map.contains_key(k) {
            map.insert(k.clone(), v.clone());
        }
    }
}

/// `edges_vertices`, `edges_assignment`, and `edges_foldAngle` for every edge (with the
/// unknown-angle list): FOLD 1.2 gives every assignment an angle (valley positive, mountain
/// negative, zero for flat, unassigned and boundary), and Origami Simulator takes the target
/// angles from this key.
fn write_edges(frame: &mut Map<String, Value>, edges: &[Edge]) {
    let ends = edges
        .iter()
        .map(|e| Value::from(vec![e.vertices[0].0, e.vertices[1].0]));
    frame.insert("edges_vertices".into(), Value::Array(ends.collect()));
    let letters = edges
        .iter()
        .map(|e| Value::from(e.assignment.letter().to_string()));
    frame.insert("edges_assignment".into(), Value::Array(letters.collect()));
    if edges.is_empty() {
        return;
    }
    let angles = edges.iter().map(|e| {
        num(e
            .fold_angle
            .or(e.assignment.flat_folded_angle())
            .unwrap_or(0.0))
    });
    frame.insert("edges_foldAngle".into(), Value::Array(angles.collect()));
    let unknown: Vec<Value> = edges
        .iter()
        .enumerate()
        .filter(|(_, e)| e.fold_angle.is_none())
        .map(|(i, _)| Value::from(i))
        .collect();
    if !unknown.is_empty() {
        frame.insert(UNKNOWN_ANGLE_KEY.into(), Value::Array(unknown));
    }
}

/// `faces_vertices`, the holes key when any face has holes, and `faceOrders`.
fn write_faces(
    frame: &mut Map<String, Value>,
    faces: Option<&[Face]>,
    orders: &[(FaceId, FaceId, i8)],
) {
    let ids =
        |c: &Vec<crate::pattern::VertexId>| Value::from(c.iter().map(|v| v.0).collect::<Vec<_>>());
    if let Some(faces) = faces {
        frame.insert(
            "faces_vertices".into(),
            faces.iter().map(|f| ids(&f.outer)).collect(),
        );
        if faces.iter().any(|f| !f.holes.is_empty()) {
            let holes = faces
                .iter()
                .map(|f| Value::Array(f.holes.iter().map(ids).collect()));
            frame.insert(HOLES_KEY.into(), Value::Array(holes.collect()));
        }
    }
    if !orders.is_empty() {
        let triples = orders
            .iter()
            .map(|&(f, g, s)| Value::from(vec![i64::from(f.0), i64::from(g.0), i64::from(s)]));
        frame.insert("faceOrders".into(), Value::Array(triples.collect()));
    }
}

/// The derived keys the input had, recomputed from the model (none for a pattern that fails
/// [`CreasePattern::validate`]).
fn write_derived(frame: &mut Map<String, Value>, cp: &CreasePattern) {
    let wanted: Vec<&str> = DERIVED_KEYS
        .into_iter()
        .filter(|k| cp.meta.derived_keys.iter().any(|d| d == k))
        .collect();
    // Deriving indexes vertices by the edges' and faces' ids: only for a sound pattern.
    if wanted.is_empty() || cp.validate().is_err() {
        return;
    }
    let fans = VertexFans::new(cp);
    for key in wanted {
        if let Some(v) = derived::derived_value(cp, key, &fans) {
            frame.insert(key.into(), v);
        }
    }
}

/// Adds (or replaces) the folded state's frame in `file_frames`.
fn add_folded_frame(root: &mut Map<String, Value>, cp: &CreasePattern, folded: &FoldedState) {
    let frame = Value::Object(folded_frame(cp, folded));
    let frames = root
        .entry(FRAMES_KEY)
        .or_insert_with(|| Value::Array(Vec::new()));
    if !frames.is_array() {
        *frames = Value::Array(Vec::new());
    }
    if let Value::Array(list) = frames {
        match list.iter().position(is_our_folded_frame) {
            Some(i) => list[i] = frame,
            None => list.push(frame),
        }
    }
}

/// A frame of the shape [`write_string`] gives a folded state.
pub(super) fn is_our_folded_frame(v: &Value) -> bool {
    v.get("frame_parent") == Some(&Value::from(0))
        && v.get("frame_inherit") == Some(&Value::Bool(true))
        && strings(v.get("frame_classes")).contains(&"foldedForm")
}

/// The folded state as a frame inheriting from the key frame.
fn folded_frame(cp: &CreasePattern, folded: &FoldedState) -> Map<String, Value> {
    let mut frame = Map::new();
    frame.insert("frame_classes".into(), Value::from(vec!["foldedForm"]));
    frame.insert("frame_parent".into(), Value::from(0));
    frame.insert("frame_inherit".into(), Value::Bool(true));
    let coords = folded
        .positions
        .iter()
        .map(|p| Value::from(vec![num(p.x), num(p.y), num(p.z)]));
    frame.insert("vertices_coords".into(), Value::Array(coords.collect()));
    // Keys written here override the key frame's; those the writer leaves out when empty are
    // written empty so that the key frame's values are not inherited.
    if folded.edges != cp.edges {
        write_edges(&mut frame, &folded.edges);
        let nulls = Value::Array(vec![Value::Null; folded.edges.len()]);
        frame.entry("edges_foldAngle").or_insert(nulls);
        frame
            .entry(UNKNOWN_ANGLE_KEY)
            .or_insert(Value::Array(Vec::new()));
    }
    if folded.faces != cp.faces || folded.face_orders != cp.face_orders {
        write_faces(&mut frame, folded.faces.as_deref(), &folded.face_orders);
        frame
            .entry("faceOrders")
            .or_insert(Value::Array(Vec::new()));
        if let Some(faces) = folded
            .faces
            .as_ref()
            .filter(|_| !frame.contains_key(HOLES_KEY))
        {
            let none = Value::Array(vec![Value::Array(Vec::new()); faces.len()]);
            frame.insert(HOLES_KEY.into(), none);
        }
    }
    frame
}
