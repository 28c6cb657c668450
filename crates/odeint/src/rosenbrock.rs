//! Linearly implicit Rosenbrock-W method of order 2(3) (Shampine & Reichelt, "The MATLAB
//! ODE suite", SIAM J. Sci. Comput. 18, 1997: the `ode23s` scheme), L-stable, with a
//! finite-difference Jacobian refreshed every step. For the stiff strut models.

use crate::dopri5::initial_step;
use crate::linalg::{lu_factor, lu_solve};
use crate::{
    check_request, error_norm, Control, Integrator, OdeError, OdeSystem, Stats, Tolerances,
};

/// Rosenbrock 2(3) for stiff systems (few states: the Jacobian is formed by finite
/// differences, `dim()` extra right-hand-side calls per step).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rosenbrock23 {
    /// Relative and absolute tolerances.
    pub tol: Tolerances,
    /// Largest step allowed (s).
    pub max_step: f64,
    /// Step budget for the whole run.
    pub max_steps: usize,
}

impl Default for Rosenbrock23 {
    fn default() -> Self {
        Self {
            tol: Tolerances {
                rtol: 1e-4,
                atol: 1e-8,
            },
            max_step: f64::INFINITY,
            max_steps: 1_000_000,
        }
    }
}

impl Rosenbrock23 {
    /// Integrator with the given tolerances and other settings at their defaults.
    pub fn new(rtol: f64, atol: f64) -> Self {
        Self {
            tol: Tolerances { rtol, atol },
            ..Self::default()
        }
    }

    /// Same integrator with a step-size ceiling.
    pub fn with_max_step(mut self, max_step: f64) -> Self {
        self.max_step = max_step;
        self
    }
}

