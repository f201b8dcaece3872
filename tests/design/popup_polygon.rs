//! Polygon pop-up cards (Mitani & Suzuki 2004): the pattern condition after every edit (eq. 4, 5), openings
//! (eq. 6), line types (§3.4, Fig. 10), the pop-up check (§3.6, Fig. 7), the open/close
//! transform (eq. 7), voxel conversion, design files and the fabrication pipeline.

use foldcam::design::popup::polygon::{
    DesignError, FaceKind, Plane, PolygonCard, PolygonError, PopupProblem, UNIT_MM, check_popup,
    crease_pattern, fold_card, from_voxel, parse_design,
};
use foldcam::design::popup::voxel::{self, VoxelCard};
use foldcam::pattern::Assignment;
use glam::{DVec2, DVec3};
use proptest::prelude::*;

use crate::support::popup_polygon as support;

use support::*;

#[test]
fn blank_card_is_back_and_base_with_one_valley() {
    let card = PolygonCard::new(100.0, 40.0, 60.0).unwrap();
    assert_pattern_condition(&card);
    let cp = crease_pattern(&card).unwrap();
    let folds: Vec<_> = cp
        .edge_ids()
        .filter(|&e| cp.edges[e.index()].assignment.is_fold())
        .map(|e| (cp.segment(e), cp.edges[e.index()].assignment))
        .collect();
    assert_eq!(folds.len(), 1);
    let ((a, b), kind) = folds[0];
    assert_eq!(
        (kind, a.y, b.y, (a.x - b.x).abs()),
        (Assignment::Valley, 0.0, 0.0, 100.0)
    );
    assert!(check_popup(&card).passed());
}

#[test]
fn eq_1_to_3_round_trip() {
    for (kind, t) in [(FaceKind::Vertical, 12.5), (FaceKind::Horizontal, 30.0)] {
        let plane = Plane {
            kind,
            t: (t / UNIT_MM) as i32,
        };
        let p = DVec2::new(7.0, -3.25);
        let q = plane.to_card(p);
        match kind {
            FaceKind::Vertical => assert_eq!(q.y, t),
            FaceKind::Horizontal => assert_eq!(q.z, t),
        }
        let back = foldcam::design::popup::polygon::pattern_point(q);
        assert!((back - p).length() < 1e-12, "{back} vs {p}");
    }
}

#[test]
fn box_has_the_lines_of_section_3_4() {
    let card = house();
    let cp = crease_pattern(&card).unwrap();
    // Valleys: back/roof (v = 30) over x 35..85, wall/base (v = −30), the central fold on both
    // sides of the box; one mountain: roof/wall (v = 0).
    let spans = |kind| {
        let mut s: Vec<(f64, f64, f64)> = cp
            .edge_ids()
            .filter(|&e| cp.edges[e.index()].assignment == kind)
            .map(|e| cp.segment(e))
            .map(|(a, b)| (a.y, a.x.min(b.x), a.x.max(b.x)))
            .collect();
        s.sort_by(|p, q| p.partial_cmp(q).unwrap());
        s
    };
    assert_eq!(
        spans(Assignment::Valley),
        vec![
            (-30.0, 35.0, 85.0),
            (0.0, 0.0, 35.0),
            (0.0, 85.0, 120.0),
            (30.0, 35.0, 85.0)
        ]
    );
    assert_eq!(spans(Assignment::Mountain), vec![(0.0, 35.0, 85.0)]);
    for e in &cp.edges {
        let want = match e.assignment {
            Assignment::Valley => Some(90.0),
            Assignment::Mountain => Some(-90.0),
            _ => None,
        };
        assert_eq!(e.fold_angle, want);
    }
}

