//! What a finished identification (section 5.3.2) can say about itself from the record:
//! whether its residual sits at the record's measurement noise, whether a pressure channel
//! is offset by one atmosphere (a gauge pressure read as absolute, or the reverse), and
//! whether the velocity it used was measured or differentiated from a noisy displacement.
//!
//! The noise is read from the record itself by `optimize::noise::measurement_noise_variance`
//! (fourth differences, robust spread): a fit whose residual RMS is several times that noise
//! leaves something the model does not describe, whatever the optimiser's convergence says.

use optimize::noise::NOISE_FLOOR_OF_RANGE;
use serde::{Deserialize, Serialize};

/// Standard atmosphere (Pa): the offset between a gauge and an absolute pressure reading.
pub const STANDARD_ATMOSPHERE_PA: f64 = 101_325.0;

/// Residual RMS above this multiple of the noise RMS is "far above the noise" (an MSE ratio
/// of 9). The noise estimate reads low for sensor-filtered noise (down to about 0.46 of its
/// variance), so a faithful fit stays under about 1.5 times; 3 leaves room for that.
pub const RESIDUAL_NOISE_LIMIT: f64 = 3.0;

/// A differentiated velocity whose noise RMS exceeds this fraction of its range biases the
/// friction and damping laws, which switch and scale on the velocity.
pub const VELOCITY_NOISE_LIMIT: f64 = 0.02;

/// One compared channel after the fit, in its own unit (N or Pa).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ChannelCheck {
    /// RMS of `simulated - measured` over the compared samples.
    pub residual_rms: f64,
    /// Measurement-noise RMS read from the record, floored at
    /// `optimize::noise::NOISE_FLOOR_OF_RANGE` (0.1 %) of its range, so a noiseless record
    /// (a simulation) does not make a 0.1 % residual look like a poor fit.
    pub noise_rms: f64,
    /// Mean of `measured - simulated`: a constant the model cannot produce.
    pub mean_offset: f64,
}

impl ChannelCheck {
    /// The check of `measured` against `simulated` (equal lengths, at least one sample).
    pub fn of(measured: &[f64], simulated: &[f64]) -> Self {
        let n = measured.len().max(1) as f64;
        let (mut sq, mut sum) = (0.0, 0.0);
        for (m, s) in measured.iter().zip(simulated) {
            sq += (s - m) * (s - m);
            sum += m - s;
        }
        Self {
            residual_rms: (sq / n).sqrt(),
            noise_rms: optimize::noise::measurement_noise_rms(measured, NOISE_FLOOR_OF_RANGE),
            mean_offset: sum / n,
        }
    }

    /// Residual RMS over noise RMS (infinite when both the noise and the range are zero
    /// and the residual is not).
    pub fn residual_to_noise(&self) -> f64 {
        if self.noise_rms > 0.0 {
            self.residual_rms / self.noise_rms
        } else if self.residual_rms > 0.0 {
            f64::INFINITY
        } else {
            0.0
        }
    }

    /// `+1` when the measured channel sits one atmosphere above the model (an absolute
    /// pressure declared gauge), `-1` when one below (a gauge pressure read as absolute),
    /// `0` otherwise: the mean offset lies within 30 % of one atmosphere and accounts for
    /// at least half of the residual's mean square.
    pub fn atmosphere_offset(&self) -> i8 {
        let o = self.mean_offset;
        let near = (o.abs() - STANDARD_ATMOSPHERE_PA).abs() <= 0.3 * STANDARD_ATMOSPHERE_PA;
        if near && o * o >= 0.5 * self.residual_rms * self.residual_rms {
            if o > 0.0 {
                1
            } else {
                -1
            }
        } else {
            0
        }
    }
}

/// The checks of the three compared channels (`None`: not in the record).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct ChannelChecks {
    /// `force_n`.
    pub force: Option<ChannelCheck>,
    /// `p_piston_pa`.
    pub p_piston: Option<ChannelCheck>,
    /// `p_rod_pa`.
    pub p_rod: Option<ChannelCheck>,
}

