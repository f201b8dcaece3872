//! DXF writer: layers and entities per operation, R12 without LWPOLYLINE, R2000 units, and
//! `ezdxf audit` (skipped with a message when python3 or ezdxf is missing).

use crate::post_common;

use std::collections::BTreeMap;
use std::process::Command;

use foldcam::fab::Operation;
use foldcam::post::{DxfVersion, PostError, dxf};
use glam::{DVec2, dvec2};
use post_common::{job, plan, toolpath};

/// Group-code/value pairs of a DXF text.
fn pairs(text: &str) -> Vec<(i32, String)> {
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len() % 2, 0, "odd number of lines");
    lines
        .chunks(2)
        .map(|c| (c[0].trim().parse().expect("group code"), c[1].to_string()))
        .collect()
}

/// Entity type and layer of every entity in the ENTITIES section (VERTEX/SEQEND excluded).
fn entities(text: &str) -> Vec<(String, String)> {
    let pairs = pairs(text);
    let start = pairs
        .iter()
        .position(|p| p == &(2, "ENTITIES".into()))
        .unwrap();
    let mut out: Vec<(String, String)> = Vec::new();
    for (code, value) in &pairs[start + 1..] {
        match (code, value.as_str()) {
            (0, "ENDSEC") => break,
            (0, "VERTEX" | "SEQEND") => out.push((value.clone(), String::new())),
            (0, kind) => out.push((kind.to_string(), String::new())),
            (8, layer) => out.last_mut().unwrap().1 = layer.to_string(),
            _ => {}
        }
    }
    out.retain(|(kind, _)| kind != "VERTEX" && kind != "SEQEND");
    out
}

fn per_layer(entities: &[(String, String)]) -> BTreeMap<String, usize> {
    let mut counts = BTreeMap::new();
    for (_, layer) in entities {
        *counts.entry(layer.clone()).or_default() += 1;
    }
    counts
}

fn text(version: DxfVersion) -> String {
    let plan = plan(job());
    String::from_utf8(dxf(&plan, &plan.jobs[0], version).unwrap()).unwrap()
}

/// Strokes per layer in the fixture: one mark, one score, three dashes, one cut (the other
/// cut stroke has no length).
fn expected() -> BTreeMap<String, usize> {
    [("CUT", 1), ("MARK", 1), ("PERFORATE", 3), ("SCORE", 1)]
        .map(|(l, n)| (l.to_string(), n))
        .into()
}

#[test]
fn one_entity_per_stroke_on_its_operation_layer() {
    for version in [DxfVersion::R2000, DxfVersion::R12] {
        assert_eq!(
            per_layer(&entities(&text(version))),
            expected(),
            "{version:?}"
        );
    }
}

#[test]
fn r12_has_no_lwpolyline_and_no_insunits() {
    let t = text(DxfVersion::R12);
    assert!(t.contains("AC1009"));
    assert!(!t.contains("LWPOLYLINE") && !t.contains("$INSUNITS"));
    let kinds: Vec<_> = entities(&t).into_iter().map(|(k, _)| k).collect();
    assert!(kinds.contains(&"LINE".to_string()) && kinds.contains(&"POLYLINE".to_string()));
}

#[test]
fn r2000_is_millimetres_with_lwpolylines() {
    let t = text(DxfVersion::R2000);
    let p = pairs(&t);
    let at = p
        .iter()
        .position(|x| x == &(9, "$INSUNITS".into()))
        .unwrap();
    assert_eq!(p[at + 1], (70, "4".into()));
    assert!(p.contains(&(1, "AC1015".into())));
    assert!(entities(&t).iter().all(|(k, _)| k == "LWPOLYLINE"));
}

#[test]
fn layers_are_named_and_coloured() {
    let p = pairs(&text(DxfVersion::R2000));
    for (name, aci) in [
        ("CUT", "1"),
        ("PERFORATE", "3"),
        ("SCORE", "5"),
        ("MARK", "7"),
    ] {
        let at = p
            .iter()
            .position(|x| x == &(2, name.to_string()))
            .expect(name);
        let colour = p[at..].iter().find(|x| x.0 == 62).unwrap();
        assert_eq!(colour.1, aci, "{name}");
    }
    assert!(
        !p.contains(&(2, "PLOT".into())),
        "no layer for an absent operation"
    );
}

#[test]
fn closed_contours_are_closed_and_coordinates_clean() {
    let t = text(DxfVersion::R2000);
    assert!(t.contains("56.744\n") && !t.contains("56.7440000"));
    assert!(!t.contains("NaN") && !t.contains("inf") && !t.contains("e-"));
    let p = pairs(&t);
    let cut = p.iter().position(|x| x == &(8, "CUT".into())).unwrap();
    let count = p[cut..].iter().find(|x| x.0 == 90).unwrap();
    let flag = p[cut..].iter().find(|x| x.0 == 70).unwrap();
    assert_eq!((count.1.as_str(), flag.1.as_str()), ("4", "1"));
}

