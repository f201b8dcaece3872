//! FOLD files that other tools open: every FOLD file foldcam writes passes the structural rules
//! of Origami Simulator's importer and Rabbit Ear, checked by an independent validator on the
//! written JSON (not on the model); and generated patterns carry fold angles.
//!
//! The rules (facts from those programs and the FOLD 1.2 specification):
//! - Origami Simulator refuses a file without all of `vertices_coords`, `edges_vertices`,
//!   `edges_assignment` and `faces_vertices`; it triangulates each face and gives every
//!   mountain, valley and flat edge the two faces on either side of it, so each such edge
//!   must be a side of exactly two faces (a boundary edge of one);
//! - Rabbit Ear rejects edges joining a vertex to itself and duplicate edges;
//! - FOLD 1.2: per-edge arrays as long as `edges_vertices`, indices in range, faces
//!   counter-clockwise, fold angles in [−180°, 180°], positive for valleys, negative for
//!   mountains, zero for flat, unassigned and boundary edges.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use foldcam::design::classic::{MiuraOri, SquareTwist, Waterbomb, Yoshimura};
use foldcam::formats;
use foldcam::pattern::{Assignment, CreasePattern};
use glam::DVec2;
use serde_json::Value;

/// Every way the JSON breaks the rules above, as readable strings.
fn conformance_faults(text: &str) -> Vec<String> {
    let fold: Value = match serde_json::from_str(text) {
        Ok(v) => v,
        Err(e) => return vec![format!("not JSON: {e}")],
    };
    let mut faults = Vec::new();
    let key = |k: &str| fold.get(k).and_then(Value::as_array);
    let (Some(coords), Some(edges), Some(assign), Some(faces)) = (
        key("vertices_coords"),
        key("edges_vertices"),
        key("edges_assignment"),
        key("faces_vertices"),
    ) else {
        return vec!["a key Origami Simulator requires is missing".into()];
    };
    let nv = coords.len();
    let index = |v: &Value| v.as_u64().map(|i| i as usize).filter(|&i| i < nv);
    let mut pairs: Vec<(usize, usize)> = Vec::new();
    for (i, e) in edges.iter().enumerate() {
        match e
            .as_array()
            .map(|a| a.iter().map(index).collect::<Vec<_>>())
        {
            Some(v) if v.len() == 2 && v.iter().all(Option::is_some) => {
                let (a, b) = (v[0].unwrap_or(0), v[1].unwrap_or(0));
                if a == b {
                    faults.push(format!("edge {i} is a loop"));
                }
                pairs.push((a.min(b), a.max(b)));
            }
            _ => faults.push(format!("edge {i} is not two vertex indices in range")),
        }
    }
    let mut sorted = pairs.clone();
    sorted.sort_unstable();
    if sorted.windows(2).any(|w| w[0] == w[1]) {
        faults.push("duplicate edges".into());
    }
    if assign.len() != edges.len() {
        faults.push("edges_assignment length differs".into());
    }
    let letters: Vec<&str> = assign.iter().map(|a| a.as_str().unwrap_or("?")).collect();
    match key("edges_foldAngle") {
        None => faults.push("no edges_foldAngle".into()),
        Some(angles) if angles.len() != edges.len() => {
            faults.push("edges_foldAngle length differs".into())
        }
        Some(angles) => {
            for (i, (a, l)) in angles.iter().zip(&letters).enumerate() {
                let Some(a) = a.as_f64().filter(|a| a.abs() <= 180.0) else {
                    faults.push(format!("edge {i}: fold angle {a} not in [-180, 180]"));
                    continue;
                };
                let ok = match *l {
                    "M" => a <= 0.0,
                    "V" => a >= 0.0,
                    _ => a == 0.0,
                };
                if !ok {
                    faults.push(format!("edge {i}: {l} with fold angle {a}"));
                }
            }
        }
    }
    let xy = |i: usize| {
        let c = coords[i].as_array();
        let n = |k: usize| {
            c.and_then(|c| c.get(k))
                .and_then(Value::as_f64)
                .unwrap_or(0.0)
        };
        DVec2::new(n(0), n(1))
    };
    let mut sides: HashMap<(usize, usize), usize> = HashMap::new();
    for (f, face) in faces.iter().enumerate() {
        let Some(ids) = face
            .as_array()
            .map(|a| a.iter().map(index).collect::<Option<Vec<_>>>())
            .and_then(|v| v)
        else {
            faults.push(format!("face {f} is not vertex indices in range"));
            continue;
        };
        let mut unique = ids.clone();
        unique.sort_unstable();
        unique.dedup();
        if ids.len() < 3 || unique.len() != ids.len() {
            faults.push(format!("face {f} has fewer than 3 corners or repeats one"));
        }
        let area: f64 = (0..ids.len())
            .map(|k| xy(ids[k]).perp_dot(xy(ids[(k + 1) % ids.len()])))
            .sum();
        if area <= 0.0 {
            faults.push(format!("face {f} is not counter-clockwise"));
        }
        for k in 0..ids.len() {
            let (a, b) = (ids[k], ids[(k + 1) % ids.len()]);
            *sides.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    for (i, (p, l)) in pairs.iter().zip(&letters).enumerate() {
        let n = sides.get(p).copied().unwrap_or(0);
        let expected = match *l {
            "B" => 1,
            "M" | "V" | "F" => 2,
            _ => continue,
        };
        if n != expected {
            faults.push(format!(
                "edge {i} ({l}) is a side of {n} faces, not {expected}"
            ));
        }
    }
    faults
}

fn assert_conforms(name: &str, text: &str) {
    let faults = conformance_faults(text);
    assert!(
        faults.is_empty(),
        "{name}: {} faults, first: {:?}",
        faults.len(),
        &faults[..faults.len().min(5)]
    );
}

fn generated() -> Vec<(&'static str, CreasePattern)> {
    let ok = |r: Result<CreasePattern, _>| {
        r.unwrap_or_else(|e: foldcam::design::classic::ClassicError| panic!("{e}"))
    };
    vec![
        ("miura", ok(MiuraOri::default().build())),
        ("square twist", ok(SquareTwist::default().build())),
        ("waterbomb", ok(Waterbomb::default().build())),
        ("yoshimura", ok(Yoshimura::default().build())),
    ]
}

#[test]
fn generated_patterns_write_conforming_fold_with_fold_angles() {
    for (name, cp) in generated() {
        let text = formats::fold::write_string(&cp, None);
        assert_conforms(name, &text);
        let folds = cp.edges.iter().filter(|e| e.assignment.is_fold());
        assert!(folds.clone().count() > 0);
        for e in folds {
            let a = e.fold_angle.unwrap_or(f64::NAN);
            assert!(a.abs() > 0.0 && a.abs() < 180.0, "{name}: {a}");
        }
    }
}

#[test]
fn generated_patterns_cut_on_card_without_the_fold_angle_warning() {
    let card = foldcam::machine::load_material("card-300gsm").unwrap_or_else(|e| panic!("{e}"));
    let stainless =
        foldcam::machine::load_material("stainless-0.5").unwrap_or_else(|e| panic!("{e}"));
    use foldcam::fab::PlanWarningKind::FoldAngleLimit;
    for (name, cp) in generated() {
        let warnings = foldcam::fab::design_limit_warnings(&cp, &card);
        assert!(
            !warnings.iter().any(|w| w.kind == FoldAngleLimit),
            "{name}: {warnings:?}"
        );
        // The angle is not hidden: a sheet that cannot fold that far still says so.
        let warnings = foldcam::fab::design_limit_warnings(&cp, &stainless);
        assert!(
            warnings
                .iter()
                .any(|w| w.kind == FoldAngleLimit && !w.edges.is_empty()),
            "{name}"
        );
    }
}

/// A drawing of crossing strokes with no faces: the writer planarises it and adds faces.
#[test]
fn a_drawing_without_faces_is_written_with_faces() {
    let mut cp = CreasePattern::new();
    let p = |x: f64, y: f64| DVec2::new(x, y);
    for (a, b) in [
        (p(0.0, 0.0), p(10.0, 0.0)),
        (p(10.0, 0.0), p(10.0, 10.0)),
        (p(10.0, 10.0), p(0.0, 10.0)),
        (p(0.0, 10.0), p(0.0, 0.0)),
    ] {
        cp.add_segment(a, b, Assignment::Boundary);
    }
    cp.add_segment(p(0.0, 0.0), p(10.0, 10.0), Assignment::Valley);
    cp.add_segment(p(0.0, 10.0), p(10.0, 0.0), Assignment::Mountain);
    assert!(cp.faces.is_none());
    let text = formats::fold::write_string(&cp, None);
    assert_conforms("crossing strokes", &text);
    let back = formats::fold::read_str(&text).unwrap_or_else(|e| panic!("{e}"));
    // Four triangles around the crossing, counted independently of the writer.
    assert_eq!(back.pattern.faces.map(|f| f.len()), Some(4));
    // A planar pattern without faces keeps its numbering.
    let ortho = MiuraOri::default()
        .build()
        .unwrap_or_else(|e| panic!("{e}"));
    let mut bare = ortho.clone();
    bare.faces = None;
    let text = formats::fold::write_string(&bare, None);
    let back = formats::fold::read_str(&text).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(back.pattern.vertices, ortho.vertices);
    assert_eq!(
        back.pattern.faces.map(|f| f.len()),
        ortho.faces.map(|f| f.len())
    );
}

#[test]
fn shipped_examples_convert_to_conforming_fold() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/patterns");
    for name in [
        "broken-vertex.fold",
        "flat-vertex.fold",
        "preliminary-base.cp",
    ] {
        let imported = formats::load(&dir.join(name)).unwrap_or_else(|e| panic!("{e}"));
        assert_conforms(name, &formats::fold::write_string(&imported.pattern, None));
    }
}

fn shared(sub: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../shared/testdata")
        .join(sub)
}

fn files(dir: &Path, ext: &str) -> Vec<PathBuf> {
    let mut out: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == ext))
        .collect();
    out.sort();
    out
}

/// Every FOLD and SVG file of the shared test data, read and written back as FOLD, passes.
#[test]
#[ignore = "needs ../shared"]
fn shared_test_data_converts_to_conforming_fold() {
    let mut inputs = files(&shared("fold"), "fold");
    inputs.extend(files(&shared("svg"), "svg"));
    inputs.extend(files(&shared("rabbit-ear"), "svg"));
    assert!(inputs.len() > 25, "{}", inputs.len());
    for path in inputs {
        let imported = formats::load(&path).unwrap_or_else(|e| panic!("{e}"));
        let text = formats::fold::write_string(&imported.pattern, imported.folded.as_ref());
        assert_conforms(&path.display().to_string(), &text);
    }
}
