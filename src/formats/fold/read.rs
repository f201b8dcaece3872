//! Reading a FOLD file: JSON → frame → model, metadata, and the folded state of a crease
//! pattern stored as a later frame.

use serde_json::{Map, Value};

use super::frames::{FRAMES_KEY, check_frame_links, file_frames, is_file_level, resolve_frame};
use super::raw::{FRAME_TEXT_KEYS, parse_frame};
use super::values::strings;
use super::write::is_our_folded_frame;
use super::{CREATOR, SOURCE_CREATOR_KEY, shape};
use crate::formats::{FindingKind, Imported, ParseError};
use crate::pattern::{FoldedState, Metadata, PatternError};

/// Parses a FOLD file's text and returns its key frame as a crease pattern (and the folded
/// state, when the key frame is one or a later `foldedForm` frame folds it).
pub fn read_str(text: &str) -> Result<Imported, ParseError> {
    read_frame_str(text, 0)
}

/// Parses a FOLD file's text and returns frame `frame` (0 is the key frame, `i` is
/// `file_frames[i - 1]`) with inheritance resolved. For `frame > 0` the metadata keeps the
/// file-level keys except `file_frames` (whose parent ids refer to the original key frame).
pub fn read_frame_str(text: &str, frame: usize) -> Result<Imported, ParseError> {
    let root = parse_root(text)?;
    check_frame_links(&root)?;
    check_other_frames(&root, frame)?;
    let resolved = resolve_frame(&root, frame)?;
    let raw = parse_frame(&resolved, frame)?;
    let mut imported = shape::build(raw, frame)?;
    if frame > 0 {
        // The frame is read as a key frame: its links to other frames no longer apply.
        for key in ["frame_parent", "frame_inherit"] {
            imported.pattern.meta.frame_extra.shift_remove(key);
        }
    }
    fill_metadata(&root, frame, &mut imported.pattern.meta);
    if frame == 0 && imported.folded.is_none() {
        attach_folded_frame(&root, &mut imported);
    }
    imported.pattern.validate().map_err(pattern_error)?;
    if frame == 0 {
        let unit = resolved.get("frame_unit").and_then(Value::as_str);
        pin_inherited_unit(&mut imported.pattern.meta, unit);
    }
    Ok(imported)
}

/// Reads every frame but `frame` as well, so a broken frame (a missing parent, a key of the
/// wrong type, an index past the vertices) is refused with its place rather than copied
/// through to the output.
fn check_other_frames(root: &Map<String, Value>, frame: usize) -> Result<(), ParseError> {
    let count = file_frames(root)?.len();
    for other in (1..=count).filter(|&f| f != frame) {
        let resolved = resolve_frame(root, other)?;
        parse_frame(&resolved, other)?;
    }
    Ok(())
}

/// The key frame's coordinates are converted to millimetres (and written with
/// `frame_unit: "mm"`), but frames kept in `file_frames` keep their numbers: those that inherit
/// the key frame's unit get it written into them, so they still read in their own unit.
fn pin_inherited_unit(meta: &mut crate::pattern::Metadata, unit: Option<&str>) {
    let Some(unit) = unit.filter(|u| *u != "mm" && *u != "unit") else {
        return;
    };
    let Some(Value::Array(frames)) = meta.file_extra.get_mut("file_frames") else {
        return;
    };
    for frame in frames.iter_mut().filter_map(Value::as_object_mut) {
        let inherits = frame.get("frame_inherit").and_then(Value::as_bool) == Some(true);
        let from_key = frame.get("frame_parent").and_then(Value::as_u64) == Some(0);
        if inherits && from_key && !frame.contains_key("frame_unit") {
            frame.insert("frame_unit".into(), Value::String(unit.into()));
        }
    }
}

/// Parses a FOLD file's text into its top-level object (for [`super::resolve_frame`] and
/// [`super::frame_count`]); JSON errors are located by line and column.
pub fn parse_root(text: &str) -> Result<Map<String, Value>, ParseError> {
    if text.trim().is_empty() {
        return Err(ParseError::new(
            "file",
            "the file is empty (expected a FOLD JSON object)",
        ));
    }
    match super::strict::parse(text) {
        Ok(Value::Object(map)) => Ok(map),
        Ok(other) => Err(ParseError::new(
            "file",
            format!(
                "expected a JSON object at the top level, found {}",
                super::values::describe(&other)
            ),
        )),
        Err(e) => Err(json_error(&e)),
    }
}

/// A serde_json error as a [`ParseError`] at its line and column.
fn json_error(e: &serde_json::Error) -> ParseError {
    let full = e.to_string();
    let message = full
        .rfind(" at line ")
        .map_or(full.as_str(), |i| &full[..i]);
    let message = if message.contains("recursion limit") {
        "JSON nested too deeply (more than 128 levels of arrays and objects)".to_string()
    } else if message.contains("number out of range") {
        "invalid JSON: number out of range (beyond ±1.8e308)".to_string()
    } else if message.starts_with("duplicate key") {
        message.to_string()
    } else if e.is_eof() {
        format!("the JSON text ends too early ({message}): the file is truncated")
    } else {
        format!("invalid JSON: {message}")
    };
    ParseError::new(format!("line {}, column {}", e.line(), e.column()), message)
}

