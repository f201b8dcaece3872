//! What a verdict says it ran: the same findings from every file format, the option that
//! would change a Kawasaki verdict, and what writing a format without fold angles loses.

use std::path::Path;
use std::process::{Command, Output};

use foldcam::formats::{Format, load, render};

fn foldcam(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_foldcam"))
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap()
}

fn last_line(o: &Output) -> String {
    let text = String::from_utf8_lossy(&o.stdout).to_string();
    text.trim_end().lines().last().unwrap_or("").to_string()
}

fn repo(path: &str) -> String {
    format!("{}/{path}", env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn a_kawasaki_failure_names_the_tolerance_that_would_pass_it() {
    let dir = tempfile::tempdir().unwrap();
    let file = repo("examples/patterns/broken-vertex.fold");
    let o = foldcam(&["check", &file], dir.path());
    assert_eq!(o.status.code(), Some(1));
    let verdict = last_line(&o);
    // A 5° error is no rounding: the verdict says so while naming the value.
    assert!(
        verdict.contains("the Kawasaki errors reach 5.0000°, more than a drawing's rounding"),
        "{verdict}"
    );
    let option = "--kawasaki-tolerance ";
    let at = verdict.find(option).expect(&verdict) + option.len();
    let value = verdict[at..].split_whitespace().next().unwrap();
    // With that tolerance the Kawasaki finding is gone (Maekawa's remains: the verdict still
    // fails, on Maekawa alone).
    let o = foldcam(&["check", &file, "--kawasaki-tolerance", value], dir.path());
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(last_line(&o), "FAIL: 1 findings (maekawa 1)");
}

type Listed = Vec<(String, i64, i64, i64)>;

/// The findings of `foldcam check --json FILE` as (kind, x, y, value) rounded to 1e-3, sorted:
/// comparable across formats, which number vertices and edges differently.
fn findings(file: &str, dir: &Path) -> Listed {
    listed(file, dir, &["findings"])
}

/// The entries of the report's lists `keys` (e.g. `findings`, `unchecked_faults`), as
/// [`findings`] gives them.
fn listed(file: &str, dir: &Path, keys: &[&str]) -> Listed {
    let o = foldcam(&["check", file, "--json"], dir);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect(file);
    let round = |x: &serde_json::Value| (x.as_f64().unwrap() * 1e3).round() as i64;
    let empty = Vec::new();
    let mut out: Vec<_> = (keys.iter())
        .flat_map(|k| v[k].as_array().unwrap_or(&empty))
        .map(|f| {
            (
                f["kind"].as_str().unwrap().to_string(),
                round(&f["position"][0]),
                round(&f["position"][1]),
                round(&f["value"]),
            )
        })
        .collect();
    out.sort();
    out
}

#[test]
fn the_crane_gives_the_same_findings_from_every_format_that_keeps_its_target() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // Origami Simulator's crane: 10 flat (F) lines, and 29 creases folding to 45°, 90° or
    // 135° (its 3D target, the SVG's stroke opacity).
    let original = repo("tests/data/traditionalCrane.svg");
    std::fs::copy(&original, d.join("crane.svg")).unwrap();
    let crane = load(Path::new(&original)).unwrap().pattern;
    let mut converted = Vec::new();
    for ext in ["fold", "cp", "opx"] {
        let out = format!("crane.{ext}");
        let o = foldcam(&["convert", "crane.svg", &out], d);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        converted.push((ext, String::from_utf8_lossy(&o.stderr).to_string()));
    }
    // FOLD keeps the fold angles: the same findings as the SVG. .cp and .opx carry none, and
    // convert says what that changes.
    assert_eq!(findings("crane.svg", d), findings("crane.fold", d));
    for (ext, err) in &converted {
        let warned = err.contains(
            "29 creases fold to less than 180° (a 3D target), and this \
                                  format carries no fold angles",
        );
        assert_eq!(warned, *ext != "fold", "{ext}: {err}");
    }
    // The same crane as a flat target (every crease folding flat, its flat lines kept): all four
    // formats give the same findings.
    let mut flat = crane.clone();
    for e in &mut flat.edges {
        e.fold_angle = None;
    }
    std::fs::write(d.join("flat.fold"), render(Format::Fold, &flat, None)).unwrap();
    let reference = findings("flat.fold", d);
    assert!(
        !reference.is_empty(),
        "the crane's drawing has Kawasaki errors"
    );
    for ext in ["svg", "cp", "opx"] {
        let out = format!("flat.{ext}");
        let o = foldcam(&["convert", "flat.fold", &out], d);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        assert!(!String::from_utf8_lossy(&o.stderr).contains("fold angles"));
        assert_eq!(findings(&out, d), reference, "{ext}");
    }
}

#[test]
fn the_crane_names_the_same_faults_from_svg_and_cp() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::copy(repo("tests/data/traditionalCrane.svg"), d.join("crane.svg")).unwrap();
    let o = foldcam(&["convert", "crane.svg", "crane.cp"], d);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // .cp reads every crease as folding flat: each fault is a failure there. The SVG keeps the
    // 3D target: the faults at its 3D-target vertices are listed apart, not as failures.
    let from_cp = findings("crane.cp", d);
    let from_svg = listed("crane.svg", d, &["findings", "unchecked_faults"]);
    assert_eq!(from_svg, from_cp);
    let failures = findings("crane.svg", d);
    assert!(!failures.is_empty() && failures.len() < from_cp.len());
    // The text report says so, line by line and in the verdict.
    let o = foldcam(&["check", "crane.svg"], d);
    let text = String::from_utf8_lossy(&o.stdout);
    let listed_apart = text
        .lines()
        .filter(|l| l.starts_with("3D target #"))
        .count();
    assert_eq!(listed_apart, from_cp.len() - failures.len(), "{text}");
    assert!(
        last_line(&o).contains("the \"3D target\" lines list"),
        "{text}"
    );
}
