//! Structured fuzzing of the readers inside `cargo test` (the coverage-guided targets are in
//! `fuzz/`): inputs that are well formed on the surface — FOLD JSON with random arrays and
//! indices, SVG with random elements, attributes and transforms, `.cp` and `.opx` lines with
//! random types and numbers, voxel cards with random headers and rows, profiles with one value
//! replaced, G-code with random words — and odd underneath (NaN spelt out, 1e308, negative and
//! out-of-range indices, unknown letters). Each reader must either return a model that keeps
//! its invariants (indices in range, finite coordinates within the limit, fold angles within
//! ±180°) or an error that says where and what; a panic fails the test. Bounded: 64–192 cases
//! per reader with fixed seeds, a few seconds in a debug build.

use foldcam::design::popup::voxel::{format_voxel_card, parse_voxel_card};
use foldcam::formats::{Format, Imported, ParseError, parse};
use foldcam::machine::{MachineProfile, load_machine, parse_machine, parse_material};
use foldcam::pattern::{CreasePattern, MAX_COORDINATE};
use foldcam::sim::run;
use proptest::prelude::*;
use proptest::test_runner::RngSeed;
use serde_json::{Value, json};

// Checks ---------------------------------------------------------------------------------

/// The model invariants every reader promises, checked here without `validate` so that a
/// reader and `validate` sharing a mistake cannot hide it.
fn assert_model(cp: &CreasePattern) {
    let n = cp.vertices.len();
    for (i, p) in cp.vertices.iter().enumerate() {
        assert!(
            p.is_finite() && p.abs().max_element() <= MAX_COORDINATE,
            "vertex {i} at {p}"
        );
    }
    for (i, e) in cp.edges.iter().enumerate() {
        let [a, b] = e.vertices;
        assert!((a.0 as usize) < n && (b.0 as usize) < n, "edge {i}: {a:?}–{b:?} of {n}");
        assert_ne!(a, b, "edge {i} is a loop");
        if let Some(angle) = e.fold_angle {
            assert!(angle.is_finite() && angle.abs() <= 180.0, "edge {i} angle {angle}");
        }
    }
    for (i, f) in cp.faces.iter().flatten().enumerate() {
        for v in f.outer.iter().chain(f.holes.iter().flatten()) {
            assert!((v.0 as usize) < n, "face {i} names vertex {v:?} of {n}");
        }
    }
    assert!(cp.validate().is_ok(), "{:?}", cp.validate());
}

/// A pattern reader's result: a valid model that FOLD writes and reads back with the same
/// counts, or an error with a place and a message.
fn check_pattern(result: Result<Imported, ParseError>) -> Result<(), TestCaseError> {
    match result {
        Ok(imported) => {
            let cp = &imported.pattern;
            assert_model(cp);
            let text = foldcam::formats::fold::write_string(cp, imported.folded.as_ref());
            let back = foldcam::formats::fold::read_str(&text)
                .map_err(|e| TestCaseError::fail(format!("written FOLD reads back: {e}")))?;
            prop_assert_eq!(back.pattern.vertices.len(), cp.vertices.len());
            prop_assert_eq!(back.pattern.edges.len(), cp.edges.len());
        }
        Err(e) => {
            prop_assert!(!e.place.trim().is_empty(), "no place: {e:?}");
            prop_assert!(!e.message.trim().is_empty(), "no message: {e:?}");
        }
    }
    Ok(())
}

// Numbers --------------------------------------------------------------------------------

/// Mostly ordinary numbers, sometimes the extremes.
fn number() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => -200.0f64..200.0,
        1 => prop::sample::select(vec![0.0, -0.0, 1e-300, 1e9, -1e9, 1.0000001e9, 1e300, 1e308, -1e308]),
    ]
}

/// A number as text, sometimes a spelling no reader should take as a number.
fn number_text() -> impl Strategy<Value = String> {
    prop_oneof![
        8 => number().prop_map(|x| x.to_string()),
        1 => prop::sample::select(vec!["NaN", "nan", "inf", "-inf", "1e999", "", "1,5", "0x10", "1e", "--1", "١٢"])
            .prop_map(String::from),
    ]
}

