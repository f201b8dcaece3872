//! The reproducers of the hardening review, one test each: out-of-range options and profile
//! keys, nonsense perforations, broken SVG, FOLD and `.cp` input, tiny height maps, oversized
//! work. Each run ends with exit 0 and a correct output, or exit 2 and a message naming the
//! option, key or element and the limit; never a panic (101) or an abort (134). A generous
//! kill-after time guards against hangs only; speed is measured in benches and reports.

use crate::bin;

use std::io::Read;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use bin::{listing, repo_file};

/// Longest a run may take before it counts as hung (debug build, loaded machine).
const HANG_GUARD: Duration = Duration::from_secs(180);

/// Runs `foldcam ARGS` in `dir`: exit code, stdout, stderr; kills it after [`HANG_GUARD`].
fn run(args: &[&str], dir: &Path) -> (i32, String, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_foldcam"))
        .args(args)
        .current_dir(dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the foldcam binary runs");
    let (mut out, mut err) = (child.stdout.take().unwrap(), child.stderr.take().unwrap());
    let reader = std::thread::spawn(move || {
        let mut s = String::new();
        out.read_to_string(&mut s).ok();
        s
    });
    let err_reader = std::thread::spawn(move || {
        let mut s = String::new();
        err.read_to_string(&mut s).ok();
        s
    });
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("waiting") {
            break status;
        }
        if start.elapsed() > HANG_GUARD {
            child.kill().ok();
            panic!("foldcam {args:?} still ran after {HANG_GUARD:?}");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let code = status.code().unwrap_or(-1);
    let (stdout, stderr) = (reader.join().unwrap(), err_reader.join().unwrap());
    assert!(
        ![101, 134, -1].contains(&code),
        "foldcam {args:?} crashed ({code}): {stderr}"
    );
    (code, stdout, stderr)
}

/// Asserts exit 2 with every `needle` in the message.
fn refused(args: &[&str], dir: &Path, needles: &[&str]) -> String {
    let (code, _, err) = run(args, dir);
    assert_eq!(code, 2, "foldcam {args:?}: {err}");
    for n in needles {
        assert!(err.contains(n), "foldcam {args:?}: {n:?} not in: {err}");
    }
    err
}

/// A Miura-ori made by the generator in `dir`.
fn miura(dir: &Path) -> &'static str {
    let (code, _, err) = run(&["generate", "miura", "-o", "miura.fold"], dir);
    assert_eq!(code, 0, "{err}");
    "miura.fold"
}

#[test]
fn kerf_beyond_its_range_is_refused_on_plan_and_cut_as_in_the_profile() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let p = miura(d);
    for kerf in ["1e20", "1e300", "1e307", "1e308"] {
        let base = ["-m", "grbl-diode", "-x", "card-300gsm", "--kerf", kerf];
        let plan: Vec<&str> = ["plan", p].iter().chain(&base).copied().collect();
        refused(&plan, d, &["--kerf", "expected a number from 0 to 5 mm"]);
        let cut: Vec<&str> = ["cut", p, "-o", "j.gcode"]
            .iter()
            .chain(&base)
            .copied()
            .collect();
        refused(&cut, d, &["--kerf", "expected a number from 0 to 5 mm"]);
    }
    assert!(!d.join("j.gcode").exists());
    // The material profile refuses the same value with the same words, naming file and key.
    let card = std::fs::read_to_string(repo_file("machines/materials/card-300gsm.toml")).unwrap();
    let bad = card.replace("kerf_mm = 0.15", "kerf_mm = 1e20");
    assert_ne!(bad, card, "the shipped card sets kerf_mm = 0.15");
    std::fs::write(d.join("wide.toml"), bad).unwrap();
    refused(
        &["plan", p, "-m", "grbl-diode", "-x", "wide.toml"],
        d,
        &["wide.toml", "kerf_mm", "expected a number from 0 to 5 mm"],
    );
    // Inside the range the job is made.
    let (code, _, err) = run(
        &[
            "plan",
            p,
            "-m",
            "grbl-diode",
            "-x",
            "card-300gsm",
            "--kerf",
            "0.2",
        ],
        d,
    );
    assert_eq!(code, 0, "{err}");
}

