//! Step-steer response metrics (section 3.3, Fig 4.6(a)): steering gain (steady
//! articulation angle over steering-wheel angle), 0-100 % rise time ("rate of articulation")
//! and percent overshoot.

use crate::error::{finite_scalar, finite_series, invalid, same_len, time_series, MeasureError};
use serde::{Deserialize, Serialize};

/// Settings of [`step_metrics_with`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct StepOptions {
    /// Fraction of the post-step duration at the end of the record averaged for the steady
    /// value (default 0.1).
    pub settle_fraction: f64,
}

impl Default for StepOptions {
    fn default() -> Self {
        StepOptions {
            settle_fraction: 0.1,
        }
    }
}

/// Step-response metrics.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StepMetrics {
    /// Steady value: mean of the output over the final `settle_fraction` of the record.
    pub steady_value: f64,
    /// Steering gain `steady_value / input_amplitude` (section 4.3.1, "Gamma").
    pub gain: f64,
    /// 0-100 % rise time: from the step to the first time the output reaches the steady
    /// value (s).
    pub rise_time_s: f64,
    /// Percent overshoot `100 (peak - steady) / (steady - initial)`, 0 when the output never
    /// exceeds its steady value.
    pub overshoot_percent: f64,
    /// Extreme output value after the step in the direction of the response.
    pub peak_value: f64,
    /// Time of [`Self::peak_value`] (s, same time base as the input).
    pub peak_time_s: f64,
    /// Output at the step time (linear interpolation), the 0 % level.
    pub initial_value: f64,
    /// `(steady_value - initial_value) / input_amplitude`: equals [`Self::gain`] when the
    /// output starts from zero.
    pub incremental_gain: f64,
    /// Mean rise rate `(steady - initial) / rise_time` (output units per s).
    pub rise_rate_per_s: f64,
}

/// Share of the step amplitude by which the input must depart from its initial value for
/// [`step_time`] to see the step (2 %).
pub const STEP_DETECTION_FRACTION: f64 = 0.02;

/// Amplitude of the step in an input record `u` (e.g. the steering-wheel angle of a step-steer
/// test, section 3.3): the mean of its final `settle_fraction` of samples (at least one) minus
/// its initial value.
pub fn step_amplitude(u: &[f64], settle_fraction: f64) -> Result<f64, MeasureError> {
    finite_series("u", u, 2)?;
    if !(settle_fraction > 0.0 && settle_fraction < 1.0) {
        return Err(invalid(
            "settle_fraction",
            format!("{settle_fraction} must lie in (0, 1)"),
        ));
    }
    let n = u.len();
    let k = ((settle_fraction * n as f64) as usize).max(1);
    let amplitude = u[n - k..].iter().sum::<f64>() / k as f64 - u[0];
    if amplitude == 0.0 {
        return Err(MeasureError::NotFound(format!(
            "has no step (amplitude {amplitude})"
        )));
    }
    Ok(amplitude)
}

/// Time of the step of `amplitude` in the input `u(t)`: the sample before the first one that
/// departs from the initial value by [`STEP_DETECTION_FRACTION`] of the amplitude (the last
/// sample still at the initial level).
pub fn step_time(t: &[f64], u: &[f64], amplitude: f64) -> Result<f64, MeasureError> {
    time_series(t, 2)?;
    same_len("t", t, "u", u)?;
    finite_series("u", u, 2)?;
    finite_scalar("amplitude", amplitude)?;
    if amplitude == 0.0 {
        return Err(invalid("amplitude", "must be non-zero"));
    }
    let u0 = u[0];
    let i = u
        .iter()
        .position(|v| (v - u0).abs() >= STEP_DETECTION_FRACTION * amplitude.abs())
        .ok_or_else(|| MeasureError::NotFound("the input never steps".into()))?;
    Ok(t[i.saturating_sub(1)])
}

/// [`step_metrics_with`] with default options.
pub fn step_metrics(
    t: &[f64],
    y: &[f64],
    t_step: f64,
    input_amplitude: f64,
) -> Result<StepMetrics, MeasureError> {
    step_metrics_with(t, y, t_step, input_amplitude, &StepOptions::default())
}

