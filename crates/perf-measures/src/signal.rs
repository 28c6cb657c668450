//! Small signal helpers shared by the measures: RMS, trapezoidal integrals, sample rate.

use crate::error::{finite_series, invalid, same_len, time_series, MeasureError};

/// Root mean square of the samples of `x` (uniformly sampled).
pub fn rms(x: &[f64]) -> Result<f64, MeasureError> {
    finite_series("x", x, 1)?;
    Ok((x.iter().map(|v| v * v).sum::<f64>() / x.len() as f64).sqrt())
}

/// Trapezoidal integral of `y(t)` over the whole record.
pub fn trapz(t: &[f64], y: &[f64]) -> Result<f64, MeasureError> {
    time_series(t, 2)?;
    same_len("t", t, "y", y)?;
    finite_series("y", y, 2)?;
    Ok(trapz_unchecked(t, y))
}

pub(crate) fn trapz_unchecked(t: &[f64], y: &[f64]) -> f64 {
    t.windows(2)
        .zip(y.windows(2))
        .map(|(tw, yw)| 0.5 * (tw[1] - tw[0]) * (yw[0] + yw[1]))
        .sum()
}

/// Time-weighted RMS of `y(t)` over `[t[i0], t[i1]]` by the trapezoidal rule on `y^2`
/// (`i0 < i1`, indices into already validated series).
pub(crate) fn trapz_rms(t: &[f64], y: &[f64], i0: usize, i1: usize) -> f64 {
    let mut acc = 0.0;
    for i in i0..i1 {
        acc += 0.5 * (t[i + 1] - t[i]) * (y[i] * y[i] + y[i + 1] * y[i + 1]);
    }
    (acc / (t[i1] - t[i0])).sqrt()
}

/// Sampling rate (Hz) of a uniformly sampled time vector. Fails if the sample interval
/// varies by more than 1 % of its mean (the weightings and running RMS need uniform
/// sampling; resample first otherwise).
pub fn sample_rate(t: &[f64]) -> Result<f64, MeasureError> {
    time_series(t, 2)?;
    let n = t.len();
    let dt = (t[n - 1] - t[0]) / (n - 1) as f64;
    if let Some(i) = t
        .windows(2)
        .position(|w| ((w[1] - w[0]) - dt).abs() > 0.01 * dt)
    {
        return Err(invalid(
            "time_s",
            format!(
                "sampling is not uniform: interval {} s at sample {} differs from the mean {} s by more than 1 %",
                t[i + 1] - t[i],
                i + 1,
                dt
            ),
        ));
    }
    Ok(1.0 / dt)
}

/// Linear interpolation of the crossing time and of `z` between samples `i` and `i + 1`
/// where `y` crosses `level`.
pub(crate) fn interp_crossing(
    t: &[f64],
    y: &[f64],
    z: Option<&[f64]>,
    i: usize,
    level: f64,
) -> (f64, f64) {
    let dy = y[i + 1] - y[i];
    let frac = if dy == 0.0 {
        0.0
    } else {
        ((level - y[i]) / dy).clamp(0.0, 1.0)
    };
    let time = t[i] + frac * (t[i + 1] - t[i]);
    let zv = z.map_or(f64::NAN, |z| z[i] + frac * (z[i + 1] - z[i]));
    (time, zv)
}
