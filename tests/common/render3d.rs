//! Folded-state fixtures and pixel helpers shared by the 3D preview tests.
#![allow(dead_code)]

use foldcam::pattern::{Assignment, Edge, Face, FoldedState, VertexId};
use foldcam::render::View3d;
use glam::{DVec2, DVec3};
use image::{Rgba, RgbaImage};

use Assignment::{Boundary as B, Cut as C, Flat as F, Mountain as M, Valley as V};

pub fn ids(v: &[u32]) -> Vec<VertexId> {
    v.iter().map(|&i| VertexId(i)).collect()
}

pub fn edge(a: u32, b: u32, kind: Assignment) -> Edge {
    Edge::new(VertexId(a), VertexId(b), kind)
}

/// A 100 × 100 sheet with a crease of kind `crease` at y = 50, its far half lifted by
/// `angle_deg` about the crease (90° stands it upright: an "L").
pub fn l_fold(angle_deg: f64, crease: Assignment) -> FoldedState {
    let (s, c) = angle_deg.to_radians().sin_cos();
    let lifted = |x: f64| DVec3::new(x, 50.0 + 50.0 * c, 50.0 * s);
    FoldedState {
        positions: vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(100.0, 0.0, 0.0),
            DVec3::new(100.0, 50.0, 0.0),
            DVec3::new(0.0, 50.0, 0.0),
            lifted(100.0),
            lifted(0.0),
        ],
        edges: vec![
            edge(0, 1, B),
            edge(1, 2, B),
            edge(2, 3, crease),
            edge(3, 0, B),
            edge(2, 4, B),
            edge(4, 5, B),
            edge(5, 3, B),
        ],
        faces: Some(vec![
            Face::simple(ids(&[0, 1, 2, 3])),
            Face::simple(ids(&[3, 2, 4, 5])),
        ]),
        face_orders: Vec::new(),
    }
}

/// A strip of `panels` 100 × 40 panels folded like an accordion, alternating mountain and
/// valley, each panel tilted by ±`angle_deg` / 2 from the horizontal.
pub fn accordion(panels: u32, angle_deg: f64) -> FoldedState {
    let half = (0.5 * angle_deg).to_radians();
    let mut yz = vec![DVec2::ZERO];
    for i in 0..panels {
        let tilt = if i % 2 == 0 { half } else { -half };
        let last = yz[yz.len() - 1];
        yz.push(last + 40.0 * DVec2::new(tilt.cos(), tilt.sin()));
    }
    let mut state = FoldedState::default();
    for p in &yz {
        state.positions.push(DVec3::new(0.0, p.x, p.y));
        state.positions.push(DVec3::new(100.0, p.x, p.y));
    }
    let mut faces = Vec::new();
    for i in 0..panels {
        let (l0, r0, l1, r1) = (2 * i, 2 * i + 1, 2 * i + 2, 2 * i + 3);
        faces.push(Face::simple(ids(&[l0, r0, r1, l1])));
        state.edges.push(edge(l0, l1, B));
        state.edges.push(edge(r0, r1, B));
    }
    state.edges.push(edge(0, 1, B));
    state.edges.push(edge(2 * panels, 2 * panels + 1, B));
    for i in 1..panels {
        let kind = if i % 2 == 1 { M } else { V };
        state.edges.push(edge(2 * i, 2 * i + 1, kind));
    }
    state.faces = Some(faces);
    state
}

/// The documented projection and framing: orthographic camera, union bounding box of the
/// given points, uniform scale into the image inside the margin, centred.
pub fn to_px(view: &View3d, img: &RgbaImage, all: &[DVec3], p: DVec3) -> (u32, u32) {
    let (sa, ca) = view.azimuth_deg.to_radians().sin_cos();
    let (se, ce) = view.elevation_deg.to_radians().sin_cos();
    let right = DVec3::new(ca, sa, 0.0);
    let eye = DVec3::new(ce * sa, -ce * ca, se);
    let up = eye.cross(right);
    let screen = |q: DVec3| DVec2::new(q.dot(right), q.dot(up));
    let (mut lo, mut hi) = (screen(all[0]), screen(all[0]));
    for &q in all {
        lo = lo.min(screen(q));
        hi = hi.max(screen(q));
    }
    let (w, h) = (f64::from(img.width()), f64::from(img.height()));
    let m = f64::from(view.margin);
    let scale = ((w - 2.0 * m) / (hi.x - lo.x)).min((h - 2.0 * m) / (hi.y - lo.y));
    let c = 0.5 * (lo + hi);
    let s = screen(p);
    let x = 0.5 * w + (s.x - c.x) * scale;
    let y = 0.5 * h - (s.y - c.y) * scale;
    (x as u32, y as u32)
}

