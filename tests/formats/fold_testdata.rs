//! Real FOLD files from the FOLD project and Origami Simulator (`tests/data/fold`, MIT):
//! they import, 3D folded forms unfold isometrically, flat x–z patterns become 2D.

use crate::overlap;

use std::path::PathBuf;

use foldcam::formats::fold::read_str;
use foldcam::pattern::{CreasePattern, FoldedState, Units};
use serde_json::Value;

fn testdata() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/fold")
}

/// The file's text and what it imports as; a missing or unreadable file fails the test.
fn read(name: &str) -> (String, foldcam::formats::Imported) {
    let path = testdata().join(name);
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let imported = read_str(&text).unwrap_or_else(|e| panic!("{name}: {e}"));
    (text, imported)
}

/// Number of entries of a top-level array key, read straight from the JSON.
fn count(text: &str, key: &str) -> usize {
    let v: Value = serde_json::from_str(text).unwrap_or_default();
    v.get(key).and_then(Value::as_array).map_or(0, Vec::len)
}

/// Every edge of the pattern is as long as in the folded state, within `rel` relative error.
fn assert_isometric(name: &str, cp: &CreasePattern, folded: &FoldedState, rel: f64) {
    assert_eq!(cp.vertices.len(), folded.positions.len(), "{name}");
    for (i, e) in cp.edges.iter().enumerate() {
        let [a, b] = e.vertices;
        let l2 = cp.vertices[a.index()].distance(cp.vertices[b.index()]);
        let l3 = folded.positions[a.index()].distance(folded.positions[b.index()]);
        assert!(
            (l2 - l3).abs() <= rel * l3.max(1e-300),
            "{name}: edge {i} is {l2} long unfolded but {l3} folded"
        );
    }
}

