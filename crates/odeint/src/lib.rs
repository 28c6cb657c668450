//! Allocation-free ODE integrators for the toolkit's models.
//!
//! A model implements [`OdeSystem`] (a tight right-hand side writing into a caller's buffer).
//! One [`Integrator`] value (a [`Solver`] plus tolerances and step limits) advances it: a
//! single driver loop ([`Integrator::run`]) owns the output grid, the observer, breakpoints,
//! event location, the step limit and the divergence error, and calls one of three
//! single-step kernels (Dormand-Prince 5(4), Tsitouras 5(4), Rosenbrock 2(3), the
//! Rosenbrock-W 3(2) ROS34PW2 and the additive Runge-Kutta ARK4(3)6L\[2\]SA on a model's
//! stiff blocks, fixed-step RK4).
//!
//! Work buffers live in a caller-supplied [`Workspace`]: a caller that runs thousands of
//! short simulations creates one and passes it to every run, and the runs allocate nothing.
//!
//! A run that produces a non-finite state, or whose step size collapses, returns
//! [`OdeError`] carrying the time and the last finite state: never NaN results.

mod ark;
mod blocks;
mod dopri5;
mod driver;
mod event;
mod explicit_rk;
mod kernel;
mod linalg;
mod rk4;
mod rosenbrock;
mod rosenbrock_w;
mod solver;
mod tolerance;
mod tsit5;
mod workspace;

pub use driver::{Integrator, Problem, Sample, SampleKind};
pub use event::{Direction, Event};
pub use solver::Solver;
pub use tolerance::Atol;
pub use workspace::Workspace;

/// A first-order system `dy/dt = f(t, y)`.
pub trait OdeSystem {
    /// Number of states.
    fn dim(&self) -> usize;
    /// Evaluate `dydt = f(t, y)`. Must not allocate; `y.len() == dydt.len() == dim()`.
    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]);
    /// Hint for [`Solver::Auto`]: `true` makes it pick the implicit [`Solver::Rosenbrock23`],
    /// `false` (the default) the explicit [`Solver::Dopri5`]. A model that knows when it is
    /// stiff (e.g. the strut under slow motion) overrides it.
    fn is_stiff(&self) -> bool {
        false
    }
    /// The stiff diagonal blocks that [`Solver::Ros34pw2`] and [`Solver::Ark436`] treat
    /// implicitly: disjoint sets
    /// of state indices whose rows, differentiated with respect to the block's own states,
    /// hold the fast eigenvalues (e.g. each HPS strut's states with the velocity of the
    /// carrier it acts on). Every other state is advanced explicitly by those methods. Empty
    /// (the default): they are then explicit in every state.
    fn stiff_blocks(&self) -> &[Vec<usize>] {
        &[]
    }
    /// Jacobian of stiff block `block`'s rows with respect to its own states at `(t, y)`,
    /// row-major in the block's index order into `jac` (`len²` entries). Return `true` when filled; the default returns
    /// `false`, and the integrator then differences the whole right-hand side over the
    /// block's states (one call per state). A model whose block is cheap to evaluate on its
    /// own (a strut beside a multibody vehicle) fills it far more cheaply. Must not allocate.
    fn block_jacobian(&self, _t: f64, _y: &[f64], _block: usize, _jac: &mut [f64]) -> bool {
        false
    }
    /// The rows of stiff block `block` of `f(t, y)`, in the block's index order, into `out`
    /// (the block's length). Return `true` when filled; the default returns `false`, and
    /// [`Solver::Ark436`] then evaluates the whole right-hand side in each Newton iteration
    /// of its implicit stages. A model whose block is cheap on its own (a strut's rates at its
    /// carrier's travel and rate) fills it with exactly the values `rhs` writes in those rows.
    /// Must not allocate.
    fn block_rhs(&self, _t: f64, _y: &[f64], _block: usize, _out: &mut [f64]) -> bool {
        false
    }
}

impl<S: OdeSystem + ?Sized> OdeSystem for &S {
    fn dim(&self) -> usize {
        (**self).dim()
    }
    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        (**self).rhs(t, y, dydt)
    }
    fn is_stiff(&self) -> bool {
        (**self).is_stiff()
    }
    fn stiff_blocks(&self) -> &[Vec<usize>] {
        (**self).stiff_blocks()
    }
    fn block_jacobian(&self, t: f64, y: &[f64], block: usize, jac: &mut [f64]) -> bool {
        (**self).block_jacobian(t, y, block, jac)
    }
    fn block_rhs(&self, t: f64, y: &[f64], block: usize, out: &mut [f64]) -> bool {
        (**self).block_rhs(t, y, block, out)
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
    /// The step size collapsed early: at the run's mean pace so far the step budget would
    /// be exceeded [`COLLAPSE_FACTOR`] times over, so the run ends now instead of at the
    /// budget. Typical of a stiff state (a near-rigid hydraulic chamber, an absurd
    /// stiffness) under an explicit method; `dominant_state` is the state with the largest
    /// scaled error in the last step attempt, the one to look at.
    #[error("step size collapsed to {h:.3e} s at t = {t:.6} s: finishing at this pace would take about {projected_steps:.1e} steps (limit {max_steps}); state {dominant_state} dominates the error (stiff?); last state: {state:?}")]
    StepSizeCollapsed {
        /// Time reached.
        t: f64,
        /// Step size of the last attempt (s).
        h: f64,
        /// Steps the whole run would take at its mean pace so far.
        projected_steps: f64,
        /// The configured step budget.
        max_steps: usize,
        /// Index of the state with the largest scaled error estimate.
        dominant_state: usize,
        /// State at `t`.
        state: Vec<f64>,
    },
    /// Bad call: wrong state length, non-finite initial state, unordered output times, bad settings.
    #[error("invalid integration request: {0}")]
    InvalidInput(String),
}

/// An adaptive run whose projected step count exceeds this multiple of its budget, after
/// [`COLLAPSE_MIN_STEPS`] steps, ends with [`OdeError::StepSizeCollapsed`].
pub const COLLAPSE_FACTOR: f64 = 10.0;

/// Steps an adaptive run takes before its pace is judged ([`COLLAPSE_FACTOR`]): start-up
/// transients and kinks may take many small steps without the run being stiff.
pub const COLLAPSE_MIN_STEPS: usize = 4096;

/// Counters of one integration run.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Stats {
    /// Right-hand-side evaluations (including those for Jacobians).
    pub rhs_evals: usize,
    /// Accepted steps.
    pub accepted: usize,
    /// Rejected steps.
    pub rejected: usize,
    /// Event crossings located and reported.
    pub events: usize,
}

/// What the observer wants after seeing an output.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Control {
    /// Keep integrating.
    Continue,
    /// End the run now (returns `Ok`).
    Stop,
}

/// Evenly spaced output times `t0, t0+dt, ..., t0+n*dt` that end at or just before `t_end`.
pub fn output_grid(t0: f64, t_end: f64, dt: f64) -> Vec<f64> {
    if dt.is_nan() || dt <= 0.0 || t_end.is_nan() || t_end < t0 {
        return vec![t0];
    }
    let n = ((t_end - t0) / dt + 1e-9).floor() as usize;
    (0..=n).map(|i| t0 + i as f64 * dt).collect()
}
