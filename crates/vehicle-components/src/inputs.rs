//! Open-loop steering-wheel inputs (section 3.3): half-sine pulse, step, ramp, and a
//! measured time history. Angles in rad, positive = right-hand turn. Shared by the vehicle
//! models (the yaw-plane model of `afsv-dynamics`, the 3-D vehicle of `vehicle-3d`), which
//! is why they live in the component layer.

use serde::{Deserialize, Serialize};

/// A steering-wheel input or a path-following driver whose numbers are not usable (the
/// message names the number and what it must satisfy).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("invalid input: {0}")]
pub struct InputError(pub String);

/// A steering-wheel angle time history theta_sw(t).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum SteerInput {
    /// Zero input (free running).
    None,
    /// Half-sine pulse `A sin(pi (t - t0)/D)` for `t0 <= t <= t0 + D` (section 3.3: D = 0.2 s).
    Pulse {
        /// Peak angle A (rad).
        amplitude_rad: f64,
        /// Duration D (s).
        duration_s: f64,
        /// Start time t0 (s).
        start_s: f64,
    },
    /// Step of `A` at `t0` (section 3.3: 30 deg).
    Step {
        /// Step height A (rad).
        amplitude_rad: f64,
        /// Step time t0 (s).
        start_s: f64,
    },
    /// Ramp at constant rate from `t0`, held once `limit_rad` is reached.
    Ramp {
        /// Rate (rad/s).
        rate_rad_s: f64,
        /// Start time t0 (s).
        start_s: f64,
        /// Magnitude at which the ramp stops and holds (rad).
        limit_rad: f64,
    },
    /// A sampled history (e.g. a measured record's `steer_wheel_deg` column converted to
    /// rad), interpolated by cubic Hermite segments with centred-difference slopes
    /// (Catmull-Rom), which pass through every sample; held constant outside its span.
    Table {
        /// Sample times (s), strictly increasing.
        time_s: Vec<f64>,
        /// Steering-wheel angle samples (rad).
        angle_rad: Vec<f64>,
    },
}

impl SteerInput {
    /// Half-sine pulse of the given peak (deg) and duration, starting at `start_s`.
    pub fn pulse_deg(amplitude_deg: f64, duration_s: f64, start_s: f64) -> Self {
        SteerInput::Pulse {
            amplitude_rad: amplitude_deg.to_radians(),
            duration_s,
            start_s,
        }
    }

    /// Step of the given height (deg) at `start_s`.
    pub fn step_deg(amplitude_deg: f64, start_s: f64) -> Self {
        SteerInput::Step {
            amplitude_rad: amplitude_deg.to_radians(),
            start_s,
        }
    }

    /// Check the input's numbers.
    pub fn validate(&self) -> Result<(), InputError> {
        let bad = |what: &str, v: f64| {
            Err(InputError(format!(
                "steering input: {what} must be finite{}, got {v}",
                if what == "pulse duration" {
                    " and positive"
                } else {
                    ""
                }
            )))
        };
        match self {
            SteerInput::None => Ok(()),
            SteerInput::Pulse {
                amplitude_rad,
                duration_s,
                start_s,
            } => {
                if !amplitude_rad.is_finite() {
                    return bad("pulse amplitude", *amplitude_rad);
                }
                if !(duration_s.is_finite() && *duration_s > 0.0) {
                    return bad("pulse duration", *duration_s);
                }
                if !start_s.is_finite() {
                    return bad("pulse start", *start_s);
                }
                Ok(())
            }
            SteerInput::Step {
                amplitude_rad,
                start_s,
            } => {
                if !amplitude_rad.is_finite() {
                    return bad("step amplitude", *amplitude_rad);
                }
                if !start_s.is_finite() {
                    return bad("step time", *start_s);
                }
                Ok(())
            }
            SteerInput::Ramp {
                rate_rad_s,
                start_s,
                limit_rad,
            } => {
                if !rate_rad_s.is_finite() {
                    return bad("ramp rate", *rate_rad_s);
                }
                if !start_s.is_finite() {
                    return bad("ramp start", *start_s);
                }
                if !(limit_rad.is_finite() && *limit_rad >= 0.0) {
                    return Err(InputError(format!(
                        "steering input: ramp limit must be finite and >= 0, got {limit_rad}"
                    )));
                }
                // the ramp's end (a breakpoint) must be a finite time
                if *rate_rad_s != 0.0 && !(start_s + limit_rad / rate_rad_s.abs()).is_finite() {
                    return Err(InputError(format!(
                        "steering input: ramp rate {rate_rad_s} rad/s is too slow to reach its limit {limit_rad} rad in finite time"
                    )));
                }
                Ok(())
            }
            SteerInput::Table { time_s, angle_rad } => {
                if time_s.len() != angle_rad.len() || time_s.is_empty() {
                    return Err(InputError(format!(
                        "steering table: {} times but {} angles (need equal, non-zero counts)",
                        time_s.len(),
                        angle_rad.len()
                    )));
                }
                for i in 0..time_s.len() {
                    if !time_s[i].is_finite() || !angle_rad[i].is_finite() {
                        return Err(InputError(format!(
                            "steering table: sample {i} is not finite"
                        )));
                    }
                    if i > 0 && time_s[i] <= time_s[i - 1] {
                        return Err(InputError(format!(
                            "steering table: time not strictly increasing at sample {i}"
                        )));
                    }
                }
                Ok(())
            }
        }
    }

