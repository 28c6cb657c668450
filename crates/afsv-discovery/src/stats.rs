//! Statistics behind "significant": information criteria corrected for serially correlated
//! residuals, a noise-floor estimate, and the decision rule.
//!
//! Time-series residuals are strongly autocorrelated, so counting every sample as an
//! independent observation would make any extra parameter look significant. We use the
//! effective sample size of an AR(1) process, `n_eff = n (1 - rho) / (1 + rho)` with `rho`
//! the lag-1 autocorrelation of the residuals (Bretherton et al., J. Climate 12, 1999),
//! in Gaussian information criteria `AIC = n_eff ln(RSS/n) + 2k`, `BIC = n_eff ln(RSS/n) + k ln(n_eff)`.

/// Lag-1 autocorrelation of a series (0 for fewer than 3 samples or zero variance).
pub fn lag1_autocorrelation(r: &[f64]) -> f64 {
    if r.len() < 3 {
        return 0.0;
    }
    let mean = r.iter().sum::<f64>() / r.len() as f64;
    let mut num = 0.0;
    let mut den = 0.0;
    for i in 0..r.len() {
        let d = r[i] - mean;
        den += d * d;
        if i + 1 < r.len() {
            num += d * (r[i + 1] - mean);
        }
    }
    if den <= 0.0 {
        0.0
    } else {
        (num / den).clamp(-0.999, 0.999)
    }
}

/// Effective number of independent samples of residual segments (one per record/channel),
/// from each segment's lag-1 autocorrelation; at least 1 per segment.
pub fn effective_samples(segments: &[&[f64]]) -> f64 {
    segments
        .iter()
        .map(|s| {
            let rho = lag1_autocorrelation(s).max(0.0);
            (s.len() as f64 * (1.0 - rho) / (1.0 + rho)).max(1.0)
        })
        .sum()
}

/// Gaussian Bayesian information criterion with `n_eff` effective samples, `n` samples,
/// residual sum of squares `rss` and `k` fitted parameters.
pub fn bic(rss: f64, n: f64, n_eff: f64, k: usize) -> f64 {
    n_eff * (rss / n).max(f64::MIN_POSITIVE).ln() + k as f64 * n_eff.max(1.0).ln()
}

/// Gaussian Akaike information criterion (same conventions as [`bic`]).
pub fn aic(rss: f64, n: f64, n_eff: f64, k: usize) -> f64 {
    n_eff * (rss / n).max(f64::MIN_POSITIVE).ln() + 2.0 * k as f64
}

/// Measurement-noise variance of a densely sampled smooth signal, from its fourth
/// differences `d[i] = y[i-2] - 4y[i-1] + 6y[i] - 4y[i+1] + y[i+2]`: white noise of variance
/// `s^2` gives `var(d) = 70 s^2`, while a smooth signal contributes `(2 pi f dt)^4` of its
/// own variance — 4e-4 for an 8 Hz strut test sampled at 360 Hz, where second differences
/// let the signal through and read the 150 N load-cell noise as 370 N. The variance is
/// `(1.4826 MAD)^2`, so a few sharp features (valve openings) do not inflate it.
///
/// Noise that a sensor's filter has made correlated from sample to sample reads low (to
/// 0.46 of its variance for a first-order filter with its corner at fs/7): the estimate is
/// then a lower bound, and the gap shrink computed with it is understated, never overstated.
pub fn noise_variance(y: &[f64]) -> f64 {
    if y.len() < 8 {
        return 0.0;
    }
    let mut d: Vec<f64> = (2..y.len() - 2)
        .map(|i| y[i - 2] - 4.0 * y[i - 1] + 6.0 * y[i] - 4.0 * y[i + 1] + y[i + 2])
        .collect();
    let med = median(&mut d);
    let mut dev: Vec<f64> = d.iter().map(|v| (v - med).abs()).collect();
    let sigma_d = 1.4826 * median(&mut dev);
    sigma_d * sigma_d / 70.0
}

fn median(v: &mut [f64]) -> f64 {
    if v.is_empty() {
        return 0.0;
    }
    v.sort_by(|a, b| a.total_cmp(b));
    let m = v.len() / 2;
    if v.len() % 2 == 1 {
        v[m]
    } else {
        0.5 * (v[m - 1] + v[m])
    }
}

/// Thresholds of the decision "this effect is significant".
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SignificanceRule {
    /// Required decrease of the effective-sample BIC on the training records.
    pub min_bic_drop: f64,
    /// Required relative decrease of the held-out mean squared error.
    pub min_holdout_gain: f64,
    /// Required decrease of the held-out error as a fraction of the calibrated baseline's
    /// reducible gap (its held-out error above the noise floor): once most of the gap is
    /// explained, polishing the last few percent does not name another effect.
    pub min_gap_fraction: f64,
}

impl Default for SignificanceRule {
    fn default() -> Self {
        Self {
            min_bic_drop: 10.0,
            min_holdout_gain: 0.10,
            min_gap_fraction: 0.02,
        }
    }
}

