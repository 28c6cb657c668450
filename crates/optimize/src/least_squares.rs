//! Bounded nonlinear least squares by Levenberg-Marquardt with Marquardt's diagonal scaling
//! (Marquardt 1963; Nocedal & Wright, *Numerical Optimization*, ch. 10), forward-difference
//! Jacobian, and parameter standard errors from the Jacobian at the solution:
//! `cov = s^2 (J^T J)^-1`, `s^2 = RSS / (m - n)`.
//!
//! The normal equations are solved in parameters scaled by their typical magnitudes
//! (`p_j / typical_j`, as MINPACK's `diag`): physical parameters span many decades (a bulk
//! modulus of 1e9 Pa beside a leakage coefficient of 1e-13 m³/(s·Pa)), and unscaled
//! `J^T J` would then lose every digit in the Cholesky factorisation.

use nalgebra::{DMatrix, DVector};

/// A least-squares problem: find `p` minimising `sum r_i(p)^2`.
pub trait Problem {
    /// Number of free parameters.
    fn n_params(&self) -> usize;
    /// Number of residuals (must be at least `n_params`).
    fn n_residuals(&self) -> usize;
    /// Fill `r` with the residuals at `p`. Return `Err` with a reason if the model cannot be
    /// evaluated there (e.g. its simulation diverged); the fit then treats the point as
    /// infinitely bad and shortens its step.
    fn residuals(&self, p: &[f64], r: &mut [f64]) -> Result<(), String>;
}

/// Settings of [`fit`].
#[derive(Debug, Clone, PartialEq)]
pub struct FitOptions {
    /// Iteration limit.
    pub max_iter: usize,
    /// Stop when the relative decrease of the residual sum of squares falls below this.
    pub ftol: f64,
    /// Stop when every parameter step is below `xtol * (|p| + xtol)`.
    pub xtol: f64,
    /// Lower bounds (one per parameter; `f64::NEG_INFINITY` for none).
    pub lower: Option<Vec<f64>>,
    /// Upper bounds.
    pub upper: Option<Vec<f64>>,
    /// Relative forward-difference step for the Jacobian.
    pub diff_step: f64,
    /// Typical magnitude of each parameter: scales the parameter in the linear algebra and
    /// sets the difference step when `p` is near zero. Default: `|p0|`, or 1 where `p0` is 0.
    pub typical: Option<Vec<f64>>,
}

impl Default for FitOptions {
    fn default() -> Self {
        Self {
            max_iter: 100,
            ftol: 1e-10,
            xtol: 1e-10,
            lower: None,
            upper: None,
            diff_step: 1e-6,
            typical: None,
        }
    }
}

/// Outcome of [`fit`].
#[derive(Debug, Clone, PartialEq)]
pub struct FitResult {
    /// Best parameters found.
    pub params: Vec<f64>,
    /// Residual sum of squares at `params`.
    pub rss: f64,
    /// Number of residuals.
    pub n_residuals: usize,
    /// Iterations used.
    pub iterations: usize,
    /// Residual evaluations used (including Jacobian columns).
    pub evaluations: usize,
    /// Whether a convergence test was met (otherwise the iteration limit ended the fit).
    pub converged: bool,
    /// Standard error of each parameter (`NaN` where the Jacobian gives no information).
    pub std_errors: Vec<f64>,
    /// Parameter covariance matrix, row-major `n x n`.
    pub covariance: Vec<f64>,
}

impl FitResult {
    /// Residual variance estimate `RSS / (m - n)`.
    pub fn residual_variance(&self) -> f64 {
        let dof = self.n_residuals.saturating_sub(self.params.len()).max(1);
        self.rss / dof as f64
    }
}

/// Why a fit could not run.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LeastSquaresError {
    /// Inconsistent sizes or non-finite start/bounds.
    #[error("invalid least-squares problem: {0}")]
    Invalid(String),
    /// The model could not be evaluated at the starting point.
    #[error("model cannot be evaluated at the starting point: {0}")]
    StartFailed(String),
}

