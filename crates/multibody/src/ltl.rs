//! Sparse `H = L^T L` factorisation of a tree's joint-space mass matrix and the solve
//! with it (Featherstone, "Rigid Body Dynamics Algorithms", 2008, section 6.5, Tables 6.3
//! and 6.4). `H[i][j]` can be non-zero only if degree of freedom `i` is an ancestor of `j`
//! or the other way round, and the factor keeps that pattern (no fill-in), so the cost is
//! the sum over degrees of freedom of their depth squared instead of `n³ / 6`.

use nalgebra::{DMatrix, DVector};

/// Factors `H = L^T L` in place over the lower triangle of `h` (`parent[k]` is the
/// previous degree of freedom on `k`'s path to the root, `λ(k)` of Table 6.3, always
/// `< k`). Returns `false`, leaving `h` partly factored, unless every pivot is finite and
/// positive (`H` positive definite).
pub(crate) fn factor(h: &mut DMatrix<f64>, parent: &[Option<usize>]) -> bool {
    for k in (0..parent.len()).rev() {
        let pivot = h[(k, k)];
        if !(pivot.is_finite() && pivot > 0.0) {
            return false;
        }
        let lkk = pivot.sqrt();
        h[(k, k)] = lkk;
        let mut i = parent[k];
        while let Some(a) = i {
            h[(k, a)] /= lkk;
            i = parent[a];
        }
        let mut i = parent[k];
        while let Some(a) = i {
            let lka = h[(k, a)];
            let mut j = Some(a);
            while let Some(b) = j {
                h[(a, b)] -= lka * h[(k, b)];
                j = parent[b];
            }
            i = parent[a];
        }
    }
    true
}

/// Solves `L^T L x = b` in place (`b` becomes `x`) with the factor of [`factor`]:
/// `L^T y = b` from the leaves to the root, then `L x = y` from the root outwards
/// (Table 6.4).
pub(crate) fn solve(l: &DMatrix<f64>, parent: &[Option<usize>], b: &mut DVector<f64>) {
    for k in (0..parent.len()).rev() {
        b[k] /= l[(k, k)];
        let mut i = parent[k];
        while let Some(a) = i {
            b[a] -= l[(k, a)] * b[k];
            i = parent[a];
        }
    }
    for k in 0..parent.len() {
        let mut i = parent[k];
        while let Some(a) = i {
            b[k] -= l[(k, a)] * b[a];
            i = parent[a];
        }
        b[k] /= l[(k, k)];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A branched tree of 6 degrees of freedom: 0 <- 1 <- 2, 1 <- 3, 0 <- 4 <- 5.
    const PARENT: [Option<usize>; 6] = [None, Some(0), Some(1), Some(1), Some(0), Some(4)];

    fn ancestor_or_self(a: usize, mut k: usize) -> bool {
        loop {
            if k == a {
                return true;
            }
            match PARENT[k] {
                Some(p) => k = p,
                None => return false,
            }
        }
    }

    /// An SPD matrix with the tree's sparsity: `M^T M + n 1` for `M` with that pattern.
    fn tree_spd() -> DMatrix<f64> {
        let n = PARENT.len();
        let m = DMatrix::from_fn(n, n, |i, j| {
            if ancestor_or_self(j, i) {
                1.0 + 0.3 * i as f64 - 0.2 * j as f64
            } else {
                0.0
            }
        });
        m.transpose() * &m + DMatrix::identity(n, n) * n as f64
    }

    #[test]
    fn solve_matches_a_dense_solve_and_keeps_the_pattern() {
        let h = tree_spd();
        let n = h.nrows();
        for i in 0..n {
            for j in 0..n {
                if !(ancestor_or_self(i, j) || ancestor_or_self(j, i)) {
                    assert_eq!(h[(i, j)], 0.0, "test matrix must have the tree pattern");
                }
            }
        }
        let b = DVector::from_fn(n, |i, _| (i as f64 - 2.5) * 0.7);
        let mut l = h.clone();
        assert!(factor(&mut l, &PARENT));
        let mut x = b.clone();
        solve(&l, &PARENT, &mut x);
        let dense = h.clone().cholesky().unwrap().solve(&b);
        assert!((&x - dense).norm() < 1e-12 * x.norm());
        assert!((&h * &x - &b).norm() < 1e-12 * b.norm());
    }

    #[test]
    fn an_indefinite_matrix_is_refused() {
        let mut h = tree_spd();
        h[(2, 2)] = -1.0;
        assert!(!factor(&mut h, &PARENT));
        let mut h = tree_spd();
        h[(0, 0)] = f64::NAN;
        assert!(!factor(&mut h, &PARENT));
    }
}
