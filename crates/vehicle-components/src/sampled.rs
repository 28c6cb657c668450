//! Lookups in sampled time tables (a recorded excitation, a steering-wheel table) at every
//! right-hand side: the interval is looked for first near a guessed index, so a uniformly
//! sampled table needs two or three comparisons instead of a binary search per call.

/// The partition point of `ts` for the predicate `left` (true on a prefix of `ts`, false on
/// the rest), exactly `ts.partition_point(left)`: looked for within four steps of the
/// index `guess` (e.g. `(t - ts[0])` times the mean sample rate; any value is safe), then by
/// binary search.
#[inline]
pub fn partition_point_near(ts: &[f64], guess: f64, left: impl Fn(f64) -> bool) -> usize {
    let n = ts.len();
    let mut i = if guess > 0.0 {
        (guess as usize).min(n)
    } else {
        0
    };
    for _ in 0..4 {
        if i > 0 && !left(ts[i - 1]) {
            i -= 1;
        } else if i < n && left(ts[i]) {
            i += 1;
        } else {
            return i;
        }
    }
    ts.partition_point(|&x| left(x))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_point_is_the_binary_search_one_from_any_guess() {
        let uniform: Vec<f64> = (0..300).map(|i| 1000.0 + i as f64 / 100.0).collect();
        let jittered: Vec<f64> = (0..300)
            .map(|i| i as f64 * 0.01 + 0.004 * ((i * 7919 % 13) as f64 / 13.0))
            .collect();
        let uneven: Vec<f64> = (0..100)
            .map(|i| i as f64 * 1e-3)
            .chain((1..100).map(|i| 0.1 + i as f64))
            .collect();
        for ts in [&uniform, &jittered, &uneven] {
            let n = ts.len();
            let rate = (n - 1) as f64 / (ts[n - 1] - ts[0]);
            let mut queries: Vec<f64> = ts.to_vec();
            queries.extend(ts.windows(2).map(|w| 0.5 * (w[0] + w[1])));
            queries.extend([ts[0] - 1.0, ts[n - 1] + 1.0, f64::NAN, f64::INFINITY]);
            for &t in &queries {
                for guess in [(t - ts[0]) * rate, -5.0, 1e9, f64::NAN, n as f64 / 2.0] {
                    let at_or_before = |x: f64| x <= t;
                    assert_eq!(
                        partition_point_near(ts, guess, at_or_before),
                        ts.partition_point(|&x| at_or_before(x)),
                        "t {t}, guess {guess}"
                    );
                    let before = |x: f64| x.total_cmp(&t) == std::cmp::Ordering::Less;
                    assert_eq!(
                        partition_point_near(ts, guess, before),
                        ts.partition_point(|&x| before(x)),
                        "t {t}, guess {guess}"
                    );
                }
            }
        }
    }
}
