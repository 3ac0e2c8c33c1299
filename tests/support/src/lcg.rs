//! Knuth's MMIX linear congruential generator: a fixed, dependency-free
//! stream, so that generated parameter sets are the same on every run.

/// The generator's state.
pub struct Lcg(pub u64);

impl Lcg {
    /// A uniform value in `[0, 1)` from the top 53 bits of the next state.
    pub fn next_unit(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Log-uniform in `[lo, hi)`.
    pub fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + self.next_unit() * (hi.ln() - lo.ln())).exp()
    }

    /// One of `items`, uniformly.
    pub fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[((self.next_unit() * items.len() as f64) as usize).min(items.len() - 1)]
    }
}