// FOLD -----------------------------------------------------------------------------------

fn fold_json() -> impl Strategy<Value = String> {
    let coords = prop::collection::vec(prop::collection::vec(number(), 0..4), 0..8);
    let index = || -2i64..10;
    let edges = prop::collection::vec(prop::collection::vec(index(), 1..4), 0..12);
    let letters = prop::sample::select(vec!["B", "M", "V", "F", "U", "C", "J", "m", "Q", ""]);
    let assignments = prop::option::of(prop::collection::vec(letters, 0..12));
    let angle = prop_oneof![
        4 => (-200.0f64..200.0).prop_map(|a| json!(a)),
        1 => Just(Value::Null),
        1 => Just(json!("ninety")),
    ];
    let angles = prop::option::of(prop::collection::vec(angle, 0..12));
    let faces = prop::option::of(prop::collection::vec(
        prop::collection::vec(index(), 0..6),
        0..5,
    ));
    let unit = prop::option::of(prop::sample::select(vec![
        "mm", "unit", "in", "m", "nm", "furlong",
    ]));
    let frames = prop::option::of(prop::collection::vec(
        (prop::option::of(-1i64..4), any::<bool>()),
        0..3,
    ));
    (coords, edges, assignments, angles, faces, unit, frames).prop_map(
        |(coords, edges, assignments, angles, faces, unit, frames)| {
            let mut m = serde_json::Map::new();
            m.insert("vertices_coords".into(), json!(coords));
            m.insert("edges_vertices".into(), json!(edges));
            if let Some(a) = assignments {
                m.insert("edges_assignment".into(), json!(a));
            }
            if let Some(a) = angles {
                m.insert("edges_foldAngle".into(), json!(a));
            }
            if let Some(f) = faces {
                m.insert("faces_vertices".into(), json!(f));
            }
            if let Some(u) = unit {
                m.insert("frame_unit".into(), json!(u));
            }
            if let Some(frames) = frames {
                let list: Vec<Value> = frames
                    .into_iter()
                    .map(|(parent, inherit)| {
                        json!({"frame_parent": parent, "frame_inherit": inherit,
                               "frame_classes": ["creasePattern"]})
                    })
                    .collect();
                m.insert("file_frames".into(), Value::Array(list));
            }
            Value::Object(m).to_string()
        },
    )
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 192,
        rng_seed: RngSeed::Fixed(0xf01d),
        ..ProptestConfig::default()
    })]

    #[test]
    fn fold_with_random_arrays_and_indices(text in fold_json()) {
        check_pattern(parse(Format::Fold, &text))?;
    }
}

// SVG ------------------------------------------------------------------------------------

fn svg_colour() -> impl Strategy<Value = String> {
    prop::sample::select(vec![
        "#ff0000", "#0000ff", "#000000", "#00ff00", "#ffff00", "#ff00ff", "red", "blue",
        "none", "url(#g)", "#12", "rgb(300,0,0)",
    ])
    .prop_map(String::from)
}

fn svg_transform() -> impl Strategy<Value = String> {
    prop_oneof![
        3 => Just(String::new()),
        1 => (number_text(), number_text()).prop_map(|(a, b)| format!("translate({a} {b})")),
        1 => number_text().prop_map(|a| format!("scale({a})")),
        1 => number_text().prop_map(|a| format!("rotate({a})")),
        1 => number_text().prop_map(|a| format!("skewX({a})")),
        1 => Just("matrix(0 0 0 0 0 0)".to_string()),
        1 => Just("scale(1e300)".to_string()),
        1 => Just("translate(".to_string()),
    ]
}

