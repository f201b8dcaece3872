//! Voxel cards from depth fields and meshes (Mitani, Suzuki & Uno 2003, §3): depth from the front, bump removal
//! (§3.2 a), eq. 7, windows kept only where the card pops up (§3.2 c), thin top faces left
//! out (§3.3), and the text format's round trip.

use std::path::PathBuf;

use foldcam::design::popup::voxel::{
    ConvertOptions, DepthField, MeshPlacement, PlacementError, UpAxis, VoxelCard, card_from_depths,
    check_popup, crease_pattern, depth_field_from_mesh, format_voxel_card, parse_voxel_card,
};
use foldcam::mesh::{PolyMesh, parse_stl, read_mesh};
use glam::DVec3;

use crate::support::popup_voxel as support;

use support::*;

fn building() -> PolyMesh {
    read_mesh(&PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/popup/building.obj"))
        .expect("bundled building mesh")
}

/// A field from columns given as (height in rows, depth) pairs, `ny` deep, `nz` high.
fn field(columns: &[(usize, u16)], ny: usize, nz: usize) -> DepthField {
    let mut depths = vec![0; columns.len() * nz];
    for (x, &(h, d)) in columns.iter().enumerate() {
        for z in 0..h {
            depths[x * nz + z] = d;
        }
    }
    DepthField {
        nx: columns.len(),
        ny,
        nz,
        depths,
    }
}

#[test]
fn the_building_mesh_becomes_a_card_that_pops_up_and_tiles_its_sheet() {
    let mesh = building();
    let (field, cell) = depth_field_from_mesh(&mesh, &MeshPlacement::default()).unwrap();
    let (lo, hi) = mesh.bounds();
    assert_eq!(field.nx, 80);
    assert!((cell - (hi.x - lo.x) / 80.0).abs() < 1e-12);
    assert_eq!(field.nz, ((hi.z - lo.z) / cell).ceil() as usize + 1);
    // One cell of base in front of the nearest point.
    assert_eq!(field.ny, ((0.5 * (hi.y - lo.y)) / cell).ceil() as usize + 1);
    assert!(field.depths.iter().all(|&d| (d as usize) < field.ny));
    let (card, report) = card_from_depths(&field, 2.0, &ConvertOptions::default()).unwrap();
    assert!(card.is_staircase());
    assert!(check_popup(&card).passed());
    assert!(
        report.added_cells > 0 && report.window_rows > 0,
        "{report:?}"
    );
    assert!(report.tops_omitted > 0, "{report:?}");
    let cp = crease_pattern(&card).unwrap();
    assert_tiles_sheet(&card, &cp);
    assert_faces_on_voxel_planes(&card, &cp);
}

#[test]
fn the_front_view_depth_is_the_nearest_surface() {
    // A box 4 wide, 2 deep (y from 1 to 3), 2 high, in front of a plate at y = 5 that is 4
    // wide and 4 high: the front half of the depth (5 − 1 = 4) stands out.
    let mut positions = Vec::new();
    let mut faces = Vec::new();
    let mut quad = |pts: [[f64; 3]; 4]| {
        let b = positions.len() as u32;
        positions.extend(pts.map(DVec3::from_array));
        faces.push(vec![b, b + 1, b + 2, b + 3]);
    };
    quad([
        [0.0, 1.0, 0.0],
        [4.0, 1.0, 0.0],
        [4.0, 1.0, 2.0],
        [0.0, 1.0, 2.0],
    ]);
    quad([
        [0.0, 5.0, 0.0],
        [4.0, 5.0, 0.0],
        [4.0, 5.0, 4.0],
        [0.0, 5.0, 4.0],
    ]);
    let mesh = PolyMesh::new(positions, faces).unwrap();
    let placement = MeshPlacement {
        up: UpAxis::Z,
        resolution: 8,
        keep_depth: 1.0,
    };
    let (f, cell) = depth_field_from_mesh(&mesh, &placement).unwrap();
    assert_eq!((f.nx, f.ny, f.nz), (8, 9, 9));
    assert_eq!(cell, 0.5);
    for x in 0..8 {
        for z in 0..9 {
            let want = if z < 4 { 8 } else { 0 };
            assert_eq!(f.depth(x, z), want, "cell ({x}, {z})");
        }
    }
    // The same mesh with y up and the viewer at +z sees the plate edge-on: nothing but edges.
    let yup = mesh.map_positions(|p| DVec3::new(p.x, p.z, -p.y)).unwrap();
    let (g, _) = depth_field_from_mesh(
        &yup,
        &MeshPlacement {
            up: UpAxis::Y,
            ..placement
        },
    )
    .unwrap();
    assert_eq!(g, f, "y-up input rotated back gives the same field");
}

#[test]
fn stl_and_obj_give_the_same_card() {
    let mesh = building();
    let triangles: Vec<stl_io::Triangle> = mesh
        .triangles()
        .map(|t| stl_io::Triangle {
            normal: stl_io::Normal::new([0.0; 3]),
            vertices: t.map(|p| stl_io::Vertex::new([p.x as f32, p.y as f32, p.z as f32])),
        })
        .collect();
    let mut bytes = Vec::new();
    stl_io::write_stl(&mut bytes, triangles.iter()).unwrap();
    let stl = parse_stl(&bytes).unwrap();
    let placement = MeshPlacement::default();
    let a = depth_field_from_mesh(&mesh, &placement).unwrap().0;
    let b = depth_field_from_mesh(&stl, &placement).unwrap().0;
    let differing = a
        .depths
        .iter()
        .zip(&b.depths)
        .filter(|(p, q)| p != q)
        .count();
    // f32 storage may move a sample that lies exactly on an edge; nothing more.
    assert!(differing * 200 < a.depths.len(), "{differing} cells differ");
}

#[test]
fn bad_placements_are_refused() {
    let flat = PolyMesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![vec![0, 1, 2]]).unwrap();
    let err = depth_field_from_mesh(&flat, &MeshPlacement::default()).unwrap_err();
    assert_eq!(err, PlacementError::Flat);
    let mesh = building();
    for (resolution, keep_depth) in [(0, 0.5), (80, 0.0), (80, 1.5), (80, f64::NAN)] {
        let p = MeshPlacement {
            resolution,
            keep_depth,
            ..MeshPlacement::default()
        };
        assert!(matches!(
            depth_field_from_mesh(&mesh, &p),
            Err(PlacementError::BadPlacement(..))
        ));
    }
    let too_big = MeshPlacement {
        resolution: 20_000,
        ..MeshPlacement::default()
    };
    assert!(matches!(
        depth_field_from_mesh(&mesh, &too_big),
        Err(PlacementError::TooLarge { .. })
    ));
    let f = field(&[(2, 2)], 4, 4);
    let even = ConvertOptions {
        element: 2,
        ..ConvertOptions::default()
    };
    assert!(card_from_depths(&f, 1.0, &even).is_err());
}

