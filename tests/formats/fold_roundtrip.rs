//! FOLD write → read round trips: random patterns with random extras come back equal;
//! real files survive read → write → read; units, frames, holes and folded states.

use std::path::PathBuf;

use foldcam::formats::fold::{
    HOLES_KEY, UNKNOWN_ANGLE_KEY, frame_count, parse_root, read_frame_str, read_str, resolve_frame,
    write_folded_string, write_string,
};
use foldcam::pattern::{
    Assignment, CreasePattern, Edge, Face, FaceId, FoldedState, Metadata, Units, VertexId,
};
use glam::{DVec2, DVec3};
use proptest::prelude::*;
use serde_json::{Map, Value, json};

// ---------------------------------------------------------------------------------------
// Random patterns

fn coordinate() -> impl Strategy<Value = f64> {
    prop_oneof![
        -1e9..1e9f64,
        -10.0..10.0f64,
        (-1000i32..1000).prop_map(f64::from),
        Just(-0.0),
        (1e-300..1e-10f64),
    ]
}

fn assignment() -> impl Strategy<Value = Assignment> {
    proptest::sample::select(Assignment::ALL.to_vec())
}

fn json_value() -> impl Strategy<Value = Value> {
    let leaf = prop_oneof![
        Just(Value::Null),
        any::<bool>().prop_map(Value::from),
        any::<i64>().prop_map(Value::from),
        (-1e300..1e300f64).prop_map(Value::from),
        "[ -~é\"\\\\\n]{0,12}".prop_map(Value::from),
    ];
    leaf.prop_recursive(4, 40, 6, |inner| {
        prop_oneof![
            prop::collection::vec(inner.clone(), 0..6).prop_map(Value::Array),
            prop::collection::vec(("[a-z]{1,6}", inner), 0..5)
                .prop_map(|kv| Value::Object(kv.into_iter().collect())),
        ]
    })
}

/// Extras under names that the reader files at the same level (file or frame).
fn extras(prefixes: &'static [&'static str]) -> impl Strategy<Value = Map<String, Value>> {
    prop::collection::vec(
        (
            proptest::sample::select(prefixes),
            "[a-z]{1,8}",
            json_value(),
        ),
        0..5,
    )
    .prop_map(|entries| {
        entries
            .into_iter()
            .map(|(prefix, name, v)| (format!("{prefix}{name}"), v))
            .collect()
    })
}

fn text() -> impl Strategy<Value = Option<String>> {
    proptest::option::of("[ -~äß€\n]{0,20}")
}

