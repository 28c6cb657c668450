//! Small dense LU factorisation with partial pivoting, in caller-owned buffers
//! (no allocation per step in the implicit integrator).

/// Factor the row-major `n x n` matrix `a` in place; `piv` receives the row permutation.
/// Returns `false` if the matrix is singular to working precision.
pub(crate) fn lu_factor(a: &mut [f64], piv: &mut [usize], n: usize) -> bool {
    for (i, p) in piv.iter_mut().enumerate().take(n) {
        *p = i;
    }
    for k in 0..n {
        let mut p = k;
        let mut best = a[k * n + k].abs();
        for r in (k + 1)..n {
            let v = a[r * n + k].abs();
            if v > best {
                best = v;
                p = r;
            }
        }
        if best.is_nan() || best <= 0.0 || !best.is_finite() {
            return false;
        }
        if p != k {
            for c in 0..n {
                a.swap(k * n + c, p * n + c);
            }
            piv.swap(k, p);
        }
        let pivot = a[k * n + k];
        for r in (k + 1)..n {
            let f = a[r * n + k] / pivot;
            a[r * n + k] = f;
            for c in (k + 1)..n {
                a[r * n + c] -= f * a[k * n + c];
            }
        }
    }
    true
}

/// Solve `A x = b` with the factors from [`lu_factor`]; `b` is overwritten by `x`,
/// `tmp` is scratch of length `n`.
pub(crate) fn lu_solve(lu: &[f64], piv: &[usize], n: usize, b: &mut [f64], tmp: &mut [f64]) {
    for i in 0..n {
        tmp[i] = b[piv[i]];
    }
    for i in 0..n {
        let mut s = tmp[i];
        for j in 0..i {
            s -= lu[i * n + j] * tmp[j];
        }
        tmp[i] = s;
    }
    for i in (0..n).rev() {
        let mut s = tmp[i];
        for j in (i + 1)..n {
            s -= lu[i * n + j] * tmp[j];
        }
        tmp[i] = s / lu[i * n + i];
    }
    b[..n].copy_from_slice(&tmp[..n]);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_a_pivoting_system() {
        // [[0, 2, 1], [1, 1, 0], [3, 0, 1]] x = [5, 3, 6] has x = [1.5, 1.5, 1.5]... check by residual.
        let a0 = [0.0, 2.0, 1.0, 1.0, 1.0, 0.0, 3.0, 0.0, 1.0];
        let mut a = a0;
        let mut piv = [0; 3];
        assert!(lu_factor(&mut a, &mut piv, 3));
        let b0 = [5.0, 3.0, 6.0];
        let mut b = b0;
        let mut tmp = [0.0; 3];
        lu_solve(&a, &piv, 3, &mut b, &mut tmp);
        for r in 0..3 {
            let s: f64 = (0..3).map(|c| a0[r * 3 + c] * b[c]).sum();
            assert!((s - b0[r]).abs() < 1e-12);
        }
    }

    #[test]
    fn singular_is_reported() {
        let mut a = [1.0, 2.0, 2.0, 4.0];
        let mut piv = [0; 2];
        assert!(!lu_factor(&mut a, &mut piv, 2));
    }
}
