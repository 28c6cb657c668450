//! Latin hypercube sampling of the unit cube (McKay, Beckman & Conover 1979): each of the
//! `n` points falls in a different one of `n` equal strata along every axis, at a uniform
//! position inside its stratum. The maximin option draws several hypercubes and keeps the
//! one whose closest pair of points is farthest apart (Johnson, Moore & Ylvisaker 1990).

use crate::problem::{require, OptimizeError};
use crate::rng::Stream;

/// Largest number of points times dimensions one sample may hold (bounds the allocation).
pub const MAX_SAMPLE_VALUES: usize = 10_000_000;

/// Settings of [`latin_hypercube`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LhsOptions {
    /// Number of points (>= 1).
    pub points: usize,
    /// Dimension (>= 1).
    pub dim: usize,
    /// Seed of the random stream.
    pub seed: u64,
    /// Hypercubes drawn for the maximin criterion (1: a plain LHS).
    pub maximin_candidates: usize,
}

/// A Latin hypercube of `points` points in `[0, 1]^dim` (one `Vec` per point).
pub fn latin_hypercube(o: &LhsOptions) -> Result<Vec<Vec<f64>>, OptimizeError> {
    require(o.points >= 1, "points", "at least 1")?;
    require(o.dim >= 1, "dim", "at least 1")?;
    require(
        o.maximin_candidates >= 1,
        "maximin_candidates",
        "at least 1",
    )?;
    require(
        o.points.saturating_mul(o.dim) <= MAX_SAMPLE_VALUES,
        "points",
        "points x dim must not exceed 1e7",
    )?;
    let mut stream = Stream::new(o.seed);
    let mut best = one_hypercube(o.points, o.dim, &mut stream);
    let mut best_d = min_distance2(&best);
    for _ in 1..o.maximin_candidates {
        let c = one_hypercube(o.points, o.dim, &mut stream);
        let d = min_distance2(&c);
        if d > best_d {
            best = c;
            best_d = d;
        }
    }
    Ok(best)
}

/// One hypercube: a random permutation of the strata per axis (Fisher-Yates), a uniform
/// offset inside each stratum.
fn one_hypercube(n: usize, dim: usize, s: &mut Stream) -> Vec<Vec<f64>> {
    let mut pts = vec![vec![0.0; dim]; n];
    let mut perm: Vec<usize> = (0..n).collect();
    for k in 0..dim {
        for i in (1..n).rev() {
            perm.swap(i, s.index(i + 1));
        }
        for (p, &stratum) in pts.iter_mut().zip(&perm) {
            p[k] = (stratum as f64 + s.uniform()) / n as f64;
        }
    }
    pts
}

/// Squared distance of the closest pair (infinity for one point).
fn min_distance2(pts: &[Vec<f64>]) -> f64 {
    let mut d = f64::INFINITY;
    for (i, a) in pts.iter().enumerate() {
        for b in &pts[i + 1..] {
            let s: f64 = a.iter().zip(b).map(|(x, y)| (x - y) * (x - y)).sum();
            d = d.min(s);
        }
    }
    d
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn opts(points: usize, dim: usize, seed: u64, m: usize) -> LhsOptions {
        LhsOptions {
            points,
            dim,
            seed,
            maximin_candidates: m,
        }
    }

    proptest! {
        #[test]
        fn one_point_per_stratum_on_every_axis(n in 1usize..40, dim in 1usize..6, seed in 0u64..1000) {
            let pts = latin_hypercube(&opts(n, dim, seed, 1)).unwrap();
            prop_assert_eq!(pts.len(), n);
            for k in 0..dim {
                let mut strata: Vec<usize> = pts.iter().map(|p| (p[k] * n as f64) as usize).collect();
                strata.sort_unstable();
                prop_assert_eq!(strata, (0..n).collect::<Vec<_>>());
            }
        }
    }

    #[test]
    fn seeded_and_maximin_spreads_points() {
        let a = latin_hypercube(&opts(20, 3, 5, 1)).unwrap();
        assert_eq!(a, latin_hypercube(&opts(20, 3, 5, 1)).unwrap());
        assert_ne!(a, latin_hypercube(&opts(20, 3, 6, 1)).unwrap());
        let m = latin_hypercube(&opts(20, 3, 5, 50)).unwrap();
        assert!(min_distance2(&m) >= min_distance2(&a));
        assert!(latin_hypercube(&opts(0, 3, 5, 1)).is_err());
        assert!(latin_hypercube(&opts(usize::MAX, 3, 5, 1)).is_err());
    }
}
