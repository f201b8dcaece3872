//! The 3D preview of folded states: shading, painter's order, outlines, holes, GIF frames
//! and input errors.

use crate::render3d_common;

use foldcam::pattern::{Face, FaceId, FoldedState, VertexId};
use foldcam::render::{RenderError, View3d, render_folded_png, render_folded_rgba, render_gif};
use glam::DVec3;
use image::codecs::gif::GifDecoder;
use image::{AnimationDecoder, Rgba, RgbaImage};
use render3d_common::*;

use foldcam::pattern::Assignment::{Mountain as M, Valley as V};

#[test]
fn l_fold_png_has_the_size_and_two_differently_shaded_faces() {
    let state = l_fold(90.0, V);
    let view = View3d {
        height: Some(300),
        ..View3d::with_width(400)
    };
    let png = render_folded_png(&state, &view).expect("png");
    save("render3d_l_fold.png", &png);
    let img = image::load_from_memory(&png).expect("decodes").to_rgba8();
    assert_eq!(img.dimensions(), (400, 300));
    let floor = *img.get_pixel_at(to_px(&view, &img, &state.positions, centroid(&state, 0)));
    let wall = *img.get_pixel_at(to_px(&view, &img, &state.positions, centroid(&state, 1)));
    assert_ne!(floor, WHITE);
    assert_ne!(wall, WHITE);
    assert_ne!(floor, wall, "the two faces are lit differently");
    let corner = *img.get_pixel(2, 2);
    assert_eq!(corner, WHITE, "the margin shows the background");
}

#[test]
fn the_crease_is_drawn_in_its_assignments_colour() {
    let view = View3d::with_width(300);
    let mid = DVec3::new(50.0, 50.0, 0.0);
    for (kind, colour_of_kind, other) in [
        (
            V,
            is_blue as fn(Rgba<u8>) -> bool,
            is_red as fn(Rgba<u8>) -> bool,
        ),
        (M, is_red, is_blue),
    ] {
        let state = l_fold(90.0, kind);
        let img = render_folded_rgba(&state, &view).expect("rgba");
        let at = to_px(&view, &img, &state.positions, mid);
        assert!(near(&img, at, 2, colour_of_kind), "{kind:?} crease colour");
        assert!(
            !near(&img, at, 2, other),
            "{kind:?} crease has no other colour"
        );
        let plain = View3d {
            outline: false,
            ..view.clone()
        };
        let img = render_folded_rgba(&state, &plain).expect("rgba");
        assert!(!near(&img, at, 2, colour_of_kind), "no outline, no crease");
    }
}

#[test]
fn painters_order_lets_the_near_face_hide_the_far_one() {
    let view = View3d {
        azimuth_deg: 0.0,
        elevation_deg: 0.0,
        outline: false,
        height: Some(200),
        ..View3d::with_width(200)
    };
    for near_first in [true, false] {
        let state = two_squares(near_first);
        let img = render_folded_rgba(&state, &view).expect("rgba");
        let px = |p: DVec3| *img.get_pixel_at(to_px(&view, &img, &state.positions, p));
        let near_only = px(DVec3::new(5.0, 0.0, 5.0));
        let far_only = px(DVec3::new(25.0, 50.0, 25.0));
        let overlap = px(DVec3::new(15.0, 0.0, 15.0));
        assert_ne!(near_only, far_only, "front and back sides differ");
        assert_ne!(far_only, WHITE);
        assert_eq!(
            overlap, near_only,
            "near face wins (near_first = {near_first})"
        );
    }
}