prop_compose! {
    fn pattern()(
        vertices in prop::collection::vec((coordinate(), coordinate()), 3..24)
    )(
        edges in prop::collection::vec(
            (0..vertices.len(), 1..vertices.len(), assignment(),
             proptest::option::of(-180.0..=180.0f64)),
            0..40,
        ),
        faces in proptest::option::of(prop::collection::vec(
            // Distinct corners: a cycle that repeats a vertex is degenerate and refused.
            (proptest::sample::subsequence((0..vertices.len() as u32).collect::<Vec<_>>(), 3..=vertices.len().min(6)),
             prop::collection::vec(proptest::sample::subsequence((0..vertices.len() as u32).collect::<Vec<_>>(), 3..=vertices.len().min(4)), 0..2)),
            0..6,
        )),
        units in prop_oneof![Just(Units::Millimetres), Just(Units::Unitless)],
        texts in (text(), text(), text(), text()),
        file_extra in extras(&["file_x", "test:", "my:thing_"]),
        frame_extra in extras(&["frame_x", "edges_test:", "test:faces_", "vertices_my:"]),
        derived in proptest::sample::subsequence(
            foldcam::formats::fold::DERIVED_KEYS.to_vec(), 0..=7),
        orders in prop::collection::vec((any::<prop::sample::Index>(), any::<prop::sample::Index>(), -1i8..=1), 0..4),
        vertices in Just(vertices),
    ) -> CreasePattern {
        let n = vertices.len();
        let edges = edges
            .into_iter()
            .map(|(a, step, asg, angle)| Edge {
                vertices: [VertexId(a as u32), VertexId(((a + step) % n) as u32)],
                assignment: asg,
                fold_angle: angle,
            })
            .collect();
        let faces: Option<Vec<Face>> = faces.map(|fs| {
            fs.into_iter()
                .map(|(outer, holes)| Face {
                    outer: outer.into_iter().map(VertexId).collect(),
                    holes: holes.into_iter().map(|h| h.into_iter().map(VertexId).collect()).collect(),
                })
                .collect()
        });
        let face_count = faces.as_ref().map_or(0, Vec::len);
        let face_orders = if face_count == 0 {
            Vec::new()
        } else {
            orders
                .into_iter()
                .map(|(f, g, s)| (FaceId(f.index(face_count) as u32), FaceId(g.index(face_count) as u32), s))
                .collect()
        };
        let needs_faces = |k: &&str| !matches!(*k, "vertices_faces" | "edges_faces" | "faces_edges" | "faces_faces");
        let derived_keys = derived
            .into_iter()
            .filter(|k| faces.is_some() || needs_faces(k))
            .map(str::to_string)
            .collect();
        let (title, author, description, creator) = texts;
        CreasePattern {
            vertices: vertices.into_iter().map(|(x, y)| DVec2::new(x, y)).collect(),
            edges,
            faces,
            face_orders,
            units,
            meta: Metadata {
                title,
                author,
                description,
                creator: creator.filter(|c| c != "foldcam"),
                file_extra,
                frame_extra,
                derived_keys,
            },
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    #[test]
    fn random_patterns_round_trip(cp in pattern()) {
        prop_assert!(cp.validate().is_ok());
        let text = write_string(&cp, None);
        let back = read_str(&text).map_err(|e| TestCaseError::fail(format!("{e}\n{text}")))?;
        prop_assert!(back.folded.is_none());
        // A pattern without faces is written with them (planarised first if it must be).
        let cp = foldcam::formats::fold::with_faces(&cp, true).into_owned();
        prop_assert_eq!(&back.pattern, &cp);
        // Bit-exact coordinates (PartialEq on f64 would accept 0.0 for -0.0).
        for (a, b) in back.pattern.vertices.iter().zip(&cp.vertices) {
            prop_assert_eq!(a.x.to_bits(), b.x.to_bits());
            prop_assert_eq!(a.y.to_bits(), b.y.to_bits());
        }
        // A second write gives the same text.
        prop_assert_eq!(write_string(&back.pattern, None), text);
    }
}

// ---------------------------------------------------------------------------------------
// Real files

fn testdata() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/fold")
}

#[test]
fn every_testdata_file_round_trips() {
    let dir = testdata();
    let mut count = 0;
    for entry in std::fs::read_dir(dir).into_iter().flatten().flatten() {
        let path = entry.path();
        if path.extension().is_none_or(|e| e != "fold") {
            continue;
        }
        count += 1;
        let name = path.display().to_string();
        let text = std::fs::read_to_string(&path).unwrap_or_default();
        let first = read_str(&text).unwrap_or_else(|e| panic!("{name}: {e}"));
        let written = write_string(&first.pattern, first.folded.as_ref());
        let second = read_str(&written).unwrap_or_else(|e| panic!("{name} rewritten: {e}"));
        assert_eq!(second.pattern, first.pattern, "{name}");
        assert_eq!(second.folded, first.folded, "{name}");
        // Writing the second read gives the same file (no frames pile up).
        assert_eq!(
            write_string(&second.pattern, second.folded.as_ref()),
            written,
            "{name}"
        );
        // Every top-level key of the original that is not interpreted survives with its value.
        let original: Value = serde_json::from_str(&text).unwrap_or_default();
        let rewritten: Value = serde_json::from_str(&written).unwrap_or_default();
        for key in [
            "cpedit:page",
            "file_classes",
            "faces_flatFoldTransform",
            "vertices_flatUnfoldCoords",
        ] {
            if let Some(v) = original.get(key) {
                assert_eq!(rewritten.get(key), Some(v), "{name}: {key}");
            }
        }
    }
    assert!(count >= 7, "expected the 7 FOLD test files, read {count}");
}

#[test]
fn unknown_keys_survive_in_order() {
    let text = r#"{
        "file_spec": 1.1, "file_creator": "Crease Pattern Editor",
        "zz:first": 1, "file_classes": ["singleModel"], "aa:second": {"nested": [1, [2, null]]},
        "vertices_coords": [[0, 0], [1, 0]], "edges_vertices": [[0, 1]],
        "edges_zz:kind": ["x"], "frame_attributes": ["2D"], "edgeOrders": [], "edges_aa:k": [true]
    }"#;
    let back =
        read_str(&write_string(&read_str(text).expect("reads").pattern, None)).expect("reads back");
    let meta = &back.pattern.meta;
    let file_keys: Vec<&str> = meta.file_extra.keys().map(String::as_str).collect();
    assert_eq!(file_keys, ["zz:first", "file_classes", "aa:second"]);
    let frame_keys: Vec<&str> = meta.frame_extra.keys().map(String::as_str).collect();
    assert_eq!(
        frame_keys,
        [
            "edges_zz:kind",
            "frame_attributes",
            "edgeOrders",
            "edges_aa:k"
        ]
    );
    assert_eq!(
        meta.file_extra["aa:second"],
        json!({"nested": [1, [2, null]]})
    );
    assert_eq!(meta.creator.as_deref(), Some("Crease Pattern Editor"));
}

