//! Plans, jobs and machines built as literals for the post-processor tests.
#![allow(dead_code)]

use foldcam::fab::{ContourRole, FabPlan, Operation, PlanStats, Setup, Side, Toolpath};
use foldcam::machine::{
    Bed, Corner, Dialect, MachineKind, MachineProfile, OperationSettings, SettingsByOperation,
};
use glam::{DAffine2, DVec2, dvec2};

/// A toolpath of `op` with `strokes`.
pub fn toolpath(op: Operation, strokes: Vec<Vec<DVec2>>) -> Toolpath {
    Toolpath {
        op,
        strokes,
        role: ContourRole::None,
        container: None,
        edges: Vec::new(),
    }
}

/// Three dashes along y = 30 from x = 10 to x = 50.
pub fn dashes() -> Vec<Vec<DVec2>> {
    (0..3)
        .map(|i| {
            let x = 10.0 + 15.0 * i as f64;
            vec![dvec2(x, 30.0), dvec2(x + 10.0, 30.0)]
        })
        .collect()
}

/// A job with a mark, a score polyline, a perforation of three dashes and a closed cut
/// (with float noise), plus a stroke that rounds to nothing.
pub fn job() -> Setup {
    let square = vec![
        dvec2(5.0, 5.0),
        dvec2(56.74400000000002, 5.0),
        dvec2(56.74400000000002, 40.1 + 0.2),
        dvec2(5.0, 40.300000000000004),
        dvec2(5.0, 5.0),
    ];
    Setup {
        name: "front".into(),
        side: Side::Front,
        to_machine: DAffine2::IDENTITY,
        paths: vec![
            toolpath(
                Operation::Mark,
                vec![vec![dvec2(1.0, 1.0), dvec2(3.0, 1.0)]],
            ),
            toolpath(
                Operation::Score,
                vec![vec![
                    dvec2(10.0, 10.0),
                    dvec2(20.0, 15.0),
                    dvec2(30.0, 10.0),
                ]],
            ),
            toolpath(Operation::Perforate, dashes()),
            toolpath(
                Operation::Cut,
                vec![square, vec![dvec2(7.0, 7.0), dvec2(7.0000001, 7.0)]],
            ),
        ],
    }
}

/// Settings with distinct powers, speeds and a two-pass cut.
pub fn settings() -> SettingsByOperation {
    let s = |speed_mm_min, power, passes| OperationSettings {
        speed_mm_min,
        power,
        passes,
    };
    SettingsByOperation {
        cut: s(300.0, 0.8, 2),
        perforate: s(600.0, 0.9, 1),
        score: s(9000.0, 0.25, 1),
        mark: s(3000.0, 0.1, 1),
        plot: s(2000.0, 0.0, 1),
    }
}

/// A plan of one job.
pub fn plan(job: Setup) -> FabPlan {
    FabPlan {
        jobs: vec![job],
        settings: settings(),
        about: Default::default(),
        stats: PlanStats::default(),
        warnings: Vec::new(),
        // Nothing beyond the job's own toolpaths is expected.
        mapping: foldcam::machine::OperationMapping {
            mountain: None,
            valley: None,
            unassigned: None,
            flat: None,
            boundary: None,
        },
        overrides: Vec::new(),
    }
}

/// A 300 × 200 mm laser in `dialect`, S from 0 to 1000, 0.001 mm resolution.
pub fn machine(dialect: Dialect) -> MachineProfile {
    MachineProfile {
        name: format!("test-{dialect:?}").to_lowercase(),
        preamble: vec!["G0 X0 Y0 ; preamble".into()],
        postamble: vec!["G0 X0 Y0 ; postamble".into()],
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

/// A pen plotter in `dialect` (`Plotter` or `Marlin`): servo pen, 0.15 s delay.
pub fn plotter(dialect: Dialect) -> MachineProfile {
    MachineProfile {
        kind: MachineKind::Plotter,
        pen_up: vec!["M280 P0 S90".into()],
        pen_down: vec!["M280 P0 S10".into()],
        pen_delay_s: 0.15,
        ..machine(dialect)
    }
}

/// Held by the tests that run the controllers' or other tools' own programs (LinuxCNC, GRBL's
/// planner, rs274, ezdxf), so that they run one at a time: LinuxCNC's simulation in user space
/// stalls now and then when other work takes the CPU from its servo thread.
pub fn external_tools_alone() -> std::sync::MutexGuard<'static, ()> {
    static LOCK: std::sync::Mutex<()> = std::sync::Mutex::new(());
    LOCK.lock().unwrap_or_else(|e| e.into_inner())
}