pub fn centroid(state: &FoldedState, face: usize) -> DVec3 {
    let outer = &state.faces.as_ref().expect("faces")[face].outer;
    outer
        .iter()
        .map(|v| state.positions[v.index()])
        .sum::<DVec3>()
        / outer.len() as f64
}

pub fn near(img: &RgbaImage, (x, y): (u32, u32), r: u32, pred: impl Fn(Rgba<u8>) -> bool) -> bool {
    (y.saturating_sub(r)..=y + r)
        .flat_map(|j| (x.saturating_sub(r)..=x + r).map(move |i| (i, j)))
        .any(|(i, j)| i < img.width() && j < img.height() && pred(*img.get_pixel(i, j)))
}

pub const WHITE: Rgba<u8> = Rgba([255, 255, 255, 255]);

pub fn is_blue(p: Rgba<u8>) -> bool {
    i32::from(p[2]) > i32::from(p[0]) + 100
}

pub fn is_red(p: Rgba<u8>) -> bool {
    i32::from(p[0]) > i32::from(p[1]) + 100 && i32::from(p[0]) > i32::from(p[2]) + 100
}

pub fn save(name: &str, png: &[u8]) {
    // Kept for looking at by hand; failures to write do not matter to the test.
    let _ = std::fs::write(std::env::temp_dir().join(name), png);
}

pub trait PixelAt {
    fn get_pixel_at(&self, at: (u32, u32)) -> &Rgba<u8>;
}

impl PixelAt for RgbaImage {
    fn get_pixel_at(&self, (x, y): (u32, u32)) -> &Rgba<u8> {
        self.get_pixel(x, y)
    }
}

/// Two parallel 20 × 20 squares facing the eye (the x-z plane seen from −y), the near one at
/// y = 0 showing its front, the far one at y = 50 shifted by 10 and showing its back.
pub fn two_squares(near_first: bool) -> FoldedState {
    let sq = |x: f64, y: f64, z: f64| {
        [
            DVec3::new(x, y, z),
            DVec3::new(x + 20.0, y, z),
            DVec3::new(x + 20.0, y, z + 20.0),
            DVec3::new(x, y, z + 20.0),
        ]
    };
    let mut positions = sq(0.0, 0.0, 0.0).to_vec();
    positions.extend(sq(10.0, 50.0, 10.0));
    // Front side towards −y: the outer cycle runs counter-clockwise seen from −y.
    let near_face = Face::simple(ids(&[0, 1, 2, 3]));
    let far_face = Face::simple(ids(&[7, 6, 5, 4]));
    let faces = if near_first {
        vec![near_face, far_face]
    } else {
        vec![far_face, near_face]
    };
    FoldedState {
        positions,
        edges: Vec::new(),
        faces: Some(faces),
        face_orders: Vec::new(),
    }
}

/// Where a point `(x, y)` of a 100 × 120 card with a box pop-up goes when the card is open
/// at `open_deg` (180 flat, 90 upright). The card folds at y = 60; cuts at x = 40 and x = 60
/// from y = 40 to y = 80 free a middle strip that folds (valley, mountain, valley) at
/// y = 40, 60, 80 into a 20 × 20 box: a parallelogram mechanism, front parallel to the back
/// page, top parallel to the base. `middle` selects the strip's side of a cut.
pub fn popup_point(x: f64, y: f64, middle: bool, open_deg: f64) -> DVec3 {
    let (s, c) = open_deg.to_radians().sin_cos();
    let up = DVec2::new(-c, s);
    let yz = if !middle {
        if y <= 60.0 {
            DVec2::new(y, 0.0)
        } else {
            DVec2::new(60.0, 0.0) + (y - 60.0) * up
        }
    } else if y <= 40.0 {
        DVec2::new(y, 0.0)
    } else if y <= 60.0 {
        DVec2::new(40.0, 0.0) + (y - 40.0) * up
    } else if y <= 80.0 {
        DVec2::new(40.0 + (y - 60.0), 0.0) + 20.0 * up
    } else {
        DVec2::new(60.0, 0.0) + (y - 60.0) * up
    };
    DVec3::new(x, yz.x, yz.y)
}

