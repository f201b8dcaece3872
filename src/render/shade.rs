//! Flat-shaded pictures of a folded state, drawn with tiny-skia.
//!
//! **Shading.** Each face gets one colour. Its normal is Newell's normal of the outer cycle,
//! which points to the paper's front side (the +z side before folding, since outer cycles run
//! counter-clockwise in the pattern). Paper has two sides: when the front faces away from the
//! eye the back side is seen, drawn with [`View3d::back_color`] and the reversed normal. The
//! brightness is Lambert's law with an ambient term, `AMBIENT + (1 − AMBIENT) · max(0, n · l)`,
//! for a fixed light `l` ([`LIGHT_DIRECTION`]) from the front left, above: it does not move
//! with the camera, so an animation lights the sheet consistently and horizontal and vertical
//! faces differ clearly in the default view.
//!
//! **Visibility.** Painter's algorithm: faces are drawn far to near in the order of
//! [`super::depth_order`] (centroid depth refined by plane tests), each immediately followed by
//! its outline, so near faces hide far faces and their lines. Limits: faces that intersect
//! each other or overlap cyclically (A over B over C over A) may be drawn wrong; coplanar
//! stacked faces (a flat fold) are ordered by the state's `face_orders` where it names them.
//! Fine for pop-up cards and partly folded sheets; not a z-buffer.
//!
//! **Outlines.** Each side of a face is drawn in the style of the edge joining its two
//! vertices: boundary and cut edges dark and 1.5 × the line width, mountain red, valley blue,
//! flat light grey and thin, unassigned magenta, join orange (the colours of [`super::style`],
//! solid); a side with no edge is drawn as boundary. Faces with holes are filled with the
//! even-odd rule.
//!
//! **Key.** With [`View3d::key`] set, the image grows by a band under the drawing holding
//! the caption, a scale bar at the framing's scale (the projection is orthographic: exact
//! for lengths parallel to the image plane), the colour scale if any, and a sample of each
//! colour used: the paper's front and back tints (unscaled by the light) unless every face
//! has a colour of its own, and, with outlines, each kind of line present.

use std::collections::HashMap;

use glam::DVec3;
use tiny_skia::{
    Color, FillRule, LineCap, LineJoin, Paint, PathBuilder, Pixmap, Stroke, Transform,
};

use super::RenderError;
use super::depth_order::{FaceGeometry, paint_order};
use super::legend::{self, Key, LegendEntry, ScaleBar};
use super::style::line_style;
use super::view3d::{Camera, Framing, View3d, drawable_faces};
use crate::pattern::{Assignment, Face, FoldedState, VertexId};

/// Direction towards the light (not normalised): from the front (−y), left (−x) and above.
pub const LIGHT_DIRECTION: [f64; 3] = [-0.3, -0.45, 0.85];

/// Share of the brightness that does not depend on the light.
pub const AMBIENT: f64 = 0.45;

/// Colour of boundary and cut outlines, RGBA.
const OUTLINE_DARK: [u8; 4] = [35, 35, 35, 255];

/// Share of the drawing's width the scale bar may take at most.
const SCALE_BAR_SHARE: f64 = 0.25;

/// Draws a folded state as PNG bytes; with a key, its caption is stored as the PNG's
/// `Description` text too.
pub fn render_folded_png(state: &FoldedState, view: &View3d) -> Result<Vec<u8>, RenderError> {
    let pixmap = render_folded_pixmap(state, view)?;
    match &view.key {
        Some(key) => legend::png_with_text(&pixmap, &[("Description", &key.caption)]),
        None => pixmap
            .encode_png()
            .map_err(|e| RenderError::Encode(e.to_string())),
    }
}

/// Draws a folded state as an RGBA image (not premultiplied).
pub fn render_folded_rgba(
    state: &FoldedState,
    view: &View3d,
) -> Result<image::RgbaImage, RenderError> {
    pixmap_to_rgba(render_folded_pixmap(state, view)?)
}

/// Draws a folded state into a tiny-skia pixmap (premultiplied RGBA).
pub fn render_folded_pixmap(state: &FoldedState, view: &View3d) -> Result<Pixmap, RenderError> {
    let (camera, framing) = Framing::fit(std::slice::from_ref(state), view)?;
    draw_state(state, view, &camera, &framing)
}

/// A pixmap as a straight-alpha RGBA image.
pub(crate) fn pixmap_to_rgba(pixmap: Pixmap) -> Result<image::RgbaImage, RenderError> {
    let (width, height) = (pixmap.width(), pixmap.height());
    image::RgbaImage::from_raw(width, height, pixmap.take_demultiplied())
        .ok_or(RenderError::Allocation { width, height })
}

