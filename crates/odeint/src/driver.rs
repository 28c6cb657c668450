//! The one driver loop every method runs under: output grid, observer, breakpoints, event
//! location, step limit and divergence error. The methods are single-step kernels.

use crate::ark::ArkKernel;
use crate::dopri5::Dopri5Kernel;
use crate::event::{locate, Event};
use crate::kernel::{initial_step, Kernel};
use crate::rk4::Rk4Kernel;
use crate::rosenbrock::Rosenbrock23Kernel;
use crate::rosenbrock_w::RosenbrockWKernel;
use crate::tsit5::Tsit5Kernel;
use crate::{
    Atol, Control, OdeError, OdeSystem, Solver, Stats, Workspace, COLLAPSE_FACTOR,
    COLLAPSE_MIN_STEPS,
};

/// Smallest step relative to `max(|t|, 1)` before a run is declared diverged.
const H_MIN_REL: f64 = 1e-13;

/// The state with the largest scaled error `|e_i| / (atol_i + rtol max(|y_i|, |y_new_i|))`
/// in the last step attempt (the adaptive kernels keep the error estimate in `aux[0]`).
fn dominant_state(ws: &Workspace, rtol: f64) -> usize {
    let mut best = (0, f64::NEG_INFINITY);
    for i in 0..ws.dim {
        let scale = ws.atol[i] + rtol * ws.y[i].abs().max(ws.y_new[i].abs());
        let q = (ws.aux[0][i] / scale).abs();
        if q > best.1 {
            best = (i, q);
        }
    }
    best.0
}

/// One integration request: initial value, output times, breakpoints, events.
pub struct Problem<'a> {
    /// Initial time.
    pub t0: f64,
    /// Initial state (`dim()` entries, finite).
    pub y0: &'a [f64],
    /// Output times, non-decreasing, all `>= t0`; the run ends at the last one.
    pub t_out: &'a [f64],
    /// Times where the right-hand side has a kink or jump (non-decreasing). Steps land on
    /// each one inside `(t0, t_end)` and the method restarts there (fresh derivative and
    /// starting step), so no step straddles a discontinuity.
    pub breakpoints: &'a [f64],
    /// Event functions whose zero crossings are located and reported.
    pub events: &'a [Event<'a>],
}

impl<'a> Problem<'a> {
    /// A request without breakpoints and events.
    pub fn new(t0: f64, y0: &'a [f64], t_out: &'a [f64]) -> Self {
        Self {
            t0,
            y0,
            t_out,
            breakpoints: &[],
            events: &[],
        }
    }

    /// The same request with breakpoints.
    pub fn with_breakpoints(mut self, breakpoints: &'a [f64]) -> Self {
        self.breakpoints = breakpoints;
        self
    }

    /// The same request with events.
    pub fn with_events(mut self, events: &'a [Event<'a>]) -> Self {
        self.events = events;
        self
    }
}

/// Why the observer is called.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SampleKind {
    /// Output time `t_out[i]`.
    Output(usize),
    /// Zero crossing of event `events[i]`.
    Event(usize),
}

/// What the observer sees: a time, the state there, and why.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample<'a> {
    /// Time (s).
    pub t: f64,
    /// State at `t` (dense output between steps).
    pub y: &'a [f64],
    /// Output or event.
    pub kind: SampleKind,
}

/// A solver with its tolerances and limits: the value a model's options hold.
#[derive(Debug, Clone, PartialEq)]
pub struct Integrator {
    /// Method.
    pub solver: Solver,
    /// Relative tolerance of the adaptive methods.
    pub rtol: f64,
    /// Absolute tolerance(s) of the adaptive methods, in the states' units.
    pub atol: Atol,
    /// Largest step of the adaptive methods (s).
    pub max_step: f64,
    /// First step of the adaptive methods; `None` picks one from the initial derivatives
    /// (HNW I, II.4).
    pub first_step: Option<f64>,
    /// Step budget (accepted plus rejected) for the whole run.
    pub max_steps: usize,
    /// Events are located to within this many seconds.
    pub event_tol: f64,
}

