//! Free-decay single-DOF fit of a yaw (articulation-angle) oscillation (sections 3.3,
//! 4.3.1 and 6.4: yaw-mode natural frequency and damping ratio "assuming single-DOF
//! system response").
//!
//! Model, with `tau = t - t[0]` (the record must start at the free-decay onset):
//!
//! `y(tau) = c + exp(-sigma tau) (a cos(wd tau) + b sin(wd tau))
//!         = c + A exp(-zeta wn tau) cos(wd tau + phi)`,
//!
//! `sigma = zeta wn`, `wd = wn sqrt(1 - zeta^2)`. The five parameters `(c, a, b, sigma, wd)`
//! are fitted by bounded Levenberg-Marquardt ([`optimize::least_squares::fit`]). The start
//! is chosen robustly: the FFT peak of the (uniformly resampled, zero-padded) record gives a
//! first `wd`; a grid over `wd` (0.35 to 2.8 times it) and `zeta` (-0.1 to 0.9) is scored by
//! variable projection (the linear parameters `c, a, b` solved exactly at each grid point);
//! zero crossings and the logarithmic decrement of successive extrema about the best grid
//! offset give one more candidate; LM is run from the three best candidates and the
//! smallest residual wins. The free offset `c` makes the fit insensitive to a non-zero
//! final value; negative `zeta` (growing oscillation, snaking) is allowed.

use crate::error::{finite_series, same_len, time_series, MeasureError};
use optimize::least_squares::{fit, FitOptions, Problem};
use realfft::RealFftPlanner;
use serde::Serialize;
use std::f64::consts::PI;

/// Start of the free decay: the second extremum of the articulation after the pulse end,
/// i.e. after the first, input-driven swing (section 3.4.2: "following the initial
/// oscillation caused by the steering input"). Returns the index into `time` and `y`, or
/// `None` when fewer than two extrema follow `pulse_end_s`; the fit of [`fit_free_decay`]
/// starts there.
pub fn decay_onset(time: &[f64], y: &[f64], pulse_end_s: f64) -> Option<usize> {
    let i0 = time.partition_point(|&x| x < pulse_end_s - 1e-12).max(1);
    let mut found = 0;
    for i in i0..y.len().saturating_sub(1) {
        let d0 = y[i] - y[i - 1];
        let d1 = y[i + 1] - y[i];
        if d0 * d1 < 0.0 || (d0 != 0.0 && d1 == 0.0) {
            found += 1;
            if found == 2 {
                return Some(i);
            }
        }
    }
    None
}

/// Result of [`fit_free_decay`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DecayFit {
    /// Undamped natural frequency `wn / 2 pi` (Hz).
    pub natural_frequency_hz: f64,
    /// Damped frequency `wd / 2 pi` (Hz).
    pub damped_frequency_hz: f64,
    /// Damping ratio `zeta` (negative for a growing oscillation).
    pub damping_ratio: f64,
    /// Initial amplitude `A` of the oscillation (units of `y`).
    pub amplitude: f64,
    /// Final value `c` the oscillation decays to (units of `y`).
    pub offset: f64,
    /// Root-mean-square residual (units of `y`).
    pub rmse: f64,
    /// Phase `phi` at the first sample (rad).
    pub phase_rad: f64,
    /// Decay rate `sigma = zeta wn` (1/s).
    pub decay_rate_1_s: f64,
    /// Standard error of the natural frequency (Hz), from the fit covariance.
    pub natural_frequency_std_hz: f64,
    /// Standard error of the damping ratio.
    pub damping_ratio_std: f64,
    /// Coefficient of determination of the fit.
    pub r_squared: f64,
    /// Number of damped cycles the record covers.
    pub cycles: f64,
    /// Levenberg-Marquardt iterations of the winning start.
    pub iterations: usize,
    /// Whether LM met its convergence test.
    pub converged: bool,
    /// Measurement-noise RMS read from the record itself (fourth differences, robust
    /// spread; `optimize::noise::measurement_noise_variance`), floored at 0.1 % of its
    /// range (units of `y`).
    pub noise_rms: f64,
}

/// A decay fit's RMS residual above this multiple of the record's noise RMS leaves a
/// response the single-mode decay does not describe (a second mode, a nonlinearity, a
/// wrong window).
pub const DECAY_RESIDUAL_NOISE_LIMIT: f64 = 3.0;

