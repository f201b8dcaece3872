//! G-code writers, read back by a small word parser: laser off on travel, power and feed per
//! operation, resolution and number format, passes, dialect framing, round-trip geometry.

use crate::post_common;

use foldcam::fab::{FabPlan, Operation};
use foldcam::machine::{Dialect, LaserMode, MachineProfile};
use foldcam::post::{PostError, gcode};
use glam::{DVec2, dvec2};
use post_common::{job, machine, plan, plotter, toolpath};

/// One parsed line: its words (letter, value text) and its comment, if any.
#[derive(Debug)]
struct Line {
    text: String,
    words: Vec<(char, String)>,
    comment: Option<String>,
}

impl Line {
    fn word(&self, letter: char) -> Option<f64> {
        let w = self.words.iter().find(|(l, _)| *l == letter)?;
        Some(w.1.parse().expect("a number"))
    }
    fn has(&self, letter: char, value: f64) -> bool {
        self.words
            .iter()
            .any(|(l, v)| *l == letter && v.parse::<f64>() == Ok(value))
    }
}

/// Splits a program into lines of words; comments are `;…` or `(…)`.
fn parse(program: &str) -> Vec<Line> {
    program.lines().map(parse_line).collect()
}

fn parse_line(text: &str) -> Line {
    let (code, mut comment) = match text.find(';') {
        Some(i) => (&text[..i], Some(text[i + 1..].trim().to_string())),
        None => (text, None),
    };
    let mut bare = String::new();
    let mut depth = 0;
    for c in code.chars() {
        match c {
            '(' => depth += 1,
            ')' => {
                depth -= 1;
                let start = code.find('(').unwrap() + 1;
                comment = Some(code[start..code.find(')').unwrap()].trim().to_string());
            }
            c if depth == 0 => bare.push(c),
            _ => {}
        }
    }
    let mut words = Vec::new();
    for token in bare.split_whitespace() {
        let letter = token.chars().next().unwrap().to_ascii_uppercase();
        assert!(letter.is_ascii_alphabetic(), "word {token:?} in {text:?}");
        let value = token[1..].to_string();
        assert!(
            !value.is_empty(),
            "word {token:?} without a number in {text:?}"
        );
        words.push((letter, value));
    }
    Line {
        text: text.to_string(),
        words,
        comment,
    }
}

/// A move as the machine would run it.
#[derive(Clone, Copy, Debug)]
struct Move {
    rapid: bool,
    from: DVec2,
    to: DVec2,
    /// Laser output: spindle M3/M4 on and S > 0.
    power: f64,
    feed: f64,
    op: Option<Operation>,
}

/// Runs `lines` through a modal state machine (M3/M4/M5, S, F, G0/G1, X/Y, group comments).
fn run(lines: &[Line]) -> Vec<Move> {
    let (mut at, mut on, mut s, mut f, mut rapid) = (DVec2::ZERO, false, 0.0, 0.0, true);
    let mut op = None;
    let mut moves = Vec::new();
    for line in lines {
        if let Some(name) = line.comment.as_deref().and_then(Operation::from_name) {
            op = Some(name);
        }
        if line.has('M', 3.0) || line.has('M', 4.0) {
            on = true;
        }
        if line.has('M', 5.0) {
            on = false;
        }
        s = line.word('S').unwrap_or(s);
        f = line.word('F').unwrap_or(f);
        if line.has('G', 0.0) {
            rapid = true;
        }
        if line.has('G', 1.0) {
            rapid = false;
        }
        if line.word('X').is_some() || line.word('Y').is_some() {
            let to = dvec2(
                line.word('X').unwrap_or(at.x),
                line.word('Y').unwrap_or(at.y),
            );
            let power = if on { s } else { 0.0 };
            moves.push(Move {
                rapid,
                from: at,
                to,
                power,
                feed: f,
                op,
            });
            at = to;
        }
    }
    moves
}

fn program(plan: &FabPlan, machine: &MachineProfile) -> String {
    gcode(plan, &plan.jobs[0], machine).expect("G-code")
}

