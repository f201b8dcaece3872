//! Malformed FOLD input: every problem is a `ParseError` naming the place (key and index, or
//! line and column) and the problem; nothing panics, whatever the bytes.

use foldcam::formats::ParseError;
use foldcam::formats::fold::{read_frame_str, read_str, write_string};
use proptest::prelude::*;

/// Reads `text`, expecting an error whose place contains `place` and whose message contains
/// `message` (case-insensitive).
fn fails(text: &str, place: &str, message: &str) -> ParseError {
    let err = match read_str(text) {
        Ok(_) => panic!("accepted: {text}"),
        Err(e) => e,
    };
    assert!(
        err.place.contains(place),
        "place {:?} lacks {place:?} ({err})",
        err.place
    );
    assert!(
        err.message.to_lowercase().contains(&message.to_lowercase()),
        "message {:?} lacks {message:?}",
        err.message
    );
    err
}

/// A valid triangle with the given extra keys (JSON object members) added, or replacing the
/// triangle's own keys of the same name in place (the reader refuses a key given twice).
fn triangle(extra: &str) -> String {
    let base = r#"{"vertices_coords": [[0, 0], [1, 0], [0, 1]],
            "edges_vertices": [[0, 1], [1, 2], [2, 0]],
            "edges_assignment": ["B", "B", "B"],
            "faces_vertices": [[0, 1, 2]]}"#;
    if extra.is_empty() {
        return base.to_string();
    }
    let mut map: serde_json::Map<String, serde_json::Value> =
        serde_json::from_str(base).expect("base parses");
    let extra: serde_json::Map<String, serde_json::Value> =
        serde_json::from_str(&format!("{{{extra}}}")).expect("extra keys parse");
    map.extend(extra);
    serde_json::to_string_pretty(&map).expect("serialises")
}

#[test]
fn the_valid_base_reads() {
    assert!(read_str(&triangle("")).is_ok());
}

// JSON level ------------------------------------------------------------------------------

#[test]
fn empty_file() {
    fails("", "file", "empty");
    fails("  \n\t ", "file", "empty");
}

#[test]
fn truncated_json_gives_line_and_column() {
    let text = triangle("");
    let cut = &text[..text.len() / 2];
    let err = fails(cut, "line", "truncated");
    assert!(err.place.contains("column"), "{err}");
}

#[test]
fn invalid_json_gives_line_and_column() {
    let err = fails(
        "{\n  \"vertices_coords\": [[0, 0],, [1, 0]]\n}",
        "line 2",
        "invalid JSON",
    );
    assert!(err.place.contains("column"), "{err}");
}

#[test]
fn deeply_nested_json() {
    let deep = format!(
        "{{\"x:deep\": {}{}}}",
        "[".repeat(100_000),
        "]".repeat(100_000)
    );
    fails(&deep, "line 1", "nested too deeply");
}

#[test]
fn top_level_must_be_an_object() {
    fails("[1, 2, 3]", "file", "top level");
    fails("42", "file", "object");
    fails("\"fold\"", "file", "object");
}

#[test]
fn huge_exponent_is_out_of_range() {
    fails(
        r#"{"vertices_coords": [[1e400, 0]]}"#,
        "line 1",
        "out of range",
    );
}

// Lengths of parallel arrays -------------------------------------------------------------

