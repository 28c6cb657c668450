//! Dense linear algebra on the cab-and-seat model's few coordinates (at most [`N_MAX`]):
//! Cholesky factorisation, the inverse of a symmetric positive definite matrix and the
//! eigenvalues of a symmetric one (cyclic Jacobi). Fixed-size arrays, no allocation.

// Dense matrix code reads best with explicit row and column indices.
#![allow(clippy::needless_range_loop)]

/// Largest number of generalised coordinates.
pub const N_MAX: usize = 5;

/// A square matrix of which the leading `n x n` block is used.
pub type Mat = [[f64; N_MAX]; N_MAX];

/// Lower Cholesky factor `L` of the leading `n x n` block of `a` (`a = L L^T`), or `None`
/// when that block is not positive definite.
pub fn cholesky(a: &Mat, n: usize) -> Option<Mat> {
    let mut l = [[0.0; N_MAX]; N_MAX];
    for i in 0..n {
        for j in 0..=i {
            let s = a[i][j] - (0..j).map(|k| l[i][k] * l[j][k]).sum::<f64>();
            if i == j {
                if !(s > 0.0 && s.is_finite()) {
                    return None;
                }
                l[i][i] = s.sqrt();
            } else {
                l[i][j] = s / l[j][j];
            }
        }
    }
    Some(l)
}

/// Solve `L y = b` (forward substitution) in place.
fn forward(l: &Mat, n: usize, b: &mut [f64; N_MAX]) {
    for i in 0..n {
        b[i] = (b[i] - (0..i).map(|k| l[i][k] * b[k]).sum::<f64>()) / l[i][i];
    }
}

/// Solve `L^T x = b` (back substitution) in place.
fn backward(l: &Mat, n: usize, b: &mut [f64; N_MAX]) {
    for i in (0..n).rev() {
        b[i] = (b[i] - (i + 1..n).map(|k| l[k][i] * b[k]).sum::<f64>()) / l[i][i];
    }
}

/// Inverse of the symmetric positive definite leading block of `a`, or `None`.
pub fn inverse_spd(a: &Mat, n: usize) -> Option<Mat> {
    let l = cholesky(a, n)?;
    let mut inv = [[0.0; N_MAX]; N_MAX];
    for j in 0..n {
        let mut e = [0.0; N_MAX];
        e[j] = 1.0;
        forward(&l, n, &mut e);
        backward(&l, n, &mut e);
        for i in 0..n {
            inv[i][j] = e[i];
        }
    }
    Some(inv)
}

/// `y = a x` on the leading block.
pub fn mul(a: &Mat, n: usize, x: &[f64; N_MAX]) -> [f64; N_MAX] {
    let mut y = [0.0; N_MAX];
    for i in 0..n {
        y[i] = (0..n).map(|j| a[i][j] * x[j]).sum();
    }
    y
}

/// Eigenvalues `lambda` of `K v = lambda M v` for symmetric `k` and symmetric positive
/// definite `m` (leading blocks), ascending: `L^-1 K L^-T` with `M = L L^T`, then cyclic
/// Jacobi rotations until the off-diagonal mass is below 1e-14 of the whole. `None` when
/// `m` is not positive definite.
pub fn generalized_eigenvalues(k: &Mat, m: &Mat, n: usize) -> Option<Vec<f64>> {
    let l = cholesky(m, n)?;
    // a = L^-1 K L^-T, column by column then row by row
    let mut a = [[0.0; N_MAX]; N_MAX];
    for j in 0..n {
        let mut col = [0.0; N_MAX];
        for i in 0..n {
            col[i] = k[i][j];
        }
        forward(&l, n, &mut col);
        for i in 0..n {
            a[i][j] = col[i];
        }
    }
    for i in 0..n {
        let mut row = a[i];
        forward(&l, n, &mut row);
        a[i] = row;
    }
    let norm: f64 = (0..n)
        .flat_map(|i| (0..n).map(move |j| (i, j)))
        .map(|(i, j)| a[i][j] * a[i][j])
        .sum();
    for _sweep in 0..50 {
        let off: f64 = (0..n)
            .flat_map(|i| (0..n).map(move |j| (i, j)))
            .filter(|(i, j)| i != j)
            .map(|(i, j)| a[i][j] * a[i][j])
            .sum();
        if off <= 1e-28 * norm {
            break;
        }
        for p in 0..n {
            for q in p + 1..n {
                if a[p][q] == 0.0 {
                    continue;
                }
                let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                // signum(0) = 1: a 45 deg rotation for equal diagonals
                let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
                let c = 1.0 / (t * t + 1.0).sqrt();
                let s = t * c;
                for r in 0..n {
                    let (arp, arq) = (a[r][p], a[r][q]);
                    a[r][p] = c * arp - s * arq;
                    a[r][q] = s * arp + c * arq;
                }
                for r in 0..n {
                    let (apr, aqr) = (a[p][r], a[q][r]);
                    a[p][r] = c * apr - s * aqr;
                    a[q][r] = s * apr + c * aqr;
                }
            }
        }
    }
    let mut ev: Vec<f64> = (0..n).map(|i| a[i][i]).collect();
    ev.sort_by(f64::total_cmp);
    Some(ev)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mat(rows: &[&[f64]]) -> Mat {
        let mut a = [[0.0; N_MAX]; N_MAX];
        for (i, r) in rows.iter().enumerate() {
            a[i][..r.len()].copy_from_slice(r);
        }
        a
    }

    #[test]
    fn the_inverse_of_a_spd_matrix_is_its_inverse() {
        let a = mat(&[&[4.0, 1.0, 0.5], &[1.0, 3.0, 0.2], &[0.5, 0.2, 2.0]]);
        let inv = inverse_spd(&a, 3).unwrap();
        for j in 0..3 {
            let mut e = [0.0; N_MAX];
            e[j] = 1.0;
            let col = mul(&a, 3, &mul(&inv, 3, &e));
            for (i, v) in col.iter().take(3).enumerate() {
                assert!((v - e[i]).abs() < 1e-14);
            }
        }
        assert!(cholesky(&mat(&[&[1.0, 2.0], &[2.0, 1.0]]), 2).is_none());
    }

    #[test]
    fn eigenvalues_of_a_two_mass_chain_match_the_quadratic() {
        // K = [[k1 + k2, -k2], [-k2, k2]], M = diag(m1, m2):
        // m1 m2 l^2 - (m1 k2 + m2 (k1 + k2)) l + k1 k2 = 0
        let (k1, k2, m1, m2) = (5.0, 2.0, 3.0, 1.0);
        let k = mat(&[&[k1 + k2, -k2], &[-k2, k2]]);
        let m = mat(&[&[m1, 0.0], &[0.0, m2]]);
        let ev = generalized_eigenvalues(&k, &m, 2).unwrap();
        let (a, b, c) = (m1 * m2, -(m1 * k2 + m2 * (k1 + k2)), k1 * k2);
        let d = (b * b - 4.0 * a * c).sqrt();
        let expect = [(-b - d) / (2.0 * a), (-b + d) / (2.0 * a)];
        for (e, x) in ev.iter().zip(expect) {
            assert!((e / x - 1.0).abs() < 1e-12, "{ev:?} vs {expect:?}");
        }
    }
}
