//! FOLD frames: the key frame (the top-level dictionary), `file_frames` (frames 1, 2, …),
//! `frame_parent` and `frame_inherit`, and which top-level keys belong to the file rather
//! than to the key frame.
//!
//! A frame with `frame_inherit: true` and a `frame_parent` takes every key of its (resolved)
//! parent that it does not set itself; chains are followed recursively and a cycle is an
//! error naming the frames. The key frame's properties are the top-level keys that are not
//! file-level (see [`is_file_level`]).

use serde_json::{Map, Value};

use super::values::{Key, array, describe, index};
use crate::formats::ParseError;

/// The key holding frames 1, 2, ….
pub(super) const FRAMES_KEY: &str = "file_frames";

/// Whether a top-level key describes the file rather than the key frame: `file_*` keys and
/// keys that name no frame property (custom `ns:key` keys such as `cpedit:page`, unknown
/// keys). Frame properties are `frame_*`, `vertices_*`, `edges_*`, `faces_*`, `faceOrders`
/// and `edgeOrders`, also after a namespace (`ns:edges_x`) or with one (`edges_ns:x`).
pub(super) fn is_file_level(key: &str) -> bool {
    let frame_like = |k: &str| {
        ["frame_", "vertices_", "edges_", "faces_"]
            .iter()
            .any(|p| k.starts_with(p))
            || k == "faceOrders"
            || k == "edgeOrders"
    };
    let last = key.rsplit(':').next().unwrap_or(key);
    !(frame_like(key) || frame_like(last))
}

/// Number of frames in a parsed FOLD file: 1 plus the length of `file_frames`.
pub fn frame_count(root: &Map<String, Value>) -> Result<usize, ParseError> {
    Ok(1 + file_frames(root)?.len())
}

/// The `file_frames` array (empty when absent), each entry checked to be an object.
pub(super) fn file_frames(root: &Map<String, Value>) -> Result<&[Value], ParseError> {
    let key = Key::new(0, FRAMES_KEY);
    let Some(v) = root.get(FRAMES_KEY) else {
        return Ok(&[]);
    };
    let frames = array(v, key, &[])?;
    if let Some((i, bad)) = frames.iter().enumerate().find(|(_, f)| !f.is_object()) {
        return Err(key.err(
            &[i],
            format!("expected a frame (an object), found {}", describe(bad)),
        ));
    }
    Ok(frames)
}

/// The properties of frame `index` of a parsed FOLD file, with inheritance resolved: for the
/// key frame (0) the top-level keys that are not file-level; for frame `i ≥ 1`
/// `file_frames[i - 1]`, preceded by its parent's keys when it has `frame_inherit: true`.
///
/// Errors name the frame and key: an index beyond the frames, a `frame_parent` that is not
/// an existing frame id, a `frame_inherit` that is not a boolean, or a cycle of parents.
pub fn resolve_frame(
    root: &Map<String, Value>,
    index: usize,
) -> Result<Map<String, Value>, ParseError> {
    let frames = file_frames(root)?;
    if index > frames.len() {
        return Err(ParseError::new(
            "file",
            format!(
                "frame {index} does not exist (the file has {} frames, 0 to {})",
                frames.len() + 1,
                frames.len()
            ),
        ));
    }
    let chain = inheritance_chain(frames, index)?;
    let mut out = Map::new();
    for &f in chain.iter().rev() {
        for (k, v) in own_keys(root, frames, f) {
            out.insert(k.clone(), v.clone());
        }
    }
    Ok(out)
}

/// The frame's own properties (without inherited ones).
fn own_keys<'a>(
    root: &'a Map<String, Value>,
    frames: &'a [Value],
    frame: usize,
) -> Box<dyn Iterator<Item = (&'a String, &'a Value)> + 'a> {
    if frame == 0 {
        return Box::new(root.iter().filter(|(k, _)| !is_file_level(k)));
    }
    match frames.get(frame - 1).and_then(Value::as_object) {
        Some(obj) => Box::new(obj.iter()),
        None => Box::new(std::iter::empty()),
    }
}

