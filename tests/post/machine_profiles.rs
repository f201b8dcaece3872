//! Machine and material profiles: every shipped profile loads, every kind of bad input is
//! refused with an error naming the file, the key and the value, and the loaded values agree
//! with the machine facts foldcam relies on.

use std::path::PathBuf;

use foldcam::check::CheckOptions;
use foldcam::fab::Operation;
use foldcam::machine::{
    Bed, Corner, Dialect, DwellUnit, LaserMode, MachineKind, load_machine, load_material,
    parse_machine, parse_material, shipped_machines, shipped_materials,
};
use foldcam::pattern::Assignment;
use glam::DVec2;
use proptest::prelude::*;

#[path = "machine_profiles/errors.rs"]
mod errors;

/// The source name the error tests parse under.
const SOURCE: &str = "profiles/test-profile.toml";

fn repo_file(rel: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(rel)
}

fn read(rel: &str) -> String {
    std::fs::read_to_string(repo_file(rel)).unwrap_or_else(|e| panic!("{rel}: {e}"))
}

#[test]
fn every_shipped_machine_loads_by_name_and_by_path() {
    assert!(shipped_machines().len() >= 5);
    for name in shipped_machines() {
        let by_name = load_machine(name).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(by_name.name, name);
        assert!(!by_name.description.is_empty());
        let path = repo_file(&format!("machines/{name}.toml"));
        let by_path =
            load_machine(path.to_str().unwrap_or_default()).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(by_path, by_name);
    }
}

#[test]
fn every_shipped_material_loads_by_name_and_by_path() {
    assert!(shipped_materials().len() >= 5);
    for name in shipped_materials() {
        let by_name = load_material(name).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(by_name.name, name);
        let path = repo_file(&format!("machines/materials/{name}.toml"));
        let by_path =
            load_material(path.to_str().unwrap_or_default()).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(by_path, by_name);
    }
}

/// Every `.toml` in a folder is shipped (a new file must be added to the embedded list).
fn assert_folder_shipped(folder: &str, shipped: Vec<&str>) {
    let mut on_disk: Vec<String> = std::fs::read_dir(repo_file(folder))
        .into_iter()
        .flatten()
        .flatten()
        .filter_map(|e| {
            e.file_name()
                .to_str()?
                .strip_suffix(".toml")
                .map(str::to_string)
        })
        .collect();
    on_disk.sort();
    assert_eq!(on_disk, shipped);
}

#[test]
fn the_shipped_lists_match_the_folders() {
    assert_folder_shipped("machines", shipped_machines());
    assert_folder_shipped("machines/materials", shipped_materials());
    for name in [
        "grbl-diode",
        "marlin-laser",
        "linuxcnc-fiber",
        "grbl-pen-plotter",
        "lightburn",
    ] {
        assert!(shipped_machines().contains(&name), "{name}");
    }
    for name in [
        "stainless-0.5",
        "stainless-0.3",
        "card-300gsm",
        "paper-160gsm",
        "polypropylene-0.5",
    ] {
        assert!(shipped_materials().contains(&name), "{name}");
    }
}

#[test]
fn an_unknown_name_lists_the_shipped_ones() {
    let e = load_machine("grbl-diod").expect_err("no such machine");
    assert_eq!(e.source_name, "grbl-diod");
    assert_eq!(e.key, "name");
    for name in shipped_machines() {
        assert!(e.message.contains(name), "{e}");
    }
    let e = load_material("steel").expect_err("no such material");
    assert!(e.message.contains("stainless-0.5"), "{e}");
}

#[test]
fn a_file_on_disk_is_named_by_its_stem() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let path = dir.path().join("my-laser.toml");
    std::fs::write(&path, read("machines/grbl-diode.toml")).unwrap_or_else(|e| panic!("{e}"));
    let machine = load_machine(path.to_str().unwrap_or_default()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(machine.name, "my-laser");
    let material = parse_material(
        &read("machines/materials/stainless-0.3.toml"),
        "x/steel-0.3.toml",
    );
    assert_eq!(material.map(|m| m.name).ok().as_deref(), Some("steel-0.3"));
}

#[test]
fn a_missing_file_names_the_path() {
    let e = load_machine("no/such/machine.toml").expect_err("missing file");
    assert_eq!(e.source_name, "no/such/machine.toml");
    assert_eq!(e.key, "file");
    let e = load_material("nothing-here.toml").expect_err("missing file");
    assert_eq!(e.key, "file");
}

