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
            // No notes (the size read): only an error could reach stderr.
            "-q",
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

fn run_in(dir: &std::path::Path, args: &[&str]) -> std::process::Output {
    foldcam()
        .args(args)
        .current_dir(dir)
        .output()
        .expect("runs")
}

fn repo(rel: &str) -> String {
    std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join(rel)
        .to_string_lossy()
        .into_owned()
}

#[test]
fn cut_frame_writes_a_dark_outline_job_and_refuses_drawings() {
    let dir = tempfile::tempdir().expect("temp dir");
    let ok = run_in(dir.path(), &["generate", "miura", "-o", "m.fold"]);
    assert!(ok.status.success());
    let args = ["cut", "m.fold", "-m", "grbl-diode", "-x", "card-300gsm"];
    let out = run_in(
        dir.path(),
        &[&args[..], &["-o", "f.gcode", "--frame"][..]].concat(),
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(String::from_utf8_lossy(&out.stdout).contains("frame front"));
    let text = std::fs::read_to_string(dir.path().join("f.gcode")).expect("written");
    let machine = load_machine("grbl-diode").expect("shipped");
    let run = foldcam::sim::run(&text, &machine).expect("readable");
    assert!(run.is_clean() && run.burns.is_empty() && run.travels.len() >= 5);
    // The frame visits the corners of what the job itself burns (both read back on the
    // simulated machine), and `--frame-power` burns that rectangle's perimeter.
    let out = run_in(dir.path(), &[&args[..], &["-o", "j.gcode"][..]].concat());
    assert!(out.status.success());
    let job_text = std::fs::read_to_string(dir.path().join("j.gcode")).expect("written");
    let job = foldcam::sim::run(&job_text, &machine).expect("readable");
    let lo = job
        .burns
        .iter()
        .flat_map(|b| [b.from, b.to])
        .fold(glam::DVec2::MAX, |a, p| a.min(p));
    let hi = job
        .burns
        .iter()
        .flat_map(|b| [b.from, b.to])
        .fold(glam::DVec2::MIN, |a, p| a.max(p));
    let tol = machine.resolution_mm + 1e-9;
    for corner in [
        lo,
        glam::DVec2::new(hi.x, lo.y),
        hi,
        glam::DVec2::new(lo.x, hi.y),
    ] {
        assert!(
            run.travels.iter().any(|t| t.to.distance(corner) <= tol),
            "the frame misses the job's corner {corner}"
        );
    }
    let out = run_in(
        dir.path(),
        &[
            &args[..],
            &["-o", "lit.gcode", "--frame", "--frame-power", "0.05"][..],
        ]
        .concat(),
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let lit_text = std::fs::read_to_string(dir.path().join("lit.gcode")).expect("written");
    let lit = foldcam::sim::run(&lit_text, &machine).expect("readable");
    let perimeter = 2.0 * ((hi.x - lo.x) + (hi.y - lo.y));
    assert!(lit.is_clean());
    assert!(
        (lit.burn_length_mm - perimeter).abs() <= 4.0 * tol,
        "{} mm burned for a {perimeter} mm frame",
        lit.burn_length_mm
    );
    let out = run_in(
        dir.path(),
        &[&args[..], &["-o", "f.svg", "--frame"][..]].concat(),
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--frame writes G-code"));
    assert!(!dir.path().join("f.svg").exists());
    // The FOLD frame selector is --fold-frame now.
    let out = run_in(dir.path(), &["check", "m.fold", "--frame", "1"]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn testgrid_writes_every_format_and_refuses_values_out_of_range() {
    let dir = tempfile::tempdir().expect("temp dir");
    let base = ["testgrid", "-m", "marlin-laser", "-x", "paper-160gsm"];
    for file in ["g.gcode", "g.dxf", "g.svg", "g.lbrn2"] {
        let out = run_in(dir.path(), &[&base[..], &["-o", file][..]].concat());
        assert!(
            out.status.success(),
            "{file}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(String::from_utf8_lossy(&out.stdout).contains("27 cells"));
        assert!(dir.path().join(file).exists());
    }
    // Lists and FROM:TO:N ranges: 2 dashes × 1 bridge × 3 powers × 2 speeds, and the job burns
    // each power at each speed (read back on the simulated machine).
    let out = run_in(
        dir.path(),
        &[
            &base[..],
            &[
                "-o",
                "r.gcode",
                "--dash",
                "1,2",
                "--bridge",
                "0.5",
                "--power",
                "0.2:0.6:3",
                "--speed",
                "1200:2400:2",
            ][..],
        ]
        .concat(),
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(String::from_utf8_lossy(&out.stdout).contains("12 cells"));
    let text = std::fs::read_to_string(dir.path().join("r.gcode")).expect("written");
    let machine = load_machine("marlin-laser").expect("shipped");
    let run = foldcam::sim::run(&text, &machine).expect("readable");
    assert!(run.is_clean(), "{:?}", run.violations.first());
    for power in [0.2, 0.4, 0.6] {
        for speed in [1200.0, 2400.0] {
            let burned: f64 = run
                .burns
                .iter()
                .filter(|b| (run.power_fraction(b.power) - power).abs() < 1e-3)
                .filter(|b| (b.feed_mm_min - speed).abs() < 1e-6)
                .map(|b| b.length())
                .sum();
            assert!(burned > 10.0, "{power} at {speed} mm/min: {burned} mm");
        }
    }
    let out = run_in(
        dir.path(),
        &[&base[..], &["-o", "bad.gcode", "--power", "0.5,2"][..]].concat(),
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("power"));
    assert!(!dir.path().join("bad.gcode").exists());
}

/// Burn length at `power` (a fraction) in a simulated run, mm.
fn burned_at(run: &foldcam::sim::SimReport, power: f64) -> f64 {
    run.burns
        .iter()
        .filter(|b| (run.power_fraction(b.power) - power).abs() < 1e-9)
        .map(|b| b.length())
        .sum()
}

#[test]
fn papercraft_jobs_mark_edge_numbers_where_the_material_can_mark() {
    let dir = tempfile::tempdir().expect("temp dir");
    let vase = repo("examples/papercraft/vase.craft.toml");
    let machine = load_machine("grbl-diode").expect("shipped");
    let card = load_material("card-300gsm").expect("shipped");
    let out = run_in(
        dir.path(),
        &[
            "papercraft",
            &vase,
            "-o",
            "v.fold",
            "--job",
            "v.gcode",
            "-m",
            "grbl-diode",
            "-x",
            "card-300gsm",
        ],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let sheet = foldcam::formats::load(&dir.path().join("v.fold"))
        .expect("sheet")
        .pattern;
    let labels: f64 = sheet
        .edge_ids()
        .filter(|&e| sheet.edges[e.index()].assignment == foldcam::pattern::Assignment::Flat)
        .map(|e| sheet.edge_length(e))
        .sum();
    assert!(labels > 0.0, "the vase has edge numbers");
    let text = std::fs::read_to_string(dir.path().join("v.gcode")).expect("job");
    let run = foldcam::sim::run(&text, &machine).expect("readable");
    assert!(run.is_clean());
    let marked = burned_at(&run, card.settings.mark.power);
    assert!(
        (marked - labels).abs() < 0.01 * labels,
        "marked {marked} of {labels} mm"
    );
    // The same card with no mark power cannot show them: none are burned.
    let toml = std::fs::read_to_string(repo("machines/materials/card-300gsm.toml")).expect("toml");
    let at = toml.find("[settings.mark]").expect("mark settings");
    let (head, tail) = toml.split_at(at);
    let dark = format!("{head}{}", tail.replacen("power = 0.1", "power = 0.0", 1));
    std::fs::write(dir.path().join("dark.toml"), dark).expect("write");
    let out = run_in(
        dir.path(),
        &[
            "papercraft",
            &vase,
            "-o",
            "w.fold",
            "--job",
            "w.gcode",
            "-m",
            "grbl-diode",
            "-x",
            "dark.toml",
        ],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(String::from_utf8_lossy(&out.stderr).contains("edge numbers left out"));
    let text = std::fs::read_to_string(dir.path().join("w.gcode")).expect("job");
    assert!(!text.contains("; mark"), "no mark layer");
    let run = foldcam::sim::run(&text, &machine).expect("readable");
    assert!(run.is_clean());
    let cut_and_score = run.burn_length_mm;
    let first = foldcam::sim::run(
        &std::fs::read_to_string(dir.path().join("v.gcode")).expect("job"),
        &machine,
    )
    .expect("readable")
    .burn_length_mm;
    assert!((first - cut_and_score - labels).abs() < 0.01 * labels);
}

#[test]
fn materials_show_their_defaults_and_card_folds_flat() {
    let out = foldcam()
        .args(["list", "materials"])
        .output()
        .expect("runs");
    let text = String::from_utf8(out.stdout).expect("UTF-8");
    let card = text
        .lines()
        .find(|l| l.starts_with("card-300gsm "))
        .expect("card listed");
    assert!(
        card.contains("by default mountain score, valley score, unassigned score")
            && card.contains("folds up to 180°"),
        "{card}"
    );
    let help = foldcam().args(["cut", "--help"]).output().expect("runs");
    let help = String::from_utf8(help.stdout).expect("UTF-8");
    assert!(
        help.contains("card-300gsm: mountain score, valley score"),
        "{help}"
    );
    assert!(help.contains("paper-160gsm: mountain perforate"), "{help}");
    // The README's bird base, folded flat, is within card's limits: no warning.
    let dir = tempfile::tempdir().expect("temp dir");
    let bird = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/examples/patterns/bird-base.cp"
    );
    let o = run_in(
        dir.path(),
        &[
            "cut",
            bird,
            "--size",
            "150",
            "-m",
            "grbl-diode",
            "-x",
            "card-300gsm",
            "-o",
            "b.gcode",
        ],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let said = format!(
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(!said.contains("fold further"), "{said}");
}

#[test]
fn a_job_beyond_the_material_limits_says_what_to_do() {
    let dir = tempfile::tempdir().expect("temp dir");
    let d = dir.path();
    assert!(
        run_in(d, &["generate", "miura", "-o", "m.fold"])
            .status
            .success()
    );
    // The Miura-ori's 170° creases fold further than 0.5 mm stainless allows (165°).
    let o = run_in(
        d,
        &[
            "cut",
            "m.fold",
            "-m",
            "linuxcnc-fiber",
            "-x",
            "stainless-0.5",
            "-o",
            "m.ngc",
        ],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(said.contains("fold further than 165°"), "{said}");
    assert!(
        said.contains(
            "take a shipped material whose limits it meets: card-300gsm, paper-160gsm, \
             polypropylene-0.5, stainless-0.3"
        ),
        "{said}"
    );
    assert!(
        said.contains("`foldcam check PATTERN --min-vertex-angle 30 --max-fold-angle 165`"),
        "{said}"
    );
    assert!(said.contains("no option is needed"), "{said}");
}