#[test]
fn bad_and_empty_jobs_are_errors() {
    let mut bad = plan(job());
    bad.jobs[0].paths[0].strokes[0][0].y = f64::NAN;
    let err = dxf(&bad, &bad.jobs[0], DxfVersion::R2000).unwrap_err();
    assert!(matches!(err, PostError::BadCoordinate { .. }));
    let mut empty = plan(job());
    empty.jobs[0].paths = vec![toolpath(Operation::Cut, vec![vec![dvec2(1.0, 1.0)]])];
    let err = dxf(&empty, &empty.jobs[0], DxfVersion::R12).unwrap_err();
    assert!(matches!(err, PostError::EmptyJob { .. }));
}

/// Audits a file with ezdxf and counts its model-space entities per layer: prints
/// `errors fixes` on the first line, then `LAYER COUNT` lines.
const AUDIT: &str = r##"
import sys, collections, ezdxf
doc = ezdxf.readfile(sys.argv[1])
auditor = doc.audit()
print(len(auditor.errors), len(auditor.fixes))
for e in auditor.errors + auditor.fixes:
    print("-", e.message, file=sys.stderr)
counts = collections.Counter(e.dxf.layer for e in doc.modelspace())
for layer, n in sorted(counts.items()):
    print(layer, n)
"##;

fn ezdxf_available() -> bool {
    let probe = Command::new("python3")
        .args(["-c", "import ezdxf"])
        .output();
    probe.is_ok_and(|o| o.status.success())
}

#[test]
#[ignore = "needs python3 with ezdxf (pip install ezdxf); .ci/run installs it"]
fn ezdxf_audit_is_clean_and_counts_match() {
    let _alone = post_common::external_tools_alone();
    assert!(
        ezdxf_available(),
        "python3 with ezdxf is not available (pip install ezdxf)"
    );
    let dir = tempfile::tempdir().unwrap();
    for version in [DxfVersion::R2000, DxfVersion::R12] {
        let file = dir.path().join(format!("{version:?}.dxf"));
        std::fs::write(&file, text(version)).unwrap();
        let out = Command::new("python3")
            .args(["-c", AUDIT])
            .arg(&file)
            .output()
            .unwrap();
        let stdout = String::from_utf8_lossy(&out.stdout);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "{version:?}: ezdxf failed:\n{stderr}");
        let mut lines = stdout.lines();
        assert_eq!(
            lines.next(),
            Some("0 0"),
            "{version:?}: audit not clean:\n{stderr}"
        );
        let counts: BTreeMap<String, usize> = lines
            .map(|l| l.split_once(' ').unwrap())
            .map(|(layer, n)| (layer.to_string(), n.parse().unwrap()))
            .collect();
        assert_eq!(counts, expected(), "{version:?}");
    }
}

#[test]
fn the_dxf_crate_reads_back_every_entity_and_layer() {
    for version in [DxfVersion::R2000, DxfVersion::R12] {
        let t = text(version);
        let drawing = ::dxf::Drawing::load(&mut t.as_bytes()).expect("readable DXF");
        let mut counts = BTreeMap::new();
        for e in drawing.entities() {
            *counts.entry(e.common.layer.clone()).or_default() += 1;
        }
        assert_eq!(counts, expected(), "{version:?}");
        // Every point read back lies where the job put it (machine coordinates, mm), stroke
        // by stroke on its operation's layer; a closed polyline repeats its first point.
        let mut read: BTreeMap<String, Vec<Vec<DVec2>>> = BTreeMap::new();
        for e in drawing.entities() {
            let points: Vec<DVec2> = match &e.specific {
                ::dxf::entities::EntityType::Line(l) => {
                    vec![dvec2(l.p1.x, l.p1.y), dvec2(l.p2.x, l.p2.y)]
                }
                ::dxf::entities::EntityType::LwPolyline(p) => {
                    let mut v: Vec<DVec2> = p.vertices.iter().map(|v| dvec2(v.x, v.y)).collect();
                    if p.is_closed() {
                        v.push(v[0]);
                    }
                    v
                }
                ::dxf::entities::EntityType::Polyline(p) => {
                    let mut v: Vec<DVec2> = p
                        .vertices()
                        .map(|v| dvec2(v.location.x, v.location.y))
                        .collect();
                    if p.is_closed() {
                        v.push(v[0]);
                    }
                    v
                }
                other => panic!("{version:?}: unexpected entity {other:?}"),
            };
            read.entry(e.common.layer.clone()).or_default().push(points);
        }
        let job = job();
        for path in &job.paths {
            let layer = path.op.name().to_uppercase();
            let strokes: Vec<&Vec<DVec2>> = path
                .strokes
                .iter()
                .filter(|s| s.windows(2).any(|w| w[0].distance(w[1]) > 1e-3))
                .collect();
            let got = &read[&layer];
            assert_eq!(got.len(), strokes.len(), "{version:?} {layer}");
            for (want, got) in strokes.iter().zip(got) {
                assert_eq!(want.len(), got.len(), "{version:?} {layer}");
                for (w, g) in want.iter().zip(got) {
                    assert!(w.distance(*g) < 1e-3, "{version:?} {layer}: {g} for {w}");
                }
            }
        }
        let cut = drawing
            .layers()
            .find(|l| l.name == "CUT")
            .expect("CUT layer");
        assert_eq!(cut.color.index(), Some(1), "{version:?}");
    }
}
