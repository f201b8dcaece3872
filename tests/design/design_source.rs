//! `foldcam::design::source` through the library: design files recognised by name and
//! content, built with the command line's defaults into the pattern the command writes, and
//! a paper craft's mesh taken only from the files given with it.

use crate::bin;

use std::path::Path;

use bin::{foldcam, repo_file};
use foldcam::design::source::{
    DesignFile, DesignKind, DesignOptions, MeshUse, SourceError, SummaryLine, build_design,
};

fn example(rel: &str) -> Vec<u8> {
    std::fs::read(repo_file(&format!("examples/{rel}"))).unwrap()
}

#[test]
fn design_files_are_recognised_by_name_then_by_content() {
    let cases = [
        ("popup/house.voxel.txt", Some(DesignKind::VoxelText)),
        ("popup/building.obj", Some(DesignKind::Mesh)),
        ("popup/taj-mahal.popup.toml", Some(DesignKind::PopupPolygon)),
        ("folding/bird-base.toml", Some(DesignKind::FoldScript)),
        ("papercraft/vase.craft.toml", Some(DesignKind::PaperCraft)),
        ("patterns/bird-base.cp", None),
    ];
    for (rel, kind) in cases {
        assert_eq!(
            DesignKind::recognise(Path::new(rel), &example(rel)),
            kind,
            "{rel}"
        );
    }
    // A plain `.toml` by its tables: the same designs renamed.
    let renamed = [
        ("popup/taj-mahal.popup.toml", DesignKind::PopupPolygon),
        ("papercraft/vase.craft.toml", DesignKind::PaperCraft),
    ];
    for (rel, kind) in renamed {
        assert_eq!(
            DesignKind::recognise(Path::new("design.toml"), &example(rel)),
            Some(kind),
            "{rel} renamed"
        );
    }
    // A machine profile is no design.
    let machine = std::fs::read(repo_file("machines/grbl-diode.toml")).unwrap();
    assert_eq!(
        DesignKind::recognise(Path::new("grbl-diode.toml"), &machine),
        None
    );
}

/// The pattern `foldcam ARGS … -o out.fold` writes, read back, and what it printed.
fn written(args: &[&str], dir: &Path) -> (foldcam::pattern::CreasePattern, String) {
    let mut all = args.to_vec();
    all.extend(["-o", "out.fold"]);
    let out = foldcam(&all, dir);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let cp = foldcam::load(&dir.join("out.fold")).unwrap().pattern;
    (cp, String::from_utf8_lossy(&out.stdout).into_owned())
}

#[test]
fn a_built_design_is_the_pattern_the_command_writes() {
    let dir = tempfile::tempdir().unwrap();
    let cases: [(&str, &[&str]); 3] = [
        ("popup/tower.voxel.txt", &["popup", "voxel"]),
        ("popup/slanted.popup.toml", &["popup", "poly"]),
        ("folding/preliminary-base.toml", &["fold"]),
    ];
    for (rel, cmd) in cases {
        let bytes = example(rel);
        let name = Path::new(rel);
        let file = DesignFile {
            name,
            bytes: &bytes,
        };
        let mut notes = Vec::new();
        let design = build_design(&file, &[], &DesignOptions::default(), &mut notes).unwrap();
        let input = repo_file(&format!("examples/{rel}"));
        let mut args = cmd.to_vec();
        args.push(&input);
        let (cp, stdout) = written(&args, dir.path());
        assert_eq!(design.pattern.vertices, cp.vertices, "{rel}: vertices");
        let ends = |p: &foldcam::pattern::CreasePattern| -> Vec<_> {
            p.edges.iter().map(|e| (e.vertices, e.assignment)).collect()
        };
        assert_eq!(ends(&design.pattern), ends(&cp), "{rel}: edges");
        // The typed summary: its numbers are the written pattern's, its words what the
        // command printed (which names the file by the path it was given).
        assert!(!design.summary.is_empty(), "{rel}: a summary");
        let (lo, hi) = cp.bounds().unwrap();
        let size = hi - lo;
        for line in &design.summary {
            match line {
                SummaryLine::VoxelCard { sheet_mm, .. } => {
                    assert!(
                        (sheet_mm[0] - size.x).abs() < 1e-6,
                        "{rel}: {line} vs {size}"
                    );
                    assert!(
                        (sheet_mm[1] - size.y).abs() < 1e-6,
                        "{rel}: {line} vs {size}"
                    );
                }
                SummaryLine::PolygonCard {
                    width_mm,
                    base_mm,
                    back_mm,
                    ..
                } => {
                    assert!((width_mm - size.x).abs() < 1e-6, "{rel}: {line} vs {size}");
                    let depth = base_mm + back_mm;
                    assert!((depth - size.y).abs() < 1e-6, "{rel}: {line} vs {size}");
                }
                SummaryLine::FoldSequence {
                    vertices, edges, ..
                } => {
                    assert_eq!(*vertices, cp.vertices.len(), "{rel}");
                    assert_eq!(*edges, cp.edges.len(), "{rel}");
                }
                other => panic!("{rel}: an unexpected line {other:?}"),
            }
            let text = line.to_string();
            let (_, words) = text.split_once(": ").unwrap();
            assert!(stdout.contains(words), "{rel}: {words:?} not in {stdout:?}");
        }
    }
}

#[test]
fn a_paper_craft_takes_its_mesh_only_from_the_files_given_with_it() {
    let design = example("papercraft/vase.craft.toml");
    let mesh = example("papercraft/vase.obj");
    let name = Path::new("vase.craft.toml");
    let file = DesignFile {
        name,
        bytes: &design,
    };
    let options = DesignOptions::default();
    let err = build_design(&file, &[], &options, &mut Vec::new()).unwrap_err();
    assert!(matches!(err, SourceError::MissingMesh { .. }), "{err}");
    assert!(
        err.to_string()
            .contains("drop vase.obj together with vase.craft.toml"),
        "{err}"
    );
    // A file of another name is not taken for it.
    let other = DesignFile {
        name: Path::new("other.obj"),
        bytes: &mesh,
    };
    assert!(build_design(&file, &[other], &options, &mut Vec::new()).is_err());
    let given = DesignFile {
        name: Path::new("vase.obj"),
        bytes: &mesh,
    };
    let built = build_design(&file, &[given], &options, &mut Vec::new()).unwrap();
    assert_eq!(built.kind, DesignKind::PaperCraft);
    assert!(!built.pattern.edges.is_empty());
}

#[test]
fn a_mesh_given_alone_becomes_a_tessellation_when_open_and_a_card_when_closed() {
    let opts = |mesh_use| DesignOptions {
        mesh_use,
        ..DesignOptions::default()
    };
    let dome = example("tessellation/dome.obj");
    let file = DesignFile {
        name: Path::new("dome.obj"),
        bytes: &dome,
    };
    let auto = build_design(&file, &[], &opts(MeshUse::Auto), &mut Vec::new()).unwrap();
    assert!(auto.made.contains("Tachi"), "{}", auto.made);
    assert!(
        auto.folded.is_some(),
        "a tessellation carries its folded form"
    );
    let card = build_design(&file, &[], &opts(MeshUse::PopupCard), &mut Vec::new()).unwrap();
    assert!(card.made.contains("Mitani"), "{}", card.made);
    let building = example("popup/building.obj");
    let closed = DesignFile {
        name: Path::new("building.obj"),
        bytes: &building,
    };
    let auto = build_design(&closed, &[], &opts(MeshUse::Auto), &mut Vec::new()).unwrap();
    assert!(auto.made.contains("Mitani"), "{}", auto.made);
}
