//! Voxel pop-up cards (Mitani, Suzuki & Uno 2003): pattern conditions (eq. 1, 2), Table 1 lines, the pop-up
//! check (§2.6), the editing operations (§2.7, eq. 4) and the open/close transform (eq. 6).

use foldcam::design::popup::voxel::{
    DepthMap, PopupProblem, VoxelCard, VoxelError, VoxelFormatError, card_from_depth_map,
    check_popup, crease_pattern, fold_card, parse_voxel_card,
};
use foldcam::pattern::{Assignment, CreasePattern, Face};
use glam::DVec3;
use proptest::prelude::*;

use crate::support::popup_voxel as support;

use support::*;

#[test]
fn samples_parse_pop_up_and_tile_the_sheet() {
    for name in ["house.voxel.txt", "tower.voxel.txt"] {
        let card = sample(name);
        assert!(card.is_staircase());
        let report = check_popup(&card);
        assert!(report.passed(), "{name}: {:?}", report.problems);
        let cp = crease_pattern(&card).unwrap();
        assert_tiles_sheet(&card, &cp);
        assert_faces_on_voxel_planes(&card, &cp);
    }
}

#[test]
fn window_free_card_lands_on_the_voxel_surface() {
    let mut card = VoxelCard::new(7, 6, 6, 3.0).unwrap();
    card.add(1, 3, 2).unwrap();
    card.add(2, 1, 4).unwrap();
    card.add(4, 4, 0).unwrap();
    card.add(5, 2, 3).unwrap();
    let cp = crease_pattern(&card).unwrap();
    assert_tiles_sheet(&card, &cp);
    assert_faces_on_voxel_planes(&card, &cp);
    assert_faces_on_solid(&card, &cp);
}

#[test]
fn one_block_has_table_1_lines() {
    // A 2-deep, 2-high block on columns 1..3 of 4.
    let mut card = VoxelCard::new(4, 3, 3, 10.0).unwrap();
    card.add(1, 1, 1).unwrap();
    card.add(2, 1, 1).unwrap();
    let cp = crease_pattern(&card).unwrap();
    let count = |a| cp.edges.iter().filter(|e| e.assignment == a).count();
    // Valleys: back/top (v = 2) over the block, base/front (v = −2) under it, and the central
    // fold on columns 0 and 3; one mountain at the front edge (v = 0); two cuts (block sides),
    // each split in two where the central fold of the neighbouring column ends on it.
    assert_eq!(count(Assignment::Mountain), 1);
    assert_eq!(count(Assignment::Valley), 4);
    let cut_len: Vec<f64> = cp
        .edge_ids()
        .filter(|&e| cp.edges[e.index()].assignment == Assignment::Cut)
        .map(|e| cp.edge_length(e))
        .collect();
    assert_eq!(cut_len, vec![20.0; 4]);
}

#[test]
fn a_long_crease_is_one_edge() {
    let mut card = VoxelCard::new(1000, 4, 4, 1.0).unwrap();
    for x in 0..1000 {
        card.add(x, 2, 2).unwrap();
    }
    let cp = crease_pattern(&card).unwrap();
    let folds: Vec<f64> = cp
        .edge_ids()
        .filter(|&e| cp.edges[e.index()].assignment.is_fold())
        .map(|e| cp.edge_length(e))
        .collect();
    assert_eq!(folds, vec![1000.0; 3]);
    assert_eq!(
        cp.edges.len(),
        3 + 4 + 6,
        "3 folds, 4 outline sides split by 3 folds each end"
    );
}

#[test]
fn block_held_from_the_back_only_is_rejected() {
    // Fig. 8 (b): the two lowest rows are windows, so the front hangs from the top only.
    let card = column_card(&[2, 2, 2, 2], &[0, 1]);
    let report = check_popup(&card);
    let named: Vec<_> = report
        .problems
        .iter()
        .map(|p| (p.x, p.depth, p.z, p.problem))
        .collect();
    let held = PopupProblem::HeldFromBackOnly;
    assert_eq!(named, vec![(1, 2, 2, held), (1, 2, 3, held)]);
}

