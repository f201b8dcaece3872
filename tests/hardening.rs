//! Hostile inputs from the hardening review end with a clear refusal (exit 2, the option and
//! the limit named), never a hang or a panic.

#[path = "common/bin.rs"]
mod bin;

use bin::foldcam;

#[test]
fn generators_refuse_sizes_beyond_a_kilometre() {
    let dir = tempfile::tempdir().expect("temp dir");
    for kind in ["miura", "square-twist", "waterbomb", "yoshimura"] {
        for (option, value) in [
            ("--width", "1e200"),
            ("--width", "1e308"),
            ("--height", "1e308"),
        ] {
            if kind == "waterbomb" && option == "--height" {
                continue;
            }
            let o = foldcam(
                &["generate", kind, "-o", "g.fold", option, value],
                dir.path(),
            );
            let err = String::from_utf8_lossy(&o.stderr);
            assert_eq!(o.status.code(), Some(2), "{kind} {option} {value}: {err}");
            assert!(
                err.contains("1,000,000 mm"),
                "{kind} {option} {value}: {err}"
            );
        }
    }
    assert!(!dir.path().join("g.fold").exists());
    // At the limit the pattern is made.
    let o = foldcam(
        &["generate", "miura", "-o", "g.fold", "--width", "1e6"],
        dir.path(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

#[test]
fn fold_pictures_beyond_the_pixel_limit_are_refused_with_a_width_that_fits() {
    let dir = tempfile::tempdir().expect("temp dir");
    let script = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("examples/folding/bird-base.toml")
        .to_string_lossy()
        .into_owned();
    for picture in ["--png", "--gif"] {
        let out = if picture == "--png" { "b.png" } else { "b.gif" };
        let o = foldcam(
            &[
                "fold", &script, "-o", "b.fold", picture, out, "--width", "16384",
            ],
            dir.path(),
        );
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert!(
            err.contains("--width 16384") && err.contains("or less"),
            "{err}"
        );
    }
    assert!(!dir.path().join("b.fold").exists());
}
