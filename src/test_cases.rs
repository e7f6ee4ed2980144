//! Reproducible pseudo-random cases for unit tests: Marsaglia's xorshift64, the same
//! numbers on every run and machine.

/// The generator; its state is the seed (not 0).
#[derive(Clone, Debug)]
pub(crate) struct Xorshift(pub u64);

impl Xorshift {
    /// The next state.
    pub fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    /// A number in [0, 1) from the next state's top 53 bits.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
}
