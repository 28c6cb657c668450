//! Dormand-Prince 5(4) with step-size control and 4th-order dense output
//! (Hairer, Nørsett & Wanner, *Solving ODEs I*, section II.5/II.6, code DOPRI5).

use crate::{
    check_request, error_norm, Control, Integrator, OdeError, OdeSystem, Stats, Tolerances,
};

const C2: f64 = 1.0 / 5.0;
const C3: f64 = 3.0 / 10.0;
const C4: f64 = 4.0 / 5.0;
const C5: f64 = 8.0 / 9.0;
const A21: f64 = 1.0 / 5.0;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
const A71: f64 = 35.0 / 384.0;
const A73: f64 = 500.0 / 1113.0;
const A74: f64 = 125.0 / 192.0;
const A75: f64 = -2187.0 / 6784.0;
const A76: f64 = 11.0 / 84.0;
const E1: f64 = 71.0 / 57600.0;
const E3: f64 = -71.0 / 16695.0;
const E4: f64 = 71.0 / 1920.0;
const E5: f64 = -17253.0 / 339200.0;
const E6: f64 = 22.0 / 525.0;
const E7: f64 = -1.0 / 40.0;
const D1: f64 = -12715105075.0 / 11282082432.0;
const D3: f64 = 87487479700.0 / 32700410799.0;
const D4: f64 = -10690763975.0 / 1880347072.0;
const D5: f64 = 701980252875.0 / 199316789632.0;
const D6: f64 = -1453857185.0 / 822651844.0;
const D7: f64 = 69997945.0 / 29380423.0;

/// Adaptive explicit Runge-Kutta 5(4) of Dormand and Prince.
///
/// The default for non-stiff models (yaw-plane vehicle, tire lag). `max_step` keeps the
/// method from stepping over short inputs such as a 0.2 s steering pulse.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dopri5 {
    /// Relative and absolute tolerances.
    pub tol: Tolerances,
    /// Largest step allowed (s).
    pub max_step: f64,
    /// First step; `None` picks one from the initial derivatives.
    pub first_step: Option<f64>,
    /// Step budget for the whole run.
    pub max_steps: usize,
}

impl Default for Dopri5 {
    fn default() -> Self {
        Self {
            tol: Tolerances {
                rtol: 1e-6,
                atol: 1e-9,
            },
            max_step: f64::INFINITY,
            first_step: None,
            max_steps: 1_000_000,
        }
    }
}

impl Dopri5 {
    /// Integrator with the given tolerances and the other settings at their defaults.
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

/// Hairer's starting-step heuristic (HNW I, II.4); costs one right-hand-side evaluation.
pub(crate) fn initial_step<S: OdeSystem + ?Sized>(
    sys: &S,
    t0: f64,
    y0: &[f64],
    f0: &[f64],
    tol: Tolerances,
    order: i32,
    scratch: [&mut [f64]; 2],
) -> f64 {
    let [scratch_y, scratch_f] = scratch;
    let n = y0.len().max(1) as f64;
    let (mut d0, mut d1) = (0.0, 0.0);
    for i in 0..y0.len() {
        let sk = tol.atol + tol.rtol * y0[i].abs();
        d0 += (y0[i] / sk).powi(2);
        d1 += (f0[i] / sk).powi(2);
    }
    d0 = (d0 / n).sqrt();
    d1 = (d1 / n).sqrt();
    let h0 = if d0 < 1e-5 || d1 < 1e-5 {
        1e-6
    } else {
        0.01 * d0 / d1
    };
    for i in 0..y0.len() {
        scratch_y[i] = y0[i] + h0 * f0[i];
    }
    sys.rhs(t0 + h0, scratch_y, scratch_f);
    let mut d2 = 0.0;
    for i in 0..y0.len() {
        let sk = tol.atol + tol.rtol * y0[i].abs();
        d2 += ((scratch_f[i] - f0[i]) / sk).powi(2);
    }
    d2 = (d2 / n).sqrt() / h0;
    let h1 = if d1.max(d2) <= 1e-15 {
        (h0 * 1e-3).max(1e-6)
    } else {
        (0.01 / d1.max(d2)).powf(1.0 / (order as f64 + 1.0))
    };
    let h = (100.0 * h0).min(h1);
    if h.is_finite() && h > 0.0 {
        h
    } else {
        1e-6
    }
}

impl Integrator for Dopri5 {
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
        // One allocation for all work vectors.
        let mut buf = vec![0.0; n * 15];
        let (y, rest) = buf.split_at_mut(n);
        let (y1, rest) = rest.split_at_mut(n);
        let (ys, rest) = rest.split_at_mut(n);
        let (k1, rest) = rest.split_at_mut(n);
        let (k2, rest) = rest.split_at_mut(n);
        let (k3, rest) = rest.split_at_mut(n);
        let (k4, rest) = rest.split_at_mut(n);
        let (k5, rest) = rest.split_at_mut(n);
        let (k6, rest) = rest.split_at_mut(n);
        let (k7, rest) = rest.split_at_mut(n);
        let (err, rest) = rest.split_at_mut(n);
        let (r3, rest) = rest.split_at_mut(n);
        let (r4, rest) = rest.split_at_mut(n);
        let (r5, yo) = rest.split_at_mut(n);