#[test]
fn holes_show_the_background() {
    let mut state = FoldedState::default();
    for (x, y) in [(0.0, 0.0), (90.0, 0.0), (90.0, 90.0), (0.0, 90.0)] {
        state.positions.push(DVec3::new(x, y, 0.0));
    }
    for (x, y) in [(30.0, 30.0), (30.0, 60.0), (60.0, 60.0), (60.0, 30.0)] {
        state.positions.push(DVec3::new(x, y, 0.0));
    }
    state.faces = Some(vec![Face {
        outer: ids(&[0, 1, 2, 3]),
        holes: vec![ids(&[4, 5, 6, 7])],
    }]);
    let view = View3d::with_width(200);
    let img = render_folded_rgba(&state, &view).expect("rgba");
    let px = |p: DVec3| *img.get_pixel_at(to_px(&view, &img, &state.positions, p));
    assert_eq!(px(DVec3::new(45.0, 45.0, 0.0)), WHITE);
    assert_ne!(px(DVec3::new(15.0, 45.0, 0.0)), WHITE);
}

#[test]
fn accordion_renders_every_panel() {
    let state = accordion(3, 90.0);
    let png = render_folded_png(&state, &View3d::with_width(400)).expect("png");
    save("render3d_accordion.png", &png);
    // From higher up the falling panel shows its front too.
    let view = View3d {
        elevation_deg: 60.0,
        ..View3d::with_width(400)
    };
    let png = render_folded_png(&state, &view).expect("png");
    save("render3d_accordion_above.png", &png);
    let img = image::load_from_memory(&png).expect("decodes").to_rgba8();
    let colours: Vec<Rgba<u8>> = (0..3)
        .map(|f| *img.get_pixel_at(to_px(&view, &img, &state.positions, centroid(&state, f))))
        .collect();
    assert!(colours.iter().all(|&c| c != WHITE));
    assert_ne!(
        colours[0], colours[1],
        "rising and falling panels are lit differently"
    );
    assert_eq!(colours[0], colours[2], "parallel panels share a shade");
}

fn decode_gif(bytes: &[u8]) -> Vec<RgbaImage> {
    let decoder = GifDecoder::new(std::io::Cursor::new(bytes)).expect("gif header");
    let frames = decoder.into_frames().collect_frames().expect("gif frames");
    frames.into_iter().map(|f| f.into_buffer()).collect()
}

#[test]
fn gif_has_one_frame_per_state_with_one_framing() {
    let states: Vec<FoldedState> = (0..5).map(|i| l_fold(f64::from(i) * 30.0, V)).collect();
    let view = View3d::with_width(240);
    let gif = render_gif(&states, &view, 80).expect("gif");
    save("render3d_opening.gif", &gif);
    let frames = decode_gif(&gif);
    assert_eq!(frames.len(), 5);
    for (i, f) in frames.iter().enumerate() {
        // Kept for looking at by hand, like `save`.
        let _ = f.save(std::env::temp_dir().join(format!("render3d_opening_{i}.png")));
    }
    let size = frames[0].dimensions();
    assert!(frames.iter().all(|f| f.dimensions() == size));
    assert_ne!(frames[0], frames[4], "different states, different frames");
    assert_ne!(frames[1], frames[2]);
    // The base does not move: its front edge lies at the same pixels in every frame.
    let all: Vec<DVec3> = states.iter().flat_map(|s| s.positions.clone()).collect();
    let front = to_px(&view, &frames[0], &all, DVec3::new(50.0, 0.0, 0.0));
    let dark = |p: Rgba<u8>| p[0] < 90 && p[1] < 90 && p[2] < 90;
    for f in &frames {
        assert!(near(f, front, 1, dark), "front edge at the shared framing");
    }
}