/// Draws one state with a framing fitted beforehand (shared by the frames of an animation).
pub(crate) fn draw_state(
    state: &FoldedState,
    view: &View3d,
    camera: &Camera,
    framing: &Framing,
) -> Result<Pixmap, RenderError> {
    let faces = drawable_faces(state)?;
    let width = framing.width;
    let font_px = legend::font_px_for(width);
    let margin = view.margin.min(width / 8);
    let inner = width.saturating_sub(2 * margin).max(1);
    let key = view.key.as_ref().map(|k| key(state, view, framing, k));
    let band = key.as_ref().map_or(0, |k| k.height(inner, font_px));
    let height = framing.height.saturating_add(band);
    if height > super::MAX_SIZE {
        return Err(RenderError::Option {
            name: "height",
            value: height.to_string(),
            expected: "a drawing and key band within 16384 pixels",
        });
    }
    let mut pixmap = Pixmap::new(width, height).ok_or(RenderError::Allocation { width, height })?;
    let [r, g, b, a] = view.background;
    pixmap.fill(Color::from_rgba8(r, g, b, a));
    let edges = edge_lookup(state);
    let pos = |v: VertexId| state.positions[v.index()];
    let normals: Vec<DVec3> = faces.iter().map(|(_, f)| newell_normal(f, &pos)).collect();
    let geometry: Vec<FaceGeometry> = faces
        .iter()
        .zip(&normals)
        .map(|(&(id, f), &n)| {
            FaceGeometry::new(id, f.outer.iter().map(|&v| pos(v)).collect(), n, camera)
        })
        .collect();
    for i in paint_order(&geometry, camera, &state.face_orders) {
        let face = faces[i].1;
        let own = view
            .face_colors
            .as_ref()
            .and_then(|c| c.get(faces[i].0.index()));
        let color = shade(normals[i], camera, view, own.copied());
        fill_face(&mut pixmap, face, &pos, camera, framing, color);
        if view.outline {
            outline_face(&mut pixmap, face, &pos, &edges, camera, framing, view);
        }
    }
    if let Some(key) = key {
        let top = f64::from(framing.height);
        let (w, h) = (f64::from(width), f64::from(band));
        legend::fill_rect(&mut pixmap, 0.0, top, w, h, legend::PAPER);
        key.draw(&mut pixmap, f64::from(margin), top, inner, font_px);
    }
    Ok(pixmap)
}

/// The key of a view of `state`: caption, scale bar, colour scale, paper sides and lines.
fn key(state: &FoldedState, view: &View3d, framing: &Framing, k: &super::view3d::ViewKey) -> Key {
    let margin = view.margin.min(framing.width / 8);
    let drawn = f64::from(framing.width.saturating_sub(2 * margin));
    let mut entries = Vec::new();
    let faces = state.faces.as_ref().map_or(0, Vec::len);
    let own_colours = view.face_colors.as_ref().map_or(0, Vec::len);
    if own_colours < faces {
        let [r, g, b] = view.front_color;
        entries.push(LegendEntry::fill("paper, front", [r, g, b, 255]));
        let [r, g, b] = view.back_color;
        entries.push(LegendEntry::fill("paper, back", [r, g, b, 255]));
    }
    if view.outline {
        let lw = view.line_width_px.max(2.0);
        let used = |a: Assignment| state.edges.iter().any(|e| e.assignment == a);
        if used(Assignment::Boundary) || used(Assignment::Cut) {
            let label = match (used(Assignment::Boundary), used(Assignment::Cut)) {
                (true, true) => "edge or cut",
                (false, true) => "cut",
                _ => "edge",
            };
            let (color, width) = outline_style(Assignment::Boundary, lw);
            entries.push(LegendEntry::line(label, color, width, None));
        }
        for a in super::style::DRAW_ORDER.iter().rev() {
            if matches!(a, Assignment::Boundary | Assignment::Cut) || !used(*a) {
                continue;
            }
            let (color, width) = outline_style(*a, lw);
            entries.push(LegendEntry::line(a.name(), color, width, None));
        }
    }
    Key {
        caption: Some(k.caption.clone()),
        scale_bar: Some(ScaleBar {
            px_per_unit: framing.scale,
            unit: k.unit,
            max_px: drawn * SCALE_BAR_SHARE,
        }),
        colour_scale: k.colour_scale.clone(),
        entries,
    }
}

/// The assignment of the edge joining each pair of vertices (keyed smaller index first).
fn edge_lookup(state: &FoldedState) -> HashMap<(VertexId, VertexId), Assignment> {
    state
        .edges
        .iter()
        .map(|e| {
            let [a, b] = e.vertices;
            ((a.min(b), a.max(b)), e.assignment)
        })
        .collect()
}

/// Newell's normal of the outer cycle (not normalised; zero for a degenerate face).
fn newell_normal(face: &Face, pos: &impl Fn(VertexId) -> DVec3) -> DVec3 {
    let n = face.outer.len();
    (0..n)
        .map(|i| pos(face.outer[i]).cross(pos(face.outer[(i + 1) % n])))
        .sum()
}