        y.copy_from_slice(y0);
        let mut t = t0;
        let mut next_out = 0;
        // Outputs at t0.
        while next_out < t_out.len() && t_out[next_out] <= t0 {
            if observe(t0, y) == Control::Stop {
                return Ok(stats);
            }
            next_out += 1;
        }
        if next_out == t_out.len() {
            return Ok(stats);
        }
        sys.rhs(t, y, k1);
        stats.rhs_evals += 1;
        let mut h = match self.first_step {
            Some(h) => h,
            None => {
                stats.rhs_evals += 1;
                initial_step(sys, t, y, k1, self.tol, 5, [ys, k2])
            }
        }
        .min(self.max_step)
        .min(t_end - t0);
        let h_min_rel = 1e-13;
        let mut last_rejected = false;

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
            let hmin = h_min_rel * t.abs().max(1.0);
            if h < hmin {
                return Err(OdeError::Diverged {
                    t,
                    h,
                    state: y.to_vec(),
                });
            }
            // Stages.
            for i in 0..n {
                ys[i] = y[i] + h * A21 * k1[i];
            }
            sys.rhs(t + C2 * h, ys, k2);
            for i in 0..n {
                ys[i] = y[i] + h * (A31 * k1[i] + A32 * k2[i]);
            }
            sys.rhs(t + C3 * h, ys, k3);
            for i in 0..n {
                ys[i] = y[i] + h * (A41 * k1[i] + A42 * k2[i] + A43 * k3[i]);
            }
            sys.rhs(t + C4 * h, ys, k4);
            for i in 0..n {
                ys[i] = y[i] + h * (A51 * k1[i] + A52 * k2[i] + A53 * k3[i] + A54 * k4[i]);
            }
            sys.rhs(t + C5 * h, ys, k5);
            for i in 0..n {
                ys[i] = y[i]
                    + h * (A61 * k1[i] + A62 * k2[i] + A63 * k3[i] + A64 * k4[i] + A65 * k5[i]);
            }
            sys.rhs(t + h, ys, k6);
            for i in 0..n {
                y1[i] = y[i]
                    + h * (A71 * k1[i] + A73 * k3[i] + A74 * k4[i] + A75 * k5[i] + A76 * k6[i]);
            }
            sys.rhs(t + h, y1, k7);
            stats.rhs_evals += 6;
            for i in 0..n {
                err[i] = h
                    * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i]);
            }
            let e = error_norm(err, y, y1, self.tol.rtol, self.tol.atol);
            let finite = e.is_finite() && y1.iter().all(|v| v.is_finite());
            if !finite || e > 1.0 {
                stats.rejected += 1;
                let fac = if finite {
                    (0.9 * e.powf(-0.2)).clamp(0.2, 1.0)
                } else {
                    0.1
                };
                h *= fac;
                last_rejected = true;
                continue;
            }
            // Accepted: dense output coefficients, then emit outputs in (t, t+h].
            let t_new = t + h;
            while next_out < t_out.len() && t_out[next_out] <= t_new {
                let theta = (t_out[next_out] - t) / h;
                let theta1 = 1.0 - theta;
                for i in 0..n {
                    let ydiff = y1[i] - y[i];
                    let bspl = h * k1[i] - ydiff;
                    r3[i] = bspl;
                    r4[i] = ydiff - h * k7[i] - bspl;
                    r5[i] = h
                        * (D1 * k1[i]
                            + D3 * k3[i]
                            + D4 * k4[i]
                            + D5 * k5[i]
                            + D6 * k6[i]
                            + D7 * k7[i]);
                    yo[i] = y[i]
                        + theta * (ydiff + theta1 * (r3[i] + theta * (r4[i] + theta1 * r5[i])));
                }
                if observe(t_out[next_out], yo) == Control::Stop {
                    stats.accepted += 1;
                    return Ok(stats);
                }
                next_out += 1;
            }
            stats.accepted += 1;
            t = t_new;
            y.copy_from_slice(y1);
            k1.copy_from_slice(k7); // FSAL
            let mut fac = (0.9 * e.max(1e-10).powf(-0.2)).clamp(0.2, 5.0);
            if last_rejected {
                fac = fac.min(1.0);
            }
            last_rejected = false;
            h = (h * fac).min(self.max_step);
        }
        Ok(stats)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output_grid;
    use crate::test_systems::*;

    #[test]
    fn oscillator_matches_closed_form() {
        let sys = Oscillator {
            w: 2.0 * std::f64::consts::PI,
        };
        let ts = output_grid(0.0, 3.0, 0.01);
        let mut max_err: f64 = 0.0;
        let stats = Dopri5::new(1e-9, 1e-12)
            .integrate(&sys, 0.0, &[1.0, 0.0], &ts, |t, y| {
                max_err = max_err.max((y[0] - (sys.w * t).cos()).abs());
                Control::Continue
            })
            .unwrap();
        assert!(max_err < 1e-7, "max error {max_err}");
        assert!(stats.accepted > 10);
    }

    #[test]
    fn error_shrinks_with_tolerance() {
        let sys = Oscillator { w: 3.0 };
        let run = |rtol: f64| {
            let mut e: f64 = 0.0;
            Dopri5::new(rtol, rtol * 1e-3)
                .integrate(&sys, 0.0, &[1.0, 0.0], &[5.0], |t, y| {
                    e = (y[0] - (3.0 * t).cos()).abs();
                    Control::Continue
                })
                .unwrap();
            e
        };
        assert!(run(1e-8) < run(1e-4) / 100.0);
    }

    #[test]
    fn blow_up_is_an_error_with_time_and_state() {
        let r = Dopri5::default().integrate(&BlowUp, 0.0, &[1.0], &[2.0], |_, _| Control::Continue);
        match r {
            Err(OdeError::Diverged { t, state, .. })
            | Err(OdeError::TooManySteps { t, state, .. }) => {
                assert!(t > 0.9 && t < 1.01, "t = {t}");
                assert!(state[0].is_finite());
            }
            other => panic!("expected an error, got {other:?}"),
        }
    }

    #[test]
    fn stop_ends_run() {
        let sys = Oscillator { w: 1.0 };
        let ts = output_grid(0.0, 10.0, 0.1);
        let mut seen = 0;
        Dopri5::default()
            .integrate(&sys, 0.0, &[1.0, 0.0], &ts, |t, _| {
                seen += 1;
                if t >= 1.0 {
                    Control::Stop
                } else {
                    Control::Continue
                }
            })
            .unwrap();
        assert_eq!(seen, 11);
    }

    #[test]
    fn rejects_bad_requests() {
        let sys = Oscillator { w: 1.0 };
        let d = Dopri5::default();
        assert!(d
            .integrate(&sys, 0.0, &[1.0], &[1.0], |_, _| Control::Continue)
            .is_err());
        assert!(d
            .integrate(&sys, 0.0, &[f64::NAN, 0.0], &[1.0], |_, _| {
                Control::Continue
            })
            .is_err());
        assert!(d
            .integrate(&sys, 0.0, &[1.0, 0.0], &[1.0, 0.5], |_, _| {
                Control::Continue
            })
            .is_err());
        assert!(Dopri5::new(-1.0, 1e-9)
            .integrate(&sys, 0.0, &[1.0, 0.0], &[1.0], |_, _| Control::Continue)
            .is_err());
    }
}
