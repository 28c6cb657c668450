//! Linearly implicit Rosenbrock-W step of order 2(3) (Shampine & Reichelt, "The MATLAB ODE
//! suite", SIAM J. Sci. Comput. 18, 1997: the `ode23s` scheme), L-stable, with a
//! finite-difference Jacobian refreshed every accepted step (`dim() + 1` extra RHS calls).
//!
//! Workspace use: `k[0]` F0 = f(t, y), `k[1]` F1, `k[2]` F2 = f(t+h, y_new) (the next F0),
//! `k[3..6]` the increments k1..k3, `k[6]` df/dt; `aux[0]` the error, `aux[1]` solve
//! scratch; `jac`, `w`, `piv` the Jacobian and the factored W = I - h d J.

use crate::kernel::Kernel;
use crate::linalg::{lu_factor, lu_solve};
use crate::tolerance::error_norm;
use crate::{OdeSystem, Workspace};

/// d = 1 / (2 + sqrt 2) of the ode23s scheme.
const D: f64 = 1.0 / (2.0 + std::f64::consts::SQRT_2);
/// e32 = 6 + sqrt 2 of the ode23s scheme.
const E32: f64 = 6.0 + std::f64::consts::SQRT_2;

/// The Rosenbrock 2(3) kernel.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Rosenbrock23Kernel {
    need_jac: bool,
    singular: bool,
}

impl Rosenbrock23Kernel {
    /// Finite-difference Jacobian J[i][j] = df_i/dy_j (row-major) and df/dt at `(t, ws.y)`.
    fn jacobian<S: OdeSystem + ?Sized>(&self, sys: &S, t: f64, rtol: f64, ws: &mut Workspace) {
        let Workspace {
            y,
            y_stage: ys,
            k,
            atol,
            jac,
            ..
        } = ws;
        let [f0, f1, .., dfdt] = k;
        let n = y.len();
        for j in 0..n {
            let yj = y[j];
            let dy = f64::EPSILON.sqrt() * yj.abs().max(atol[j] / rtol).max(1e-8);
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
    }
}

impl Kernel for Rosenbrock23Kernel {
    const ORDER: i32 = 2;

    fn start<S: OdeSystem + ?Sized>(&mut self, sys: &S, t: f64, ws: &mut Workspace) -> usize {
        self.need_jac = true;
        sys.rhs(t, &ws.y, &mut ws.k[0]);
        1
    }

    fn attempt<S: OdeSystem + ?Sized>(
        &mut self,
        sys: &S,
        t: f64,
        h: f64,
        rtol: f64,
        ws: &mut Workspace,
    ) -> (f64, usize) {
        let n = ws.dim;
        let mut evals = 0;
        if self.need_jac {
            self.jacobian(sys, t, rtol, ws);
            evals += n + 1;
            self.need_jac = false;
        }
        let Workspace {
            y,
            y_new: y1,
            y_stage: ys,
            k,
            aux,
            atol,
            jac,
            w,
            piv,
            ..
        } = ws;
        let [f0, f1, f2, k1, k2, k3, dfdt] = k;
        let [err, tmp, ..] = aux;
        // W = I - h d J, factored in its own buffer so the Jacobian survives a rejection.
        let hd = h * D;
        for i in 0..n {
            for j in 0..n {
                w[i * n + j] = -hd * jac[i * n + j] + if i == j { 1.0 } else { 0.0 };
            }
        }
        self.singular = !lu_factor(w, piv, n);
        if self.singular {
            return (f64::INFINITY, evals);
        }
        // k1 = W^-1 (F0 + h d T)
        for i in 0..n {
            k1[i] = f0[i] + hd * dfdt[i];
        }
        lu_solve(w, piv, n, k1, tmp);
        for i in 0..n {
            ys[i] = y[i] + 0.5 * h * k1[i];
        }
        sys.rhs(t + 0.5 * h, ys, f1);
        // k2 = W^-1 (F1 - k1) + k1
        for i in 0..n {
            k2[i] = f1[i] - k1[i];
        }
        lu_solve(w, piv, n, k2, tmp);
        for i in 0..n {
            k2[i] += k1[i];
            y1[i] = y[i] + h * k2[i];
        }
        sys.rhs(t + h, y1, f2);
        // k3 = W^-1 [F2 - e32 (k2 - F1) - 2 (k1 - F0) + h d T]
        for i in 0..n {
            k3[i] = f2[i] - E32 * (k2[i] - f1[i]) - 2.0 * (k1[i] - f0[i]) + hd * dfdt[i];
        }
        lu_solve(w, piv, n, k3, tmp);
        evals += 2;
        for i in 0..n {
            err[i] = h / 6.0 * (k1[i] - 2.0 * k2[i] + k3[i]);
        }
        let e = error_norm(err, y, y1, rtol, atol);
        let finite = e.is_finite() && y1.iter().all(|v| v.is_finite());
        (if finite { e } else { f64::INFINITY }, evals)
    }

    fn reject_factor(&self, e: f64) -> f64 {
        if self.singular {
            0.5
        } else if e.is_finite() {
            (0.8 * e.powf(-1.0 / 3.0)).clamp(0.1, 0.5)
        } else {
            0.1
        }
    }

    fn accept_factor(&self, e: f64, _last_rejected: bool) -> f64 {
        (0.8 * e.max(1e-10).powf(-1.0 / 3.0)).clamp(0.2, 5.0)
    }

    fn prepare_dense<S: OdeSystem + ?Sized>(
        &mut self,
        _sys: &S,
        _t: f64,
        _h: f64,
        _ws: &mut Workspace,
    ) -> usize {
        0
    }

    /// Shampine & Reichelt's interpolant `y + h (s(1-s) k1 + s(s-2d) k2) / (1-2d)`.
    fn dense(&self, theta: f64, h: f64, ws: &mut Workspace) {
        let s = theta;
        let c1 = s * (1.0 - s) / (1.0 - 2.0 * D);
        let c2 = s * (s - 2.0 * D) / (1.0 - 2.0 * D);
        let Workspace { y, y_out, k, .. } = ws;
        let [.., k1, k2, _, _] = k;
        for i in 0..y.len() {
            y_out[i] = y[i] + h * (c1 * k1[i] + c2 * k2[i]);
        }
    }

    fn accept<S: OdeSystem + ?Sized>(
        &mut self,
        _sys: &S,
        _t_new: f64,
        ws: &mut Workspace,
    ) -> usize {
        ws.y.copy_from_slice(&ws.y_new);
        let [f0, _, f2, ..] = &mut ws.k;
        f0.copy_from_slice(f2);
        self.need_jac = true;
        0
    }
}
