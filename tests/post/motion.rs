//! The motion-time model against closed forms: trapezoids, triangles, junction speeds.

use foldcam::machine::{Bed, Corner, Dialect, MachineProfile};
use foldcam::machine::{Kinematics, Move, job_time, junction_speed, move_times};
use glam::DVec2;
use proptest::prelude::*;

/// Acceleration 1000 mm/s², feeds up to 6000 mm/min (100 mm/s), travel 6000 mm/min.
fn machine() -> MachineProfile {
    MachineProfile {
        name: "test".into(),
        ..MachineProfile::generic_laser(
            Dialect::Grbl,
            Bed {
                width_mm: 400.0,
                height_mm: 400.0,
                origin: Corner::BottomLeft,
                y_flipped: false,
            },
        )
    }
}

fn feed(x: f64, y: f64, f: f64) -> Move {
    Move {
        to: DVec2::new(x, y),
        feed_mm_min: f,
        rapid: false,
        sync: false,
    }
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * b.abs().max(1.0)
}

#[test]
fn long_move_is_a_trapezoid() {
    // v = 50 mm/s, a = 1000 mm/s²: t = L/v + v/a.
    let t = job_time(DVec2::ZERO, &[feed(200.0, 0.0, 3000.0)], &machine());
    assert!(close(t, 200.0 / 50.0 + 50.0 / 1000.0), "{t}");
}

#[test]
fn short_move_is_a_triangle() {
    // Reaching 50 mm/s needs 1.25 mm each way; 1 mm never gets there: t = 2√(L/a).
    let t = job_time(DVec2::ZERO, &[feed(0.0, 1.0, 3000.0)], &machine());
    assert!(close(t, 2.0 * (1.0f64 / 1000.0).sqrt()), "{t}");
}

#[test]
fn straight_continuation_does_not_slow_down() {
    let split: Vec<Move> = (1..=10)
        .map(|i| feed(20.0 * i as f64, 0.0, 3000.0))
        .collect();
    let t = job_time(DVec2::ZERO, &split, &machine());
    assert!(close(t, 200.0 / 50.0 + 50.0 / 1000.0), "{t}");
}

#[test]
fn reversal_stops_fully() {
    let m = machine();
    let there_and_back = [feed(100.0, 0.0, 3000.0), feed(0.0, 0.0, 3000.0)];
    let t = job_time(DVec2::ZERO, &there_and_back, &m);
    let one = job_time(DVec2::ZERO, &[feed(100.0, 0.0, 3000.0)], &m);
    assert!(close(t, 2.0 * one), "{t} vs 2 × {one}");
}

#[test]
fn feed_is_capped_at_the_machine_maximum() {
    let m = machine();
    let fast = job_time(DVec2::ZERO, &[feed(300.0, 0.0, 60_000.0)], &m);
    let max = job_time(DVec2::ZERO, &[feed(300.0, 0.0, 6000.0)], &m);
    assert!(close(fast, max));
}

#[test]
fn rapids_use_the_travel_feed() {
    let mut m = machine();
    m.travel_feed_mm_min = 1200.0; // 20 mm/s
    let rapid = Move {
        to: DVec2::new(100.0, 0.0),
        feed_mm_min: 1.0,
        rapid: true,
        sync: false,
    };
    let t = job_time(DVec2::ZERO, &[rapid], &m);
    assert!(close(t, 100.0 / 20.0 + 20.0 / 1000.0), "{t}");
}

#[test]
fn corner_costs_more_than_straight_and_less_than_a_stop() {
    let m = machine();
    let corner = [feed(100.0, 0.0, 3000.0), feed(100.0, 100.0, 3000.0)];
    let t = job_time(DVec2::ZERO, &corner, &m);
    let straight = job_time(DVec2::ZERO, &[feed(200.0, 0.0, 3000.0)], &m);
    let stop = 2.0 * job_time(DVec2::ZERO, &[feed(100.0, 0.0, 3000.0)], &m);
    assert!(straight < t && t < stop, "{straight} < {t} < {stop}");
}

#[test]
fn time_grows_with_path_length() {
    let m = machine();
    let mut last = 0.0;
    for i in 1..200 {
        let len = 0.05 * f64::from(i) * f64::from(i);
        let t = job_time(DVec2::ZERO, &[feed(len, 0.0, 3000.0)], &m);
        assert!(t > last, "length {len}: {t} after {last}");
        last = t;
    }
}

#[test]
fn junction_speed_limits() {
    let x = DVec2::X;
    assert_eq!(junction_speed(x, -x, 1000.0, 0.01), 0.0);
    assert_eq!(junction_speed(x, x, 1000.0, 0.01), f64::INFINITY);
    // 90°: sin(θ/2) = √½, v² = a δ √½ / (1 − √½).
    let s = 0.5f64.sqrt();
    let expected = (1000.0 * 0.01 * s / (1.0 - s)).sqrt();
    assert!(close(junction_speed(x, DVec2::Y, 1000.0, 0.01), expected));
    // Sharper turns are slower.
    let shallow = junction_speed(x, DVec2::new(1.0, 0.2).normalize(), 1000.0, 0.01);
    let sharp = junction_speed(x, DVec2::new(-1.0, 0.2).normalize(), 1000.0, 0.01);
    assert!(shallow > expected && expected > sharp && sharp > 0.0);
}

#[test]
fn per_move_times_sum_to_the_job_time_and_skip_empty_moves() {
    let m = machine();
    let moves = [
        feed(10.0, 0.0, 3000.0),
        feed(10.0, 0.0, 3000.0),
        feed(10.0, 10.0, 600.0),
    ];
    let times = move_times(DVec2::ZERO, &moves, &Kinematics::of(&m));
    assert_eq!(times[1], 0.0);
    let total: f64 = times.iter().sum();
    assert!(close(total, job_time(DVec2::ZERO, &moves, &m)));
}