/// The plan's burns, snapped and without zero-length segments, repeated per pass.
fn expected_segments(plan: &FabPlan, res: f64) -> Vec<(Operation, DVec2, DVec2)> {
    let snap = |p: DVec2| (p / res).round() * res;
    let mut out = Vec::new();
    for path in &plan.jobs[0].paths {
        for _ in 0..plan.settings.get(path.op).passes {
            for stroke in &path.strokes {
                for w in stroke.windows(2) {
                    if snap(w[0]) != snap(w[1]) {
                        out.push((path.op, w[0], w[1]));
                    }
                }
            }
        }
    }
    out
}

#[test]
fn grbl_travel_is_dark_and_burns_carry_their_power() {
    let (plan, m) = (plan(job()), machine(Dialect::Grbl));
    let lines = parse(&program(&plan, &m));
    let moves = run(&lines);
    assert!(moves.iter().any(|m| m.rapid));
    for mv in &moves {
        if mv.rapid {
            assert_eq!(mv.power, 0.0, "laser on during travel {mv:?}");
            continue;
        }
        let op = mv.op.expect("burn inside an operation group");
        let s = plan.settings.get(op);
        assert_eq!(
            mv.power,
            m.power.min + s.power * (m.power.max - m.power.min)
        );
        assert_eq!(mv.feed, s.speed_mm_min.min(m.max_feed_mm_min));
    }
    assert!(
        lines.iter().any(|l| l.text == "M4 S0"),
        "dynamic mode armed once"
    );
    assert_eq!(lines.iter().filter(|l| l.has('M', 4.0)).count(), 1);
}

#[test]
fn burns_read_back_equal_the_plan_within_the_resolution() {
    for dialect in [Dialect::Grbl, Dialect::Marlin, Dialect::LinuxCnc] {
        let (plan, m) = (plan(job()), machine(dialect));
        let burns: Vec<_> = run(&parse(&program(&plan, &m)))
            .into_iter()
            .filter(|mv| !mv.rapid)
            .collect();
        let expected = expected_segments(&plan, m.resolution_mm);
        assert_eq!(burns.len(), expected.len(), "{dialect:?}");
        let tolerance = m.resolution_mm / 2.0 + 1e-9;
        for (mv, (op, a, b)) in burns.iter().zip(&expected) {
            assert_eq!(mv.op, Some(*op));
            assert!(
                mv.from.distance(*a) <= tolerance * 2f64.sqrt(),
                "{mv:?} vs {a}"
            );
            assert!(
                mv.to.distance(*b) <= tolerance * 2f64.sqrt(),
                "{mv:?} vs {b}"
            );
            assert!(mv.power > 0.0, "{dialect:?}: burn without power {mv:?}");
            let feed = plan.settings.get(*op).speed_mm_min.min(m.max_feed_mm_min);
            assert_eq!(mv.feed, feed, "{dialect:?}: {mv:?}");
        }
    }
}

#[test]
fn passes_repeat_the_whole_toolpath() {
    let (plan, m) = (plan(job()), machine(Dialect::Grbl));
    let cuts: Vec<_> = run(&parse(&program(&plan, &m)))
        .into_iter()
        .filter(|mv| !mv.rapid && mv.op == Some(Operation::Cut))
        .collect();
    assert_eq!(plan.settings.cut.passes, 2);
    assert_eq!(cuts.len(), 8, "a closed square of four sides, twice");
    for i in 0..4 {
        assert_eq!(cuts[i].from, cuts[i + 4].from);
        assert_eq!(cuts[i].to, cuts[i + 4].to);
    }
}

#[test]
fn coordinates_sit_on_the_resolution_without_float_noise() {
    for res in [0.001, 0.01, 0.025] {
        let mut m = machine(Dialect::Grbl);
        m.resolution_mm = res;
        let text = program(&plan(job()), &m);
        assert!(text.contains("56.744") || res != 0.001, "{text}");
        for line in parse(&text) {
            for (letter, value) in line.words.iter().filter(|(l, _)| matches!(l, 'X' | 'Y')) {
                let v: f64 = value.parse().unwrap();
                let steps = v / res;
                assert!(
                    (steps - steps.round()).abs() < 1e-6,
                    "{letter}{value} at {res}"
                );
                assert!(!value.contains(['e', 'E']), "exponent in {value}");
                assert_ne!(value, "-0");
                let decimals = value.split('.').nth(1).map_or(0, str::len);
                assert!(decimals <= 3, "float noise in {value}");
            }
        }
    }
}

