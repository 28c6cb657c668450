//! Small dense LU factorisation with partial pivoting, in caller-owned buffers
//! (no allocation per step in the implicit integrator).

/// Factor the row-major `n x n` matrix `a` in place; `piv` receives the row permutation.
/// Returns `false` if the matrix is singular to working precision. As in [`lu_solve`], a
/// 3 x 3 matrix runs fixed-size code with the same operations in the same order.
pub(crate) fn lu_factor(a: &mut [f64], piv: &mut [usize], n: usize) -> bool {
    if n == 3 {
        return eliminate(&mut a[..9], &mut piv[..3]);
    }
    eliminate(&mut a[..n * n], &mut piv[..n])
}

/// Gaussian elimination with partial pivoting of [`lu_factor`] (`piv.len()` rows).
#[inline(always)]
fn eliminate(a: &mut [f64], piv: &mut [usize]) -> bool {
    let n = piv.len();
    for (i, p) in piv.iter_mut().enumerate() {
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
/// `tmp` is scratch of length `n`. The strut blocks' size (3) runs fixed-size code the
/// compiler unrolls, with the same operations in the same order as any other size.
pub(crate) fn lu_solve(lu: &[f64], piv: &[usize], n: usize, b: &mut [f64], tmp: &mut [f64]) {
    if n == 3 {
        let mut x = [0.0; 3];
        substitute(&lu[..9], &piv[..3], b, &mut x);
        b[..3].copy_from_slice(&x);
        return;
    }
    let x = &mut tmp[..n];
    substitute(lu, piv, b, x);
    b[..n].copy_from_slice(x);
}

/// Forward and back substitution of [`lu_solve`] into `x` (`x.len()` unknowns).
#[inline(always)]
fn substitute(lu: &[f64], piv: &[usize], b: &[f64], x: &mut [f64]) {
    let n = x.len();
    for i in 0..n {
        x[i] = b[piv[i]];
    }
    for i in 0..n {
        let mut s = x[i];
        for j in 0..i {
            s -= lu[i * n + j] * x[j];
        }
        x[i] = s;
    }
    for i in (0..n).rev() {
        let mut s = x[i];
        for j in (i + 1)..n {
            s -= lu[i * n + j] * x[j];
        }
        x[i] = s / lu[i * n + i];
    }
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

    /// A 3 x 3 system takes the fixed-size code; the same system as the leading block of a
    /// 4 x 4 block-diagonal one takes the general code, whose extra terms are exact zeros:
    /// both must give the same unknowns to the bit.
    #[test]
    fn the_fixed_size_path_is_the_general_one_to_the_bit() {
        let a3 = [0.3, -2.0, 1.1, 4.0, 0.7, -0.2, -1.3, 0.9, 5.0];
        let b3 = [1.0, -0.4, 2.5];
        let mut lu3 = a3;
        let mut piv3 = [0; 3];
        assert!(lu_factor(&mut lu3, &mut piv3, 3));
        let mut x3 = b3;
        lu_solve(&lu3, &piv3, 3, &mut x3, &mut [0.0; 3]);
        let mut a4 = [0.0; 16];
        for r in 0..3 {
            a4[r * 4..r * 4 + 3].copy_from_slice(&a3[r * 3..r * 3 + 3]);
        }
        a4[15] = 1.0;
        let mut piv4 = [0; 4];
        assert!(lu_factor(&mut a4, &mut piv4, 4));
        assert_eq!(piv4[..3], piv3);
        let mut x4 = [b3[0], b3[1], b3[2], 7.0];
        lu_solve(&a4, &piv4, 4, &mut x4, &mut [0.0; 4]);
        assert_eq!(x4[..3], x3);
        assert_eq!(x4[3], 7.0);
        for r in 0..3 {
            let s: f64 = (0..3).map(|c| a3[r * 3 + c] * x3[c]).sum();
            assert!((s - b3[r]).abs() < 1e-12, "row {r}: {s}");
        }
    }

    #[test]
    fn singular_is_reported() {
        let mut a = [1.0, 2.0, 2.0, 4.0];
        let mut piv = [0; 2];
        assert!(!lu_factor(&mut a, &mut piv, 2));
    }
}
