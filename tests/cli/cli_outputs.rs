//! Commands with several outputs write all of them or none: a run that fails on one output
//! (a missing folder, a wrong extension, the input named as output) leaves every existing
//! file as it was and no temporary behind.

use crate::bin;

use bin::{foldcam, listing, repo_file as example};

/// Runs `args` in a folder holding `k.fold` = "OLD": the run must exit 2, naming `culprit`,
/// and leave `k.fold` and the folder exactly as they were.
fn assert_untouched(args: &[&str], culprit: &str) {
    let dir = tempfile::tempdir().expect("temp dir");
    std::fs::write(dir.path().join("k.fold"), "OLD").expect("write");
    let o = foldcam(args, dir.path());
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
    assert!(err.contains(culprit), "{args:?}: {err}");
    assert_eq!(
        std::fs::read_to_string(dir.path().join("k.fold")).expect("kept"),
        "OLD",
        "{args:?} replaced k.fold"
    );
    assert_eq!(listing(dir.path()), vec!["k.fold"], "{args:?}");
}

#[test]
fn fold_keeps_every_output_when_its_picture_cannot_be_written() {
    let script = example("examples/folding/waterbomb-base.toml");
    assert_untouched(
        &["fold", &script, "-o", "k.fold", "--png", "nodir/x.png"],
        "nodir/x.png",
    );
    assert_untouched(
        &["fold", &script, "-o", "k.fold", "--gif", "x.png"],
        "x.png",
    );
}

#[test]
fn popup_commands_keep_every_output_on_failure() {
    let house = example("examples/popup/house.voxel.txt");
    assert_untouched(
        &[
            "popup",
            "voxel",
            &house,
            "-o",
            "k.fold",
            "--png",
            "nodir/x.png",
        ],
        "nodir/x.png",
    );
    assert_untouched(
        &[
            "popup",
            "voxel",
            &house,
            "-o",
            "k.fold",
            "--save-voxels",
            "nodir/v.txt",
        ],
        "nodir/v.txt",
    );
    assert_untouched(
        &["popup", "voxel", &house, "-o", "k.fold", "--png", "x.jpg"],
        "x.jpg",
    );
    let taj = example("examples/popup/taj-mahal.popup.toml");
    assert_untouched(
        &[
            "popup",
            "poly",
            &taj,
            "-o",
            "k.fold",
            "--gif",
            "nodir/x.gif",
        ],
        "nodir/x.gif",
    );
}

#[test]
fn papercraft_and_tessellate_keep_every_output_on_failure() {
    let vase = example("examples/papercraft/vase.craft.toml");
    assert_untouched(
        &["papercraft", &vase, "-o", "k.fold", "--svg", "nodir/v.svg"],
        "nodir/v",
    );
    let dome = example("examples/tessellation/dome.obj");
    assert_untouched(
        &[
            "tessellate",
            &dome,
            "-o",
            "k.fold",
            "--cp-png",
            "nodir/x.png",
        ],
        "nodir/x.png",
    );
}

#[test]
fn an_output_may_not_overwrite_the_input() {
    let dir = tempfile::tempdir().expect("temp dir");
    let script = dir.path().join("s.toml");
    std::fs::copy(example("examples/folding/waterbomb-base.toml"), &script).expect("copy");
    let before = std::fs::read(&script).expect("read");
    let o = foldcam(
        &["fold", "s.toml", "-o", "k.fold", "--png", "s.toml"],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(2));
    // Either refused as the input or as a PNG without the .png extension: never written.
    assert_eq!(std::fs::read(&script).expect("read"), before);
    let o = foldcam(&["fold", "s.toml", "-o", "./s.toml"], dir.path());
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("overwrite the input"), "{err}");
    assert_eq!(std::fs::read(&script).expect("read"), before);
    assert_eq!(listing(dir.path()), vec!["s.toml"]);
}
