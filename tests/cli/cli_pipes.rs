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

/// The subcommands `foldcam help` lists (without `help` itself).
fn listed_commands(d: &std::path::Path) -> Vec<String> {
    let o = foldcam(&["help"], d, b"");
    ok(&o);
    let text = String::from_utf8_lossy(&o.stdout).into_owned();
    let list = text
        .split("Commands:\n")
        .nth(1)
        .expect("a Commands: section")
        .split("\n\n")
        .next()
        .expect("its lines");
    list.lines()
        .filter(|l| l.starts_with("  ") && !l.starts_with("   "))
        .filter_map(|l| l.split_whitespace().next())
        .filter(|c| *c != "help")
        .map(str::to_owned)
        .collect()
}

#[test]
fn completions_and_man_page_name_every_command() {
    let dir = tempfile::tempdir().expect("temp dir");
    let d = dir.path();
    let commands = listed_commands(d);
    assert!(commands.len() >= 19, "{commands:?}");
    for shell in ["bash", "zsh", "fish", "powershell"] {
        let o = foldcam(&["completions", shell], d, b"");
        ok(&o);
        let script = String::from_utf8_lossy(&o.stdout);
        for command in &commands {
            assert!(
                script.contains(command.as_str()),
                "{shell} completes {command}"
            );
        }
        if shell == "bash" {
            // The script bash would source parses (bash is on every machine this runs on).
            std::fs::write(d.join("foldcam.bash"), script.as_bytes()).expect("written");
            let syntax = std::process::Command::new("bash")
                .arg("-n")
                .arg(d.join("foldcam.bash"))
                .output()
                .expect("bash runs");
            assert!(
                syntax.status.success(),
                "bash -n: {}",
                String::from_utf8_lossy(&syntax.stderr)
            );
        }
    }
    let o = foldcam(&["man"], d, b"");
    ok(&o);
    // roff writes a hyphen as `\-`.
    let page = String::from_utf8_lossy(&o.stdout).replace("\\-", "-");
    assert!(page.contains(".TH foldcam 1"), "a roff man page");
    for command in &commands {
        assert!(
            page.contains(command.as_str()),
            "the man page names {command}"
        );
    }
    ok(&foldcam(&["man", "--dir", "man1"], d, b""));
    assert!(d.join("man1/foldcam.1").is_file());
    for command in &commands {
        let file = d.join(format!("man1/foldcam-{command}.1"));
        assert!(file.is_file(), "{} written", file.display());
        // groff reads every page without a warning, as man-db runs it (-k: UTF-8 through preconv;
        // -ww: all warnings; -z: no output).
        let groff = std::process::Command::new("groff")
            .args(["-k", "-z", "-ww", "-man"])
            .arg(&file)
            .output()
            .expect("groff runs (Debian groff-base)");
        assert!(
            groff.status.success() && groff.stderr.is_empty(),
            "{}: {}",
            file.display(),
            String::from_utf8_lossy(&groff.stderr)
        );
    }
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
    // Its 170° creases are a 3D target the check cannot judge without a frame: accepted here.
    let report = foldcam(&["-q", "check", "b.fold", "--allow-unchecked"], d, b"");
    ok(&report);
    assert!(String::from_utf8_lossy(&report.stdout).contains("PASS"));
}