#[test]
fn creator_is_foldcam_and_the_source_is_kept() {
    let text = r#"{"file_creator": "Oripa", "vertices_coords": [[0, 0]]}"#;
    let written = write_string(&read_str(text).expect("reads").pattern, None);
    let v: Value = serde_json::from_str(&written).unwrap_or_default();
    assert_eq!(v["file_creator"], json!("foldcam"));
    assert_eq!(v["file_spec"], json!(1.2));
    assert_eq!(
        read_str(&written)
            .expect("reads")
            .pattern
            .meta
            .creator
            .as_deref(),
        Some("Oripa")
    );
}

// ---------------------------------------------------------------------------------------
// Units

#[test]
fn centimetres_read_as_millimetres() {
    let text = r#"{"frame_unit": "cm", "vertices_coords": [[0, 0], [3, 4]],
        "edges_vertices": [[0, 1]], "edges_length": [5]}"#;
    let cp = read_str(text).expect("reads").pattern;
    assert_eq!(cp.units, Units::Millimetres);
    assert_eq!(cp.vertices[1], DVec2::new(30.0, 40.0));
    let v: Value = serde_json::from_str(&write_string(&cp, None)).unwrap_or_default();
    assert_eq!(v["frame_unit"], json!("mm"));
    assert_eq!(v["vertices_coords"][1], json!([30, 40]));
    // edges_length is recomputed in the new unit.
    assert_eq!(v["edges_length"], json!([50]));
}

