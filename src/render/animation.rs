//! Animated GIFs of a sequence of folded states, e.g. a pop-up card opening.
//!
//! One frame per state, drawn as by [`super::render_folded_png`] with **one framing for all
//! frames** (fitted to the union of every state's projected bounding box, see
//! [`super::view3d`]), so the sheet neither jumps nor zooms; the GIF loops forever.
//!
//! Limits: at most [`MAX_FRAMES`] frames; the frame delay is stored by GIF in hundredths of a
//! second, so it is rounded to 10 ms steps and must lie in 10 ms to 655.35 s. Colours are
//! reduced to a 256-colour palette per frame (NeuQuant, at a moderate speed setting), which
//! may band the smooth edges slightly.

use image::codecs::gif::{GifEncoder, Repeat};
use image::{Delay, Frame};

use super::RenderError;
use super::shade::{draw_state, pixmap_to_rgba};
use super::view3d::{Framing, View3d};
use crate::pattern::FoldedState;

/// Largest number of frames of one animation.
pub const MAX_FRAMES: usize = 1000;

/// Shortest and longest frame delay GIF can store, milliseconds.
pub const FRAME_DELAY_MS: std::ops::RangeInclusive<u32> = 10..=655_350;

/// Palette quantisation speed of the GIF encoder (1 best and slowest, 30 fastest).
const QUANTISE_SPEED: i32 = 10;

/// Draws one frame per state and encodes them as a looping animated GIF, `frame_delay_ms`
/// milliseconds per frame.
pub fn render_gif(
    states: &[FoldedState],
    view: &View3d,
    frame_delay_ms: u32,
) -> Result<Vec<u8>, RenderError> {
    if states.is_empty() {
        return Err(RenderError::NoFrames);
    }
    if states.len() > MAX_FRAMES {
        return Err(RenderError::Option {
            name: "frames",
            value: states.len().to_string(),
            expected: "at most 1000 folded states",
        });
    }
    if !FRAME_DELAY_MS.contains(&frame_delay_ms) {
        return Err(RenderError::Option {
            name: "frame_delay_ms",
            value: frame_delay_ms.to_string(),
            expected: "10 to 655350 milliseconds",
        });
    }
    let (camera, framing) = Framing::fit(states, view)?;
    let gif_error = |e: image::ImageError| RenderError::GifEncode(e.to_string());
    let mut out = Vec::new();
    {
        let mut encoder = GifEncoder::new_with_speed(&mut out, QUANTISE_SPEED);
        encoder.set_repeat(Repeat::Infinite).map_err(gif_error)?;
        for state in states {
            let rgba = pixmap_to_rgba(draw_state(state, view, &camera, &framing)?)?;
            let delay = Delay::from_numer_denom_ms(frame_delay_ms, 1);
            encoder
                .encode_frame(Frame::from_parts(rgba, 0, 0, delay))
                .map_err(gif_error)?;
        }
    }
    Ok(out)
}