/// The caveat of a fit whose RMS residual is `residual_to_noise` times the record's noise
/// (None within [`DECAY_RESIDUAL_NOISE_LIMIT`], or when the ratio is not finite): the
/// response is not one decaying mode, so the fitted frequency and damping depend on the
/// window. For design measures of a model's own response, which keep their numbers.
pub fn not_one_mode(residual_to_noise: f64) -> Option<String> {
    (residual_to_noise.is_finite() && residual_to_noise > DECAY_RESIDUAL_NOISE_LIMIT).then(|| {
        format!(
            "the single-mode decay fit leaves a residual {residual_to_noise:.0}x the record's noise, so the free response is not one decaying mode and the fitted frequency and damping depend on the window"
        )
    })
}

/// Fewer damped cycles than this leave the damping ratio poorly determined.
pub const DECAY_MIN_CYCLES: f64 = 1.5;

impl DecayFit {
    /// What keeps this fit from being a measurement, one sentence each (empty when the fit
    /// earned its numbers): no convergence, a residual far above the record's noise, too few
    /// cycles, or a damping ratio whose standard error exceeds half its value.
    pub fn problems(&self) -> Vec<String> {
        let mut out = Vec::new();
        if !self.converged {
            out.push(format!(
                "the decay fit met no convergence test in {} iterations",
                self.iterations
            ));
        }
        if self.rmse > DECAY_RESIDUAL_NOISE_LIMIT * self.noise_rms {
            out.push(format!(
                "the residual ({:.4e} RMS) is {:.1} times the noise the record shows ({:.4e} RMS): the response is not one decaying mode over this window (another mode, a nonlinearity, or the window starts before the input ends)",
                self.rmse,
                self.rmse / self.noise_rms,
                self.noise_rms
            ));
        }
        if self.cycles < DECAY_MIN_CYCLES {
            out.push(format!(
                "the window covers {:.2} damped cycles (need {DECAY_MIN_CYCLES} for a damping ratio)",
                self.cycles
            ));
        }
        let determined = self.damping_ratio_std <= 0.5 * self.damping_ratio.abs();
        if !determined {
            out.push(format!(
                "the damping ratio {:.4} has a standard error of {:.4}: not determined by this record",
                self.damping_ratio, self.damping_ratio_std
            ));
        }
        out
    }
}

struct DecayProblem<'a> {
    tau: &'a [f64],
    y: &'a [f64],
    /// Spacing of `tau` when uniform ([`uniform_spacing`]).
    h: Option<f64>,
}

/// Samples between two exact evaluations of the damped phasor in [`Phasors`].
const PHASOR_BLOCK: usize = 64;

/// The damped phasor `exp(-sigma tau) (cos(wd tau), sin(wd tau))` at every `tau`. On a
/// uniform grid (spacing `h`) it is advanced by one complex multiplication per sample,
/// `z(tau + h) = z(tau) exp((-sigma + i wd) h)`, and evaluated exactly every
/// [`PHASOR_BLOCK`] samples, so rounding cannot accumulate (relative error ~1e-14); on any
/// other grid every sample is evaluated exactly. The grid scores and the Levenberg-Marquardt
/// residuals of the fit evaluate the phasor at 600 samples hundreds of times, and the
/// recurrence replaces an `exp` and a `sin_cos` per sample by four multiplications.
fn for_each_phasor(
    tau: &[f64],
    uniform_h: Option<f64>,
    sigma: f64,
    wd: f64,
    mut f: impl FnMut(usize, f64, f64),
) {
    let exact = |t: f64| {
        let e = (-sigma * t).exp();
        let (s, c) = (wd * t).sin_cos();
        (e * c, e * s)
    };
    match uniform_h {
        Some(h) => {
            let (step_re, step_im) = exact(h);
            let (mut re, mut im) = (0.0, 0.0);
            for (i, &t) in tau.iter().enumerate() {
                if i % PHASOR_BLOCK == 0 {
                    (re, im) = exact(t);
                } else {
                    (re, im) = (re * step_re - im * step_im, re * step_im + im * step_re);
                }
                f(i, re, im);
            }
        }
        None => {
            for (i, &t) in tau.iter().enumerate() {
                let (re, im) = exact(t);
                f(i, re, im);
            }
        }
    }
}

/// The spacing of `tau` when it is uniform (every sample within 1e-9 spacings of
/// `i h`), else `None`.
fn uniform_spacing(tau: &[f64]) -> Option<f64> {
    let n = tau.len();
    if n < 2 {
        return None;
    }
    let h = (tau[n - 1] - tau[0]) / (n - 1) as f64;
    let uniform = h > 0.0
        && tau
            .iter()
            .enumerate()
            .all(|(i, &t)| (t - tau[0] - i as f64 * h).abs() <= 1e-9 * h);
    uniform.then_some(h)
}

