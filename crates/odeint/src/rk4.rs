//! Classical fixed-step Runge-Kutta 4 step (reference integrator for convergence checks),
//! with a cubic Hermite interpolant for event location.
//!
//! Workspace use: `k[0..4]` the stages k1..k4, `k[4]` f(t+h, y_new) when the interpolant
//! was needed (then it is the next step's k1).

use crate::kernel::Kernel;
use crate::{OdeSystem, Workspace};

/// The RK4 kernel.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Rk4Kernel {
    /// `k[0]` holds f(t, y) of the current step.
    start_ready: bool,
    /// `k[4]` holds f(t+h, y_new) of the step just taken.
    end_ready: bool,
}

impl Kernel for Rk4Kernel {
    const ORDER: i32 = 4;

    fn start<S: OdeSystem + ?Sized>(&mut self, sys: &S, t: f64, ws: &mut Workspace) -> usize {
        sys.rhs(t, &ws.y, &mut ws.k[0]);
        self.start_ready = true;
        1
    }

    fn attempt<S: OdeSystem + ?Sized>(
        &mut self,
        sys: &S,
        t: f64,
        h: f64,
        _rtol: f64,
        ws: &mut Workspace,
    ) -> (f64, usize) {
        let mut evals = 3;
        if !self.start_ready {
            evals += self.start(sys, t, ws);
        }
        self.end_ready = false;
        let Workspace {
            y,
            y_new,
            y_stage: ys,
            k,
            ..
        } = ws;
        let [k1, k2, k3, k4, ..] = k;
        let n = y.len();
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
        let mut finite = true;
        for i in 0..n {
            let v = y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
            finite &= v.is_finite();
            y_new[i] = v;
        }
        (if finite { 0.0 } else { f64::INFINITY }, evals)
    }

    fn reject_factor(&self, _e: f64) -> f64 {
        1.0
    }

    fn accept_factor(&self, _e: f64, _last_rejected: bool) -> f64 {
        1.0
    }

    fn prepare_dense<S: OdeSystem + ?Sized>(
        &mut self,
        sys: &S,
        t: f64,
        h: f64,
        ws: &mut Workspace,
    ) -> usize {
        if self.end_ready {
            return 0;
        }
        sys.rhs(t + h, &ws.y_new, &mut ws.k[4]);
        self.end_ready = true;
        1
    }

    /// Cubic Hermite interpolation between (y, k1) and (y_new, f(t+h, y_new)).
    fn dense(&self, theta: f64, h: f64, ws: &mut Workspace) {
        hermite(
            theta,
            h,
            &ws.y,
            &ws.k[0],
            &ws.y_new,
            &ws.k[4],
            &mut ws.y_out,
        );
    }

    fn accept<S: OdeSystem + ?Sized>(
        &mut self,
        _sys: &S,
        _t_new: f64,
        ws: &mut Workspace,
    ) -> usize {
        ws.y.copy_from_slice(&ws.y_new);
        self.start_ready = self.end_ready;
        if self.end_ready {
            let [k1, .., f_end, _, _] = &mut ws.k;
            k1.copy_from_slice(f_end);
        }
        0
    }
}

/// Cubic Hermite interpolation at `t + theta h` between `(y0, f0)` at `t` and `(y1, f1)` at
/// `t + h` into `out`: third-order accurate, the dense output of RK4 and ROS34PW2.
pub(crate) fn hermite(
    theta: f64,
    h: f64,
    y0: &[f64],
    f0: &[f64],
    y1: &[f64],
    f1: &[f64],
    out: &mut [f64],
) {
    let s = theta;
    let h00 = (1.0 + 2.0 * s) * (1.0 - s) * (1.0 - s);
    let h10 = s * (1.0 - s) * (1.0 - s);
    let h01 = s * s * (3.0 - 2.0 * s);
    let h11 = s * s * (s - 1.0);
    for i in 0..out.len() {
        out[i] = h00 * y0[i] + h * h10 * f0[i] + h01 * y1[i] + h * h11 * f1[i];
    }
}
