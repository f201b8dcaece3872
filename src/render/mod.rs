//! PLACEHOLDER: previews (written by the render work).

use crate::check::Finding;
use crate::pattern::CreasePattern;

/// Options of [`preview_png`].
#[derive(Clone, Debug, PartialEq)]
pub struct PreviewOptions {
    /// Image width in pixels; the height follows the pattern's aspect ratio.
    pub width: u32,
}

/// Errors of rendering.
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    /// Nothing to draw.
    #[error("the pattern has no edges to draw")]
    Empty,
}

/// Draws a pattern as PNG bytes, highlighting `faults`.
pub fn preview_png(
    _cp: &CreasePattern,
    _opts: &PreviewOptions,
    _faults: &[Finding],
) -> Result<Vec<u8>, RenderError> {
    todo!()
}
