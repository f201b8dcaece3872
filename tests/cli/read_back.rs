//! Every crease pattern foldcam writes is one foldcam reads: each command's pattern outputs
//! (FOLD with every frame, SVG, ORIPA `.cp` and `.opx`) are read back by `check`, which exits
//! 0 (pass) or 1 (findings) and never 2 (a file it refuses).

use crate::bin;

use bin::{foldcam, repo_file as example};
use std::path::Path;

/// Runs `args` in `dir`; it must succeed or report findings (exit 0 or 1).
fn run(args: &[&str], dir: &Path) {
    let o = foldcam(args, dir);
    assert!(
        matches!(o.status.code(), Some(0 | 1)),
        "{args:?}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
}

/// Frames in a FOLD file: the key frame and its `file_frames`.
fn frames(path: &Path) -> usize {
    let text = std::fs::read_to_string(path).unwrap();
    let json: serde_json::Value = serde_json::from_str(&text).unwrap();
    1 + json["file_frames"].as_array().map_or(0, Vec::len)
}

#[test]
fn every_pattern_any_command_writes_is_read_back_by_check() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let bird = example("examples/patterns/bird-base.cp");
    for kind in ["miura", "square-twist", "waterbomb", "yoshimura"] {
        for ext in ["fold", "svg", "cp"] {
            run(&["generate", kind, "-o", &format!("{kind}.{ext}")], d);
        }
    }
    for ext in ["fold", "svg", "cp", "opx"] {
        run(&["convert", &bird, &format!("bird.{ext}")], d);
    }
    run(
        &[
            "fold",
            &example("examples/folding/bird-base.toml"),
            "-o",
            "sequence.fold",
        ],
        d,
    );
    run(&["fold-flat", &bird, "-o", "flat-folded.fold"], d);
    // Folded all the way, the Miura's creases reach ±180°: the written angles stay in range.
    run(
        &[
            "fold3d",
            "miura.fold",
            "--percent",
            "100",
            "-o",
            "fold3d.fold",
        ],
        d,
    );
    run(
        &[
            "popup",
            "voxel",
            &example("examples/popup/house.voxel.txt"),
            "-o",
            "house.fold",
        ],
        d,
    );
    for ext in ["fold", "svg"] {
        run(
            &[
                "popup",
                "poly",
                &example("examples/popup/taj-mahal.popup.toml"),
                "-o",
                &format!("taj.{ext}"),
            ],
            d,
        );
    }
    run(
        &[
            "papercraft",
            &example("examples/papercraft/vase.craft.toml"),
            "-o",
            "vase.fold",
            "--svg",
            "vase.svg",
        ],
        d,
    );
    run(
        &[
            "tessellate",
            &example("examples/tessellation/dome.obj"),
            "-x",
            "stainless-0.5",
            "-o",
            "dome.fold",
        ],
        d,
    );
    let mut checked = 0;
    let mut files = 0;
    let mut names: Vec<_> = std::fs::read_dir(d)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    names.sort();
    for path in &names {
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
        let count = match ext {
            "fold" => frames(path),
            "svg" | "cp" | "opx" => 1,
            _ => continue,
        };
        files += 1;
        for frame in 0..count {
            let file = path.to_str().unwrap();
            let frame_arg = frame.to_string();
            let mut args = vec!["check", file];
            if ext == "fold" {
                args.extend(["--fold-frame", &frame_arg]);
            }
            let o = foldcam(&args, d);
            assert!(
                matches!(o.status.code(), Some(0 | 1)),
                "foldcam refuses its own {} (frame {frame}): {}",
                path.display(),
                String::from_utf8_lossy(&o.stderr)
            );
            checked += 1;
        }
    }
    // 12 generated, 4 converted, sequence, fold-flat, fold3d, house, taj ×2, vase ×2, dome;
    // and the FOLD files' further frames.
    assert_eq!(files, 25, "{names:?}");
    assert!(checked > files, "{checked} frames checked");
}
