//! Hostile inputs from the hardening review end with a clear refusal (exit 2, the option and
//! the limit named), never a hang or a panic.

use std::path::Path;
use std::process::{Command, Output};

fn foldcam(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_foldcam"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("the foldcam binary runs")
}

#[test]
fn generators_refuse_sizes_beyond_a_kilometre() {
    let dir = tempfile::tempdir().expect("temp dir");
    for kind in ["miura", "square-twist", "waterbomb", "yoshimura"] {
        for (option, value) in [("--width", "1e200"), ("--width", "1e308"), ("--height", "1e308")] {
            if kind == "waterbomb" && option == "--height" {
                continue;
            }
            let o = foldcam(&["generate", kind, "-o", "g.fold", option, value], dir.path());
            let err = String::from_utf8_lossy(&o.stderr);
            assert_eq!(o.status.code(), Some(2), "{kind} {option} {value}: {err}");
            assert!(err.contains("1,000,000 mm"), "{kind} {option} {value}: {err}");
        }
    }
    assert!(!dir.path().join("g.fold").exists());
    // At the limit the pattern is made.
    let o = foldcam(&["generate", "miura", "-o", "g.fold", "--width", "1e6"], dir.path());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}
