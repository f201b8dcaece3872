//! 3D views of folded states: the camera, the projection and the framing.
//!
//! **Axes.** The sheet of a crease pattern lies in the x-y plane (z = 0) before folding; the
//! camera treats **z as up**, so a pop-up card lying on its base (x-y) with its back page
//! standing up along z is seen upright.
//!
//! **Camera.** [`View3d::azimuth_deg`] turns the eye about the z axis, starting at the front
//! (the −y side, looking towards +y) and moving right (towards +x) for positive angles;
//! [`View3d::elevation_deg`] raises it above the x-y plane (90° looks straight down). The
//! default, 30° and 25°, is a three-quarter view from the front right, slightly above: a card
//! standing at 90° shows both its base and its back page.
//!
//! **Projection.** Orthographic (parallel rays, no perspective): a point `p` lands at
//! `(p · right, p · up)` on the screen and its depth is `p · toward_eye`, with the orthonormal
//! basis `right = (cos a, sin a, 0)`, `toward_eye = (cos e sin a, −cos e cos a, sin e)`,
//! `up = toward_eye × right`. Parallel edges stay parallel and sizes do not depend on depth,
//! which keeps the preview honest about proportions.
//!
//! **Framing.** The projected bounding box of every vertex a face uses, over *all* states of
//! an animation (their union), is scaled uniformly to fit the image inside the margin and
//! centred, so the sheet does not jump or zoom between frames. Without an explicit height the
//! image takes the aspect ratio of that box, capped at 4 × the width and [`MAX_SIZE`] pixels.
//!
//! **Key.** With [`View3d::key`] set, a band under the drawing ([`super::legend`]) holds a
//! caption line (what is shown), a scale bar, the colour scale of the faces when they are
//! coloured by a quantity, and a sample of each colour drawn: the paper's two sides and each
//! kind of line. The projection is orthographic, so the scale bar is exact for lengths
//! parallel to the image plane at any depth, and shorter on screen for lengths slanting away
//! from it. The band adds to the image's height: [`View3d::height`] is the drawing's.
//!
//! **Input checks.** Every position must be finite and within ±[`MAX_COORDINATE`]; every
//! vertex a face names must have a position; at least one face needs three or more corners.
//! Violations are [`RenderError`]s, never panics.

use glam::{DVec2, DVec3};

use super::legend::ColourScale;
use super::{MAX_SIZE, MIN_SIZE, RenderError};
use crate::pattern::{Face, FaceId, FoldedState, MAX_COORDINATE, VertexId};

/// Largest height as a multiple of the width when the height follows the drawing.
const MAX_ASPECT: u32 = 4;

/// How to look at a folded state: camera angles, image size and colours.
#[derive(Clone, Debug, PartialEq)]
pub struct View3d {
    /// Turn of the eye about the z axis, degrees: 0 looks from the front (−y), positive moves
    /// the eye to the right (+x).
    pub azimuth_deg: f64,
    /// Height of the eye above the x-y plane, degrees (−90 to 90; 90 looks straight down).
    pub elevation_deg: f64,
    /// Image width, pixels (16 to 16384).
    pub width: u32,
    /// Height of the drawing, pixels (16 to 16384), without the key's band under it; `None`
    /// follows the drawing's aspect ratio.
    pub height: Option<u32>,
    /// Background colour, RGBA (not premultiplied).
    pub background: [u8; 4],
    /// Draw face outlines: boundary and cut edges dark, creases in their assignment's colour.
    pub outline: bool,
    /// Width of crease lines, pixels (0 < w ≤ 64); boundary and cut lines are 1.5 × as wide.
    pub line_width_px: f32,
    /// Empty space around the drawing, pixels (reduced to an eighth of the smaller image side
    /// if larger).
    pub margin: u32,
    /// Colour of the paper's front side (the side facing +z before folding), RGB.
    pub front_color: [u8; 3],
    /// Colour of the paper's back side, RGB: a different tint so the two sides can be told
    /// apart.
    pub back_color: [u8; 3],
    /// One colour per face of the state (by face index), used on both sides instead of
    /// `front_color`/`back_color` (e.g. strain colouring, [`super::heat::heat_color`]); faces
    /// beyond its end keep the paper colours.
    pub face_colors: Option<Vec<[u8; 3]>>,
    /// The key drawn in a band under the drawing (see the module docs); `None` draws the
    /// drawing alone.
    pub key: Option<ViewKey>,
}