#[test]
fn inches_points_and_unitless() {
    let cp = read_str(r#"{"frame_unit": "in", "vertices_coords": [[1, 2]]}"#)
        .expect("in")
        .pattern;
    assert_eq!(cp.vertices[0], DVec2::new(25.4, 50.8));
    let cp = read_str(r#"{"frame_unit": "pt", "vertices_coords": [[72, 0]]}"#)
        .expect("pt")
        .pattern;
    assert!((cp.vertices[0].x - 25.4).abs() < 1e-12);
    let cp = read_str(r#"{"vertices_coords": [[72, 0]]}"#)
        .expect("none")
        .pattern;
    assert_eq!(cp.units, Units::Unitless);
    let v: Value = serde_json::from_str(&write_string(&cp, None)).unwrap_or_default();
    assert_eq!(v["frame_unit"], json!("unit"));
}

// ---------------------------------------------------------------------------------------
// Frames

const FRAMES: &str = r#"{
    "file_title": "frames",
    "frame_title": "key",
    "vertices_coords": [[0, 0], [1, 0], [1, 1]],
    "edges_vertices": [[0, 1], [1, 2], [2, 0]],
    "edges_assignment": ["B", "B", "B"],
    "file_frames": [
        {"frame_parent": 0, "frame_inherit": true, "frame_title": "one",
         "edges_assignment": ["B", "M", "V"]},
        {"frame_parent": 1, "frame_inherit": true, "vertices_coords": [[0, 0], [2, 0], [2, 2]]},
        {"frame_parent": 1, "vertices_coords": [[5, 5]]}
    ]
}"#;

#[test]
fn frames_inherit_from_their_parents() {
    let one = read_frame_str(FRAMES, 1).expect("frame 1").pattern;
    assert_eq!(one.vertices.len(), 3);
    assert_eq!(one.edges[1].assignment, Assignment::Mountain);
    assert_eq!(one.meta.title.as_deref(), Some("one"));
    assert!(!one.meta.frame_extra.contains_key("frame_parent"));
    assert!(!one.meta.frame_extra.contains_key("frame_inherit"));
    let two = read_frame_str(FRAMES, 2).expect("frame 2").pattern;
    assert_eq!(two.vertices[2], DVec2::new(2.0, 2.0));
    assert_eq!(two.edges[2].assignment, Assignment::Valley);
    assert_eq!(two.meta.title.as_deref(), Some("one"));
    assert!(!two.meta.file_extra.contains_key("file_frames"));
    // Frame 3 does not inherit: one vertex, no edges.
    let three = read_frame_str(FRAMES, 3).expect("frame 3").pattern;
    assert_eq!((three.vertices.len(), three.edges.len()), (1, 0));
    let key = read_str(FRAMES).expect("key frame").pattern;
    assert_eq!(key.meta.title.as_deref(), Some("key"));
    assert!(key.meta.file_extra.contains_key("file_frames"));
    assert!(read_frame_str(FRAMES, 4).is_err());
}

/// Two unit squares side by side, hinged on a valley of 90° (boundary outside), and the
/// right square turned up about the hinge.
fn hinged_sheet() -> (CreasePattern, FoldedState) {
    let mut cp = CreasePattern::new();
    for (x, y) in [
        (0.0, 0.0),
        (2.0, 0.0),
        (2.0, 1.0),
        (0.0, 1.0),
        (1.0, 0.0),
        (1.0, 1.0),
    ] {
        cp.add_vertex(DVec2::new(x, y));
    }
    for (a, b, asg) in [
        (0, 4, 'B'),
        (4, 1, 'B'),
        (1, 2, 'B'),
        (2, 5, 'B'),
        (5, 3, 'B'),
        (3, 0, 'B'),
        (4, 5, 'V'),
    ] {
        cp.add_edge(
            VertexId(a),
            VertexId(b),
            Assignment::from_letter(asg).unwrap_or(Assignment::Flat),
        );
    }
    cp.edges[6].fold_angle = Some(90.0);
    let ids = |v: &[u32]| v.iter().map(|&i| VertexId(i)).collect::<Vec<_>>();
    cp.faces = Some(vec![
        Face::simple(ids(&[0, 4, 5, 3])),
        Face::simple(ids(&[4, 1, 2, 5])),
    ]);
    let folded = FoldedState {
        positions: vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 1.0),
            DVec3::new(1.0, 1.0, 1.0),
            DVec3::new(0.0, 1.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(1.0, 1.0, 0.0),
        ],
        edges: cp.edges.clone(),
        faces: cp.faces.clone(),
        face_orders: Vec::new(),
    };
    (cp, folded)
}

#[test]
fn folded_state_is_written_as_an_inheriting_frame() {
    let (cp, folded) = hinged_sheet();
    let text = write_string(&cp, Some(&folded));
    let v: Value = serde_json::from_str(&text).unwrap_or_default();
    assert_eq!(v["frame_classes"], json!(["creasePattern"]));
    let frame = &v["file_frames"][0];
    assert_eq!(frame["frame_classes"], json!(["foldedForm"]));
    assert_eq!(frame["frame_parent"], json!(0));
    assert_eq!(frame["frame_inherit"], json!(true));
    assert_eq!(frame["vertices_coords"][1], json!([1, 0, 1]));
    assert!(
        frame.get("edges_vertices").is_none(),
        "unchanged keys are inherited"
    );
    let back = read_str(&text).expect("reads");
    // The folded frame moves into `folded` (and back into `file_frames` on writing).
    assert_eq!(back.pattern, cp);
    assert_eq!(back.folded.as_ref(), Some(&folded));
    // The folded frame alone, with inheritance, is a 3D state that unfolds to the pattern.
    let alone = read_frame_str(&text, 1).expect("frame 1");
    for (a, b) in alone.pattern.vertices.iter().zip(&cp.vertices) {
        assert!(a.distance(*b) < 1e-12, "{a} vs {b}");
    }
    // Writing again replaces our folded frame instead of adding a second one.
    let again = write_string(&back.pattern, back.folded.as_ref());
    let v2: Value = serde_json::from_str(&again).unwrap_or_default();
    assert_eq!(v2["file_frames"].as_array().map(Vec::len), Some(1));
}

#[test]
fn a_folded_form_alone_is_a_3d_key_frame_that_unfolds_to_the_pattern() {
    let (cp, folded) = hinged_sheet();
    let text = write_folded_string(&cp, &folded);
    let v: Value = serde_json::from_str(&text).unwrap_or_default();
    assert_eq!(v["frame_classes"], json!(["foldedForm"]));
    assert_eq!(v["frame_attributes"], json!(["3D"]));
    assert!(v.get("file_frames").is_none(), "one frame only");
    assert!(v.get("frame_parent").is_none() && v.get("frame_inherit").is_none());
    assert_eq!(v["vertices_coords"][1], json!([1, 0, 1]));
    assert_eq!(v["edges_assignment"][6], json!("V"));
    assert_eq!(v["edges_foldAngle"][6], json!(90));
    // Read back, it unfolds onto the crease pattern (the same edges, the sheet flat again).
    let back = read_str(&text).expect("reads");
    assert_eq!(back.pattern.edges.len(), cp.edges.len());
    for (a, b) in back.pattern.vertices.iter().zip(&cp.vertices) {
        assert!(a.distance(*b) < 1e-12, "{a} vs {b}");
    }
}

// ---------------------------------------------------------------------------------------
// Holes and fold angles

#[test]
fn faces_with_holes_round_trip() {
    let mut cp = CreasePattern::new();
    for (x, y) in [
        (0.0, 0.0),
        (4.0, 0.0),
        (4.0, 4.0),
        (0.0, 4.0),
        (1.0, 1.0),
        (1.0, 3.0),
        (3.0, 3.0),
        (3.0, 1.0),
    ] {
        cp.add_vertex(DVec2::new(x, y));
    }
    for i in 0..4u32 {
        cp.add_edge(VertexId(i), VertexId((i + 1) % 4), Assignment::Boundary);
        cp.add_edge(VertexId(4 + i), VertexId(4 + (i + 1) % 4), Assignment::Cut);
    }
    cp.faces = Some(vec![Face {
        outer: (0..4).map(VertexId).collect(),
        holes: vec![(4..8).map(VertexId).collect()],
    }]);
    cp.meta.derived_keys = vec!["faces_edges".into(), "edges_faces".into()];
    let text = write_string(&cp, None);
    let v: Value = serde_json::from_str(&text).unwrap_or_default();
    assert_eq!(v["faces_vertices"], json!([[0, 1, 2, 3]]));
    assert_eq!(v[HOLES_KEY], json!([[[4, 5, 6, 7]]]));
    // Hole edges have the face on their left, since holes run clockwise.
    assert_eq!(v["edges_faces"][1], json!([0, null]));
    let back = read_str(&text).expect("reads").pattern;
    assert_eq!(back.faces, cp.faces);
}

#[test]
fn unknown_fold_angles_round_trip() {
    let text = r#"{"vertices_coords": [[0, 0], [1, 0], [0, 1]],
        "edges_vertices": [[0, 1], [1, 2], [2, 0]],
        "edges_assignment": ["v", "m", "b"],
        "edges_foldAngle": [null, -90, null]}"#;
    let cp = read_str(text).expect("reads").pattern;
    let angles: Vec<Option<f64>> = cp.edges.iter().map(|e| e.fold_angle).collect();
    assert_eq!(angles, [None, Some(-90.0), None]);
    assert_eq!(cp.edges[0].assignment, Assignment::Valley);
    let v: Value = serde_json::from_str(&write_string(&cp, None)).unwrap_or_default();
    // No nulls: the valley gets its full fold, the boundary 0, and both are listed as unknown.
    assert_eq!(v["edges_foldAngle"], json!([180, -90, 0]));
    assert_eq!(v[UNKNOWN_ANGLE_KEY], json!([0, 2]));
    let mut back = read_str(&write_string(&cp, None))
        .expect("reads back")
        .pattern;
    // The writer adds the triangle's one face; everything else comes back as it was.
    assert_eq!(back.faces.take().map(|f| f.len()), Some(1));
    assert_eq!(back, cp);
}

