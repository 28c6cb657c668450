//! Two-track synthesis by random-phase spectral synthesis (replaces the third-order filters of
//! Fig 2.4 / Fig 6.5).
//!
//! On a frequency grid `n_k = k dn`, each track's Fourier coefficient is
//!
//! ```text
//! L_k = sqrt(P_k) (a_k Z0_k + b_k Z1_k),   R_k = sqrt(P_k) (a_k Z0_k + b_k Z2_k)
//! a_k^2 = gamma(n_k),  b_k^2 = 1 - gamma(n_k),  gamma = sqrt(gamma^2) (Eq 2.9)
//! P_k = integral of G_d over [n_k - dn/2, n_k + dn/2] intersected with [n_min, n_max]
//! ```
//!
//! with `Z0, Z1, Z2` independent circular complex Gaussians: `Z0` is the part common to both
//! tracks (the "correlated" branch `sqrt(gamma^2)` of Fig 2.4), `Z1`/`Z2` the independent
//! parts (`sqrt(1 - gamma^2)`). Then, exactly and for every line,
//! `E|L_k|^2 = E|R_k|^2 ∝ P_k`, `E[L_k R_k*] ∝ gamma(n_k) P_k`, so the coherence of line k is
//! `gamma^2(n_k)` and the expected variance of each track is `integral_{n_min}^{n_max} G_d dn`.
//! One inverse real FFT per track turns the lines into profiles.
//!
//! The synthesis period is at least [`PERIOD_FACTOR`]` / n_min` (so the lowest band frequency is
//! resolved by >= 16 lines) and the requested length is cut from it, which keeps a short profile a
//! window of a stationary non-periodic process rather than a few discrete sinusoids.

use crate::coherence::CoherenceModel;
use crate::error::{positive, Result, TerrainError};
use crate::psd::{Band, PowerLawPsd};
use rand_chacha::rand_core::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use realfft::num_complex::Complex;
use serde::{Deserialize, Serialize};

/// The synthesis period is at least `PERIOD_FACTOR / n_min` (m): 16 lines below `n_min`.
pub const PERIOD_FACTOR: f64 = 16.0;

/// Largest number of samples (output or synthesis period) accepted.
pub const MAX_SAMPLES: usize = 1 << 26;

/// What to synthesize: the displacement PSD, its band and the coherence of the two tracks.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TwoTrackSpec {
    /// Displacement PSD of each track (Eq 2.8).
    pub psd: PowerLawPsd,
    /// Spatial band outside which the PSD is zero.
    pub band: Band,
    /// Coherence between the tracks.
    pub coherence: CoherenceModel,
}

impl TwoTrackSpec {
    /// A validated spec.
    pub fn new(psd: PowerLawPsd, band: Band, coherence: CoherenceModel) -> Result<Self> {
        let s = Self {
            psd,
            band,
            coherence,
        };
        s.validate()?;
        Ok(s)
    }

    /// The paper's nominal terrain (sections 2.2.2 and 6.2.3): ISO 8608 class E
    /// (`alpha_r = 4.096e-5`, `w = 2`), band 0.02-5 cycles/m, piecewise-linear coherence
    /// with `m_c = 0.3` cycles/m.
    pub fn paper_nominal() -> Self {
        Self {
            psd: PowerLawPsd::paper_nominal(),
            band: Band::PAPER,
            coherence: CoherenceModel::PAPER,
        }
    }

    /// Check every field.
    pub fn validate(&self) -> Result<()> {
        self.psd.validate()?;
        self.band.validate()?;
        self.coherence.validate()
    }

    /// Target one-sided PSD of each track at `n` (m^3): `G_d(n)` inside the band, 0 outside.
    pub fn target_psd(&self, n: f64) -> f64 {
        if self.band.contains(n) {
            self.psd.gd(n)
        } else {
            0.0
        }
    }

    /// Target magnitude-squared coherence at `n`.
    pub fn target_msc(&self, n: f64) -> f64 {
        self.coherence.msc(n)
    }

    /// Target one-sided PSD of the cross-slope angle `(q - p)/B` (rad^2/(cycle/m)), the roll
    /// excitation of Fig 2.7: `2 G_d(n) (1 - gamma(n)) / B^2` (real cross-spectrum).
    pub fn target_cross_slope_psd(&self, n: f64, track_width_m: f64) -> f64 {
        let g = self.target_msc(n).sqrt();
        2.0 * self.target_psd(n) * (1.0 - g) / (track_width_m * track_width_m)
    }