/// What the key under a 3D view says besides the colours, which it finds in the view.
#[derive(Clone, Debug, PartialEq)]
pub struct ViewKey {
    /// What the picture shows, one line ("opened to 90°, seen from the front"); also stored
    /// as the PNG's `Description` text.
    pub caption: String,
    /// The unit of the state's coordinates, which the scale bar is labelled in ("mm",
    /// "units").
    pub unit: &'static str,
    /// What [`View3d::face_colors`] measure, when they are [`super::heat_color`]s of a
    /// quantity: drawn as a gradient with its ends' values. With it, the key shows no paper
    /// colours.
    pub colour_scale: Option<ColourScale>,
}

impl ViewKey {
    /// A key in millimetres with `caption` and no colour scale.
    pub fn mm(caption: impl Into<String>) -> Self {
        ViewKey {
            caption: caption.into(),
            unit: "mm",
            colour_scale: None,
        }
    }
}

impl Default for View3d {
    fn default() -> Self {
        View3d {
            azimuth_deg: 30.0,
            elevation_deg: 25.0,
            width: 640,
            height: None,
            background: [255, 255, 255, 255],
            outline: true,
            line_width_px: 1.5,
            margin: 16,
            front_color: [246, 236, 208],
            back_color: [176, 204, 236],
            face_colors: None,
            key: None,
        }
    }
}

impl View3d {
    /// The default view at a given width.
    pub fn with_width(width: u32) -> Self {
        View3d {
            width,
            ..View3d::default()
        }
    }

    /// Where the eye is, in words, from the angles: "the front", "the front right", "the
    /// back left" … (azimuth in 60° sectors about the front, back, left and right, 30° wide
    /// at the sides' middles), then "above" or "below" for elevations beyond ±15°
    /// ("straight above" or "straight below" beyond ±75°).
    pub fn seen_from(&self) -> String {
        let az = self.azimuth_deg.rem_euclid(360.0);
        let az = if az > 180.0 { az - 360.0 } else { az };
        let side = if az >= 0.0 { "right" } else { "left" };
        let around = match az.abs() {
            a if a < 15.0 => "the front".to_string(),
            a if a < 75.0 => format!("the front {side}"),
            a if a <= 105.0 => format!("the {side}"),
            a if a <= 165.0 => format!("the back {side}"),
            _ => "the back".to_string(),
        };
        match self.elevation_deg {
            e if e > 75.0 => "straight above".to_string(),
            e if e < -75.0 => "straight below".to_string(),
            e if e > 15.0 => format!("{around}, above"),
            e if e < -15.0 => format!("{around}, below"),
            _ => around,
        }
    }

    /// This view with a key (see [`ViewKey`]) captioned "`shows`, seen from …" (see
    /// [`View3d::seen_from`]), its scale bar in `unit`.
    pub fn with_key(self, shows: &str, unit: &'static str) -> View3d {
        let caption = format!("{shows}, seen from {}", self.seen_from());
        View3d {
            key: Some(ViewKey {
                caption,
                unit,
                colour_scale: None,
            }),
            ..self
        }
    }

    /// Checks the options, returning the first one out of range.
    pub fn validate(&self) -> Result<(), RenderError> {
        if !(MIN_SIZE..=MAX_SIZE).contains(&self.width) {
            return Err(RenderError::Width(self.width));
        }
        if let Some(h) = self.height.filter(|h| !(MIN_SIZE..=MAX_SIZE).contains(h)) {
            return Err(bad_option("height", h, "16 to 16384 pixels"));
        }
        if !self.azimuth_deg.is_finite() {
            return Err(bad_option(
                "azimuth_deg",
                self.azimuth_deg,
                "a finite angle",
            ));
        }
        if !(self.elevation_deg.is_finite() && self.elevation_deg.abs() <= 90.0) {
            return Err(bad_option(
                "elevation_deg",
                self.elevation_deg,
                "an angle from -90 to 90 degrees",
            ));
        }
        let lw = self.line_width_px;
        if !(lw.is_finite() && lw > 0.0 && lw <= 64.0) {
            return Err(bad_option(
                "line_width_px",
                lw,
                "a width in pixels above 0 and at most 64",
            ));
        }
        Ok(())
    }
}

fn bad_option(name: &'static str, value: impl ToString, expected: &'static str) -> RenderError {
    RenderError::Option {
        name,
        value: value.to_string(),
        expected,
    }
}

/// The orthonormal camera basis of a view (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Camera {
    right: DVec3,
    up: DVec3,
    /// Unit vector from the scene towards the eye.
    pub(crate) toward_eye: DVec3,
}