#[test]
fn floating_block_is_rejected() {
    // Fig. 8 (a): windows on the top and bottom rows cut the middle of the front loose.
    let card = column_card(&[2, 2, 2, 2], &[0, 3]);
    let report = check_popup(&card);
    let named: Vec<_> = report
        .problems
        .iter()
        .map(|p| (p.x, p.z, p.problem))
        .collect();
    let f = PopupProblem::Floating;
    assert_eq!(named, vec![(1, 1, f), (1, 2, f)]);
    let text = report.problems[0].to_string();
    assert_eq!(
        text,
        "front face of cell (1, 1, 1) floats: cut off from both sheets"
    );
}

/// Three columns one cell deep and four rows high; column 1's rows 0–2 are windows. By §2.3 its
/// row 0 shows on the base and rows 1–2 on the back sheet, between the solid fronts of
/// columns 0 and 2 and under the front of row 3: a strip of back sheet cut free on three
/// sides and hinged only at the central fold.
pub(crate) fn strip_card(margin: f64) -> VoxelCard {
    let mut card = VoxelCard::new(3, 2, 6, 5.0).unwrap();
    card.set_margin_mm(margin).unwrap();
    for x in 0..3 {
        card.add(x, 0, 3).unwrap();
    }
    for z in 0..3 {
        card.set_hole(1, z, true).unwrap();
    }
    card
}

#[test]
fn a_back_sheet_strip_hinged_only_at_the_central_fold_is_rejected() {
    for margin in [0.0, 4.0] {
        let card = strip_card(margin);
        let report = check_popup(&card);
        let named: Vec<_> = report
            .problems
            .iter()
            .map(|p| (p.x, p.depth, p.z, p.problem))
            .collect();
        let base_only = PopupProblem::HeldFromBaseOnly;
        assert_eq!(named, vec![(1, 0, 0, base_only), (1, 0, 1, base_only)]);
        assert_eq!(
            report.problems[1].describe_at(card.cell_mm()),
            "back-sheet cell (x 1, z 1), part of a piece cut free of the back sheet, is held \
             from the base sheet only (on the pattern x 5.0–10.0 mm from the cells' left edge, \
             5.0–10.0 mm above the central fold)"
        );
    }
    // Without the windows the column is solid and the card pops up.
    let mut solid = strip_card(0.0);
    for z in 0..3 {
        solid.set_hole(1, z, false).unwrap();
    }
    assert!(check_popup(&solid).passed());
}

#[test]
fn back_sheet_paper_beside_a_margin_is_the_back_sheet() {
    // The same window strip in the first column: cut free of the cells' back sheet but joined
    // to the margin's, so it is the back sheet itself when the card has a margin.
    let mut card = VoxelCard::new(3, 2, 6, 5.0).unwrap();
    for x in 0..3 {
        card.add(x, 0, 3).unwrap();
    }
    for z in 0..3 {
        card.set_hole(0, z, true).unwrap();
    }
    assert!(!check_popup(&card).passed());
    card.set_margin_mm(4.0).unwrap();
    assert!(check_popup(&card).passed(), "{:?}", check_popup(&card));
}

#[test]
fn same_block_without_windows_passes() {
    assert!(check_popup(&column_card(&[2, 2, 2, 2], &[])).passed());
    // One column with a window is split in two, but a window between neighbours is held.
    assert!(!check_popup(&column_card(&[2, 2, 2, 2], &[1])).passed());
    let mut wide = VoxelCard::new(5, 4, 8, 5.0).unwrap();
    for x in 1..4 {
        wide.add(x, 1, 3).unwrap();
    }
    wide.set_hole(2, 1, true).unwrap();
    assert!(check_popup(&wide).passed());
}

#[test]
fn transform_at_standing_flat_and_closed() {
    let card = sample("house.voxel.txt");
    let cp = crease_pattern(&card).unwrap();
    let s = card.cell_mm();
    let standing = fold_card(&card, &cp, 90.0);
    let flat = fold_card(&card, &cp, 180.0);
    let closed = fold_card(&card, &cp, 0.0);
    for (i, v) in flat.source.iter().enumerate() {
        let p = cp.position(*v);
        let f = flat.state.positions[i];
        assert!(
            (f - DVec3::new(p.x, -p.y, 0.0)).length() < 1e-9,
            "flat {f} vs {p}"
        );
        let q = standing.state.positions[i];
        assert!(q.y >= -1e-9 && q.z >= -1e-9 && (q.z - q.y - p.y).abs() < 1e-9);
        let c = closed.state.positions[i];
        assert!(c.z.abs() < 1e-9 && (c.y - q.y - q.z).abs() < 1e-9);
        let m = card.margin_mm() + 1e-9;
        assert!(q.y <= card.ny() as f64 * s + m && q.z <= card.nz() as f64 * s + m);
    }
}

