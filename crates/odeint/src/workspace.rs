//! Caller-owned work buffers (the faer `MemStack` habit): create one per thread, pass it
//! to every run, and the runs allocate nothing.

/// Work buffers for systems of `dim` states and up to `n_events` event functions.
///
/// [`crate::Integrator::run`] grows a workspace that is too small (one allocation) and
/// reuses it as it is otherwise; a run's results do not depend on what an earlier run left
/// in it.
#[derive(Debug, Clone, Default)]
pub struct Workspace {
    pub(crate) dim: usize,
    /// Current state y_n.
    pub(crate) y: Vec<f64>,
    /// Candidate state y_{n+1}.
    pub(crate) y_new: Vec<f64>,
    /// Stage argument.
    pub(crate) y_stage: Vec<f64>,
    /// Interpolated state handed to the observer.
    pub(crate) y_out: Vec<f64>,
    /// Stage derivatives / increments (method-specific use).
    pub(crate) k: [Vec<f64>; 7],
    /// Error estimate, dense-output coefficients and solve scratch (method-specific use).
    pub(crate) aux: [Vec<f64>; 4],
    /// Per-state absolute tolerance of the run.
    pub(crate) atol: Vec<f64>,
    /// Jacobian (row-major dim x dim).
    pub(crate) jac: Vec<f64>,
    /// Iteration matrix W = I - h d J and its LU factors.
    pub(crate) w: Vec<f64>,
    /// LU pivots.
    pub(crate) piv: Vec<usize>,
    /// Event values at the start of the step.
    pub(crate) g_old: Vec<f64>,
    /// Event values at the end of the step.
    pub(crate) g_new: Vec<f64>,
    /// Located crossing time of each event in the current step (NaN: none).
    pub(crate) t_cross: Vec<f64>,
}

impl Workspace {
    /// Buffers for systems of `dim` states without events.
    pub fn new(dim: usize) -> Self {
        let mut ws = Self::default();
        ws.fit(dim, 0);
        ws
    }

    /// Buffers for systems of `dim` states and `n_events` event functions.
    pub fn with_events(dim: usize, n_events: usize) -> Self {
        let mut ws = Self::default();
        ws.fit(dim, n_events);
        ws
    }

    /// Number of states the buffers are sized for.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// Size the buffers for `dim` states and `n_events` events; allocates only when the
    /// current buffers differ in size.
    pub(crate) fn fit(&mut self, dim: usize, n_events: usize) {
        if self.dim != dim || self.y.len() != dim {
            self.dim = dim;
            for v in [
                &mut self.y,
                &mut self.y_new,
                &mut self.y_stage,
                &mut self.y_out,
                &mut self.atol,
            ] {
                *v = vec![0.0; dim];
            }
            for v in self.k.iter_mut().chain(self.aux.iter_mut()) {
                *v = vec![0.0; dim];
            }
            self.jac = vec![0.0; dim * dim];
            self.w = vec![0.0; dim * dim];
            self.piv = vec![0; dim];
        }
        if self.g_old.len() != n_events {
            self.g_old = vec![0.0; n_events];
            self.g_new = vec![0.0; n_events];
            self.t_cross = vec![f64::NAN; n_events];
        }
    }
}
