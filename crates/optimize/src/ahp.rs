//! Analytic Hierarchy Process (Saaty): weights as the normalised principal eigenvector of a
//! reciprocal pairwise-comparison matrix, Saaty's consistency ratio, and the composition of
//! level weights used in section 4.3.4 (Eqs 4.11-4.17).

/// Why AHP weights could not be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum AhpError {
    /// The matrix is empty, not square, or has non-positive / non-finite entries.
    #[error("invalid pairwise comparison matrix: {0}")]
    Invalid(String),
    /// Power iteration did not settle.
    #[error("principal eigenvector did not converge in {0} iterations")]
    NoConvergence(usize),
}

/// Weights of one comparison matrix.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct AhpWeights {
    /// Normalised principal eigenvector (sums to 1).
    pub weights: Vec<f64>,
    /// Principal eigenvalue `lambda_max`.
    pub lambda_max: f64,
    /// Consistency index `(lambda_max - n) / (n - 1)`.
    pub consistency_index: f64,
    /// Consistency ratio `CI / RI(n)` (Saaty's random index); below 0.1 is acceptable.
    pub consistency_ratio: f64,
}

/// Saaty's random consistency index for n = 1..=10.
const RANDOM_INDEX: [f64; 10] = [0.0, 0.0, 0.58, 0.90, 1.12, 1.24, 1.32, 1.41, 1.45, 1.49];

/// Principal-eigenvector weights of the square pairwise-comparison matrix `m` (rows of
/// equal length, positive entries), by power iteration (Eq 4.12 from Eq 4.11).
pub fn weights(m: &[Vec<f64>]) -> Result<AhpWeights, AhpError> {
    let n = m.len();
    if n == 0 || m.iter().any(|r| r.len() != n) {
        return Err(AhpError::Invalid(format!(
            "expected a square matrix, got {n} rows"
        )));
    }
    if m.iter().flatten().any(|v| !v.is_finite() || *v <= 0.0) {
        return Err(AhpError::Invalid(
            "entries must be positive and finite".into(),
        ));
    }
    let mut w = vec![1.0 / n as f64; n];
    let mut next = vec![0.0; n];
    let max_iter = 1000;
    for it in 0..max_iter {
        for i in 0..n {
            next[i] = m[i].iter().zip(&w).map(|(a, b)| a * b).sum();
        }
        let s: f64 = next.iter().sum();
        let mut change: f64 = 0.0;
        for i in 0..n {
            let v = next[i] / s;
            change = change.max((v - w[i]).abs());
            w[i] = v;
        }
        if change < 1e-14 {
            break;
        }
        if it + 1 == max_iter {
            return Err(AhpError::NoConvergence(max_iter));
        }
    }
    let lambda_max = (0..n)
        .map(|i| m[i].iter().zip(&w).map(|(a, b)| a * b).sum::<f64>() / w[i])
        .sum::<f64>()
        / n as f64;
    let consistency_index = if n > 1 {
        (lambda_max - n as f64) / (n as f64 - 1.0)
    } else {
        0.0
    };
    let ri = RANDOM_INDEX.get(n - 1).copied().unwrap_or(1.49);
    let consistency_ratio = if ri > 0.0 {
        consistency_index / ri
    } else {
        0.0
    };
    Ok(AhpWeights {
        weights: w,
        lambda_max,
        consistency_index,
        consistency_ratio,
    })
}

/// Composite weights of an incomplete hierarchy (Eq 4.17):
/// `W = normalize(W_III/II · W_a · W_II/I)`, where `lower[k]` holds the level-III weights
/// with respect to goal `k` (length = number of measures, zeros for unrelated measures),
/// `w_a[k]` the share of measures related to goal `k` (Eq 4.16), and `upper` the
/// level-II weights (Eq 4.12).
pub fn compose(lower: &[Vec<f64>], w_a: &[f64], upper: &[f64]) -> Result<Vec<f64>, AhpError> {
    if lower.len() != upper.len() || w_a.len() != upper.len() || lower.is_empty() {
        return Err(AhpError::Invalid(
            "one column of level-III weights and one W_a entry per level-II goal".into(),
        ));
    }
    let m = lower[0].len();
    if lower.iter().any(|c| c.len() != m) {
        return Err(AhpError::Invalid(
            "level-III columns differ in length".into(),
        ));
    }
    let mut w = vec![0.0; m];
    for k in 0..upper.len() {
        for (wi, l) in w.iter_mut().zip(&lower[k]) {
            *wi += l * w_a[k] * upper[k];
        }
    }
    let s: f64 = w.iter().sum();
    if s.is_nan() || s <= 0.0 {
        return Err(AhpError::Invalid("composite weights sum to zero".into()));
    }
    Ok(w.into_iter().map(|v| v / s).collect())
}