#[test]
fn zero_length_moves_are_skipped() {
    let (plan, mut m) = (plan(job()), machine(Dialect::Grbl));
    (m.preamble, m.postamble) = (Vec::new(), Vec::new());
    for mv in run(&parse(&program(&plan, &m))) {
        assert_ne!(mv.from, mv.to, "zero-length move {mv:?}");
    }
}

#[test]
fn preamble_postamble_and_program_end_frame_the_moves() {
    let m = machine(Dialect::Grbl);
    let text = program(&plan(job()), &m);
    let lines: Vec<&str> = text.lines().collect();
    let pos = |needle: &str| lines.iter().position(|l| *l == needle).expect(needle);
    let (g21, g90) = (pos("G21"), pos("G90"));
    let (pre, post) = (pos(&m.preamble[0]), pos(&m.postamble[0]));
    let first_burn = lines.iter().position(|l| l.starts_with("G1")).unwrap();
    let last_burn = lines.iter().rposition(|l| l.starts_with("G1")).unwrap();
    assert!(g21 < pre && g90 < pre && pre < first_burn);
    assert!(last_burn < pos("M5") && pos("M5") < post);
    assert_eq!(lines.last(), Some(&"M2"));
}

#[test]
fn one_comment_per_operation_group() {
    let mut j = job();
    let extra = toolpath(
        Operation::Cut,
        vec![vec![dvec2(80.0, 80.0), dvec2(90.0, 80.0)]],
    );
    j.paths.push(extra);
    let text = program(&plan(j), &machine(Dialect::Grbl));
    let groups: Vec<_> = parse(&text)
        .into_iter()
        .filter_map(|l| l.comment.as_deref().and_then(Operation::from_name))
        .collect();
    let want = [
        Operation::Mark,
        Operation::Score,
        Operation::Perforate,
        Operation::Cut,
    ];
    assert_eq!(groups, want);
}

#[test]
fn marlin_sets_power_inline_and_blanks_travel() {
    let mut m = machine(Dialect::Marlin);
    m.laser_mode = LaserMode::Constant;
    let text = program(&plan(job()), &m);
    let lines = parse(&text);
    assert!(lines.iter().any(|l| l.text == "M3 S0 I1"), "{text}");
    assert_eq!(
        lines.iter().filter(|l| l.has('M', 3.0)).count(),
        1,
        "armed once"
    );
    let ours = |l: &&Line| !m.preamble.contains(&l.text) && !m.postamble.contains(&l.text);
    for line in lines.iter().filter(ours).filter(|l| l.has('G', 0.0)) {
        assert_eq!(
            line.word('S'),
            Some(0.0),
            "travel without S0: {}",
            line.text
        );
    }
    assert!(!lines.iter().any(|l| l.has('M', 2.0)), "Marlin has no M2");
    assert_eq!(lines.last().unwrap().text, m.postamble[0]);
}

#[test]
fn linuxcnc_frames_each_stroke_and_uses_parentheses() {
    let text = program(&plan(job()), &machine(Dialect::LinuxCnc));
    assert!(text.contains("(cut)") && !text.contains("; cut"), "{text}");
    let lines = parse(&text);
    let mut on = false;
    for line in &lines {
        if line.has('M', 3.0) {
            on = true;
        } else if line.has('M', 5.0) {
            on = false;
        }
        if line.has('G', 0.0) {
            assert!(!on, "spindle on during travel: {}", line.text);
        }
        assert!(!line.has('M', 4.0), "M4 is reverse rotation on LinuxCNC");
    }
    assert_eq!(lines.last().unwrap().text, "M2");
}

#[test]
#[ignore = "needs rs274 (Debian linuxcnc-uspace)"]
fn linuxcnc_interpreter_accepts_the_program() {
    let _alone = post_common::external_tools_alone();
    let plan = plan(job());
    let text = program(&plan, &machine(Dialect::LinuxCnc));
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("job.ngc");
    std::fs::write(&file, &text).unwrap();
    let out = std::process::Command::new("rs274")
        .arg("-g")
        .arg(&file)
        .output()
        .expect("rs274 (Debian linuxcnc-uspace) runs");
    let canon = String::from_utf8_lossy(&out.stdout);
    let errors = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "rs274 refused:\n{errors}\n{canon}");
    let feeds = canon.matches("STRAIGHT_FEED(").count();
    assert_eq!(feeds, expected_segments(&plan, 0.001).len());
    assert!(canon.contains("PROGRAM_END()"));
    let mut spinning = false;
    for call in canon.lines() {
        spinning = (spinning || call.contains("START_SPINDLE")) && !call.contains("STOP_SPINDLE");
        assert!(!(spinning && call.contains("STRAIGHT_TRAVERSE")), "{call}");
    }
}

