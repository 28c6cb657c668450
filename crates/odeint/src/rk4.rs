//! Classical fixed-step Runge-Kutta 4 (reference integrator for convergence checks).

use crate::{check_request, Control, Integrator, OdeError, OdeSystem, Stats};

/// Fixed-step RK4. Output times are hit exactly: each interval between outputs is split
/// into `ceil(dt / step)` equal steps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rk4 {
    /// Largest step (s).
    pub step: f64,
}

impl Integrator for Rk4 {
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
        if !self.step.is_finite() || self.step <= 0.0 {
            return Err(OdeError::InvalidInput(format!(
                "RK4 step must be positive, got {}",
                self.step
            )));
        }
        let n = y0.len();
        let mut buf = vec![0.0; 6 * n];
        let (y, rest) = buf.split_at_mut(n);
        let (ys, rest) = rest.split_at_mut(n);
        let (k1, rest) = rest.split_at_mut(n);
        let (k2, rest) = rest.split_at_mut(n);
        let (k3, k4) = rest.split_at_mut(n);
        y.copy_from_slice(y0);
        let mut stats = Stats::default();
        let mut t = t0;
        for &to in t_out {
            let span = to - t;
            let m = (span / self.step).ceil().max(0.0) as usize;
            let h = if m > 0 { span / m as f64 } else { 0.0 };
            for _ in 0..m {
                sys.rhs(t, y, k1);
                for i in 0..n {
                    ys[i] = y[i] + 0.5 * h * k1[i];
                }
                sys.rhs(t + 0.5 * h, ys, k2);
                for i in 0..n {
                    ys[i] = y[i] + 0.5 * h * k2[i];
                }
                sys.rhs(t + 0.5 * h, ys, k3);
                for i in 0..n {
                    ys[i] = y[i] + h * k3[i];
                }
                sys.rhs(t + h, ys, k4);
                stats.rhs_evals += 4;
                let mut finite = true;
                for i in 0..n {
                    let v = y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
                    finite &= v.is_finite();
                    ys[i] = v;
                }
                if !finite {
                    return Err(OdeError::Diverged {
                        t,
                        h,
                        state: y.to_vec(),
                    });
                }
                y.copy_from_slice(ys);
                t += h;
                stats.accepted += 1;
            }
            t = to;
            if observe(t, y) == Control::Stop {
                break;
            }
        }
        Ok(stats)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_systems::Oscillator;

    #[test]
    fn fourth_order_convergence() {
        let sys = Oscillator { w: 1.0 };
        let err = |h: f64| {
            let mut e = 0.0;
            Rk4 { step: h }
                .integrate(&sys, 0.0, &[1.0, 0.0], &[2.0], |t, y| {
                    e = (y[0] - t.cos()).abs();
                    Control::Continue
                })
                .unwrap();
            e
        };
        let ratio = err(0.1) / err(0.05);
        assert!((ratio - 16.0).abs() < 2.0, "ratio {ratio}");
    }
}
