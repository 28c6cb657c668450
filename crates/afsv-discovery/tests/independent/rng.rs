//! A tiny seeded noise source of our own (splitmix64 + Box-Muller), so the records do not
//! depend on the toolkit's random-number plumbing. Same seed -> same sequence, on every
//! platform (only integer arithmetic and IEEE f64 `ln`, `sqrt`, `cos`).

/// splitmix64 generator (Steele, Lea & Flood 2014).
#[derive(Debug, Clone)]
pub struct Noise {
    state: u64,
    spare: Option<f64>,
}

impl Noise {
    /// New stream; `stream` separates the channels/records drawn from one seed.
    pub fn new(seed: u64, stream: u64) -> Self {
        let mut n = Self {
            state: seed ^ stream.wrapping_mul(0xA076_1D64_78BD_642F),
            spare: None,
        };
        // discard a few outputs so nearby seeds decorrelate
        for _ in 0..4 {
            n.next_u64();
        }
        n
    }

    /// Next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in (0, 1).
    pub fn uniform(&mut self) -> f64 {
        ((self.next_u64() >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }

    /// Uniform in (lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.uniform()
    }

    /// Standard normal deviate (Box-Muller, both values used).
    pub fn gauss(&mut self) -> f64 {
        if let Some(s) = self.spare.take() {
            return s;
        }
        let u1 = self.uniform();
        let u2 = self.uniform();
        let r = (-2.0 * u1.ln()).sqrt();
        let a = 2.0 * std::f64::consts::PI * u2;
        self.spare = Some(r * a.sin());
        r * a.cos()
    }

    /// Add white Gaussian noise of standard deviation `sd` to every sample.
    pub fn add(&mut self, x: &mut [f64], sd: f64) {
        for v in x.iter_mut() {
            *v += sd * self.gauss();
        }
    }

    /// Add white Gaussian noise of `share` times the signal's own (population) standard
    /// deviation to every sample.
    pub fn add_share(&mut self, x: &mut [f64], share: f64) {
        let m = x.iter().sum::<f64>() / x.len() as f64;
        let sd = (x.iter().map(|v| (v - m).powi(2)).sum::<f64>() / x.len() as f64).sqrt();
        self.add(x, share * sd);
    }
}
