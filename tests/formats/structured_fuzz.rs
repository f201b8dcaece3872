//! Structured fuzzing of the readers inside `cargo test` (the coverage-guided targets are in
//! `fuzz/`): inputs that are well formed on the surface — FOLD JSON with random arrays and
//! indices, SVG with random elements, attributes and transforms, `.cp` and `.opx` lines with
//! random types and numbers, voxel cards with random headers and rows, profiles with one value
//! replaced, G-code with random words — and odd here and there (NaN spelt out, 1e308, negative
//! and out-of-range indices, unknown letters). Each reader must either return a model that
//! keeps its invariants (indices in range, finite coordinates within the limit, fold angles
//! within ±180°) or an error that says where and what; a panic fails the test. Each property
//! also counts how many inputs were accepted and how many refused, and fails when either is
//! below a tenth of the cases, so a generator that drifts into producing only garbage (or only
//! clean files) is noticed. Bounded: 128–192 cases per reader with fixed seeds, well under a
//! second in a debug build.

use std::cell::Cell;

use foldcam::design::popup::voxel::{format_voxel_card, parse_voxel_card};
use foldcam::formats::{Format, Imported, ParseError, parse};
use foldcam::machine::{MachineProfile, load_machine, parse_machine, parse_material};
use foldcam::pattern::{CreasePattern, MAX_COORDINATE};
use foldcam::sim::run;
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed, TestRunner};
use serde_json::{Value, json};

// Running --------------------------------------------------------------------------------

/// Runs `check` on `cases` inputs from `strategy` (fixed `seed`); `check` says whether the
/// input was accepted. Fails on a failed check (shrunk) or when fewer than a tenth of the
/// inputs were accepted, or fewer than a tenth refused.
fn fuzz<S: Strategy>(
    name: &str,
    cases: u32,
    seed: u64,
    strategy: S,
    check: impl Fn(S::Value) -> Result<bool, TestCaseError>,
) {
    let accepted = Cell::new(0u32);
    let refused = Cell::new(0u32);
    let mut runner = TestRunner::new(Config {
        cases,
        rng_seed: RngSeed::Fixed(seed),
        failure_persistence: None,
        ..Config::default()
    });
    let result = runner.run(&strategy, |input| {
        let ok = check(input)?;
        let counter = if ok { &accepted } else { &refused };
        counter.set(counter.get() + 1);
        Ok(())
    });
    if let Err(e) = result {
        panic!("{name}: {e}");
    }
    let (a, r) = (accepted.get(), refused.get());
    assert!(
        a >= cases / 10 && r >= cases / 10,
        "{name}: {a} accepted, {r} refused of {cases}: the generator needs rebalancing"
    );
}

// Checks ---------------------------------------------------------------------------------

/// The model invariants every reader promises, checked here field by field (and then by
/// `validate`), so that a reader and `validate` sharing a mistake cannot hide it.
fn assert_model(cp: &CreasePattern) -> Result<(), TestCaseError> {
    let n = cp.vertices.len();
    for (i, p) in cp.vertices.iter().enumerate() {
        prop_assert!(
            p.is_finite() && p.abs().max_element() <= MAX_COORDINATE,
            "vertex {} at {}",
            i,
            p
        );
    }
    for (i, e) in cp.edges.iter().enumerate() {
        let [a, b] = e.vertices;
        prop_assert!(
            (a.0 as usize) < n && (b.0 as usize) < n,
            "edge {i}: {a:?}–{b:?} of {n}"
        );
        prop_assert_ne!(a, b, "edge {} is a loop", i);
        if let Some(angle) = e.fold_angle {
            prop_assert!(
                angle.is_finite() && angle.abs() <= 180.0,
                "edge {i} angle {angle}"
            );
        }
    }
    for (i, f) in cp.faces.iter().flatten().enumerate() {
        for v in f.outer.iter().chain(f.holes.iter().flatten()) {
            prop_assert!((v.0 as usize) < n, "face {i} names vertex {v:?} of {n}");
        }
    }
    prop_assert!(cp.validate().is_ok(), "{:?}", cp.validate());
    Ok(())
}