impl Camera {
    pub(crate) fn new(azimuth_deg: f64, elevation_deg: f64) -> Camera {
        let (sa, ca) = azimuth_deg.to_radians().sin_cos();
        let (se, ce) = elevation_deg.to_radians().sin_cos();
        let right = DVec3::new(ca, sa, 0.0);
        let toward_eye = DVec3::new(ce * sa, -ce * ca, se);
        Camera {
            right,
            up: toward_eye.cross(right),
            toward_eye,
        }
    }

    /// Screen position (x right, y up) of a point.
    #[inline]
    pub(crate) fn screen(&self, p: DVec3) -> DVec2 {
        DVec2::new(p.dot(self.right), p.dot(self.up))
    }

    /// Depth of a point: larger is nearer the eye.
    #[inline]
    pub(crate) fn depth(&self, p: DVec3) -> f64 {
        p.dot(self.toward_eye)
    }
}

/// The uniform mapping from screen coordinates to pixels, and the image size.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Framing {
    pub(crate) width: u32,
    pub(crate) height: u32,
    /// Pixels per unit of the state's coordinates.
    pub(crate) scale: f64,
    center: DVec2,
}

impl Framing {
    /// Fits the union of the states' drawn vertices into the view's image, after checking the
    /// view and every state.
    pub(crate) fn fit(
        states: &[FoldedState],
        view: &View3d,
    ) -> Result<(Camera, Framing), RenderError> {
        view.validate()?;
        let camera = Camera::new(view.azimuth_deg, view.elevation_deg);
        let mut bounds: Option<(DVec2, DVec2)> = None;
        for state in states {
            for (_, face) in drawable_faces(state)? {
                for v in face.outer.iter().chain(face.holes.iter().flatten()) {
                    let s = camera.screen(state.positions[v.index()]);
                    bounds = Some(bounds.map_or((s, s), |(lo, hi)| (lo.min(s), hi.max(s))));
                }
            }
        }
        let (lo, hi) = bounds.ok_or(RenderError::NoFaces)?;
        Ok((camera, Framing::new(lo, hi, view)))
    }

    fn new(lo: DVec2, hi: DVec2, view: &View3d) -> Framing {
        let width = view.width;
        let ext = hi - lo;
        let height = view.height.unwrap_or_else(|| auto_height(ext, view));
        let margin = f64::from(view.margin.min(width / 8).min(height / 8));
        let avail = DVec2::new(f64::from(width), f64::from(height)) - 2.0 * margin;
        let fit = |avail: f64, ext: f64| {
            if ext > 0.0 {
                avail / ext
            } else {
                f64::INFINITY
            }
        };
        let scale = match fit(avail.x, ext.x).min(fit(avail.y, ext.y)) {
            s if s.is_finite() && s > 0.0 => s,
            _ => 1.0,
        };
        Framing {
            width,
            height,
            scale,
            center: 0.5 * (lo + hi),
        }
    }

    /// The pixel position (y down) of a screen point.
    #[inline]
    pub(crate) fn pixel(&self, s: DVec2) -> DVec2 {
        DVec2::new(
            0.5 * f64::from(self.width) + (s.x - self.center.x) * self.scale,
            0.5 * f64::from(self.height) - (s.y - self.center.y) * self.scale,
        )
    }
}

/// The height that keeps the drawing's aspect ratio at the view's width.
fn auto_height(ext: DVec2, view: &View3d) -> u32 {
    let max = view.width.saturating_mul(MAX_ASPECT).min(MAX_SIZE);
    if ext.x <= 0.0 {
        return view.width.min(max);
    }
    let margin = f64::from(view.margin.min(view.width / 8));
    let drawn = ext.y * (f64::from(view.width) - 2.0 * margin) / ext.x;
    let h = (drawn + 2.0 * margin).ceil();
    if h.is_finite() {
        (h.min(f64::from(max)) as u32).max(MIN_SIZE)
    } else {
        max
    }
}