fn project(p: &mut [f64], lo: &[f64], hi: &[f64]) {
    for i in 0..p.len() {
        p[i] = p[i].clamp(lo[i], hi[i]);
    }
}

fn rss_of(r: &[f64]) -> f64 {
    r.iter().map(|v| v * v).sum()
}

/// Minimise `sum r_i(p)^2` from `p0` within the bounds of `opts`.
pub fn fit<P: Problem + ?Sized>(
    problem: &P,
    p0: &[f64],
    opts: &FitOptions,
) -> Result<FitResult, LeastSquaresError> {
    let n = problem.n_params();
    let m = problem.n_residuals();
    let (lo, hi, typical) = checked_inputs(n, m, p0, opts)?;
    // Column scales of the Jacobian: work in q_j = p_j / scale_j.
    let scale: Vec<f64> = typical.iter().map(|t| t.abs()).collect();
    let mut p = p0.to_vec();
    project(&mut p, &lo, &hi);
    let mut r = vec![0.0; m];
    let mut evaluations = 1;
    problem
        .residuals(&p, &mut r)
        .map_err(LeastSquaresError::StartFailed)?;
    if r.iter().any(|v| !v.is_finite()) {
        return Err(LeastSquaresError::StartFailed(
            "residuals are not finite at the start".into(),
        ));
    }
    let mut rss = rss_of(&r);
    let mut jac = DMatrix::<f64>::zeros(m, n);
    let mut r_try = vec![0.0; m];
    let mut p_try = vec![0.0; n];
    let mut lambda = 1e-3;
    let mut converged = false;
    let mut iterations = 0;

    let jacobian = |p: &[f64], r: &[f64], jac: &mut DMatrix<f64>, evals: &mut usize| {
        let mut pp = p.to_vec();
        let mut rr = vec![0.0; m];
        for j in 0..n {
            let mut h = opts.diff_step * p[j].abs().max(typical[j].abs()).max(1e-12);
            // Step inward when the upper bound is in the way.
            if p[j] + h > hi[j] {
                h = -h;
            }
            pp[j] = p[j] + h;
            *evals += 1;
            let ok = problem.residuals(&pp, &mut rr).is_ok() && rr.iter().all(|v| v.is_finite());
            for i in 0..m {
                jac[(i, j)] = if ok {
                    (rr[i] - r[i]) / h * scale[j]
                } else {
                    0.0
                };
            }
            pp[j] = p[j];
        }
    };

    jacobian(&p, &r, &mut jac, &mut evaluations);
    while iterations < opts.max_iter {
        iterations += 1;
        let jtj = jac.transpose() * &jac;
        let jtr = jac.transpose() * DVector::from_column_slice(&r);
        let mut improved = false;
        let mut small_step = false;
        // A parameter the residuals do not depend on gets a small damping floor, so that
        // the damped matrix stays positive definite.
        let floor = 1e-12
            * (0..n)
                .map(|d| jtj[(d, d)])
                .fold(f64::MIN_POSITIVE, f64::max);
        for _ in 0..30 {
            let mut a = jtj.clone();
            for d in 0..n {
                a[(d, d)] += lambda * jtj[(d, d)].max(floor);
            }
            let Some(step) = a.clone().cholesky().map(|c| c.solve(&(-&jtr))) else {
                lambda *= 10.0;
                continue;
            };
            for j in 0..n {
                p_try[j] = p[j] + step[j] * scale[j];
            }
            project(&mut p_try, &lo, &hi);
            small_step =
                (0..n).all(|j| (p_try[j] - p[j]).abs() <= opts.xtol * (p[j].abs() + opts.xtol));
            evaluations += 1;
            let ok = problem.residuals(&p_try, &mut r_try).is_ok()
                && r_try.iter().all(|v| v.is_finite());
            let rss_try = if ok { rss_of(&r_try) } else { f64::INFINITY };
            if rss_try < rss {
                let rel = (rss - rss_try) / rss.max(f64::MIN_POSITIVE);
                p.copy_from_slice(&p_try);
                r.copy_from_slice(&r_try);
                rss = rss_try;
                lambda = (lambda / 10.0).max(1e-12);
                improved = true;
                if rel < opts.ftol {
                    converged = true;
                }
                break;
            }
            if small_step {
                break;
            }
            lambda *= 10.0;
            if lambda > 1e16 {
                break;
            }
        }
        if !improved || small_step {
            converged = true;
        }
        if rss == 0.0 {
            converged = true;
        }
        if improved {
            jacobian(&p, &r, &mut jac, &mut evaluations);
        }
        if converged {
            break;
        }
    }

    let (covariance, std_errors) = covariance(&jac, rss, m, n, &scale);
    Ok(FitResult {
        params: p,
        rss,
        n_residuals: m,
        iterations,
        evaluations,
        converged,
        std_errors,
        covariance,
    })
}