fn svg_element() -> impl Strategy<Value = String> {
    let n = number_text;
    let shape = prop_oneof![
        (n(), n(), n(), n()).prop_map(|(a, b, c, d)| format!(
            r#"<line x1="{a}" y1="{b}" x2="{c}" y2="{d}""#
        )),
        prop::collection::vec(n(), 0..8)
            .prop_map(|p| format!(r#"<polyline points="{}""#, p.join(" "))),
        prop::collection::vec(n(), 0..8)
            .prop_map(|p| format!(r#"<polygon points="{}""#, p.join(","))),
        (n(), n(), n(), n())
            .prop_map(|(a, b, c, d)| format!(r#"<path d="M {a} {b} L {c} {d} Q {a} {d} {c} {b} Z""#)),
        (n(), n(), n(), n()).prop_map(|(a, b, c, d)| format!(
            r#"<rect x="{a}" y="{b}" width="{c}" height="{d}""#
        )),
        (n(), n(), n()).prop_map(|(a, b, c)| format!(r#"<circle cx="{a}" cy="{b}" r="{c}""#)),
        (n(), n(), n(), n()).prop_map(|(a, b, c, d)| format!(
            r#"<path d="M {a} {b} A {c} {d} 0 1 0 {b} {a}""#
        )),
    ];
    let extra = prop::sample::select(vec![
        "",
        r#" stroke-dasharray="5 2""#,
        r#" stroke-dasharray="0""#,
        r#" stroke-opacity="0.5""#,
        r#" stroke-opacity="NaN""#,
        r#" data-assignment="M""#,
        r#" data-assignment="Z""#,
        r#" class="valley""#,
        r#" stroke-width="-1""#,
        r#" display="none""#,
    ]);
    (shape, svg_colour(), svg_transform(), extra).prop_map(|(shape, colour, t, extra)| {
        format!(r#"{shape} stroke="{colour}" transform="{t}"{extra}/>"#)
    })
}

fn svg_document() -> impl Strategy<Value = String> {
    let size = prop::sample::select(vec![
        "100mm", "100", "10in", "-5mm", "0", "1e308mm", "abc", "50%", "",
    ]);
    let view_box = prop::sample::select(vec!["0 0 100 100", "0 0 0 0", "-50 -50 100 100", "1 2", ""]);
    let group = prop::collection::vec(svg_element(), 0..4);
    (size.clone(), size, view_box, prop::collection::vec((svg_transform(), group), 0..3))
        .prop_map(|(w, h, vb, groups)| {
            let body: String = groups
                .into_iter()
                .map(|(t, els)| format!(r#"<g transform="{t}">{}</g>"#, els.concat()))
                .collect();
            format!(
                r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="{vb}">{body}</svg>"#
            )
        })
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 128,
        rng_seed: RngSeed::Fixed(0x5f6),
        ..ProptestConfig::default()
    })]

    #[test]
    fn svg_with_random_elements_attributes_and_transforms(text in svg_document()) {
        check_pattern(parse(Format::Svg, &text))?;
    }
}

// ORIPA .cp and .opx ---------------------------------------------------------------------

fn line_type() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => (0i64..6).prop_map(|t| t.to_string()),
        1 => prop::sample::select(vec!["-1", "99999999999999999999", "2.5", "x", ""])
            .prop_map(String::from),
    ]
}

fn cp_text() -> impl Strategy<Value = String> {
    let line = prop_oneof![
        8 => (line_type(), number_text(), number_text(), number_text(), number_text())
            .prop_map(|(t, a, b, c, d)| format!("{t} {a} {b} {c} {d}")),
        1 => prop::collection::vec(number_text(), 0..8).prop_map(|f| f.join(" ")),
        1 => Just(String::new()),
    ];
    prop::collection::vec(line, 0..10).prop_map(|l| l.join("\n"))
}

fn opx_text() -> impl Strategy<Value = String> {
    let field = |name: &'static str, value: BoxedStrategy<String>| {
        prop::option::of(value).prop_map(move |v| match v {
            Some(v) if name == "type" => {
                format!(r#"<void property="type"><int>{v}</int></void>"#)
            }
            Some(v) => format!(r#"<void property="{name}"><double>{v}</double></void>"#),
            None => String::new(),
        })
    };
    let object = (
        field("type", line_type().boxed()),
        field("x0", number_text().boxed()),
        field("y0", number_text().boxed()),
        field("x1", number_text().boxed()),
        field("y1", number_text().boxed()),
        any::<bool>(),
    )
        .prop_map(|(t, a, b, c, d, closed)| {
            let end = if closed { "</object>" } else { "" };
            format!(r#"<object class="oripa.OriLineProxy">{t}{a}{b}{c}{d}{end}"#)
        });
    prop::collection::vec(object, 0..8).prop_map(|objects| {
        format!(
            "<?xml version=\"1.0\"?>\n<java><object class=\"oripa.DataSet\"><void property=\"lines\">\
             <array class=\"oripa.OriLineProxy\" length=\"{}\">{}</array></void></object></java>\n",
            objects.len(),
            objects.concat()
        )
    })
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 192,
        rng_seed: RngSeed::Fixed(0xc9),
        ..ProptestConfig::default()
    })]

    #[test]
    fn cp_lines_with_random_types_and_numbers(text in cp_text()) {
        check_pattern(parse(Format::Cp, &text))?;
    }

    #[test]
    fn opx_objects_with_random_types_and_numbers(text in opx_text()) {
        check_pattern(parse(Format::Opx, &text))?;
    }
}

// Voxel cards ----------------------------------------------------------------------------

fn voxel_text() -> impl Strategy<Value = String> {
    let count = prop::sample::select(vec!["0", "1", "3", "8", "-2", "99999999999", "2.5", "x"]);
    let header = (
        number_text(),
        count.clone(),
        count,
        prop::option::of(number_text()),
    )
        .prop_map(|(cell, depth, height, margin)| {
            let margin = margin.map(|m| format!("margin_mm {m}\n")).unwrap_or_default();
            format!("cell_mm {cell}\ndepth {depth}\nheight {height}\n{margin}rows\n")
        });
    let token = prop_oneof![
        6 => (0usize..5, prop::sample::select(vec!["", "", "w", "t", "wt", "ww", "x"]))
            .prop_map(|(d, f)| format!("{d}{f}")),
        1 => Just("-1".to_string()),
    ];
    let row = (1usize..5).prop_flat_map(move |width| {
        prop::collection::vec(prop::collection::vec(token.clone(), width..=width), 0..5)
    });
    (header, row).prop_map(|(h, rows)| {
        let rows: Vec<String> = rows.iter().map(|r| r.join(" ")).collect();
        format!("{h}{}\n", rows.join("\n"))
    })
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 192,
        rng_seed: RngSeed::Fixed(0x70c),
        ..ProptestConfig::default()
    })]

    /// A card read is written back and reads again to the same card; errors say something.
    #[test]
    fn voxel_cards_with_random_headers_and_rows(text in voxel_text()) {
        match parse_voxel_card(&text) {
            Ok(card) => {
                let again = parse_voxel_card(&format_voxel_card(&card))
                    .map_err(|e| TestCaseError::fail(format!("written card reads back: {e}")))?;
                prop_assert_eq!(again, card);
            }
            Err(e) => prop_assert!(!e.to_string().trim().is_empty()),
        }
    }
}

// Machine and material profiles ----------------------------------------------------------

/// A shipped profile with the value of one of its `key = value` lines replaced.
fn profile_with_one_value(text: &'static str) -> impl Strategy<Value = (String, String)> {
    let keys: Vec<usize> = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim_start().starts_with('#') && l.contains(" = "))
        .map(|(i, _)| i)
        .collect();
    let value = prop_oneof![
        number_text().prop_map(|v| if v.parse::<f64>().is_ok() || ["nan", "inf", "-inf"].contains(&v.as_str()) { v } else { format!("{v:?}") }),
        prop::sample::select(vec!["\"\"", "true", "[]", "{}", "-1", "0", "\"grbl\"", "[1, 2]"]).prop_map(String::from),
    ];
    (prop::sample::select(keys), value).prop_map(move |(line, value)| {
        let mut key = String::new();
        let out: Vec<String> = text
            .lines()
            .enumerate()
            .map(|(i, l)| {
                if i == line {
                    let k = l.split(" = ").next().unwrap_or("").to_string();
                    key = k.trim().to_string();
                    format!("{k} = {value}")
                } else {
                    l.to_string()
                }
            })
            .collect();
        (out.join("\n"), key)
    })
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 128,
        rng_seed: RngSeed::Fixed(0x7011),
        ..ProptestConfig::default()
    })]

    /// A machine profile with one value replaced loads with finite, positive settings, or the
    /// error names the source, a key and the problem.
    #[test]
    fn machine_profile_with_one_value_replaced(
        (text, key) in profile_with_one_value(include_str!("../machines/grbl-diode.toml"))
    ) {
        match parse_machine(&text, "m.toml") {
            Ok(m) => {
                prop_assert!(m.max_feed_mm_min.is_finite() && m.max_feed_mm_min > 0.0);
                prop_assert!(m.acceleration_mm_s2.is_finite() && m.acceleration_mm_s2 > 0.0);
                prop_assert!(m.bed.width_mm.is_finite() && m.bed.height_mm.is_finite());
            }
            Err(e) => {
                prop_assert!(e.source_name == "m.toml", "{e}");
                prop_assert!(!e.key.is_empty() && !e.message.trim().is_empty(), "{key}: {e}");
            }
        }
    }

    #[test]
    fn material_profile_with_one_value_replaced(
        (text, key) in profile_with_one_value(include_str!("../machines/materials/card-300gsm.toml"))
    ) {
        match parse_material(&text, "x.toml") {
            Ok(x) => prop_assert!(x.kerf_mm.is_finite() && x.kerf_mm >= 0.0),
            Err(e) => {
                prop_assert!(e.source_name == "x.toml", "{e}");
                prop_assert!(!e.key.is_empty() && !e.message.trim().is_empty(), "{key}: {e}");
            }
        }
    }
}