impl Integrator {
    /// `solver` with tolerances `rtol`, `atol`, no step ceiling, 10^6 steps, events to 1e-10 s.
    pub fn new(solver: Solver, rtol: f64, atol: impl Into<Atol>) -> Self {
        Self {
            solver,
            rtol,
            atol: atol.into(),
            max_step: f64::INFINITY,
            first_step: None,
            max_steps: 1_000_000,
            event_tol: 1e-10,
        }
    }

    /// Same integrator with a step-size ceiling (s).
    pub fn with_max_step(mut self, max_step: f64) -> Self {
        self.max_step = max_step;
        self
    }

    /// Same integrator with a step budget.
    pub fn with_max_steps(mut self, max_steps: usize) -> Self {
        self.max_steps = max_steps;
        self
    }

    /// Integrate from `(t0, y0)` and call `observe(t, y)` at every time of `t_out`, with a
    /// workspace of its own (one allocation). See [`Integrator::run`] for the rest.
    pub fn integrate<S, F>(
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
        let mut ws = Workspace::new(sys.dim());
        self.run(sys, &Problem::new(t0, y0, t_out), &mut ws, |s| {
            observe(s.t, s.y)
        })
    }

    /// Integrate `problem` using the buffers of `ws` (grown if too small, otherwise no
    /// allocation). The observer sees every output time (interpolated with the method's
    /// dense output) and every located event crossing, in time order, and may end the run
    /// with [`Control::Stop`] (the run then returns `Ok`).
    ///
    /// Errors: [`OdeError::InvalidInput`] for a bad request, [`OdeError::TooManySteps`] past
    /// `max_steps`, [`OdeError::Diverged`] with the time, step and last finite state when the
    /// state turns non-finite or the step collapses below `1e-13 max(|t|, 1)`.
    pub fn run<S, F>(
        &self,
        sys: &S,
        problem: &Problem<'_>,
        ws: &mut Workspace,
        mut observe: F,
    ) -> Result<Stats, OdeError>
    where
        S: OdeSystem + ?Sized,
        F: FnMut(Sample<'_>) -> Control,
    {
        check_request(sys, problem)?;
        self.check_settings()?;
        ws.fit(sys.dim(), problem.events.len());
        self.atol.fill(&mut ws.atol)?;
        // `resolve` never returns `Auto`.
        match self.solver.resolve(sys) {
            Solver::Rosenbrock23 => Drive::new(self, sys, problem, Rosenbrock23Kernel::default())
                .run(None, ws, &mut observe),
            Solver::Ros34pw2 => Drive::new(self, sys, problem, RosenbrockWKernel::default()).run(
                None,
                ws,
                &mut observe,
            ),
            Solver::Ark436 => {
                Drive::new(self, sys, problem, ArkKernel::default()).run(None, ws, &mut observe)
            }
            Solver::Rk4 { step } => Drive::new(self, sys, problem, Rk4Kernel::default()).run(
                Some(step),
                ws,
                &mut observe,
            ),
            Solver::Tsit5 => {
                Drive::new(self, sys, problem, Tsit5Kernel::default()).run(None, ws, &mut observe)
            }
            Solver::Dopri5 | Solver::Auto => {
                Drive::new(self, sys, problem, Dopri5Kernel::default()).run(None, ws, &mut observe)
            }
        }
    }

    fn check_settings(&self) -> Result<(), OdeError> {
        let positive = |v: f64| v.is_finite() && v > 0.0;
        if !positive(self.rtol) {
            return Err(OdeError::InvalidInput(format!(
                "rtol must be positive and finite, got {}",
                self.rtol
            )));
        }
        if self.max_step.is_nan() || self.max_step <= 0.0 {
            return Err(OdeError::InvalidInput(format!(
                "max_step must be positive, got {}",
                self.max_step
            )));
        }
        if let Some(h) = self.first_step.filter(|&h| !positive(h)) {
            return Err(OdeError::InvalidInput(format!(
                "first_step must be positive and finite, got {h}"
            )));
        }
        if self.max_steps == 0 {
            return Err(OdeError::InvalidInput(
                "max_steps must be at least 1".into(),
            ));
        }
        if !positive(self.event_tol) {
            return Err(OdeError::InvalidInput(format!(
                "event_tol must be positive and finite, got {}",
                self.event_tol
            )));
        }
        if let Solver::Rk4 { step } = self.solver {
            if !positive(step) {
                return Err(OdeError::InvalidInput(format!(
                    "RK4 step must be positive and finite, got {step}"
                )));
            }
        }
        Ok(())
    }
}

/// Check the preconditions of an integration request.
fn check_request<S: OdeSystem + ?Sized>(sys: &S, p: &Problem<'_>) -> Result<(), OdeError> {
    if p.y0.len() != sys.dim() {
        return Err(OdeError::InvalidInput(format!(
            "initial state has {} entries, system has {} states",
            p.y0.len(),
            sys.dim()
        )));
    }
    if !p.t0.is_finite() {
        return Err(OdeError::InvalidInput(format!(
            "t0 = {} is not finite",
            p.t0
        )));
    }
    if let Some(i) = p.y0.iter().position(|v| !v.is_finite()) {
        return Err(OdeError::InvalidInput(format!(
            "initial state entry {i} is not finite ({})",
            p.y0[i]
        )));
    }
    let mut prev = p.t0;
    for (i, &t) in p.t_out.iter().enumerate() {
        if !t.is_finite() || t < prev {
            return Err(OdeError::InvalidInput(format!(
                "output time {i} ({t}) is not finite or goes backwards (previous {prev})"
            )));
        }
        prev = t;
    }
    let mut seen = 0;
    for (i, b) in sys.stiff_blocks().iter().enumerate() {
        let n = sys.dim();
        let repeated = |k: usize| b[..k].contains(&b[k]);
        let earlier = |j: usize| sys.stiff_blocks()[..i].iter().any(|o| o.contains(&j));
        if b.is_empty() || (0..b.len()).any(|k| b[k] >= n || repeated(k) || earlier(b[k])) {
            return Err(OdeError::InvalidInput(format!(
                "stiff block {i} ({b:?}) is empty, repeats a state, shares one with an earlier block or names one past the {n} states"
            )));
        }
        seen += b.len();
    }
    if seen > sys.dim() {
        return Err(OdeError::InvalidInput(
            "stiff blocks hold more states than the system".into(),
        ));
    }
    let mut prev = f64::NEG_INFINITY;
    for (i, &b) in p.breakpoints.iter().enumerate() {
        if !b.is_finite() || b < prev {
            return Err(OdeError::InvalidInput(format!(
                "breakpoint {i} ({b}) is not finite or goes backwards (previous {prev})"
            )));
        }
        prev = b;
    }
    Ok(())
}

/// State of one run.
struct Drive<'r, S: ?Sized, K> {
    cfg: &'r Integrator,
    sys: &'r S,
    p: &'r Problem<'r>,
    kernel: K,
    t: f64,
    next_out: usize,
    next_bp: usize,
    stats: Stats,
}