#[test]
fn eq_7_fills_under_an_overhang_and_a_window_opens_where_pillars_hold_it() {
    // Columns: a pillar, three columns with only a roof slab (rows 4..6) standing out 5
    // cells, a pillar. Eq. 7 fills rows 0..4 of the middle columns to depth 5; windows there
    // keep the card valid because the pillars hold the roof from the base.
    let mut f = field(&[(6, 5), (6, 5), (6, 5), (6, 5), (6, 5)], 8, 8);
    for x in 1..4 {
        for z in 0..4 {
            f.depths[x * 8 + z] = 0;
        }
    }
    let options = ConvertOptions {
        element: 1,
        thin_top: 0,
        ..ConvertOptions::default()
    };
    let (card, report) = card_from_depths(&f, 1.0, &options).unwrap();
    assert_eq!(report.added_cells, 3 * 4 * 5);
    assert_eq!(report.filled_rows, 12);
    assert_eq!(report.window_rows, 12);
    for x in 0..5 {
        for z in 0..6 {
            assert_eq!(card.depth(x, z), 5);
            assert_eq!(
                card.is_hole(x, z),
                (1..4).contains(&x) && z < 4,
                "({x}, {z})"
            );
        }
    }
    assert!(check_popup(&card).passed());
}

#[test]
fn a_balcony_without_pillars_keeps_one_supporting_column() {
    // A wall 2 cells out, 8 rows high, with a balcony 5 cells out at rows 5..7 over all four
    // columns. Windows under the whole balcony would leave it held from the back only.
    let mut f = field(&[(8, 2); 4], 8, 9);
    for x in 0..4 {
        for z in 5..7 {
            f.depths[x * 9 + z] = 5;
        }
    }
    let options = ConvertOptions {
        element: 1,
        thin_top: 0,
        ..ConvertOptions::default()
    };
    let (card, report) = card_from_depths(&f, 1.0, &options).unwrap();
    assert!(check_popup(&card).passed());
    let open: Vec<bool> = (0..4).map(|x| card.is_hole(x, 0)).collect();
    assert_eq!(open.iter().filter(|&&o| !o).count(), 1, "{open:?}");
    assert_eq!(report.window_rows, 3 * 5);
    // Windowing every column is exactly what the check refuses.
    let mut all = card.clone();
    for x in 0..4 {
        for z in 0..5 {
            all.set_hole(x, z, true).unwrap();
        }
    }
    assert!(!check_popup(&all).passed());
}