#[test]
fn every_angle_keeps_edge_lengths() {
    let card = sample("tower.voxel.txt");
    let cp = crease_pattern(&card).unwrap();
    for angle in [0.0, 15.0, 60.0, 90.0, 133.0, 180.0] {
        let folded = fold_card(&card, &cp, angle);
        assert!(!folded.state.edges.is_empty());
        for e in &folded.state.edges {
            let [a, b] = e.vertices.map(|v| v.index());
            let len3 = folded.state.positions[a].distance(folded.state.positions[b]);
            let len2 = cp
                .position(folded.source[a])
                .distance(cp.position(folded.source[b]));
            assert!(
                (len3 - len2).abs() < 1e-9,
                "angle {angle}: {len3} vs {len2}"
            );
        }
    }
}

#[test]
fn parse_errors_name_the_line() {
    let bad_token = "cell_mm 5\ndepth 4\nheight 4\nrows\n0 1 0\n0 x 0\n";
    let err = parse_voxel_card(bad_token).unwrap_err();
    assert!(
        matches!(err, VoxelFormatError::Syntax { line: 6, .. }),
        "{err}"
    );
    let not_staircase = "cell_mm 5\ndepth 4\nheight 4\nrows\n0 3 0\n0 1 0\n";
    let err = parse_voxel_card(not_staircase).unwrap_err();
    assert!(
        matches!(err, VoxelFormatError::Card { line: 5, .. }),
        "{err}"
    );
    let too_deep = "cell_mm 5\ndepth 2\nheight 4\nrows\n0 3 0\n";
    assert!(matches!(
        parse_voxel_card(too_deep),
        Err(VoxelFormatError::Card { line: 5, .. })
    ));
    let ragged = "cell_mm 5\ndepth 4\nheight 4\nrows\n0 1\n0 1 0\n"; // line 6 is off
    assert!(matches!(
        parse_voxel_card(ragged),
        Err(VoxelFormatError::Syntax { line: 6, .. })
    ));
    let no_cell = "depth 4\nheight 4\nrows\n0\n";
    assert_eq!(
        parse_voxel_card(no_cell),
        Err(VoxelFormatError::MissingKey("cell_mm"))
    );
    let bad_key = "cell_mm 5\nwidth 3\n";
    assert!(matches!(
        parse_voxel_card(bad_key),
        Err(VoxelFormatError::Syntax { line: 2, .. })
    ));
    assert!(parse_voxel_card("cell_mm -1\ndepth 4\nheight 4\nrows\n0\n").is_err());
}

#[test]
fn big_card_fits() {
    // 2000 × 1000 × 1000 cells: the model holds one depth and one flag per (x, z) row.
    let mut card = VoxelCard::new(2000, 1000, 1000, 0.5).unwrap();
    card.add(1999, 999, 999).unwrap();
    assert!(card.cell(1999, 0, 0) && card.cell(1999, 999, 999) && !card.cell(1998, 0, 0));
}

proptest! {
    #[test]
    fn edits_keep_the_staircase(ops in prop::collection::vec((any::<bool>(), 0..4usize, 0..6usize, 0..5usize), 1..40)) {
        let mut card = VoxelCard::new(4, 6, 5, 1.0).unwrap();
        for (add, x, y, z) in ops {
            if add {
                card.add(x, y, z).unwrap();
                prop_assert!(card.cell(x, y, z));
            } else {
                card.delete(x, y, z).unwrap();
                prop_assert!(!card.cell(x, y, z));
            }
            prop_assert!(card.is_staircase());
            // Eq. 4 cell by cell.
            for (cx, cy, cz) in itertools_cells(&card) {
                if card.cell(cx, cy, cz) {
                    prop_assert!(cy == 0 || card.cell(cx, cy - 1, cz));
                    prop_assert!(cz == 0 || card.cell(cx, cy, cz - 1));
                }
            }
        }
        prop_assert!(card.add(4, 0, 0).is_err() && card.delete(0, 6, 0).is_err());
    }
}

fn itertools_cells(card: &VoxelCard) -> Vec<(usize, usize, usize)> {
    let mut out = Vec::new();
    for x in 0..card.nx() {
        for y in 0..card.ny() {
            for z in 0..card.nz() {
                out.push((x, y, z));
            }
        }
    }
    out
}