impl Integrator for Rosenbrock23 {
    fn integrate<S, F>(
        &self,
        sys: &S,
        t0: f64,
        y0: &[f64],
        t_out: &[f64],
        mut observe: F,
    ) -> Result<Stats, OdeError>
    where
        S: OdeSystem + ?Sized,
        F: FnMut(f64, &[f64]) -> Control,
    {
        check_request(sys, t0, y0, t_out)?;
        self.tol.validate()?;
        if self.max_step.is_nan() || self.max_step <= 0.0 {
            return Err(OdeError::InvalidInput(format!(
                "max_step must be positive, got {}",
                self.max_step
            )));
        }
        let n = y0.len();
        let mut stats = Stats::default();
        let Some(&t_end) = t_out.last() else {
            return Ok(stats);
        };
        let d = 1.0 / (2.0 + std::f64::consts::SQRT_2);
        let e32 = 6.0 + std::f64::consts::SQRT_2;

        let mut buf = vec![0.0; 12 * n];
        let (y, rest) = buf.split_at_mut(n);
        let (y1, rest) = rest.split_at_mut(n);
        let (ys, rest) = rest.split_at_mut(n);
        let (f0, rest) = rest.split_at_mut(n);
        let (f1, rest) = rest.split_at_mut(n);
        let (f2, rest) = rest.split_at_mut(n);
        let (k1, rest) = rest.split_at_mut(n);
        let (k2, rest) = rest.split_at_mut(n);
        let (k3, rest) = rest.split_at_mut(n);
        let (dfdt, rest) = rest.split_at_mut(n);
        let (err, tmp) = rest.split_at_mut(n);
        let mut jac = vec![0.0; n * n];
        let mut wmat = vec![0.0; n * n];
        let mut piv = vec![0usize; n];

        y.copy_from_slice(y0);
        let mut t = t0;
        let mut next_out = 0;
        while next_out < t_out.len() && t_out[next_out] <= t0 {
            if observe(t0, y) == Control::Stop {
                return Ok(stats);
            }
            next_out += 1;
        }
        if next_out == t_out.len() {
            return Ok(stats);
        }
        sys.rhs(t, y, f0);
        stats.rhs_evals += 1;
        stats.rhs_evals += 1;
        let mut h = initial_step(sys, t, y, f0, self.tol, 2, [ys, f1])
            .min(self.max_step)
            .min(t_end - t0);
        let mut need_jac = true;

        while t < t_end {
            if stats.accepted + stats.rejected >= self.max_steps {
                return Err(OdeError::TooManySteps {
                    max_steps: self.max_steps,
                    t,
                    state: y.to_vec(),
                });
            }
            if t + 1.01 * h >= t_end {
                h = t_end - t;
            }
            if h < 1e-13 * t.abs().max(1.0) {
                return Err(OdeError::Diverged {
                    t,
                    h,
                    state: y.to_vec(),
                });
            }
            if need_jac {
                // Finite-difference Jacobian (column j in jac[:, j], row-major) and df/dt.
                for j in 0..n {
                    let yj = y[j];
                    let dy = (f64::EPSILON.sqrt())
                        * yj.abs().max(self.tol.atol / self.tol.rtol).max(1e-8);
                    ys.copy_from_slice(y);
                    ys[j] = yj + dy;
                    sys.rhs(t, ys, f1);
                    for i in 0..n {
                        jac[i * n + j] = (f1[i] - f0[i]) / dy;
                    }
                }
                let dt = f64::EPSILON.sqrt() * t.abs().max(1e-3);
                sys.rhs(t + dt, y, f1);
                for i in 0..n {
                    dfdt[i] = (f1[i] - f0[i]) / dt;
                }
                stats.rhs_evals += n + 1;
                need_jac = false;
            }
            // W = I - h d J, factored in its own buffer so the Jacobian survives a rejection.
            let hd = h * d;
            for i in 0..n {
                for j in 0..n {
                    wmat[i * n + j] = -hd * jac[i * n + j] + if i == j { 1.0 } else { 0.0 };
                }
            }
            let ok = lu_factor(&mut wmat, &mut piv, n);
            if !ok {
                stats.rejected += 1;
                h *= 0.5;
                continue;
            }
            // k1 = W^-1 (F0 + h d T)
            for i in 0..n {
                k1[i] = f0[i] + hd * dfdt[i];
            }
            lu_solve(&wmat, &piv, n, k1, tmp);
            for i in 0..n {
                ys[i] = y[i] + 0.5 * h * k1[i];
            }
            sys.rhs(t + 0.5 * h, ys, f1);
            // k2 = W^-1 (F1 - k1) + k1
            for i in 0..n {
                k2[i] = f1[i] - k1[i];
            }
            lu_solve(&wmat, &piv, n, k2, tmp);
            for i in 0..n {
                k2[i] += k1[i];
                y1[i] = y[i] + h * k2[i];
            }
            sys.rhs(t + h, y1, f2);
            // k3 = W^-1 [F2 - e32 (k2 - F1) - 2 (k1 - F0) + h d T]
            for i in 0..n {
                k3[i] = f2[i] - e32 * (k2[i] - f1[i]) - 2.0 * (k1[i] - f0[i]) + hd * dfdt[i];
            }
            lu_solve(&wmat, &piv, n, k3, tmp);
            stats.rhs_evals += 2;
            for i in 0..n {
                err[i] = h / 6.0 * (k1[i] - 2.0 * k2[i] + k3[i]);
            }
            let e = error_norm(err, y, y1, self.tol.rtol, self.tol.atol);
            let finite = e.is_finite() && y1.iter().all(|v| v.is_finite());
            if !finite || e > 1.0 {
                stats.rejected += 1;
                h *= if finite {
                    (0.8 * e.powf(-1.0 / 3.0)).clamp(0.1, 0.5)
                } else {
                    0.1
                };
                continue;
            }
            let t_new = t + h;
            while next_out < t_out.len() && t_out[next_out] <= t_new {
                let s = (t_out[next_out] - t) / h;
                let c1 = s * (1.0 - s) / (1.0 - 2.0 * d);
                let c2 = s * (s - 2.0 * d) / (1.0 - 2.0 * d);
                for i in 0..n {
                    ys[i] = y[i] + h * (c1 * k1[i] + c2 * k2[i]);
                }
                if observe(t_out[next_out], ys) == Control::Stop {
                    stats.accepted += 1;
                    return Ok(stats);
                }
                next_out += 1;
            }
            stats.accepted += 1;
            t = t_new;
            y.copy_from_slice(y1);
            f0.copy_from_slice(f2);
            need_jac = true;
            h = (h * (0.8 * e.max(1e-10).powf(-1.0 / 3.0)).clamp(0.2, 5.0)).min(self.max_step);
        }
        Ok(stats)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_systems::*;
    use crate::Dopri5;

    #[test]
    fn stiff_problem_solved_in_few_steps() {
        let sys = StiffCos { k: 1e6 };
        let mut max_err: f64 = 0.0;
        let ts = crate::output_grid(0.0, 2.0, 0.1);
        let st = Rosenbrock23::new(1e-5, 1e-8)
            .integrate(&sys, 0.0, &[1.0], &ts, |t, y| {
                max_err = max_err.max((y[0] - t.cos()).abs());
                Control::Continue
            })
            .unwrap();
        assert!(max_err < 1e-4, "max err {max_err}");
        // The explicit method needs ~k*T/3 steps here; the implicit one a few hundred at most.
        assert!(st.accepted < 500, "{st:?}");
        let ex = Dopri5::new(1e-5, 1e-8)
            .integrate(&sys, 0.0, &[1.0], &ts, |_, _| Control::Continue)
            .unwrap();
        assert!(
            ex.accepted > 10 * st.accepted,
            "explicit {ex:?} vs implicit {st:?}"
        );
    }

    #[test]
    fn oscillator_second_order_accuracy() {
        let sys = Oscillator { w: 1.0 };
        let mut e = 0.0;
        Rosenbrock23::new(1e-7, 1e-10)
            .integrate(&sys, 0.0, &[1.0, 0.0], &[3.0], |t, y| {
                e = (y[0] - t.cos()).abs();
                Control::Continue
            })
            .unwrap();
        assert!(e < 1e-5, "err {e}");
    }

    #[test]
    fn blow_up_is_an_error() {
        let r = Rosenbrock23::default()
            .integrate(&BlowUp, 0.0, &[1.0], &[2.0], |_, _| Control::Continue);
        assert!(r.is_err());
    }
}