impl SignificanceRule {
    /// Whether going from (`bic_old`, `mse_old`) to (`bic_new`, `mse_new`) is significant,
    /// given the calibrated baseline's reducible held-out gap `gap`.
    pub fn accepts(
        &self,
        bic_old: f64,
        bic_new: f64,
        mse_old: f64,
        mse_new: f64,
        gap: f64,
    ) -> bool {
        let bic_ok = bic_old - bic_new >= self.min_bic_drop;
        let gain = if mse_old > 0.0 {
            (mse_old - mse_new) / mse_old
        } else {
            0.0
        };
        let of_gap = if gap > 0.0 {
            (mse_old - mse_new) / gap
        } else {
            0.0
        };
        bic_ok && gain >= self.min_holdout_gain && of_gap >= self.min_gap_fraction
    }
}

/// Fraction of the reducible held-out error removed: `(mse_before - mse_after) /
/// (mse_before - noise)`, clamped to [0, 1] and 0 when there is nothing reducible.
pub fn gap_shrink(mse_before: f64, mse_after: f64, noise: f64) -> f64 {
    let reducible = mse_before - noise;
    if reducible <= 0.0 {
        return 0.0;
    }
    ((mse_before - mse_after) / reducible).clamp(0.0, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lcg_noise(n: usize, seed: u64) -> Vec<f64> {
        let mut s = seed;
        (0..n)
            .map(|_| {
                // Sum of 4 uniforms: near-Gaussian, variance 4/12.
                (0..4)
                    .map(|_| {
                        s = s
                            .wrapping_mul(6364136223846793005)
                            .wrapping_add(1442695040888963407);
                        (s >> 11) as f64 / (1u64 << 53) as f64 - 0.5
                    })
                    .sum::<f64>()
            })
            .collect()
    }

    #[test]
    fn noise_variance_of_smooth_signal_plus_noise() {
        let e = lcg_noise(20_000, 3);
        let y: Vec<f64> = e
            .iter()
            .enumerate()
            .map(|(i, v)| (i as f64 * 0.001).sin() * 5.0 + 0.1 * v)
            .collect();
        let want = 0.01 * 4.0 / 12.0;
        let got = noise_variance(&y);
        assert!((got / want - 1.0).abs() < 0.1, "{got} vs {want}");
    }

    #[test]
    fn noise_variance_beside_a_fast_large_signal() {
        // 50 kN at 8 Hz sampled at 360 Hz with 150 N of noise (the strut bench's load cell).
        let e = lcg_noise(20_000, 5);
        let scale = 150.0 / (4.0_f64 / 12.0).sqrt();
        let y: Vec<f64> = e
            .iter()
            .enumerate()
            .map(|(i, v)| {
                5e4 * (2.0 * std::f64::consts::PI * 8.0 * i as f64 / 360.0).sin() + scale * v
            })
            .collect();
        let got = noise_variance(&y).sqrt();
        assert!((got / 150.0 - 1.0).abs() < 0.1, "{got} vs 150");
    }

    #[test]
    fn band_limited_noise_reads_low_never_high() {
        // First-order low-pass noise (a sensor's conditioning filter), corners 50 Hz and
        // 30 Hz at 360 and 200 Hz, on a slow signal: the estimate is a lower bound.
        for (a, seed) in [
            ((-2.0 * std::f64::consts::PI * 50.0 / 360.0).exp(), 7),
            ((-2.0 * std::f64::consts::PI * 30.0 / 200.0).exp(), 8),
        ] {
            let w = lcg_noise(40_000, seed);
            let mut e = vec![0.0; w.len()];
            for i in 1..w.len() {
                e[i] = a * e[i - 1] + w[i];
            }
            let var: f64 = e.iter().map(|v| v * v).sum::<f64>() / e.len() as f64;
            let y: Vec<f64> = e
                .iter()
                .enumerate()
                .map(|(i, v)| 20.0 * (i as f64 * 0.002).sin() + v)
                .collect();
            let got = noise_variance(&y);
            assert!(got < var && got > 0.3 * var, "a {a}: {got} vs {var}");
        }
    }

    #[test]
    fn white_noise_has_full_effective_size_and_smooth_residuals_do_not() {
        let e = lcg_noise(5000, 11);
        let n_white = effective_samples(&[&e]);
        assert!(n_white > 4000.0, "{n_white}");
        let smooth: Vec<f64> = (0..5000).map(|i| (i as f64 * 0.01).sin()).collect();
        assert!(effective_samples(&[&smooth]) < 10.0);
    }

    #[test]
    fn rule_needs_bic_holdout_and_gap() {
        let r = SignificanceRule::default();
        assert!(r.accepts(100.0, 50.0, 1.0, 0.5, 1.0));
        assert!(!r.accepts(100.0, 95.0, 1.0, 0.5, 1.0));
        assert!(!r.accepts(100.0, 50.0, 1.0, 0.99, 1.0));
        // A 20 % gain on what is left after a 99 % shrink is not a new effect.
        assert!(!r.accepts(100.0, 50.0, 0.01, 0.008, 1.0));
    }

    #[test]
    fn gap_shrink_accounts_for_noise() {
        assert!((gap_shrink(2.0, 1.1, 1.0) - 0.9).abs() < 1e-12);
        assert_eq!(gap_shrink(1.0, 0.9, 1.0), 0.0);
        assert_eq!(gap_shrink(2.0, 3.0, 0.0), 0.0);
    }
}
