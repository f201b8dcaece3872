//! Shared helpers: a seeded generator and polyline lengths.

use glam::DVec3;

/// A small deterministic generator (SplitMix64) for fixed-seed test data.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Rng(seed)
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// A point uniform in the cube [−h, h]³.
    pub fn cube(&mut self, h: f64) -> DVec3 {
        DVec3::new(self.range(-h, h), self.range(-h, h), self.range(-h, h))
    }
}

/// Length of the curve `f` on [a, b] by polylines with n and 2n pieces, Richardson-extrapolated
/// (error O(n⁻⁴) for a smooth curve).
pub fn curve_length(f: impl Fn(f64) -> DVec3, a: f64, b: f64, n: usize) -> f64 {
    let poly = |m: usize| {
        let pts: Vec<DVec3> = (0..=m)
            .map(|k| f(a + (b - a) * k as f64 / m as f64))
            .collect();
        pts.windows(2).map(|w| w[0].distance(w[1])).sum::<f64>()
    };
    (4.0 * poly(2 * n) - poly(n)) / 3.0
}
