//! Spectral estimators: Welch one-sided PSD, cross-spectral density, magnitude-squared
//! coherence (Eq 2.9) and the cross-slope (roll-excitation) PSD of Fig 2.7.
//!
//! Conventions (as scipy.signal.welch / csd with `scaling="density"`):
//! - segments of `segment_len` samples, `step = segment_len - round(overlap * segment_len)`,
//!   trailing samples that do not fill a segment are dropped;
//! - each segment is detrended (mean removed by default), multiplied by the window `w`
//!   (periodic Hann by default) and transformed, `X_k = sum_j w_j x_j e^{-2 pi i jk/L}`;
//! - one-sided density `G_xx(n_k) = c_k |X_k|^2 dx / sum_j w_j^2` with `c_k = 2` except at
//!   DC and Nyquist (`c_k = 1`), `n_k = k / (L dx)` cycles/m, averaged over segments.
//!   With this scaling `sum_k G_xx(n_k) dn` equals the window-weighted mean square of the
//!   segments (Parseval), i.e. the variance of a zero-mean stationary signal;
//! - cross-spectrum `G_xy = c_k conj(X_k) Y_k dx / sum w^2`; coherence
//!   `gamma^2 = |G_xy|^2 / (G_xx G_yy)` (0 where `G_xx G_yy = 0`).

use crate::error::{positive, Result, TerrainError};
use realfft::num_complex::Complex;
use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;

/// Shortest segment accepted (samples).
pub const MIN_SEGMENT: usize = 8;

/// Segment window.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum Window {
    /// Periodic (DFT-even) Hann window `w_j = 0.5 - 0.5 cos(2 pi j / L)`.
    #[default]
    Hann,
    /// No window (boxcar).
    Rectangular,
}

impl Window {
    /// The `len` window samples.
    pub fn samples(self, len: usize) -> Vec<f64> {
        match self {
            Window::Hann => (0..len)
                .map(|j| 0.5 - 0.5 * (std::f64::consts::TAU * j as f64 / len as f64).cos())
                .collect(),
            Window::Rectangular => vec![1.0; len],
        }
    }
}

impl FromStr for Window {
    type Err = TerrainError;
    fn from_str(s: &str) -> Result<Self> {
        match s.trim().to_ascii_lowercase().as_str() {
            "hann" | "hanning" => Ok(Window::Hann),
            "rect" | "rectangular" | "boxcar" | "none" => Ok(Window::Rectangular),
            _ => Err(TerrainError::Unknown {
                what: "window",
                given: s.to_string(),
                expected: "hann, rectangular",
            }),
        }
    }
}

impl fmt::Display for Window {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Window::Hann => "hann",
            Window::Rectangular => "rectangular",
        })
    }
}

/// Per-segment detrending before windowing.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum Detrend {
    /// Use the samples as they are.
    None,
    /// Remove the segment mean.
    #[default]
    Mean,
    /// Remove the least-squares straight line.
    Linear,
}

impl FromStr for Detrend {
    type Err = TerrainError;
    fn from_str(s: &str) -> Result<Self> {
        match s.trim().to_ascii_lowercase().as_str() {
            "none" => Ok(Detrend::None),
            "mean" | "constant" => Ok(Detrend::Mean),
            "linear" => Ok(Detrend::Linear),
            _ => Err(TerrainError::Unknown {
                what: "detrend",
                given: s.to_string(),
                expected: "none, mean, linear",
            }),
        }
    }
}

impl fmt::Display for Detrend {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Detrend::None => "none",
            Detrend::Mean => "mean",
            Detrend::Linear => "linear",
        })
    }
}

/// Welch estimator settings.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct WelchConfig {
    /// Segment length (samples), >= [`MIN_SEGMENT`] and <= the signal length.
    pub segment_len: usize,
    /// Fractional overlap of consecutive segments, `0 <= overlap < 1` (0.5 by default).
    pub overlap: f64,
    /// Window applied to each segment.
    pub window: Window,
    /// Detrending of each segment.
    pub detrend: Detrend,
}