#[test]
fn without_acceleration_the_feed_is_constant() {
    let mut m = machine();
    m.acceleration_mm_s2 = 0.0;
    let t = job_time(DVec2::ZERO, &[feed(100.0, 0.0, 3000.0)], &m);
    assert!(close(t, 2.0));
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    /// Any path takes at least its constant-feed time (acceleration only slows it) and no more
    /// than stopping at every move would take.
    #[test]
    fn time_lies_between_constant_feed_and_full_stops(
        points in prop::collection::vec((0.0..300.0f64, 0.0..300.0f64, 60.0..9000.0f64), 1..30)
    ) {
        let m = machine();
        let kin = Kinematics::of(&m);
        let moves: Vec<Move> = points.iter().map(|&(x, y, f)| feed(x, y, f)).collect();
        let t = job_time(DVec2::ZERO, &moves, &m);
        let mut at = DVec2::ZERO;
        let (mut floor, mut ceiling) = (0.0, 0.0);
        for mv in &moves {
            // GRBL limits each axis: a diagonal may run faster than the maximum feed.
            let most = 6000.0 * kin.axis_scale((mv.to - at).normalize_or_zero());
            floor += at.distance(mv.to) / (mv.feed_mm_min.min(most) / 60.0);
            ceiling += job_time(at, std::slice::from_ref(mv), &m);
            at = mv.to;
        }
        prop_assert!(t.is_finite());
        prop_assert!(t >= floor * (1.0 - 1e-12), "{} < {}", t, floor);
        prop_assert!(t <= ceiling * (1.0 + 1e-12) + 1e-12, "{} > {}", t, ceiling);
    }
}

#[test]
fn grbl_limits_each_axis_so_diagonals_run_faster() {
    // GRBL (planner.c, limit_value_by_axis_maximum): along (1, 1)/√2 each axis carries 1/√2
    // of the motion, so the path may accelerate at √2·a and run at √2 times the maximum
    // feed. 42.43 mm at F9000 on a 6000 mm/min, 1000 mm/s² machine: v = 141.4 mm/s,
    // a = 1414 mm/s², t = L/v + v/a = 0.3 + 0.1 s. LinuxCNC limits the path: v = 100 mm/s,
    // a = 1000 mm/s², t = 0.4243 + 0.1 s.
    let grbl = machine();
    let diagonal = [feed(30.0, 30.0, 9000.0)];
    assert!(close(job_time(DVec2::ZERO, &diagonal, &grbl), 0.4));
    let along_x = [feed(30.0, 0.0, 9000.0)];
    assert!(close(job_time(DVec2::ZERO, &along_x, &grbl), 0.4));
    let lcnc = MachineProfile {
        dialect: Dialect::LinuxCnc,
        ..machine()
    };
    let t = job_time(DVec2::ZERO, &diagonal, &lcnc);
    assert!(close(t, 1800f64.sqrt() / 100.0 + 0.1), "{t}");
}

/// LinuxCNC (`linuxcnc-fiber`: 3000 mm/s², `G64 P0.01`): a corner beside a move that switches
/// a synchronised output runs no faster than LinuxCNC's blend arc taking half of that move,
/// √(√3/2 · a · tan θ' · L/2) with θ' half the angle between the reversed incoming and the
/// outgoing move; the same corner without the switch keeps the junction-deviation speed.
#[test]
fn linuxcnc_caps_a_corner_beside_a_switch_by_a_blend_arc_on_half_of_it() {
    let m = foldcam::machine::load_machine("linuxcnc-fiber").unwrap();
    let kin = Kinematics::of(&m);
    let turn = 10f64.to_radians();
    let out = DVec2::new(turn.cos(), turn.sin());
    // 20 mm, a 0.2 mm move that switches, then 20 mm turned by 10°, at 10 m/min.
    let moves = |sync: bool| {
        let b = DVec2::new(20.2, 0.0);
        [
            Move {
                to: DVec2::new(20.0, 0.0),
                feed_mm_min: 10_000.0,
                rapid: false,
                sync: false,
            },
            Move {
                to: b,
                feed_mm_min: 10_000.0,
                rapid: false,
                sync,
            },
            Move {
                to: b + out * 20.0,
                feed_mm_min: 10_000.0,
                rapid: false,
                sync: false,
            },
        ]
    };
    let total = |sync| -> f64 { move_times(DVec2::ZERO, &moves(sync), &kin).iter().sum() };
    let a = 3000.0;
    let half = (90.0f64 - 5.0).to_radians();
    let cap = (0.75f64.sqrt() * a * half.tan() * 0.1).sqrt();
    // The junction-deviation speed of that corner (LinuxCNC's blend arc within `G64 P0.01`)
    // is higher (about 82.6 mm/s).
    let free = junction_speed(
        DVec2::X,
        out,
        a * foldcam::machine::BLEND_ACC_RATIO_NORMAL,
        0.01,
    );
    assert!(cap < 0.7 * free, "{cap} {free}");
    // Entering the short move no faster than it can slow down to the cap.
    let entry = (cap * cap + 2.0 * a * 0.2).sqrt();
    let v = 10_000.0 / 60.0;
    let expected = foldcam::machine::trapezoid_time(20.0, 0.0, entry, v, a)
        + foldcam::machine::trapezoid_time(0.2, entry, cap, v, a)
        + foldcam::machine::trapezoid_time(20.0, cap, 0.0, v, a);
    assert!(
        (total(true) - expected).abs() < 1e-9,
        "{} {expected}",
        total(true)
    );
    assert!(total(false) < total(true) - 1e-3);
}