#[test]
fn depth_map_becomes_a_staircase_by_eq_7() {
    // 3 × 3 pixels, top row first: a bump high in column 1 fills the rows below it (eq. 7).
    let max = u16::MAX;
    let levels = [0, max, 0, 0, 0, max / 2, 0, 0, 0];
    let map = DepthMap {
        width: 3,
        height: 3,
        levels: &levels,
    };
    let card = card_from_depth_map(map, 4, 2.0).unwrap();
    assert!(card.is_staircase());
    assert_eq!(
        (0..3).map(|z| card.depth(1, z)).collect::<Vec<_>>(),
        vec![4, 4, 4]
    );
    assert_eq!(
        (0..3).map(|z| card.depth(2, z)).collect::<Vec<_>>(),
        vec![2, 2, 0]
    );
    assert_eq!(card.depth(0, 0), 0);
    let short = DepthMap {
        width: 3,
        height: 3,
        levels: &levels[..8],
    };
    let err = card_from_depth_map(short, 4, 2.0).unwrap_err();
    assert_eq!(
        err,
        VoxelError::MapSize {
            expected: 9,
            got: 8
        }
    );
}

/// A random small card: edits per §2.7 and random windows.
fn random_card(
    ops: &[(bool, usize, usize, usize)],
    windows: &[(usize, usize)],
    tops: &[(usize, usize)],
    margin: f64,
) -> VoxelCard {
    let mut card = VoxelCard::new(5, 5, 5, 2.5).unwrap();
    card.set_margin_mm(margin).unwrap();
    for &(add, x, y, z) in ops {
        let edit = if add {
            VoxelCard::add
        } else {
            VoxelCard::delete
        };
        edit(&mut card, x, y, z).unwrap();
    }
    for &(x, z) in windows {
        card.set_hole(x, z, true).unwrap();
    }
    for &(x, z) in tops {
        card.set_top_omitted(x, z, true).unwrap();
    }
    card
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    #[test]
    fn random_cards_give_one_sheet_that_folds_isometrically(
        ops in prop::collection::vec((any::<bool>(), 0..5usize, 0..5usize, 0..5usize), 1..12),
        windows in prop::collection::vec((0..5usize, 0..5usize), 0..4),
        tops in prop::collection::vec((0..5usize, 0..5usize), 0..3),
        margin in prop::sample::select(vec![0.0, 1.0, 7.5]),
    ) {
        let card = random_card(&ops, &windows, &tops, margin);
        let cp = crease_pattern(&card).unwrap();
        assert_tiles_sheet(&card, &cp);
        assert_faces_on_voxel_planes(&card, &cp);
        if windows.is_empty() && tops.is_empty() {
            assert_faces_on_solid_unless_flat(&card, &cp);
        }
        for angle in [0.0, 45.0, 120.0] {
            let folded = fold_card(&card, &cp, angle);
            for e in &folded.state.edges {
                let [a, b] = e.vertices.map(|v| v.index());
                let len3 = folded.state.positions[a].distance(folded.state.positions[b]);
                let len2 = cp.position(folded.source[a]).distance(cp.position(folded.source[b]));
                prop_assert!((len3 - len2).abs() < 1e-9);
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]
    /// The run-based check equals the cell-by-cell floods of §2.6, cell for cell.
    #[test]
    fn pop_up_check_matches_the_cell_floods(
        ops in prop::collection::vec((any::<bool>(), 0..5usize, 0..5usize, 0..5usize), 1..14),
        windows in prop::collection::vec((0..5usize, 0..5usize), 0..6),
        tops in prop::collection::vec((0..5usize, 0..5usize), 0..4),
        margin in prop::sample::select(vec![0.0, 2.0]),
    ) {
        let card = random_card(&ops, &windows, &tops, margin);
        prop_assert_eq!(check_popup(&card).problems, cell_flood_problems(&card));
    }
}

fn assert_faces_on_solid_unless_flat(card: &VoxelCard, cp: &CreasePattern) {
    let any_block = (0..card.nx()).any(|x| card.depth(x, 0) > 0);
    if any_block {
        assert_faces_on_solid(card, cp);
    }
}

#[test]
fn margins_continue_the_back_and_base_sheets() {
    let mut card = VoxelCard::new(4, 3, 3, 10.0).unwrap();
    card.set_margin_mm(5.0).unwrap();
    card.add(1, 1, 2).unwrap(); // reaches the top edge of the cells
    card.add(2, 1, 1).unwrap();
    let cp = crease_pattern(&card).unwrap();
    assert_tiles_sheet(&card, &cp);
    assert_eq!(card.sheet_mm(), (50.0, 70.0));
    let valleys = |y: f64| {
        let mut spans: Vec<(f64, f64)> = cp
            .edge_ids()
            .filter(|&e| cp.edges[e.index()].assignment == Assignment::Valley)
            .map(|e| cp.segment(e))
            .filter(|(a, b)| a.y == y && b.y == y)
            .map(|(a, b)| (a.x.min(b.x), a.x.max(b.x)))
            .collect();
        spans.sort_by(|p, q| p.0.total_cmp(&q.0));
        spans
    };
    // The central fold runs through the side margins; the block on column 1 meets the top
    // margin (the back sheet) in a valley at the cells' top edge v = 30.
    assert_eq!(valleys(0.0), vec![(-5.0, 10.0), (30.0, 45.0)]);
    assert_eq!(valleys(30.0), vec![(10.0, 20.0)]);
    let f = fold_card(&card, &cp, 90.0);
    let top = f.state.positions.iter().map(|p| p.z).fold(0.0, f64::max);
    assert!(
        (top - 35.0).abs() < 1e-9,
        "top margin stands up to 35 mm, got {top}"
    );
    let text = "cell_mm 5\ndepth 4\nheight 4\nmargin_mm -2\nrows\n0\n";
    let err = parse_voxel_card(text).unwrap_err();
    assert!(
        matches!(err, VoxelFormatError::Card { line: 4, .. }),
        "{err}"
    );
}

/// Unit normal of a folded face (Newell's method on its outer ring).
fn normal(positions: &[DVec3], f: &Face) -> DVec3 {
    let ring: Vec<DVec3> = f.outer.iter().map(|v| positions[v.index()]).collect();
    let n = (0..ring.len()).fold(DVec3::ZERO, |n, i| {
        n + ring[i].cross(ring[(i + 1) % ring.len()])
    });
    n.normalize()
}

#[test]
fn fold_angles_match_the_folded_faces() {
    let card = sample("tower.voxel.txt");
    let cp = crease_pattern(&card).unwrap();
    for opening in [10.0, 90.0, 150.0] {
        let folded = fold_card(&card, &cp, opening);
        let faces = folded.state.faces.as_ref().unwrap();
        let mut by_edge = std::collections::HashMap::<_, Vec<usize>>::new();
        for (i, f) in faces.iter().enumerate() {
            for ring in std::iter::once(&f.outer).chain(&f.holes) {
                for k in 0..ring.len() {
                    let (a, b) = (ring[k], ring[(k + 1) % ring.len()]);
                    by_edge.entry((a.min(b), a.max(b))).or_default().push(i);
                }
            }
        }
        let mut checked = 0;
        for e in folded.state.edges.iter().filter(|e| e.assignment.is_fold()) {
            let [a, b] = e.vertices;
            let pair = &by_edge[&(a.min(b), a.max(b))];
            assert_eq!(pair.len(), 2, "a fold joins two faces: {e:?}");
            let (n1, n2) = (
                normal(&folded.state.positions, &faces[pair[0]]),
                normal(&folded.state.positions, &faces[pair[1]]),
            );
            let turn = n1.dot(n2).clamp(-1.0, 1.0).acos().to_degrees();
            let want = e.fold_angle.unwrap();
            assert!(
                (turn - want.abs()).abs() < 1e-6,
                "opening {opening}: {turn} vs {want}"
            );
            assert_eq!(
                want.signum(),
                if e.assignment == Assignment::Valley {
                    1.0
                } else {
                    -1.0
                }
            );
            checked += 1;
        }
        assert!(checked > 10);
    }
}

/// Regression (proptest): a 2 × 2 block whose face centre lies on a grid line once fooled
/// the face-on-solid check's sample point.
#[test]
fn regression_block_with_face_centre_on_grid_line() {
    let card = random_card(&[(false, 0, 0, 0), (true, 1, 1, 1)], &[], &[], 0.0);
    let cp = crease_pattern(&card).unwrap();
    assert_tiles_sheet(&card, &cp);
    assert_faces_on_solid(&card, &cp);
}