impl WelchConfig {
    /// Hann window, 50 % overlap, mean removed, `segment_len` samples.
    pub fn new(segment_len: usize) -> Self {
        Self {
            segment_len,
            overlap: 0.5,
            window: Window::Hann,
            detrend: Detrend::Mean,
        }
    }

    /// Segment of `round(segment_m / dx)` samples.
    pub fn with_segment_m(segment_m: f64, dx_m: f64) -> Result<Self> {
        positive("segment", segment_m)?;
        positive("dx", dx_m)?;
        let len = (segment_m / dx_m).round();
        if !len.is_finite() || len < MIN_SEGMENT as f64 || len >= u32::MAX as f64 {
            return Err(TerrainError::Parameter {
                name: "segment",
                value: segment_m,
                requirement: format!("must span at least {MIN_SEGMENT} samples of dx = {dx_m} m"),
            });
        }
        Ok(Self::new(len as usize))
    }

    /// Default segment for `n_samples`: the largest power of two <= `n_samples / 8` (>= 15
    /// half-overlapping segments, so that the coherence bias `~(1 - gamma^2)^2 / K` stays
    /// below ~0.05), at least [`MIN_SEGMENT`].
    pub fn auto(n_samples: usize) -> Result<Self> {
        if n_samples < MIN_SEGMENT {
            return Err(TerrainError::Signal(format!(
                "signal has {n_samples} samples; at least {MIN_SEGMENT} are needed"
            )));
        }
        let eighth = (n_samples / 8).max(MIN_SEGMENT);
        let mut len = MIN_SEGMENT;
        while len * 2 <= eighth {
            len *= 2;
        }
        Ok(Self::new(len.min(n_samples)))
    }

    /// Samples between consecutive segment starts (>= 1).
    pub fn step(&self) -> usize {
        let ov = (self.overlap * self.segment_len as f64).round() as usize;
        self.segment_len.saturating_sub(ov).max(1)
    }

    /// Number of segments in a signal of `n_samples`.
    pub fn segment_count(&self, n_samples: usize) -> usize {
        if n_samples < self.segment_len || self.segment_len == 0 {
            0
        } else {
            (n_samples - self.segment_len) / self.step() + 1
        }
    }

    /// Check the settings against a signal of `n_samples`.
    pub fn validate(&self, n_samples: usize) -> Result<()> {
        if !(self.overlap.is_finite() && (0.0..1.0).contains(&self.overlap)) {
            return Err(TerrainError::Parameter {
                name: "overlap",
                value: self.overlap,
                requirement: "must satisfy 0 <= overlap < 1".into(),
            });
        }
        if self.segment_len < MIN_SEGMENT {
            return Err(TerrainError::Signal(format!(
                "segment of {} samples is too short; at least {MIN_SEGMENT} are needed",
                self.segment_len
            )));
        }
        if self.segment_len > n_samples {
            return Err(TerrainError::Signal(format!(
                "segment of {} samples is longer than the signal ({n_samples} samples)",
                self.segment_len
            )));
        }
        Ok(())
    }
}

/// A one-sided spectral density on `freq` (cycles/m when the spacing is in m).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Spectrum {
    /// Frequencies `k / (L dx)`, `k = 0..=L/2`.
    pub freq: Vec<f64>,
    /// One-sided density (signal unit^2 per frequency unit).
    pub psd: Vec<f64>,
    /// Frequency resolution `1 / (L dx)`.
    pub df: f64,
    /// Number of averaged segments.
    pub segments: usize,
}

impl Spectrum {
    /// `sum_k psd_k df`: by Parseval, the mean square of the (detrended, windowed) segments.
    pub fn integral(&self) -> f64 {
        self.psd.iter().sum::<f64>() * self.df
    }
}

