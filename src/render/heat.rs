//! A colour scale for quantities on faces (e.g. the fold simulation's strain): blue at 0,
//! through green and yellow, to red at the top of the scale; linear in between.

/// The scale's stops, from 0 to 1.
const STOPS: [[f64; 3]; 5] = [
    [49.0, 54.0, 149.0],
    [69.0, 117.0, 180.0],
    [102.0, 189.0, 99.0],
    [254.0, 224.0, 70.0],
    [215.0, 48.0, 39.0],
];

/// The colour of `value` on a scale from 0 to `top` (values outside are clamped; a `top` of 0
/// or less, or a non-finite value, gives the bottom colour).
pub fn heat_color(value: f64, top: f64) -> [u8; 3] {
    let t = if top > 0.0 && value.is_finite() {
        (value / top).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let x = t * (STOPS.len() - 1) as f64;
    let i = (x.floor() as usize).min(STOPS.len() - 2);
    let f = x - i as f64;
    let (a, b) = (STOPS[i], STOPS[i + 1]);
    [0, 1, 2].map(|c| (a[c] + (b[c] - a[c]) * f).round() as u8)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ends_of_the_scale_and_clamping() {
        assert_eq!(heat_color(0.0, 1.0), [49, 54, 149]);
        assert_eq!(heat_color(1.0, 1.0), [215, 48, 39]);
        assert_eq!(heat_color(5.0, 1.0), heat_color(1.0, 1.0));
        assert_eq!(heat_color(f64::NAN, 1.0), heat_color(0.0, 1.0));
        assert_eq!(heat_color(0.5, 1.0), [102, 189, 99]);
    }
}