/// The box pop-up card of [`popup_point`] as a folded state: eight faces, counter-clockwise
/// in the card's plane, vertices shared where their 3D positions agree. Sides shared by two
/// faces are creases along x (mountain at the box's top front, valley elsewhere) and flat
/// along y; unshared sides are cuts at x = 40 and 60 and boundary elsewhere.
pub fn popup_box(open_deg: f64) -> FoldedState {
    // (x0, x1, y0, y1, middle) of each face in the flat card.
    let rects = [
        (0.0, 40.0, 0.0, 60.0, false),
        (60.0, 100.0, 0.0, 60.0, false),
        (0.0, 40.0, 60.0, 120.0, false),
        (60.0, 100.0, 60.0, 120.0, false),
        (40.0, 60.0, 0.0, 40.0, true),
        (40.0, 60.0, 40.0, 60.0, true),
        (40.0, 60.0, 60.0, 80.0, true),
        (40.0, 60.0, 80.0, 120.0, true),
    ];
    let mut state = FoldedState::default();
    let mut keys: Vec<(i64, i64, bool)> = Vec::new();
    let mut faces = Vec::new();
    for &(x0, x1, y0, y1, middle) in &rects {
        let mut ring = Vec::new();
        // Side faces touch x = 40 or 60 along the cut; split their sides there.
        let mut corners = vec![(x0, y0), (x1, y0)];
        if !middle && x1 == 40.0 || middle && x1 == 60.0 {
            corners.extend(
                [(x1, 40.0), (x1, 60.0), (x1, 80.0)]
                    .into_iter()
                    .filter(|c| c.1 > y0 && c.1 < y1),
            );
        }
        corners.push((x1, y1));
        corners.push((x0, y1));
        if !middle && x0 == 60.0 || middle && x0 == 40.0 {
            corners.extend(
                [(x0, 80.0), (x0, 60.0), (x0, 40.0)]
                    .into_iter()
                    .filter(|c| c.1 > y0 && c.1 < y1),
            );
        }
        for (x, y) in corners {
            // Only the cut's inner points differ between the two sides of a cut.
            let on_cut = (x == 40.0 || x == 60.0) && y > 40.0 && y < 80.0;
            let key = (x as i64, y as i64, middle && on_cut);
            let id = keys.iter().position(|k| *k == key).unwrap_or_else(|| {
                keys.push(key);
                state.positions.push(popup_point(x, y, middle, open_deg));
                keys.len() - 1
            });
            ring.push(VertexId(id as u32));
        }
        faces.push(Face::simple(ring));
    }
    state.edges = popup_edges(&faces, &keys);
    state.faces = Some(faces);
    state
}

fn popup_edges(faces: &[Face], keys: &[(i64, i64, bool)]) -> Vec<Edge> {
    let mut sides: Vec<(VertexId, VertexId, usize)> = Vec::new();
    for f in faces {
        for (i, &a) in f.outer.iter().enumerate() {
            let b = f.outer[(i + 1) % f.outer.len()];
            let key = (a.min(b), a.max(b));
            match sides.iter_mut().find(|s| (s.0, s.1) == key) {
                Some(s) => s.2 += 1,
                None => sides.push((key.0, key.1, 1)),
            }
        }
    }
    sides
        .into_iter()
        .map(|(a, b, count)| {
            let (ka, kb) = (keys[a.index()], keys[b.index()]);
            let kind = if count == 2 && ka.0 == kb.0 {
                F
            } else if count == 2 {
                if ka.1 == 60 && kb.1 == 60 && ka.0 >= 40 && kb.0 <= 60 && ka.0 <= 60 && kb.0 >= 40
                {
                    M
                } else {
                    V
                }
            } else if ka.0 == kb.0 && (ka.0 == 40 || ka.0 == 60) {
                C
            } else {
                B
            };
            Edge::new(a, b, kind)
        })
        .collect()
}