/// Place the weights of a sub-matrix comparing `indices` of `n` measures into a full column
/// (zeros elsewhere), as the block matrices of Eq 4.14 do.
pub fn embed(sub: &[f64], indices: &[usize], n: usize) -> Vec<f64> {
    let mut col = vec![0.0; n];
    for (&i, &v) in indices.iter().zip(sub) {
        col[i] = v;
    }
    col
}

#[cfg(test)]
mod tests {
    use super::*;

    fn m2() -> Vec<Vec<f64>> {
        vec![
            vec![1.0, 3.0, 2.0],
            vec![1.0 / 3.0, 1.0, 0.5],
            vec![0.5, 2.0, 1.0],
        ]
    }

    #[test]
    fn consistent_matrix_gives_exact_ratios() {
        let m = vec![
            vec![1.0, 2.0, 4.0],
            vec![0.5, 1.0, 2.0],
            vec![0.25, 0.5, 1.0],
        ];
        let w = weights(&m).unwrap();
        assert!((w.weights[0] - 4.0 / 7.0).abs() < 1e-12);
        assert!((w.lambda_max - 3.0).abs() < 1e-12);
        assert!(w.consistency_ratio.abs() < 1e-12);
    }

    #[test]
    fn level_two_weights_of_eq_4_12() {
        let w = weights(&m2()).unwrap();
        for (got, want) in w.weights.iter().zip([0.54, 0.16, 0.30]) {
            assert!((got - want).abs() < 0.005, "{:?}", w.weights);
        }
        assert!(w.consistency_ratio < 0.1);
    }

    #[test]
    fn composite_weights_of_eq_4_17() {
        // Eq 4.14: yaw stability compares (L, omega, zeta); efficiency (zeta, Gamma);
        // maneuverability (Gamma, OS, psi). Measure order: L, omega, zeta, Gamma, OS, psi.
        let a1 = weights(&[
            vec![1.0, 0.2, 1.0],
            vec![5.0, 1.0, 1.59],
            vec![1.0, 0.63, 1.0],
        ])
        .unwrap();
        let a2 = weights(&[vec![1.0, 1.76], vec![0.57, 1.0]]).unwrap();
        let a3 = weights(&[
            vec![1.0, 1.25, 1.0],
            vec![0.8, 1.0, 1.3],
            vec![1.0, 0.77, 1.0],
        ])
        .unwrap();
        let lower = vec![
            embed(&a1.weights, &[0, 1, 2], 6),
            embed(&a2.weights, &[2, 3], 6),
            embed(&a3.weights, &[3, 4, 5], 6),
        ];
        // Eq 4.15 columns.
        for (got, want) in lower[0].iter().zip([0.17, 0.58, 0.25, 0.0, 0.0, 0.0]) {
            assert!((got - want).abs() < 0.01, "{:?}", lower[0]);
        }
        let upper = weights(&m2()).unwrap().weights;
        let w = compose(&lower, &[3.0 / 6.0, 2.0 / 6.0, 3.0 / 6.0], &upper).unwrap();
        for (got, want) in w.iter().zip([0.1, 0.33, 0.21, 0.15, 0.11, 0.1]) {
            assert!((got - want).abs() < 0.01, "{w:?}");
        }
    }

    #[test]
    fn bad_matrices_are_errors() {
        assert!(weights(&[]).is_err());
        assert!(weights(&[vec![1.0, 2.0]]).is_err());
        assert!(weights(&[vec![1.0, -2.0], vec![0.5, 1.0]]).is_err());
        assert!(weights(&[vec![1.0, f64::NAN], vec![0.5, 1.0]]).is_err());
    }
}