/// Lower bounds, upper bounds and typical magnitudes of a checked fit.
type CheckedInputs = (Vec<f64>, Vec<f64>, Vec<f64>);

/// The bounds and typical magnitudes of a fit of `n` parameters to `m` residuals from `p0`,
/// after checking that sizes agree, bounds are ordered and the start is finite.
fn checked_inputs(
    n: usize,
    m: usize,
    p0: &[f64],
    opts: &FitOptions,
) -> Result<CheckedInputs, LeastSquaresError> {
    if p0.len() != n {
        return Err(LeastSquaresError::Invalid(format!(
            "start has {} parameters, problem has {n}",
            p0.len()
        )));
    }
    if n == 0 || m < n {
        return Err(LeastSquaresError::Invalid(format!(
            "need at least as many residuals ({m}) as parameters ({n}), and one parameter"
        )));
    }
    let lo = opts
        .lower
        .clone()
        .unwrap_or_else(|| vec![f64::NEG_INFINITY; n]);
    let hi = opts.upper.clone().unwrap_or_else(|| vec![f64::INFINITY; n]);
    if lo.len() != n
        || hi.len() != n
        || lo
            .iter()
            .zip(&hi)
            .any(|(a, b)| a.is_nan() || b.is_nan() || a > b)
    {
        return Err(LeastSquaresError::Invalid(
            "bounds must have one entry per parameter with lower <= upper".into(),
        ));
    }
    if p0.iter().any(|v| !v.is_finite()) {
        return Err(LeastSquaresError::Invalid(format!(
            "start {p0:?} is not finite"
        )));
    }
    let typical = opts.typical.clone().unwrap_or_else(|| {
        p0.iter()
            .map(|v| if *v != 0.0 { v.abs() } else { 1.0 })
            .collect()
    });
    if typical.len() != n || typical.iter().any(|t| !t.is_finite() || *t == 0.0) {
        return Err(LeastSquaresError::Invalid(
            "typical magnitudes must have one finite, non-zero entry per parameter".into(),
        ));
    }
    Ok((lo, hi, typical))
}