/// `frame` followed by the ancestors it inherits from, nearest first.
fn inheritance_chain(frames: &[Value], frame: usize) -> Result<Vec<usize>, ParseError> {
    let mut chain = vec![frame];
    let mut current = frame;
    while let Some(parent) = inherited_parent(frames, current)? {
        if let Some(pos) = chain.iter().position(|&f| f == parent) {
            let cycle: Vec<String> = chain[pos..]
                .iter()
                .chain(std::iter::once(&parent))
                .map(usize::to_string)
                .collect();
            return Err(Key::new(current, "frame_parent").err(
                &[],
                format!("frames inherit in a cycle: {}", cycle.join(" → ")),
            ));
        }
        chain.push(parent);
        current = parent;
    }
    Ok(chain)
}

/// Checks the `frame_parent` and `frame_inherit` of every frame, not only of the one read, so
/// that a file whose other frames point at missing parents or inherit in a cycle is refused
/// rather than copied through. Linear in the number of frames (each is walked once).
pub(super) fn check_frame_links(root: &Map<String, Value>) -> Result<(), ParseError> {
    let frames = file_frames(root)?;
    // 0: not seen; 1: on the current walk; 2: its chain ends without a cycle.
    let mut state = vec![0u8; frames.len() + 1];
    for start in 1..=frames.len() {
        let mut walk = Vec::new();
        let mut f = start;
        loop {
            match state[f] {
                2 => break,
                // Back on the current walk: a cycle; the chain from here names it.
                1 => return inheritance_chain(frames, f).map(|_| ()),
                _ => {}
            }
            state[f] = 1;
            walk.push(f);
            match inherited_parent(frames, f)? {
                Some(parent) => f = parent,
                None => break,
            }
        }
        for w in walk {
            state[w] = 2;
        }
    }
    Ok(())
}

/// The parent `frame` inherits from, if it has `frame_inherit: true` and a `frame_parent`.
fn inherited_parent(frames: &[Value], frame: usize) -> Result<Option<usize>, ParseError> {
    let Some(obj) = frame
        .checked_sub(1)
        .and_then(|i| frames.get(i))
        .and_then(Value::as_object)
    else {
        return Ok(None);
    };
    let inherit = match obj.get("frame_inherit") {
        None | Some(Value::Null) => false,
        Some(Value::Bool(b)) => *b,
        Some(other) => {
            return Err(Key::new(frame, "frame_inherit").err(
                &[],
                format!("expected true or false, found {}", describe(other)),
            ));
        }
    };
    let parent_key = Key::new(frame, "frame_parent");
    let parent = obj
        .get("frame_parent")
        .filter(|v| !v.is_null())
        .map(|v| index(v, frames.len() + 1, "frame", parent_key, &[]))
        .transpose()?;
    Ok(parent.filter(|_| inherit).map(|p| p as usize))
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn root(v: Value) -> Map<String, Value> {
        v.as_object().cloned().unwrap_or_default()
    }

    #[test]
    fn classifies_keys() {
        assert!(is_file_level("file_title"));
        assert!(is_file_level("cpedit:page"));
        assert!(is_file_level("mystery"));
        assert!(!is_file_level("frame_classes"));
        assert!(!is_file_level("edges_tm:structuralType"));
        assert!(!is_file_level("tm:edges_x"));
        assert!(!is_file_level("faceOrders"));
    }

    #[test]
    fn inherits_recursively_and_overrides() {
        let r = root(json!({
            "file_title": "t",
            "vertices_coords": [[0, 0]],
            "frame_title": "zero",
            "file_frames": [
                {"frame_parent": 0, "frame_inherit": true, "frame_title": "one"},
                {"frame_parent": 1, "frame_inherit": true, "edges_vertices": []},
                {"frame_parent": 0, "frame_title": "no inherit"}
            ]
        }));
        let f2 = resolve_frame(&r, 2).unwrap();
        assert_eq!(f2["frame_title"], json!("one"));
        assert_eq!(f2["vertices_coords"], json!([[0, 0]]));
        assert!(f2.contains_key("edges_vertices"));
        assert!(!f2.contains_key("file_title"));
        let f3 = resolve_frame(&r, 3).unwrap();
        assert!(!f3.contains_key("vertices_coords"));
        assert_eq!(frame_count(&r), Ok(4));
        assert!(resolve_frame(&r, 4).is_err());
    }

    #[test]
    fn cycles_are_errors() {
        let r = root(json!({"file_frames": [
            {"frame_parent": 2, "frame_inherit": true},
            {"frame_parent": 1, "frame_inherit": true}
        ]}));
        let err = resolve_frame(&r, 1).unwrap_err();
        assert!(err.message.contains("cycle"), "{}", err.message);
        assert!(err.place.contains("frame_parent"));
    }
}