impl<'r, S: OdeSystem + ?Sized, K: Kernel> Drive<'r, S, K> {
    fn new(cfg: &'r Integrator, sys: &'r S, p: &'r Problem<'r>, kernel: K) -> Self {
        Self {
            cfg,
            sys,
            p,
            kernel,
            t: p.t0,
            next_out: 0,
            next_bp: 0,
            stats: Stats::default(),
        }
    }

    /// The next time a step must land on: the first breakpoint after `t`, or `t_end`.
    fn next_stop(&mut self, t_end: f64) -> f64 {
        let bps = self.p.breakpoints;
        while self.next_bp < bps.len() && bps[self.next_bp] <= self.t {
            self.next_bp += 1;
        }
        match bps.get(self.next_bp) {
            Some(&b) if b < t_end => b,
            _ => t_end,
        }
    }

    /// (Re)start the method at `(t, ws.y)`; the starting step of an adaptive method.
    fn restart(&mut self, ws: &mut Workspace, stop: f64) -> f64 {
        self.stats.rhs_evals += self.kernel.start(self.sys, self.t, ws);
        let h = match self.cfg.first_step {
            Some(h) => h,
            None => {
                self.stats.rhs_evals += 1;
                initial_step(self.sys, self.t, self.cfg.rtol, K::ORDER, ws)
            }
        };
        h.min(self.cfg.max_step).min(stop - self.t)
    }

