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
//!
//! The measurement noise of a densely sampled record ([`measurement_noise_variance`]) uses
//! the fourth differences the same way, with a robust (median) spread: fits compare their
//! residual with it to tell "the model fits to the noise" from "the model misses something".

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

/// The usual floor of [`measurement_noise_rms`]: 0.1 % of the record's range.
pub const NOISE_FLOOR_OF_RANGE: f64 = 1e-3;

/// The noise RMS that a fit compares its residual with: [`measurement_noise_variance`]'s
/// square root, floored at `floor_of_range` of the record's range (max - min), so a
/// noiseless record (a simulation) does not make a residual of that size look like a poor
/// fit.
pub fn measurement_noise_rms(y: &[f64], floor_of_range: f64) -> f64 {
    let (lo, hi) = y
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(*v), b.max(*v))
        });
    let range = if hi >= lo { hi - lo } else { 0.0 };
    measurement_noise_variance(y)
        .sqrt()
        .max(floor_of_range * range)
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
pub fn measurement_noise_variance(y: &[f64]) -> f64 {
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
        let got = measurement_noise_variance(&y);
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
        let got = measurement_noise_variance(&y).sqrt();
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
            let got = measurement_noise_variance(&y);
            assert!(got < var && got > 0.3 * var, "a {a}: {got} vs {var}");
        }
    }
}
