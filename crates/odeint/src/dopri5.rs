//! Dormand-Prince 5(4) step with error estimate and 4th-order dense output
//! (Hairer, Nørsett & Wanner, *Solving ODEs I*, section II.5/II.6, code DOPRI5).
//!
//! Workspace use: `k[0..7]` the stages k1..k7 (k7 = f(t+h, y_new) is the next k1, FSAL),
//! `aux[0]` the error estimate, `aux[1..4]` the dense-output coefficients, `y_stage` the
//! sixth stage's argument (kept to the end of the step for the stiffness test).
//!
//! Stiffness detection: [`crate::stiffness`] on the stages k6 and k7, both at `t + h`.

use crate::kernel::Kernel;
use crate::stiffness::StiffnessWatch;
use crate::tolerance::error_norm;
use crate::{OdeSystem, Workspace};

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

/// The Dormand-Prince 5(4) kernel with its stiffness test.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Dopri5Kernel {
    /// Step of the last attempt.
    h: f64,
    /// Stiffness test.
    watch: StiffnessWatch,
}

impl Kernel for Dopri5Kernel {
    const ORDER: i32 = 5;

    fn start<S: OdeSystem + ?Sized>(&mut self, sys: &S, t: f64, ws: &mut Workspace) -> usize {
        self.watch.reset();
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
        let Workspace {
            y,
            y_new: y1,
            y_stage: ys,
            k,
            aux,
            atol,
            ..
        } = ws;
        let [k1, k2, k3, k4, k5, k6, k7] = k;
        let err = &mut aux[0];
        let n = y.len();
        self.h = h;
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
            ys[i] =
                y[i] + h * (A61 * k1[i] + A62 * k2[i] + A63 * k3[i] + A64 * k4[i] + A65 * k5[i]);
        }
        sys.rhs(t + h, ys, k6);
        for i in 0..n {
            y1[i] =
                y[i] + h * (A71 * k1[i] + A73 * k3[i] + A74 * k4[i] + A75 * k5[i] + A76 * k6[i]);
        }
        sys.rhs(t + h, y1, k7);
        for i in 0..n {
            err[i] =
                h * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i]);
        }
        let e = error_norm(err, y, y1, rtol, atol);
        let finite = e.is_finite() && y1.iter().all(|v| v.is_finite());
        (if finite { e } else { f64::INFINITY }, 6)
    }

    fn reject_factor(&self, e: f64) -> f64 {
        if e.is_finite() {
            (0.9 * e.powf(-0.2)).clamp(0.2, 1.0)
        } else {
            0.1
        }
    }

    fn accept_factor(&self, e: f64, last_rejected: bool) -> f64 {
        let fac = (0.9 * e.max(1e-10).powf(-0.2)).clamp(0.2, 5.0);
        if last_rejected {
            fac.min(1.0)
        } else {
            fac
        }
    }

    fn prepare_dense<S: OdeSystem + ?Sized>(
        &mut self,
        _sys: &S,
        _t: f64,
        h: f64,
        ws: &mut Workspace,
    ) -> usize {
        let Workspace {
            y,
            y_new: y1,
            k,
            aux,
            ..
        } = ws;
        let [k1, _, k3, k4, k5, k6, k7] = k;
        let [_, r3, r4, r5] = aux;
        for i in 0..y.len() {
            let ydiff = y1[i] - y[i];
            let bspl = h * k1[i] - ydiff;
            r3[i] = bspl;
            r4[i] = ydiff - h * k7[i] - bspl;
            r5[i] =
                h * (D1 * k1[i] + D3 * k3[i] + D4 * k4[i] + D5 * k5[i] + D6 * k6[i] + D7 * k7[i]);
        }
        0
    }

    fn dense(&self, theta: f64, _h: f64, ws: &mut Workspace) {
        let Workspace {
            y,
            y_new: y1,
            y_out,
            aux,
            ..
        } = ws;
        let [_, r3, r4, r5] = aux;
        let theta1 = 1.0 - theta;
        for i in 0..y.len() {
            let ydiff = y1[i] - y[i];
            y_out[i] = y[i] + theta * (ydiff + theta1 * (r3[i] + theta * (r4[i] + theta1 * r5[i])));
        }
    }

    fn accept<S: OdeSystem + ?Sized>(
        &mut self,
        _sys: &S,
        _t_new: f64,
        ws: &mut Workspace,
    ) -> usize {
        let [k1, .., k6, k7] = &mut ws.k;
        self.watch.observe(self.h, k6, k7, &ws.y_stage, &ws.y_new);
        k1.copy_from_slice(k7);
        ws.y.copy_from_slice(&ws.y_new);
        0
    }

    fn stiff(&self) -> bool {
        self.watch.stiff()
    }
}