#[test]
fn partly_shared_segments_are_split_at_end_points() {
    // Fig. 10: a horizontal strip at z = 10 over y 10..20 (pattern v −10..0, x 20..80), then a
    // wall at y = 20 under its right half (x 50..80, z 0..10: v −20..−10). The strip's lower
    // edge (one segment, x 20..80) is shared with the base on 20..50 and with the wall on
    // 50..80: split at x = 50, it is a cut where the base lies (card lines (10, 0) and
    // (20, 10) differ) and a mountain where the wall meets the strip on (20, 10).
    let mut card = PolygonCard::new(100.0, 50.0, 50.0).unwrap();
    card.add_face(FaceKind::Horizontal, 10.0, &quad(20.0, 10.0, 80.0, 20.0))
        .unwrap();
    card.add_face(FaceKind::Vertical, 20.0, &quad(50.0, 0.0, 80.0, 10.0))
        .unwrap();
    let cp = crease_pattern(&card).unwrap();
    let mut on_line: Vec<(f64, f64, Assignment)> = cp
        .edge_ids()
        .map(|e| (cp.segment(e), cp.edges[e.index()].assignment))
        .filter(|((a, b), _)| a.y == -10.0 && b.y == -10.0)
        .map(|((a, b), k)| (a.x.min(b.x), a.x.max(b.x), k))
        .collect();
    on_line.sort_by(|p, q| p.0.total_cmp(&q.0));
    assert_eq!(
        on_line,
        vec![
            (20.0, 50.0, Assignment::Cut),
            (50.0, 80.0, Assignment::Mountain)
        ]
    );
    // The strip's upper edge (v = 0, card line (10, 10)) borders the back sheet (0, 0): cut.
    let valleys_at_zero: f64 = cp
        .edge_ids()
        .filter(|&e| cp.edges[e.index()].assignment == Assignment::Valley)
        .map(|e| (cp.segment(e), cp.edge_length(e)))
        .filter(|((a, b), _)| a.y == 0.0 && b.y == 0.0)
        .map(|(_, l)| l)
        .sum();
    assert_eq!(
        valleys_at_zero, 40.0,
        "central fold left and right of the strip only"
    );
    assert_eq!(fold_lengths(&cp, Assignment::Mountain), vec![30.0]);
}

#[test]
fn openings_add_the_equivalent_face_of_eq_6() {
    let mut card = house();
    // A V hole at z 15..24 becomes an HFace at z = minZ = 15 with the same pattern polygon.
    let i = card
        .add_opening(FaceKind::Vertical, 30.0, &quad(40.0, 15.0, 50.0, 24.0))
        .unwrap();
    let f = &card.faces()[i];
    assert_eq!((f.plane.kind, f.plane.t_mm()), (FaceKind::Horizontal, 15.0));
    assert!((f.area_mm2() - 90.0).abs() < 1e-9);
    let ring = &f.polygon_mm()[0][0];
    let (lo, hi) = ring_bounds(ring);
    assert_eq!((lo, hi), (DVec2::new(40.0, -15.0), DVec2::new(50.0, -6.0)));
    // An H hole in the roof at y 10..20 becomes a VFace at y = minY = 10.
    let j = card
        .add_opening(FaceKind::Horizontal, 30.0, &quad(60.0, 10.0, 70.0, 20.0))
        .unwrap();
    let g = &card.faces()[j];
    assert_eq!((g.plane.kind, g.plane.t_mm()), (FaceKind::Vertical, 10.0));
    let (lo, hi) = ring_bounds(&g.polygon_mm()[0][0]);
    assert_eq!((lo, hi), (DVec2::new(60.0, 10.0), DVec2::new(70.0, 20.0)));
    assert_pattern_condition(&card);
    // The hole's paper hangs from the roof's back edge: the sill lies on its plane at 90°.
    let cp = crease_pattern(&card).unwrap();
    assert_faces_on_planes(&card, &cp);
}

#[test]
fn slanted_outlines_and_cut_outs_work() {
    let card = example("slanted.popup.toml");
    assert_pattern_condition(&card);
    assert!(check_popup(&card).passed());
    let cp = crease_pattern(&card).unwrap();
    let slanted_cuts = cp
        .edge_ids()
        .filter(|&e| cp.edges[e.index()].assignment == Assignment::Cut)
        .map(|e| cp.segment(e))
        .filter(|(a, b)| a.x != b.x && a.y != b.y)
        .count();
    assert!(
        slanted_cuts >= 2 + 2 + 4,
        "gable, step sides, diamond: {slanted_cuts}"
    );
    assert_creases_parallel_to_x(&cp);
    assert_faces_on_planes(&card, &cp);
}

#[test]
fn floating_face_is_rejected_by_name() {
    // Fig. 7 (a): a wall standing in mid-air, cut from both sheets.
    let mut card = PolygonCard::new(100.0, 50.0, 50.0).unwrap();
    let wall = card
        .add_face(FaceKind::Vertical, 20.0, &quad(30.0, 10.0, 50.0, 20.0))
        .unwrap();
    let report = check_popup(&card);
    assert_eq!(report.faces(), vec![wall]);
    assert_eq!(report.problems[0].problem, PopupProblem::Floating);
}