/// Auto-, cross-spectra and coherence of two signals.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CrossSpectrum {
    /// Frequencies `k / (L dx)`.
    pub freq: Vec<f64>,
    /// One-sided PSD of x.
    pub pxx: Vec<f64>,
    /// One-sided PSD of y.
    pub pyy: Vec<f64>,
    /// Real part of the one-sided cross-spectral density `G_xy` (conj(X) Y convention).
    pub csd_re: Vec<f64>,
    /// Imaginary part of `G_xy`.
    pub csd_im: Vec<f64>,
    /// Magnitude-squared coherence `|G_xy|^2 / (G_xx G_yy)` (Eq 2.9), 0 where undefined.
    pub coherence: Vec<f64>,
    /// Frequency resolution.
    pub df: f64,
    /// Number of averaged segments.
    pub segments: usize,
}

fn check_signal(name: &str, x: &[f64]) -> Result<()> {
    if let Some(i) = x.iter().position(|v| !v.is_finite()) {
        return Err(TerrainError::Signal(format!(
            "{name}: sample {i} is not finite ({})",
            x[i]
        )));
    }
    Ok(())
}

fn detrend(buf: &mut [f64], how: Detrend) {
    let n = buf.len() as f64;
    match how {
        Detrend::None => {}
        Detrend::Mean => {
            let m = buf.iter().sum::<f64>() / n;
            buf.iter_mut().for_each(|v| *v -= m);
        }
        Detrend::Linear => {
            let tm = (n - 1.0) / 2.0;
            let ym = buf.iter().sum::<f64>() / n;
            let (mut sty, mut stt) = (0.0, 0.0);
            for (j, v) in buf.iter().enumerate() {
                let t = j as f64 - tm;
                sty += t * (v - ym);
                stt += t * t;
            }
            let slope = if stt > 0.0 { sty / stt } else { 0.0 };
            for (j, v) in buf.iter_mut().enumerate() {
                *v -= ym + slope * (j as f64 - tm);
            }
        }
    }
}

/// Windowed, detrended segment transforms shared by the estimators.
struct Segmenter {
    cfg: WelchConfig,
    window: Vec<f64>,
    fft: std::sync::Arc<dyn realfft::RealToComplex<f64>>,
    input: Vec<f64>,
    scratch: Vec<Complex<f64>>,
    /// One-sided density scale per bin: `c_k dx / sum w^2`.
    scale: Vec<f64>,
    freq: Vec<f64>,
    df: f64,
}

impl Segmenter {
    fn new(cfg: WelchConfig, n_samples: usize, dx: f64) -> Result<Self> {
        positive("dx", dx)?;
        cfg.validate(n_samples)?;
        let l = cfg.segment_len;
        let window = cfg.window.samples(l);
        let s2: f64 = window.iter().map(|w| w * w).sum();
        let fft = crate::fft::forward(l);
        let nb = l / 2 + 1;
        let scale = (0..nb)
            .map(|k| {
                let c = if k == 0 || (l % 2 == 0 && k == l / 2) {
                    1.0
                } else {
                    2.0
                };
                c * dx / s2
            })
            .collect();
        let df = 1.0 / (l as f64 * dx);
        Ok(Self {
            cfg,
            window,
            input: fft.make_input_vec(),
            scratch: fft.make_scratch_vec(),
            fft,
            scale,
            freq: (0..nb).map(|k| k as f64 * df).collect(),
            df,
        })
    }

    fn transform(&mut self, seg: &[f64], out: &mut [Complex<f64>]) -> Result<()> {
        self.input.copy_from_slice(seg);
        detrend(&mut self.input, self.cfg.detrend);
        for (v, w) in self.input.iter_mut().zip(&self.window) {
            *v *= w;
        }
        self.fft
            .process_with_scratch(&mut self.input, out, &mut self.scratch)
            .map_err(|e| TerrainError::Signal(format!("FFT failed: {e}")))
    }
}