#[test]
fn edges_are_taken_from_faces_when_missing() {
    let text = r#"{"vertices_coords": [[0, 0], [1, 0], [1, 1], [0, 1]],
        "faces_vertices": [[0, 1, 2], [0, 2, 3]]}"#;
    let imported = read_str(text).expect("reads");
    let cp = &imported.pattern;
    assert_eq!(cp.edges.len(), 5);
    let diagonal = cp.edges.iter().find(|e| {
        let mut v = e.vertices.map(|v| v.0);
        v.sort();
        v == [0, 2]
    });
    assert_eq!(diagonal.map(|e| e.assignment), Some(Assignment::Unassigned));
    assert_eq!(cp.assignment_counts()[0], 4, "four boundary edges");
    assert!(imported.found(foldcam::formats::FindingKind::EdgesFromFaces));
}

#[test]
fn resolve_frame_exposes_inherited_keys() {
    let root = parse_root(FRAMES).expect("parses");
    assert_eq!(frame_count(&root), Ok(4));
    let two = resolve_frame(&root, 2).expect("frame 2");
    assert_eq!(two["edges_assignment"], json!(["B", "M", "V"]));
    assert!(!two.contains_key("file_title"));
}

#[test]
fn other_frames_stay_when_the_folded_frame_is_taken() {
    // Frame 1 is a folded state in the writer's shape; frames 2 and 3 are someone else's,
    // frame 3 a child of frame 2.
    let text = r#"{
        "vertices_coords": [[0, 0], [1, 0], [0, 1]],
        "edges_vertices": [[0, 1], [1, 2], [2, 0]],
        "faces_vertices": [[0, 1, 2]],
        "file_frames": [
            {"frame_classes": ["foldedForm"], "frame_parent": 0, "frame_inherit": true,
             "vertices_coords": [[0, 0, 0], [1, 0, 0], [0, 0, 1]]},
            {"frame_title": "other", "vertices_coords": [[0, 0]]},
            {"frame_parent": 2, "frame_inherit": true, "frame_title": "child"}
        ]
    }"#;
    let first = read_str(text).expect("reads");
    let folded = first.folded.as_ref().expect("frame 1 is the folded state");
    assert_eq!(folded.positions[2], DVec3::new(0.0, 0.0, 1.0));
    let kept = &first.pattern.meta.file_extra["file_frames"];
    assert_eq!(kept.as_array().map(Vec::len), Some(2));
    assert_eq!(
        kept[1]["frame_parent"],
        json!(1),
        "renumbered after taking frame 1"
    );
    let written = write_string(&first.pattern, first.folded.as_ref());
    let second = read_str(&written).expect("reads back");
    assert_eq!(second.pattern, first.pattern);
    assert_eq!(second.folded, first.folded);
    // The child still inherits from "other" in the rewritten file.
    let child = read_frame_str(&written, 2).expect("child");
    assert_eq!(child.pattern.meta.title.as_deref(), Some("child"));
    assert_eq!(child.pattern.vertices.len(), 1);
}

