//! A fixed-seed generator for unit tests: a 64-bit linear congruential generator (Knuth's MMIX
//! constants), so random cases are reproducible without a dependency.

/// The generator's state.
#[derive(Clone, Debug)]
pub(crate) struct TestRng(u64);

impl TestRng {
    /// A generator starting from `seed`.
    pub(crate) fn new(seed: u64) -> Self {
        TestRng(seed)
    }

    /// The next value, uniform in [0, 1) (the state's top 53 bits).
    pub(crate) fn unit(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}
