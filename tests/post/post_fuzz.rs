//! Any plan, however broken, gives every writer a clean file or an error: no panic, and no
//! NaN, infinity, exponent or negative zero in the output.

use crate::post_common;

use foldcam::fab::{FabPlan, Operation};
use foldcam::machine::{Dialect, MachineProfile};
use foldcam::post::{DxfVersion, dxf, gcode, svg};
use glam::DVec2;
use post_common::{machine, plan, plotter, toolpath};
use proptest::prelude::*;
use proptest::test_runner::{RngSeed, TestRunner};

/// Mostly ordinary millimetres, sometimes NaN, infinities, huge or tiny values.
fn coordinate() -> impl Strategy<Value = f64> {
    prop_oneof![
        8 => -50.0f64..350.0,
        1 => prop_oneof![
            Just(f64::NAN),
            Just(f64::INFINITY),
            Just(-1e12),
            Just(1e-12),
            Just(-0.0),
            Just(5e8)
        ],
    ]
}

fn stroke() -> impl Strategy<Value = Vec<DVec2>> {
    prop::collection::vec((coordinate(), coordinate()), 0..6)
        .prop_map(|ps| ps.into_iter().map(|(x, y)| DVec2::new(x, y)).collect())
}

fn any_plan() -> impl Strategy<Value = FabPlan> {
    let path = (
        0..Operation::ALL.len(),
        prop::collection::vec(stroke(), 0..4),
    );
    let paths = prop::collection::vec(path, 0..5);
    let numbers = (
        prop_oneof![Just(f64::NAN), -1.0f64..2.0],
        prop_oneof![Just(0.0), 1.0f64..20000.0],
        0u32..3,
    );
    (paths, numbers).prop_map(|(paths, (power, speed, passes))| {
        let mut p = plan(post_common::job());
        p.jobs[0].paths = paths
            .into_iter()
            .map(|(op, strokes)| toolpath(Operation::ALL[op], strokes))
            .collect();
        p.settings.cut.power = power;
        p.settings.score.speed_mm_min = speed;
        p.settings.perforate.passes = passes;
        p
    })
}

fn machines() -> Vec<MachineProfile> {
    let mut coarse = machine(Dialect::Grbl);
    coarse.resolution_mm = 0.025;
    vec![
        coarse,
        machine(Dialect::Marlin),
        machine(Dialect::LinuxCnc),
        plotter(Dialect::Plotter),
    ]
}

fn clean(text: &str) {
    for bad in ["NaN", "inf", "-0 ", "-0\n", "-0\""] {
        assert!(!text.contains(bad), "{bad:?} in output:\n{text}");
    }
    // The perforation colour #00E000 is the one digit-E-digit that is not a number.
    let chars: Vec<char> = text.replace("#00E000", "").chars().collect();
    for w in chars.windows(3) {
        let exponent = w[0].is_ascii_digit()
            && matches!(w[1], 'e' | 'E')
            && (w[2].is_ascii_digit() || matches!(w[2], '-' | '+'));
        assert!(!exponent, "exponent {w:?} in output:\n{text}");
    }
}

/// Outcomes of every writer over the sampled plans: (clean files, errors).
#[derive(Default)]
struct Outcomes {
    files: usize,
    errors: usize,
}

impl Outcomes {
    fn count<T, E>(&mut self, result: Result<T, E>) -> Option<T> {
        match result {
            Ok(v) => {
                self.files += 1;
                Some(v)
            }
            Err(_) => {
                self.errors += 1;
                None
            }
        }
    }
}

#[test]
fn any_plan_gives_a_clean_file_or_an_error() {
    let config = ProptestConfig {
        cases: 256,
        rng_seed: RngSeed::Fixed(0x0f01_dca3),
        ..ProptestConfig::default()
    };
    let outcomes = std::cell::RefCell::new(Outcomes::default());
    let mut runner = TestRunner::new(config);
    runner
        .run(&any_plan(), |plan| {
            let mut o = outcomes.borrow_mut();
            let job = &plan.jobs[0];
            for m in machines() {
                if let Some(text) = o.count(gcode(&plan, job, &m)) {
                    clean(&text);
                }
            }
            for version in [DxfVersion::R2000, DxfVersion::R12] {
                if let Some(bytes) = o.count(dxf(&plan, job, version)) {
                    clean(&String::from_utf8(bytes).unwrap());
                }
            }
            let bed = machine(Dialect::Grbl).bed;
            for dasharray in [false, true] {
                if let Some(text) = o.count(svg(&plan, job, &bed, dasharray)) {
                    clean(&text);
                }
            }
            Ok(())
        })
        .unwrap();
    // The sample reaches both outcomes often enough that each side of the contract is tested.
    let o = outcomes.into_inner();
    let all = (o.files + o.errors) as f64;
    assert!(o.files as f64 >= 0.1 * all, "{} files of {all}", o.files);
    assert!(o.errors as f64 >= 0.1 * all, "{} errors of {all}", o.errors);
}