    fn run<F>(
        mut self,
        fixed: Option<f64>,
        ws: &mut Workspace,
        observe: &mut F,
    ) -> Result<Stats, OdeError>
    where
        F: FnMut(Sample<'_>) -> Control,
    {
        if self.begin(ws, observe) == Control::Continue {
            self.advance(fixed, ws, observe)?;
        }
        Ok(self.stats)
    }

    /// Hand the observer the outputs at `t0` and evaluate the events there. `Stop` when the
    /// run is over already (no outputs after `t0`, or the observer stopped it).
    fn begin<F>(&mut self, ws: &mut Workspace, observe: &mut F) -> Control
    where
        F: FnMut(Sample<'_>) -> Control,
    {
        let (t_out, t0) = (self.p.t_out, self.p.t0);
        if t_out.is_empty() {
            return Control::Stop;
        }
        ws.y.copy_from_slice(self.p.y0);
        while self.next_out < t_out.len() && t_out[self.next_out] <= t0 {
            let kind = SampleKind::Output(self.next_out);
            if observe(Sample {
                t: t0,
                y: &ws.y,
                kind,
            }) == Control::Stop
            {
                return Control::Stop;
            }
            self.next_out += 1;
        }
        if self.next_out == t_out.len() {
            return Control::Stop;
        }
        for (i, ev) in self.p.events.iter().enumerate() {
            ws.g_old[i] = (ev.g)(t0, &ws.y);
        }
        Control::Continue
    }

    /// Integrate from `(self.t, ws.y)` (the method restarted there) to the end.
    fn advance<F>(
        &mut self,
        fixed: Option<f64>,
        ws: &mut Workspace,
        observe: &mut F,
    ) -> Result<(), OdeError>
    where
        F: FnMut(Sample<'_>) -> Control,
    {
        let (t_out, t0) = (self.p.t_out, self.p.t0);
        let t_end = t_out[t_out.len() - 1];
        let mut stop = self.next_stop(t_end);
        let mut h = self.restart(ws, stop);
        let mut last_rejected = false;
        // Fixed-step methods: steps left to the current target, and that target.
        let (mut left, mut target) = (0usize, self.t);
        while self.t < t_end {
            if self.stats.accepted + self.stats.rejected >= self.cfg.max_steps {
                return Err(OdeError::TooManySteps {
                    max_steps: self.cfg.max_steps,
                    t: self.t,
                    state: ws.y.to_vec(),
                });
            }
            if fixed.is_none() {
                self.check_pace(t0, t_end, h, ws)?;
            }
            let t = self.t;
            let lands = match fixed {
                Some(step) => {
                    if left == 0 {
                        target = t_out[self.next_out..]
                            .iter()
                            .copied()
                            .find(|&to| to > t)
                            .map_or(stop, |to| to.min(stop));
                        let span = target - t;
                        left = ((span / step).ceil() as usize).max(1);
                        h = span / left as f64;
                    }
                    left == 1
                }
                None => {
                    let lands = t + 1.01 * h >= stop;
                    if lands {
                        h = stop - t;
                    }
                    if h < H_MIN_REL * t.abs().max(1.0) {
                        return Err(self.diverged(h, ws));
                    }
                    lands
                }
            };
            let (e, evals) = self.kernel.attempt(self.sys, t, h, self.cfg.rtol, ws);
            self.stats.rhs_evals += evals;
            if e > 1.0 {
                if fixed.is_some() {
                    return Err(self.diverged(h, ws));
                }
                self.stats.rejected += 1;
                h *= self.kernel.reject_factor(e);
                last_rejected = true;
                continue;
            }
            let t_new = match (lands, fixed) {
                (true, Some(_)) => target,
                (true, None) => stop,
                (false, _) => t + h,
            };
            let ctl = self.emit_step(ws, t_new, h, observe);
            self.stats.accepted += 1;
            if ctl == Control::Stop {
                return Ok(());
            }
            self.stats.rhs_evals += self.kernel.accept(self.sys, t_new, ws);
            std::mem::swap(&mut ws.g_old, &mut ws.g_new);
            self.t = t_new;
            left = left.saturating_sub(1);
            if lands && fixed.is_none() && stop < t_end {
                stop = self.next_stop(t_end);
                h = self.restart(ws, stop);
                last_rejected = false;
            } else if lands && fixed.is_some() && t_new >= stop && stop < t_end {
                stop = self.next_stop(t_end);
                self.stats.rhs_evals += self.kernel.start(self.sys, t_new, ws);
            } else if fixed.is_none() {
                h = (h * self.kernel.accept_factor(e, last_rejected)).min(self.cfg.max_step);
                last_rejected = false;
            }
        }
        Ok(())
    }

    /// [`OdeError::StepSizeCollapsed`] when, every 1024 steps from [`COLLAPSE_MIN_STEPS`]
    /// on, the run's mean pace `(t - t0) / steps` projects more than [`COLLAPSE_FACTOR`]
    /// times the step budget for the whole span.
    fn check_pace(&self, t0: f64, t_end: f64, h: f64, ws: &Workspace) -> Result<(), OdeError> {
        let steps = self.stats.accepted + self.stats.rejected;
        if steps < COLLAPSE_MIN_STEPS || steps % 1024 != 0 {
            return Ok(());
        }
        let pace = (self.t - t0) / steps as f64;
        let projected = steps as f64 + (t_end - self.t) / pace;
        if projected <= COLLAPSE_FACTOR * self.cfg.max_steps as f64 {
            return Ok(());
        }
        Err(OdeError::StepSizeCollapsed {
            t: self.t,
            h,
            projected_steps: projected,
            max_steps: self.cfg.max_steps,
            dominant_state: dominant_state(ws, self.cfg.rtol),
            state: ws.y.to_vec(),
        })
    }

    fn diverged(&self, h: f64, ws: &Workspace) -> OdeError {
        OdeError::Diverged {
            t: self.t,
            h,
            state: ws.y.to_vec(),
        }
    }

    /// Locate the events of the accepted step `(t, t_new]` and hand the observer, in time
    /// order, the outputs and crossings up to the first terminal crossing.
    fn emit_step<F>(&mut self, ws: &mut Workspace, t_new: f64, h: f64, observe: &mut F) -> Control
    where
        F: FnMut(Sample<'_>) -> Control,
    {
        let t = self.t;
        let mut dense_ready = false;
        let mut limit = t_new;
        for (i, ev) in self.p.events.iter().enumerate() {
            ws.g_new[i] = (ev.g)(t_new, &ws.y_new);
            ws.t_cross[i] = f64::NAN;
            if ev.direction.crosses(ws.g_old[i], ws.g_new[i]) {
                if !dense_ready {
                    self.stats.rhs_evals += self.kernel.prepare_dense(self.sys, t, h, ws);
                    dense_ready = true;
                }
                let g = (ws.g_old[i], ws.g_new[i]);
                let tc = locate(&self.kernel, ev, (t, h), g, self.cfg.event_tol, ws);
                ws.t_cross[i] = tc;
                if ev.terminal && tc < limit {
                    limit = tc;
                }
            }
        }
        let t_out = self.p.t_out;
        loop {
            let out = (self.next_out < t_out.len() && t_out[self.next_out] <= limit)
                .then(|| t_out[self.next_out]);
            let ev = ws
                .t_cross
                .iter()
                .enumerate()
                .filter(|(_, tc)| **tc <= limit)
                .min_by(|a, b| a.1.total_cmp(b.1))
                .map(|(i, &tc)| (i, tc));
            let (ts, kind) = match (out, ev) {
                (Some(to), Some((_, te))) if to <= te => (to, SampleKind::Output(self.next_out)),
                (Some(to), None) => (to, SampleKind::Output(self.next_out)),
                (_, Some((i, te))) => (te, SampleKind::Event(i)),
                (None, None) => return Control::Continue,
            };
            let y: &[f64] = if ts == t_new {
                &ws.y_new
            } else {
                if !dense_ready {
                    self.stats.rhs_evals += self.kernel.prepare_dense(self.sys, t, h, ws);
                    dense_ready = true;
                }
                self.kernel.dense((ts - t) / h, h, ws);
                &ws.y_out
            };
            let ctl = observe(Sample { t: ts, y, kind });
            match kind {
                SampleKind::Output(_) => self.next_out += 1,
                SampleKind::Event(i) => {
                    ws.t_cross[i] = f64::NAN;
                    self.stats.events += 1;
                    if self.p.events[i].terminal {
                        return Control::Stop;
                    }
                }
            }
            if ctl == Control::Stop {
                return Control::Stop;
            }
        }
    }
}
