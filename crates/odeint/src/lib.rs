//! Allocation-free ODE integrators for the toolkit's models.
//!
//! A model implements [`OdeSystem`] (a tight right-hand side writing into a caller's buffer);
//! an integrator ([`Dopri5`], [`Rk4`], [`Rosenbrock23`]) advances it and reports the state at
//! requested output times through a callback. Work buffers are allocated once per
//! [`Integrator::integrate`] call, never per step.
//!
//! A run that produces a non-finite state, or whose step size collapses, returns
//! [`OdeError`] carrying the time and the last finite state: never NaN results.

mod dopri5;
mod linalg;
mod rk4;
mod rosenbrock;

pub use dopri5::Dopri5;
pub use rk4::Rk4;
pub use rosenbrock::Rosenbrock23;

/// A first-order system `dy/dt = f(t, y)`.
pub trait OdeSystem {
    /// Number of states.
    fn dim(&self) -> usize;
    /// Evaluate `dydt = f(t, y)`. Must not allocate; `y.len() == dydt.len() == dim()`.
    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]);
}

impl<S: OdeSystem + ?Sized> OdeSystem for &S {
    fn dim(&self) -> usize {
        (**self).dim()
    }
    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        (**self).rhs(t, y, dydt)
    }
}

/// Why an integration stopped early.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum OdeError {
    /// The state became NaN/infinite, or the error estimate could not be met even at the
    /// smallest step: the model diverged at `t`.
    #[error("solver diverged at t = {t:.6} s (step size {h:.3e} s); last finite state: {state:?}")]
    Diverged {
        /// Time of the last accepted step.
        t: f64,
        /// Step size when the run gave up.
        h: f64,
        /// Last finite state.
        state: Vec<f64>,
    },
    /// More steps were needed than `max_steps` allows.
    #[error("step limit of {max_steps} reached at t = {t:.6} s; last state: {state:?}")]
    TooManySteps {
        /// The configured limit.
        max_steps: usize,
        /// Time reached.
        t: f64,
        /// State at that time.
        state: Vec<f64>,
    },
    /// Bad call: wrong state length, non-finite initial state, unordered output times, bad settings.
    #[error("invalid integration request: {0}")]
    InvalidInput(String),
}

/// Counters of one integration run.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Stats {
    /// Right-hand-side evaluations (including those for Jacobians).
    pub rhs_evals: usize,
    /// Accepted steps.
    pub accepted: usize,
    /// Rejected steps.
    pub rejected: usize,
}

/// Common interface of the integrators.
pub trait Integrator {
    /// Integrate from `(t0, y0)` and call `observe(t, y)` at every time of `t_out`
    /// (non-decreasing, all `>= t0`; the run ends at the last one).
    ///
    /// `observe` returns [`Control::Continue`] or [`Control::Stop`] to end the run early
    /// (e.g. a rollover event). Outputs are interpolated with the method's dense output.
    fn integrate<S, F>(
        &self,
        sys: &S,
        t0: f64,
        y0: &[f64],
        t_out: &[f64],
        observe: F,
    ) -> Result<Stats, OdeError>
    where
        S: OdeSystem + ?Sized,
        F: FnMut(f64, &[f64]) -> Control;
}

/// What the observer wants after seeing an output.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Control {
    /// Keep integrating.
    Continue,
    /// End the run now (returns `Ok`).
    Stop,
}

/// Check the common preconditions of an integration request.
pub(crate) fn check_request<S: OdeSystem + ?Sized>(
    sys: &S,
    t0: f64,
    y0: &[f64],
    t_out: &[f64],
) -> Result<(), OdeError> {
    if y0.len() != sys.dim() {
        return Err(OdeError::InvalidInput(format!(
            "initial state has {} entries, system has {} states",
            y0.len(),
            sys.dim()
        )));
    }
    if !t0.is_finite() {
        return Err(OdeError::InvalidInput(format!("t0 = {t0} is not finite")));
    }
    if let Some(i) = y0.iter().position(|v| !v.is_finite()) {
        return Err(OdeError::InvalidInput(format!(
            "initial state entry {i} is not finite ({})",
            y0[i]
        )));
    }
    let mut prev = t0;
    for (i, &t) in t_out.iter().enumerate() {
        if !t.is_finite() || t < prev {
            return Err(OdeError::InvalidInput(format!(
                "output time {i} ({t}) is not finite or goes backwards (previous {prev})"
            )));
        }
        prev = t;
    }
    Ok(())
}

/// Weighted RMS norm used by the adaptive methods: `sqrt(mean((e_i / (atol + rtol*max(|a_i|,|b_i|)))^2))`.
pub(crate) fn error_norm(err: &[f64], a: &[f64], b: &[f64], rtol: f64, atol: f64) -> f64 {
    let n = err.len().max(1) as f64;
    let mut s = 0.0;
    for i in 0..err.len() {
        let sk = atol + rtol * a[i].abs().max(b[i].abs());
        let q = err[i] / sk;
        s += q * q;
    }
    (s / n).sqrt()
}

/// Evenly spaced output times `t0, t0+dt, ..., t0+n*dt` that end at or just before `t_end`.
pub fn output_grid(t0: f64, t_end: f64, dt: f64) -> Vec<f64> {
    if dt.is_nan() || dt <= 0.0 || t_end.is_nan() || t_end < t0 {
        return vec![t0];
    }
    let n = ((t_end - t0) / dt + 1e-9).floor() as usize;
    (0..=n).map(|i| t0 + i as f64 * dt).collect()
}

/// Settings shared by the adaptive integrators.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerances {
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance (same units as the states; scale states to O(1) or set per model).
    pub atol: f64,
}

impl Tolerances {
    pub(crate) fn validate(&self) -> Result<(), OdeError> {
        let positive = |v: f64| v.is_finite() && v > 0.0;
        if !positive(self.rtol) || !positive(self.atol) {
            return Err(OdeError::InvalidInput(format!(
                "tolerances must be positive and finite (rtol = {}, atol = {})",
                self.rtol, self.atol
            )));
        }
        Ok(())
    }
}

#[cfg(test)]
pub(crate) mod test_systems {
    use super::OdeSystem;

    /// Harmonic oscillator x'' = -w^2 x as (x, v).
    pub struct Oscillator {
        pub w: f64,
    }
    impl OdeSystem for Oscillator {
        fn dim(&self) -> usize {
            2
        }
        fn rhs(&self, _t: f64, y: &[f64], d: &mut [f64]) {
            d[0] = y[1];
            d[1] = -self.w * self.w * y[0];
        }
    }

    /// Stiff linear test problem y' = -k (y - cos t) - sin t, exact y = cos t for y(0)=1.
    pub struct StiffCos {
        pub k: f64,
    }
    impl OdeSystem for StiffCos {
        fn dim(&self) -> usize {
            1
        }
        fn rhs(&self, t: f64, y: &[f64], d: &mut [f64]) {
            d[0] = -self.k * (y[0] - t.cos()) - t.sin();
        }
    }

    /// Blows up in finite time: y' = y^2, y(0)=1 -> y = 1/(1-t).
    pub struct BlowUp;
    impl OdeSystem for BlowUp {
        fn dim(&self) -> usize {
            1
        }
        fn rhs(&self, _t: f64, y: &[f64], d: &mut [f64]) {
            d[0] = y[0] * y[0];
        }
    }
}