#[test]
fn bad_states_are_errors_not_panics() {
    let view = View3d::with_width(100);
    let render = |s: &FoldedState| render_folded_png(s, &view);
    assert!(matches!(
        render(&FoldedState::default()),
        Err(RenderError::NoFaces)
    ));
    let mut no_faces = l_fold(90.0, V);
    no_faces.faces = None;
    assert!(matches!(render(&no_faces), Err(RenderError::NoFaces)));
    no_faces.faces = Some(vec![Face::simple(ids(&[0, 1]))]);
    assert!(matches!(render(&no_faces), Err(RenderError::NoFaces)));
    let mut nan = l_fold(90.0, V);
    nan.positions[2].y = f64::NAN;
    assert!(matches!(
        render(&nan),
        Err(RenderError::Position {
            vertex: VertexId(2)
        })
    ));
    let mut far = l_fold(90.0, V);
    far.positions[4].z = f64::INFINITY;
    assert!(matches!(render(&far), Err(RenderError::Position { .. })));
    let mut missing = l_fold(90.0, V);
    missing.positions.truncate(5);
    assert!(matches!(
        render(&missing),
        Err(RenderError::MissingVertex {
            face: FaceId(1),
            vertex: VertexId(5)
        })
    ));
    assert!(matches!(
        render_gif(&[], &view, 50),
        Err(RenderError::NoFrames)
    ));
    let mixed = [l_fold(0.0, V), nan];
    assert!(matches!(
        render_gif(&mixed, &view, 50),
        Err(RenderError::Position { .. })
    ));
    assert!(render_gif(&[l_fold(0.0, V)], &view, 0).is_err());
}

#[test]
fn bad_views_are_errors() {
    let state = l_fold(90.0, V);
    for view in [
        View3d::with_width(0),
        View3d::with_width(100_000),
        View3d {
            height: Some(3),
            ..View3d::default()
        },
        View3d {
            elevation_deg: f64::NAN,
            ..View3d::default()
        },
        View3d {
            line_width_px: -1.0,
            ..View3d::default()
        },
    ] {
        assert!(render_folded_png(&state, &view).is_err(), "{view:?}");
    }
}

#[test]
fn a_flat_sheet_seen_edge_on_does_not_panic() {
    let view = View3d {
        elevation_deg: 0.0,
        ..View3d::with_width(64)
    };
    let img = render_folded_rgba(&l_fold(0.0, V), &view).expect("rgba");
    assert_eq!(img.width(), 64);
}

#[test]
fn without_outlines_adjacent_faces_leave_no_background_seam() {
    let state = l_fold(90.0, V);
    let view = View3d {
        outline: false,
        ..View3d::with_width(300)
    };
    let png = render_folded_png(&state, &view).expect("png");
    save("render3d_l_fold_plain.png", &png);
    let img = image::load_from_memory(&png).expect("decodes").to_rgba8();
    for t in [0.2, 0.5, 0.8] {
        let at = to_px(
            &view,
            &img,
            &state.positions,
            DVec3::new(100.0 * t, 50.0, 0.0),
        );
        let light = |p: Rgba<u8>| p[0] > 240 && p[1] > 240 && p[2] > 240;
        assert!(!near(&img, at, 1, light), "seam at t = {t}");
    }
}

/// A 100 × 100 base with a low 20 × 6 piece standing on it near the back, facing the front:
/// the base's centroid is nearer the eye than the piece's, and the piece projects inside the
/// base, yet the piece must stay visible.
#[test]
fn a_piece_standing_on_a_large_base_is_not_painted_over() {
    let mut positions = vec![
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(100.0, 0.0, 0.0),
        DVec3::new(100.0, 100.0, 0.0),
        DVec3::new(0.0, 100.0, 0.0),
    ];
    for (x, z) in [(40.0, 0.0), (60.0, 0.0), (60.0, 6.0), (40.0, 6.0)] {
        positions.push(DVec3::new(x, 80.0, z));
    }
    let state = FoldedState {
        positions,
        edges: Vec::new(),
        faces: Some(vec![
            Face::simple(ids(&[4, 5, 6, 7])),
            Face::simple(ids(&[0, 1, 2, 3])),
        ]),
        face_orders: Vec::new(),
    };
    let view = View3d::with_width(300);
    let png = render_folded_png(&state, &view).expect("png");
    save("render3d_piece_on_base.png", &png);
    let img = image::load_from_memory(&png).expect("decodes").to_rgba8();
    let px = |p: DVec3| *img.get_pixel_at(to_px(&view, &img, &state.positions, p));
    let piece = px(DVec3::new(50.0, 80.0, 3.0));
    let base = px(DVec3::new(20.0, 20.0, 0.0));
    assert_ne!(piece, WHITE);
    assert_ne!(piece, base, "the piece shows its own shade");
}