/// Where the identification's velocity came from.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case", tag = "source")]
pub enum VelocitySource {
    /// The record's `velocity_m_s`.
    Measured,
    /// Central differences of `displacement_m`; `noise_of_range` is the velocity noise RMS
    /// that the displacement's noise makes, over the velocity's range.
    Differentiated {
        /// Velocity noise RMS over velocity range.
        noise_of_range: f64,
    },
}

impl VelocitySource {
    /// The source for a record with `velocity` or, without it, differentiated from the
    /// displacement `z` sampled at the times `t`: white displacement noise `s` becomes
    /// velocity noise `s / (sqrt(2) dt)` under central differences.
    pub fn of(t: &[f64], z: &[f64], velocity: Option<&[f64]>) -> Self {
        if velocity.is_some() || t.len() < 3 {
            return Self::Measured;
        }
        let dt = (t[t.len() - 1] - t[0]) / (t.len() - 1) as f64;
        let noise_v =
            optimize::noise::measurement_noise_variance(z).sqrt() / (std::f64::consts::SQRT_2 * dt);
        // The range from differences over 8 samples, which the noise barely widens.
        let k = 8.min(z.len() - 1);
        let v: Vec<f64> = (k..z.len())
            .map(|i| (z[i] - z[i - k]) / (t[i] - t[i - k]))
            .collect();
        let (lo, hi) = v
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
                (a.min(*x), b.max(*x))
            });
        let range = hi - lo;
        Self::Differentiated {
            noise_of_range: if range > 0.0 { noise_v / range } else { 0.0 },
        }
    }
}

impl ChannelChecks {
    /// What the residuals say is wrong, one sentence each: a channel far above its noise,
    /// and a pressure offset by one atmosphere.
    pub fn problems(&self) -> Vec<String> {
        let mut out = Vec::new();
        for (name, unit, c) in [
            ("force_n", "N", &self.force),
            ("p_piston_pa", "Pa", &self.p_piston),
            ("p_rod_pa", "Pa", &self.p_rod),
        ] {
            let Some(c) = c else { continue };
            match c.atmosphere_offset() {
                -1 => out.push(format!(
                    "{name} reads {:.1} kPa below the fitted model on average, about one atmosphere: a gauge pressure read as absolute? Declare it in the sidecar (\"sign_convention\": {{\"{name}\": \"gauge\"}})",
                    -c.mean_offset / 1e3
                )),
                1 => out.push(format!(
                    "{name} reads {:.1} kPa above the fitted model on average, about one atmosphere: an absolute pressure declared gauge? Check the sidecar's \"sign_convention\" for {name}",
                    c.mean_offset / 1e3
                )),
                _ => {}
            }
            let ratio = c.residual_to_noise();
            if ratio > RESIDUAL_NOISE_LIMIT {
                out.push(format!(
                    "the {name} residual ({:.4e} {unit} RMS) is {ratio:.1} times the noise the record shows ({:.4e} {unit} RMS): the model with these parameters does not describe the record (another strut, a missing effect, or a channel in another unit or convention)",
                    c.residual_rms, c.noise_rms
                ));
            }
        }
        out
    }
}