    /// Target variance of each track (m^2): `integral_{n_min}^{n_max} G_d(n) dn`.
    pub fn variance(&self) -> f64 {
        self.psd.integral(self.band.n_min, self.band.n_max)
    }
}

impl Default for TwoTrackSpec {
    fn default() -> Self {
        Self::paper_nominal()
    }
}

/// Left and right elevation profiles sampled at `x_i = i dx`, `i = 0..len`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TwoTrackProfile {
    /// Sample spacing (m).
    pub dx_m: f64,
    /// Left-track elevation `q(x)` (m).
    pub left_m: Vec<f64>,
    /// Right-track elevation `p(x)` (m).
    pub right_m: Vec<f64>,
}

/// The uniform spacing of the longitudinal coordinates `x` (m): at least 2, increasing, each
/// step within 1e-6 of the mean step. A bad step names its row counted from 1 (the file
/// row is one more when a header precedes the data).
pub fn uniform_spacing(x: &[f64]) -> Result<f64> {
    if x.len() < 2 {
        return Err(TerrainError::Signal(format!(
            "a profile needs at least 2 samples, has {}",
            x.len()
        )));
    }
    let dx = (x[x.len() - 1] - x[0]) / (x.len() - 1) as f64;
    if !(dx.is_finite() && dx > 0.0) {
        return Err(TerrainError::Signal("x must increase".into()));
    }
    for (i, w) in x.windows(2).enumerate() {
        let step = w[1] - w[0];
        let uniform = (step - dx).abs() <= 1e-6 * dx;
        if !uniform {
            return Err(TerrainError::Signal(format!(
                "x is not uniformly spaced (sample {}: step {step} m, mean step {dx} m)",
                i + 2
            )));
        }
    }
    Ok(dx)
}

impl TwoTrackProfile {
    /// A measured profile: elevations `left` and `right` (m) at the uniformly spaced `x`
    /// (m; [`uniform_spacing`]), laid out from its first sample (`x_0` becomes 0).
    pub fn from_samples(x: &[f64], left: &[f64], right: &[f64]) -> Result<Self> {
        if left.len() != x.len() || right.len() != x.len() {
            return Err(TerrainError::Signal(format!(
                "x has {} samples, left {}, right {}",
                x.len(),
                left.len(),
                right.len()
            )));
        }
        Ok(Self {
            dx_m: uniform_spacing(x)?,
            left_m: left.to_vec(),
            right_m: right.to_vec(),
        })
    }

    /// Number of samples per track.
    #[inline]
    pub fn len(&self) -> usize {
        self.left_m.len()
    }

    /// True when there are no samples.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.left_m.is_empty()
    }

    /// Longitudinal coordinates `x_i = i dx` (m).
    pub fn x_m(&self) -> Vec<f64> {
        (0..self.len()).map(|i| i as f64 * self.dx_m).collect()
    }

    /// Length `(len - 1) dx` (m).
    #[inline]
    pub fn length_m(&self) -> f64 {
        self.len().saturating_sub(1) as f64 * self.dx_m
    }

    /// Linearly interpolated `(left, right)` elevations at `x` (m); `None` outside `[0, length]`.
    #[inline]
    pub fn heights_at(&self, x: f64) -> Option<(f64, f64)> {
        if self.is_empty() || !(x >= 0.0 && x <= self.length_m()) {
            return None;
        }
        let s = x / self.dx_m;
        // s >= 0 here, so the cast truncates to floor(s) without a call to libm's floor
        let i = (s as usize).min(self.len() - 1);
        let j = (i + 1).min(self.len() - 1);
        let t = s - i as f64;
        let lerp = |v: &[f64]| v[i] + t * (v[j] - v[i]);
        Some((lerp(&self.left_m), lerp(&self.right_m)))
    }

    /// Cross-slope angle `(left - right) / track_width` (rad, small-angle), the roll excitation.
    pub fn cross_slope_rad(&self, track_width_m: f64) -> Vec<f64> {
        self.left_m
            .iter()
            .zip(&self.right_m)
            .map(|(l, r)| (l - r) / track_width_m)
            .collect()
    }
}

/// Number of samples `round(length/dx) + 1` of a profile, validated.
pub fn sample_count(length_m: f64, dx_m: f64) -> Result<usize> {
    positive("length", length_m)?;
    positive("dx", dx_m)?;
    let steps = (length_m / dx_m).round();
    if !steps.is_finite() || steps < 1.0 || steps >= MAX_SAMPLES as f64 {
        return Err(TerrainError::Parameter {
            name: "length",
            value: length_m,
            requirement: format!(
                "length/dx must give between 2 and {MAX_SAMPLES} samples (dx = {dx_m} m)"
            ),
        });
    }
    Ok(steps as usize + 1)
}

