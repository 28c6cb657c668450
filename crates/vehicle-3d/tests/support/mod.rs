//! Helpers shared by the vehicle's integration tests.

use odeint::{Control, Integrator, Problem, Solver};
use vehicle_3d::Vehicle;

/// Fixed RK4 steps (both runs of a comparison take the same steps), `channel` sampled
/// every 10 ms over `t_end` s.
pub fn sampled(
    v: &Vehicle,
    y0: &[f64],
    t_end: f64,
    mut channel: impl FnMut(&[f64]) -> Vec<f64>,
) -> Vec<Vec<f64>> {
    let t_out: Vec<f64> = (0..=(t_end * 100.0).round() as usize)
        .map(|i| i as f64 * 0.01)
        .collect();
    let mut out = Vec::new();
    Integrator::new(Solver::Rk4 { step: 2e-4 }, 1e-6, 1e-6)
        .run(
            v,
            &Problem::new(0.0, y0, &t_out),
            &mut odeint::Workspace::new(y0.len()),
            |s| {
                out.push(channel(s.y));
                Control::Continue
            },
        )
        .unwrap();
    out
}

/// The oscillatory linear modes of `v` at `y0`: its right-hand side's Jacobian by central
/// differences (step `1e-7 max(|y_c|, 1e-2)` per state), its eigenvalues `λ` with
/// `Im λ > 0`, damping ratio `-Re λ / |λ|` at most 0.5 and frequency `|λ| / 2π` in `band`
/// (Hz), each with the velocity block `v` of its eigenvector (three steps of inverse
/// iteration from a shift beside `λ`; only its magnitudes are meaningful). Returns
/// `(frequency, |eigenvector entry|² of each velocity)`.
///
/// The eigenvalues come from nalgebra's real Schur form after balancing: the vehicle's
/// Jacobian mixes entries near 1e-2 with the tire terms near 1e8, and without balancing the
/// unbalanced QR iteration finds or misses the slow body modes depending on round-off in the
/// right-hand side (the two-axle bounce and pitch modes vanished from its list when the
/// forward dynamics changed at the 1e-13 level).
pub fn body_modes(v: &Vehicle, y0: &[f64], band: std::ops::Range<f64>) -> Vec<(f64, Vec<f64>)> {
    use nalgebra::{Complex, DMatrix, DVector};
    use odeint::OdeSystem;
    let n = y0.len();
    let mut jac = DMatrix::<f64>::zeros(n, n);
    let (mut fp, mut fm) = (vec![0.0; n], vec![0.0; n]);
    for c in 0..n {
        let h = 1e-7 * y0[c].abs().max(1e-2);
        let mut y = y0.to_vec();
        y[c] = y0[c] + h;
        v.rhs(0.0, &y, &mut fp);
        y[c] = y0[c] - h;
        v.rhs(0.0, &y, &mut fm);
        for r in 0..n {
            jac[(r, c)] = (fp[r] - fm[r]) / (2.0 * h);
        }
    }
    let jc = jac.map(|x| Complex::new(x, 0.0));
    let o = v.offsets();
    let mut modes = Vec::new();
    for lambda in balanced(&jac).complex_eigenvalues().iter() {
        let f = lambda.norm() / (2.0 * std::f64::consts::PI);
        if lambda.im <= 0.0 || -lambda.re > 0.5 * lambda.norm() || !band.contains(&f) {
            continue;
        }
        let shift = lambda * Complex::new(1.0 + 1e-9, 1e-9);
        let lu = (&jc - DMatrix::identity(n, n) * shift).lu();
        let mut x = DVector::from_element(n, Complex::new(1.0, 0.0));
        for _ in 0..3 {
            x = lu.solve(&x).unwrap();
            x /= Complex::new(x.norm(), 0.0);
        }
        modes.push((f, (o.v..o.afs).map(|k| x[k].norm_sqr()).collect()));
    }
    modes
}

/// `D⁻¹ a D` with `D` diagonal in powers of two (exact in floating point), each row and
/// column brought to comparable norms: the balancing of Parlett & Reinsch (Numer. Math. 13,
/// 1969), as LAPACK's `gebal` does before its QR iteration. The eigenvalues are `a`'s.
fn balanced(a: &nalgebra::DMatrix<f64>) -> nalgebra::DMatrix<f64> {
    let n = a.nrows();
    let mut b = a.clone();
    loop {
        let mut converged = true;
        for i in 0..n {
            let (mut c, mut r) = (0.0, 0.0);
            for j in (0..n).filter(|&j| j != i) {
                c += b[(j, i)].abs();
                r += b[(i, j)].abs();
            }
            if c == 0.0 || r == 0.0 {
                continue;
            }
            let s = c + r;
            let mut f = 1.0;
            while c < r / 2.0 {
                f *= 2.0;
                c *= 4.0;
            }
            while c > r * 2.0 {
                f /= 2.0;
                c /= 4.0;
            }
            if (c + r) / f < 0.95 * s {
                converged = false;
                for j in 0..n {
                    b[(i, j)] /= f;
                    b[(j, i)] *= f;
                }
            }
        }
        if converged {
            return b;
        }
    }
}