impl Problem for DecayProblem<'_> {
    fn n_params(&self) -> usize {
        5
    }
    fn n_residuals(&self) -> usize {
        self.y.len()
    }
    fn residuals(&self, p: &[f64], r: &mut [f64]) -> Result<(), String> {
        for_each_phasor(self.tau, self.h, p[3], p[4], |i, ec, es| {
            r[i] = p[0] + p[1] * ec + p[2] * es - self.y[i];
        });
        if r.iter().all(|v| v.is_finite()) {
            Ok(())
        } else {
            Err("model overflow".into())
        }
    }
}

/// Variable projection at fixed `(sigma, wd)`: least-squares `c, a, b` and the RSS
/// (`yy` = the sum of `y^2`).
fn projected(
    tau: &[f64],
    y: &[f64],
    yy: f64,
    h: Option<f64>,
    sigma: f64,
    wd: f64,
) -> Option<([f64; 3], f64)> {
    let mut m = [[0.0f64; 3]; 3];
    let mut rhs = [0.0f64; 3];
    for_each_phasor(tau, h, sigma, wd, |k, ec, es| {
        let g = [1.0, ec, es];
        for i in 0..3 {
            rhs[i] += g[i] * y[k];
            for j in i..3 {
                m[i][j] += g[i] * g[j];
            }
        }
    });
    m[1][0] = m[0][1];
    m[2][0] = m[0][2];
    m[2][1] = m[1][2];
    let x = solve3(m, rhs)?;
    // At the least-squares solution (M x = G'y) the residual sum of squares is
    // y'y - x'G'y: no second pass over the samples. It only ranks grid points, so the
    // cancellation of a near-perfect fit (relative error ~1e-16 y'y / rss) does not matter.
    let rss = (yy - (x[0] * rhs[0] + x[1] * rhs[1] + x[2] * rhs[2])).max(0.0);
    Some((x, rss))
}

fn solve3(m: [[f64; 3]; 3], r: [f64; 3]) -> Option<[f64; 3]> {
    let det = |a: [[f64; 3]; 3]| {
        a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
            - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
            + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])
    };
    let d = det(m);
    let scale = m[0][0] * m[1][1] * m[2][2];
    if d.abs() <= 1e-12 * scale.abs() || !d.is_finite() {
        return None;
    }
    let mut x = [0.0; 3];
    for (k, xk) in x.iter_mut().enumerate() {
        let mut a = m;
        for i in 0..3 {
            a[i][k] = r[i];
        }
        *xk = det(a) / d;
    }
    Some(x)
}

/// FFT-peak estimate of the dominant angular frequency (rad/s), ignoring frequencies below
/// half a cycle per record. Non-uniform records are linearly resampled first.
fn fft_peak_omega(tau: &[f64], y: &[f64]) -> Option<f64> {
    let n = tau.len();
    let duration = tau[n - 1];
    let dt = duration / (n - 1) as f64;
    let mut j = 0;
    let mean = y.iter().sum::<f64>() / n as f64;
    let mut u: Vec<f64> = (0..n)
        .map(|i| {
            let t = i as f64 * dt;
            while j + 2 < n && tau[j + 1] < t {
                j += 1;
            }
            let f = ((t - tau[j]) / (tau[j + 1] - tau[j])).clamp(0.0, 1.0);
            y[j] + f * (y[j + 1] - y[j]) - mean
        })
        .collect();
    let len = crate::iso2631::filter::fast_fft_len(8 * n);
    u.resize(len, 0.0);
    let mut planner = RealFftPlanner::<f64>::new();
    let r2c = planner.plan_fft_forward(len);
    let mut spec = r2c.make_output_vec();
    r2c.process(&mut u, &mut spec).ok()?;
    let df = 1.0 / (len as f64 * dt);
    let k_min = ((0.5 / duration) / df).ceil().max(1.0) as usize;
    let mags: Vec<f64> = spec.iter().map(|c| c.norm()).collect();
    let k = (k_min..mags.len() - 1).max_by(|&a, &b| mags[a].total_cmp(&mags[b]))?;
    let (a, b, c) = (mags[k - 1], mags[k], mags[k + 1]);
    let den = a - 2.0 * b + c;
    let shift = if den != 0.0 { 0.5 * (a - c) / den } else { 0.0 };
    Some(2.0 * PI * (k as f64 + shift.clamp(-0.5, 0.5)) * df)
}