    /// theta_sw(t) (rad). Allocation-free (binary search and cubic Hermite for tables).
    #[inline]
    pub fn angle(&self, t: f64) -> f64 {
        match *self {
            SteerInput::None => 0.0,
            SteerInput::Pulse {
                amplitude_rad,
                duration_s,
                start_s,
            } => {
                let x = (t - start_s) / duration_s;
                if (0.0..=1.0).contains(&x) {
                    amplitude_rad * (std::f64::consts::PI * x).sin()
                } else {
                    0.0
                }
            }
            SteerInput::Step {
                amplitude_rad,
                start_s,
            } => {
                if t >= start_s {
                    amplitude_rad
                } else {
                    0.0
                }
            }
            SteerInput::Ramp {
                rate_rad_s,
                start_s,
                limit_rad,
            } => {
                if t <= start_s {
                    0.0
                } else {
                    (rate_rad_s * (t - start_s)).clamp(-limit_rad, limit_rad)
                }
            }
            SteerInput::Table {
                ref time_s,
                ref angle_rad,
            } => {
                let n = time_s.len();
                if t <= time_s[0] {
                    return angle_rad[0];
                }
                if t >= time_s[n - 1] {
                    return angle_rad[n - 1];
                }
                // time_s[i-1] <= t < time_s[i]; a NaN t (a diverging solver) finds no
                // interval, and the clamp keeps it in the table so the NaN reaches the
                // solver's divergence check instead of an index panic
                let i = samples_at_or_before(time_s, t).clamp(1, n - 1);
                let (t0, t1) = (time_s[i - 1], time_s[i]);
                let h = t1 - t0;
                let w = (t - t0) / h;
                let (y0, y1) = (angle_rad[i - 1], angle_rad[i]);
                // Cubic Hermite with centred-difference slopes (Catmull-Rom): a sampled
                // driver input is smooth between samples, and linear interpolation of a
                // 100 Hz record shifts fast steering by up to half a sample.
                let slope = |k: usize| {
                    let (a, b) = (k.saturating_sub(1), (k + 1).min(n - 1));
                    (angle_rad[b] - angle_rad[a]) / (time_s[b] - time_s[a])
                };
                let (m0, m1) = (slope(i - 1) * h, slope(i) * h);
                let (w2, w3) = (w * w, w * w * w);
                (2.0 * w3 - 3.0 * w2 + 1.0) * y0
                    + (w3 - 2.0 * w2 + w) * m0
                    + (-2.0 * w3 + 3.0 * w2) * y1
                    + (w3 - w2) * m1
            }
        }
    }

    /// Times where the input or its slope jumps; the integrator is restarted there.
    pub fn breakpoints(&self) -> Vec<f64> {
        match *self {
            SteerInput::None | SteerInput::Table { .. } => Vec::new(),
            SteerInput::Pulse {
                duration_s,
                start_s,
                ..
            } => vec![start_s, start_s + duration_s],
            SteerInput::Step { start_s, .. } => vec![start_s],
            SteerInput::Ramp {
                rate_rad_s,
                start_s,
                limit_rad,
            } => {
                if rate_rad_s != 0.0 && limit_rad > 0.0 {
                    vec![start_s, start_s + limit_rad / rate_rad_s.abs()]
                } else {
                    vec![start_s]
                }
            }
        }
    }
}

