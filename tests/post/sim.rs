//! The simulated machine on hand-written programs in each dialect: lengths, violations with
//! their lines, units and modes, dwell units, pen states, malformed text, coverage and the
//! PNG.

use foldcam::fab::{ContourRole, FabPlan, Operation, PlanStats, Setup, Side, Toolpath};
use foldcam::machine::{
    Bed, Corner, Dialect, MachineKind, MachineProfile, OperationSettings, SettingsByOperation,
};
use foldcam::pattern::{Assignment, CreasePattern, EdgeId};
use foldcam::sim::{self, SimError, SimReport, ViolationKind};
use glam::{DAffine2, DVec2};
use proptest::prelude::*;

#[path = "sim/coverage.rs"]
mod coverage;
#[path = "sim/render.rs"]
mod render;

/// A 300 × 200 mm laser bed, S 0–1000, 6000 mm/min max, 1000 mm/s².
fn laser(dialect: Dialect) -> MachineProfile {
    MachineProfile {
        name: format!("{dialect:?}").to_lowercase(),
        ..MachineProfile::generic_laser(
            dialect,
            Bed {
                width_mm: 300.0,
                height_mm: 200.0,
                origin: Corner::BottomLeft,
                y_flipped: false,
            },
        )
    }
}

fn plotter() -> MachineProfile {
    MachineProfile {
        kind: MachineKind::Plotter,
        pen_up: vec!["M3 S30".into(), "G4 P0.2".into()],
        pen_down: vec!["M3 S90".into(), "G4 P0.2".into()],
        pen_delay_s: 0.2,
        ..laser(Dialect::Plotter)
    }
}

fn run(text: &str, machine: &MachineProfile) -> SimReport {
    sim::run(text, machine).expect("readable program")
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-6
}

/// Kinds and lines of every violation.
fn found(r: &SimReport) -> Vec<(ViolationKind, usize)> {
    r.violations.iter().map(|v| (v.kind, v.line)).collect()
}

const CLEAN_GRBL: &str = "\
; foldcam test job
G21 G90 G94
M4 S0
G0 X10 Y10
G1 X60 Y10 F1200 S800
G1 X60 Y40
G0 X10 Y40
G1 X10 Y60 S300
G0 X0 Y0 S0
M5
M2
";

#[test]
fn clean_grbl_job() {
    let r = run(CLEAN_GRBL, &laser(Dialect::Grbl));
    assert!(r.is_clean(), "{:?}", r.violations);
    assert_eq!(r.burns.len(), 3);
    assert!(close(r.burn_length_mm, 100.0));
    let by_power: Vec<(f64, f64)> = r
        .burn_by_power
        .iter()
        .map(|p| (p.power, p.length_mm))
        .collect();
    assert_eq!(by_power, vec![(300.0, 20.0), (800.0, 80.0)]);
    let travel = 200f64.sqrt() + 50.0 + (100.0f64 + 3600.0).sqrt();
    assert!(close(r.travel_length_mm, travel), "{}", r.travel_length_mm);
    assert_eq!(r.pierces, 2);
    let bounds = r.burn_bounds.unwrap();
    assert_eq!(
        (bounds.min, bounds.max),
        (DVec2::new(10.0, 10.0), DVec2::new(60.0, 60.0))
    );
    assert_eq!(r.burns[0].line, 5);
    assert_eq!(r.burns[0].feed_mm_min, 1200.0);
    // Time is at least the constant-feed time and not absurdly more.
    let floor = 100.0 / 20.0 + travel / 100.0;
    assert!(r.time_s > floor && r.time_s < floor + 2.0, "{}", r.time_s);
    assert_eq!(r.end_position, DVec2::ZERO);
}

#[test]
fn sim_time_is_the_planner_time_plus_dwells() {
    use foldcam::machine::{Move, job_time};
    let machine = laser(Dialect::Grbl);
    let text = "M4 S500\nG0 X10 Y10\nG1 X40 Y10 F1800\nG1 X40 Y30\nG1 X10 Y10\nG0 X0 Y0\nM5\nM2";
    let r = run(text, &machine);
    let mv = |x: f64, y: f64, rapid| Move {
        to: DVec2::new(x, y),
        feed_mm_min: 1800.0,
        rapid,
        sync: false,
    };
    let moves = [
        mv(10.0, 10.0, true),
        mv(40.0, 10.0, false),
        mv(40.0, 30.0, false),
        mv(10.0, 10.0, false),
        mv(0.0, 0.0, true),
    ];
    assert!(close(r.time_s, job_time(DVec2::ZERO, &moves, &machine)));
    let with_dwell = run(&text.replace("G1 X40 Y30", "G1 X40 Y30\nG4 P2"), &machine);
    let split = job_time(DVec2::ZERO, &moves[..3], &machine)
        + job_time(DVec2::new(40.0, 30.0), &moves[3..], &machine);
    assert!(close(with_dwell.time_s, split + 2.0));
    assert!(
        split > job_time(DVec2::ZERO, &moves, &machine),
        "a dwell stops the machine"
    );
}