#[test]
fn perforation_options_take_the_ranges_the_material_profile_takes() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let p = miura(d);
    for (option, range) in [
        ("--dash", "from 0.01 to 1000 mm"),
        ("--bridge", "from 0.01 to 1000 mm"),
        ("--min-web", "from 0.01 to 1000 mm"),
        ("--clearance", "from 0 to 100 mm"),
        ("--tabs", "from 0.01 to 100 mm"),
    ] {
        for value in ["1e308", "NaN"] {
            let args = [
                "plan",
                p,
                "-m",
                "grbl-diode",
                "-x",
                "card-300gsm",
                option,
                value,
            ];
            refused(&args, d, &[option, range]);
        }
    }
}

#[test]
fn a_dash_that_would_become_a_continuous_slot_is_refused_by_plan_cut_and_simulate() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let p = miura(d);
    let perforate = ["--mountain", "perforate", "--valley", "perforate"];
    let mut cut = vec![
        "cut",
        p,
        "-m",
        "grbl-diode",
        "-x",
        "card-300gsm",
        "-o",
        "d.gcode",
    ];
    cut.extend(perforate);
    let mut slot = cut.clone();
    slot.extend(["--dash", "0.01"]);
    refused(&slot, d, &["--dash", "0.5 mm", "continuous slot"]);
    assert!(!d.join("d.gcode").exists());
    // A job cut with real dashes, simulated with --dash 0.01, is refused too rather than
    // called "as planned".
    let (code, _, err) = run(&cut, d);
    assert_eq!(code, 0, "{err}");
    let mut sim = vec!["simulate", "d.gcode", "-m", "grbl-diode", "--pattern", p];
    sim.extend(["-x", "card-300gsm", "--dash", "0.01"]);
    sim.extend(perforate);
    let err = refused(&sim, d, &["--dash", "continuous slot"]);
    assert!(!err.contains("as planned"), "{err}");
    // A dash at the shortest dash is a perforation.
    let mut fine: Vec<&str> = cut
        .iter()
        .map(|a| if *a == "d.gcode" { "fine.gcode" } else { a })
        .collect();
    fine.extend(["--dash", "0.5"]);
    let (code, out, err) = run(&fine, d);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("perforate"), "{out}");
}

/// An SVG with one red line whose attributes are `line`, inside `root` attributes.
fn svg(root: &str, body: &str) -> String {
    format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" {root}>\n{body}\n\
         <line x1=\"0\" y1=\"50\" x2=\"100\" y2=\"50\" stroke=\"blue\"/>\n</svg>\n"
    )
}

const SIZE: &str = "width=\"100mm\" height=\"100mm\" viewBox=\"0 0 100 100\"";

#[test]
fn svg_coordinates_that_are_not_numbers_are_refused_with_element_and_line() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let body = "<line x1='NaN' y1='0' x2='50' y2='50' stroke='red'/>";
    std::fs::write(d.join("nan.svg"), svg(SIZE, body)).unwrap();
    refused(
        &["convert", "nan.svg", "nan.fold"],
        d,
        &["nan.svg", "line 2", "<line>", "x1=\"NaN\"", "not a number"],
    );
    assert!(!d.join("nan.fold").exists());
}

#[test]
fn svg_numbers_beyond_the_reader_limit_name_the_attribute() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let body =
        "<g transform=\"scale(1e300)\"><line x1='0' y1='0' x2='50' y2='50' stroke='red'/></g>";
    std::fs::write(d.join("scale.svg"), svg(SIZE, body)).unwrap();
    refused(
        &["convert", "scale.svg", "s.fold"],
        d,
        &["line 2", "<g>", "transform", "1e300", "1e9"],
    );
    let root = "width=\"1e308mm\" height=\"100mm\" viewBox=\"0 0 100 100\"";
    std::fs::write(d.join("wide.svg"), svg(root, "")).unwrap();
    refused(
        &["convert", "wide.svg", "w.fold"],
        d,
        &["line 1", "<svg>", "width=\"1e308mm\"", "1e9"],
    );
}

