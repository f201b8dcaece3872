//! Packing on part shapes: gaps measured between the real outlines and tabs, parts inside
//! their sheets, and interlocking shapes needing fewer sheets than their boxes.

use foldcam::design::papercraft::Part;
use foldcam::design::papercraft::pack_shapes;
use foldcam::design::papercraft::parse_design;
use foldcam::design::papercraft::{Placement, SheetSpec, pack, pack_boxes, part_points, usage};
use foldcam::geom::contains_point;
use foldcam::geom::segment_distance;
use glam::DVec2;

use super::support::{Rng, build_example};

/// Every edge of a placed part (outline and the tabs' free edges) on its sheet.
fn placed_edges(part: &Part, pl: &Placement) -> Vec<[DVec2; 2]> {
    let n = part.outline.len();
    let mut out: Vec<[DVec2; 2]> = (0..n)
        .map(|i| {
            [
                pl.apply(part.outline[i]),
                pl.apply(part.outline[(i + 1) % n]),
            ]
        })
        .collect();
    for t in &part.tabs {
        let (a, b) = (part.point(t.from), part.point(t.from + t.len));
        let [oa, ob] = t.outer;
        for [p, q] in [[a, oa], [oa, ob], [ob, b]] {
            out.push([pl.apply(p), pl.apply(q)]);
        }
    }
    out
}

/// The outline and tab polygons of a placed part.
fn placed_rings(part: &Part, pl: &Placement) -> Vec<Vec<DVec2>> {
    let mut rings = vec![part.outline.iter().map(|&p| pl.apply(p)).collect()];
    for t in &part.tabs {
        rings.push(part.tab_polygon(t).iter().map(|&p| pl.apply(p)).collect());
    }
    rings
}

/// Asserts that every part lies inside its sheet's margins and that no two parts on a sheet
/// come closer than the gap (edge to edge, tabs included) or lie one inside the other.
/// Returns the smallest distance seen between two parts.
fn assert_packed(name: &str, parts: &[Part], placements: &[Placement], spec: &SheetSpec) -> f64 {
    assert_eq!(placements.len(), parts.len(), "{name}");
    for pl in placements {
        for p in part_points(&parts[pl.part]) {
            let q = pl.apply(p);
            let inside = q.x >= spec.margin - 1e-9
                && q.x <= spec.width - spec.margin + 1e-9
                && q.y >= spec.margin - 1e-9
                && q.y <= spec.height - spec.margin + 1e-9;
            assert!(inside, "{name}: part {} at {q} leaves its sheet", pl.part);
        }
    }
    let mut closest = f64::INFINITY;
    for (i, a) in placements.iter().enumerate() {
        for b in &placements[i + 1..] {
            if a.sheet != b.sheet {
                continue;
            }
            let (ea, eb) = (
                placed_edges(&parts[a.part], a),
                placed_edges(&parts[b.part], b),
            );
            let d = ea
                .iter()
                .flat_map(|x| {
                    eb.iter()
                        .map(move |y| segment_distance(x[0], x[1], y[0], y[1]))
                })
                .fold(f64::INFINITY, f64::min);
            assert!(
                d >= spec.gap - 1e-6,
                "{name}: parts {} and {} are {d} mm apart (gap {})",
                a.part,
                b.part,
                spec.gap
            );
            closest = closest.min(d);
            let (ra, rb) = (
                placed_rings(&parts[a.part], a),
                placed_rings(&parts[b.part], b),
            );
            let nested = |r: &[Vec<DVec2>], s: &[Vec<DVec2>]| {
                r.iter().any(|x| s.iter().any(|y| contains_point(y, x[0])))
            };
            assert!(
                !nested(&ra, &rb) && !nested(&rb, &ra),
                "{name}: parts {} and {} lie one inside the other",
                a.part,
                b.part
            );
        }
    }
    closest
}

fn spec_of(name: &str) -> SheetSpec {
    let text = std::fs::read_to_string(format!("examples/papercraft/{name}.craft.toml")).unwrap();
    let design = parse_design(&text).unwrap();
    SheetSpec {
        width: design.sheet.width,
        height: design.sheet.height,
        margin: design.sheet.margin,
        gap: design.sheet.gap,
    }
}

#[test]
fn the_examples_keep_the_gap_between_real_outlines_and_stay_on_their_sheets() {
    for name in ["vase", "vase_auto", "fish"] {
        let made = build_example(name);
        let spec = spec_of(name);
        assert_packed(name, &made.parts, &made.placements, &spec);
        // The packing on shapes alone: some pair comes within a few gaps (boxes alone would
        // keep curved parts further apart).
        let alone = pack_shapes(&made.parts, &spec).unwrap();
        let closest = assert_packed(name, &made.parts, &alone, &spec);
        assert!(
            closest < 3.0 * spec.gap,
            "{name}: closest pair {closest} mm"
        );
        let shapes = usage(&made.parts, &alone, &spec);
        let kept = usage(&made.parts, &made.placements, &spec);
        let boxes = usage(&made.parts, &pack_boxes(&made.parts, &spec).unwrap(), &spec);
        println!(
            "{name}: shapes {} sheet(s), {:.1}% of the used area; boxes {} sheet(s), {:.1}%; \
             kept {} sheet(s), {:.1}%",
            shapes.sheets,
            100.0 * shapes.ratio(),
            boxes.sheets,
            100.0 * boxes.ratio(),
            kept.sheets,
            100.0 * kept.ratio()
        );
        // `pack` keeps the layout with fewer sheets, then less used area.
        assert!(
            kept.sheets < boxes.sheets
                || (kept.sheets == boxes.sheets && kept.used_area <= boxes.used_area),
            "{name}: kept {kept:?}, boxes {boxes:?}"
        );
        if name.starts_with("vase") {
            // The staggered gores interlock their tabs: all eight fit on one A4 sheet, where
            // their boxes need two.
            assert!(
                shapes.sheets < boxes.sheets,
                "{name}: {shapes:?} vs {boxes:?}"
            );
            assert_eq!(kept, shapes, "{name}");
        }
    }
}