/// Seconds to run `length` mm from rest to rest at `v` mm/s with acceleration `a` (closed form:
/// a trapezoid, or a triangle when `v` is not reached).
fn rest_to_rest(length: f64, v: f64, a: f64) -> f64 {
    if v * v / a <= length {
        length / v + v / a
    } else {
        2.0 * (length / a).sqrt()
    }
}

#[test]
fn linuxcnc_stops_between_rapid_and_feed_moves() {
    // Three collinear 10 mm moves, the middle one a rapid: LinuxCNC cannot blend a rapid into
    // a feed move (tp.c, tpCheckCanonType), so each is run from rest to rest. GRBL blends them
    // (a straight continuation), so it is faster; so is LinuxCNC when the middle move is a G1.
    let text = "G1 X10 F1800\nG0 X20\nG1 X30\nM2";
    let (a, feed, rapid) = (1000.0, 30.0, 100.0);
    let lcnc = run(text, &laser(Dialect::LinuxCnc));
    let stops = 2.0 * rest_to_rest(10.0, feed, a) + rest_to_rest(10.0, rapid, a);
    assert!(close(lcnc.time_s, stops), "{} vs {stops}", lcnc.time_s);
    let grbl = run(text, &laser(Dialect::Grbl));
    assert!(grbl.time_s < stops - 0.05, "{} vs {stops}", grbl.time_s);
    let linked_text = text.replace("G0 X20\nG1 X30", "G1 X20 F6000\nG1 X30 F1800");
    let linked = run(&linked_text, &laser(Dialect::LinuxCnc));
    assert!(linked.time_s < stops - 0.05, "{} vs {stops}", linked.time_s);
    assert!(
        close(linked.time_s, grbl.time_s),
        "{} vs {}",
        linked.time_s,
        grbl.time_s
    );
}

#[test]
fn grbl_waits_its_step_idle_delay_at_every_stop_after_motion() {
    // GRBL holds the motors $1 ms each time its moves come to rest (stepper.c, st_go_idle):
    // once after each run of moves, not at a dwell that follows no motion.
    let mut m = laser(Dialect::Grbl);
    m.control.step_idle_delay_s = 0.025;
    let text = "G4 P0.5\nG1 X10 F1800\nG4 P0\nG4 P0\nG1 X20\nM2";
    let run_s = 2.0 * rest_to_rest(10.0, 30.0, 1000.0);
    let r = run(text, &m);
    assert!(close(r.time_s, 0.5 + run_s + 2.0 * 0.025), "{}", r.time_s);
    m.control.step_idle_delay_s = 0.0;
    assert!(close(run(text, &m).time_s, 0.5 + run_s));
}

#[test]
fn each_violation_is_found_on_its_line() {
    let grbl = laser(Dialect::Grbl);
    let cases: [(&str, ViolationKind, usize); 9] = [
        ("G21\nG0 X500 Y10\nM2", ViolationKind::OutOfBed, 2),
        ("G21\nG1 X10 Y-1 F100\nM2", ViolationKind::OutOfBed, 2),
        ("M4 S1500\nM5\nM2", ViolationKind::PowerOutOfRange, 1),
        ("G0 X1\nG1 X2 Q5 F100\nM2", ViolationKind::UnknownWord, 2),
        (
            "G0 X1\n\nG2 X10 Y0 I5 J0 F100\nM2",
            ViolationKind::Unsupported,
            3,
        ),
        ("G1 X10 F99999\nM2", ViolationKind::FeedTooHigh, 1),
        ("M4 S100\nG1 X10\nM5\nM2", ViolationKind::MissingFeed, 2),
        ("G0 X1\nG1 X1.2.3\nM2", ViolationKind::Malformed, 2),
        ("M3 S500\nG1 X10 F100", ViolationKind::ToolLeftOn, 2),
    ];
    for (text, kind, line) in cases {
        let r = run(text, &grbl);
        assert_eq!(found(&r), vec![(kind, line)], "{text}");
    }
}

#[test]
fn rejected_lines_do_not_move() {
    let r = run(
        "G0 X10\nG1 X50 Q5 F100\nG2 X0 Y0 I1 J1\nM2",
        &laser(Dialect::Grbl),
    );
    assert_eq!(r.end_position, DVec2::new(10.0, 0.0));
}