#[test]
fn face_held_from_one_side_is_rejected_by_name() {
    // Fig. 7 (b): a box whose front stops short of the base hangs from the back sheet.
    let mut card = PolygonCard::new(100.0, 50.0, 50.0).unwrap();
    let front = card
        .add_face(FaceKind::Vertical, 20.0, &quad(30.0, 5.0, 50.0, 20.0))
        .unwrap();
    card.add_face(FaceKind::Horizontal, 20.0, &quad(30.0, 0.0, 50.0, 20.0))
        .unwrap();
    let report = check_popup(&card);
    assert_eq!(report.faces(), vec![front]);
    assert_eq!(report.problems[0].problem, PopupProblem::HeldFromBackOnly);
    // A step standing on the base with no top reaching back: held from the base only.
    let mut card = PolygonCard::new(100.0, 50.0, 50.0).unwrap();
    let step = card
        .add_face(FaceKind::Vertical, 20.0, &quad(30.0, 0.0, 50.0, 10.0))
        .unwrap();
    card.add_face(FaceKind::Horizontal, 10.0, &quad(30.0, 10.0, 50.0, 20.0))
        .unwrap();
    let report = check_popup(&card);
    assert_eq!(report.faces(), vec![step]);
    assert_eq!(report.problems[0].problem, PopupProblem::HeldFromBaseOnly);
    // Completing the step's top back to the back sheet fixes it.
    card.add_face(FaceKind::Horizontal, 10.0, &quad(30.0, 0.0, 50.0, 20.0))
        .unwrap();
    assert!(check_popup(&card).passed());
}

#[test]
fn bad_input_is_refused() {
    assert!(matches!(
        PolygonCard::new(f64::NAN, 10.0, 10.0),
        Err(PolygonError::BadSize { what: "width", .. })
    ));
    let mut card = PolygonCard::new(100.0, 50.0, 50.0).unwrap();
    let sq = quad(0.0, 0.0, 10.0, 10.0);
    assert!(matches!(
        card.add_face(FaceKind::Vertical, 60.0, &sq),
        Err(PolygonError::BadPlane { .. })
    ));
    assert!(matches!(
        card.add_face(FaceKind::Vertical, 10.0, &sq[..2]),
        Err(PolygonError::PointCount(2))
    ));
    let mut nan = sq.clone();
    nan[2].x = f64::INFINITY;
    assert!(matches!(
        card.add_face(FaceKind::Vertical, 10.0, &nan),
        Err(PolygonError::BadPoint { index: 2, .. })
    ));
    let outside = quad(200.0, 0.0, 210.0, 10.0);
    assert_eq!(
        card.add_face(FaceKind::Vertical, 10.0, &outside),
        Err(PolygonError::Empty)
    );
    assert_eq!(card.faces().len(), 2, "refused edits change nothing");
}

#[test]
fn design_errors_name_the_operation() {
    let head = "[card]\nwidth = 100\ndepth = 50\nheight = 50\n";
    let op = |body: &str| {
        format!(
            "{head}[[operation]]\nplane = \"vertical\"\nat = 10\npolygon = [[0,0],[10,0],[10,10]]\n[[operation]]\n{body}\n"
        )
    };
    let err = parse_design(&op(
        "plane = \"vertical\"\nat = 70\npolygon = [[0,0],[10,0],[10,10]]",
    ))
    .unwrap()
    .build()
    .unwrap_err();
    assert!(
        matches!(err, DesignError::Operation { index: 2, .. }),
        "{err}"
    );
    assert!(err.to_string().starts_with("operation 2: "), "{err}");
    let err = parse_design(&op(
        "plane = \"vertical\"\nat = 1\nunits = \"grid\"\npolygon = [[0,0],[1,0],[1,1]]",
    ))
    .unwrap()
    .build()
    .unwrap_err();
    assert_eq!(err, DesignError::NoGrid(2));
    let err = parse_design(&op("plane = \"diagonal\"\nat = 1\npolygon = []")).unwrap_err();
    assert!(
        matches!(err, DesignError::Syntax(_)) && err.to_string().contains("diagonal"),
        "{err}"
    );
    let err = parse_design(&format!("{head}colour = 3\n")).unwrap_err();
    assert!(err.to_string().contains("colour"), "{err}");
}