/// Welch one-sided PSD of `x` sampled at spacing `dx`.
pub fn welch_psd(x: &[f64], dx: f64, cfg: &WelchConfig) -> Result<Spectrum> {
    check_signal("signal", x)?;
    let mut seg = Segmenter::new(*cfg, x.len(), dx)?;
    let mut spec = seg.fft.make_output_vec();
    let mut acc = vec![0.0; spec.len()];
    let count = cfg.segment_count(x.len());
    for s in 0..count {
        let start = s * cfg.step();
        seg.transform(&x[start..start + cfg.segment_len], &mut spec)?;
        for (a, c) in acc.iter_mut().zip(&spec) {
            *a += c.norm_sqr();
        }
    }
    let psd = acc
        .iter()
        .zip(&seg.scale)
        .map(|(a, s)| a * s / count as f64)
        .collect();
    Ok(Spectrum {
        freq: seg.freq,
        psd,
        df: seg.df,
        segments: count,
    })
}

/// Welch auto-spectra, cross-spectral density and magnitude-squared coherence of `x`, `y`.
pub fn cross_spectrum(x: &[f64], y: &[f64], dx: f64, cfg: &WelchConfig) -> Result<CrossSpectrum> {
    if x.len() != y.len() {
        return Err(TerrainError::Signal(format!(
            "signals differ in length ({} and {} samples)",
            x.len(),
            y.len()
        )));
    }
    check_signal("left/x signal", x)?;
    check_signal("right/y signal", y)?;
    let mut seg = Segmenter::new(*cfg, x.len(), dx)?;
    let mut sx = seg.fft.make_output_vec();
    let mut sy = seg.fft.make_output_vec();
    let nb = sx.len();
    let (mut axx, mut ayy) = (vec![0.0; nb], vec![0.0; nb]);
    let mut axy = vec![Complex::new(0.0, 0.0); nb];
    let count = cfg.segment_count(x.len());
    for s in 0..count {
        let start = s * cfg.step();
        seg.transform(&x[start..start + cfg.segment_len], &mut sx)?;
        seg.transform(&y[start..start + cfg.segment_len], &mut sy)?;
        for k in 0..nb {
            axx[k] += sx[k].norm_sqr();
            ayy[k] += sy[k].norm_sqr();
            axy[k] += sx[k].conj() * sy[k];
        }
    }
    let c = count as f64;
    let pxx: Vec<f64> = (0..nb).map(|k| axx[k] * seg.scale[k] / c).collect();
    let pyy: Vec<f64> = (0..nb).map(|k| ayy[k] * seg.scale[k] / c).collect();
    let pxy: Vec<Complex<f64>> = (0..nb).map(|k| axy[k] * (seg.scale[k] / c)).collect();
    let coherence = (0..nb)
        .map(|k| {
            let d = pxx[k] * pyy[k];
            if d > 0.0 {
                (pxy[k].norm_sqr() / d).min(1.0)
            } else {
                0.0
            }
        })
        .collect();
    Ok(CrossSpectrum {
        freq: seg.freq,
        pxx,
        pyy,
        csd_re: pxy.iter().map(|z| z.re).collect(),
        csd_im: pxy.iter().map(|z| z.im).collect(),
        coherence,
        df: seg.df,
        segments: count,
    })
}