/// A pattern reader's result: a valid model whose FOLD text reads back and writes again to
/// the same text (the writer may planarise a drawing that is not planar, so counts can
/// change once, but not twice), or an error with a place and a message. True when accepted.
fn check_pattern(result: Result<Imported, ParseError>) -> Result<bool, TestCaseError> {
    match result {
        Ok(imported) => {
            let cp = &imported.pattern;
            assert_model(cp)?;
            let text = foldcam::formats::fold::write_string(cp, imported.folded.as_ref());
            let back = foldcam::formats::fold::read_str(&text)
                .map_err(|e| TestCaseError::fail(format!("written FOLD reads back: {e}")))?;
            let again = foldcam::formats::fold::write_string(&back.pattern, back.folded.as_ref());
            prop_assert_eq!(again, text, "the FOLD text changed on a second round trip");
            Ok(true)
        }
        Err(e) => {
            prop_assert!(!e.place.trim().is_empty(), "no place: {:?}", e);
            prop_assert!(!e.message.trim().is_empty(), "no message: {:?}", e);
            Ok(false)
        }
    }
}

// Numbers --------------------------------------------------------------------------------

/// An ordinary number, or rarely one of the extremes.
fn number() -> impl Strategy<Value = f64> {
    prop_oneof![
        30 => -200.0f64..200.0,
        1 => prop::sample::select(vec![0.0, -0.0, 1e-300, 1e9, -1e9, 1.0000001e9, 1e300, 1e308, -1e308]),
    ]
}

/// A number as text, rarely a spelling no reader should take as a number.
fn number_text() -> impl Strategy<Value = String> {
    prop_oneof![
        30 => number().prop_map(|x| x.to_string()),
        1 => prop::sample::select(vec!["NaN", "nan", "inf", "-inf", "1e999", "", "1,5", "0x10", "1e", "--1", "١٢"])
            .prop_map(String::from),
    ]
}

// FOLD -----------------------------------------------------------------------------------

/// One edge: its vertex ids, assignment letter and fold angle, given `n` vertices.
fn fold_edge(n: i64) -> impl Strategy<Value = (Vec<i64>, &'static str, Value)> {
    let ends = prop_oneof![
        20 => prop::collection::vec(0..n, 2..=2),
        1 => prop::collection::vec(-2..n + 3, 1..4),
    ];
    let letter = prop_oneof![
        20 => prop::sample::select(vec!["B", "M", "V", "F", "U", "C", "J", "m"]),
        1 => prop::sample::select(vec!["Q", ""]),
    ];
    let angle = prop_oneof![
        20 => (-180.0f64..=180.0).prop_map(|a| json!(a)),
        1 => Just(Value::Null),
        1 => prop::sample::select(vec![json!(500.0), json!("ninety")]),
    ];
    (ends, letter, angle)
}

