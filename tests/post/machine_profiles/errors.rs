//! Bad profiles: every kind of bad input is refused with an error naming the file, the dotted
//! key and the value found.

use foldcam::machine::{ProfileError, parse_machine, parse_material};

use super::{SOURCE, read};

/// The grbl-diode file with `from` replaced by `to` (which must occur).
fn machine_edit(from: &str, to: &str) -> String {
    let text = read("machines/grbl-diode.toml");
    assert!(
        text.contains(from),
        "test edit: {from:?} not in grbl-diode.toml"
    );
    text.replacen(from, to, 1)
}

fn material_edit(from: &str, to: &str) -> String {
    let text = read("machines/materials/stainless-0.5.toml");
    assert!(
        text.contains(from),
        "test edit: {from:?} not in stainless-0.5.toml"
    );
    text.replacen(from, to, 1)
}

/// Asserts `result` failed on `key`, naming the test source and every word of `mentions`.
fn assert_error<T: std::fmt::Debug>(result: Result<T, ProfileError>, key: &str, mentions: &[&str]) {
    let e = result.expect_err("the profile should be refused");
    assert_eq!(e.source_name, SOURCE, "{e}");
    assert_eq!(e.key, key, "{e}");
    let shown = e.to_string();
    assert!(shown.starts_with(&format!("{SOURCE}: {key}: ")), "{shown}");
    for word in mentions {
        assert!(e.message.contains(word), "{shown} should mention {word}");
    }
}

#[test]
fn unknown_keys_are_refused_by_name() {
    let text = machine_edit(
        "max_feed_mm_min = 6000",
        "max_feed_mm_min = 6000\nmax_feed_mm_mim = 7000",
    );
    assert_error(
        parse_machine(&text, SOURCE),
        "max_feed_mm_mim",
        &["unknown", "7000"],
    );
    let text = machine_edit("width_mm = 400", "width_mm = 400\nwidht_mm = 300");
    assert_error(
        parse_machine(&text, SOURCE),
        "bed.widht_mm",
        &["unknown", "width_mm"],
    );
    let text = material_edit("passes = 1", "passes = 1\npasses_ = 2");
    assert_error(
        parse_material(&text, SOURCE),
        "settings.cut.passes_",
        &["unknown"],
    );
    let text = material_edit("[limits]", "[limts]\nx = 1\n[limits]");
    assert_error(parse_material(&text, SOURCE), "limts", &["unknown"]);
}

#[test]
fn wrong_types_are_refused_with_the_value() {
    let text = machine_edit("max_feed_mm_min = 6000", "max_feed_mm_min = \"fast\"");
    assert_error(
        parse_machine(&text, SOURCE),
        "max_feed_mm_min",
        &["number", "\"fast\""],
    );
    let text = machine_edit("y_flipped = false", "y_flipped = \"no\"");
    assert_error(
        parse_machine(&text, SOURCE),
        "bed.y_flipped",
        &["true or false", "\"no\""],
    );
    let text = machine_edit("preamble = [\"G94\"", "preamble = [21");
    assert_error(
        parse_machine(&text, SOURCE),
        "preamble[0]",
        &["string", "21"],
    );
    let text = material_edit("passes = 1", "passes = 1.5");
    assert_error(
        parse_material(&text, SOURCE),
        "settings.cut.passes",
        &["whole number", "1.5"],
    );
    let text = format!("power = 3\n{}", machine_edit("[power]", "[power_]"));
    assert_error(parse_machine(&text, SOURCE), "power", &["table", "3"]);
}

