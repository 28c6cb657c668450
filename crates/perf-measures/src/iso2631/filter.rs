//! Frequency weighting of sampled time histories.
//!
//! Two implementations of the Annex A weightings are given:
//!
//! * [`weight_fft`] (the default of [`weight_time_history`]): frequency-domain weighting.
//!   The record (mean removed, zero-padded by the filter's settling time) is transformed
//!   with a real FFT, every bin is multiplied by the exact analog response
//!   `H(j 2 pi f_k)`, and transformed back. Magnitude and phase are those of the analog
//!   weighting at every bin up to the Nyquist frequency, so the method has no warping or
//!   aliasing error at any sampling rate; the only approximation is the truncation of the
//!   impulse response tail at the pad length, below `exp(-14)` (1e-6) of its initial
//!   envelope. This is equivalent to running the analog filter on the band-limited
//!   (sinc-interpolated) signal, starting from rest after the mean was removed.
//! * [`IirWeighting`]: a causal, streaming cascade of biquads, each section of Annex A
//!   discretised by the bilinear transform pre-warped at its own characteristic frequency
//!   (`f1`, `f2`, `f4`, `sqrt(f5 f6)`). It allocates nothing per sample. Its magnitude equals
//!   the analog one at the pre-warping frequencies; elsewhere the frequency compression of
//!   the bilinear map (`f -> fs/pi tan(pi f/fs)`) adds an error that grows towards
//!   Nyquist: within 2 % of the analog weighting up to 100 Hz for `fs >= 2 kHz`
//!   (see [`super::check`] and `docs/perf-measures.md` for measured values), but
//!   only up to about `fs/8` for lower sampling rates. When `f2 >= 0.49 fs` the
//!   band-limiting low pass cannot be represented and is omitted (its analog factor is
//!   still >= 0.97 below `f2/2`).

use super::weighting::{SectionKind, Weighting, WeightingParams};
use crate::error::{finite_series, invalid, positive, MeasureError};
use realfft::num_complex::Complex64;
use realfft::RealFftPlanner;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// How a time history is weighted.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum FilterMethod {
    /// Frequency-domain weighting with the exact analog response ([`weight_fft`]).
    #[default]
    Fft,
    /// Causal bilinear-transform IIR cascade ([`IirWeighting`]).
    Iir,
}

/// One digital biquad `(b0 + b1 z^-1 + b2 z^-2) / (1 + a1 z^-1 + a2 z^-2)` in transposed
/// direct form II.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Biquad {
    /// Numerator coefficients.
    pub b: [f64; 3],
    /// Denominator coefficients `a1, a2` (`a0 = 1`).
    pub a: [f64; 2],
    s1: f64,
    s2: f64,
}

impl Biquad {
    /// Bilinear transform of the analog section `N(s)/D(s)` (ascending coefficients),
    /// `s = k (1 - z^-1)/(1 + z^-1)`.
    fn bilinear(num: [f64; 3], den: [f64; 3], k: f64) -> Self {
        let k2 = k * k;
        let z0 = |c: [f64; 3]| c[0] + c[1] * k + c[2] * k2;
        let z1 = |c: [f64; 3]| 2.0 * c[0] - 2.0 * c[2] * k2;
        let z2 = |c: [f64; 3]| c[0] - c[1] * k + c[2] * k2;
        let a0 = z0(den);
        Biquad {
            b: [z0(num) / a0, z1(num) / a0, z2(num) / a0],
            a: [z1(den) / a0, z2(den) / a0],
            s1: 0.0,
            s2: 0.0,
        }
    }

    #[inline]
    fn step(&mut self, x: f64) -> f64 {
        let y = self.b[0] * x + self.s1;
        self.s1 = self.b[1] * x - self.a[0] * y + self.s2;
        self.s2 = self.b[2] * x - self.a[1] * y;
        y
    }

    fn response(&self, z_inv: Complex64) -> Complex64 {
        let n = self.b[0] + z_inv * (self.b[1] + z_inv * self.b[2]);
        let d = 1.0 + z_inv * (self.a[0] + z_inv * self.a[1]);
        n / d
    }
}