/// Titles, creator and file-level extras from the root; frame-level titles from the
/// frame extras.
fn fill_metadata(root: &Map<String, Value>, frame: usize, meta: &mut Metadata) {
    let [title, author, description] =
        FRAME_TEXT_KEYS.map(|k| take_string(&mut meta.frame_extra, k));
    let mut file_extra: Map<String, Value> = root
        .iter()
        .filter(|(k, _)| is_file_level(k) && k.as_str() != "file_spec")
        .filter(|(k, _)| frame == 0 || k.as_str() != FRAMES_KEY)
        .map(|(k, v)| (k.clone(), v.clone()))
        .collect();
    // The frame's own text wins; the file-level one then stays among the extras.
    let mut pick = |frame_text: Option<String>, file_key: &str| {
        frame_text.or_else(|| take_string(&mut file_extra, file_key))
    };
    meta.title = pick(title, "file_title");
    meta.author = pick(author, "file_author");
    meta.description = pick(description, "file_description");
    let source = take_string(&mut file_extra, SOURCE_CREATOR_KEY);
    let creator = take_string(&mut file_extra, "file_creator");
    meta.creator = source.or(creator.filter(|c| c != CREATOR));
    meta.file_extra = file_extra;
}

/// Removes `key` from `map` and returns it if it is a string (other values stay).
fn take_string(map: &mut Map<String, Value>, key: &str) -> Option<String> {
    match map.get(key) {
        Some(Value::String(_)) => match map.shift_remove(key) {
            Some(Value::String(s)) => Some(s),
            _ => None,
        },
        _ => None,
    }
}

/// Takes the first `foldedForm` frame of `file_frames` whose vertex and edge counts match the
/// key frame as its folded state; unusable ones give a warning.
fn attach_folded_frame(root: &Map<String, Value>, imported: &mut Imported) {
    let Ok(frames) = file_frames(root) else {
        return;
    };
    for i in 1..=frames.len() {
        let Ok(resolved) = resolve_frame(root, i) else {
            continue;
        };
        if !strings(resolved.get("frame_classes")).contains(&"foldedForm") {
            continue;
        }
        match folded_frame(&resolved, i, imported) {
            Ok(folded) => {
                imported.folded = Some(folded);
                take_written_frame(&mut imported.pattern.meta.file_extra, i);
                return;
            }
            Err(why) => imported.findings.push(
                FindingKind::FoldedFrameIgnored
                    .warning(format!("frame {i} (foldedForm) ignored: {why}")),
            ),
        }
    }
}

/// Removes frame `i` from the kept `file_frames` when it has the shape the writer gives a
/// folded state and no frame inherits from it (the writer adds it back from
/// [`Imported::folded`], so read → write round trips neither lose nor duplicate it). Later
/// frames' `frame_parent` ids are renumbered; an emptied `file_frames` is removed.
fn take_written_frame(file_extra: &mut Map<String, Value>, i: usize) {
    let Some(Value::Array(list)) = file_extra.get_mut(FRAMES_KEY) else {
        return;
    };
    let is_parent = |f: &Value| f.get("frame_parent").and_then(Value::as_u64) == Some(i as u64);
    if !list.get(i - 1).is_some_and(is_our_folded_frame) || list.iter().any(is_parent) {
        return;
    }
    list.remove(i - 1);
    for frame in list.iter_mut() {
        if let Some(p) = frame.get_mut("frame_parent")
            && let Some(n) = p.as_u64().filter(|&n| n > i as u64)
        {
            *p = Value::from(n - 1);
        }
    }
    if list.is_empty() {
        file_extra.shift_remove(FRAMES_KEY);
    }
}

/// Frame `i` as the folded state of the imported pattern.
fn folded_frame(
    resolved: &Map<String, Value>,
    i: usize,
    imported: &Imported,
) -> Result<FoldedState, String> {
    let raw = parse_frame(resolved, i).map_err(|e| e.to_string())?;
    let cp = &imported.pattern;
    if raw.units != cp.units {
        return Err("its frame_unit differs from the crease pattern's".into());
    }
    if raw.coords.len() != cp.vertices.len() || raw.edges.len() != cp.edges.len() {
        return Err(format!(
            "it has {} vertices and {} edges, the crease pattern {} and {}",
            raw.coords.len(),
            raw.edges.len(),
            cp.vertices.len(),
            cp.edges.len()
        ));
    }
    Ok(FoldedState {
        positions: raw.coords,
        edges: raw.edges,
        faces: raw.faces,
        face_orders: raw.face_orders,
    })
}

/// A broken model invariant as a [`ParseError`] at the key holding the element.
fn pattern_error(e: PatternError) -> ParseError {
    let (key, i) = match &e {
        PatternError::NonFiniteCoordinate { vertex } => ("vertices_coords", vertex.index()),
        PatternError::CoordinateTooLarge { vertex, .. } => ("vertices_coords", vertex.index()),
        PatternError::VertexOutOfRange { edge, .. } => ("edges_vertices", edge.index()),
        PatternError::LoopEdge { edge } => ("edges_vertices", edge.index()),
        PatternError::FoldAngleOutOfRange { edge, .. } => ("edges_foldAngle", edge.index()),
        PatternError::DegenerateFace { face } => ("faces_vertices", face.index()),
        PatternError::FaceVertexOutOfRange { face, .. } => ("faces_vertices", face.index()),
    };
    ParseError::new(format!("key {key:?}[{i}]"), e.to_string())
}