#[test]
fn replay_names_the_operation_that_broke_the_card() {
    let text = std::fs::read_to_string(example_path("house-door.popup.toml")).unwrap();
    // A wall floating in front of the house, added last: the card breaks at operation 5.
    let bad = format!(
        "{text}\n[[operation]]\nplane = \"vertical\"\nat = 50\npolygon = [[90,10],[110,10],[110,20],[90,20]]\n"
    );
    let replay = parse_design(&bad).unwrap().replay().unwrap();
    assert_eq!(replay.became_invalid_after, Some(5));
    assert_eq!(replay.report.faces(), vec![6]);
    let good = parse_design(&text).unwrap().replay().unwrap();
    assert_eq!(good.became_invalid_after, None);
}

#[test]
fn every_example_pops_up_and_folds_on_its_planes() {
    for name in [
        "house-door.popup.toml",
        "slanted.popup.toml",
        "taj-mahal.popup.toml",
    ] {
        let card = example(name);
        let report = check_popup(&card);
        assert!(report.passed(), "{name}: {:?}", report.problems);
        assert_pattern_condition(&card);
        let cp = crease_pattern(&card).unwrap();
        assert_tiles_sheet(&card, &cp);
        assert_creases_parallel_to_x(&cp);
        assert_faces_on_planes(&card, &cp);
    }
}

#[test]
fn fold_angles_match_the_folded_faces_at_every_opening() {
    let card = example("taj-mahal.popup.toml");
    let cp = crease_pattern(&card).unwrap();
    for opening in [0.0, 30.0, 90.0, 150.0, 180.0] {
        let folded = fold_card(&card, &cp, opening);
        assert_isometric(&cp, &folded.state, &folded.source);
        assert!(assert_fold_angles(&folded.state) > 20);
    }
    // Flat open (opening 180°) is the pattern itself, with Y = −v (eq. 7 at θ = 0).
    let flat = fold_card(&card, &cp, 180.0);
    for (p, v) in flat.state.positions.iter().zip(&flat.source) {
        let q = cp.position(*v);
        assert!(
            (*p - DVec3::new(q.x, -q.y, 0.0)).length() < 1e-9,
            "{p} vs {q}"
        );
    }
}

#[test]
fn voxel_cards_convert_to_the_same_surface() {
    for (name, margin) in [("house.voxel.txt", 0.0), ("tower.voxel.txt", 4.0)] {
        let path = format!("{}/examples/popup/{name}", env!("CARGO_MANIFEST_DIR"));
        let mut vcard = voxel::parse_voxel_card(&std::fs::read_to_string(path).unwrap()).unwrap();
        vcard.set_margin_mm(margin).unwrap();
        let pcard = from_voxel(&vcard).unwrap();
        assert_pattern_condition(&pcard);
        assert_eq!(
            check_popup(&pcard).passed(),
            voxel::check_popup(&vcard).passed()
        );
        assert_same_surface(&vcard, &pcard);
        let (vcp, pcp) = (
            voxel::crease_pattern(&vcard).unwrap(),
            crease_pattern(&pcard).unwrap(),
        );
        for kind in [Assignment::Valley, Assignment::Mountain, Assignment::Cut] {
            let (a, b) = (total_length(&vcp, kind), total_length(&pcp, kind));
            assert!(
                (a - b).abs() < 1e-6,
                "{name} {kind:?}: voxel {a}, polygon {b}"
            );
        }
    }
}

#[test]
fn examples_cut_clean_on_card_stock() {
    for name in [
        "house-door.popup.toml",
        "slanted.popup.toml",
        "taj-mahal.popup.toml",
    ] {
        let cp = crease_pattern(&example(name)).unwrap();
        assert_cuts_clean(name, &cp);
    }
}

/// One random edit: plane kind, t, a polygon on the plane (a rectangle or a slanted
/// quadrilateral), face or opening.
fn edit() -> impl Strategy<Value = (bool, f64, Vec<DVec2>, bool)> {
    (
        any::<bool>(),
        0.0..40.0f64,
        (
            0.0..90.0f64,
            0.0..40.0f64,
            1.0..40.0f64,
            1.0..30.0f64,
            -8.0..8.0f64,
        ),
        any::<bool>(),
    )
        .prop_map(|(vertical, t, (x, y, w, h, skew), opening)| {
            let pts = vec![
                DVec2::new(x, y),
                DVec2::new(x + w, y),
                DVec2::new(x + w + skew, y + h),
                DVec2::new(x + skew * 0.5, y + h),
            ];
            (vertical, t, pts, opening)
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]
    #[test]
    fn random_edits_keep_one_sheet_and_fold_on_the_planes(
        edits in prop::collection::vec(edit(), 1..12)
    ) {
        let mut card = PolygonCard::new(100.0, 40.0, 45.0).unwrap();
        for (vertical, t, pts, opening) in &edits {
            let kind = if *vertical { FaceKind::Vertical } else { FaceKind::Horizontal };
            let r = if *opening {
                card.add_opening(kind, *t, pts)
            } else {
                card.add_face(kind, *t, pts)
            };
            match r {
                Ok(_) | Err(PolygonError::Empty) | Err(PolygonError::BadPlane { .. }) => {}
                Err(e) => panic!("{e}"),
            }
            assert_pattern_condition(&card);
        }
        let cp = crease_pattern(&card).unwrap();
        assert_tiles_sheet(&card, &cp);
        assert_creases_parallel_to_x(&cp);
        assert_faces_on_planes(&card, &cp);
        let folded = fold_card(&card, &cp, 60.0);
        assert_isometric(&cp, &folded.state, &folded.source);
    }
}

fn foldcam(args: &[&str], dir: &std::path::Path) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_foldcam"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("the foldcam binary runs")
}

