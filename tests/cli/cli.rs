//! The `foldcam` binary end to end: exit codes, messages that name the file, atomic outputs.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn foldcam(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_foldcam"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("the foldcam binary runs")
}

fn example(name: &str) -> String {
    let p = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("examples/patterns")
        .join(name);
    p.to_string_lossy().into_owned()
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// Files in `dir`, sorted (to see that nothing was left behind).
fn listing(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .expect("temp dir readable")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn convert_round_trips_through_every_format() {
    let dir = tempfile::tempdir().expect("temp dir");
    let src = example("flat-vertex.fold");
    for ext in ["svg", "cp", "fold"] {
        let out = format!("out.{ext}");
        let o = foldcam(&["convert", &src, &out], dir.path());
        assert!(o.status.success(), "convert to {ext}: {}", text(&o.stderr));
        let back = format!("back-{ext}.fold");
        let o = foldcam(&["convert", &out, &back], dir.path());
        assert!(
            o.status.success(),
            "convert {ext} back: {}",
            text(&o.stderr)
        );
        let a = foldcam::formats::load(Path::new(&src))
            .expect("source loads")
            .pattern;
        let b = foldcam::formats::load(&dir.path().join(&back))
            .expect("result loads")
            .pattern;
        assert_eq!(a.edges.len(), b.edges.len(), "edge count through {ext}");
        // Every edge comes back at the same place with the same assignment (a swapped
        // mountain/valley or a moved vertex fails here).
        let (lo, hi) = a.bounds().expect("vertices");
        let tol = 1e-5 * (hi - lo).max_element();
        for e in &a.edges {
            let [p, q] = e.vertices.map(|v| a.position(v));
            let twin = b.edges.iter().find(|f| {
                let [r, s] = f.vertices.map(|v| b.position(v));
                (p.distance(r) <= tol && q.distance(s) <= tol)
                    || (p.distance(s) <= tol && q.distance(r) <= tol)
            });
            let twin = twin.unwrap_or_else(|| panic!("edge {p}-{q} lost through {ext}"));
            assert_eq!(twin.assignment, e.assignment, "edge {p}-{q} through {ext}");
        }
    }
}

#[test]
fn check_exit_codes_follow_the_verdict() {
    let dir = tempfile::tempdir().expect("temp dir");
    // flat-vertex.fold's creases are stored at ±150°, a 3D target without a 3D frame: its
    // vertex passes Kawasaki and Maekawa, but the pass says NOT CHECKED and exits 1 unless
    // --allow-unchecked accepts that.
    let good = foldcam(&["check", &example("flat-vertex.fold")], dir.path());
    assert_eq!(good.status.code(), Some(1), "{}", text(&good.stdout));
    assert!(text(&good.stdout).contains("PASS, but NOT CHECKED at 1 of 1 interior vertices"));
    let good = foldcam(
        &["check", "--allow-unchecked", &example("flat-vertex.fold")],
        dir.path(),
    );
    assert_eq!(good.status.code(), Some(0), "{}", text(&good.stdout));
    let bad = foldcam(&["check", &example("broken-vertex.fold")], dir.path());
    assert_eq!(bad.status.code(), Some(1));
    let out = text(&bad.stdout).to_lowercase();
    assert!(out.contains("kawasaki") && out.contains("maekawa"), "{out}");
    let json = foldcam(
        &["check", "--json", &example("broken-vertex.fold")],
        dir.path(),
    );
    assert_eq!(json.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&json.stdout).expect("valid JSON");
    let kinds: Vec<&str> = v["findings"]
        .as_array()
        .expect("findings array")
        .iter()
        .filter_map(|f| f["kind"].as_str())
        .collect();
    assert!(
        kinds.contains(&"kawasaki") && kinds.contains(&"maekawa"),
        "{kinds:?}"
    );
}

#[test]
fn vertex_angle_limit_fails_the_check() {
    let dir = tempfile::tempdir().expect("temp dir");
    // flat-vertex.fold's smallest sector is 60° (its ±150° creases, a 3D target, accepted).
    let ok = foldcam(
        &[
            "check",
            "--allow-unchecked",
            "--min-vertex-angle",
            "50",
            &example("flat-vertex.fold"),
        ],
        dir.path(),
    );
    assert_eq!(ok.status.code(), Some(0), "{}", text(&ok.stdout));
    let tight = foldcam(
        &[
            "check",
            "--min-vertex-angle",
            "70",
            &example("flat-vertex.fold"),
        ],
        dir.path(),
    );
    assert_eq!(tight.status.code(), Some(1), "{}", text(&tight.stdout));
}

#[test]
fn preview_writes_a_png_of_the_requested_width() {
    let dir = tempfile::tempdir().expect("temp dir");
    let o = foldcam(
        &[
            "preview",
            &example("broken-vertex.fold"),
            "-o",
            "p.png",
            "--width",
            "321",
            "--check",
        ],
        dir.path(),
    );
    // The broken vertex fails Kawasaki and Maekawa: the preview is written with the faults
    // ringed, and the exit status says so, as `foldcam check` does.
    assert_eq!(o.status.code(), Some(1), "{}", text(&o.stderr));
    let img = image::open(dir.path().join("p.png")).expect("a PNG");
    assert_eq!(img.width(), 321);
}

#[test]
fn preview_check_exit_status_follows_the_faults() {
    let dir = tempfile::tempdir().expect("temp dir");
    let run = |input: &str, out: &str, check: bool| {
        let mut args = vec!["preview", input, "-o", out, "--width", "200"];
        if check {
            args.push("--check");
        }
        foldcam(&args, dir.path())
    };
    let good = run(&example("flat-vertex.fold"), "good.png", true);
    assert_eq!(good.status.code(), Some(0), "{}", text(&good.stderr));
    let bad = run(&example("broken-vertex.fold"), "bad.png", true);
    assert_eq!(bad.status.code(), Some(1), "{}", text(&bad.stderr));
    assert!(
        text(&bad.stderr).contains("ringed"),
        "{}",
        text(&bad.stderr)
    );
    // Without --check nothing is judged.
    let plain = run(&example("broken-vertex.fold"), "plain.png", false);
    assert_eq!(plain.status.code(), Some(0), "{}", text(&plain.stderr));
    assert_eq!(listing(dir.path()), ["bad.png", "good.png", "plain.png"]);
}

#[test]
fn generated_patterns_pass_their_check() {
    let dir = tempfile::tempdir().expect("temp dir");
    let last = |o: &std::process::Output| {
        text(&o.stdout)
            .trim_end()
            .lines()
            .last()
            .unwrap_or("")
            .to_string()
    };
    for kind in ["miura", "square-twist", "waterbomb", "yoshimura"] {
        // Folded flat (180°), Kawasaki and Maekawa decide: a plain pass.
        let flat = format!("{kind}-flat.fold");
        let o = foldcam(
            &["generate", kind, "--fold-angle", "180", "-o", &flat],
            dir.path(),
        );
        assert!(o.status.success(), "{kind}: {}", text(&o.stderr));
        let c = foldcam(&["check", &flat], dir.path());
        assert_eq!(c.status.code(), Some(0), "{kind}: {}", text(&c.stdout));
        assert!(
            last(&c).starts_with("PASS (checked: flat_foldability ("),
            "{kind}: {}",
            last(&c)
        );
        // At the default 170° the creases are a 3D target that no frame shows: Kawasaki and
        // Maekawa hold, but the pass says what was not checked and exits 1 unless accepted.
        let out = format!("{kind}.fold");
        let o = foldcam(&["generate", kind, "-o", &out], dir.path());
        assert!(o.status.success(), "{kind}: {}", text(&o.stderr));
        let c = foldcam(&["check", &out], dir.path());
        assert_eq!(c.status.code(), Some(1), "{kind}: {}", text(&c.stdout));
        assert!(
            last(&c).starts_with("PASS, but NOT CHECKED at "),
            "{kind}: {}",
            last(&c)
        );
        assert!(
            last(&c).contains("Kawasaki and Maekawa hold there all the same"),
            "{kind}: {}",
            last(&c)
        );
        let c = foldcam(&["check", &out, "--allow-unchecked"], dir.path());
        assert_eq!(c.status.code(), Some(0), "{kind}: {}", text(&c.stdout));
    }
}

#[test]
fn demo_runs_end_to_end() {
    let dir = tempfile::tempdir().expect("temp dir");
    let o = foldcam(&["demo", "--out", "d", "--width", "300"], dir.path());
    assert!(
        o.status.success(),
        "{}\n{}",
        text(&o.stdout),
        text(&o.stderr)
    );
    let files = listing(&dir.path().join("d"));
    for stem in [
        "miura-ori",
        "square-twist",
        "waterbomb",
        "yoshimura",
        "broken-vertex",
    ] {
        for ext in ["fold", "svg", "cp", "png"] {
            let name = format!("{stem}.{ext}");
            assert!(files.contains(&name), "{name} missing from {files:?}");
        }
    }
    // The design stages: tessellation (Tachi 2014) and paper craft (Ōgaki 2016), each with its
    // machine job (the demo fails when the simulated machine finds a problem in one).
    for name in [
        "tessellation-dome.fold",
        "tessellation-dome.linuxcnc-fiber.stainless-0.5.ngc",
        "tessellation-mask.fold",
        "tessellation-mask.linuxcnc-fiber.stainless-0.5.ngc",
        "papercraft-vase-1.fold",
        "papercraft-vase-1.png",
        "papercraft-vase-1.grbl-diode.paper-160gsm.gcode",
        "fold3d-miura.fold",
        "fold3d-miura.png",
        "fold3d-miura.gif",
    ] {
        assert!(
            files.contains(&name.to_string()),
            "{name} missing from {files:?}"
        );
    }
    let sheet = foldcam::formats::load(&dir.path().join("d/papercraft-vase-1.fold"))
        .expect("the vase sheet reads back");
    assert!(
        sheet.pattern.edges.len() > 100,
        "{}",
        sheet.pattern.edges.len()
    );
    // The 3D fold stage: the Miura-ori's folded form is a frame of its FOLD file, in 3D.
    let miura = foldcam::formats::load(&dir.path().join("d/fold3d-miura.fold"))
        .expect("the folded Miura-ori reads back");
    let folded = miura.folded.expect("a foldedForm frame");
    assert!(folded.positions.iter().any(|p| p.z.abs() > 1.0));
    // Folded, the sheet is not stretched: every edge keeps its flat length (the bar-and-hinge
    // model lets bars strain a little).
    crate::isometry::assert_isometric(&miura.pattern, &folded, 0.01, "folded Miura-ori");
    // Every machine job the demo wrote runs clean on the simulated machine it names
    // (`PATTERN.MACHINE.MATERIAL.EXT`), names a shipped material, burns or draws something
    // and has its toolpath picture.
    let mut jobs = 0;
    for name in &files {
        let Some((_, machine, material, stem)) = job_name_parts(name) else {
            continue;
        };
        foldcam::machine::load_material(material).unwrap_or_else(|e| panic!("{name}: {e}"));
        let picture = format!("{stem}.toolpath.png");
        assert!(files.contains(&picture), "{picture} missing from {files:?}");
        let machine =
            foldcam::machine::load_machine(machine).unwrap_or_else(|e| panic!("{name}: {e}"));
        let program = std::fs::read_to_string(dir.path().join("d").join(name)).expect("job");
        // Its header names the pattern it came from, designs included, and its material.
        let (pattern, _, material, _) = job_name_parts(name).unwrap();
        let source = program
            .lines()
            .find_map(|l| {
                l.split_once("source: ")
                    .map(|(_, s)| s.trim_end_matches(')').to_string())
            })
            .unwrap_or_else(|| panic!("{name}: no source line"));
        assert!(
            source.ends_with(&format!("material: {material}")),
            "{name}: {source}"
        );
        assert!(!source.contains("without a name"), "{name}: {source}");
        if pattern.starts_with("popup-") || pattern.starts_with("tessellation-") {
            assert!(source.starts_with(pattern), "{name}: {source}");
        }
        let run = foldcam::sim::run(&program, &machine).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(run.is_clean(), "{name}: {:?}", run.violations.first());
        assert!(
            run.burn_length_mm > 10.0,
            "{name}: {} mm",
            run.burn_length_mm
        );
        jobs += 1;
    }
    assert!(jobs >= 8, "{jobs} jobs in {files:?}");
    demo_index_lists_every_job_and_picture(&dir.path().join("d"), &files);
}

/// A design made into a job by its command names the design file as the job's source.
#[test]
fn design_jobs_name_their_design_file_as_source() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let house = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/popup/house.voxel.txt");
    let taj = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/popup/taj-mahal.popup.toml");
    for (design, out, want) in [
        (
            &house,
            "house.gcode",
            "; source: house, material: card-300gsm",
        ),
        (
            &taj,
            "taj.gcode",
            "; source: taj-mahal, material: card-300gsm",
        ),
    ] {
        let command = if design == &house { "voxel" } else { "poly" };
        let o = foldcam(
            &[
                "popup",
                command,
                design.to_str().unwrap(),
                "-m",
                "grbl-diode",
                "-x",
                "card-300gsm",
                "-o",
                out,
            ],
            d,
        );
        assert!(o.status.success(), "{}", text(&o.stderr));
        let program = std::fs::read_to_string(d.join(out)).unwrap();
        assert!(program.lines().any(|l| l == want), "{out}: {program:.600}");
    }
    assert_eq!(
        foldcam::design::source::design_title(Path::new("a/vase.craft.toml")).as_deref(),
        Some("vase")
    );
    assert_eq!(
        foldcam::design::source::design_title(Path::new("scan.v2.OBJ")).as_deref(),
        Some("scan.v2")
    );
}

/// A G-code job's name `PATTERN.MACHINE.MATERIAL.EXT` split at the shipped machine it names
/// (material names hold dots, `stainless-0.5`), with the name without its extension.
fn job_name_parts(name: &str) -> Option<(&str, &str, &str, &str)> {
    let (stem, ext) = name.rsplit_once('.')?;
    if !matches!(ext, "gcode" | "ngc" | "nc") {
        return None;
    }
    foldcam::machine::shipped_machines()
        .into_iter()
        .find_map(|m| {
            let (pattern, material) = stem.split_once(&format!(".{m}."))?;
            Some((pattern, m, material, stem))
        })
}

/// The demo's `index.html` (parsed as the XML it is written as) lists every job file of the
/// folder in its table, and every picture or file it links exists there.
fn demo_index_lists_every_job_and_picture(dir: &Path, files: &[String]) {
    let html = std::fs::read_to_string(dir.join("index.html")).expect("the demo writes index.html");
    let doc = roxmltree::Document::parse_with_options(
        &html,
        roxmltree::ParsingOptions {
            allow_dtd: true,
            ..Default::default()
        },
    )
    .unwrap_or_else(|e| panic!("index.html: {e}"));
    let linked = |tag: &str, attr: &str| -> Vec<String> {
        doc.descendants()
            .filter(|n| n.has_tag_name(tag))
            .filter_map(|n| n.attribute(attr).map(str::to_string))
            .collect()
    };
    let (links, images) = (linked("a", "href"), linked("img", "src"));
    for target in links.iter().chain(&images) {
        assert!(
            !target.contains('/') && !target.contains(':'),
            "{target}: not a relative link in the folder"
        );
        assert!(
            files.contains(target),
            "index.html links {target}, not in {files:?}"
        );
    }
    let rows: Vec<_> = doc.descendants().filter(|n| n.has_tag_name("tr")).collect();
    for name in files {
        let Some((pattern, machine, material, _)) = job_name_parts(name) else {
            continue;
        };
        let row = rows
            .iter()
            .find(|r| {
                r.descendants()
                    .any(|a| a.attribute("href") == Some(name.as_str()))
            })
            .unwrap_or_else(|| panic!("index.html does not list {name}"));
        let cells: Vec<String> = row
            .children()
            .filter(|c| c.has_tag_name("td"))
            .map(|c| {
                c.descendants()
                    .filter(|t| t.is_text())
                    .filter_map(|t| t.text())
                    .collect()
            })
            .collect();
        assert_eq!(&cells[..3], [pattern, machine, material], "{name}");
        assert!(
            cells[3].ends_with(" s"),
            "{name}: planned time {:?}",
            cells[3]
        );
        assert!(
            cells[4].ends_with(" s"),
            "{name}: simulated time {:?}",
            cells[4]
        );
        assert!(
            row.descendants().any(|i| i.has_tag_name("img")),
            "{name}: no toolpath picture"
        );
    }
    for preview in ["miura-ori.png", "popup-house.gif", "fold3d-miura.png"] {
        assert!(
            images.iter().any(|i| i == preview),
            "index.html shows no {preview}"
        );
    }
}

/// Malformed inputs: exit 2, the message names the file, no panic, and no output file (nor
/// a temporary one) is left behind.
#[test]
fn malformed_inputs_fail_cleanly_without_output() {
    let deep = format!("{}{}", "[".repeat(100_000), "]".repeat(100_000));
    let cases: Vec<(&str, String)> = vec![
        ("empty.fold", String::new()),
        ("truncated.fold", r#"{"vertices_coords": [[0,0],[1,"#.into()),
        ("deep.fold", deep),
        ("mismatch.fold", r#"{"vertices_coords":[[0,0],[1,0]],"edges_vertices":[[0,1]],"edges_assignment":["M","V"]}"#.into()),
        ("negative.fold", r#"{"vertices_coords":[[0,0],[1,0]],"edges_vertices":[[0,-1]]}"#.into()),
        ("missing.fold", r#"{"vertices_coords":[[0,0],[1,0]],"edges_vertices":[[0,7]]}"#.into()),
        ("nonnumeric.fold", r#"{"vertices_coords":[[0,"a"],[1,0]],"edges_vertices":[[0,1]]}"#.into()),
        ("huge.fold", r#"{"vertices_coords":[[0,0],[1e12,0]],"edges_vertices":[[0,1]]}"#.into()),
        ("overflow.fold", r#"{"vertices_coords":[[0,0],[1e400,0]],"edges_vertices":[[0,1]]}"#.into()),
        ("onevertex.fold", r#"{"vertices_coords":[[0,0],[1,0]],"edges_vertices":[[0]]}"#.into()),
        ("letter.fold", r#"{"vertices_coords":[[0,0],[1,0]],"edges_vertices":[[0,1]],"edges_assignment":["X"]}"#.into()),
        ("angle.fold", r#"{"vertices_coords":[[0,0],[1,0]],"edges_vertices":[[0,1]],"edges_foldAngle":[270]}"#.into()),
        ("notxml.svg", "this is not < xml".into()),
        ("nolines.svg", r#"<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10"><circle cx="5" cy="5" r="2" fill="red"/></svg>"#.into()),
        ("bad.cp", "2 0 0 1 1\n3 0 zero 1 1\n".into()),
        ("short.cp", "2 0 0 1\n".into()),
    ];
    for (name, content) in cases {
        let dir = tempfile::tempdir().expect("temp dir");
        std::fs::write(dir.path().join(name), content).expect("write input");
        let o = foldcam(&["convert", name, "out.fold"], dir.path());
        let err = text(&o.stderr);
        assert_eq!(
            o.status.code(),
            Some(2),
            "{name}: exit {:?}, stderr {err}",
            o.status.code()
        );
        assert!(
            err.contains(name),
            "{name}: message does not name the file: {err}"
        );
        assert!(!err.contains("panicked"), "{name}: panicked: {err}");
        assert_eq!(
            listing(dir.path()),
            vec![name.to_string()],
            "{name}: output left behind"
        );
    }
}

#[test]
fn bad_usage_exits_2() {
    let dir = tempfile::tempdir().expect("temp dir");
    let o = foldcam(&["convert", "a.fold", "b.xyz"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    let o = foldcam(&["check", "--min-vertex-angle", "-5", "a.fold"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    let o = foldcam(&["check", "does-not-exist.fold"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("does-not-exist.fold"));
}

#[test]
fn frame_option_reads_a_later_frame_with_inheritance() {
    let dir = tempfile::tempdir().expect("temp dir");
    let fold = r#"{
      "file_spec": 1.2, "frame_unit": "mm",
      "vertices_coords": [[0,0],[10,0],[10,10]],
      "edges_vertices": [[0,1],[1,2],[2,0]],
      "edges_assignment": ["B","B","V"],
      "file_frames": [{"frame_parent": 0, "frame_inherit": true,
                       "vertices_coords": [[0,0],[20,0],[20,20]]}]
    }"#;
    std::fs::write(dir.path().join("multi.fold"), fold).expect("write");
    let o = foldcam(
        &["convert", "multi.fold", "f1.fold", "--fold-frame", "1"],
        dir.path(),
    );
    assert!(o.status.success(), "{}", text(&o.stderr));
    let cp = foldcam::formats::load(&dir.path().join("f1.fold"))
        .expect("loads")
        .pattern;
    let (_, hi) = cp.bounds().expect("vertices");
    assert_eq!(hi, glam::DVec2::new(20.0, 20.0), "frame 1's coordinates");
    assert_eq!(cp.edges.len(), 3, "edges inherited from frame 0");
    let o = foldcam(
        &["convert", "multi.fold", "f9.fold", "--fold-frame", "9"],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("multi.fold"));
    let o = foldcam(
        &[
            "check",
            &example("preliminary-base.cp"),
            "--fold-frame",
            "1",
        ],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(2), "--fold-frame on a .cp file");
}

#[test]
fn scale_gives_a_unitless_pattern_millimetres() {
    let dir = tempfile::tempdir().expect("temp dir");
    let o = foldcam(
        &[
            "convert",
            &example("preliminary-base.cp"),
            "sized.fold",
            "--size",
            "150",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", text(&o.stderr));
    let cp = foldcam::formats::load(&dir.path().join("sized.fold"))
        .expect("loads")
        .pattern;
    assert_eq!(cp.units, foldcam::pattern::Units::Millimetres);
    let (lo, hi) = cp.bounds().expect("vertices");
    assert!(((hi - lo).max_element() - 150.0).abs() < 1e-9);
    let raw = std::fs::read_to_string(dir.path().join("sized.fold")).expect("read");
    assert!(raw.contains("\"frame_unit\": \"mm\""), "{raw}");
}

#[test]
fn unitless_patterns_ask_for_a_size_until_given_one() {
    let mut cp = foldcam::formats::load(Path::new(&example("preliminary-base.cp")))
        .expect("loads")
        .pattern;
    let err = cp
        .require_millimetres()
        .expect_err("ORIPA files are unitless");
    assert!(err.to_string().contains("--size"), "{err}");
    cp.scale_to_mm(0.5);
    assert_eq!(cp.require_millimetres(), Ok(()));
}

#[test]
fn an_edgeless_fold_file_is_refused() {
    let dir = tempfile::tempdir().expect("temp dir");
    std::fs::write(dir.path().join("e.fold"), "{}").expect("write");
    for args in [vec!["check", "e.fold"], vec!["convert", "e.fold", "e.svg"]] {
        let o = foldcam(&args, dir.path());
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(text(&o.stderr).contains("no edges"), "{}", text(&o.stderr));
    }
    assert_eq!(listing(dir.path()), vec!["e.fold".to_string()]);
}

#[test]
fn an_absurd_scale_is_refused_without_output() {
    let dir = tempfile::tempdir().expect("temp dir");
    let o = foldcam(
        &[
            "convert",
            &example("preliminary-base.cp"),
            "big.fold",
            "--scale",
            "1e308",
        ],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(2), "{}", text(&o.stderr));
    assert!(listing(dir.path()).is_empty());
}

#[test]
fn piles_of_identical_lines_clean_quickly_to_one_edge_each() {
    // 5,000 copies of one line (the crossing search would be cubic without deduplication),
    // and one line across it so that the pattern has a sheet (lines on one line are refused).
    let dir = tempfile::tempdir().expect("temp dir");
    let mut pile: String = (0..5000).map(|_| "2 0 0 100 0\n").collect();
    pile.push_str("1 0 0 0 100\n");
    std::fs::write(dir.path().join("pile.cp"), pile).expect("write");
    let o = foldcam(&["convert", "pile.cp", "one.fold"], dir.path());
    assert!(o.status.success(), "{}", text(&o.stderr));
    let cp = foldcam::formats::load(&dir.path().join("one.fold"))
        .expect("loads")
        .pattern;
    assert_eq!(cp.edges.len(), 2);
}

#[test]
fn cut_writes_jobs_the_simulated_machine_accepts() {
    let dir = tempfile::tempdir().expect("temp dir");
    let src = example("flat-vertex.fold");
    let o = foldcam(
        &[
            "cut",
            &src,
            "-m",
            "grbl-diode",
            "-x",
            "card-300gsm",
            "-o",
            "job.gcode",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", text(&o.stderr));
    assert!(text(&o.stdout).contains("pierces"), "plan summary printed");
    let o = foldcam(
        &[
            "simulate",
            "job.gcode",
            "-m",
            "grbl-diode",
            "--png",
            "path.png",
            "--pattern",
            &src,
            "-x",
            "card-300gsm",
        ],
        dir.path(),
    );
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}{}",
        text(&o.stdout),
        text(&o.stderr)
    );
    assert!(text(&o.stdout).contains("PASS"));
    assert!(image::open(dir.path().join("path.png")).is_ok());
    // Two-sided: one file per job.
    let o = foldcam(
        &[
            "cut",
            &src,
            "-m",
            "linuxcnc-fiber",
            "-x",
            "stainless-0.5",
            "-o",
            "two.ngc",
            "--two-sided",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", text(&o.stderr));
    let files = listing(dir.path());
    assert!(
        files.contains(&"two.front.ngc".to_string()) && files.contains(&"two.back.ngc".to_string()),
        "{files:?}"
    );
    // DXF and SVG for a file-only machine.
    for out in ["job.dxf", "job.svg"] {
        let o = foldcam(
            &[
                "cut",
                &src,
                "-m",
                "lightburn",
                "-x",
                "stainless-0.5",
                "-o",
                out,
            ],
            dir.path(),
        );
        assert!(o.status.success(), "{out}: {}", text(&o.stderr));
    }
    // G-code for a file-only machine is refused.
    let o = foldcam(
        &[
            "cut",
            &src,
            "-m",
            "lightburn",
            "-x",
            "stainless-0.5",
            "-o",
            "no.gcode",
        ],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(!listing(dir.path()).contains(&"no.gcode".to_string()));
}

#[test]
fn cut_refuses_what_cannot_be_made_without_writing() {
    let dir = tempfile::tempdir().expect("temp dir");
    let cases: Vec<(Vec<String>, &str)> = vec![
        // ORIPA files have no size.
        (
            vec![
                example("preliminary-base.cp"),
                "-m".into(),
                "grbl-diode".into(),
                "-x".into(),
                "card-300gsm".into(),
            ],
            "--size",
        ),
        // 2 m does not fit a 400 mm bed.
        (
            vec![
                example("flat-vertex.fold"),
                "--size".into(),
                "2000".into(),
                "-m".into(),
                "grbl-diode".into(),
                "-x".into(),
                "card-300gsm".into(),
            ],
            "does not fit",
        ),
        // Unknown profiles list the shipped ones.
        (
            vec![
                example("flat-vertex.fold"),
                "-m".into(),
                "nope".into(),
                "-x".into(),
                "card-300gsm".into(),
            ],
            "grbl-diode",
        ),
        // A laser cannot plot.
        (
            vec![
                example("flat-vertex.fold"),
                "-m".into(),
                "grbl-diode".into(),
                "-x".into(),
                "card-300gsm".into(),
                "--mountain".into(),
                "plot".into(),
            ],
            "cannot plot",
        ),
    ];
    for (mut args, expect) in cases {
        args.insert(0, "cut".into());
        args.extend(["-o".into(), "out.gcode".into()]);
        let refs: Vec<&str> = args.iter().map(String::as_str).collect();
        let o = foldcam(&refs, dir.path());
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", text(&o.stderr));
        assert!(
            text(&o.stderr).contains(expect),
            "{args:?}: {}",
            text(&o.stderr)
        );
        assert!(listing(dir.path()).is_empty(), "{args:?} left output");
    }
}

#[test]
fn simulate_reports_violations_with_exit_1() {
    let dir = tempfile::tempdir().expect("temp dir");
    let job = "G21\nG90\nM4 S0\nG0 X10 Y10\nG1 X900 Y10 S500 F1000\nM5\nM2\n";
    std::fs::write(dir.path().join("bad.gcode"), job).expect("write");
    let o = foldcam(&["simulate", "bad.gcode", "-m", "grbl-diode"], dir.path());
    assert_eq!(o.status.code(), Some(1), "{}", text(&o.stdout));
    assert!(
        text(&o.stdout).contains("line      5"),
        "{}",
        text(&o.stdout)
    );
    let o = foldcam(
        &[
            "plan",
            &example("flat-vertex.fold"),
            "-m",
            "grbl-diode",
            "-x",
            "card-300gsm",
            "--json",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", text(&o.stderr));
    let stats: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    assert!(stats["pierces"].as_u64().unwrap_or(0) > 0);
}

#[test]
fn popup_voxel_card_is_written_previewed_and_cuts_clean() {
    let dir = tempfile::tempdir().expect("temp dir");
    let house = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/popup/house.voxel.txt");
    let house = house.to_string_lossy().into_owned();
    let o = foldcam(
        &[
            "popup",
            "voxel",
            &house,
            "-o",
            "house.fold",
            "--png",
            "house.png",
            "--width",
            "200",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", text(&o.stderr));
    assert_eq!(
        image::open(dir.path().join("house.png"))
            .expect("PNG")
            .width(),
        200
    );
    let o = foldcam(
        &[
            "cut",
            "house.fold",
            "-m",
            "grbl-diode",
            "-x",
            "card-300gsm",
            "-o",
            "house.gcode",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", text(&o.stderr));
    // A floating block (a row standing out further than the row below, with a gap) is refused.
    let floating = "cell_mm 5\ndepth 4\nheight 4\nrows\n0 0 0 0\n0 2 2 0\n0 0 0 0\n0 0 0 0\n";
    std::fs::write(dir.path().join("bad.voxel.txt"), floating).expect("write");
    let o = foldcam(
        &["popup", "voxel", "bad.voxel.txt", "-o", "bad.fold"],
        dir.path(),
    );
    // Bad input: exit 2 (not a panic's 101), naming the file, the line and the rule broken.
    assert_eq!(o.status.code(), Some(2), "{}", text(&o.stdout));
    let err = text(&o.stderr);
    assert!(
        err.contains("bad.voxel.txt: line 6") && err.contains("staircase"),
        "{err}"
    );
    assert!(!listing(dir.path()).contains(&"bad.fold".to_string()));
}

#[test]
fn popup_voxel_from_a_mesh_cuts_directly_and_saves_its_voxels() {
    let dir = tempfile::tempdir().expect("temp dir");
    let mesh = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/popup/building.obj");
    let mesh = mesh.to_string_lossy().into_owned();
    // Straight to G-code: `cut` refuses to write a job the simulated machine faults on.
    let o = foldcam(
        &[
            "popup",
            "voxel",
            &mesh,
            "--resolution",
            "60",
            "-m",
            "grbl-diode",
            "-x",
            "card-300gsm",
            "-o",
            "building.gcode",
            "--save-voxels",
            "building.voxel.txt",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", text(&o.stderr));
    let gcode = std::fs::read_to_string(dir.path().join("building.gcode")).expect("G-code");
    let machine = foldcam::machine::load_machine("grbl-diode").expect("profile");
    let report = foldcam::sim::run(&gcode, &machine).expect("simulated");
    assert_eq!(report.violation_count, 0);
    assert!(
        text(&o.stderr).contains("pop-up checks"),
        "progress is reported"
    );
    // The saved model reads back and makes the same card.
    let o = foldcam(
        &["popup", "voxel", "building.voxel.txt", "-o", "again.fold"],
        dir.path(),
    );
    assert!(o.status.success(), "{}", text(&o.stderr));
    let o = foldcam(
        &[
            "popup",
            "voxel",
            &mesh,
            "--resolution",
            "60",
            "-o",
            "direct.fold",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", text(&o.stderr));
    let load = |name: &str| {
        foldcam::formats::load(&dir.path().join(name))
            .expect("card loads")
            .pattern
    };
    let (again, direct) = (load("again.fold"), load("direct.fold"));
    assert_eq!(
        again.vertices, direct.vertices,
        "same card from the saved voxels"
    );
    assert_eq!(again.edges, direct.edges, "same card from the saved voxels");
    // A broken mesh is refused, naming the file, and nothing is written.
    std::fs::write(
        dir.path().join("bad.obj"),
        "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n",
    )
    .expect("write");
    let o = foldcam(&["popup", "voxel", "bad.obj", "-o", "bad.fold"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("bad.obj"), "{}", text(&o.stderr));
    assert!(!listing(dir.path()).contains(&"bad.fold".to_string()));
}

#[test]
fn tessellation_passes_the_checks_that_apply_to_it() {
    // A star-tuck dome folds to a 3D form (every fold below 180°): Kawasaki and Maekawa, which
    // describe folding flat, do not apply; the fabrication limits it was solved for do, and
    // the FOLD file's 3D frame must unfold onto the pattern.
    let dir = tempfile::tempdir().expect("temp dir");
    let dome = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/tessellation/dome.obj");
    let o = foldcam(
        &[
            "tessellate",
            &dome.to_string_lossy(),
            "-x",
            "stainless-0.5",
            "-o",
            "t.fold",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", text(&o.stderr));
    let o = foldcam(&["convert", "t.fold", "t.svg"], dir.path());
    assert!(o.status.success(), "{}", text(&o.stderr));
    let limits = [
        "--min-vertex-angle",
        "30",
        "--max-fold-angle",
        "165",
        "--json",
    ];
    for (file, frame) in [("t.svg", false), ("t.fold", true)] {
        let mut args = vec!["check", file];
        args.extend(limits);
        let o = foldcam(&args, dir.path());
        // Without the 3D frame nothing judged whether the SVG's vertices fold (they are 3D
        // targets, and a star-tuck vertex does not fold flat): NOT CHECKED, exit 1.
        assert_eq!(
            o.status.code(),
            Some(if frame { 0 } else { 1 }),
            "{file}: {}",
            text(&o.stdout)
        );
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
        let unchecked = v["unchecked_vertices"].as_u64().unwrap();
        let (all_3d, flat_3d) = (
            v["summary"]["vertices_3d"].as_u64().unwrap(),
            v["summary"]["vertices_3d_flat"].as_u64().unwrap(),
        );
        assert_eq!(
            unchecked,
            if frame { 0 } else { all_3d - flat_3d },
            "{file}"
        );
        assert!(frame || unchecked > 0, "{file}");
        let run = |name: &str| {
            v["runs"]
                .as_array()
                .expect("runs")
                .iter()
                .find(|r| r["name"] == name)
                .cloned()
                .expect(name)
        };
        assert_eq!(run("flat_foldability")["ran"], false, "{file}");
        assert!(v["summary"]["vertices_3d"].as_u64().unwrap() > 0);
        assert_eq!(run("vertex_angle")["ran"], true);
        assert_eq!(run("fold_angle")["ran"], true);
        // Only the FOLD file carries the 3D frame.
        assert_eq!(run("developability")["ran"], frame, "{file}");
    }
    let allowed = foldcam(&["check", "t.svg", "--allow-unchecked"], dir.path());
    assert_eq!(allowed.status.code(), Some(0), "{}", text(&allowed.stdout));
    assert!(text(&allowed.stdout).contains("NOT CHECKED"));
    // Tighter limits than the solve's still fail: the check is not switched off.
    let o = foldcam(&["check", "t.svg", "--max-fold-angle", "120"], dir.path());
    assert_eq!(o.status.code(), Some(1), "{}", text(&o.stdout));
    let out = text(&o.stdout);
    assert!(out.contains("flat_foldability  not run"), "{out}");
}

/// `serve --open` on a machine whose opener fails (xdg-open without a browser prints a line
/// for every program it tries) says so once, in its own words, and keeps serving.
#[test]
fn serve_open_without_a_browser_says_so_once() {
    use std::io::{BufRead, BufReader, Read};
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().unwrap();
    let opener = dir.path().join("xdg-open");
    let script =
        "#!/bin/sh\nfor p in a b c d e f g; do echo \"xdg-open: no method $p\" >&2; done\nexit 3\n";
    std::fs::write(&opener, script).unwrap();
    std::fs::set_permissions(&opener, std::fs::Permissions::from_mode(0o755)).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_foldcam"))
        .args(["serve", "--port", "0", "--open"])
        .current_dir(dir.path())
        .env("PATH", dir.path())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut first)
        .unwrap();
    assert!(first.starts_with("foldcam studio: http://"), "{first}");
    let mut stderr = child.stderr.take().unwrap();
    // The warning comes once the opener has ended; the server is still running then.
    let start = std::time::Instant::now();
    let mut said = Vec::new();
    let mut buf = [0u8; 4096];
    let whole_line = |said: &[u8]| {
        let text = String::from_utf8_lossy(said);
        text.split_once("could not open a browser")
            .is_some_and(|(_, rest)| rest.contains('\n'))
    };
    while !whole_line(&said) && start.elapsed() < std::time::Duration::from_secs(20) {
        let n = stderr.read(&mut buf).unwrap();
        if n == 0 {
            break;
        }
        said.extend_from_slice(&buf[..n]);
    }
    assert!(child.try_wait().unwrap().is_none(), "the server stopped");
    child.kill().unwrap();
    child.wait().unwrap();
    let said = String::from_utf8_lossy(&said);
    assert_eq!(
        said.matches("could not open a browser").count(),
        1,
        "{said}"
    );
    assert!(said.contains("open http://127.0.0.1:"), "{said}");
    assert!(
        !said.contains("no method"),
        "the opener's own lines: {said}"
    );
}

/// Every import says the size it was read at (an SVG's pixels become millimetres at 96 dpi
/// unless it says otherwise): the note's width, height and line count are the written FOLD's.
#[test]
fn every_import_says_the_size_it_read() {
    let dir = tempfile::tempdir().unwrap();
    let crane = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/traditionalCrane.svg");
    let out = foldcam(
        &["convert", crane.to_str().unwrap(), "crane.fold"],
        dir.path(),
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stderr = String::from_utf8_lossy(&out.stderr);
    let fold: serde_json::Value =
        serde_json::from_slice(&std::fs::read(dir.path().join("crane.fold")).unwrap()).unwrap();
    let coords: Vec<[f64; 2]> = fold["vertices_coords"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()])
        .collect();
    let range = |k: usize| {
        coords.iter().fold((f64::MAX, f64::MIN), |(lo, hi), p| {
            (lo.min(p[k]), hi.max(p[k]))
        })
    };
    let ((x0, x1), (y0, y1)) = (range(0), range(1));
    let lines = fold["edges_vertices"].as_array().unwrap().len();
    // The size, then where it lies in the frame the findings' positions use: y up, so the
    // SVG's page (y down from its top) lies below y = 0.
    let want = format!(
        "read {:.1} × {:.1} mm, {lines} lines; x {x0:.1} to {x1:.1}, y {y0:.1} to {y1:.1} (y up: \
         an SVG's page, whose y runs down, lies below y = 0)",
        x1 - x0,
        y1 - y0
    );
    assert!(y1 <= 0.0);
    assert!(stderr.contains(&want), "{want} not in\n{stderr}");
    // Quiet runs say only results and warnings.
    let quiet = foldcam(
        &["convert", crane.to_str().unwrap(), "quiet.fold", "-q"],
        dir.path(),
    );
    assert!(!String::from_utf8_lossy(&quiet.stderr).contains("read "));
}

/// `foldcam COMMAND --help`, which must succeed.
fn help_text(command: &[&str], dir: &Path) -> String {
    let mut args = command.to_vec();
    args.push("--help");
    let out = foldcam(&args, dir);
    assert!(out.status.success(), "{command:?}");
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// The help of every command and of `popup`'s subcommands, as (command, text).
fn every_help_text(dir: &Path) -> Vec<(String, String)> {
    let top = help_text(&[], dir);
    let commands: Vec<String> = top
        .lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| !l.trim().is_empty())
        // A command's line, not its description's wrapped continuation.
        .filter(|l| !l.starts_with("   "))
        .filter_map(|l| l.split_whitespace().next().map(str::to_string))
        .filter(|c| c != "help")
        .collect();
    assert!(commands.len() > 15, "{top}");
    let mut texts = Vec::new();
    for command in commands {
        texts.push((command.clone(), help_text(&[command.as_str()], dir)));
        if command == "popup" {
            for sub in ["voxel", "poly"] {
                texts.push((format!("popup {sub}"), help_text(&["popup", sub], dir)));
            }
        }
    }
    texts
}

/// Every example in every command's help is a whole command line: it starts with `foldcam` (or
/// `cargo`), or continues one that ends with ` \\`; none is wrapped mid-command.
#[test]
fn help_examples_are_whole_command_lines() {
    let dir = tempfile::tempdir().unwrap();
    let mut examples = 0;
    for (command, text) in every_help_text(dir.path()) {
        {
            let mut continued = false;
            for line in text
                .lines()
                .skip_while(|l| !l.starts_with("Example"))
                .skip(1)
                .take_while(|l| !l.trim().is_empty())
            {
                let whole = line.starts_with("  foldcam ") || line.starts_with("  cargo ");
                assert!(
                    whole || (continued && line.starts_with("      ")),
                    "`{command} --help`: an example wrapped mid-command: {line:?}"
                );
                examples += usize::from(whole);
                continued = line.ends_with(" \\");
            }
        }
    }
    assert!(examples > 30, "{examples} examples");
}

/// Symbols from the papers are said in plain words where they appear: Tachi's δ's in the help,
/// the layer solver's constraint names, the bar stiffness EA of `fold3d`; the tessellation
/// solver's ρ and θ are no longer printed by name.
#[test]
fn symbols_come_with_plain_words() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (command, text) in every_help_text(d) {
        let flat = text.split_whitespace().collect::<Vec<_>>().join(" ");
        for (symbol, plain) in [
            ("δ_corner", "Tachi 2014 calls it δ_corner"),
            (
                "δ_fold",
                "180 minus the opening a fold must keep (Tachi 2014's δ_fold)",
            ),
        ] {
            let uses = flat.matches(symbol).count();
            assert_eq!(
                flat.matches(plain).count(),
                uses,
                "`{command} --help`: {symbol} without its plain words"
            );
        }
        for bare in ["|rho|", "theta", "EA "] {
            assert!(!flat.contains(bare), "`{command} --help` says {bare}");
        }
    }
    let bird = example("bird-base.cp");
    let o = foldcam(&["check", &bird, "--layers"], d);
    let text = String::from_utf8_lossy(&o.stdout);
    for plain in [
        "taco-taco ",
        " (two creases along one line), taco-tortilla ",
        " (a crease across a face), tortilla-tortilla ",
        " (faces sharing an overlap), transitivity ",
        " (three faces stacked)",
    ] {
        assert!(text.contains(plain), "{plain:?} not in\n{text}");
    }
    let o = foldcam(
        &["fold3d", &bird, "-o", "bird3d.fold", "--percent", "30"],
        d,
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let both = format!(
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(
        both.contains("of a bar's stiffness EA (Young's modulus × cross-section)"),
        "{both}"
    );
}

/// `--from` is offered by the commands that read a pattern, `--to` by those that write
/// files, and neither by the others (they were listed under every command).
#[test]
fn stdin_and_stdout_formats_are_offered_where_they_apply() {
    let dir = tempfile::tempdir().unwrap();
    let help = |command: &[&str]| {
        let text = help_text(command, dir.path());
        (
            text.contains("--from <FORMAT>"),
            text.contains("--to <FORMAT>"),
        )
    };
    // `simulate --pattern` reads a pattern too.
    for command in [
        &["convert"][..],
        &["preview"],
        &["cut"],
        &["fold3d"],
        &["fold-flat"],
        &["simulate"],
    ] {
        assert_eq!(help(command), (true, true), "{command:?}");
    }
    for command in [&["check"][..], &["plan"]] {
        assert_eq!(help(command), (true, false), "{command:?}");
    }
    for command in [
        &["generate"][..],
        &["fold"],
        &["tessellate"],
        &["papercraft"],
        &["testgrid"],
        &["popup", "voxel"],
        &["popup", "poly"],
    ] {
        assert_eq!(help(command), (false, true), "{command:?}");
    }
    for command in [
        &["list"][..],
        &["serve"],
        &["demo"],
        &["man"],
        &["completions"],
    ] {
        assert_eq!(help(command), (false, false), "{command:?}");
    }
}

/// Every command's help names the formats from the one table the readers and writers use
/// (`convert` left out `.opx`, `cut` `.lbrn2`).
#[test]
fn help_lists_the_formats_of_the_format_table() {
    use foldcam::formats::Format;
    let dir = tempfile::tempdir().unwrap();
    // Long help wraps lines: join them.
    let help = |command: &[&str]| {
        help_text(command, dir.path())
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ")
    };
    for command in [
        "check",
        "convert",
        "preview",
        "cut",
        "plan",
        "fold3d",
        "fold-flat",
    ] {
        assert!(help(&[command]).contains(Format::EXTENSIONS), "{command}");
    }
    assert!(help(&["convert"]).contains(Format::WRITABLE));
    assert!(help(&["cut"]).contains(foldcam::job::JOB_EXTENSIONS));
    for command in [&["generate"][..], &["popup", "voxel"], &["tessellate"]] {
        let text = help(command);
        assert!(text.contains(Format::WRITABLE), "{command:?}");
        assert!(text.contains(foldcam::job::JOB_EXTENSIONS), "{command:?}");
    }
}

/// Option placeholders name a unit or a kind of thing, one style throughout (`<MM>`, `<DEG>`,
/// `<N>`, `<PX>`, `<SECONDS>`, `<SHARE>` for 0 to 1, `<PNG>`, …), never a field name such
/// as `<TIME_LIMIT>` or `<MAX_FOLD_ANGLE>`.
#[test]
fn option_placeholders_share_one_style() {
    const UNITS: [&str; 12] = [
        "MM", "LEN", "DEG", "N", "SHARE", "PX", "SECONDS", "PERCENT", "CELLS", "FACES", "MIB",
        "SCALE",
    ];
    const KINDS: [&str; 22] = [
        "X,Y", "OP", "FORMAT", "OUTPUT", "MATERIAL", "MACHINE", "PNG", "GIF", "SVG", "FILE", "DIR",
        "PATH", "ORIGIN", "MEANING", "VALUES", "UP", "TUCK", "SIDE", "PORT", "HOST", "LAYOUT",
        "METHOD",
    ];
    let dir = tempfile::tempdir().unwrap();
    let commands: [&[&str]; 18] = [
        &["convert"],
        &["check"],
        &["preview"],
        &["generate"],
        &["cut"],
        &["plan"],
        &["simulate"],
        &["popup", "voxel"],
        &["popup", "poly"],
        &["fold-flat"],
        &["fold"],
        &["fold3d"],
        &["papercraft"],
        &["demo"],
        &["tessellate"],
        &["list"],
        &["testgrid"],
        &["serve"],
    ];
    for command in commands {
        let text = help_text(command, dir.path());
        for line in text
            .lines()
            .map(str::trim_start)
            .filter(|l| l.starts_with('-'))
        {
            let Some(start) = line.find('<') else {
                continue;
            };
            // Only the option's own placeholder, before its help text.
            if line[..start].contains("  ") {
                continue;
            }
            let name = &line[start + 1..start + line[start..].find('>').unwrap()];
            assert!(
                UNITS.contains(&name) || KINDS.contains(&name),
                "{command:?}: {line}"
            );
        }
    }
}

/// A tessellation whose folded form lies farther than 5% of the mesh's size from it is written
/// but exits 1 and says why, unless `--allow-partial`; one that fits exits 0 and says how well.
#[test]
fn a_partial_tessellation_exits_1_unless_allowed() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let mesh = |name: &str| {
        PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("examples/tessellation")
            .join(name)
            .to_string_lossy()
            .into_owned()
    };
    let saddle = mesh("saddle.obj");
    let run = |extra: &[&str], out: &str| {
        let mut args = vec![
            "tessellate",
            saddle.as_str(),
            "-x",
            "stainless-0.5",
            "-o",
            out,
        ];
        args.extend_from_slice(extra);
        foldcam(&args, d)
    };
    let o = run(&[], "partial.fold");
    assert_eq!(o.status.code(), Some(1), "{}", text(&o.stderr));
    let err = text(&o.stderr);
    assert!(
        err.contains("the tessellation is partial: a face corner lies")
            && err.contains("--allow-partial accepts it"),
        "{err}"
    );
    assert!(d.join("partial.fold").exists(), "written all the same");
    let o = run(&["--allow-partial"], "allowed.fold");
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert!(text(&o.stderr).contains("(accepted: --allow-partial)"));
    // The distance it names is the largest corner distance it reports, over 5% of the size.
    let out = text(&o.stdout);
    let line = out
        .lines()
        .find(|l| l.starts_with("fit to the input"))
        .expect(&out);
    assert!(line.contains("covers 99.8% of its area"), "{line}");
    // The dome fits: exit 0, its whole area covered.
    let dome = mesh("dome.obj");
    let o = foldcam(
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
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert!(text(&o.stdout).contains("fit to the input: covers 100.0% of its area"));
}