#[test]
fn dwell_units_follow_the_firmware() {
    for name in shipped_machines() {
        let m = load_machine(name).unwrap_or_else(|e| panic!("{e}"));
        let expected = match m.dialect {
            Dialect::Marlin => DwellUnit::Milliseconds,
            _ => DwellUnit::Seconds,
        };
        assert_eq!(m.dwell_unit, expected, "{name}");
    }
    let marlin = load_machine("marlin-laser").unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(marlin.dwell_unit, DwellUnit::Milliseconds);
    assert_eq!(marlin.dwell_p(0.25), 250.0);
    let grbl = load_machine("grbl-diode").unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(grbl.dwell_p(0.25), 0.25);
}

#[test]
fn laser_power_ranges_follow_the_firmware() {
    let grbl = load_machine("grbl-diode").unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        (grbl.kind, grbl.dialect),
        (MachineKind::Laser, Dialect::Grbl)
    );
    assert_eq!((grbl.power.min, grbl.power.max), (0.0, 1000.0));
    assert_eq!(grbl.laser_mode, LaserMode::Dynamic);
    assert_eq!(grbl.laser_mode.command(), "M4");
    assert_eq!(grbl.power_to_s(0.0), 0.0);
    assert_eq!(grbl.power_to_s(0.5), 500.0);
    assert_eq!(grbl.power_to_s(1.0), 1000.0);
    assert_eq!(grbl.power_to_s(1.5), 1000.0);
    assert_eq!(grbl.power_to_s(f64::NAN), 0.0);
    let marlin = load_machine("marlin-laser").unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(marlin.power.max, 255.0);
    assert_eq!(marlin.power_to_s(1.0), 255.0);
    let fiber = load_machine("linuxcnc-fiber").unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        (fiber.dialect, fiber.kind),
        (Dialect::LinuxCnc, MachineKind::Laser)
    );
}

#[test]
fn every_shipped_machine_is_sensible() {
    for name in shipped_machines() {
        let m = load_machine(name).unwrap_or_else(|e| panic!("{e}"));
        assert!(m.travel_feed_mm_min <= m.max_feed_mm_min, "{name}");
        assert!(m.power.min < m.power.max, "{name}");
        assert!((1e-5..=0.1).contains(&m.resolution_mm), "{name}");
        assert!(m.decimals() <= 5, "{name}");
        let is_plotter = m.kind == MachineKind::Plotter;
        assert_eq!(is_plotter, !m.pen_up.is_empty(), "{name}: pen commands");
        assert_eq!(m.supports(Operation::Plot), is_plotter, "{name}");
        assert_eq!(m.emits_gcode(), m.dialect != Dialect::FileOnly, "{name}");
    }
    let plotter = load_machine("grbl-pen-plotter").unwrap_or_else(|e| panic!("{e}"));
    assert!(plotter.pen_delay_s > 0.0);
    assert!(!load_machine("lightburn").is_ok_and(|m| m.emits_gcode()));
}

#[test]
fn coordinates_round_to_the_resolution() {
    let fiber = load_machine("linuxcnc-fiber").unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(fiber.decimals(), 3);
    assert!((fiber.round_mm(1.23456) - 1.235).abs() < 1e-12);
    let grbl = load_machine("grbl-diode").unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(grbl.decimals(), 2);
}

#[test]
fn the_bed_holds_its_corners_for_every_origin() {
    for origin in Corner::ALL {
        for y_flipped in [false, true] {
            let bed = Bed {
                width_mm: 300.0,
                height_mm: 200.0,
                origin,
                y_flipped,
            };
            let to_machine = bed.to_machine();
            for corner in [
                (0.0, 0.0),
                (300.0, 0.0),
                (0.0, 200.0),
                (300.0, 200.0),
                (150.0, 100.0),
            ] {
                let p = to_machine.transform_point2(DVec2::from(corner));
                assert!(bed.contains(p), "{origin:?} {y_flipped}: {corner:?} → {p}");
            }
            let machine_origin = to_machine.inverse().transform_point2(DVec2::ZERO);
            let expect_x = if origin.is_right() { 300.0 } else { 0.0 };
            let expect_y = if origin.is_top() { 200.0 } else { 0.0 };
            assert_eq!(machine_origin, DVec2::new(expect_x, expect_y), "{origin:?}");
            assert!(!bed.contains(to_machine.transform_point2(DVec2::new(301.0, 100.0))));
            assert!(!bed.contains(to_machine.transform_point2(DVec2::new(150.0, -1.0))));
        }
    }
}