#[test]
fn an_element_with_too_many_attributes_is_refused_before_parsing() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let many: String = (0..100_000).map(|i| format!(" data-a{i}=\"1\"")).collect();
    let body = format!("<line x1='0' y1='0' x2='50' y2='50' stroke='red'{many}/>");
    std::fs::write(d.join("attrs.svg"), svg(SIZE, &body)).unwrap();
    refused(
        &["convert", "attrs.svg", "a.fold"],
        d,
        &["line 2", "<line>", "more than 1000 attributes"],
    );
}

#[test]
fn a_presentation_attribute_read_leniently_is_warned_about_with_element_and_line() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let body = "<line x1='0' y1='0' x2='50' y2='50' stroke='red' stroke-width='thick'/>";
    std::fs::write(d.join("w.svg"), svg(SIZE, body)).unwrap();
    let (code, _, err) = run(&["convert", "w.svg", "w.fold"], d);
    assert_eq!(code, 0, "{err}");
    for needle in ["warning", "line 2, <line>", "stroke-width=\"thick\""] {
        assert!(err.contains(needle), "{needle:?} not in {err}");
    }
    // The line is still read: a mountain from (0, 0) to (50, 50).
    let fold: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("w.fold")).unwrap()).unwrap();
    let assignments = fold["edges_assignment"].as_array().unwrap();
    assert!(assignments.iter().any(|a| a == "M"), "{assignments:?}");
}

#[test]
fn a_height_map_smaller_than_four_pixels_is_refused_with_the_minimum() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    image::GrayImage::from_pixel(1, 1, image::Luma([128]))
        .save(d.join("one.png"))
        .unwrap();
    refused(
        &["popup", "voxel", "one.png", "-o", "one.fold"],
        d,
        &["one.png", "1 × 1 pixels", "at least 3 × 3"],
    );
    assert!(!d.join("one.fold").exists());
}

#[test]
fn cell_sizes_and_resolutions_out_of_range_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let building = repo_file("examples/popup/building.obj");
    refused(
        &[
            "popup",
            "voxel",
            &building,
            "-o",
            "c.fold",
            "--cell-mm",
            "1e-300",
        ],
        d,
        &["--cell-mm", "from 0.1 to 1000 mm"],
    );
    refused(
        &[
            "popup",
            "voxel",
            &building,
            "-o",
            "c.fold",
            "--resolution",
            "5000",
        ],
        d,
        &["--resolution", "from 4 to 4000 cells"],
    );
    // A height map with a base of no depth: the library's option check, which the command
    // reaches through the design source.
    image::GrayImage::from_pixel(8, 8, image::Luma([128]))
        .save(d.join("grey.png"))
        .unwrap();
    refused(
        &["popup", "voxel", "grey.png", "-o", "g.fold", "--depth", "0"],
        d,
        &["--depth must be at least 1 cell"],
    );
    assert!(!d.join("g.fold").exists());
    // The library refuses the cell size too, whoever calls it.
    let e = foldcam::design::popup::voxel::VoxelCard::new(4, 4, 4, 1e-300).unwrap_err();
    assert!(e.to_string().contains("from 0.1 to 1000 mm"), "{e}");
}

#[test]
fn a_merge_tolerance_larger_than_the_pattern_is_refused_instead_of_emptying_it() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let p = miura(d);
    refused(
        &["convert", p, "t.fold", "--planarize", "--tolerance", "1e9"],
        d,
        &["--tolerance", "diagonal"],
    );
    assert!(!d.join("t.fold").exists());
    // A tolerance well inside the pattern cleans it and keeps every edge.
    let (code, _, err) = run(
        &[
            "convert",
            p,
            "t.fold",
            "--planarize",
            "--tolerance",
            "0.001",
        ],
        d,
    );
    assert_eq!(code, 0, "{err}");
    let count = |f: &str| {
        let v: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(d.join(f)).unwrap()).unwrap();
        v["edges_vertices"].as_array().unwrap().len()
    };
    assert_eq!(count("t.fold"), count(p));
}

