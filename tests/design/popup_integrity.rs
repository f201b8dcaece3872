//! Pop-up cards hold together and close within their outline: every bundled example and a
//! sweep of mesh resolutions and thin-top widths, built by the `foldcam` binary and read
//! back from the FOLD file it writes, has no piece cut free on every side (found by an
//! independent flood over the faces through edges that are not cut), and either closes
//! within its outline, is given the paper it needs by `--fit` (tests/design/popup_fit.rs), or is
//! refused.

use crate::bin;

use bin::{foldcam, repo_file};

use std::path::Path;

use foldcam::design::popup::{loose_pieces, loose_pieces_where};
use foldcam::pattern::{Assignment, CreasePattern, Face};
use glam::DVec2;

fn example(name: &str) -> String {
    repo_file(&format!("examples/popup/{name}"))
}

/// Pieces of the card written to `out` (re-read from the file) that fall out, leaving aside
/// cut-outs by design: every fold of a pop-up card runs parallel to the central fold (x),
/// so a piece without an edge along x was never meant to be held (a slanted diamond opening).
fn loose_in(out: &Path) -> usize {
    let cp = foldcam::formats::load(out)
        .expect("the card reads back")
        .pattern;
    let along_x = |f: &Face| {
        let ring = &f.outer;
        (0..ring.len()).any(|i| {
            let (a, b) = (
                cp.position(ring[i]),
                cp.position(ring[(i + 1) % ring.len()]),
            );
            (a.y - b.y).abs() < 1e-6 && a.x != b.x
        })
    };
    loose_pieces_where(&cp, along_x).len()
}

/// Builds a card with `args`; asserts that it is written without loose pieces, or refused
/// with exit 1 and nothing written. Returns whether it was written.
fn assert_holds(label: &str, args: &[&str], dir: &Path) -> bool {
    let out = dir.join("card.fold");
    let _ = std::fs::remove_file(&out);
    let mut all = args.to_vec();
    all.extend(["-o", "card.fold"]);
    let o = foldcam(&all, dir);
    let stdout = String::from_utf8_lossy(&o.stdout);
    match o.status.code() {
        Some(0) => {
            assert_eq!(loose_in(&out), 0, "{label}: loose pieces\n{stdout}");
            true
        }
        Some(1) => {
            assert!(!out.exists(), "{label}: refused but written");
            assert!(
                stdout.contains("would") || stdout.contains("beyond"),
                "{label}: {stdout}"
            );
            false
        }
        _ => panic!("{label}: {}", String::from_utf8_lossy(&o.stderr)),
    }
}

#[test]
fn building_mesh_sweep_keeps_every_piece() {
    let dir = tempfile::tempdir().unwrap();
    let mesh = example("building.obj");
    for resolution in ["80", "160", "320"] {
        for thin in ["0", "1", "2"] {
            let label = format!("building --resolution {resolution} --thin-top {thin}");
            let args = [
                "popup",
                "voxel",
                mesh.as_str(),
                "--resolution",
                resolution,
                "--thin-top",
                thin,
            ];
            // The defaults (and this sweep) used to drop strips cut on every side; now
            // every card is written whole.
            assert!(assert_holds(&label, &args, dir.path()), "{label}: refused");
        }
    }
}

#[test]
fn bundled_examples_hold_together_and_fit_or_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let cases: Vec<(String, Vec<String>)> = [
        ("voxel", "house.voxel.txt"),
        ("voxel", "tower.voxel.txt"),
        ("voxel", "building.obj"),
        ("poly", "house-door.popup.toml"),
        ("poly", "slanted.popup.toml"),
        ("poly", "taj-mahal.popup.toml"),
    ]
    .into_iter()
    .map(|(kind, name)| {
        (
            name.to_string(),
            vec!["popup".into(), kind.into(), example(name)],
        )
    })
    .collect();
    for (name, args) in &cases {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        assert!(assert_holds(name, &args, dir.path()), "{name}: refused");
        // Closed, the card stays within its outline, or --fit refuses it.
        let mut fit = args.clone();
        fit.push("--fit");
        let fits = assert_holds(&format!("{name} --fit"), &fit, dir.path());
        // A card that fits as it is (--fit added nothing) closes without a warning.
        let fit_run = foldcam(
            &fit.iter()
                .copied()
                .chain(["-o", "f.fold"])
                .collect::<Vec<_>>(),
            dir.path(),
        );
        let grown = String::from_utf8_lossy(&fit_run.stderr).contains("--fit added");
        if fits && !grown {
            let o = foldcam(
                &args
                    .iter()
                    .copied()
                    .chain(["-o", "x.fold"])
                    .collect::<Vec<_>>(),
                dir.path(),
            );
            let err = String::from_utf8_lossy(&o.stderr);
            assert!(!err.contains("beyond"), "{name}: warned yet fits\n{err}");
        }
    }
}

/// A 100 × 60 sheet folded at y = 30 with a 10 × 20 flap cut on three sides (held by its
/// crease) and, when `loose`, a strip cut on all four sides.
fn sheet_with_flap(loose: bool) -> CreasePattern {
    let mut cp = CreasePattern::new();
    let mut seg = |a: (f64, f64), b: (f64, f64), kind| {
        cp.add_segment(DVec2::new(a.0, a.1), DVec2::new(b.0, b.1), kind);
    };
    for (a, b) in [
        ((0.0, 0.0), (100.0, 0.0)),
        ((100.0, 0.0), (100.0, 60.0)),
        ((100.0, 60.0), (0.0, 60.0)),
        ((0.0, 60.0), (0.0, 0.0)),
    ] {
        seg(a, b, Assignment::Boundary);
    }
    seg((0.0, 30.0), (100.0, 30.0), Assignment::Valley);
    seg((10.0, 5.0), (20.0, 5.0), Assignment::Cut);
    seg((10.0, 5.0), (10.0, 25.0), Assignment::Cut);
    seg((20.0, 5.0), (20.0, 25.0), Assignment::Cut);
    seg((10.0, 25.0), (20.0, 25.0), Assignment::Mountain);
    if loose {
        for (a, b) in [
            ((40.0, 40.0), (42.0, 40.0)),
            ((42.0, 40.0), (42.0, 52.0)),
            ((42.0, 52.0), (40.0, 52.0)),
            ((40.0, 52.0), (40.0, 40.0)),
        ] {
            seg(a, b, Assignment::Cut);
        }
    }
    foldcam::pattern::planarize(&mut cp, &Default::default()).unwrap();
    cp
}

#[test]
fn a_strip_cut_on_every_side_is_loose_and_a_hinged_flap_is_not() {
    assert!(loose_pieces(&sheet_with_flap(false)).is_empty());
    let loose = loose_pieces(&sheet_with_flap(true));
    assert_eq!(loose.len(), 1);
    assert!((loose[0].area_mm2 - 24.0).abs() < 1e-9, "{:?}", loose[0]);
    assert_eq!(loose[0].min, DVec2::new(40.0, 40.0));
    assert_eq!(loose[0].max, DVec2::new(42.0, 52.0));
}