#[test]
fn window_gap_leaves_a_wall_behind_an_eave_solid() {
    // A wall 4 cells out under an eave 5 cells out: eq. 7 adds one cell per row.
    let mut f = field(&[(8, 4); 3], 12, 10);
    for x in 0..3 {
        f.depths[x * 10 + 7] = 5;
    }
    let paper = ConvertOptions {
        element: 1,
        thin_top: 0,
        window_gap: 0.0,
        ..ConvertOptions::default()
    };
    let (_, as_paper) = card_from_depths(&f, 1.0, &paper).unwrap();
    assert_eq!(as_paper.window_candidates, 21);
    let ours = ConvertOptions {
        window_gap: 0.25,
        ..paper
    };
    let (card, report) = card_from_depths(&f, 1.0, &ours).unwrap();
    assert_eq!(report.filled_rows, 21);
    assert_eq!(report.window_candidates, 0);
    assert!((0..3).all(|x| (0..8).all(|z| !card.is_hole(x, z))));
}

#[test]
fn thin_tops_go_except_the_tallest_support_as_in_fig_14() {
    // Front view: columns a..d stepping down one row each (tops one column wide), all at the
    // same depth, then two columns of a wide block.
    let f = field(&[(8, 3), (7, 3), (6, 3), (5, 3), (3, 5), (3, 5)], 8, 10);
    let options = ConvertOptions {
        element: 1,
        windows: false,
        thin_top: 1,
        ..ConvertOptions::default()
    };
    let (card, report) = card_from_depths(&f, 1.0, &options).unwrap();
    assert_eq!(
        report.thin_tops, 4,
        "the wide block's top is two columns wide"
    );
    assert_eq!(report.tops_omitted, 3);
    assert!(
        !card.is_top_omitted(0, 7),
        "a, the tallest, stays as the support"
    );
    for (x, z) in [(1, 6), (2, 5), (3, 4)] {
        assert!(card.is_top_omitted(x, z), "column {x}");
    }
    assert!(check_popup(&card).passed());
    let cp = crease_pattern(&card).unwrap();
    assert_tiles_sheet(&card, &cp);
    assert_faces_on_voxel_planes(&card, &cp);
    // Leaving out a's top too would make the whole front face hang from the base only.
    let mut all = card.clone();
    all.set_top_omitted(0, 7, true).unwrap();
    assert!(!check_popup(&all).passed());
}

#[test]
fn small_bumps_are_removed_before_eq_7() {
    // A wall 4 out with a one-row ledge 6 out at row 3 and a one-row notch at row 6.
    let mut f = field(&[(10, 4); 3], 10, 12);
    for x in 0..3 {
        f.depths[x * 12 + 3] = 6;
        f.depths[x * 12 + 6] = 2;
    }
    let smooth = ConvertOptions {
        element: 3,
        windows: false,
        thin_top: 0,
        ..ConvertOptions::default()
    };
    let (card, report) = card_from_depths(&f, 1.0, &smooth).unwrap();
    assert_eq!(report.smoothed_cells, 3 * (2 + 2));
    assert!((0..3).all(|x| (0..10).all(|z| card.depth(x, z) == 4)));
    // Without it, eq. 7 fills below the ledge (3 rows by 2) and the notch (1 row by 2).
    let (raw, raw_report) = card_from_depths(&f, 1.0, &ConvertOptions::EQ7_ONLY).unwrap();
    assert_eq!(raw.depth(0, 0), 6);
    assert_eq!(raw_report.added_cells, 3 * (3 * 2 + 2));
}

#[test]
fn the_text_format_round_trips_windows_and_left_out_tops() {
    let mesh = building();
    let (field, _) = depth_field_from_mesh(&mesh, &MeshPlacement::default()).unwrap();
    let (mut card, _) = card_from_depths(&field, 2.0, &ConvertOptions::default()).unwrap();
    card.set_margin_mm(7.5).unwrap();
    let text = format_voxel_card(&card);
    let back: VoxelCard = parse_voxel_card(&text).unwrap();
    assert_eq!(back, card);
    assert!(parse_voxel_card(&text.replace(" 0 ", " 0ww ")).is_err());
}
