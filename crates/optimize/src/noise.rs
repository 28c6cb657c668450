//! The noise level of an objective from its values at equally spaced points along a line,
//! by the difference-table method of Moré & Wild (2011, "Estimating computational noise",
//! SIAM J. Sci. Comput. 33): for noise of standard deviation sigma, the k-th differences
//! satisfy `E[(Delta^k f)^2] = sigma^2 (2k)! / (k!)^2`, while a smooth part's differences
//! vanish as the spacing shrinks. The estimate is taken at the first order k whose
//! estimates for k, k+1 and k+2 agree within a factor 4 and whose differences change sign.
//!
//! Use: a forward-difference step near `2 sqrt(sigma / |f''|)` and a central one near
//! `(3 sigma / |f'''|)^(1/3)` balance truncation against noise (Gill, Murray & Wright
//! 1981, section 8.6); a gradient error of about `sigma / h` is what the noise costs.

/// Highest difference order examined.
const MAX_ORDER: usize = 6;

/// Noise standard deviation of `values` (f at equally spaced points, at least
/// `MAX_ORDER + 3 = 9` of them), or `None` when the table shows no consistent noise level
/// (a smooth function at this spacing, or too few points).
pub fn noise_level(values: &[f64]) -> Option<f64> {
    if values.len() < MAX_ORDER + 3 || values.iter().any(|v| !v.is_finite()) {
        return None;
    }
    let mut diff = values.to_vec();
    let mut sigma = [0.0; MAX_ORDER + 1];
    let mut sign_change = [false; MAX_ORDER + 1];
    let mut gamma = 1.0;
    for k in 1..=MAX_ORDER {
        diff = diff.windows(2).map(|w| w[1] - w[0]).collect();
        // gamma_k = (k!)^2 / (2k)!, by the recurrence gamma_k = gamma_{k-1} k / (2 (2k - 1)).
        gamma *= k as f64 / (2.0 * (2.0 * k as f64 - 1.0));
        let mean_sq = diff.iter().map(|d| d * d).sum::<f64>() / diff.len() as f64;
        sigma[k] = (gamma * mean_sq).sqrt();
        let (lo, hi) = diff
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), d| (a.min(*d), b.max(*d)));
        sign_change[k] = lo < 0.0 && hi > 0.0;
    }
    if sigma[1] == 0.0 {
        return Some(0.0);
    }
    (1..=MAX_ORDER - 2).find_map(|k| {
        let s = &sigma[k..k + 3];
        let (lo, hi) = s
            .iter()
            .fold((f64::MAX, 0.0f64), |(a, b), v| (a.min(*v), b.max(*v)));
        (sign_change[k] && hi <= 4.0 * lo).then_some(sigma[k])
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Stream;

    /// Uniform noise of standard deviation `sigma` (width sigma sqrt(12)).
    fn noisy(sigma: f64, seed: u64, smooth: impl Fn(f64) -> f64) -> Vec<f64> {
        let mut s = Stream::new(seed);
        (0..13)
            .map(|i| smooth(1.0 + 1e-4 * i as f64) + sigma * 12f64.sqrt() * (s.uniform() - 0.5))
            .collect()
    }

    #[test]
    fn recovers_the_noise_of_a_smooth_function_within_a_factor_3() {
        for seed in 0..20 {
            let sigma = 1e-6;
            let est = noise_level(&noisy(sigma, seed, |x| x.exp() + x * x)).unwrap();
            assert!(est > sigma / 3.0 && est < 3.0 * sigma, "seed {seed}: {est}");
        }
    }

    #[test]
    fn exact_and_short_inputs() {
        assert_eq!(noise_level(&[2.0; 9]), Some(0.0));
        assert_eq!(noise_level(&[1.0; 5]), None);
        // A noiseless cubic: the fourth differences vanish without sign changes.
        let cubic: Vec<f64> = (0..12).map(|i| (i as f64).powi(3)).collect();
        assert_eq!(noise_level(&cubic), None);
    }
}