/// Metrics of the response `y(t)` to a step of `input_amplitude` applied at `t_step`.
pub fn step_metrics_with(
    t: &[f64],
    y: &[f64],
    t_step: f64,
    input_amplitude: f64,
    opts: &StepOptions,
) -> Result<StepMetrics, MeasureError> {
    time_series(t, 4)?;
    same_len("t", t, "y", y)?;
    finite_series("y", y, 4)?;
    finite_scalar("t_step", t_step)?;
    finite_scalar("input_amplitude", input_amplitude)?;
    if input_amplitude == 0.0 {
        return Err(invalid("input_amplitude", "must be non-zero"));
    }
    if !(opts.settle_fraction > 0.0 && opts.settle_fraction < 1.0) {
        return Err(invalid(
            "settle_fraction",
            format!("{} must lie in (0, 1)", opts.settle_fraction),
        ));
    }
    let n = t.len();
    if t_step < t[0] || t_step >= t[n - 1] {
        return Err(invalid(
            "t_step",
            format!(
                "{t_step} s lies outside the record [{}, {}) s",
                t[0],
                t[n - 1]
            ),
        ));
    }
    // First sample at or after the step; interpolate the initial value.
    let i0 = t.partition_point(|&v| v < t_step);
    let initial_value = if i0 == 0 {
        y[0]
    } else {
        let f = (t_step - t[i0 - 1]) / (t[i0] - t[i0 - 1]);
        y[i0 - 1] + f * (y[i0] - y[i0 - 1])
    };
    let t_settle = t[n - 1] - opts.settle_fraction * (t[n - 1] - t_step);
    let is = t.partition_point(|&v| v < t_settle).min(n - 1);
    let tail = &y[is..];
    if tail.len() < 2 || is <= i0 {
        return Err(MeasureError::TooShort {
            field: "y",
            needed: 2,
            got: tail.len(),
        });
    }
    let steady_value = tail.iter().sum::<f64>() / tail.len() as f64;
    let change = steady_value - initial_value;
    if change == 0.0 {
        return Err(MeasureError::NotFound(
            "the output does not change after the step".into(),
        ));
    }
    let dir = change.signum();
    // 100 % rise: first crossing of the steady value after the step.
    let mut rise_time_s = f64::NAN;
    for i in i0..n {
        if dir * (y[i] - steady_value) >= 0.0 {
            let tc = if i == 0 {
                t[0]
            } else {
                crate::signal::interp_crossing(t, y, None, i - 1, steady_value).0
            };
            rise_time_s = tc.max(t_step) - t_step;
            break;
        }
    }
    if !rise_time_s.is_finite() {
        return Err(MeasureError::NotFound(
            "the output never reaches its steady value".into(),
        ));
    }
    let (ip, _) = y[i0..]
        .iter()
        .enumerate()
        .map(|(k, v)| (i0 + k, dir * v))
        .fold(
            (i0, f64::NEG_INFINITY),
            |m, v| if v.1 > m.1 { v } else { m },
        );
    let peak_value = y[ip];
    let overshoot = 100.0 * (peak_value - steady_value) / change;
    Ok(StepMetrics {
        steady_value,
        gain: steady_value / input_amplitude,
        rise_time_s,
        overshoot_percent: overshoot.max(0.0),
        peak_value,
        peak_time_s: t[ip],
        initial_value,
        incremental_gain: change / input_amplitude,
        rise_rate_per_s: if rise_time_s > 0.0 {
            change / rise_time_s
        } else {
            f64::INFINITY
        },
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn step_of_a_sampled_input_is_found() {
        // 0 until 1.0 s, 30 from 1.01 s on, 10 ms samples.
        let t: Vec<f64> = (0..401).map(|i| i as f64 * 0.01).collect();
        let u: Vec<f64> = t
            .iter()
            .map(|&x| if x < 1.005 { 0.0 } else { 30.0 })
            .collect();
        let a = step_amplitude(&u, 0.1).unwrap();
        assert_eq!(a, 30.0);
        assert!((step_time(&t, &u, a).unwrap() - 1.0).abs() < 1e-12);
        // A negative step is found the same way.
        let neg: Vec<f64> = u.iter().map(|v| 5.0 - v).collect();
        let a = step_amplitude(&neg, 0.1).unwrap();
        assert_eq!(a, -30.0);
        assert!((step_time(&t, &neg, a).unwrap() - 1.0).abs() < 1e-12);
    }

    #[test]
    fn inputs_without_a_step_are_errors() {
        let t = [0.0, 1.0, 2.0, 3.0];
        let flat = [2.0; 4];
        let e = step_amplitude(&flat, 0.1).unwrap_err();
        assert!(e.to_string().contains("no step"), "{e}");
        assert!(matches!(
            step_time(&t, &flat, 1.0),
            Err(MeasureError::NotFound(_))
        ));
        assert!(step_time(&t, &flat, 0.0).is_err());
        assert!(step_amplitude(&[0.0, f64::NAN], 0.1).is_err());
        assert!(step_amplitude(&flat, 1.0).is_err());
        assert!(step_time(&t, &flat[..3], 1.0).is_err());
    }
}