/// Zero crossings of `y - c` give the damped period; the log decrement of the alternating
/// extrema between them gives `zeta`.
fn zero_crossing_estimate(tau: &[f64], y: &[f64], c: f64) -> Option<(f64, f64)> {
    let mut crossings = Vec::new();
    for i in 0..tau.len() - 1 {
        let (a, b) = (y[i] - c, y[i + 1] - c);
        if a == 0.0 || a * b < 0.0 {
            crossings.push(tau[i] + (tau[i + 1] - tau[i]) * a / (a - b));
        }
    }
    if crossings.len() < 2 {
        return None;
    }
    let half = (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as f64;
    let wd = PI / half;
    // Extrema between successive crossings.
    let mut ext = Vec::new();
    let mut start = 0;
    for &tc in &crossings {
        let end = tau.partition_point(|&t| t <= tc);
        if end > start {
            let m = y[start..end]
                .iter()
                .map(|v| (v - c).abs())
                .fold(0.0, f64::max);
            ext.push(m);
        }
        start = end;
    }
    let logs: Vec<f64> = ext
        .windows(2)
        .filter(|w| w[0] > 0.0 && w[1] > 0.0)
        .map(|w| (w[0] / w[1]).ln())
        .collect();
    let delta = if logs.is_empty() {
        0.0
    } else {
        2.0 * logs.iter().sum::<f64>() / logs.len() as f64
    };
    let zeta = delta / (4.0 * PI * PI + delta * delta).sqrt();
    Some((wd, zeta.clamp(-0.3, 0.95)))
}

/// The samples `i0..i1` of a free decay to fit: from the first sample at or after `start_s`
/// (default: the sample of the largest deviation from the final value, the mean of the last
/// 10 % up to `end_s`) to the last sample at or before `end_s` (default: the end). A window
/// that holds fewer than two samples, a non-finite bound, or columns of unequal length is
/// an error naming `start_s`/`end_s`, never a panic.
pub fn decay_window(
    t: &[f64],
    y: &[f64],
    start_s: Option<f64>,
    end_s: Option<f64>,
) -> Result<std::ops::Range<usize>, MeasureError> {
    same_len("t", t, "y", y)?;
    for (field, v) in [("start_s", start_s), ("end_s", end_s)] {
        if let Some(v) = v.filter(|v| !v.is_finite()) {
            return Err(crate::error::invalid(
                field,
                format!("must be finite, got {v}"),
            ));
        }
    }
    let empty = |field: &'static str| {
        let show = |v: Option<f64>, d: &str| v.map_or(d.to_string(), |v| v.to_string());
        crate::error::invalid(
            field,
            format!(
                "the window [{}, {}] s holds fewer than 2 samples (the record spans {} to {} s)",
                show(start_s, "start"),
                show(end_s, "end"),
                show(t.first().copied(), "-"),
                show(t.last().copied(), "-"),
            ),
        )
    };
    let i1 = match end_s {
        Some(e) => t.partition_point(|&v| v <= e),
        None => t.len(),
    };
    if i1 < 2 {
        return Err(empty(if end_s.is_some() { "end_s" } else { "t" }));
    }
    let i0 = match start_s {
        Some(s) => t.partition_point(|&v| v < s),
        None => {
            let n_tail = (i1 / 10).max(1);
            let fin = y[i1 - n_tail..i1].iter().sum::<f64>() / n_tail as f64;
            (0..i1)
                .max_by(|&a, &b| (y[a] - fin).abs().total_cmp(&(y[b] - fin).abs()))
                .unwrap_or(0)
        }
    };
    if i1 <= i0 + 1 {
        return Err(empty(if start_s.is_some() {
            "start_s"
        } else {
            "end_s"
        }));
    }
    Ok(i0..i1)
}