#[test]
fn box_popup_card_shows_the_box_and_opens_without_jumping() {
    let card = popup_box(90.0);
    let view = View3d::with_width(400);
    let png = render_folded_png(&card, &view).expect("png");
    save("render3d_popup_box.png", &png);
    let img = image::load_from_memory(&png).expect("decodes").to_rgba8();
    let px = |p: DVec3| *img.get_pixel_at(to_px(&view, &img, &card.positions, p));
    let base = px(DVec3::new(20.0, 30.0, 0.0));
    let back = px(DVec3::new(20.0, 60.0, 40.0));
    let box_front = px(DVec3::new(50.0, 40.0, 10.0));
    let box_top = px(DVec3::new(50.0, 50.0, 20.0));
    assert_eq!(
        box_front, back,
        "the box front is parallel to the back page"
    );
    assert_eq!(box_top, base, "the box top is parallel to the base");
    assert_ne!(base, back);
    let states: Vec<FoldedState> = [180.0, 150.0, 120.0, 90.0].map(popup_box).to_vec();
    let gif = render_gif(&states, &view, 100).expect("gif");
    save("render3d_popup_box.gif", &gif);
    assert_eq!(decode_gif(&gif).len(), 4);
}

/// Two overlapping squares in the plane z = 0 seen from above, face 0 showing its front and
/// face 1 (reversed) its back: only `face_orders` can tell which lies on top.
#[test]
fn coplanar_faces_follow_face_orders() {
    let mut state = two_squares(true);
    for p in &mut state.positions {
        *p = DVec3::new(p.x, p.z, 0.0);
    }
    // Face 0 = [0, 1, 2, 3] now runs counter-clockwise seen from +z (its normal points up,
    // towards the eye), face 1 clockwise (normal down).
    let view = View3d {
        elevation_deg: 90.0,
        outline: false,
        ..View3d::with_width(200)
    };
    let colour_on_top = |orders: Vec<(FaceId, FaceId, i8)>| {
        let state = FoldedState {
            face_orders: orders,
            ..state.clone()
        };
        let img = render_folded_rgba(&state, &view).expect("rgba");
        let px = |p: DVec3| *img.get_pixel_at(to_px(&view, &img, &state.positions, p));
        let (only0, only1) = (
            px(DVec3::new(5.0, 5.0, 0.0)),
            px(DVec3::new(25.0, 25.0, 0.0)),
        );
        assert_ne!(only0, only1);
        let overlap = px(DVec3::new(15.0, 15.0, 0.0));
        if overlap == only0 {
            0
        } else if overlap == only1 {
            1
        } else {
            2
        }
    };
    // Face 1's normal points down: +1 puts face 0 below face 1.
    assert_eq!(colour_on_top(vec![(FaceId(0), FaceId(1), 1)]), 1);
    assert_eq!(colour_on_top(vec![(FaceId(0), FaceId(1), -1)]), 0);
    // Face 0's normal points up: +1 puts face 1 above face 0.
    assert_eq!(colour_on_top(vec![(FaceId(1), FaceId(0), 1)]), 1);
    assert_eq!(colour_on_top(vec![(FaceId(1), FaceId(0), -1)]), 0);
}

#[test]
fn degenerate_geometry_draws_without_panicking() {
    let mut point = l_fold(90.0, V);
    point.positions.fill(DVec3::splat(7.0));
    let img = render_folded_rgba(&point, &View3d::with_width(32)).expect("rgba");
    assert_eq!(img.width(), 32);
    let mut tiny = l_fold(90.0, V);
    for p in &mut tiny.positions {
        *p *= 1e-300;
    }
    let img = render_folded_rgba(&tiny, &View3d::with_width(64)).expect("rgba");
    assert!(
        img.pixels().any(|&p| p != WHITE),
        "a tiny sheet is scaled up to fit"
    );
    let mut far_hole = l_fold(0.0, V);
    far_hole.positions.push(DVec3::new(1e9, -1e9, 0.0));
    if let Some(faces) = far_hole.faces.as_mut() {
        faces[0].holes.push(ids(&[6, 6, 6]));
    }
    render_folded_rgba(&far_hole, &View3d::with_width(64)).expect("rgba");
}