/// The number of samples of `ts` (strictly increasing, as [`SteerInput::validate`]
/// requires) at or before `t`: `ts.partition_point(|&x| x <= t)`, looked for first within a
/// few samples of the index on the mean grid, so that a uniformly sampled table needs two or
/// three comparisons instead of a binary search at every right-hand side.
#[inline]
fn samples_at_or_before(ts: &[f64], t: f64) -> usize {
    let n = ts.len();
    let guess = (t - ts[0]) * (n - 1) as f64 / (ts[n - 1] - ts[0]);
    // `x <= t` is false for x > t and for a NaN t alike
    crate::sampled::partition_point_near(ts, guess, |x| x <= t)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_interval_is_the_binary_search_one() {
        // the lookup itself is tested in vehicle_components::sampled; here its guess
        let ts: Vec<f64> = (0..100).map(|i| 2.0 + i as f64 * 0.05).collect();
        for t in [1.0, 2.0, 2.025, 4.5, 6.95, 7.0, f64::NAN] {
            assert_eq!(
                samples_at_or_before(&ts, t),
                ts.partition_point(|&x| x <= t)
            );
        }
    }

    #[test]
    fn pulse_step_ramp_table_values() {
        let p = SteerInput::pulse_deg(30.0, 0.2, 1.0);
        assert_eq!(p.angle(0.9), 0.0);
        assert!((p.angle(1.1) - 30f64.to_radians()).abs() < 1e-12);
        assert_eq!(p.angle(1.3), 0.0);
        let s = SteerInput::step_deg(30.0, 0.5);
        assert_eq!(s.angle(0.49), 0.0);
        assert_eq!(s.angle(0.5), 30f64.to_radians());
        let r = SteerInput::Ramp {
            rate_rad_s: 0.1,
            start_s: 1.0,
            limit_rad: 0.15,
        };
        assert!((r.angle(2.0) - 0.1).abs() < 1e-12);
        assert!((r.angle(5.0) - 0.15).abs() < 1e-12);
        assert_eq!(r.breakpoints(), vec![1.0, 2.5]);
        let t = SteerInput::Table {
            time_s: vec![0.0, 1.0, 3.0],
            angle_rad: vec![0.0, 1.0, -1.0],
        };
        t.validate().unwrap();
        // Cubic Hermite with centred-difference slopes (hand-computed): slopes 1, -1/3, -1
        // at the knots; the samples themselves are reproduced.
        assert!((t.angle(0.5) - 2.0 / 3.0).abs() < 1e-12);
        assert!((t.angle(2.0) - 1.0 / 6.0).abs() < 1e-12);
        assert!((t.angle(1.0) - 1.0).abs() < 1e-12);
        assert_eq!(t.angle(9.0), -1.0);
        // a diverging solver's NaN time gives NaN, not an index panic
        assert!(t.angle(f64::NAN).is_nan());
        // A uniformly sampled ramp is reproduced exactly between the samples.
        let ramp = SteerInput::Table {
            time_s: (0..10).map(|k| 0.01 * k as f64).collect(),
            angle_rad: (0..10).map(|k| 0.3 * k as f64).collect(),
        };
        assert!((ramp.angle(0.0437) - 30.0 * 0.0437).abs() < 1e-12);
    }

    #[test]
    fn invalid_inputs_rejected() {
        assert!(SteerInput::pulse_deg(30.0, 0.0, 1.0).validate().is_err());
        assert!(SteerInput::step_deg(f64::NAN, 1.0).validate().is_err());
        let t = SteerInput::Table {
            time_s: vec![0.0, 0.0],
            angle_rad: vec![0.0, 1.0],
        };
        assert!(t.validate().is_err());
        // a ramp so slow that its end (a breakpoint) is not a finite time
        let slow = SteerInput::Ramp {
            rate_rad_s: 1e-320,
            start_s: 1.0,
            limit_rad: 1.0,
        };
        assert!(slow
            .validate()
            .unwrap_err()
            .to_string()
            .contains("too slow"));
        let fine = SteerInput::Ramp {
            rate_rad_s: 0.1,
            start_s: 1.0,
            limit_rad: 1.0,
        };
        assert!(fine.validate().is_ok());
        assert!(fine.breakpoints().iter().all(|t| t.is_finite()));
    }
}