#[test]
fn rapids_with_the_laser_on_depend_on_the_dialect() {
    let text = "M3 S200\nG0 X10 Y10\nG1 X20 F600\nM5\nM2";
    // GRBL blanks G0 in laser mode: no burn, no violation.
    let grbl = run(text, &laser(Dialect::Grbl));
    assert!(grbl.is_clean());
    assert!(close(grbl.burn_length_mm, 10.0));
    // Marlin and LinuxCNC burn along the rapid: flagged and recorded.
    for dialect in [Dialect::Marlin, Dialect::LinuxCnc] {
        let r = run(text, &laser(dialect));
        assert_eq!(
            found(&r),
            vec![(ViolationKind::LitTravel, 2)],
            "{dialect:?}"
        );
        assert!(close(r.burn_length_mm, 10.0 + 200f64.sqrt()));
        assert_eq!(r.pierces, 1, "one continuous burn");
    }
    // S0 is off everywhere.
    let dark = run("M3 S0\nG0 X10 Y10\nM5\nM2", &laser(Dialect::LinuxCnc));
    assert!(dark.is_clean() && dark.burns.is_empty());
}

#[test]
fn inches_convert_to_millimetres() {
    let r = run(
        "G20\nM3 S500\nG1 X1 Y0.5 F10\nM5\nG21\nG0 X0 Y0\nM2",
        &laser(Dialect::Grbl),
    );
    assert!(r.is_clean(), "{:?}", r.violations);
    assert_eq!(r.burns[0].to, DVec2::new(25.4, 12.7));
    assert!(close(r.burns[0].feed_mm_min, 254.0));
    assert_eq!(r.end_position, DVec2::ZERO);
}

#[test]
fn relative_mode_adds_up() {
    let text = "G91\nG0 X10 Y10\nM4 S400\nG1 X5 F600\nG1 Y5\nM5\nG90\nG0 X1 Y1\nM2";
    let r = run(text, &laser(Dialect::Grbl));
    assert!(r.is_clean(), "{:?}", r.violations);
    let ends: Vec<DVec2> = r.burns.iter().map(|b| b.to).collect();
    assert_eq!(ends, vec![DVec2::new(15.0, 10.0), DVec2::new(15.0, 15.0)]);
    assert_eq!(r.end_position, DVec2::new(1.0, 1.0));
}

#[test]
fn dwell_units_per_dialect() {
    let text = "G4 P500\nM2";
    let marlin = run(text, &laser(Dialect::Marlin));
    assert!(close(marlin.dwell_s, 0.5));
    let grbl = run(text, &laser(Dialect::Grbl));
    assert!(close(grbl.dwell_s, 500.0));
    assert!(close(grbl.time_s, 500.0));
    // Marlin's G4 S is seconds and does not set the laser power.
    let s = run("G4 S2\nM3\nG1 X10 F600\nM5\nM2", &laser(Dialect::Marlin));
    assert!(close(s.dwell_s, 2.0));
    assert!(s.burns.is_empty());
}

#[test]
fn lit_dwell_follows_the_laser_mode() {
    let grbl = laser(Dialect::Grbl);
    assert!(close(
        run("M3 S500\nG4 P1.5\nM5\nM2", &grbl).lit_dwell_s,
        1.5
    ));
    assert!(close(
        run("M4 S500\nG4 P1.5\nM5\nM2", &grbl).lit_dwell_s,
        0.0
    ));
    assert!(close(
        run("M4 S500\nG4 P1500\nM5\nM2", &laser(Dialect::Marlin)).lit_dwell_s,
        1.5
    ));
}

#[test]
fn linuxcnc_program_with_tape_marks_and_line_numbers() {
    let text = "%\n(foldcam job)\nN10 G17 G21 G90 G64 P0.01\nN20 M3 S0\nN30 G0 X5 Y5\n\
                N40 G1 X25 Y5 F900 S700 (cut)\nN50 S0\nN60 G0 X0 Y0\nN70 M5\nN80 M2\n%\n";
    let r = run(text, &laser(Dialect::LinuxCnc));
    assert!(r.is_clean(), "{:?}", r.violations);
    assert!(close(r.burn_length_mm, 20.0));
    assert_eq!(r.lines, 11);
}

/// `line*NN` with the XOR checksum of the line.
fn with_sum(line: &str) -> String {
    format!("{line}*{}", line.bytes().fold(0u8, |a, b| a ^ b))
}

#[test]
fn marlin_checksums() {
    let lines = ["N1 M3 S100", "N2 G0 X0", "N3 G1 X10 F600", "N4 M5", "N5 M2"];
    let good: Vec<String> = lines.iter().map(|l| with_sum(l)).collect();
    let r = run(&good.join("\n"), &laser(Dialect::Marlin));
    assert!(r.is_clean(), "{:?}", r.violations);
    assert!(close(r.burn_length_mm, 10.0));
    let mut bad = good.clone();
    bad[2] = with_sum("N3 G1 X11 F600").replace("X11", "X10");
    let r = run(&bad.join("\n"), &laser(Dialect::Marlin));
    assert_eq!(found(&r), vec![(ViolationKind::Checksum, 3)]);
    assert!(
        r.burns.is_empty(),
        "a line with a wrong checksum is rejected"
    );
}

