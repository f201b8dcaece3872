//! Numbers as machine files print them: snapped to a grid, without float noise.
//!
//! A [`Grid`] of step `s` (a machine's resolution, e.g. 0.001 mm) turns a coordinate into an
//! integer count of steps, so that equality after rounding is exact integer equality (which is
//! how zero-length moves are found), and prints a count back with just enough decimals for the
//! step: `56.744`, never `56.74400000000002`, never `-0`, never an exponent. Steps that are not
//! a power of ten (0.025) print with the decimals they need (3). Counts are `i64`: callers
//! keep coordinates within ±1e9 mm and steps at least 1e-6 mm (see `check`), far inside range.

use crate::geom::tolerance::RELATIVE;

/// Most decimals a grid prints; finer steps are refused by `check`.
pub const MAX_DECIMALS: usize = 9;

/// A rounding grid: values are whole multiples of `step`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    step: f64,
    decimals: usize,
}

impl Grid {
    /// A grid of `step` (finite, positive), or `None`.
    pub fn new(step: f64) -> Option<Grid> {
        (step.is_finite() && step > 0.0).then(|| Grid {
            step,
            decimals: decimals_for(step),
        })
    }

    /// The grid of `10^-decimals`, for constant steps (`decimals` ≤ [`MAX_DECIMALS`]).
    pub const fn decimal(decimals: usize) -> Grid {
        let mut step = 1.0;
        let mut i = 0;
        while i < decimals && i < MAX_DECIMALS {
            step /= 10.0;
            i += 1;
        }
        Grid { step, decimals: i }
    }

    /// The step.
    pub fn step(&self) -> f64 {
        self.step
    }

    /// The nearest whole number of steps to `value` (finite, checked by the caller).
    pub fn snap(&self, value: f64) -> i64 {
        (value / self.step).round() as i64
    }

    /// `steps` × step, printed.
    pub fn print(&self, steps: i64) -> String {
        fixed(steps as f64 * self.step, self.decimals)
    }

    /// `value` rounded to the grid, printed.
    pub fn round(&self, value: f64) -> String {
        self.print(self.snap(value))
    }
}

/// Fewest decimals (up to [`MAX_DECIMALS`]) that write `step` exactly.
fn decimals_for(step: f64) -> usize {
    (0..MAX_DECIMALS)
        .find(|&d| {
            let scaled = step * 10f64.powi(d as i32);
            (scaled - scaled.round()).abs() <= RELATIVE * scaled.max(1.0)
        })
        .unwrap_or(MAX_DECIMALS)
}

/// `value` with at most `decimals` decimals, trailing zeros and a lone `-` of zero dropped.
pub fn fixed(value: f64, decimals: usize) -> String {
    let mut text = format!("{value:.decimals$}");
    if text.contains('.') {
        let kept = text.trim_end_matches('0').trim_end_matches('.').len();
        text.truncate(kept);
    }
    if text == "-0" {
        text.remove(0);
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn prints_without_noise() {
        let g = Grid::new(0.001).unwrap();
        assert_eq!(g.round(56.74400000000002), "56.744");
        assert_eq!(g.round(-0.0001), "0");
        assert_eq!(g.round(12.0), "12");
        assert_eq!(g.round(0.1 + 0.2), "0.3");
        assert_eq!(g.round(1e9), "1000000000");
        assert_eq!(g.round(-3.2006), "-3.201");
    }

    #[test]
    fn odd_steps_keep_their_decimals() {
        let g = Grid::new(0.025).unwrap();
        assert_eq!(g.round(1.01), "1");
        assert_eq!(g.round(1.04), "1.05");
        assert_eq!(Grid::new(1.0).unwrap().round(2.6), "3");
        assert_eq!(Grid::new(0.0005).unwrap().round(0.00074), "0.0005");
    }

    #[test]
    fn decimal_grids() {
        assert_eq!(Grid::decimal(3), Grid::new(0.001).unwrap());
        assert_eq!(Grid::decimal(6).round(1.0000004), "1");
        assert_eq!(Grid::decimal(0).round(2.4), "2");
    }

    #[test]
    fn refuses_bad_steps() {
        assert!(Grid::new(0.0).is_none());
        assert!(Grid::new(f64::NAN).is_none());
        assert!(Grid::new(-0.1).is_none());
    }

    #[test]
    fn fixed_trims() {
        assert_eq!(fixed(350.0, 3), "350");
        assert_eq!(fixed(-0.0, 3), "0");
        assert_eq!(fixed(2.6, 0), "3");
        assert_eq!(fixed(0.1251, 2), "0.13");
    }
}
