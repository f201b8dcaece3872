//! PNG previews of crease patterns, drawn with tiny-skia.
//!
//! [`preview_png`] draws every edge in the usual origami line styles ([`style`]), on a
//! background with a margin, y up in the pattern and y down in the image (no mirroring), with
//! a key under the drawing ([`legend`]: a scale bar of a 1, 2 or 5 × 10^k length labelled in mm
//! or "units", and one legend entry per line style drawn) and with the findings of
//! [`crate::check`](mod@crate::check) highlighted: a ring at each finding's position, numbered as the check's
//! text report numbers it ([`rings`]), and an orange halo under an edge the finding names.
//!
//! The width is the caller's (16 to 16384 pixels); the height follows the aspect ratio and is
//! capped at 4 × the width and 16384 pixels ([`layout`]). Geometry stays f64 until it is
//! handed to tiny-skia as f32 pixel coordinates. Cost: one path per assignment, with the edges
//! of each straight crease line chained into one polyline so dashes run on across vertices.
//!
//! 3D views of a [`FoldedState`](crate::pattern::FoldedState) ([`render_folded_png`],
//! [`render_gif`]), with a key band under the drawing when [`View3d::key`] asks for one:
//! orthographic camera and framing in [`view3d`], flat two-sided shading in
//! [`shade`], the painter's order in [`depth_order`], animations in [`animation`], fold-step
//! sheets with captions at one scale in [`step_sheet`].

pub(crate) mod animation;
mod chain;
pub(crate) mod depth_order;
pub(crate) mod font;
pub(crate) mod heat;
pub(crate) mod layout;
pub(crate) mod legend;
mod preview;
pub(crate) mod rings;
pub(crate) mod shade;
pub(crate) mod step_sheet;
pub(crate) mod style;
pub(crate) mod top_view;
pub(crate) mod view3d;

use crate::check::Finding;
use crate::pattern::CreasePattern;

pub use animation::render_gif;
pub use heat::heat_color;
pub use layout::{MAX_SIZE, MIN_SIZE};
pub use legend::ColourScale;
pub use preview::render_pixmap;
pub use shade::{render_folded_pixmap, render_folded_png, render_folded_rgba};
pub use step_sheet::{step_sheet_png, step_sheet_rgba};
pub use top_view::render_top_view_png;
pub use view3d::{View3d, ViewKey, with_marked_triangles};

/// Options of [`preview_png`].
#[derive(Clone, Debug, PartialEq)]
pub struct PreviewOptions {
    /// Image width in pixels (16 to 16384); the height follows the pattern's aspect ratio.
    pub width: u32,
    /// Background colour, RGBA (not premultiplied).
    pub background: [u8; 4],
    /// Draw a scale bar at the bottom left.
    pub scale_bar: bool,
    /// Draw a legend under the drawing: one entry per line style drawn, and the rings.
    pub legend: bool,
    /// Draw flat lines dark and as wide as creases (paper-craft sheets, whose flat lines are
    /// the edge numbers), instead of thin and light grey.
    pub dark_flat: bool,
    /// Base line width in pixels (0 < w ≤ 64); other widths and dashes are multiples of it.
    pub line_width_px: f32,
    /// Empty space around the drawing, pixels (reduced to an eighth of the width if larger).
    pub margin: u32,
}

impl Default for PreviewOptions {
    fn default() -> Self {
        PreviewOptions {
            width: 1024,
            background: [255, 255, 255, 255],
            scale_bar: true,
            legend: true,
            dark_flat: false,
            line_width_px: 2.0,
            margin: 24,
        }
    }
}

impl PreviewOptions {
    /// Default options at a given width.
    pub fn with_width(width: u32) -> Self {
        PreviewOptions {
            width,
            ..PreviewOptions::default()
        }
    }
}

/// Errors of rendering.
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    /// Nothing to draw.
    #[error("the pattern has no edges to draw")]
    Empty,
    /// The requested width is out of range.
    #[error("image width {0} px is out of range: use 16 to 16384 px")]
    Width(u32),
    /// An option is out of range.
    #[error("preview option {name} = {value} is out of range: {expected}")]
    Option {
        /// The option.
        name: &'static str,
        /// Its value, as text.
        value: String,
        /// What is accepted.
        expected: &'static str,
    },
    /// The image could not be allocated.
    #[error("cannot allocate a {width} × {height} px image")]
    Allocation {
        /// Width, pixels.
        width: u32,
        /// Height, pixels.
        height: u32,
    },
    /// PNG encoding failed.
    #[error("PNG encoding failed: {0}")]
    Encode(String),
    /// A folded state has no faces with three or more corners.
    #[error("the folded state has no faces to draw")]
    NoFaces,
    /// A position is NaN, infinite or beyond the coordinate limit.
    #[error("vertex {vertex} has a non-finite or out-of-range position")]
    Position {
        /// The vertex.
        vertex: crate::pattern::VertexId,
    },
    /// A face names a vertex that has no position.
    #[error("face {face} names vertex {vertex}, which has no position")]
    MissingVertex {
        /// The face.
        face: crate::pattern::FaceId,
        /// The missing vertex.
        vertex: crate::pattern::VertexId,
    },
    /// An animation was asked for without any folded state.
    #[error("an animation needs at least one folded state")]
    NoFrames,
    /// GIF encoding failed.
    #[error("GIF encoding failed: {0}")]
    GifEncode(String),
}

/// Draws a pattern as PNG bytes, highlighting `faults`.
pub fn preview_png(
    cp: &CreasePattern,
    opts: &PreviewOptions,
    faults: &[Finding],
) -> Result<Vec<u8>, RenderError> {
    render_pixmap(cp, opts, faults)?
        .encode_png()
        .map_err(|e| RenderError::Encode(e.to_string()))
}

/// Draws a pattern as an RGBA image (not premultiplied), highlighting `faults`.
pub fn render_rgba(
    cp: &CreasePattern,
    opts: &PreviewOptions,
    faults: &[Finding],
) -> Result<image::RgbaImage, RenderError> {
    let pixmap = render_pixmap(cp, opts, faults)?;
    let (w, h) = (pixmap.width(), pixmap.height());
    image::RgbaImage::from_raw(w, h, pixmap.take_demultiplied()).ok_or(RenderError::Allocation {
        width: w,
        height: h,
    })
}
