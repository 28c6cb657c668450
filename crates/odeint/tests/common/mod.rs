//! Test systems with closed-form solutions.
#![allow(dead_code)]

use odeint::OdeSystem;
use std::cell::Cell;

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

/// Two nonlinear equations with closed forms (every elementary differential of order <= 5
/// appears, unlike on a linear problem): the logistic `y0' = y0 (1 - y0)`, `y0(0) = 0.1`,
/// and `y1' = -2 t y1²`, `y1(0) = 1`, whose solution is `1 / (1 + t²)`.
pub struct Logistic;

impl Logistic {
    pub fn exact(t: f64) -> [f64; 2] {
        [1.0 / (1.0 + 9.0 * (-t).exp()), 1.0 / (1.0 + t * t)]
    }
}

impl OdeSystem for Logistic {
    fn dim(&self) -> usize {
        2
    }
    fn rhs(&self, t: f64, y: &[f64], d: &mut [f64]) {
        d[0] = y[0] * (1.0 - y[0]);
        d[1] = -2.0 * t * y[1] * y[1];
    }
}

/// Least-squares slope of log(error) against log(steps).
pub fn loglog_slope(points: &[(f64, f64)]) -> f64 {
    let n = points.len() as f64;
    let (mx, my) = points.iter().fold((0.0, 0.0), |(a, b), (x, y)| {
        (a + x.ln() / n, b + y.ln() / n)
    });
    let (sxy, sxx) = points.iter().fold((0.0, 0.0), |(a, b), (x, y)| {
        let dx = x.ln() - mx;
        (a + dx * (y.ln() - my), b + dx * dx)
    });
    sxy / sxx
}

/// A slow oscillator beside a stiff state that follows it linearly: `x'' = −x`,
/// `s' = −k (s − x)`; `s` follows `x` within `1/k`. The block `blocks` names (if any) has
/// its exact Jacobian when `own_jacobian` and its own rates when `own_rates`;
/// `block_evals` counts the evaluations of those rates.
pub struct StiffFollower {
    pub k: f64,
    pub blocks: Vec<Vec<usize>>,
    pub own_jacobian: bool,
    pub own_rates: bool,
    pub block_evals: Cell<usize>,
}

impl StiffFollower {
    /// The follower with stiffness `k` and the stiff blocks `blocks`, the block's Jacobian
    /// its own when `own_jacobian`, and no block rates of its own.
    pub fn new(k: f64, blocks: Vec<Vec<usize>>, own_jacobian: bool) -> Self {
        Self {
            k,
            blocks,
            own_jacobian,
            own_rates: false,
            block_evals: Cell::new(0),
        }
    }
}

impl OdeSystem for StiffFollower {
    fn dim(&self) -> usize {
        3
    }
    fn rhs(&self, _t: f64, y: &[f64], d: &mut [f64]) {
        d[0] = y[1];
        d[1] = -y[0];
        d[2] = -self.k * (y[2] - y[0]);
    }
    fn stiff_blocks(&self) -> &[Vec<usize>] {
        &self.blocks
    }
    fn block_jacobian(&self, _t: f64, _y: &[f64], _block: usize, jac: &mut [f64]) -> bool {
        if self.own_jacobian {
            jac[0] = -self.k;
        }
        self.own_jacobian
    }
    fn block_rhs(&self, _t: f64, y: &[f64], _block: usize, out: &mut [f64]) -> bool {
        if self.own_rates {
            self.block_evals.set(self.block_evals.get() + 1);
            out[0] = -self.k * (y[2] - y[0]);
        }
        self.own_rates
    }
}