#[test]
fn plotter_lifts_the_pen_before_every_travel_and_dwells_in_seconds() {
    let m = plotter(Dialect::Plotter);
    let text = program(&plan(job()), &m);
    pen_discipline(&text, &m);
    assert!(
        text.contains("G4 P0.15"),
        "GRBL-style dwell in seconds:\n{text}"
    );
}

#[test]
fn marlin_plotter_dwells_in_milliseconds() {
    let m = plotter(Dialect::Marlin);
    let text = program(&plan(job()), &m);
    pen_discipline(&text, &m);
    assert!(text.contains("G4 P150"), "Marlin dwell in ms:\n{text}");
    assert!(!text.contains("G4 P0.15"));
}

/// Pen up before every travel, down before every burn; no S words but the pen's own.
fn pen_discipline(text: &str, m: &MachineProfile) {
    let mut down = None;
    for line in parse(text) {
        if m.pen_up.contains(&line.text) {
            down = Some(false);
            continue;
        }
        if m.pen_down.contains(&line.text) {
            down = Some(true);
            continue;
        }
        assert!(
            line.word('S').is_none(),
            "S word on a plotter: {}",
            line.text
        );
        if line.has('G', 0.0) {
            assert_eq!(down, Some(false), "travel with the pen down: {}", line.text);
        }
        if line.has('G', 1.0) {
            assert_eq!(down, Some(true), "burn with the pen up: {}", line.text);
        }
    }
    assert_eq!(down, Some(false), "pen left down");
}

#[test]
fn file_only_machines_take_no_gcode() {
    let plan = plan(job());
    let err = gcode(&plan, &plan.jobs[0], &machine(Dialect::FileOnly)).unwrap_err();
    assert!(matches!(err, PostError::NoGcode { .. }), "{err}");
}

#[test]
fn nan_never_reaches_the_output() {
    let m = machine(Dialect::Grbl);
    let mut bad = plan(job());
    bad.jobs[0].paths[1].strokes[0][1].x = f64::NAN;
    let err = gcode(&bad, &bad.jobs[0], &m).unwrap_err();
    assert!(
        matches!(
            err,
            PostError::BadCoordinate {
                path: 1,
                stroke: 0,
                ..
            }
        ),
        "{err}"
    );

    let mut bad = plan(job());
    bad.settings.cut.power = f64::NAN;
    let err = gcode(&bad, &bad.jobs[0], &m).unwrap_err();
    assert!(
        matches!(err, PostError::BadSetting { key: "power", .. }),
        "{err}"
    );

    let mut bad = plan(job());
    bad.settings.score.speed_mm_min = f64::INFINITY;
    let err = gcode(&bad, &bad.jobs[0], &m).unwrap_err();
    assert!(
        matches!(
            err,
            PostError::BadSetting {
                op: "score",
                key: "speed_mm_min",
                ..
            }
        ),
        "{err}"
    );

    let mut bad_machine = machine(Dialect::Grbl);
    bad_machine.resolution_mm = 0.0;
    let plan = plan(job());
    let err = gcode(&plan, &plan.jobs[0], &bad_machine).unwrap_err();
    assert!(
        matches!(
            err,
            PostError::BadMachine {
                key: "resolution_mm",
                ..
            }
        ),
        "{err}"
    );
}

#[test]
fn power_out_of_range_and_zero_passes_are_refused() {
    let m = machine(Dialect::Grbl);
    let mut bad = plan(job());
    bad.settings.mark.power = 1.5;
    let err = gcode(&bad, &bad.jobs[0], &m).unwrap_err();
    assert!(
        matches!(err, PostError::BadSetting { op: "mark", key: "power", value, .. } if value == 1.5),
        "{err}"
    );
    let mut bad = plan(job());
    bad.settings.perforate.passes = 0;
    let err = gcode(&bad, &bad.jobs[0], &m).unwrap_err();
    assert!(
        matches!(
            err,
            PostError::BadSetting {
                op: "perforate",
                key: "passes",
                ..
            }
        ),
        "{err}"
    );
}

