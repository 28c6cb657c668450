//! Locating the disagreement between a model's prediction and a measured channel: overall
//! and per-phase normalised errors, bias, time lag, amplitude ratio, frequency shift,
//! low/high-frequency split of the residual, excess error near zero crossings (dead zone,
//! backlash), and loop area (energy per cycle) against an abscissa channel.

use super::Phase;

/// Signatures of one channel of one record.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ChannelSignature {
    /// Channel name.
    pub channel: String,
    /// RMS of the residual divided by the measured channel's standard deviation.
    pub nrmse: f64,
    /// Mean residual (prediction minus measurement) over the measured standard deviation.
    pub bias: f64,
    /// Delay of the prediction behind the measurement (s) at maximum cross-correlation;
    /// positive means the model lags.
    pub lag_s: f64,
    /// Standard deviation of the prediction over that of the measurement.
    pub amplitude_ratio: f64,
    /// Relative shift of the zero-crossing rate (a proxy of the dominant frequency), %.
    pub frequency_shift_percent: f64,
    /// Fraction of residual energy below `split_hz`.
    pub low_band_fraction: f64,
    /// Split frequency used (Hz).
    pub split_hz: f64,
    /// RMS residual within 10 % of the range around the measured signal's mean over the
    /// RMS residual elsewhere (> 1 hints at a dead zone or backlash near zero crossings).
    pub zero_crossing_ratio: f64,
    /// Per-phase NRMSE.
    pub phases: Vec<(String, f64)>,
    /// Loop area of measurement and prediction against the abscissa channel, if any.
    pub loop_area: Option<(f64, f64)>,
}

/// Standard deviation (population) of `x`.
pub fn std_dev(x: &[f64]) -> f64 {
    if x.is_empty() {
        return 0.0;
    }
    let m = x.iter().sum::<f64>() / x.len() as f64;
    (x.iter().map(|v| (v - m) * (v - m)).sum::<f64>() / x.len() as f64).sqrt()
}

/// Signed area enclosed by the path `(x, y)`: `sum y_mid dx` (energy per cycle for
/// force versus displacement).
pub fn loop_area(x: &[f64], y: &[f64]) -> f64 {
    let n = x.len().min(y.len());
    (1..n)
        .map(|i| 0.5 * (y[i] + y[i - 1]) * (x[i] - x[i - 1]))
        .sum()
}

fn zero_crossings(x: &[f64]) -> usize {
    let m = x.iter().sum::<f64>() / x.len().max(1) as f64;
    x.windows(2)
        .filter(|w| (w[0] - m) * (w[1] - m) < 0.0)
        .count()
}

/// Lag (in samples) of `b` behind `a` maximising their cross-correlation, within `max_lag`.
fn best_lag(a: &[f64], b: &[f64], max_lag: usize) -> isize {
    let n = a.len().min(b.len());
    let ma = a.iter().sum::<f64>() / n.max(1) as f64;
    let mb = b.iter().sum::<f64>() / n.max(1) as f64;
    let mut best = (f64::NEG_INFINITY, 0isize);
    for lag in -(max_lag as isize)..=(max_lag as isize) {
        let mut s = 0.0;
        for (i, ai) in a.iter().enumerate().take(n) {
            let j = i as isize + lag;
            if j >= 0 && (j as usize) < n {
                s += (ai - ma) * (b[j as usize] - mb);
            }
        }
        if s > best.0 {
            best = (s, lag);
        }
    }
    best.1
}

