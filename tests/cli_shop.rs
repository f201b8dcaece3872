//! Shop habits at the command line: `list`, and a closed pipe ending quietly.

use std::process::{Command, Stdio};

use foldcam::machine::{load_machine, load_material, shipped_machines, shipped_materials};

fn foldcam() -> Command {
    Command::new(env!("CARGO_BIN_EXE_foldcam"))
}

#[test]
fn list_names_every_shipped_profile_with_its_description() {
    for (what, names) in [
        ("machines", shipped_machines()),
        ("materials", shipped_materials()),
    ] {
        let out = foldcam().args(["list", what]).output().expect("runs");
        assert!(out.status.success());
        let text = String::from_utf8(out.stdout).expect("UTF-8");
        assert_eq!(text.lines().count(), names.len(), "{text}");
        for name in names {
            let description = if what == "machines" {
                load_machine(name).expect("shipped").description
            } else {
                load_material(name).expect("shipped").description
            };
            let line = text
                .lines()
                .find(|l| l.split_whitespace().next() == Some(name))
                .unwrap_or_else(|| panic!("{name} missing from {text}"));
            assert!(
                line.contains(&description) && line.contains(".toml"),
                "{line}"
            );
        }
    }
}

#[test]
fn a_closed_pipe_ends_the_program_quietly() {
    let dir = tempfile::tempdir().expect("temp dir");
    let fold = dir.path().join("miura.fold");
    let job = dir.path().join("miura.gcode");
    let run = |args: &[&str]| {
        let s = foldcam()
            .args(args)
            .current_dir(dir.path())
            .output()
            .expect("runs");
        assert!(s.status.success(), "{}", String::from_utf8_lossy(&s.stderr));
    };
    run(&["generate", "miura", "-o", fold.to_str().expect("path")]);
    run(&[
        "cut",
        "miura.fold",
        "-m",
        "grbl-diode",
        "-x",
        "card-300gsm",
        "-o",
        "miura.gcode",
    ]);
    assert!(job.is_file());
    // The report (about 68 kB with coverage) is larger than a pipe's buffer, and the reading
    // end is closed before anything is read.
    let mut child = foldcam()
        .args([
            "simulate",
            "miura.gcode",
            "-m",
            "grbl-diode",
            "--json",
            "--pattern",
            "miura.fold",
            "-x",
            "card-300gsm",
        ])
        .current_dir(dir.path())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawns");
    drop(child.stdout.take());
    let out = child.wait_with_output().expect("waits");
    assert_eq!(out.status.code(), Some(0));
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}