// ---------------------------------------------------------------------------------------
// Folded states with a known crease pattern

/// An accordion: a strip of `widths.len()` rectangles of height `h` joined along vertical
/// creases, folded by `angles` (degrees, one per crease) about those creases. Returns the
/// flat vertex positions and the FOLD text of the folded state.
fn accordion(widths: &[f64], h: f64, angles: &[f64], noise: &[f64]) -> (Vec<DVec2>, String) {
    let mut flat = Vec::new();
    let mut folded = Vec::new();
    let (mut x, mut p, mut heading) = (0.0, DVec3::ZERO, 0.0f64);
    for i in 0..=widths.len() {
        for y in [0.0, h] {
            flat.push(DVec2::new(x, y));
            folded.push(p + DVec3::new(0.0, y, 0.0));
        }
        if let Some(&w) = widths.get(i) {
            if i > 0 {
                heading += angles[i - 1].to_radians();
            }
            x += w;
            p += DVec3::new(heading.cos(), 0.0, heading.sin()) * w;
        }
    }
    let faces: Vec<Value> = (0..widths.len() as u32)
        .map(|i| json!([2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1]))
        .collect();
    let jitter = |i: usize| noise.get(i % noise.len().max(1)).copied().unwrap_or(0.0);
    let coords: Vec<Value> = folded
        .iter()
        .enumerate()
        .map(|(i, q)| {
            json!([
                q.x + jitter(3 * i),
                q.y + jitter(3 * i + 1),
                q.z + jitter(3 * i + 2)
            ])
        })
        .collect();
    let text = json!({
        "frame_classes": ["foldedForm"],
        "frame_unit": "mm",
        "vertices_coords": coords,
        "faces_vertices": faces,
    });
    (flat, text.to_string())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    #[test]
    fn folded_accordions_unfold_to_their_pattern(
        widths in prop::collection::vec(0.5..20.0f64, 2..8),
        h in 0.5..20.0f64,
        angles in prop::collection::vec(
            prop_oneof![-170.0..-10.0f64, 10.0..170.0f64], 7),
    ) {
        let (flat, text) = accordion(&widths, h, &angles, &[]);
        let imported = read_str(&text).map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert!(imported.folded.is_some());
        let cp = &imported.pattern;
        prop_assert_eq!(cp.vertices.len(), flat.len());
        // Congruent to the strip it was folded from: every pairwise distance agrees.
        for i in 0..flat.len() {
            for j in 0..i {
                let want = flat[i].distance(flat[j]);
                let got = cp.vertices[i].distance(cp.vertices[j]);
                prop_assert!((got - want).abs() <= 1e-9 * want.max(1.0), "{} {}: {} vs {}", i, j, got, want);
            }
        }
        // Not mirrored: the faces come out counter-clockwise like the strip's.
        for f in cp.faces.iter().flatten() {
            let area = foldcam::geom::signed_area(f.outer.iter().map(|v| cp.vertices[v.index()]));
            prop_assert!(area > 0.0);
        }
        // The edges come from the faces: boundary where one face, unassigned across creases.
        prop_assert_eq!(cp.edges.len(), 3 * widths.len() + 1);
        prop_assert_eq!(cp.assignment_counts()[4], widths.len() - 1);
    }
}