/// Compute the signatures of one channel. `t` is the time base, `phases` optional masks,
/// `abscissa` an optional channel for loop areas, `split_hz` the band split.
pub fn channel_signature(
    channel: &str,
    t: &[f64],
    meas: &[f64],
    pred: &[f64],
    phases: &[Phase],
    abscissa: Option<&[f64]>,
    split_hz: f64,
) -> ChannelSignature {
    let n = meas.len().min(pred.len()).min(t.len());
    let (meas, pred, t) = (&meas[..n], &pred[..n], &t[..n]);
    let sd = std_dev(meas).max(f64::MIN_POSITIVE);
    let res: Vec<f64> = (0..n).map(|i| pred[i] - meas[i]).collect();
    let rms = |idx: &mut dyn Iterator<Item = usize>| {
        let (mut s, mut c) = (0.0, 0usize);
        for i in idx {
            s += res[i] * res[i];
            c += 1;
        }
        if c == 0 {
            f64::NAN
        } else {
            (s / c as f64).sqrt()
        }
    };
    let nrmse = rms(&mut (0..n)) / sd;
    let bias = res.iter().sum::<f64>() / n.max(1) as f64 / sd;
    let dt = if n > 1 {
        (t[n - 1] - t[0]) / (n - 1) as f64
    } else {
        1.0
    };
    let max_lag = (n / 10).min((0.5 / dt.max(1e-12)) as usize).max(1);
    let lag_s = best_lag(meas, pred, max_lag) as f64 * dt;
    let amplitude_ratio = std_dev(pred) / sd;
    let zc_m = zero_crossings(meas) as f64;
    let zc_p = zero_crossings(pred) as f64;
    let frequency_shift_percent = if zc_m > 0.0 {
        100.0 * (zc_p - zc_m) / zc_m
    } else {
        0.0
    };
    // Low band: moving average of the residual over one period of split_hz.
    let w = ((1.0 / split_hz) / dt.max(1e-12)).round().max(1.0) as usize;
    let mut low = vec![0.0; n];
    let mut acc = 0.0;
    for i in 0..n {
        acc += res[i];
        if i >= w {
            acc -= res[i - w];
        }
        low[i] = acc / (i + 1).min(w) as f64;
    }
    let e_low: f64 = low.iter().map(|v| v * v).sum();
    let e_all: f64 = res.iter().map(|v| v * v).sum();
    let low_band_fraction = if e_all > 0.0 {
        (e_low / e_all).min(1.0)
    } else {
        0.0
    };
    let mean_m = meas.iter().sum::<f64>() / n.max(1) as f64;
    let (lo, hi) = meas
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    let band = 0.1 * (hi - lo);
    let near = rms(&mut (0..n).filter(|&i| (meas[i] - mean_m).abs() < band));
    let far = rms(&mut (0..n).filter(|&i| (meas[i] - mean_m).abs() >= band));
    let zero_crossing_ratio = if far > 0.0 && near.is_finite() {
        near / far
    } else {
        f64::NAN
    };
    let phases = phases
        .iter()
        .map(|p| {
            let v = rms(&mut (0..n).filter(|&i| p.mask.get(i).copied().unwrap_or(false))) / sd;
            (p.name.clone(), v)
        })
        .collect();
    let loop_area = abscissa.map(|x| (loop_area(&x[..n], meas), loop_area(&x[..n], pred)));
    ChannelSignature {
        channel: channel.to_string(),
        nrmse,
        bias,
        lag_s,
        amplitude_ratio,
        frequency_shift_percent,
        low_band_fraction,
        split_hz,
        zero_crossing_ratio,
        phases,
        loop_area,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lag_and_amplitude_of_a_shifted_scaled_sine() {
        let dt = 0.001;
        let t: Vec<f64> = (0..5000).map(|i| i as f64 * dt).collect();
        let meas: Vec<f64> = t
            .iter()
            .map(|t| (2.0 * std::f64::consts::PI * t).sin())
            .collect();
        let pred: Vec<f64> = t
            .iter()
            .map(|t| 0.8 * (2.0 * std::f64::consts::PI * (t - 0.05)).sin())
            .collect();
        let s = channel_signature("x", &t, &meas, &pred, &[], None, 2.0);
        assert!((s.lag_s - 0.05).abs() < 2.0 * dt, "{}", s.lag_s);
        assert!((s.amplitude_ratio - 0.8).abs() < 0.01);
        assert!(s.bias.abs() < 0.01);
        assert!(s.frequency_shift_percent.abs() < 15.0);
    }

    #[test]
    fn loop_area_of_a_circle() {
        let n = 10_001;
        let th: Vec<f64> = (0..n)
            .map(|i| i as f64 / (n - 1) as f64 * 2.0 * std::f64::consts::PI)
            .collect();
        let x: Vec<f64> = th.iter().map(|a| a.cos()).collect();
        let y: Vec<f64> = th.iter().map(|a| a.sin()).collect();
        assert!((loop_area(&x, &y).abs() - std::f64::consts::PI).abs() < 1e-4);
    }

    #[test]
    fn bias_is_detected() {
        let t: Vec<f64> = (0..1000).map(|i| i as f64 * 0.01).collect();
        let meas: Vec<f64> = t.iter().map(|t| t.sin()).collect();
        let pred: Vec<f64> = meas.iter().map(|v| v + 0.1).collect();
        let s = channel_signature("x", &t, &meas, &pred, &[], None, 1.0);
        assert!((s.bias - 0.1 / std_dev(&meas)).abs() < 1e-9);
        assert!(s.low_band_fraction > 0.9);
    }
}