impl VelocitySource {
    /// The problem a differentiated velocity makes, if its noise is above
    /// [`VELOCITY_NOISE_LIMIT`] of its range.
    pub fn problem(&self) -> Option<String> {
        match *self {
            Self::Differentiated { noise_of_range } if noise_of_range > VELOCITY_NOISE_LIMIT => {
                Some(format!(
                    "the record has no velocity_m_s, and differentiating displacement_m gives velocity noise of {:.1} % of its range: friction and damping fits are biased by it (record the velocity, or low-pass the displacement first)",
                    100.0 * noise_of_range
                ))
            }
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn noise(n: usize, seed: u64, sd: f64) -> Vec<f64> {
        let mut s = seed;
        (0..n)
            .map(|_| {
                let u: f64 = (0..12)
                    .map(|_| {
                        s = s
                            .wrapping_mul(6364136223846793005)
                            .wrapping_add(1442695040888963407);
                        (s >> 11) as f64 / (1u64 << 53) as f64
                    })
                    .sum();
                sd * (u - 6.0)
            })
            .collect()
    }

    fn wave(n: usize, amp: f64) -> Vec<f64> {
        (0..n)
            .map(|i| amp * (2.0 * std::f64::consts::PI * 2.0 * i as f64 / 360.0).sin())
            .collect()
    }

    #[test]
    fn a_fit_at_the_noise_passes_and_a_model_error_does_not() {
        let model = wave(3600, 5e4);
        let e = noise(3600, 1, 150.0);
        let meas: Vec<f64> = model.iter().zip(&e).map(|(m, e)| m + e).collect();
        let good = ChannelCheck::of(&meas, &model);
        assert!(good.residual_to_noise() < 1.3, "{good:?}");
        // A 3 % amplitude error: 1,060 N RMS against 150 N of noise.
        let off: Vec<f64> = model.iter().map(|m| 0.97 * m).collect();
        let bad = ChannelCheck::of(&meas, &off);
        assert!(bad.residual_to_noise() > 5.0, "{bad:?}");
        let checks = ChannelChecks {
            force: Some(bad),
            ..Default::default()
        };
        let p = checks.problems();
        assert_eq!(p.len(), 1);
        assert!(p[0].contains("force_n residual") && p[0].contains("times the noise"));
    }

    #[test]
    fn one_atmosphere_below_the_model_reads_as_gauge() {
        let model: Vec<f64> = wave(3600, 2e6).iter().map(|p| p + 5e6).collect();
        let e = noise(3600, 2, 2e3);
        let gauge: Vec<f64> = model
            .iter()
            .zip(&e)
            .map(|(m, e)| m - STANDARD_ATMOSPHERE_PA + e)
            .collect();
        let c = ChannelCheck::of(&gauge, &model);
        assert_eq!(c.atmosphere_offset(), -1);
        let checks = ChannelChecks {
            p_rod: Some(c),
            ..Default::default()
        };
        assert!(checks.problems()[0].contains("gauge pressure read as absolute"));
        let abs: Vec<f64> = model.iter().map(|m| m + STANDARD_ATMOSPHERE_PA).collect();
        assert_eq!(ChannelCheck::of(&abs, &model).atmosphere_offset(), 1);
        // Half an atmosphere is not one.
        let half: Vec<f64> = model.iter().map(|m| m - 0.5e5).collect();
        assert_eq!(ChannelCheck::of(&half, &model).atmosphere_offset(), 0);
    }

    #[test]
    fn a_noiseless_exact_fit_is_not_flagged() {
        let model = wave(720, 1e4);
        let c = ChannelCheck::of(&model, &model);
        assert_eq!(c.residual_to_noise(), 0.0);
        assert!(c.noise_rms >= NOISE_FLOOR_OF_RANGE * 2e4 * 0.99);
    }

    #[test]
    fn differentiated_velocity_noise_is_measured_against_its_range() {
        let t: Vec<f64> = (0..3600).map(|i| i as f64 / 360.0).collect();
        let z = wave(3600, 7.5e-3);
        assert_eq!(
            VelocitySource::of(&t, &z, Some(&z)),
            VelocitySource::Measured
        );
        let clean = VelocitySource::of(&t, &z, None);
        assert!(clean.problem().is_none(), "{clean:?}");
        // 20 um of displacement noise at 360 Hz: 5 mm/s of velocity noise on a 0.19 m/s range.
        let e = noise(3600, 3, 2e-5);
        let noisy: Vec<f64> = z.iter().zip(&e).map(|(a, b)| a + b).collect();
        let v = VelocitySource::of(&t, &noisy, None);
        let VelocitySource::Differentiated { noise_of_range } = v else {
            panic!("{v:?}")
        };
        assert!(noise_of_range > 0.02 && noise_of_range < 0.04, "{v:?}");
        assert!(v.problem().unwrap().contains("no velocity_m_s"));
    }
}