#[test]
fn cli_writes_pattern_and_previews_and_refuses_invalid_designs() {
    let dir = tempfile::tempdir().unwrap();
    let design = example_path("house-door.popup.toml");
    let o = foldcam(
        &[
            "popup",
            "poly",
            &design,
            "-o",
            "house.svg",
            "--png",
            "house.png",
            "--gif",
            "house.gif",
            "--width",
            "160",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(
        image::open(dir.path().join("house.png")).unwrap().width(),
        160
    );
    assert!(
        std::fs::read(dir.path().join("house.gif"))
            .unwrap()
            .starts_with(b"GIF8")
    );
    let cp = foldcam::formats::load(&dir.path().join("house.svg"))
        .unwrap()
        .pattern;
    assert!(
        cp.edges
            .iter()
            .any(|e| e.assignment == Assignment::Mountain)
    );
    // A floating wall added as operation 5: exit 1, the operation named, nothing written.
    let text = std::fs::read_to_string(&design).unwrap();
    let bad = format!(
        "{text}\n[[operation]]\nplane = \"vertical\"\nat = 50\npolygon = [[90,10],[110,10],[110,20],[90,20]]\n"
    );
    std::fs::write(dir.path().join("bad.popup.toml"), bad).unwrap();
    let o = foldcam(
        &[
            "popup",
            "poly",
            "bad.popup.toml",
            "-o",
            "bad.fold",
            "--png",
            "bad.png",
        ],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(1));
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(
        out.contains("invalid at operation 5") && out.contains("face 6"),
        "{out}"
    );
    assert!(!dir.path().join("bad.fold").exists() && !dir.path().join("bad.png").exists());
    // Bad input: exit 2 with the file and the operation in the message.
    std::fs::write(
        dir.path().join("worse.popup.toml"),
        "[card]\nwidth = 100\ndepth = 50\nheight = 50\n[[operation]]\nplane = \"vertical\"\nat = 99\npolygon = [[0,0],[1,0],[1,1]]\n",
    )
    .unwrap();
    let o = foldcam(
        &["popup", "poly", "worse.popup.toml", "-o", "w.fold"],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("worse.popup.toml: operation 1:"), "{err}");
}

#[test]
fn converted_voxel_cards_with_windows_keep_the_check_result() {
    // The voxel tests' single column of four rows (Fig. 8 of Mitani, Suzuki & Uno (2003)): windows at the bottom
    // (held from the back only), top and bottom (floating), none, one in the middle.
    for (windows, pops) in [
        (&[0, 1][..], false),
        (&[0, 3], false),
        (&[], true),
        (&[1], false),
    ] {
        let mut vcard = VoxelCard::new(3, 4, 8, 5.0).unwrap();
        for z in 0..4 {
            vcard.set_depth(1, z, 2).unwrap();
        }
        for &z in windows {
            vcard.set_hole(1, z, true).unwrap();
        }
        assert_eq!(voxel::check_popup(&vcard).passed(), pops);
        let pcard = from_voxel(&vcard).unwrap();
        assert_pattern_condition(&pcard);
        assert_same_surface(&vcard, &pcard);
        let report = check_popup(&pcard);
        assert_eq!(
            report.passed(),
            pops,
            "windows {windows:?}: {:?}",
            report.problems
        );
        if !pops {
            // The failing face is the column's front at y = 10 mm.
            assert!(
                report.problems.iter().all(|p| p.plane.t_mm() == 10.0),
                "{:?}",
                report.problems
            );
        }
    }
}