fn fold_json() -> impl Strategy<Value = String> {
    (3i64..8)
        .prop_flat_map(|n| {
            let vertex = prop_oneof![
                20 => prop::collection::vec(number(), 2..=2),
                1 => prop::collection::vec(number(), 0..5),
            ];
            let coords = prop::collection::vec(vertex, n as usize..=n as usize);
            let edges = prop::collection::vec(fold_edge(n), 0..10);
            // Which optional arrays the file has; a short array now and then.
            let keys = (any::<bool>(), any::<bool>(), prop::bool::weighted(0.05));
            let faces = prop::option::weighted(
                0.2,
                prop::collection::vec(prop::collection::vec(-1..n + 1, 0..6), 0..4),
            );
            let unit = prop::sample::select(vec![
                None,
                Some("mm"),
                Some("unit"),
                Some("in"),
                Some("furlong"),
            ]);
            let frames = prop::option::weighted(
                0.2,
                prop::collection::vec((prop::option::of(-1i64..4), any::<bool>()), 0..3),
            );
            (coords, edges, keys, faces, unit, frames)
        })
        .prop_map(
            |(coords, edges, (with_letters, with_angles, short), faces, unit, frames)| {
                let mut m = serde_json::Map::new();
                m.insert("vertices_coords".into(), json!(coords));
                let cut = usize::from(short && !edges.is_empty());
                let ends: Vec<&Vec<i64>> = edges.iter().map(|e| &e.0).collect();
                m.insert("edges_vertices".into(), json!(ends));
                if with_letters {
                    let letters: Vec<&str> = edges.iter().map(|e| e.1).collect();
                    m.insert("edges_assignment".into(), json!(letters[cut..]));
                }
                if with_angles {
                    let angles: Vec<&Value> = edges.iter().map(|e| &e.2).collect();
                    m.insert("edges_foldAngle".into(), json!(angles));
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

#[test]
fn fold_with_random_arrays_and_indices() {
    fuzz("FOLD", 192, 0xf01d, fold_json(), |text| {
        check_pattern(parse(Format::Fold, &text))
    });
}

// SVG ------------------------------------------------------------------------------------

fn svg_colour() -> impl Strategy<Value = &'static str> {
    prop_oneof![
        10 => prop::sample::select(vec![
            "#ff0000", "#0000ff", "#000000", "#00ff00", "#ffff00", "#ff00ff", "red", "blue",
        ]),
        1 => prop::sample::select(vec!["none", "url(#g)", "#12", "rgb(300,0,0)"]),
    ]
}

fn svg_transform() -> impl Strategy<Value = String> {
    prop_oneof![
        12 => Just(String::new()),
        2 => (number_text(), number_text()).prop_map(|(a, b)| format!("translate({a} {b})")),
        2 => number_text().prop_map(|a| format!("scale({a})")),
        2 => number_text().prop_map(|a| format!("rotate({a})")),
        1 => number_text().prop_map(|a| format!("skewX({a})")),
        1 => prop::sample::select(vec!["matrix(0 0 0 0 0 0)", "scale(1e300)", "translate("])
            .prop_map(String::from),
    ]
}

fn svg_element() -> impl Strategy<Value = String> {
    let n = number_text;
    let shape = prop_oneof![
        4 => (n(), n(), n(), n()).prop_map(|(a, b, c, d)| format!(
            r#"<line x1="{a}" y1="{b}" x2="{c}" y2="{d}""#
        )),
        1 => prop::collection::vec(n(), 0..8)
            .prop_map(|p| format!(r#"<polyline points="{}""#, p.join(" "))),
        1 => prop::collection::vec(n(), 0..8)
            .prop_map(|p| format!(r#"<polygon points="{}""#, p.join(","))),
        1 => (n(), n(), n(), n())
            .prop_map(|(a, b, c, d)| format!(r#"<path d="M {a} {b} L {c} {d} Q {a} {d} {c} {b} Z""#)),
        1 => (n(), n(), n(), n()).prop_map(|(a, b, c, d)| format!(
            r#"<rect x="{a}" y="{b}" width="{c}" height="{d}""#
        )),
        1 => (n(), n(), n()).prop_map(|(a, b, c)| format!(r#"<circle cx="{a}" cy="{b}" r="{c}""#)),
        1 => (n(), n(), n(), n()).prop_map(|(a, b, c, d)| format!(
            r#"<path d="M {a} {b} A {c} {d} 0 1 0 {b} {a}""#
        )),
    ];
    let extra = prop_oneof![
        6 => Just(""),
        1 => prop::sample::select(vec![
            r#" stroke-dasharray="5 2""#,
            r#" stroke-dasharray="0""#,
            r#" stroke-opacity="0.5""#,
            r#" stroke-opacity="NaN""#,
            r#" data-assignment="M""#,
            r#" data-assignment="Z""#,
            r#" class="valley""#,
            r#" stroke-width="-1""#,
            r#" stroke-miterlimit="1e39""#,
            r#" display="none""#,
        ]),
    ];
    (shape, svg_colour(), svg_transform(), extra).prop_map(|(shape, colour, t, extra)| {
        format!(r#"{shape} stroke="{colour}" transform="{t}"{extra}/>"#)
    })
}

fn svg_document() -> impl Strategy<Value = String> {
    let size = prop_oneof![
        8 => prop::sample::select(vec!["200mm", "200", "10in"]),
        1 => prop::sample::select(vec!["-5mm", "0", "1e308mm", "abc", "50%", ""]),
    ];
    let view_box = prop_oneof![
        8 => prop::sample::select(vec!["-200 -200 400 400", ""]),
        1 => prop::sample::select(vec!["0 0 0 0", "1 2", "0 0 1e-30 1e-30"]),
    ];
    let group = prop::collection::vec(svg_element(), 1..5);
    (size.clone(), size, view_box, prop::collection::vec((svg_transform(), group), 1..3))
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

#[test]
fn svg_with_random_elements_attributes_and_transforms() {
    fuzz("SVG", 128, 0x5f6, svg_document(), |text| {
        check_pattern(parse(Format::Svg, &text))
    });
}

// ORIPA .cp and .opx ---------------------------------------------------------------------

/// An ORIPA line type: mostly 0–5, rarely something that is no type.
fn line_type() -> impl Strategy<Value = String> {
    prop_oneof![
        20 => (0i64..6).prop_map(|t| t.to_string()),
        1 => prop::sample::select(vec!["-1", "99999999999999999999", "2.5", "x", ""])
            .prop_map(String::from),
    ]
}

fn cp_text() -> impl Strategy<Value = String> {
    let line = prop_oneof![
        30 => (line_type(), number_text(), number_text(), number_text(), number_text())
            .prop_map(|(t, a, b, c, d)| format!("{t} {a} {b} {c} {d}")),
        1 => prop::collection::vec(number_text(), 0..8).prop_map(|f| f.join(" ")),
        1 => Just(String::new()),
    ];
    prop::collection::vec(line, 0..8).prop_map(|l| l.join("\n"))
}

fn opx_text() -> impl Strategy<Value = String> {
    let field = |name: &'static str, value: BoxedStrategy<String>| {
        prop::option::weighted(0.95, value).prop_map(move |v| match v {
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
        prop::bool::weighted(0.97),
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

#[test]
fn cp_lines_with_random_types_and_numbers() {
    fuzz("cp", 192, 0xc9, cp_text(), |text| {
        check_pattern(parse(Format::Cp, &text))
    });
}

#[test]
fn opx_objects_with_random_types_and_numbers() {
    fuzz("opx", 192, 0x09c, opx_text(), |text| {
        check_pattern(parse(Format::Opx, &text))
    });
}

// Voxel cards ----------------------------------------------------------------------------

fn voxel_text() -> impl Strategy<Value = String> {
    let count = || {
        prop_oneof![
            12 => (1usize..9).prop_map(|c| c.to_string()),
            1 => prop::sample::select(vec!["0", "-2", "99999999999", "2.5", "x"]).prop_map(String::from),
        ]
    };
    let header = (
        number_text(),
        count(),
        count(),
        prop::option::of(number_text()),
    )
        .prop_map(|(cell, depth, height, margin)| {
            let margin = margin
                .map(|m| format!("margin_mm {}\n", m.trim_start_matches('-')))
                .unwrap_or_default();
            let cell = cell.trim_start_matches('-');
            format!("cell_mm {cell}\ndepth {depth}\nheight {height}\n{margin}rows\n")
        });
    // Each column's depths, sorted so that they shrink upwards (the first line is the top),
    // as a valid card needs; a flag, and rarely a token that is no depth.
    let cell = (
        0usize..4,
        prop::sample::select(vec!["", "", "", "", "w", "t", "wt"]),
        prop::sample::select(vec!["-1", "ww", "3x", "7"]),
        prop::bool::weighted(0.02),
    );
    let rows = (1usize..5, 1usize..5).prop_flat_map(move |(width, height)| {
        prop::collection::vec(cell.clone(), width * height).prop_map(move |mut cells| {
            for x in 0..width {
                let mut depths: Vec<usize> = (0..height).map(|z| cells[z * width + x].0).collect();
                depths.sort_unstable();
                for (z, d) in depths.into_iter().enumerate() {
                    cells[z * width + x].0 = d;
                }
            }
            cells
                .chunks(width)
                .map(|row| {
                    let tokens: Vec<String> = row
                        .iter()
                        .map(|&(d, flag, odd, is_odd)| {
                            if is_odd {
                                odd.to_string()
                            } else {
                                format!("{d}{flag}")
                            }
                        })
                        .collect();
                    tokens.join(" ")
                })
                .collect::<Vec<String>>()
        })
    });
    (header, rows).prop_map(|(h, rows)| format!("{h}{}\n", rows.join("\n")))
}

#[test]
fn voxel_cards_with_random_headers_and_rows() {
    // A card read is written back and reads again to the same card; errors say something.
    fuzz(
        "voxel",
        192,
        0x70c,
        voxel_text(),
        |text| match parse_voxel_card(&text) {
            Ok(card) => {
                let again = parse_voxel_card(&format_voxel_card(&card))
                    .map_err(|e| TestCaseError::fail(format!("written card reads back: {e}")))?;
                prop_assert_eq!(again, card);
                Ok(true)
            }
            Err(e) => {
                prop_assert!(!e.to_string().trim().is_empty());
                Ok(false)
            }
        },
    );
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
        3 => Just(None::<String>),
        2 => number().prop_map(|v| Some(v.to_string())),
        1 => prop::sample::select(vec!["nan", "inf", "\"\"", "true", "[]", "{}", "-1", "0", "\"grbl\"", "[1, 2]", "= 3"])
            .prop_map(|v| Some(v.to_string())),
    ];
    (prop::sample::select(keys), value).prop_map(move |(line, value)| {
        let mut key = String::new();
        let out: Vec<String> = text
            .lines()
            .enumerate()
            .map(|(i, l)| match &value {
                Some(value) if i == line => {
                    let k = l.split(" = ").next().unwrap_or("");
                    key = k.trim().to_string();
                    format!("{k} = {value}")
                }
                _ => l.to_string(),
            })
            .collect();
        (out.join("\n"), key)
    })
}

#[test]
fn machine_profile_with_one_value_replaced() {
    // Loads with finite, positive settings, or the error names the source, a key and the
    // problem.
    let strategy = profile_with_one_value(include_str!("../../machines/grbl-diode.toml"));
    fuzz(
        "machine",
        128,
        0x7011,
        strategy,
        |(text, key)| match parse_machine(&text, "m.toml") {
            Ok(m) => {
                prop_assert!(m.max_feed_mm_min.is_finite() && m.max_feed_mm_min > 0.0);
                prop_assert!(m.acceleration_mm_s2.is_finite() && m.acceleration_mm_s2 > 0.0);
                prop_assert!(m.bed.width_mm.is_finite() && m.bed.height_mm.is_finite());
                Ok(true)
            }
            Err(e) => {
                prop_assert!(e.source_name == "m.toml", "{}", e);
                prop_assert!(
                    !e.key.is_empty() && !e.message.trim().is_empty(),
                    "{}: {}",
                    key,
                    e
                );
                Ok(false)
            }
        },
    );
}

#[test]
fn material_profile_with_one_value_replaced() {
    let strategy =
        profile_with_one_value(include_str!("../../machines/materials/card-300gsm.toml"));
    fuzz(
        "material",
        128,
        0x7012,
        strategy,
        |(text, key)| match parse_material(&text, "x.toml") {
            Ok(x) => {
                prop_assert!(x.kerf_mm.is_finite() && x.kerf_mm >= 0.0);
                Ok(true)
            }
            Err(e) => {
                prop_assert!(e.source_name == "x.toml", "{}", e);
                prop_assert!(
                    !e.key.is_empty() && !e.message.trim().is_empty(),
                    "{}: {}",
                    key,
                    e
                );
                Ok(false)
            }
        },
    );
}

// G-code ---------------------------------------------------------------------------------

fn gcode_line() -> impl Strategy<Value = String> {
    let letter = prop::sample::select(vec![
        'G', 'M', 'X', 'Y', 'Z', 'F', 'S', 'P', 'T', 'E', 'I', 'J', 'R', 'N', 'Q',
    ]);
    let word = (
        letter,
        prop_oneof![
            4 => (0u32..100).prop_map(|n| n.to_string()),
            2 => number_text(),
        ],
    )
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

#[test]
fn gcode_with_random_words() {
    // The simulated machine runs any job to a report with finite, non-negative totals and
    // violations on existing lines, or refuses it with a message. "Accepted" here is a
    // report without violations; jobs of random words mostly break a rule.
    let machines = machines();
    let jobs = prop_oneof![
        1 => prop::collection::vec(gcode_line(), 0..20),
        1 => prop::collection::vec(
            (0.0f64..300.0, 0.0f64..300.0).prop_map(|(x, y)| format!("G1 X{x:.3} Y{y:.3} F1200")),
            0..8,
        ),
    ];
    fuzz("G-code", 192, 0x6c0de, jobs, |lines| {
        let text = lines.join("\n");
        let mut clean = true;
        for machine in &machines {
            match run(&text, machine) {
                Ok(report) => {
                    prop_assert!(report.time_s.is_finite() && report.time_s >= 0.0);
                    prop_assert!(report.burn_length_mm.is_finite() && report.burn_length_mm >= 0.0);
                    prop_assert!(
                        report.travel_length_mm.is_finite() && report.travel_length_mm >= 0.0
                    );
                    for v in &report.violations {
                        prop_assert!(v.line >= 1 && v.line <= lines.len().max(1), "{:?}", v);
                    }
                    clean &= report.violations.is_empty();
                }
                Err(e) => {
                    prop_assert!(!e.to_string().trim().is_empty());
                    clean = false;
                }
            }
        }
        Ok(clean)
    });
}