#[test]
fn tilted_flat_pattern_is_rotated_onto_xy() {
    // A 3 × 2 rectangle with a diagonal, turned into a tilted plane and moved away.
    let flat = [
        DVec2::new(0.0, 0.0),
        DVec2::new(3.0, 0.0),
        DVec2::new(3.0, 2.0),
        DVec2::new(0.0, 2.0),
    ];
    let rotation = glam::DQuat::from_axis_angle(DVec3::new(1.0, -2.0, 0.5).normalize(), 1.1);
    let coords: Vec<Value> = flat
        .iter()
        .map(|p| rotation * p.extend(0.0) + DVec3::new(5.0, -7.0, 11.0))
        .map(|q| json!([q.x, q.y, q.z]))
        .collect();
    let text = json!({
        "frame_unit": "cm",
        "vertices_coords": coords,
        "edges_vertices": [[0, 1], [1, 2], [2, 3], [3, 0], [0, 2]],
        "edges_assignment": ["B", "B", "B", "B", "V"],
        "faces_vertices": [[0, 1, 2], [0, 2, 3]],
        "frame_attributes": ["3D"]
    })
    .to_string();
    let imported = read_str(&text).expect("reads");
    assert!(imported.folded.is_none());
    assert!(
        imported.found(foldcam::formats::FindingKind::PlaneRotated),
        "{:?}",
        imported.findings
    );
    let cp = &imported.pattern;
    for i in 0..4 {
        for j in 0..i {
            let want = 10.0 * flat[i].distance(flat[j]);
            assert!((cp.vertices[i].distance(cp.vertices[j]) - want).abs() < 1e-9);
        }
    }
    for f in cp.faces.iter().flatten() {
        let ring = f.outer.iter().map(|v| cp.vertices[v.index()]);
        assert!(foldcam::geom::signed_area(ring) > 0.0);
    }
    assert_eq!(cp.meta.frame_extra["frame_attributes"], json!(["2D"]));
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 32, ..ProptestConfig::default() })]

    /// Coordinates disturbed by up to 1e-6 (like a file written with six digits): faces are
    /// no longer flat, yet a strip has more coordinates than edges, so the unfolding can
    /// still give every edge its 3D length.
    #[test]
    fn slightly_bent_accordions_keep_their_edge_lengths(
        widths in prop::collection::vec(0.5..20.0f64, 2..8),
        h in 0.5..20.0f64,
        angles in prop::collection::vec(prop_oneof![-170.0..-10.0f64, 10.0..170.0f64], 7),
        noise in prop::collection::vec(-1e-6..1e-6f64, 48),
    ) {
        let (_, text) = accordion(&widths, h, &angles, &noise);
        let imported = read_str(&text).map_err(|e| TestCaseError::fail(e.to_string()))?;
        let folded = imported.folded.as_ref().ok_or_else(|| TestCaseError::fail("not folded"))?;
        let cp = &imported.pattern;
        for e in &cp.edges {
            let [a, b] = e.vertices;
            let l3 = folded.positions[a.index()].distance(folded.positions[b.index()]);
            let l2 = cp.vertices[a.index()].distance(cp.vertices[b.index()]);
            prop_assert!((l2 - l3).abs() <= 1e-9 * l3, "{} vs {}", l2, l3);
        }
    }
}