#[test]
fn numbers_out_of_range_are_refused_with_the_value() {
    let cases = [
        (
            "max_feed_mm_min = 6000",
            "max_feed_mm_min = -6000",
            "max_feed_mm_min",
            "-6000",
        ),
        (
            "travel_feed_mm_min = 6000",
            "travel_feed_mm_min = 9000",
            "travel_feed_mm_min",
            "9000",
        ),
        (
            "acceleration_mm_s2 = 1000",
            "acceleration_mm_s2 = 0",
            "acceleration_mm_s2",
            "0",
        ),
        (
            "resolution_mm = 0.01",
            "resolution_mm = 0.5",
            "resolution_mm",
            "0.5",
        ),
        (
            "resolution_mm = 0.01",
            "resolution_mm = 1e-6",
            "resolution_mm",
            "0.000001",
        ),
        ("width_mm = 400", "width_mm = 0", "bed.width_mm", "0"),
        ("min = 0", "min = -1", "power.min", "-1"),
    ];
    for (from, to, key, value) in cases {
        assert_error(
            parse_machine(&machine_edit(from, to), SOURCE),
            key,
            &[value],
        );
    }
    let text = material_edit("power = 0.3", "power = 30");
    assert_error(
        parse_material(&text, SOURCE),
        "settings.score.power",
        &["30"],
    );
    let text = material_edit("min_dash_mm = 0.5", "min_dash_mm = 4.0");
    assert_error(
        parse_material(&text, SOURCE),
        "perforation.min_dash_mm",
        &["4.0", "cut_mm"],
    );
    let text = material_edit("max_fold_angle_deg = 165", "max_fold_angle_deg = 200");
    assert_error(
        parse_material(&text, SOURCE),
        "limits.max_fold_angle_deg",
        &["200"],
    );
}

#[test]
fn power_min_must_be_below_max() {
    let text = machine_edit("max = 1000", "max = 0");
    assert_error(parse_machine(&text, SOURCE), "power.max", &["0"]);
    let text = machine_edit("min = 0", "min = 1000");
    assert_error(parse_machine(&text, SOURCE), "power.max", &["1000"]);
}

#[test]
fn nan_and_infinity_are_refused() {
    for bad in ["nan", "inf", "-inf", "+nan"] {
        let text = machine_edit(
            "acceleration_mm_s2 = 1000",
            &format!("acceleration_mm_s2 = {bad}"),
        );
        assert_error(
            parse_machine(&text, SOURCE),
            "acceleration_mm_s2",
            &[bad.trim_start_matches('+')],
        );
        let text = material_edit("kerf_mm = 0.08", &format!("kerf_mm = {bad}"));
        assert_error(parse_material(&text, SOURCE), "kerf_mm", &[]);
    }
}

#[test]
fn missing_keys_are_named() {
    let text = machine_edit("acceleration_mm_s2 = 1000", "");
    assert_error(
        parse_machine(&text, SOURCE),
        "acceleration_mm_s2",
        &["missing"],
    );
    let text = machine_edit("laser_mode = \"dynamic\"", "");
    assert_error(
        parse_machine(&text, SOURCE),
        "laser_mode",
        &["missing", "dynamic"],
    );
    let text = material_edit("bridge_mm = 1.0", "");
    assert_error(
        parse_material(&text, SOURCE),
        "perforation.bridge_mm",
        &["missing"],
    );
    let text = read("machines/materials/stainless-0.5.toml");
    let without_plot = text.replacen("[settings.plot]", "[settings.plot_]", 1);
    assert_error(
        parse_material(&without_plot, SOURCE),
        "settings.plot",
        &["missing"],
    );
}

#[test]
fn a_misspelt_required_key_is_pointed_out() {
    let text = material_edit("vertex_clearance_mm = 1.5", "vertex_clearence_mm = 1.5");
    let key = "perforation.vertex_clearance_mm";
    assert_error(
        parse_material(&text, SOURCE),
        key,
        &["missing", "`vertex_clearence_mm`"],
    );
    let text = machine_edit("dialect = ", "dialekt = ");
    assert_error(
        parse_machine(&text, SOURCE),
        "dialect",
        &["missing", "`dialekt`"],
    );
}

