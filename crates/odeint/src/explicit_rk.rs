//! What the two explicit 5(4) pairs share, Dormand-Prince ([`crate::dopri5`]) and Tsitouras
//! ([`crate::tsit5`]): seven stages, first same as last (the propagated solution is the
//! seventh stage's argument, so `k7 = f(t + h, y_new)` is the next step's `k1`), the error
//! estimate `h Σ (b̂_i − b_i) k_i` and the step-size factors of an order-5 controller. A
//! pair gives its tableau and its own dense output ([`Pair`]); [`FsalKernel`] does the rest.
//!
//! Workspace use: `k[0..7]` the stages k1..k7, `aux[0]` the error estimate, `y_stage` the
//! stage argument; `aux[1..4]` are the pair's, for its dense output.
//!
//! The stage sums are written term by term from `k1` on, each term whose coefficient is
//! zero left out (the coefficients are constants, so the test costs nothing): the same
//! operations in the same order as a hand-written stage of the pair.

use crate::kernel::{accepted_step_factor, rejected_step_factor, Kernel};
use crate::tolerance::error_norm;
use crate::{OdeSystem, Workspace};

/// A seven-stage FSAL pair of order 5(4): its tableau and its dense output.
pub(crate) trait Pair {
    /// Nodes `c_2..c_5` (`c_6 = c_7 = 1`).
    const C: [f64; 4];
    /// `a_21`.
    const A2: f64;
    /// `a_31, a_32`.
    const A3: [f64; 2];
    /// `a_41..a_43`.
    const A4: [f64; 3];
    /// `a_51..a_54`.
    const A5: [f64; 4];
    /// `a_61..a_65`.
    const A6: [f64; 5];
    /// `a_7j = b_j`, the fifth-order weights (`b_7 = 0`).
    const B: [f64; 6];
    /// `b̂_i − b_i`: the embedded fourth-order solution minus the fifth-order one.
    const E: [f64; 7];

    /// Dense-output preparation after an accepted step of size `h` (into `aux[1..4]` if the
    /// pair needs it); right-hand sides evaluated.
    fn prepare_dense(h: f64, ws: &mut Workspace) -> usize;

    /// `y(t + θh)` into `y_out`.
    fn dense(theta: f64, h: f64, ws: &mut Workspace);
}

/// `Σ_j c_j k_j[i]` from `j = 0` on, terms with `c_j = 0` left out (module docs).
#[inline(always)]
fn weighted<const N: usize>(c: &[f64; N], k: [&[f64]; N], i: usize) -> f64 {
    let mut sum = c[0] * k[0][i];
    for j in 1..N {
        if c[j] != 0.0 {
            sum += c[j] * k[j][i];
        }
    }
    sum
}

/// The step of a seven-stage FSAL pair `P`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct FsalKernel<P> {
    pair: std::marker::PhantomData<P>,
}

impl<P> Default for FsalKernel<P> {
    fn default() -> Self {
        Self {
            pair: std::marker::PhantomData,
        }
    }
}

impl<P: Pair> Kernel for FsalKernel<P> {
    const ORDER: i32 = 5;

    fn start<S: OdeSystem + ?Sized>(&mut self, sys: &S, t: f64, ws: &mut Workspace) -> usize {
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
        for i in 0..n {
            ys[i] = y[i] + h * P::A2 * k1[i];
        }
        sys.rhs(t + P::C[0] * h, ys, k2);
        for i in 0..n {
            ys[i] = y[i] + h * weighted(&P::A3, [k1, k2], i);
        }
        sys.rhs(t + P::C[1] * h, ys, k3);
        for i in 0..n {
            ys[i] = y[i] + h * weighted(&P::A4, [k1, k2, k3], i);
        }
        sys.rhs(t + P::C[2] * h, ys, k4);
        for i in 0..n {
            ys[i] = y[i] + h * weighted(&P::A5, [k1, k2, k3, k4], i);
        }
        sys.rhs(t + P::C[3] * h, ys, k5);
        for i in 0..n {
            ys[i] = y[i] + h * weighted(&P::A6, [k1, k2, k3, k4, k5], i);
        }
        sys.rhs(t + h, ys, k6);
        for i in 0..n {
            y1[i] = y[i] + h * weighted(&P::B, [k1, k2, k3, k4, k5, k6], i);
        }
        sys.rhs(t + h, y1, k7);
        for (i, e) in err.iter_mut().enumerate() {
            *e = h * weighted(&P::E, [k1, k2, k3, k4, k5, k6, k7], i);
        }
        let e = error_norm(err, y, y1, rtol, atol);
        let finite = e.is_finite() && y1.iter().all(|v| v.is_finite());
        (if finite { e } else { f64::INFINITY }, 6)
    }

    fn reject_factor(&self, e: f64) -> f64 {
        rejected_step_factor(e, -0.2, 1.0)
    }

    fn accept_factor(&self, e: f64, last_rejected: bool) -> f64 {
        accepted_step_factor(e, -0.2, last_rejected)
    }

    fn prepare_dense<S: OdeSystem + ?Sized>(
        &mut self,
        _sys: &S,
        _t: f64,
        h: f64,
        ws: &mut Workspace,
    ) -> usize {
        P::prepare_dense(h, ws)
    }

    fn dense(&self, theta: f64, h: f64, ws: &mut Workspace) {
        P::dense(theta, h, ws)
    }

    fn accept<S: OdeSystem + ?Sized>(
        &mut self,
        _sys: &S,
        _t_new: f64,
        ws: &mut Workspace,
    ) -> usize {
        let [k1, .., k7] = &mut ws.k;
        k1.copy_from_slice(k7);
        ws.y.copy_from_slice(&ws.y_new);
        0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weighted_sums_leave_out_zero_terms_in_order() {
        let k = [[1.0, 2.0], [f64::INFINITY, 3.0], [0.5, -1.0]];
        // the zero coefficient skips the infinite entry instead of making NaN
        assert_eq!(weighted(&[2.0, 0.0, 4.0], [&k[0], &k[1], &k[2]], 0), 4.0);
        assert_eq!(weighted(&[2.0, 1.0, 4.0], [&k[0], &k[1], &k[2]], 1), 3.0);
        // left to right: (0.1 + 0.2) + 0.3, not 0.1 + (0.2 + 0.3)
        let ones = [1.0];
        let s = weighted(&[0.1, 0.2, 0.3], [&ones, &ones, &ones], 0);
        assert_eq!(s, (0.1 + 0.2) + 0.3);
    }
}