/// Parameter covariance (row-major, `n * n`) and standard errors from the final scaled
/// Jacobian `jac` (`m` residuals, column scales `scale`) and residual sum of squares `rss`:
/// `cov = scale_i scale_j (J_s^T J_s)^-1_ij rss / (m - n)`. NaN where `J^T J` is singular.
fn covariance(
    jac: &DMatrix<f64>,
    rss: f64,
    m: usize,
    n: usize,
    scale: &[f64],
) -> (Vec<f64>, Vec<f64>) {
    let jtj = jac.transpose() * jac;
    let dof = m.saturating_sub(n).max(1) as f64;
    let s2 = rss / dof;
    match jtj.clone().try_inverse() {
        Some(inv) if inv.iter().all(|v| v.is_finite()) => {
            // Back from scaled parameters: cov_ij = scale_i scale_j (J_s^T J_s)^-1_ij s^2.
            let cov = DMatrix::from_fn(n, n, |i, j| inv[(i, j)] * scale[i] * scale[j] * s2);
            let se = (0..n)
                .map(|i| {
                    let v = cov[(i, i)];
                    if v >= 0.0 {
                        v.sqrt()
                    } else {
                        f64::NAN
                    }
                })
                .collect();
            let mut flat = Vec::with_capacity(n * n);
            for i in 0..n {
                for j in 0..n {
                    flat.push(cov[(i, j)]);
                }
            }
            (flat, se)
        }
        _ => (vec![f64::NAN; n * n], vec![f64::NAN; n]),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// y = a exp(-b x) + c sampled with deterministic pseudo-noise.
    struct ExpDecay {
        x: Vec<f64>,
        y: Vec<f64>,
    }
    impl Problem for ExpDecay {
        fn n_params(&self) -> usize {
            3
        }
        fn n_residuals(&self) -> usize {
            self.x.len()
        }
        fn residuals(&self, p: &[f64], r: &mut [f64]) -> Result<(), String> {
            for ((ri, x), y) in r.iter_mut().zip(&self.x).zip(&self.y) {
                *ri = p[0] * (-p[1] * x).exp() + p[2] - y;
            }
            Ok(())
        }
    }

    fn data(noise: f64) -> ExpDecay {
        let x: Vec<f64> = (0..200).map(|i| i as f64 * 0.05).collect();
        // Deterministic zero-mean uniform noise from a 64-bit LCG.
        let mut state: u64 = 0x2545_F491_4F6C_DD1D;
        let y = x
            .iter()
            .map(|&x| {
                state = state
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                let e = (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
                2.5 * (-1.3 * x).exp() + 0.7 + noise * e
            })
            .collect();
        ExpDecay { x, y }
    }

    #[test]
    fn recovers_exact_parameters() {
        let prob = data(0.0);
        let res = fit(&prob, &[1.0, 0.5, 0.0], &FitOptions::default()).unwrap();
        assert!(res.converged);
        for (got, want) in res.params.iter().zip([2.5, 1.3, 0.7]) {
            assert!((got - want).abs() < 1e-6, "{:?}", res.params);
        }
    }

    #[test]
    fn noisy_fit_within_standard_errors() {
        let prob = data(0.05);
        let res = fit(&prob, &[1.0, 0.5, 0.0], &FitOptions::default()).unwrap();
        for ((got, want), se) in res.params.iter().zip([2.5, 1.3, 0.7]).zip(&res.std_errors) {
            assert!(se.is_finite() && *se > 0.0);
            assert!((got - want).abs() < 4.0 * se, "{got} vs {want} (se {se})");
        }
    }

    #[test]
    fn bounds_are_respected() {
        let prob = data(0.0);
        let opts = FitOptions {
            upper: Some(vec![2.0, 10.0, 10.0]),
            lower: Some(vec![0.0, 0.0, -10.0]),
            ..FitOptions::default()
        };
        let res = fit(&prob, &[1.0, 0.5, 0.0], &opts).unwrap();
        assert!(res.params[0] <= 2.0);
    }

    #[test]
    fn failing_model_is_an_error_at_start() {
        struct Fails;
        impl Problem for Fails {
            fn n_params(&self) -> usize {
                1
            }
            fn n_residuals(&self) -> usize {
                2
            }
            fn residuals(&self, _: &[f64], _: &mut [f64]) -> Result<(), String> {
                Err("diverged".into())
            }
        }
        assert!(matches!(
            fit(&Fails, &[1.0], &FitOptions::default()),
            Err(LeastSquaresError::StartFailed(_))
        ));
    }
}