/// The faces of a state with at least three corners and their ids, after checking the
/// state: positions finite and in range, every named vertex present.
pub(crate) fn drawable_faces(state: &FoldedState) -> Result<Vec<(FaceId, &Face)>, RenderError> {
    let faces = state.faces.as_deref().unwrap_or_default();
    if faces.is_empty() {
        return Err(RenderError::NoFaces);
    }
    if let Some(i) = state
        .positions
        .iter()
        .position(|p| !(p.is_finite() && p.abs().max_element() <= MAX_COORDINATE))
    {
        return Err(RenderError::Position {
            vertex: VertexId(u32::try_from(i).unwrap_or(u32::MAX)),
        });
    }
    for (i, face) in faces.iter().enumerate() {
        let ring_vertices = face.outer.iter().chain(face.holes.iter().flatten());
        if let Some(&v) = ring_vertices
            .into_iter()
            .find(|v| v.index() >= state.positions.len())
        {
            return Err(RenderError::MissingVertex {
                face: FaceId(u32::try_from(i).unwrap_or(u32::MAX)),
                vertex: v,
            });
        }
    }
    let drawable: Vec<(FaceId, &Face)> = (0u32..)
        .map(FaceId)
        .zip(faces)
        .filter(|(_, f)| f.outer.len() >= 3)
        .collect();
    if drawable.is_empty() {
        return Err(RenderError::NoFaces);
    }
    Ok(drawable)
}

/// `state` with `triangles` (3D corners, the state's units) added as faces drawn in `colour`
/// on both sides, and `view` with the face colours that name them (the added faces come
/// first; the state's own keep the paper colours): e.g. the input's area a tessellation leaves
/// uncovered. Without triangles, the state and view as they are.
pub fn with_marked_triangles(
    state: &FoldedState,
    triangles: &[[DVec3; 3]],
    colour: [u8; 3],
    view: View3d,
) -> (FoldedState, View3d) {
    if triangles.is_empty() {
        return (state.clone(), view);
    }
    let base = state.positions.len();
    let mut marked = state.clone();
    marked.positions.extend(triangles.iter().flatten());
    let added = (0..triangles.len()).map(|k| Face {
        outer: (0..3).map(|i| VertexId::new(base + 3 * k + i)).collect(),
        holes: Vec::new(),
    });
    let faces = state.faces.clone().unwrap_or_default();
    marked.faces = Some(added.chain(faces).collect());
    let shift = |f: FaceId| FaceId::new(f.index() + triangles.len());
    marked.face_orders = (state.face_orders.iter())
        .map(|&(a, b, o)| (shift(a), shift(b), o))
        .collect();
    let view = View3d {
        face_colors: Some(vec![colour; triangles.len()]),
        ..view
    };
    (marked, view)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn camera_basis_is_orthonormal_and_front_view_is_upright() {
        let c = Camera::new(0.0, 0.0);
        assert!((c.screen(DVec3::X) - DVec2::X).length() < 1e-12);
        assert!((c.screen(DVec3::Z) - DVec2::Y).length() < 1e-12);
        assert!(c.depth(-DVec3::Y) > 0.0, "the front (-y) is nearest");
        let c = Camera::new(37.0, 61.0);
        for (a, b) in [
            (c.right, c.up),
            (c.up, c.toward_eye),
            (c.right, c.toward_eye),
        ] {
            assert!(a.dot(b).abs() < 1e-12);
        }
        assert!((c.up.length() - 1.0).abs() < 1e-12);
    }

    #[test]
    fn the_eye_is_named_from_the_angles() {
        let at = |azimuth_deg, elevation_deg| {
            View3d {
                azimuth_deg,
                elevation_deg,
                ..View3d::default()
            }
            .seen_from()
        };
        assert_eq!(at(0.0, 0.0), "the front");
        assert_eq!(at(30.0, 25.0), "the front right, above");
        assert_eq!(at(-20.0, 28.0), "the front left, above");
        assert_eq!(at(270.0, -30.0), "the left, below");
        assert_eq!(at(180.0, 0.0), "the back");
        assert_eq!(at(10.0, 90.0), "straight above");
    }

    #[test]
    fn framing_centres_and_fits_the_box() {
        let view = View3d {
            width: 200,
            height: Some(100),
            margin: 10,
            ..View3d::default()
        };
        let f = Framing::new(DVec2::ZERO, DVec2::new(4.0, 1.0), &view);
        assert_eq!(f.scale, 45.0);
        assert_eq!(f.pixel(DVec2::new(2.0, 0.5)), DVec2::new(100.0, 50.0));
        assert_eq!(f.pixel(DVec2::new(0.0, 1.0)), DVec2::new(10.0, 27.5));
    }

    #[test]
    fn auto_height_follows_the_aspect_and_is_capped() {
        let view = View3d {
            width: 120,
            margin: 10,
            ..View3d::default()
        };
        assert_eq!(auto_height(DVec2::new(2.0, 1.0), &view), 70);
        assert_eq!(auto_height(DVec2::new(1.0, 100.0), &view), 480);
        assert_eq!(auto_height(DVec2::ZERO, &view), 120);
    }
}
