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