/// Synthesis period (samples) used for `n_out` output samples: the smallest even 2^a 3^b 5^c
/// that is >= `n_out` and >= `PERIOD_FACTOR / (n_min dx)`.
pub fn synthesis_len(band: &Band, n_out: usize, dx_m: f64) -> Result<usize> {
    let need = (PERIOD_FACTOR / (band.n_min * dx_m) * (1.0 - 1e-12)).ceil();
    if !need.is_finite() || need >= MAX_SAMPLES as f64 {
        return Err(TerrainError::Parameter {
            name: "band.n_min",
            value: band.n_min,
            requirement: format!(
                "too low for dx = {dx_m} m: synthesis would need {need} samples (limit {MAX_SAMPLES}); raise n_min or dx"
            ),
        });
    }
    let n = next_fast_even(n_out.max(need as usize).max(2));
    if n > MAX_SAMPLES {
        return Err(TerrainError::Parameter {
            name: "length",
            value: n_out as f64 * dx_m,
            requirement: format!("needs {n} samples, limit {MAX_SAMPLES}"),
        });
    }
    Ok(n)
}

fn next_fast_even(n: usize) -> usize {
    let mut m = n.max(2);
    loop {
        if m % 2 == 0 {
            let mut r = m;
            for p in [2, 3, 5] {
                while r % p == 0 {
                    r /= p;
                }
            }
            if r == 1 {
                return m;
            }
        }
        m += 1;
    }
}

/// Standard-normal source on ChaCha8 (uniforms from the top 53 bits of `next_u64`, Box-Muller).
pub(crate) struct Gaussian {
    rng: ChaCha8Rng,
}

impl Gaussian {
    pub(crate) fn new(seed: u64) -> Self {
        Self {
            rng: ChaCha8Rng::seed_from_u64(seed),
        }
    }

    /// Uniform in the open interval (0, 1).
    fn uniform(&mut self) -> f64 {
        ((self.rng.next_u64() >> 11) as f64 + 0.5) * (1.0 / (1u64 << 53) as f64)
    }

    /// A circular complex Gaussian whose real and imaginary parts are independent N(0, 1)
    /// (Marsaglia's polar method: two uniforms per try, accepted with probability pi/4).
    pub(crate) fn complex(&mut self) -> Complex<f64> {
        loop {
            let u = 2.0 * self.uniform() - 1.0;
            let v = 2.0 * self.uniform() - 1.0;
            let s = u * u + v * v;
            if s < 1.0 && s > 0.0 {
                let f = (-2.0 * s.ln() / s).sqrt();
                return Complex::new(u * f, v * f);
            }
        }
    }
}

/// One synthesized spectral line: index `k` of `n_syn`, frequency `n = k dn` (cycles/m) and
/// power `P_k` (m^2), the integral of `G_d` over the line's cell `[n - dn/2, n + dn/2]`
/// clipped to the band.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpectralLine {
    /// FFT bin index.
    pub k: usize,
    /// Spatial frequency (cycles/m).
    pub n: f64,
    /// Variance carried by the line (m^2).
    pub power: f64,
}

/// The lines with non-zero power for a synthesis period of `n_syn` samples at `dx_m`,
/// ascending in `k`. Their powers add up to `integral_{n_min}^{n_max} G_d dn` exactly
/// (up to rounding) when `n_max` does not exceed the Nyquist frequency.
pub fn spectral_lines(spec: &TwoTrackSpec, n_syn: usize, dx_m: f64) -> Vec<SpectralLine> {
    let half = n_syn / 2;
    let dn = 1.0 / (n_syn as f64 * dx_m);
    let k_first = (spec.band.n_min / dn - 0.5).floor().max(1.0) as usize;
    let k_last = ((spec.band.n_max / dn + 0.5).ceil() as usize).min(half);
    let (alpha, w) = (spec.psd.alpha_r, spec.psd.waviness);
    // Antiderivative n^(1-w) evaluated once per cell edge (one powf per line); near w = 1,
    // where the difference of antiderivatives cancels, the exact pairwise integral is used.
    let pairwise = (1.0 - w).abs() < 1e-3;
    let mut prev: Option<(f64, f64)> = None; // (edge, edge^(1-w))
    let mut lines = Vec::with_capacity(k_last.saturating_sub(k_first) + 1);
    for k in k_first..=k_last {
        let n = k as f64 * dn;
        let lo = (n - 0.5 * dn).max(spec.band.n_min);
        let hi = if k == half {
            n.min(spec.band.n_max)
        } else {
            (n + 0.5 * dn).min(spec.band.n_max)
        };
        if hi <= lo {
            continue;
        }
        let power = if pairwise {
            spec.psd.integral(lo, hi)
        } else {
            let f_lo = match prev {
                Some((e, f)) if e == lo => f,
                _ => lo.powf(1.0 - w),
            };
            let f_hi = hi.powf(1.0 - w);
            prev = Some((hi, f_hi));
            alpha * (f_hi - f_lo) / (1.0 - w)
        };
        lines.push(SpectralLine { k, n, power });
    }
    lines
}

