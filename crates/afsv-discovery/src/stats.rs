//! Statistics behind "significant": information criteria corrected for serially correlated
//! residuals and the decision rule (the noise floor is
//! `optimize::noise::measurement_noise_variance`).
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
