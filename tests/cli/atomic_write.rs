//! The failure paths of atomic writes: the target keeps its old contents and no temporary
//! file is left behind.

use crate::bin;

use bin::listing;
use foldcam::formats::write_atomic;

#[test]
fn a_failed_rename_leaves_the_target_and_no_temporary() {
    let dir = tempfile::tempdir().expect("temp dir");
    // The target is a non-empty folder: the temporary is written, the rename over it fails.
    let target = dir.path().join("out.fold");
    std::fs::create_dir(&target).expect("folder");
    std::fs::write(target.join("keep.txt"), "OLD").expect("write");
    let err = write_atomic(&target, b"NEW").expect_err("cannot replace a folder");
    assert!(!err.to_string().is_empty());
    assert_eq!(
        listing(dir.path()),
        vec!["out.fold".to_string()],
        "no temporary left"
    );
    assert_eq!(
        std::fs::read_to_string(target.join("keep.txt")).expect("kept"),
        "OLD"
    );
}

#[test]
fn a_missing_folder_is_an_error_and_a_success_replaces_whole() {
    let dir = tempfile::tempdir().expect("temp dir");
    let err = write_atomic(&dir.path().join("no/such/dir/x.fold"), b"NEW");
    assert_eq!(
        err.expect_err("no folder").kind(),
        std::io::ErrorKind::NotFound
    );
    let file = dir.path().join("x.fold");
    std::fs::write(&file, "OLD CONTENTS THAT ARE LONGER").expect("write");
    write_atomic(&file, b"NEW").expect("written");
    assert_eq!(std::fs::read_to_string(&file).expect("read"), "NEW");
    assert_eq!(listing(dir.path()), vec!["x.fold".to_string()]);
}