/// The flat colour of a face with normal `normal`: the side facing the eye, lit by Lambert's
/// law with an ambient term; `own` replaces the paper colours of both sides.
fn shade(normal: DVec3, camera: &Camera, view: &View3d, own: Option<[u8; 3]>) -> [u8; 3] {
    let n = normal.normalize_or_zero();
    let (n, base) = if n.dot(camera.toward_eye) >= 0.0 {
        (n, view.front_color)
    } else {
        (-n, view.back_color)
    };
    let base = own.unwrap_or(base);
    let light = DVec3::from_array(LIGHT_DIRECTION).normalize();
    let k = AMBIENT + (1.0 - AMBIENT) * n.dot(light).max(0.0);
    base.map(|c| (f64::from(c) * k).round().clamp(0.0, 255.0) as u8)
}

fn paint(color: [u8; 4]) -> Paint<'static> {
    let mut paint = Paint::default();
    paint.set_color_rgba8(color[0], color[1], color[2], color[3]);
    paint.anti_alias = true;
    paint
}

/// Adds a closed ring of vertices to a path, in pixels.
fn push_ring(
    pb: &mut PathBuilder,
    ring: &[VertexId],
    pos: &impl Fn(VertexId) -> DVec3,
    camera: &Camera,
    framing: &Framing,
) {
    for (i, &v) in ring.iter().enumerate() {
        let p = framing.pixel(camera.screen(pos(v)));
        if i == 0 {
            pb.move_to(p.x as f32, p.y as f32);
        } else {
            pb.line_to(p.x as f32, p.y as f32);
        }
    }
    pb.close();
}

fn fill_face(
    pixmap: &mut Pixmap,
    face: &Face,
    pos: &impl Fn(VertexId) -> DVec3,
    camera: &Camera,
    framing: &Framing,
    [r, g, b]: [u8; 3],
) {
    let mut pb = PathBuilder::new();
    for ring in std::iter::once(&face.outer).chain(&face.holes) {
        if ring.len() >= 3 {
            push_ring(&mut pb, ring, pos, camera, framing);
        }
    }
    if let Some(path) = pb.finish() {
        let p = paint([r, g, b, 255]);
        pixmap.fill_path(&path, &p, FillRule::EvenOdd, Transform::identity(), None);
    }
}

/// Colour and width of an outline side of an edge of assignment `a`.
fn outline_style(a: Assignment, lw: f32) -> ([u8; 4], f32) {
    match a {
        Assignment::Boundary | Assignment::Cut => (OUTLINE_DARK, 1.5 * lw),
        Assignment::Flat => (line_style(a, lw).color, 0.6 * lw),
        _ => (line_style(a, lw).color, lw),
    }
}

/// Strokes the sides of a face's rings, one path per assignment, faint styles first.
fn outline_face(
    pixmap: &mut Pixmap,
    face: &Face,
    pos: &impl Fn(VertexId) -> DVec3,
    edges: &HashMap<(VertexId, VertexId), Assignment>,
    camera: &Camera,
    framing: &Framing,
    view: &View3d,
) {
    let mut paths: Vec<(Assignment, PathBuilder)> = Vec::new();
    for ring in std::iter::once(&face.outer).chain(&face.holes) {
        for (i, &a) in ring.iter().enumerate() {
            let b = ring[(i + 1) % ring.len()];
            let kind = edges
                .get(&(a.min(b), a.max(b)))
                .copied()
                .unwrap_or(Assignment::Boundary);
            let slot = match paths.iter().position(|(k, _)| *k == kind) {
                Some(s) => s,
                None => {
                    paths.push((kind, PathBuilder::new()));
                    paths.len() - 1
                }
            };
            let (p, q) = (
                framing.pixel(camera.screen(pos(a))),
                framing.pixel(camera.screen(pos(b))),
            );
            paths[slot].1.move_to(p.x as f32, p.y as f32);
            paths[slot].1.line_to(q.x as f32, q.y as f32);
        }
    }
    paths.sort_by_key(|(k, _)| super::style::DRAW_ORDER.iter().position(|d| d == k));
    for (kind, pb) in paths {
        let Some(path) = pb.finish() else {
            continue;
        };
        let (color, width) = outline_style(kind, view.line_width_px);
        let stroke = Stroke {
            width,
            line_cap: LineCap::Round,
            line_join: LineJoin::Round,
            ..Stroke::default()
        };
        pixmap.stroke_path(&path, &paint(color), &stroke, Transform::identity(), None);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lit_faces_are_brighter_and_back_sides_use_the_back_tint() {
        let view = View3d::default();
        let camera = Camera::new(view.azimuth_deg, view.elevation_deg);
        let up = shade(DVec3::Z, &camera, &view, None);
        let wall = shade(-DVec3::Y, &camera, &view, None);
        assert!(up[0] > wall[0], "the top face is lit more steeply");
        let under = shade(-DVec3::Z, &camera, &view, None);
        let back_tint = shade(
            DVec3::Z,
            &camera,
            &View3d {
                back_color: [0, 0, 0],
                ..view.clone()
            },
            None,
        );
        assert_ne!(under, up);
        assert_eq!(
            back_tint, up,
            "a face seen from the front ignores the back colour"
        );
        let degenerate = shade(DVec3::ZERO, &camera, &view, None);
        let ambient = view
            .front_color
            .map(|c| (f64::from(c) * AMBIENT).round() as u8);
        assert_eq!(degenerate, ambient);
    }
}