#[test]
fn assignment_shorter_than_edges() {
    fails(
        &triangle(r#""edges_assignment": ["B", "B"]"#),
        "key \"edges_assignment\"",
        "same length",
    );
}

#[test]
fn fold_angles_longer_than_edges() {
    fails(
        &triangle(r#""edges_foldAngle": [0, 0, 0, 0]"#),
        "key \"edges_foldAngle\"",
        "same length",
    );
}

#[test]
fn derived_key_of_the_wrong_length() {
    fails(
        &triangle(r#""vertices_edges": [[0, 2]]"#),
        "key \"vertices_edges\"",
        "same length",
    );
}

#[test]
fn holes_not_parallel_to_faces() {
    fails(
        &triangle(r#""foldcam:faces_holes": []"#),
        "foldcam:faces_holes",
        "same length",
    );
}

#[test]
fn edge_properties_without_edges() {
    fails(
        r#"{"vertices_coords": [[0, 0]], "edges_assignment": ["B"]}"#,
        "key \"edges_assignment\"",
        "without \"edges_vertices\"",
    );
}

// Indices ---------------------------------------------------------------------------------

#[test]
fn edge_index_missing() {
    fails(
        &triangle(r#""edges_vertices": [[0, 1], [1], [2, 0]]"#),
        "\"edges_vertices\"[1]",
        "exactly 2",
    );
}

#[test]
fn edge_with_three_vertices() {
    fails(
        &triangle(r#""edges_vertices": [[0, 1], [1, 2], [2, 0, 1]]"#),
        "\"edges_vertices\"[2]",
        "found 3",
    );
}

#[test]
fn edge_joining_a_vertex_to_itself() {
    fails(
        &triangle(r#""edges_vertices": [[0, 1], [1, 1], [2, 0]]"#),
        "\"edges_vertices\"[1]",
        "itself",
    );
}

#[test]
fn negative_index() {
    fails(
        &triangle(r#""edges_vertices": [[0, 1], [1, -2], [2, 0]]"#),
        "\"edges_vertices\"[1][1]",
        "negative",
    );
}

#[test]
fn fractional_index() {
    fails(
        &triangle(r#""faces_vertices": [[0, 1.5, 2]]"#),
        "\"faces_vertices\"[0][1]",
        "whole number",
    );
}

#[test]
fn index_out_of_range() {
    fails(
        &triangle(r#""edges_vertices": [[0, 1], [1, 2], [2, 3]]"#),
        "\"edges_vertices\"[2][1]",
        "vertex 3 does not exist",
    );
}

#[test]
fn index_that_is_a_string() {
    fails(
        &triangle(r#""edges_vertices": [[0, 1], ["1", 2], [2, 0]]"#),
        "\"edges_vertices\"[1][0]",
        "expected a vertex id",
    );
}

#[test]
fn index_beyond_u32() {
    fails(
        &triangle(r#""faces_vertices": [[0, 1, 99999999999]]"#),
        "\"faces_vertices\"[0][2]",
        "does not exist",
    );
}

#[test]
fn face_with_two_vertices() {
    fails(
        &triangle(r#""faces_vertices": [[0, 1]]"#),
        "\"faces_vertices\"[0]",
        "at least 3",
    );
}

#[test]
fn face_orders_malformed() {
    fails(
        &triangle(r#""faceOrders": [[0, 0, 2]]"#),
        "\"faceOrders\"[0][2]",
        "-1, 0 or 1",
    );
    fails(
        &triangle(r#""faceOrders": [[0, 1, 1]]"#),
        "\"faceOrders\"[0][1]",
        "face 1 does not exist",
    );
    fails(
        &triangle(r#""faceOrders": [[0, 0]]"#),
        "\"faceOrders\"[0]",
        "[f, g, s]",
    );
}

#[test]
fn unknown_angle_list_out_of_range() {
    fails(
        &triangle(r#""foldcam:edges_foldAngleUnknown": [3]"#),
        "foldcam:edges_foldAngleUnknown",
        "edge 3",
    );
}

// Coordinates -----------------------------------------------------------------------------

#[test]
fn non_numeric_coordinate() {
    fails(
        &triangle(r#""vertices_coords": [[0, 0], ["one", 0], [0, 1]]"#),
        "\"vertices_coords\"[1][0]",
        "expected a number",
    );
    fails(
        &triangle(r#""vertices_coords": [[0, 0], [1, null], [0, 1]]"#),
        "\"vertices_coords\"[1][1]",
        "null",
    );
    fails(
        &triangle(r#""vertices_coords": [[0, 0], [1, 0], "0, 1"]"#),
        "\"vertices_coords\"[2]",
        "expected an array",
    );
}

#[test]
fn nan_and_infinity_as_strings() {
    fails(
        &triangle(r#""vertices_coords": [[0, 0], ["NaN", 0], [0, 1]]"#),
        "\"vertices_coords\"[1][0]",
        "NaN",
    );
    fails(
        &triangle(r#""vertices_coords": [[0, 0], [1, "Infinity"], [0, 1]]"#),
        "\"vertices_coords\"[1][1]",
        "Infinity",
    );
}

#[test]
fn absurd_coordinates() {
    fails(
        &triangle(r#""vertices_coords": [[0, 0], [2e9, 0], [0, 1]], "frame_unit": "mm""#),
        "\"vertices_coords\"[1][0]",
        "limit",
    );
    // 2e8 cm is 2e9 mm: beyond the limit only after conversion.
    fails(
        &triangle(r#""vertices_coords": [[0, 0], [0, 2e8], [0, 1]], "frame_unit": "cm""#),
        "\"vertices_coords\"[1][1]",
        "limit",
    );
    assert!(
        read_str(&triangle(
            r#""vertices_coords": [[0, 0], [0, 2e8], [0, 1]], "frame_unit": "mm""#
        ))
        .is_ok()
    );
}

#[test]
fn coordinates_with_too_few_or_too_many_components() {
    fails(
        &triangle(r#""vertices_coords": [[0, 0], [1], [0, 1]]"#),
        "\"vertices_coords\"[1]",
        "2 or 3",
    );
    fails(
        &triangle(r#""vertices_coords": [[0, 0], [1, 0, 0, 0], [0, 1]]"#),
        "\"vertices_coords\"[1]",
        "found 4",
    );
}

#[test]
fn unknown_unit() {
    fails(
        &triangle(r#""frame_unit": "furlong""#),
        "key \"frame_unit\"",
        "furlong",
    );
    fails(
        &triangle(r#""frame_unit": 25.4"#),
        "key \"frame_unit\"",
        "string",
    );
}

// Assignments and angles ------------------------------------------------------------------

#[test]
fn assignment_letters_fold_does_not_define() {
    fails(
        &triangle(r#""edges_assignment": ["B", "X", "B"]"#),
        "\"edges_assignment\"[1]",
        "\"X\"",
    );
    fails(
        &triangle(r#""edges_assignment": ["B", "MV", "B"]"#),
        "\"edges_assignment\"[1]",
        "unknown",
    );
    fails(
        &triangle(r#""edges_assignment": ["B", 1, "B"]"#),
        "\"edges_assignment\"[1]",
        "expected a letter",
    );
}

#[test]
fn lower_case_letters_are_accepted() {
    assert!(read_str(&triangle(r#""edges_assignment": ["b", "m", "v"]"#)).is_ok());
}

#[test]
fn fold_angles_outside_the_range() {
    fails(
        &triangle(r#""edges_foldAngle": [0, 180.5, 0]"#),
        "\"edges_foldAngle\"[1]",
        "outside",
    );
    fails(
        &triangle(r#""edges_foldAngle": [-181, 0, 0]"#),
        "\"edges_foldAngle\"[0]",
        "outside",
    );
    fails(
        &triangle(r#""edges_foldAngle": [0, "90", 0]"#),
        "\"edges_foldAngle\"[1]",
        "expected a number",
    );
}

// Frames and shape ------------------------------------------------------------------------

#[test]
fn frame_parent_cycle() {
    let text = triangle(
        r#""file_frames": [{"frame_parent": 2, "frame_inherit": true},
                           {"frame_parent": 1, "frame_inherit": true}]"#,
    );
    let err = read_frame_str(&text, 1).expect_err("cycle");
    assert!(
        err.message.contains("cycle") && err.place.contains("frame_parent"),
        "{err}"
    );
}

#[test]
fn frame_errors_name_the_frame() {
    let text = triangle(r#""file_frames": [{"frame_parent": 9, "frame_inherit": true}]"#);
    let err = read_frame_str(&text, 1).expect_err("bad parent");
    assert!(
        err.place.contains("frame 1") && err.message.contains("frame 9"),
        "{err}"
    );
    let text = triangle(r#""file_frames": [{"vertices_coords": [[0, "x"]]}]"#);
    let err = read_frame_str(&text, 1).expect_err("bad coordinate");
    assert_eq!(err.place, "frame 1, key \"vertices_coords\"[0][1]");
    let err = read_frame_str(&triangle(r#""file_frames": 3"#), 0).expect_err("not frames");
    assert!(err.place.contains("file_frames"), "{err}");
    assert!(read_frame_str(&triangle(""), 1).is_err());
}

#[test]
fn folded_state_without_faces() {
    let text = r#"{"vertices_coords": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
        "edges_vertices": [[0, 1], [0, 2], [0, 3]]}"#;
    fails(text, "key \"faces_vertices\"", "folded state");
}

#[test]
fn key_of_the_wrong_type() {
    fails(
        r#"{"vertices_coords": {"0": [0, 0]}}"#,
        "key \"vertices_coords\"",
        "expected an array",
    );
    fails(
        &triangle(r#""faces_vertices": 7"#),
        "key \"faces_vertices\"",
        "expected an array",
    );
}

// Random damage ---------------------------------------------------------------------------

/// A valid file with several frames, folded state, holes, derived keys and extras.
fn sample() -> String {
    let base = read_str(&triangle(
        r#""vertices_vertices": [[1, 2], [2, 0], [0, 1]], "edges_faces": [[0], [0], [0]],
           "edges_foldAngle": [0, null, 0], "faceOrders": [[0, 0, 0]], "frame_unit": "cm",
           "x:extra": {"a": [1, 2.5, "s"]},
           "file_frames": [{"frame_parent": 0, "frame_inherit": true, "frame_title": "f",
                            "edges_assignment": ["M", "V", "U"]}]"#,
    ))
    .expect("sample reads");
    write_string(&base.pattern, None)
}

/// A text edit: (position fraction, kind, replacement choice).
fn mutate(text: &str, edits: &[(f64, u8, u8)]) -> String {
    let mut s = text.to_string();
    for &(at, kind, pick) in edits {
        let mut i = ((s.len() as f64) * at) as usize;
        while i > 0 && !s.is_char_boundary(i) {
            i -= 1;
        }
        let replacements = [
            "\"x\"",
            "1e400",
            "-1",
            "0.5",
            "null",
            "[]",
            "{}",
            "4294967296",
            "1e308",
            "-0",
            "[[",
            "]",
            ",",
            "\"",
            "true",
            "9e9",
        ];
        let r = replacements[pick as usize % replacements.len()];
        match kind % 4 {
            0 => s.truncate(i),
            1 => s.insert_str(i, r),
            2 => {
                // Replace the number starting at or after i.
                let start = s[i..].find(|c: char| c.is_ascii_digit()).map(|k| i + k);
                if let Some(start) = start {
                    let end = s[start..]
                        .find(|c: char| !(c.is_ascii_digit() || ".eE+-".contains(c)))
                        .map_or(s.len(), |k| start + k);
                    s.replace_range(start..end, r);
                }
            }
            _ => {
                let end = (i + 1 + pick as usize % 7).min(s.len());
                let end = (end..=s.len())
                    .find(|&e| s.is_char_boundary(e))
                    .unwrap_or(s.len());
                s.replace_range(i..end, "");
            }
        }
    }
    s
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    #[test]
    fn damaged_files_never_panic(
        edits in prop::collection::vec((0.0..1.0f64, any::<u8>(), any::<u8>()), 1..4),
        frame in 0usize..3,
    ) {
        let text = mutate(&sample(), &edits);
        // Ok or Err, never a panic; an error always says where.
        for result in [read_str(&text), read_frame_str(&text, frame)] {
            if let Err(e) = result {
                prop_assert!(!e.place.is_empty() && !e.message.is_empty());
            }
        }
    }

    #[test]
    fn arbitrary_bytes_never_panic(text in "\\PC{0,200}") {
        // Whatever is accepted is a valid pattern; whatever is refused says where.
        match read_str(&text) {
            Ok(imported) => prop_assert!(imported.pattern.validate().is_ok()),
            Err(e) => prop_assert!(!e.message.is_empty()),
        }
    }
}