/// Fit the single-DOF free decay `y = offset + A exp(-zeta wn t) cos(wd t + phi)` to a
/// history `(t, y)` that starts at the free-decay onset (see the module documentation).
/// Needs at least 8 samples covering at least half a damped cycle.
pub fn fit_free_decay(t: &[f64], y: &[f64]) -> Result<DecayFit, MeasureError> {
    time_series(t, 8)?;
    same_len("t", t, "y", y)?;
    finite_series("y", y, 8)?;
    let n = t.len();
    let tau: Vec<f64> = t.iter().map(|v| v - t[0]).collect();
    let h = uniform_spacing(&tau);
    let yy: f64 = y.iter().map(|v| v * v).sum();
    let duration = tau[n - 1];
    let mean = y.iter().sum::<f64>() / n as f64;
    let sst: f64 = y.iter().map(|v| (v - mean).powi(2)).sum();
    if sst.is_nan() || sst <= 0.0 {
        return Err(MeasureError::Fit("the record is constant".into()));
    }
    let min_dt = tau
        .windows(2)
        .map(|w| w[1] - w[0])
        .fold(f64::INFINITY, f64::min);
    let w_nyq = PI / min_dt;
    let w_lo = PI / (2.0 * duration);
    let w_fft = fft_peak_omega(&tau, y).unwrap_or(2.0 * PI / duration);

    // Variable-projection grid.
    let zetas = [
        -0.1, -0.03, 0.0, 0.03, 0.06, 0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9,
    ];
    let mut cands: Vec<(f64, [f64; 5])> = Vec::new();
    let n_w = 33;
    for iw in 0..n_w {
        let wd = w_fft * 2f64.powf(-1.5 + 3.0 * iw as f64 / (n_w - 1) as f64);
        if wd < w_lo || wd > 0.5 * w_nyq {
            continue;
        }
        for &z in &zetas {
            let sigma = z * wd / (1.0 - z * z).sqrt();
            if let Some((lin, rss)) = projected(&tau, y, yy, h, sigma, wd) {
                cands.push((rss, [lin[0], lin[1], lin[2], sigma, wd]));
            }
        }
    }
    cands.sort_by(|a, b| a.0.total_cmp(&b.0));
    // Zero crossings / log decrement about the best grid offset.
    if let Some(best) = cands.first() {
        if let Some((wd, z)) = zero_crossing_estimate(&tau, y, best.1[0]) {
            if wd > w_lo && wd < 0.5 * w_nyq {
                let sigma = z * wd / (1.0 - z * z).sqrt();
                if let Some((lin, rss)) = projected(&tau, y, yy, h, sigma, wd) {
                    cands.insert(0, (rss, [lin[0], lin[1], lin[2], sigma, wd]));
                }
            }
        }
    }
    if cands.is_empty() {
        return Err(MeasureError::Fit(
            "no oscillation could be located in the record".into(),
        ));
    }
    // Distinct starts: the zero-crossing candidate and the best grid points of distinct wd.
    let mut starts: Vec<[f64; 5]> = Vec::new();
    for (_, p) in &cands {
        if starts.len() >= 3 {
            break;
        }
        if starts.iter().all(|s| (s[4] / p[4] - 1.0).abs() > 0.1) {
            starts.push(*p);
        }
    }
    let y_scale = sst.sqrt() / (n as f64).sqrt();
    let opts = FitOptions {
        max_iter: 200,
        lower: Some(vec![
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
            -0.5 * w_nyq,
            w_lo,
        ]),
        upper: Some(vec![
            f64::INFINITY,
            f64::INFINITY,
            f64::INFINITY,
            10.0 * w_nyq,
            w_nyq,
        ]),
        typical: Some(vec![y_scale, y_scale, y_scale, 0.1 * w_fft, w_fft]),
        ..FitOptions::default()
    };
    let problem = DecayProblem { tau: &tau, y, h };
    let mut best: Option<optimize::least_squares::FitResult> = None;
    for s in &starts {
        if let Ok(r) = fit(&problem, s, &opts) {
            if r.params.iter().all(|v| v.is_finite()) && best.as_ref().is_none_or(|b| r.rss < b.rss)
            {
                best = Some(r);
            }
        }
    }
    let r = best
        .ok_or_else(|| MeasureError::Fit("Levenberg-Marquardt failed from every start".into()))?;
    let [c, a, b, sigma, wd] = [
        r.params[0],
        r.params[1],
        r.params[2],
        r.params[3],
        r.params[4],
    ];
    let amplitude = a.hypot(b);
    if amplitude.is_nan() || amplitude <= 0.0 {
        return Err(MeasureError::Fit(
            "fitted oscillation amplitude is zero".into(),
        ));
    }
    let wn = sigma.hypot(wd);
    let zeta = sigma / wn;
    let cov = |i: usize, j: usize| r.covariance.get(i * 5 + j).copied().unwrap_or(f64::NAN);
    let (g_wn, g_z) = (
        [sigma / wn, wd / wn],
        [wd * wd / wn.powi(3), -sigma * wd / wn.powi(3)],
    );
    let var = |g: [f64; 2]| {
        g[0] * g[0] * cov(3, 3) + 2.0 * g[0] * g[1] * cov(3, 4) + g[1] * g[1] * cov(4, 4)
    };
    let cycles = wd * duration / (2.0 * PI);
    if cycles < 0.5 {
        return Err(MeasureError::Fit(format!(
            "the record covers only {cycles:.2} damped cycles of the fitted {:.3} Hz oscillation (need >= 0.5)",
            wd / (2.0 * PI)
        )));
    }
    Ok(DecayFit {
        natural_frequency_hz: wn / (2.0 * PI),
        damped_frequency_hz: wd / (2.0 * PI),
        damping_ratio: zeta,
        amplitude,
        offset: c,
        rmse: (r.rss / n as f64).sqrt(),
        phase_rad: (-b).atan2(a),
        decay_rate_1_s: sigma,
        natural_frequency_std_hz: var(g_wn).max(0.0).sqrt() / (2.0 * PI),
        damping_ratio_std: var(g_z).max(0.0).sqrt(),
        r_squared: 1.0 - r.rss / sst,
        cycles,
        noise_rms: optimize::noise::measurement_noise_rms(y, optimize::noise::NOISE_FLOOR_OF_RANGE),
        iterations: r.iterations,
        converged: r.converged,
    })
}

