//! Giving a pattern a physical size: a scale factor or a target size, with the coordinate
//! limit every reader enforces.

use super::{CreasePattern, MAX_COORDINATE, Units};

/// How to size a pattern.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Scale {
    /// Millimetres per pattern unit (for unitless patterns); also rescales millimetre ones.
    Factor(f64),
    /// The longer side of the bounding box becomes this many millimetres.
    Size(f64),
}

/// What [`CreasePattern::scale_to`] did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scaled {
    /// The factor applied to every coordinate (1 when nothing changed).
    pub factor: f64,
    /// Other FOLD frames (`file_frames`) were dropped: their numbers would not be rescaled.
    pub dropped_frames: bool,
}

/// A scale that cannot be applied.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum ScaleError {
    /// The factor or size is not a finite number greater than zero.
    #[error("a scale or size must be a finite number greater than 0, not {0}")]
    NotPositive(f64),
    /// The scaled coordinates would pass [`MAX_COORDINATE`].
    #[error(
        "a scale of {factor} puts coordinates at {reach:e} mm, beyond the limit of {MAX_COORDINATE:e} mm"
    )]
    TooLarge {
        /// The factor asked for.
        factor: f64,
        /// The largest |coordinate| it would give, mm.
        reach: f64,
    },
}

impl CreasePattern {
    /// Scales the pattern into millimetres: by a factor, or so the longer side of its bounding
    /// box is `Scale::Size` mm (a pattern without extent keeps its size). Afterwards the units
    /// are millimetres. Refuses a factor that is not positive and finite or that pushes a
    /// coordinate past [`MAX_COORDINATE`] (the pattern is then unchanged). Other FOLD frames
    /// kept from the input would keep their old numbers, so they are dropped (reported in
    /// [`Scaled::dropped_frames`]). A folded state of the pattern scales by the returned factor.
    ///
    /// ```
    /// use foldcam::pattern::{CreasePattern, Scale, Units};
    /// let mut cp = foldcam::design::classic::MiuraOri::default().build()?;
    /// let (lo, hi) = cp.bounds().unwrap();
    /// let side = (hi - lo).max_element();
    /// let scaled = cp.scale_to(Scale::Size(100.0))?;
    /// let (lo, hi) = cp.bounds().unwrap();
    /// let close = |a: f64, b: f64| (a - b).abs() <= 8.0 * f64::EPSILON * b.abs();
    /// assert!(close((hi - lo).max_element(), 100.0));
    /// assert!(close(scaled.factor, 100.0 / side));
    /// assert_eq!(cp.units, Units::Millimetres);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn scale_to(&mut self, scale: Scale) -> Result<Scaled, ScaleError> {
        let factor = match scale {
            Scale::Factor(f) => f,
            Scale::Size(size) => {
                if !(size.is_finite() && size > 0.0) {
                    return Err(ScaleError::NotPositive(size));
                }
                let extent = self
                    .bounds()
                    .map_or(0.0, |(lo, hi)| (hi - lo).max_element());
                if extent > 0.0 { size / extent } else { 1.0 }
            }
        };
        if !(factor.is_finite() && factor > 0.0) {
            return Err(ScaleError::NotPositive(factor));
        }
        let extent = self
            .bounds()
            .map_or(0.0, |(lo, hi)| lo.abs().max(hi.abs()).max_element());
        let reach = extent * factor;
        if !reach.is_finite() || reach > MAX_COORDINATE {
            return Err(ScaleError::TooLarge { factor, reach });
        }
        let mut dropped_frames = false;
        if factor != 1.0 || self.units == Units::Unitless {
            self.scale_to_mm(factor);
            dropped_frames = self.meta.file_extra.shift_remove("file_frames").is_some();
        }
        Ok(Scaled {
            factor,
            dropped_frames,
        })
    }
}