/// Synthesize left and right profiles of `length_m` (m) at spacing `dx_m` (m) from `seed`.
///
/// The band must lie below the Nyquist frequency `1/(2 dx)`. The same inputs give the same
/// bytes. Draw order (part of the reproducibility contract): for each line `k` inside the band,
/// ascending, three complex Gaussians `Z0, Z1, Z2` (polar method on ChaCha8 uniforms).
pub fn synthesize(
    spec: &TwoTrackSpec,
    length_m: f64,
    dx_m: f64,
    seed: u64,
) -> Result<TwoTrackProfile> {
    spec.validate()?;
    let n_out = sample_count(length_m, dx_m)?;
    let nyquist = 0.5 / dx_m;
    if spec.band.n_max > nyquist * (1.0 + 1e-12) {
        return Err(TerrainError::Parameter {
            name: "band.n_max",
            value: spec.band.n_max,
            requirement: format!(
                "must not exceed the Nyquist frequency 1/(2 dx) = {nyquist} cycles/m; reduce dx"
            ),
        });
    }
    let n_syn = synthesis_len(&spec.band, n_out, dx_m)?;
    let half = n_syn / 2;
    let mut left = vec![Complex::new(0.0, 0.0); half + 1];
    let mut right = left.clone();
    let mut gauss = Gaussian::new(seed);
    for line in spectral_lines(spec, n_syn, dx_m) {
        let gamma = spec.coherence.msc(line.n).sqrt();
        let (a, b) = (gamma.sqrt(), (1.0 - gamma).max(0.0).sqrt());
        let z0 = gauss.complex();
        let z1 = gauss.complex();
        let z2 = gauss.complex();
        let amp = line.power.sqrt();
        let mut l = (z0 * a + z1 * b) * amp;
        let mut r = (z0 * a + z2 * b) * amp;
        if line.k == half {
            // The Nyquist line is real: its coefficient carries the full variance P_k.
            l = Complex::new(l.re, 0.0);
            r = Complex::new(r.re, 0.0);
        } else {
            // x_j = sum_k 2 Re(X_k e^{i theta}) for 0 < k < N/2, so Re, Im ~ N(0, P_k/4).
            l *= 0.5;
            r *= 0.5;
        }
        left[line.k] = l;
        right[line.k] = r;
    }
    let inverse = crate::fft::inverse(n_syn);
    let mut scratch = inverse.make_scratch_vec();
    let mut out_l = vec![0.0; n_syn];
    let mut out_r = vec![0.0; n_syn];
    let fft_err = |e: realfft::FftError| TerrainError::Signal(format!("inverse FFT failed: {e}"));
    inverse
        .process_with_scratch(&mut left, &mut out_l, &mut scratch)
        .map_err(fft_err)?;
    inverse
        .process_with_scratch(&mut right, &mut out_r, &mut scratch)
        .map_err(fft_err)?;
    out_l.truncate(n_out);
    out_r.truncate(n_out);
    if out_l.iter().chain(&out_r).any(|v| !v.is_finite()) {
        return Err(TerrainError::Signal(
            "synthesized profile is not finite: alpha_r or waviness too large for this band".into(),
        ));
    }
    Ok(TwoTrackProfile {
        dx_m,
        left_m: out_l,
        right_m: out_r,
    })
}