#[cfg(test)]
mod phasor_tests {
    use super::{decay_onset, for_each_phasor, not_one_mode, uniform_spacing};

    #[test]
    fn only_a_residual_far_above_the_noise_gets_the_caveat() {
        assert!(not_one_mode(2.9).is_none());
        assert!(not_one_mode(f64::INFINITY).is_none() && not_one_mode(f64::NAN).is_none());
        let c = not_one_mode(12.4).unwrap();
        assert!(
            c.contains("12x") && c.contains("not one decaying mode"),
            "{c}"
        );
    }

    #[test]
    fn the_recurrence_matches_the_exact_phasor() {
        let tau: Vec<f64> = (0..601).map(|i| i as f64 * 0.005).collect();
        let h = uniform_spacing(&tau);
        assert_eq!(h, Some(0.005));
        for (sigma, wd) in [(0.8, 6.0), (-0.3, 40.0), (0.0, 1.0)] {
            let mut worst = 0.0f64;
            for_each_phasor(&tau, h, sigma, wd, |i, re, im| {
                let e = (-sigma * tau[i]).exp();
                let (s, c) = (wd * tau[i]).sin_cos();
                worst = worst.max(((re - e * c).abs() + (im - e * s).abs()) / e);
            });
            assert!(worst < 1e-13, "sigma {sigma}, wd {wd}: {worst:e}");
        }
        let mut jittered = tau.clone();
        jittered[7] += 1e-4;
        assert_eq!(uniform_spacing(&jittered), None);
        let mut n = 0;
        for_each_phasor(&jittered, None, 1.0, 2.0, |i, re, _| {
            assert_eq!(re, (-jittered[i]).exp() * (2.0 * jittered[i]).cos());
            n += 1;
        });
        assert_eq!(n, jittered.len());
    }

    #[test]
    fn the_decay_starts_at_the_second_extremum_after_the_pulse() {
        // y = cos(pi t) sampled at 0.1 s: extrema at t = 1, 2, 3, ...
        let t: Vec<f64> = (0..=50).map(|i| i as f64 * 0.1).collect();
        let y: Vec<f64> = t
            .iter()
            .map(|&t| (std::f64::consts::PI * t).cos())
            .collect();
        // After a pulse ending at 0.5 s the extrema are at 1 s (the driven swing) and 2 s.
        assert_eq!(decay_onset(&t, &y, 0.5), Some(20));
        // A pulse ending exactly on a sample counts that sample as after the pulse.
        assert_eq!(decay_onset(&t, &y, 1.0), Some(20));
        assert_eq!(decay_onset(&t, &y, 1.05), Some(30));
        // Fewer than two extrema after the pulse: no onset.
        assert_eq!(decay_onset(&t, &y, 3.5), None);
        assert_eq!(decay_onset(&t, &vec![1.0; t.len()], 0.5), None);
        // A flat top (a repeated sample) counts once, at its first sample.
        let y2 = [0.0, 1.0, 2.0, 2.0, 1.0, 0.0, -1.0, 0.0];
        let t2: Vec<f64> = (0..y2.len()).map(|i| i as f64).collect();
        assert_eq!(decay_onset(&t2, &y2, 0.0), Some(6));
    }
}