/// Causal digital weighting filter: bilinear transform with per-section pre-warping
/// (see the module documentation for its accuracy).
#[derive(Debug, Clone, PartialEq)]
pub struct IirWeighting {
    sections: Vec<Biquad>,
    fs_hz: f64,
    omitted_low_pass: bool,
}

impl IirWeighting {
    /// Design the filter of weighting `w` for sampling rate `fs_hz`.
    pub fn new(w: Weighting, fs_hz: f64) -> Result<Self, MeasureError> {
        Self::from_params(&w.params(), fs_hz)
    }

    /// Design from explicit parameters. `fs_hz` must exceed 2.5 times every corner
    /// frequency except `f2` (the band-limiting low pass, omitted when `f2 >= 0.49 fs`).
    pub fn from_params(p: &WeightingParams, fs_hz: f64) -> Result<Self, MeasureError> {
        p.validate()?;
        positive("fs_hz", fs_hz)?;
        let highest = [p.f1_hz]
            .into_iter()
            .chain([p.f3_hz, p.f4_hz, p.f5_hz, p.f6_hz].into_iter().flatten())
            .fold(0.0, f64::max);
        if fs_hz < 2.5 * highest {
            return Err(invalid(
                "fs_hz",
                format!(
                    "sampling rate {fs_hz} Hz is too low for this weighting (needs >= {} Hz)",
                    2.5 * highest
                ),
            ));
        }
        let t = 1.0 / fs_hz;
        let mut sections = Vec::with_capacity(4);
        let mut omitted_low_pass = false;
        for sec in p.sections() {
            let f_char = sec.w_char / (2.0 * PI);
            if f_char >= 0.49 * fs_hz {
                if sec.kind == SectionKind::LowPass {
                    omitted_low_pass = true;
                    continue;
                }
                sections.push(Biquad::bilinear(sec.num, sec.den, 2.0 * fs_hz));
            } else {
                let k = sec.w_char / (sec.w_char * t / 2.0).tan();
                sections.push(Biquad::bilinear(sec.num, sec.den, k));
            }
        }
        Ok(IirWeighting {
            sections,
            fs_hz,
            omitted_low_pass,
        })
    }

    /// Sampling rate (Hz).
    pub fn fs_hz(&self) -> f64 {
        self.fs_hz
    }

    /// Whether the band-limiting low pass was omitted because `f2` is at or above Nyquist.
    pub fn omitted_low_pass(&self) -> bool {
        self.omitted_low_pass
    }

    /// The biquad sections.
    pub fn sections(&self) -> &[Biquad] {
        &self.sections
    }

    /// Zero the filter state.
    pub fn reset(&mut self) {
        for s in &mut self.sections {
            s.s1 = 0.0;
            s.s2 = 0.0;
        }
    }

    /// Filter one sample.
    #[inline]
    pub fn step(&mut self, x: f64) -> f64 {
        self.sections.iter_mut().fold(x, |v, s| s.step(v))
    }

    /// Filter a block in place, continuing from the current state (allocation-free).
    pub fn process_in_place(&mut self, x: &mut [f64]) {
        for v in x.iter_mut() {
            *v = self.step(*v);
        }
    }

    /// Complex response of the digital filter at `f_hz` (`z = exp(j 2 pi f / fs)`).
    pub fn response(&self, f_hz: f64) -> Complex64 {
        let z_inv = Complex64::from_polar(1.0, -2.0 * PI * f_hz / self.fs_hz);
        self.sections
            .iter()
            .fold(Complex64::new(1.0, 0.0), |acc, s| acc * s.response(z_inv))
    }

    /// Magnitude of the digital filter at `f_hz`.
    pub fn magnitude(&self, f_hz: f64) -> f64 {
        self.response(f_hz).norm()
    }
}

/// Smallest `n >= min` whose only prime factors are 2, 3 and 5 (fast FFT sizes).
pub fn fast_fft_len(min: usize) -> usize {
    let mut n = min.max(1);
    loop {
        let mut m = n;
        for p in [2, 3, 5] {
            while m % p == 0 {
                m /= p;
            }
        }
        if m == 1 {
            return n;
        }
        n += 1;
    }
}

/// Longest FFT (record plus settling padding) the FFT method runs: 2^25 samples.
pub const MAX_FFT_LEN: usize = 1 << 25;

