//! The single-step interface the driver calls, and the starting-step heuristic the adaptive
//! kernels share.

use crate::{OdeSystem, Workspace};

/// One method's step, error estimate, dense output and step-size rule. The driver owns
/// everything else (outputs, breakpoints, events, limits). By convention `ws.k[0]` holds
/// f(t, y) at the start of the step.
pub(crate) trait Kernel {
    /// Order of the propagated solution (starting-step heuristic).
    const ORDER: i32;

    /// (Re)start at `(t, ws.y)`: evaluate what the first step needs. Returns RHS calls.
    fn start<S: OdeSystem + ?Sized>(&mut self, sys: &S, t: f64, ws: &mut Workspace) -> usize;

    /// One step of size `h` from `(t, ws.y)` into `ws.y_new`. Returns the weighted RMS
    /// error norm (`f64::INFINITY` for a non-finite candidate; 0 for fixed-step methods)
    /// and the RHS calls made.
    fn attempt<S: OdeSystem + ?Sized>(
        &mut self,
        sys: &S,
        t: f64,
        h: f64,
        rtol: f64,
        ws: &mut Workspace,
    ) -> (f64, usize);

    /// Step-size factor after a rejected step with error norm `e` (possibly not finite).
    fn reject_factor(&self, e: f64) -> f64;

    /// Step-size factor after an accepted step with error norm `e`.
    fn accept_factor(&self, e: f64, last_rejected: bool) -> f64;

    /// Make the dense output of the step just taken usable. Returns RHS calls.
    fn prepare_dense<S: OdeSystem + ?Sized>(
        &mut self,
        sys: &S,
        t: f64,
        h: f64,
        ws: &mut Workspace,
    ) -> usize;

    /// State at `t + theta h` of the step just taken (after [`Kernel::prepare_dense`]) into `ws.y_out`.
    fn dense(&self, theta: f64, h: f64, ws: &mut Workspace);

    /// Commit the step (`ws.y <- ws.y_new`) and carry what the next step can reuse.
    /// Returns RHS calls.
    fn accept<S: OdeSystem + ?Sized>(&mut self, sys: &S, t_new: f64, ws: &mut Workspace) -> usize;
}

/// Step-size factor after an accepted step of an adaptive kernel whose error estimate is of
/// order `q − 1` (`exponent = −1/q`): `0.9 e^exponent` within `[0.2, 5]`, at most 1 right
/// after a rejection (HNW I, II.4).
pub(crate) fn accepted_step_factor(e: f64, exponent: f64, last_rejected: bool) -> f64 {
    let f = (0.9 * e.max(1e-10).powf(exponent)).clamp(0.2, 5.0);
    if last_rejected {
        f.min(1.0)
    } else {
        f
    }
}

/// Step-size factor after a rejected step with error norm `e`: `0.9 e^exponent` within
/// `[0.2, max]`, or 0.1 when the attempt gave no finite error.
pub(crate) fn rejected_step_factor(e: f64, exponent: f64, max: f64) -> f64 {
    if e.is_finite() {
        (0.9 * e.powf(exponent)).clamp(0.2, max)
    } else {
        0.1
    }
}

/// Hairer's starting-step heuristic (HNW I, II.4) for a method of order `order`, from
/// `(t, ws.y)` with `ws.k[0] = f(t, y)`; costs one RHS call (scratch `ws.y_stage`, `ws.k[1]`).
pub(crate) fn initial_step<S: OdeSystem + ?Sized>(
    sys: &S,
    t: f64,
    rtol: f64,
    order: i32,
    ws: &mut Workspace,
) -> f64 {
    let Workspace {
        y,
        y_stage,
        k,
        atol,
        ..
    } = ws;
    let [f0, f1, ..] = k;
    let n = y.len().max(1) as f64;
    let (mut d0, mut d1) = (0.0, 0.0);
    for i in 0..y.len() {
        let sk = atol[i] + rtol * y[i].abs();
        d0 += (y[i] / sk).powi(2);
        d1 += (f0[i] / sk).powi(2);
    }
    d0 = (d0 / n).sqrt();
    d1 = (d1 / n).sqrt();
    let h0 = if d0 < 1e-5 || d1 < 1e-5 {
        1e-6
    } else {
        0.01 * d0 / d1
    };
    for i in 0..y.len() {
        y_stage[i] = y[i] + h0 * f0[i];
    }
    sys.rhs(t + h0, y_stage, f1);
    let mut d2 = 0.0;
    for i in 0..y.len() {
        let sk = atol[i] + rtol * y[i].abs();
        d2 += ((f1[i] - f0[i]) / sk).powi(2);
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
