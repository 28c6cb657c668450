//! A seeded random stream (ChaCha8) whose position can be saved and restored, so that a
//! checkpointed run continues with exactly the numbers an uninterrupted one would draw.

use rand_chacha::rand_core::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

/// Seed and word position of a [`Stream`], the whole of its state.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct StreamState {
    /// Seed given to `ChaCha8Rng::seed_from_u64`.
    pub seed: u64,
    /// Number of 32-bit words drawn so far.
    pub word_pos: u64,
}

/// Uniform numbers in [0, 1) from ChaCha8 (top 53 bits of `next_u64`).
#[derive(Debug, Clone)]
pub struct Stream {
    rng: ChaCha8Rng,
    seed: u64,
}

impl Stream {
    /// A stream at the start of `seed`.
    pub fn new(seed: u64) -> Self {
        Self {
            rng: ChaCha8Rng::seed_from_u64(seed),
            seed,
        }
    }

    /// The stream at a saved position.
    pub fn restore(state: StreamState) -> Self {
        let mut s = Self::new(state.seed);
        s.rng.set_word_pos(u128::from(state.word_pos));
        s
    }

    /// The position to save.
    pub fn state(&self) -> StreamState {
        StreamState {
            seed: self.seed,
            // 2^64 words are never drawn in one run.
            word_pos: self.rng.get_word_pos() as u64,
        }
    }

    /// A uniform number in [0, 1).
    pub fn uniform(&mut self) -> f64 {
        (self.rng.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// A uniform index in `0..n` (`n > 0`).
    pub fn index(&mut self, n: usize) -> usize {
        ((self.uniform() * n as f64) as usize).min(n - 1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn restored_stream_continues_identically() {
        let mut a = Stream::new(7);
        for _ in 0..13 {
            a.uniform();
        }
        let mut b = Stream::restore(a.state());
        for _ in 0..50 {
            let (x, y) = (a.uniform(), b.uniform());
            assert_eq!(x.to_bits(), y.to_bits());
            assert!((0.0..1.0).contains(&x));
        }
        assert!(Stream::new(1).index(3) < 3);
    }
}
