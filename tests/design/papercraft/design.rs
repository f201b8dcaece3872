use std::path::Path;

use foldcam::design::papercraft::PapercraftError;
use foldcam::design::papercraft::parse_design;
use foldcam::mesh::ReferenceMesh;
use foldcam::mesh::read_mesh;

use super::support::{assert_cuts_clean_on_paper, side_lengths};

fn vase_text() -> String {
    std::fs::read_to_string("examples/papercraft/vase.craft.toml").unwrap()
}

#[test]
fn the_vase_example_builds_cuts_clean_and_its_gores_match() {
    let design = parse_design(&vase_text()).unwrap();
    let mesh = read_mesh(&Path::new("examples/papercraft").join(&design.mesh)).unwrap();
    let made = design.build(&ReferenceMesh::new(&mesh).unwrap()).unwrap();
    assert_eq!(made.parts.len(), 8);
    assert!(made.parts.iter().all(|p| p.dropped_tabs == 0));
    // The gores are mirror images across each meridian plane, so they meet on the shared
    // wall: the two sides glued together have the same length, up to the 1e-4 mm rounding of
    // the design file's coordinates and the two polylines' different refinements (0.05 mm
    // tolerance).
    for meridian in 0..8 {
        let lengths = side_lengths(&made, meridian);
        assert_eq!(lengths.len(), 2, "meridian {meridian} joins two gores");
        assert!(
            (lengths[0] - lengths[1]).abs() < 1e-3,
            "meridian {meridian}: {lengths:?}"
        );
        assert!(
            lengths[0] > 100.0,
            "a meridian is longer than the vase is tall"
        );
    }
    for (s, cp) in made.sheets.iter().enumerate() {
        assert_cuts_clean_on_paper(&format!("vase sheet {s}"), cp);
    }
}

#[test]
fn bad_designs_name_the_problem() {
    let unknown = vase_text().replacen("scale = 1.0", "scale = 1.0\ncolour = 3", 1);
    assert!(
        matches!(parse_design(&unknown), Err(PapercraftError::BadParameter(m)) if m.contains("colour"))
    );
    let zero = vase_text().replacen("scale = 1.0", "scale = 0.0", 1);
    assert!(matches!(
        parse_design(&zero),
        Err(PapercraftError::BadParameter(_))
    ));
    // Gore 0 listing a rim arc of another gore: its loop no longer closes.
    let open = vase_text().replacen("cut_lines = [8, 1, 16, 0]", "cut_lines = [8, 1, 17, 0]", 1);
    assert_ne!(open, vase_text());
    let design = parse_design(&open).unwrap();
    let mesh = read_mesh(Path::new("examples/papercraft/vase.obj")).unwrap();
    let err = design
        .build(&ReferenceMesh::new(&mesh).unwrap())
        .unwrap_err();
    assert!(
        matches!(err, PapercraftError::OpenLoop { patch: 0, .. }),
        "{err}"
    );
}

#[test]
fn the_cli_writes_every_sheet() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("vase.fold");
    let svg = dir.path().join("vase.svg");
    // On A5 the eight gores need several sheets (on A4 they fit on one).
    let mesh = std::fs::canonicalize("examples/papercraft/vase.obj").unwrap();
    let a5 = vase_text()
        .replacen(
            "mesh = \"vase.obj\"",
            &format!("mesh = {:?}", mesh.display().to_string()),
            1,
        )
        .replacen(
            "width = 210.0\nheight = 297.0",
            "width = 148.0\nheight = 210.0",
            1,
        );
    assert!(a5.contains("height = 210.0"));
    let design = dir.path().join("vase.craft.toml");
    std::fs::write(&design, a5).unwrap();
    let status = std::process::Command::new(env!("CARGO_BIN_EXE_foldcam"))
        .arg("papercraft")
        .arg(&design)
        .arg("-o")
        .arg(&out)
        .arg("--svg")
        .arg(&svg)
        .output()
        .unwrap();
    assert!(
        status.status.success(),
        "{}",
        String::from_utf8_lossy(&status.stderr)
    );
    let stdout = String::from_utf8_lossy(&status.stdout);
    assert!(stdout.contains("8 parts"), "{stdout}");
    let sheets: usize = stdout
        .lines()
        .flat_map(|l| l.split(", "))
        .find_map(|s| s.strip_suffix(" sheet(s)"))
        .and_then(|n| n.parse().ok())
        .unwrap_or(0);
    assert!(sheets >= 2, "{stdout}");
    for s in 1..=sheets {
        let suffix = if s == 1 {
            String::new()
        } else {
            format!("-{s}")
        };
        for ext in ["fold", "svg"] {
            let name = format!("vase{suffix}.{ext}");
            assert!(dir.path().join(&name).exists(), "{name} missing");
        }
    }
    assert!(
        !dir.path()
            .join(format!("vase-{}.fold", sheets + 1))
            .exists()
    );
    let loaded = foldcam::formats::load(&out).unwrap();
    assert!(
        loaded
            .pattern
            .edges
            .iter()
            .any(|e| e.assignment == foldcam::pattern::Assignment::Mountain)
    );
    // A missing design is exit status 2 with the path named.
    let missing = std::process::Command::new(env!("CARGO_BIN_EXE_foldcam"))
        .args(["papercraft", "no-such.craft.toml", "-o"])
        .arg(&out)
        .output()
        .unwrap();
    assert_eq!(missing.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&missing.stderr).contains("no-such.craft.toml"));
}