#[test]
fn empty_jobs_are_an_error_not_a_panic() {
    let m = machine(Dialect::Grbl);
    let mut empty = plan(job());
    empty.jobs[0].paths.clear();
    let err = gcode(&empty, &empty.jobs[0], &m).unwrap_err();
    assert!(matches!(err, PostError::EmptyJob { .. }));
    let mut dots = plan(job());
    let dot = vec![dvec2(1.0, 1.0), dvec2(1.0001, 1.0)];
    dots.jobs[0].paths = vec![toolpath(
        Operation::Cut,
        vec![dot, Vec::new(), vec![DVec2::ONE]],
    )];
    let err = gcode(&dots, &dots.jobs[0], &m).unwrap_err();
    assert!(matches!(err, PostError::EmptyJob { .. }));
}

/// The header names the output the program switches, by the number its `M67` words use
/// (it said `motion.analog-out-NN`).
#[test]
fn linuxcnc_header_names_the_output_the_program_switches() {
    use foldcam::machine::{load_machine, load_material};
    let machine = load_machine("linuxcnc-fiber").unwrap();
    let material = load_material("stainless-0.5").unwrap();
    let cp = foldcam::design::classic::MiuraOri::default()
        .build()
        .unwrap();
    let o =
        foldcam::fab::PlanOptions::for_machine(&machine, &material, &Default::default()).unwrap();
    let p = foldcam::fab::plan(&cp, &machine, &material, &o).unwrap();
    let text = foldcam::post::gcode(&p, &p.jobs[0], &machine).unwrap();
    assert!(!text.contains("-NN"), "{}", &text[..600.min(text.len())]);
    let pin = text
        .split("motion.analog-out-")
        .nth(1)
        .and_then(|rest| rest.get(..2))
        .expect("the header names the analog output");
    let number: u32 = pin.parse().unwrap();
    let switches: Vec<&str> = text.lines().filter(|l| l.starts_with("M67")).collect();
    assert!(!switches.is_empty());
    for line in switches {
        assert!(
            line.contains(&format!(" E{number} ")),
            "{line}: not the output the header names ({pin})"
        );
    }
}

/// Every dialect's header names the source, the machine and the material, and the settings of
/// each operation, in comments of the dialect's own syntax (no `;` or `%` inside LinuxCNC's
/// parentheses), and the simulated machine still reads the program clean.
#[test]
fn gcode_headers_name_source_machine_material_and_settings() {
    use foldcam::machine::{load_machine, load_material};
    let mut cp = foldcam::design::classic::MiuraOri::default()
        .build()
        .unwrap();
    cp.meta.title = Some("crane; 22.5° 100% ×".into());
    for (machine, material, comment) in [
        ("grbl-diode", "card-300gsm", ";"),
        ("marlin-laser", "card-300gsm", ";"),
        ("linuxcnc-fiber", "stainless-0.5", "("),
        ("grbl-pen-plotter", "paper-160gsm", ";"),
    ] {
        let m = load_machine(machine).unwrap();
        let x = load_material(material).unwrap();
        let o = foldcam::fab::PlanOptions::for_machine(&m, &x, &Default::default()).unwrap();
        let p = foldcam::fab::plan(&cp, &m, &x, &o).unwrap();
        let text = gcode(&p, &p.jobs[0], &m).unwrap();
        let header: Vec<&str> = text
            .lines()
            .take_while(|l| l.starts_with(comment))
            .collect();
        let all = header.join("\n");
        assert!(all.contains(machine), "{machine}: {all}");
        assert!(
            all.contains(&format!("material: {material}")),
            "{machine}: {all}"
        );
        assert!(
            all.contains("source: crane, 22.5d 100? x"),
            "{machine}: {all}"
        );
        assert!(
            all.contains("speed ") && all.contains("pass"),
            "{machine}: {all}"
        );
        if !m.pen_tool() {
            assert!(all.contains("power "), "{machine}: {all}");
        }
        if comment == "(" {
            for line in &header {
                assert!(line.ends_with(')'), "{line}");
                assert!(!line.contains(';') && !line.contains('%'), "{line}");
            }
        }
        let run = foldcam::sim::run(&text, &m).unwrap();
        assert!(run.is_clean(), "{machine}: {:?}", run.violations.first());
    }
}