#[test]
fn unknown_choices_are_refused_with_the_choices() {
    let text = machine_edit("dialect = \"grbl\"", "dialect = \"grbl2\"");
    assert_error(
        parse_machine(&text, SOURCE),
        "dialect",
        &["\"grbl2\"", "\"marlin\"", "\"file-only\""],
    );
    let text = machine_edit("origin = \"bottom-left\"", "origin = \"middle\"");
    assert_error(
        parse_machine(&text, SOURCE),
        "bed.origin",
        &["\"middle\"", "\"top-right\""],
    );
    let text = material_edit("mountain = \"perforate\"", "mountain = \"fold\"");
    assert_error(
        parse_material(&text, SOURCE),
        "operations.mountain",
        &["\"fold\"", "\"skip\""],
    );
}

#[test]
fn a_file_that_is_not_toml_is_refused_with_its_line() {
    let text = "kind = \"laser\"\nthis is not toml\n";
    assert_error(parse_machine(text, SOURCE), "file", &["TOML", "line 2"]);
    assert_error(parse_material("{}{}", SOURCE), "file", &["TOML"]);
    assert_error(parse_material("", SOURCE), "description", &["missing"]);
}

#[test]
fn inconsistent_settings_are_refused() {
    let text = machine_edit("dwell_unit = \"seconds\"", "dwell_unit = \"milliseconds\"");
    assert_error(
        parse_machine(&text, SOURCE),
        "dwell_unit",
        &["milliseconds", "seconds"],
    );
    let text = machine_edit("dialect = \"grbl\"", "dialect = \"plotter\"");
    assert_error(parse_machine(&text, SOURCE), "dialect", &["\"plotter\""]);
    let plotter = read("machines/grbl-pen-plotter.toml");
    let no_pen = plotter.replacen("[pen]", "[pen_]", 1);
    assert_error(parse_machine(&no_pen, SOURCE), "pen", &["missing"]);
    let no_down = plotter.replacen("down = [\"M3 S1000\"]", "down = []", 1);
    assert_error(parse_machine(&no_down, SOURCE), "pen.down", &["empty"]);
    let two_lines = plotter.replacen("down = [\"M3 S1000\"]", "down = [\"M3\\nG0 X0\"]", 1);
    assert_error(
        parse_machine(&two_lines, SOURCE),
        "pen.down[0]",
        &["control"],
    );
    let two_lines = material_edit("description = \"", "description = \"two\\nlines ");
    assert_error(
        parse_material(&two_lines, SOURCE),
        "description",
        &["control", "two"],
    );
    let text = material_edit("valley = \"perforate\"", "valley = \"cut\"");
    assert_error(
        parse_material(&text, SOURCE),
        "operations.valley",
        &["\"cut\""],
    );
}

#[test]
fn unknown_tables_and_arrays_of_tables_are_refused() {
    let text = format!(
        "{}\n[[passes]]\nspeed = 1\n",
        read("machines/grbl-diode.toml")
    );
    assert_error(
        parse_machine(&text, SOURCE),
        "passes",
        &["unknown", "speed = 1"],
    );
    let text = format!("{}\n[bed.extra]\nx = 1\n", read("machines/grbl-diode.toml"));
    assert_error(
        parse_machine(&text, SOURCE),
        "bed.extra",
        &["unknown", "a table"],
    );
}

/// The 1-based line of `text` that starts with `start`.
fn line_starting(text: &str, start: &str) -> usize {
    let found = text.lines().position(|l| l.starts_with(start));
    found.map_or(0, |i| i + 1)
}

#[test]
fn errors_give_the_line_of_the_key() {
    let text = machine_edit("max_feed_mm_min = 6000", "max_feed_mm_min = -1");
    let line = line_starting(&text, "max_feed_mm_min = -1");
    let message = format!("(line {line})");
    assert_error(
        parse_machine(&text, SOURCE),
        "max_feed_mm_min",
        &["-1", &message],
    );
    let text = material_edit(
        "vertex_clearance_mm = 1.5",
        "vertex_clearance_mm = 1.5\nvertex_clearence_mm = 2",
    );
    let line = line_starting(&text, "vertex_clearence_mm");
    let message = format!("(line {line})");
    let key = "perforation.vertex_clearence_mm";
    assert_error(parse_material(&text, SOURCE), key, &["unknown", &message]);
}
