//! Habits of Unix tools: `-` for standard input and output (`--from`, `--to`), results on
//! standard output and messages on standard error, shell completions, the man page,
//! `--quiet`. Every output is read back (re-imported, or run on the simulated machine).

use std::io::Write;
use std::path::Path;
use std::process::{Command, Output, Stdio};

fn foldcam(args: &[&str], dir: &Path, stdin: &[u8]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_foldcam"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the foldcam binary runs");
    if let Some(mut input) = child.stdin.take() {
        // A command that does not read its input may close it first.
        let _ = input.write_all(stdin);
    }
    child.wait_with_output().expect("foldcam finishes")
}

fn ok(o: &Output) {
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

fn bird_cp() -> Vec<u8> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/patterns/bird-base.cp");
    std::fs::read(path).expect("shipped example")
}

#[test]
fn convert_reads_standard_input_in_the_format_from_names() {
    let dir = tempfile::tempdir().expect("temp dir");
    let d = dir.path();
    let o = foldcam(&["convert", "-", "out.fold", "--from", "cp"], d, &bird_cp());
    ok(&o);
    assert!(o.stdout.is_empty(), "nothing on standard output");
    // The same pattern as converting the file.
    std::fs::write(d.join("bird.cp"), bird_cp()).expect("write");
    ok(&foldcam(&["convert", "bird.cp", "file.fold"], d, b""));
    let a = std::fs::read_to_string(d.join("out.fold")).expect("out");
    let b = std::fs::read_to_string(d.join("file.fold")).expect("file");
    assert_eq!(a, b);
    // Without --from, a clear error and nothing written.
    let o = foldcam(&["convert", "-", "none.fold"], d, &bird_cp());
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--from"));
    assert!(!d.join("none.fold").exists());
}

#[test]
fn cut_writes_gcode_to_standard_output_and_its_summary_to_standard_error() {
    let dir = tempfile::tempdir().expect("temp dir");
    let d = dir.path();
    ok(&foldcam(&["generate", "miura", "-o", "m.fold"], d, b""));
    let args = [
        "cut",
        "m.fold",
        "-m",
        "grbl-diode",
        "-x",
        "card-300gsm",
        "-o",
        "-",
        "--to",
        "gcode",
    ];
    let o = foldcam(&args, d, b"");
    ok(&o);
    let gcode = String::from_utf8(o.stdout.clone()).expect("text");
    assert!(
        gcode.starts_with("; foldcam"),
        "{}",
        &gcode[..80.min(gcode.len())]
    );
    assert!(String::from_utf8_lossy(&o.stderr).contains("pierces"));
    // The same bytes as the job written to a file, and the simulated machine runs it from
    // standard input clean.
    ok(&foldcam(
        &[
            "cut",
            "m.fold",
            "-m",
            "grbl-diode",
            "-x",
            "card-300gsm",
            "-o",
            "m.gcode",
        ],
        d,
        b"",
    ));
    assert_eq!(std::fs::read(d.join("m.gcode")).expect("job"), o.stdout);
    let sim = foldcam(&["simulate", "-", "-m", "grbl-diode"], d, &o.stdout);
    ok(&sim);
    assert!(String::from_utf8_lossy(&sim.stdout).contains("PASS: 0 violations"));
}

#[test]
fn check_plan_and_preview_read_and_write_pipes() {
    let dir = tempfile::tempdir().expect("temp dir");
    let d = dir.path();
    let o = foldcam(&["check", "-", "--from", "cp"], d, &bird_cp());
    ok(&o);
    assert!(String::from_utf8_lossy(&o.stdout).contains("PASS"));
    let o = foldcam(
        &["preview", "-", "-o", "-", "--from", "cp", "--to", "png"],
        d,
        &bird_cp(),
    );
    ok(&o);
    let png = image::load_from_memory(&o.stdout).expect("a PNG on standard output");
    // The same picture as the preview written to a file.
    std::fs::write(d.join("bird.cp"), bird_cp()).expect("write");
    ok(&foldcam(&["preview", "bird.cp", "-o", "file.png"], d, b""));
    let file = image::open(d.join("file.png")).expect("PNG");
    assert_eq!(png.to_rgba8(), file.to_rgba8());
    let o = foldcam(
        &[
            "plan",
            "-",
            "--from",
            "cp",
            "--size",
            "150",
            "-m",
            "grbl-diode",
            "-x",
            "card-300gsm",
        ],
        d,
        &bird_cp(),
    );
    ok(&o);
    assert!(String::from_utf8_lossy(&o.stdout).contains("pierces"));
}

#[test]
fn completions_and_man_page_name_every_command() {
    let dir = tempfile::tempdir().expect("temp dir");
    let d = dir.path();
    for shell in ["bash", "zsh", "fish", "powershell"] {
        let o = foldcam(&["completions", shell], d, b"");
        ok(&o);
        let script = String::from_utf8_lossy(&o.stdout);
        for command in ["convert", "tessellate", "papercraft", "completions"] {
            assert!(script.contains(command), "{shell} completes {command}");
        }
    }
    let o = foldcam(&["man"], d, b"");
    ok(&o);
    let page = String::from_utf8_lossy(&o.stdout);
    assert!(page.contains(".TH foldcam 1"), "a roff man page");
    assert!(page.contains("papercraft"));
    ok(&foldcam(&["man", "--dir", "man1"], d, b""));
    assert!(d.join("man1/foldcam.1").is_file());
    assert!(d.join("man1/foldcam-cut.1").is_file());
}

#[test]
fn quiet_keeps_results_and_drops_notes() {
    let dir = tempfile::tempdir().expect("temp dir");
    let d = dir.path();
    let loud = foldcam(&["generate", "miura", "-o", "a.fold"], d, b"");
    ok(&loud);
    assert!(String::from_utf8_lossy(&loud.stderr).contains("wrote"));
    let quiet = foldcam(&["generate", "miura", "-o", "b.fold", "--quiet"], d, b"");
    ok(&quiet);
    assert!(
        quiet.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&quiet.stderr)
    );
    assert!(d.join("b.fold").is_file());
    let report = foldcam(&["-q", "check", "b.fold"], d, b"");
    ok(&report);
    assert!(String::from_utf8_lossy(&report.stdout).contains("PASS"));
}