/// The vase with gore 0's patch tilted off the mesh (its ruling leaning 31° out of the
/// horizontal plane), its mesh named by absolute path.
fn tilted_vase(dir: &Path) -> std::path::PathBuf {
    let mesh = std::fs::canonicalize("examples/papercraft/vase.obj").unwrap();
    let text = vase_text()
        .replacen(
            "mesh = \"vase.obj\"",
            &format!("mesh = {:?}", mesh.display().to_string()),
            1,
        )
        .replacen(
            "ruling = [-0.3827, 0.9239, 0.0000]",
            "ruling = [-0.3827, 0.9239, 0.6]",
            1,
        );
    assert!(text.contains("0.9239, 0.6]"));
    let path = dir.join("tilted.craft.toml");
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn seams_are_the_glued_sides_lengths_and_the_vase_glues() {
    let design = parse_design(&vase_text()).unwrap();
    let mesh = read_mesh(Path::new("examples/papercraft/vase.obj")).unwrap();
    let made = design.build(&ReferenceMesh::new(&mesh).unwrap()).unwrap();
    // Every cut line between two gores (8 meridians; foot and rim lines border one part).
    assert_eq!(made.seams.len(), 8, "{:?}", made.seams);
    for s in &made.seams {
        let mut lengths = side_lengths(&made, s.cut_line);
        lengths.sort_by(f64::total_cmp);
        let mut ours = s.lengths_mm;
        ours.sort_by(f64::total_cmp);
        assert!((ours[0] - lengths[0]).abs() < 1e-9 && (ours[1] - lengths[1]).abs() < 1e-9);
        assert!(s.glues(), "{s}");
    }
}

#[test]
fn the_cli_names_glued_edges_that_differ_and_exits_1() {
    let dir = tempfile::tempdir().unwrap();
    let design = tilted_vase(dir.path());
    let run = |extra: &[&str], out: &str| {
        std::process::Command::new(env!("CARGO_BIN_EXE_foldcam"))
            .arg("papercraft")
            .arg(&design)
            .arg("-o")
            .arg(dir.path().join(out))
            .args(extra)
            .output()
            .unwrap()
    };
    let refused = run(&[], "a.fold");
    let stderr = String::from_utf8_lossy(&refused.stderr);
    assert_eq!(refused.status.code(), Some(1), "{stderr}");
    // The seams named are those the library measures beyond the tolerance, with both lengths.
    let text = std::fs::read_to_string(&design).unwrap();
    let made = parse_design(&text)
        .unwrap()
        .build(
            &ReferenceMesh::new(&read_mesh(Path::new("examples/papercraft/vase.obj")).unwrap())
                .unwrap(),
        )
        .unwrap();
    let bad: Vec<_> = made.seams.iter().filter(|s| !s.glues()).collect();
    assert!(
        !bad.is_empty(),
        "the tilted gore fits badly: {:?}",
        made.seams
    );
    for s in &bad {
        assert!(s.mismatch_mm() > 0.1);
        assert!(
            stderr.contains(&format!(
                "cut line {}: {:.2} mm",
                s.cut_line, s.lengths_mm[0]
            )),
            "{stderr}"
        );
    }
    assert!(
        dir.path().join("a.fold").exists(),
        "the parts are written to be looked at"
    );
    let allowed = run(&["--allow-mismatch"], "b.fold");
    assert!(
        allowed.status.success(),
        "{}",
        String::from_utf8_lossy(&allowed.stderr)
    );
    assert!(String::from_utf8_lossy(&allowed.stderr).contains("warning: cut line"));
}