#[test]
fn cp_line_types_beyond_the_known_ones_are_read_as_auxiliary_with_a_warning() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let text = "1 0 0 10 0\n1 10 0 10 10\n1 10 10 0 10\n1 0 10 0 0\n7 0 0 10 10\n";
    std::fs::write(d.join("t.cp"), text).unwrap();
    let (code, _, err) = run(&["convert", "t.cp", "t.fold"], d);
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("line 5, type 7") && err.contains("flat"),
        "{err}"
    );
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("t.fold")).unwrap()).unwrap();
    let flat = v["edges_assignment"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|a| *a == "F")
        .count();
    assert_eq!(flat, 1, "the diagonal is the one flat line: {v}");
    // A type that is not a number: the message lists the same mapping.
    std::fs::write(d.join("x.cp"), "x 0 0 10 10\n").unwrap();
    refused(
        &["convert", "x.cp", "x.fold"],
        d,
        &["line 1", "read as flat"],
    );
}

const TRIANGLE: &str = "\"vertices_coords\": [[0,0],[10,0],[10,10]], \
    \"edges_vertices\": [[0,1],[1,2],[2,0]], \"edges_assignment\": [\"B\",\"B\",\"B\"]";

#[test]
fn fold_duplicate_keys_degenerate_faces_and_broken_frames_are_refused_with_their_place() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let cases = [
        (
            format!("{{{TRIANGLE},\n\"vertices_coords\": [[0,0],[20,0],[20,20]]}}"),
            vec!["line 2", "\"vertices_coords\" appears twice"],
        ),
        (
            format!("{{{TRIANGLE}, \"faces_vertices\": [[0,0,0]]}}"),
            vec!["faces_vertices", "[0]", "follows itself"],
        ),
        (
            format!(
                "{{{TRIANGLE}, \"file_frames\": [{{\"frame_parent\": 7, \"frame_inherit\": true}}]}}"
            ),
            vec!["frame 1", "frame_parent"],
        ),
        (
            format!("{{{TRIANGLE}, \"file_frames\": [{{\"vertices_coords\": \"bad\"}}]}}"),
            vec!["frame 1", "vertices_coords"],
        ),
    ];
    for (i, (text, needles)) in cases.iter().enumerate() {
        let name = format!("case{i}.fold");
        std::fs::write(d.join(&name), text).unwrap();
        refused(&["convert", &name, "out.fold"], d, needles);
        assert!(!d.join("out.fold").exists());
    }
    // The same triangle without the fault converts.
    std::fs::write(d.join("ok.fold"), format!("{{{TRIANGLE}}}")).unwrap();
    let (code, _, err) = run(&["convert", "ok.fold", "out.fold"], d);
    assert_eq!(code, 0, "{err}");
}

/// A GRBL job of `n` alternating travels and burns at S900 between points on a 300 mm square,
/// and the burn length it holds (computed here, not by the simulator).
fn long_job(n: usize) -> (String, f64) {
    let mut text = String::from("G21\nG90\nM4 S0\nF1200\n");
    let mut rng = 0x2545_f491_4f6c_dd1d_u64;
    let mut next = || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        5.0 + (rng % 30_000) as f64 / 100.0
    };
    let (mut at, mut burned) = ((0.0, 0.0), 0.0);
    for i in 0..n {
        let to = (next(), next());
        if i % 2 == 0 {
            text.push_str(&format!("G0 X{:.2} Y{:.2} S0\n", to.0, to.1));
        } else {
            text.push_str(&format!("G1 X{:.2} Y{:.2} S900\n", to.0, to.1));
            burned += ((to.0 - at.0) * (to.0 - at.0) + (to.1 - at.1) * (to.1 - at.1)).sqrt();
        }
        at = to;
    }
    text.push_str("M5\nM2\n");
    (text, burned)
}

/// The burn length at S900 printed by `simulate`.
fn printed_burn(out: &str) -> f64 {
    let line = out
        .lines()
        .find(|l| l.contains("burn at S900"))
        .unwrap_or_else(|| panic!("no burn line in {out}"));
    line.split_whitespace().nth(3).unwrap().parse().unwrap()
}