/// An L of `w` × `h` with arms `t` thick, counter-clockwise.
fn l_part(w: f64, h: f64, t: f64) -> Part {
    let outline = [(0.0, 0.0), (w, 0.0), (w, t), (t, t), (t, h), (0.0, h)]
        .iter()
        .map(|&(x, y)| DVec2::new(x, y))
        .collect();
    Part {
        patch: 0,
        outline,
        sides: Vec::new(),
        tabs: Vec::new(),
        dropped_tabs: 0,
        labels: Vec::new(),
    }
}

#[test]
fn interlocking_ls_need_fewer_sheets_than_their_boxes() {
    // Four Ls of 120 × 80 mm, arms 30 mm: two boxes fit one above the other on the usable
    // 134 × 240 mm, while two Ls turned against each other take 114 mm of height.
    let parts: Vec<Part> = (0..4).map(|_| l_part(120.0, 80.0, 30.0)).collect();
    let spec = SheetSpec {
        width: 150.0,
        height: 256.0,
        margin: 8.0,
        gap: 4.0,
    };
    let boxes = pack_boxes(&parts, &spec).unwrap();
    let shapes = pack_shapes(&parts, &spec).unwrap();
    assert_eq!(pack(&parts, &spec).unwrap(), shapes);
    assert_packed("Ls", &parts, &shapes, &spec);
    let (b, s) = (usage(&parts, &boxes, &spec), usage(&parts, &shapes, &spec));
    assert_eq!(b.sheets, 2, "{b:?}");
    assert_eq!(s.sheets, 1, "{s:?}");
    assert!(s.ratio() > b.ratio(), "{s:?} vs {b:?}");
}

/// A star-shaped (non-convex) polygon round the origin, counter-clockwise.
fn star(rng: &mut Rng, size: f64) -> Part {
    let n = 5 + (rng.unit() * 20.0) as usize;
    let outline = (0..n)
        .map(|k| {
            let a = std::f64::consts::TAU * (k as f64 + rng.range(0.0, 0.6)) / n as f64;
            DVec2::from_angle(a) * size * rng.range(0.3, 1.0)
        })
        .collect();
    Part {
        outline,
        ..l_part(1.0, 1.0, 0.5)
    }
}

#[test]
fn random_non_convex_parts_never_overlap_or_come_too_close() {
    let mut rng = Rng::new(5);
    let spec = SheetSpec {
        width: 200.0,
        height: 160.0,
        margin: 5.0,
        gap: 3.0,
    };
    for round in 0..4 {
        let parts: Vec<Part> = (0..14)
            .map(|_| {
                let size = rng.range(10.0, 45.0);
                star(&mut rng, size)
            })
            .collect();
        let placements = pack_shapes(&parts, &spec).unwrap();
        assert_packed(&format!("stars {round}"), &parts, &placements, &spec);
        assert_packed(
            &format!("stars {round}, kept"),
            &parts,
            &pack(&parts, &spec).unwrap(),
            &spec,
        );
        let (s, b) = (
            usage(&parts, &placements, &spec),
            usage(&parts, &pack_boxes(&parts, &spec).unwrap(), &spec),
        );
        assert!(
            s.sheets < b.sheets || (s.sheets == b.sheets && s.used_area <= b.used_area),
            "round {round}: {s:?} vs {b:?}"
        );
    }
}

#[test]
fn bad_parts_and_sheets_are_refused_by_both_packers() {
    let spec = SheetSpec {
        width: 210.0,
        height: 297.0,
        margin: 5.0,
        gap: 3.0,
    };
    assert_eq!(pack(&[], &spec).unwrap(), Vec::<Placement>::new());
    let mut nan = l_part(40.0, 30.0, 10.0);
    nan.outline[2].x = f64::NAN;
    let empty = Part {
        outline: Vec::new(),
        ..l_part(1.0, 1.0, 0.5)
    };
    let huge = l_part(400.0, 400.0, 100.0);
    let huge_sheet = SheetSpec {
        width: 1e12,
        ..spec
    };
    for packer in [pack_shapes, pack_boxes, pack] {
        for (what, parts, spec) in [
            ("NaN", vec![nan.clone()], &spec),
            ("empty outline", vec![empty.clone()], &spec),
            ("larger than the sheet", vec![huge.clone()], &spec),
            (
                "sheet of 1e12 mm",
                vec![l_part(40.0, 30.0, 10.0)],
                &huge_sheet,
            ),
        ] {
            let err = packer(&parts, spec).expect_err(what);
            assert!(!err.to_string().is_empty(), "{what}");
        }
    }
}