#[test]
fn every_file_imports() {
    let dir = testdata();
    let mut seen = 0;
    for entry in std::fs::read_dir(dir).expect("listing").flatten() {
        let path = entry.path();
        if path.extension().is_some_and(|e| e == "fold") {
            let text = std::fs::read_to_string(&path).unwrap_or_default();
            let imported = read_str(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            assert!(imported.pattern.validate().is_ok());
            assert!(!imported.pattern.vertices.is_empty(), "{}", path.display());
            seen += 1;
        }
    }
    assert!(seen >= 7, "only {seen} .fold files found");
}

#[test]
fn folded_forms_unfold_isometrically() {
    for name in [
        "squaretwist.fold",
        "simple.fold",
        "box.fold",
        "diagonal-folded.fold",
    ] {
        let (text, imported) = read(name);
        let folded = imported
            .folded
            .as_ref()
            .unwrap_or_else(|| panic!("{name}: no folded state"));
        assert_eq!(
            folded.positions.len(),
            count(&text, "vertices_coords"),
            "{name}"
        );
        assert_eq!(imported.pattern.edges, folded.edges, "{name}");
        assert!(
            imported.found(foldcam::formats::FindingKind::Unfolded),
            "{name}: {:?}",
            imported.findings
        );
        assert_isometric(name, &imported.pattern, folded, 1e-9);
    }
}

#[test]
fn unfolded_faces_are_counter_clockwise_and_do_not_overlap() {
    for name in ["squaretwist.fold", "simple.fold", "diagonal-folded.fold"] {
        let (_, imported) = read(name);
        let cp = &imported.pattern;
        let faces = cp
            .faces
            .as_ref()
            .unwrap_or_else(|| panic!("{name}: no faces"));
        let area = |f: &foldcam::pattern::Face| {
            foldcam::geom::signed_area(f.outer.iter().map(|v| cp.vertices[v.index()]))
        };
        assert!(faces.iter().all(|f| area(f) > 0.0), "{name}");
        // No overlap: the union of the faces (by i_overlay) is as large as their areas added up.
        let rings: Vec<Vec<glam::DVec2>> = faces
            .iter()
            .map(|f| f.outer.iter().map(|v| cp.vertices[v.index()]).collect())
            .collect();
        let twice = overlap::overlap_area(&rings);
        let total = overlap::area_sum(&rings);
        assert!(
            twice <= 1e-7 * total,
            "{name}: {twice:.3e} of {total:.3e} covered twice"
        );
    }
}

#[test]
fn flat_folded_diagonal_unfolds_to_its_crease_pattern() {
    let (_, folded) = read("diagonal-folded.fold");
    let (_, cp) = read("diagonal-cp.fold");
    // Both files describe the same square: the unfolding must be congruent to the CP (it is
    // placed with face 0, which is not flipped, in place, so equal up to rounding).
    for (a, b) in folded.pattern.vertices.iter().zip(&cp.pattern.vertices) {
        assert!(a.distance(*b) < 1e-12, "{a} vs {b}");
    }
    let state = folded.folded.unwrap_or_default();
    assert!(state.positions.iter().all(|p| p.z == 0.0));
    assert_eq!(cp.pattern.units, Units::Unitless);
}

#[test]
fn origami_simulator_patterns_become_flat() {
    for name in ["os-BoxPleatPyramid.fold", "os-BoxPleatTessellation.fold"] {
        let (text, imported) = read(name);
        assert!(imported.folded.is_none(), "{name}");
        let cp = &imported.pattern;
        assert_eq!(cp.vertices.len(), count(&text, "vertices_coords"), "{name}");
        assert_eq!(cp.edges.len(), count(&text, "edges_vertices"), "{name}");
        assert_eq!(
            cp.faces.as_ref().map_or(0, Vec::len),
            count(&text, "faces_vertices")
        );
        assert_eq!(cp.units, Units::Unitless);
        assert!(
            imported.found(foldcam::formats::FindingKind::PlaneRotated),
            "{name}"
        );
        // The rotation is an isometry: lengths match the 3D file.
        let v: Value = serde_json::from_str(&text).unwrap_or_default();
        let coords = v["vertices_coords"].as_array().cloned().unwrap_or_default();
        let p3 = |i: usize| {
            let c = &coords[i];
            glam::DVec3::new(
                c[0].as_f64().unwrap_or(0.0),
                c[1].as_f64().unwrap_or(0.0),
                c[2].as_f64().unwrap_or(0.0),
            )
        };
        for e in cp.edges.iter().step_by(7) {
            let [a, b] = e.vertices;
            let l3 = p3(a.index()).distance(p3(b.index()));
            let l2 = cp.vertices[a.index()].distance(cp.vertices[b.index()]);
            assert!((l2 - l3).abs() <= 1e-6 * l3, "{name}: {l2} vs {l3}");
        }
        // Faces counter-clockwise (Origami Simulator's run clockwise once y is turned up).
        for f in cp.faces.iter().flatten() {
            let ring = f.outer.iter().map(|v| cp.vertices[v.index()]);
            assert!(foldcam::geom::signed_area(ring) > 0.0, "{name}");
        }
        assert!(
            imported.found(foldcam::formats::FindingKind::FacesReversed),
            "{name}"
        );
        // Read as (x, −z), the SVG it was drawn from with y turned up: the first vertex.
        for (i, v) in cp.vertices.iter().enumerate().step_by(11) {
            let p = p3(i);
            assert!(
                v.distance(glam::DVec2::new(p.x, -p.z)) < 1e-12,
                "{name}: {v} vs {p}"
            );
        }
    }
}

#[test]
fn crease_pattern_file_keeps_its_coordinates_and_extras() {
    let (_, imported) = read("diagonal-cp.fold");
    let cp = &imported.pattern;
    assert_eq!(cp.vertices[2], glam::DVec2::new(1.0, 1.0));
    assert_eq!(cp.edges[4].fold_angle, Some(180.0));
    assert!(cp.meta.file_extra.contains_key("cpedit:page"));
    assert_eq!(cp.meta.title.as_deref(), Some("diagonal"));
    assert_eq!(cp.meta.creator.as_deref(), Some("Crease Pattern Editor"));
    assert!(cp.meta.derived_keys.iter().any(|k| k == "faces_edges"));
    assert!(
        imported.warnings().next().is_none(),
        "{:?}",
        imported.findings
    );
}