#[test]
fn a_long_job_is_simulated_streaming_with_the_same_totals_and_drawn() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let n = 200_000;
    let (text, burned) = long_job(n);
    std::fs::write(d.join("long.gcode"), text).unwrap();
    let (code, out, err) = run(&["simulate", "long.gcode", "-m", "grbl-diode"], d);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains(&format!("({} lines)", n + 6)), "{out}");
    let streamed = printed_burn(&out);
    // Printed to 0.1 mm.
    assert!(
        (streamed - burned).abs() <= 0.05 + 1e-9 * burned,
        "{streamed} vs {burned}"
    );
    // With a picture the moves are kept; the totals are the same as streamed.
    let (text, burned) = long_job(20_000);
    std::fs::write(d.join("short.gcode"), text).unwrap();
    let args = ["simulate", "short.gcode", "-m", "grbl-diode"];
    let (_, streamed, _) = run(&args, d);
    let (code, kept, err) = run(&[&args[..], &["--png", "long.png"]].concat(), d);
    assert_eq!(code, 0, "{err}");
    assert_eq!(printed_burn(&kept), printed_burn(&streamed));
    assert!((printed_burn(&kept) - burned).abs() <= 0.05 + 1e-9 * burned);
    let png = std::fs::read(d.join("long.png")).unwrap();
    assert_eq!(&png[1..4], b"PNG");
}

#[test]
fn a_popup_cut_directly_writes_all_its_outputs_or_none() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("card.gcode"), "OLD").unwrap();
    let house = repo_file("examples/popup/house.voxel.txt");
    let base = [
        "popup",
        "voxel",
        house.as_str(),
        "-m",
        "grbl-diode",
        "-x",
        "card-300gsm",
    ];
    let mut failing: Vec<&str> = base.to_vec();
    failing.extend(["-o", "card.gcode", "--png", "nodir/x.png"]);
    let (code, _, err) = run(&failing, d);
    assert_eq!(code, 2, "{err}");
    assert_eq!(
        std::fs::read_to_string(d.join("card.gcode")).unwrap(),
        "OLD"
    );
    assert_eq!(listing(d), vec!["card.gcode".to_string()]);
    let mut fine: Vec<&str> = base.to_vec();
    fine.extend(["-o", "card.gcode", "--png", "card.png"]);
    let (code, out, err) = run(&fine, d);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("pierces"), "{out}");
    assert!(
        std::fs::read_to_string(d.join("card.gcode"))
            .unwrap()
            .contains("G1")
    );
    assert!(d.join("card.png").exists());
}

#[test]
fn long_design_steps_print_an_estimate_first() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let dome = repo_file("examples/tessellation/dome.obj");
    let (code, _, err) = run(
        &[
            "tessellate",
            &dome,
            "-x",
            "stainless-0.5",
            "-o",
            "dome.fold",
        ],
        d,
    );
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("estimate:") && err.contains("star tucks took"),
        "{err}"
    );
    let building = repo_file("examples/popup/building.obj");
    let (code, _, err) = run(&["popup", "voxel", &building, "-o", "b.fold"], d);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("(estimated)"), "{err}");
}

#[test]
fn simulate_json_into_a_closed_pipe_ends_quietly() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (text, _) = long_job(20_000);
    std::fs::write(d.join("job.gcode"), text).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_foldcam"))
        .args(["simulate", "job.gcode", "-m", "grbl-diode", "--json"])
        .current_dir(d)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Read the first line, as `head -1` does, and close the pipe.
    let mut stdout = child.stdout.take().unwrap();
    let mut first = [0u8; 1];
    stdout.read_exact(&mut first).unwrap();
    drop(stdout);
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        assert!(start.elapsed() < HANG_GUARD, "simulate did not end");
        std::thread::sleep(Duration::from_millis(20));
    }
    let out = child.wait_with_output().unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(first, *b"{");
}

#[test]
fn pictures_are_refused_under_a_name_of_another_format() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let script = repo_file("examples/folding/waterbomb-base.toml");
    for name in ["x.jpg", "x.gif", "x.svg"] {
        refused(
            &["fold", &script, "-o", "k.fold", "--png", name],
            d,
            &[name, ".png extension"],
        );
    }
    assert!(listing(d).is_empty(), "{:?}", listing(d));
}