/// Welch PSD of the cross-slope angle `(left - right) / track_width` (rad^2/(cycle/m)): the
/// terrain roll excitation of Fig 2.7.
pub fn cross_slope_psd(
    left: &[f64],
    right: &[f64],
    dx: f64,
    track_width_m: f64,
    cfg: &WelchConfig,
) -> Result<Spectrum> {
    positive("track_width", track_width_m)?;
    if left.len() != right.len() {
        return Err(TerrainError::Signal(format!(
            "tracks differ in length ({} and {} samples)",
            left.len(),
            right.len()
        )));
    }
    let slope: Vec<f64> = left
        .iter()
        .zip(right)
        .map(|(l, r)| (l - r) / track_width_m)
        .collect();
    welch_psd(&slope, dx, cfg)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sine_amplitude_and_parseval() {
        // A sine of amplitude 2 at an exact bin: the PSD integral is A^2/2 = 2.
        let dx = 0.1;
        let l = 256;
        let f0 = 20.0 / (l as f64 * dx);
        let x: Vec<f64> = (0..4096)
            .map(|j| 2.0 * (std::f64::consts::TAU * f0 * j as f64 * dx).sin())
            .collect();
        for window in [Window::Hann, Window::Rectangular] {
            let cfg = WelchConfig {
                window,
                ..WelchConfig::new(l)
            };
            let s = welch_psd(&x, dx, &cfg).unwrap();
            assert!(
                (s.integral() - 2.0).abs() < 1e-9,
                "{window}: {}",
                s.integral()
            );
            let kmax = (0..s.psd.len())
                .max_by(|a, b| s.psd[*a].total_cmp(&s.psd[*b]))
                .unwrap();
            assert!((s.freq[kmax] - f0).abs() < 1e-12);
        }
    }

    #[test]
    fn white_noise_level_and_coherence_of_identical_signals() {
        let mut g = crate::synth::Gaussian::new(11);
        let x: Vec<f64> = (0..65536).map(|_| g.complex().re).collect();
        let dx = 0.5; // one-sided white density = 2 sigma^2 dx = 1.0
        let s = welch_psd(&x, dx, &WelchConfig::new(512)).unwrap();
        let mid = &s.psd[10..250];
        let mean = mid.iter().sum::<f64>() / mid.len() as f64;
        assert!((mean - 1.0).abs() < 0.03, "{mean}");
        let c = cross_spectrum(&x, &x, dx, &WelchConfig::new(512)).unwrap();
        assert!(c.coherence[1..].iter().all(|v| (v - 1.0).abs() < 1e-9));
        assert!(c.csd_im.iter().all(|v| v.abs() < 1e-12));
        let neg: Vec<f64> = x.iter().map(|v| -v).collect();
        let c = cross_spectrum(&x, &neg, dx, &WelchConfig::new(512)).unwrap();
        assert!(c.coherence[1..].iter().all(|v| (v - 1.0).abs() < 1e-9));
    }

    #[test]
    fn detrending() {
        let mut v: Vec<f64> = (0..10).map(|j| 3.0 + 0.5 * j as f64).collect();
        detrend(&mut v, Detrend::Linear);
        assert!(v.iter().all(|e| e.abs() < 1e-12));
        let mut v = vec![2.0; 8];
        detrend(&mut v, Detrend::Mean);
        assert!(v.iter().all(|e| e.abs() < 1e-15));
    }

    #[test]
    fn config_checks() {
        assert_eq!(WelchConfig::auto(2001).unwrap().segment_len, 128);
        assert_eq!(WelchConfig::auto(40001).unwrap().segment_len, 4096);
        assert_eq!(WelchConfig::auto(8).unwrap().segment_len, 8);
        assert!(WelchConfig::auto(7).is_err());
        let x = vec![0.0; 100];
        assert!(welch_psd(&x, 0.1, &WelchConfig::new(200)).is_err());
        assert!(welch_psd(&x, 0.1, &WelchConfig::new(4)).is_err());
        assert!(welch_psd(&x, 0.0, &WelchConfig::new(16)).is_err());
        let bad = WelchConfig {
            overlap: 1.0,
            ..WelchConfig::new(16)
        };
        assert!(welch_psd(&x, 0.1, &bad).is_err());
        let mut y = x.clone();
        y[3] = f64::NAN;
        assert!(welch_psd(&y, 0.1, &WelchConfig::new(16)).is_err());
        assert!(cross_spectrum(&x, &x[..50], 0.1, &WelchConfig::new(16)).is_err());
        assert_eq!(WelchConfig::new(16).segment_count(100), 11);
        assert!(WelchConfig::with_segment_m(0.1, 0.05).is_err());
        assert_eq!(
            WelchConfig::with_segment_m(51.2, 0.05).unwrap().segment_len,
            1024
        );
    }
}