/// One track: the left track of a fully coherent synthesis.
pub fn synthesize_track(
    psd: &PowerLawPsd,
    band: &Band,
    length_m: f64,
    dx_m: f64,
    seed: u64,
) -> Result<Vec<f64>> {
    let spec = TwoTrackSpec::new(*psd, *band, CoherenceModel::Full)?;
    Ok(synthesize(&spec, length_m, dx_m, seed)?.left_m)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_measured_profile_needs_uniform_increasing_x() {
        let p = TwoTrackProfile::from_samples(&[5.0, 5.1, 5.2], &[0.0; 3], &[0.01; 3]).unwrap();
        assert!((p.dx_m - 0.1).abs() < 1e-12 && p.len() == 3);
        let e = TwoTrackProfile::from_samples(&[0.0, 0.1, 0.3], &[0.0; 3], &[0.0; 3]);
        assert!(e.unwrap_err().to_string().contains("sample 2"));
        assert!(uniform_spacing(&[1.0, 0.5]).is_err());
        assert!(uniform_spacing(&[0.0, f64::NAN, 1.0]).is_err());
        assert!(TwoTrackProfile::from_samples(&[0.0, 1.0], &[0.0], &[0.0, 0.0]).is_err());
    }

    #[test]
    fn line_powers_integrate_the_psd_exactly() {
        for (band, dx, n_syn) in [
            (Band::PAPER, 0.05, 16000),
            (Band::new(0.013, 2.7).unwrap(), 0.05, 40500),
            (Band::new(0.5, 10.0).unwrap(), 0.05, 2000), // n_max = Nyquist
        ] {
            for psd in [
                PowerLawPsd::paper_nominal(),
                PowerLawPsd::new(3e-4, 1.6).unwrap(),
            ] {
                let spec = TwoTrackSpec::new(psd, band, CoherenceModel::PAPER).unwrap();
                let sum: f64 = spectral_lines(&spec, n_syn, dx)
                    .iter()
                    .map(|l| l.power)
                    .sum();
                let exact = spec.variance();
                assert!((sum - exact).abs() < 1e-10 * exact, "{sum} vs {exact}");
            }
        }
    }

    #[test]
    fn fast_lengths() {
        assert_eq!(next_fast_even(1), 2);
        assert_eq!(next_fast_even(7), 8);
        assert_eq!(next_fast_even(2001), 2048);
        assert_eq!(next_fast_even(16000), 16000);
        assert_eq!(next_fast_even(16001), 16200);
    }

    #[test]
    fn sample_counts_and_period() {
        assert_eq!(sample_count(100.0, 0.05).unwrap(), 2001);
        assert!(sample_count(0.0, 0.05).is_err());
        assert!(sample_count(1.0, f64::NAN).is_err());
        assert!(sample_count(1e12, 1e-3).is_err());
        // 16 / 0.02 = 800 m at 0.05 m -> 16000 samples.
        assert_eq!(synthesis_len(&Band::PAPER, 2001, 0.05).unwrap(), 16000);
        assert_eq!(synthesis_len(&Band::PAPER, 40001, 0.05).unwrap(), 40500);
    }

    #[test]
    fn uniforms_are_in_the_open_unit_interval() {
        let mut g = Gaussian::new(3);
        for _ in 0..10_000 {
            let u = g.uniform();
            assert!(u > 0.0 && u < 1.0);
        }
    }

    #[test]
    fn full_and_independent_extremes() {
        let mut spec = TwoTrackSpec::paper_nominal();
        spec.coherence = CoherenceModel::Full;
        let p = synthesize(&spec, 50.0, 0.05, 9).unwrap();
        assert_eq!(p.left_m, p.right_m);
        assert_eq!(p.len(), 1001);
        spec.coherence = CoherenceModel::Independent;
        let q = synthesize(&spec, 50.0, 0.05, 9).unwrap();
        assert_ne!(q.left_m, q.right_m);
    }

    #[test]
    fn nyquist_and_interpolation() {
        let spec = TwoTrackSpec::paper_nominal();
        // dx = 0.2 m -> Nyquist 2.5 cycles/m < 5.
        assert!(synthesize(&spec, 100.0, 0.2, 1).is_err());
        let p = synthesize(&spec, 10.0, 0.1, 1).unwrap();
        assert_eq!(p.heights_at(0.0), Some((p.left_m[0], p.right_m[0])));
        let (l, _) = p.heights_at(0.05).unwrap();
        assert!((l - 0.5 * (p.left_m[0] + p.left_m[1])).abs() < 1e-15);
        assert_eq!(p.heights_at(10.0).unwrap().0, *p.left_m.last().unwrap());
        assert!(p.heights_at(-0.1).is_none());
        assert!(p.heights_at(10.01).is_none());
        assert!(p.heights_at(f64::NAN).is_none());
    }
}