#[test]
fn plotter_pen_states() {
    let text = "G21 G90\nM3 S30\nG4 P0.2\nG0 X10 Y10\nM3 S90\nG4 P0.2\nG1 X20 Y10 F1000\n\
                G1 X20 Y20\nM3 S30\nG4 P0.2\nG0 X0 Y0\nM2";
    let r = run(text, &plotter());
    assert!(r.is_clean(), "{:?}", r.violations);
    assert!(close(r.burn_length_mm, 20.0));
    assert_eq!(r.pierces, 1);
    assert!(close(r.dwell_s, 0.6));
    assert!(r.burns.iter().all(|b| b.power == 0.0));
    // A rapid with the pen down draws: flagged.
    let dragged = run("M3 S90\nG0 X10 Y10\nM3 S30\nM2", &plotter());
    assert_eq!(found(&dragged), vec![(ViolationKind::LitTravel, 2)]);
    assert!(close(dragged.burn_length_mm, 200f64.sqrt()));
    // The pen left down at the end is flagged.
    let left = run("M3 S90\nG1 X10 F500", &plotter());
    assert_eq!(found(&left), vec![(ViolationKind::ToolLeftOn, 2)]);
}

#[test]
fn grbl_system_commands_are_accepted_only_on_grbl() {
    assert!(run("$32=1\nG0 X1\nM2", &laser(Dialect::Grbl)).is_clean());
    let r = run("$32=1\nG0 X1\nM2", &laser(Dialect::Marlin));
    assert_eq!(found(&r), vec![(ViolationKind::UnknownWord, 1)]);
}

#[test]
fn text_after_program_end_is_ignored() {
    let r = run("G0 X5\nM2\nG0 X500\nQ9", &laser(Dialect::Grbl));
    assert!(r.is_clean());
    assert_eq!(r.end_position, DVec2::new(5.0, 0.0));
}

#[test]
fn unreadable_input_is_an_error() {
    let long = format!("G0 X1 ({})", "x".repeat(sim::MAX_LINE_BYTES));
    assert!(matches!(
        sim::run(&long, &laser(Dialect::Grbl)),
        Err(SimError::LineTooLong { line: 1, .. })
    ));
    let file_only = laser(Dialect::FileOnly);
    assert!(matches!(
        sim::run("G0 X1", &file_only),
        Err(SimError::NoGcode { .. })
    ));
}

#[test]
fn violations_are_capped_but_counted() {
    let text = "Q1\n".repeat(sim::MAX_VIOLATIONS + 10);
    let r = run(&text, &laser(Dialect::Grbl));
    assert_eq!(r.violations.len(), sim::MAX_VIOLATIONS);
    assert_eq!(r.violation_count, sim::MAX_VIOLATIONS + 10);
}

/// Regressions: inputs that once looked dangerous.
#[test]
fn hostile_numbers_are_flagged_not_panicking() {
    let grbl = laser(Dialect::Grbl);
    for text in [
        "G1 X1e308 F100",
        "G1 XNaN F100",
        "G1 Xinf F100",
        "G1 X99999999999999999999 F100",
        "G91\nG1 X900000000 F100\nG1 X900000000",
        "G4 P-1",
        "G1 F-5 X1",
        "M99999999999",
        "G0.0000001",
        "(((",
        "\u{0}\u{7f}é ü",
        "N*\n*\n**",
    ] {
        let r = run(text, &grbl);
        assert!(!r.is_clean(), "{text:?} should be flagged");
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    #[test]
    fn random_text_never_panics(text in "\\PC{0,400}") {
        for machine in [laser(Dialect::Grbl), laser(Dialect::Marlin), plotter()] {
            // A report never points past the text, and counts every violation it lists.
            if let Ok(r) = sim::run(&text, &machine) {
                let lines = text.lines().count();
                prop_assert!(r.lines <= lines);
                prop_assert!(r.violations.iter().all(|v| (1..=lines.max(1)).contains(&v.line)));
                prop_assert!(r.violation_count >= r.violations.len());
            }
        }
    }

    #[test]
    fn random_gcode_like_text_never_panics(
        lines in prop::collection::vec(
            "([GMXYZFSPNQIJ*$%();/]|-?[0-9]{0,12}(\\.[0-9]{0,6})?| ){0,14}", 0..40)
    ) {
        let text = lines.join("\n");
        let r = sim::run(&text, &laser(Dialect::LinuxCnc)).unwrap();
        prop_assert!(r.time_s.is_finite() && r.time_s >= 0.0);
        prop_assert!(r.burn_length_mm.is_finite() && r.travel_length_mm.is_finite());
    }
}