// G-code ---------------------------------------------------------------------------------

fn gcode_line() -> impl Strategy<Value = String> {
    let letter = prop::sample::select(vec![
        'G', 'M', 'X', 'Y', 'Z', 'F', 'S', 'P', 'T', 'E', 'I', 'J', 'R', 'N', 'Q',
    ]);
    let word = (letter, prop_oneof![
        4 => (0u32..100).prop_map(|n| n.to_string()),
        2 => number_text(),
    ])
        .prop_map(|(l, n)| format!("{l}{n}"));
    prop_oneof![
        8 => prop::collection::vec(word, 0..5).prop_map(|w| w.join(" ")),
        1 => prop::sample::select(vec!["; comment", "(comment)", "(unclosed", "%", "$H", "M3 S500", "G4 P-1", "G0 X1 X2"])
            .prop_map(String::from),
    ]
}

fn machines() -> Vec<MachineProfile> {
    ["grbl-diode", "marlin-laser", "grbl-pen-plotter"]
        .iter()
        .map(|m| load_machine(m).expect("shipped profile"))
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 192,
        rng_seed: RngSeed::Fixed(0x6c0de),
        ..ProptestConfig::default()
    })]

    /// The simulated machine runs any job to a report with finite, non-negative totals and
    /// violations on existing lines, or refuses it with a message.
    #[test]
    fn gcode_with_random_words(lines in prop::collection::vec(gcode_line(), 0..20)) {
        let text = lines.join("\n");
        for machine in machines() {
            match run(&text, &machine) {
                Ok(report) => {
                    prop_assert!(report.time_s.is_finite() && report.time_s >= 0.0);
                    prop_assert!(report.burn_length_mm.is_finite() && report.burn_length_mm >= 0.0);
                    prop_assert!(report.travel_length_mm.is_finite() && report.travel_length_mm >= 0.0);
                    for v in &report.violations {
                        prop_assert!(v.line >= 1 && v.line <= lines.len().max(1), "{v:?}");
                    }
                }
                Err(e) => prop_assert!(!e.to_string().trim().is_empty()),
            }
        }
    }
}