/// Samples of zero padding the FFT method appends: the time for the slowest pole of the
/// weighting to decay by `exp(-14)`.
pub fn settling_samples(p: &WeightingParams, fs_hz: f64) -> usize {
    let slowest = p
        .sections()
        .iter()
        .map(|s| s.decay_rate())
        .fold(f64::INFINITY, f64::min);
    (14.0 / slowest * fs_hz).ceil() as usize
}

fn check_record(x: &[f64], fs_hz: f64) -> Result<(), MeasureError> {
    positive("fs_hz", fs_hz)?;
    finite_series("acceleration", x, 2)
}

/// Frequency-domain weighting of `x` sampled at `fs_hz` (module documentation gives the
/// method and its accuracy). The record mean is removed first (every weighting has zero
/// gain at DC, so this only removes the start-up transient of a constant offset such as
/// gravity).
pub fn weight_fft(w: Weighting, x: &[f64], fs_hz: f64) -> Result<Vec<f64>, MeasureError> {
    weight_fft_params(&w.params(), x, fs_hz)
}

/// [`weight_fft`] with explicit parameters.
pub fn weight_fft_params(
    p: &WeightingParams,
    x: &[f64],
    fs_hz: f64,
) -> Result<Vec<f64>, MeasureError> {
    p.validate()?;
    check_record(x, fs_hz)?;
    let n = x.len();
    let pad = settling_samples(p, fs_hz);
    if pad > MAX_FFT_LEN || n > MAX_FFT_LEN - pad {
        return Err(invalid(
            "fs_hz",
            format!(
                "{fs_hz:e} Hz needs {pad} samples of settling padding beside {n} samples, at most {MAX_FFT_LEN} in all (use the IIR method or resample the record)"
            ),
        ));
    }
    let len = fast_fft_len(n + pad);
    let mean = x.iter().sum::<f64>() / n as f64;
    let mut planner = RealFftPlanner::<f64>::new();
    let r2c = planner.plan_fft_forward(len);
    let c2r = planner.plan_fft_inverse(len);
    let mut buf = vec![0.0; len];
    for (b, v) in buf.iter_mut().zip(x) {
        *b = v - mean;
    }
    let mut spec = r2c.make_output_vec();
    r2c.process(&mut buf, &mut spec)
        .map_err(|e| invalid("acceleration", format!("FFT failed: {e}")))?;
    let sections = p.sections();
    let df = fs_hz / len as f64;
    let last = spec.len() - 1;
    for (k, c) in spec.iter_mut().enumerate() {
        let s = Complex64::new(0.0, 2.0 * PI * df * k as f64);
        let h = sections
            .iter()
            .fold(Complex64::new(1.0, 0.0), |acc, sec| acc * sec.response(s));
        *c *= h / len as f64;
        if k == 0 || (k == last && len % 2 == 0) {
            c.im = 0.0;
        }
    }
    c2r.process(&mut spec, &mut buf)
        .map_err(|e| invalid("acceleration", format!("inverse FFT failed: {e}")))?;
    buf.truncate(n);
    Ok(buf)
}

/// Weight `x` (sampled at `fs_hz`) with the IIR cascade, after removing the mean, starting
/// from rest.
pub fn weight_iir(w: Weighting, x: &[f64], fs_hz: f64) -> Result<Vec<f64>, MeasureError> {
    check_record(x, fs_hz)?;
    let mut f = IirWeighting::new(w, fs_hz)?;
    let mean = x.iter().sum::<f64>() / x.len() as f64;
    let mut y: Vec<f64> = x.iter().map(|v| v - mean).collect();
    f.process_in_place(&mut y);
    Ok(y)
}

/// Frequency-weighted time history of `x` (m/s^2, sampled at `fs_hz`) by `method`.
pub fn weight_time_history(
    w: Weighting,
    x: &[f64],
    fs_hz: f64,
    method: FilterMethod,
) -> Result<Vec<f64>, MeasureError> {
    match method {
        FilterMethod::Fft => weight_fft(w, x, fs_hz),
        FilterMethod::Iir => weight_iir(w, x, fs_hz),
    }
}