#[test]
fn the_key_band_adds_to_the_height_and_its_scale_bar_matches_the_drawing() {
    // A 100 mm square seen straight from above: the drawing is 100 mm across, so the scale
    // bar's length in pixels over the square's must be its length in mm over 100.
    let mut state = FoldedState::default();
    for (x, y) in [(0.0, 0.0), (100.0, 0.0), (100.0, 100.0), (0.0, 100.0)] {
        state.positions.push(DVec3::new(x, y, 0.0));
    }
    state.faces = Some(vec![Face {
        outer: ids(&[0, 1, 2, 3]),
        holes: vec![],
    }]);
    let plain = View3d {
        azimuth_deg: 0.0,
        elevation_deg: 90.0,
        height: Some(300),
        ..View3d::with_width(300)
    };
    let keyed = plain.clone().with_key("a square", "mm");
    let img = render_folded_rgba(&state, &keyed).expect("rgba");
    assert_eq!(img.width(), 300);
    assert!(img.height() > 300 + 20, "a band under the drawing");
    let without = render_folded_rgba(&state, &plain).expect("rgba");
    assert_eq!(without.height(), 300, "no key, no band");
    let dark = |p: &Rgba<u8>| p[0] < 80 && p[1] < 80 && p[2] < 80;
    let run = |y: u32, x0: u32, x1: u32| {
        let (mut best, mut cur) = (0u32, 0u32);
        for x in x0..x1 {
            cur = if dark(img.get_pixel(x, y)) {
                cur + 1
            } else {
                0
            };
            best = best.max(cur);
        }
        best
    };
    // The square's dark outline: its widest dark row in the drawing.
    let square = (0..300).map(|y| run(y, 0, 300)).max().unwrap_or(0);
    let bar = (300..img.height())
        .map(|y| run(y, 0, 300))
        .max()
        .unwrap_or(0);
    let mm = 100.0 * f64::from(bar) / f64::from(square);
    assert!(
        [10.0, 20.0, 50.0].iter().any(|r| (mm - r).abs() < 1.5),
        "bar {bar} px on a square of {square} px = {mm:.1} mm"
    );
}

/// Marked triangles (e.g. the input area a partial tessellation leaves uncovered) are drawn
/// in their colour where they are, beside the state's faces in paper colours.
#[test]
fn marked_triangles_are_drawn_in_their_colour() {
    let state = l_fold(90.0, V);
    // A triangle on the floor's plane beyond its far edge (x 110 to 150).
    let beyond = [
        DVec3::new(110.0, 0.0, 0.0),
        DVec3::new(150.0, 0.0, 0.0),
        DVec3::new(150.0, 40.0, 0.0),
    ];
    let colour = [214, 40, 40];
    let view = View3d {
        height: Some(300),
        ..View3d::with_width(400)
    };
    let (marked, view) = foldcam::render::with_marked_triangles(&state, &[beyond], colour, view);
    assert_eq!(marked.faces.as_ref().map(Vec::len), Some(3));
    let png = render_folded_png(&marked, &view).expect("png");
    let img = image::load_from_memory(&png).expect("decodes").to_rgba8();
    let centre = (beyond[0] + beyond[1] + beyond[2]) / 3.0;
    let at = to_px(&view, &img, &marked.positions, centre);
    let reddish = |p: Rgba<u8>| p[0] > 120 && p[1] < 60 && p[2] < 60;
    assert!(
        reddish(*img.get_pixel(at.0, at.1)),
        "{:?}",
        img.get_pixel(at.0, at.1)
    );
    // The floor keeps its paper colour.
    let floor = to_px(&view, &img, &marked.positions, centroid(&marked, 1));
    assert!(!reddish(*img.get_pixel(floor.0, floor.1)));
}