#[test]
fn a_plotter_cannot_cut_and_a_laser_cannot_plot() {
    let card = load_material("card-300gsm").unwrap_or_else(|e| panic!("{e}"));
    let plotter = load_machine("grbl-pen-plotter").unwrap_or_else(|e| panic!("{e}"));
    let laser = load_machine("grbl-diode").unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        card.unsupported_by(&plotter),
        [Operation::Score, Operation::Cut]
    );
    assert!(card.unsupported_by(&laser).is_empty());
}

#[test]
fn material_limits_become_check_options() {
    let steel = load_material("stainless-0.5").unwrap_or_else(|e| panic!("{e}"));
    let opts = steel.check_options();
    assert_eq!(opts.min_vertex_angle_deg, Some(30.0));
    assert_eq!(opts.max_fold_angle_deg, Some(165.0));
    assert_eq!(
        opts.flat_foldability,
        CheckOptions::default().flat_foldability
    );
    assert_eq!(
        steel.mapping.get(Assignment::Mountain),
        Some(Operation::Perforate)
    );
    assert_eq!(steel.mapping.get(Assignment::Cut), Some(Operation::Cut));
    assert_eq!(steel.mapping.get(Assignment::Flat), None);
}

#[test]
fn every_shipped_material_is_sensible() {
    for name in shipped_materials() {
        let m = load_material(name).unwrap_or_else(|e| panic!("{e}"));
        let p = m.perforation;
        assert!(
            p.min_dash_mm <= p.cut_mm && p.min_web_mm <= p.bridge_mm,
            "{name}"
        );
        assert!(m.kerf_mm < m.thickness_mm, "{name}: kerf {} mm", m.kerf_mm);
        assert_eq!(m.mapping.boundary, Some(Operation::Cut), "{name}");
        for a in [
            Assignment::Mountain,
            Assignment::Valley,
            Assignment::Unassigned,
            Assignment::Flat,
        ] {
            assert_ne!(m.mapping.get(a), Some(Operation::Cut), "{name}: {a:?}");
        }
        for op in Operation::ALL {
            let s = m.settings.get(op);
            assert!(s.speed_mm_min > 0.0 && (0.0..=1.0).contains(&s.power) && s.passes >= 1);
        }
        assert!(m.limits.max_fold_angle_deg <= 180.0, "{name}");
        assert!(m.used_operations().contains(&Operation::Cut), "{name}");
    }
}

/// A valid profile with one random edit: a deletion, an insertion or a replacement.
fn edited(text: &str, at: usize, len: usize, insert: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let at = at % (chars.len() + 1);
    let end = (at + len).min(chars.len());
    chars[..at]
        .iter()
        .chain(insert.chars().collect::<Vec<_>>().iter())
        .chain(&chars[end..])
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    #[test]
    fn random_edits_never_panic_the_loader(
        which in 0usize..10,
        at in 0usize..4000,
        len in 0usize..12,
        insert in prop_oneof![
            Just(String::new()),
            "[ -~]{0,8}",
            Just("nan".to_string()),
            Just("-1e400".to_string()),
            Just("\n[x]\n".to_string()),
            Just("\"".to_string()),
            "[0-9.eE+-]{1,6}",
        ],
    ) {
        let names = ["grbl-diode", "marlin-laser", "linuxcnc-fiber", "grbl-pen-plotter", "lightburn"];
        let result = if which < 5 {
            let text = read(&format!("machines/{}.toml", names[which]));
            parse_machine(&edited(&text, at, len, &insert), SOURCE).map(|_| ()).err()
        } else {
            let text = read(&format!("machines/materials/{}.toml", shipped_materials()[which - 5]));
            parse_material(&edited(&text, at, len, &insert), SOURCE).map(|_| ()).err()
        };
        if let Some(e) = result {
            prop_assert_eq!(&e.source_name, SOURCE);
            prop_assert!(!e.key.is_empty() && !e.message.is_empty());
        }
    }
}
