//! Linearly implicit Rosenbrock-W step of order 3(2), ROS34PW2 (J. Rang & L. Angermann,
//! "New Rosenbrock W-methods of order 3 for partial differential algebraic equations of
//! index 1", BIT 45, 2005, 761-787): four stages, stiffly accurate, L-stable with the exact
//! Jacobian, and of order 3 for *any* matrix in place of the Jacobian (a W-method).
//!
//! The W property is what makes it cheap on the suspended vehicles: the matrix it inverts
//! holds only the model's stiff diagonal blocks ([`crate::OdeSystem::stiff_blocks`], e.g.
//! each HPS strut's three states), zero elsewhere. The stiff states are then treated
//! implicitly through a few 3 × 3 factorisations, the rest of the state (the multibody
//! block) explicitly, and the order of the method does not depend on the coupling left out.
//!
//! Stages in the transformed variables `u_i = Σ_j γ_ij k_j` (Hairer & Wanner, *Solving ODEs
//! II*, IV.7, Eq 7.25), autonomous form (the time derivative is part of what a W-method may
//! leave out of its matrix):
//!
//! ```text
//! (I/(h γ) − J) u_i = f(t + α_i h, y + Σ_{j<i} a_ij u_j) + Σ_{j<i} (c_ij / h) u_j
//! y_1 = y + Σ m_i u_i,   error = Σ (m_i − m̂_i) u_i
//! a = α Γ⁻¹,  c = diag(1/γ) − Γ⁻¹,  m = b Γ⁻¹,  m̂ = b̂ Γ⁻¹
//! ```
//!
//! with Rang & Angermann's α, Γ (γ = 0.4358665215 on the diagonal), b and the order-2
//! embedding b̂; the transformed coefficients are computed from them once per run
//! ([`Tableau::ros34pw2`]). Dense output: cubic Hermite between `(y, f(t, y))` and
//! `(y_1, f(t + h, y_1))` in the explicit states, linear in the stiff ones;
//! `f(t + h, y_1)` is the next step's first stage, so an accepted step costs four
//! right-hand sides and a rejected one three.
//!
//! Workspace use: `k[0]` f(t, y), `k[1..5]` the stage increments u_1..u_4, `k[5]` the stage
//! derivative, `k[6]` f(t + h, y_1); `aux[0]` the error, `aux[1]` solve scratch, `aux[2]`
//! the blocks' gathered entries, `aux[3]` the mask of block states for the dense output (set
//! at each start); `jac`, `w` and `piv` the blocks' Jacobians and factors
//! ([`crate::blocks`]).

use crate::blocks;
use crate::kernel::{accepted_step_factor, rejected_step_factor, Kernel};
use crate::linalg::lu_solve;
use crate::tolerance::error_norm;
use crate::{OdeSystem, Workspace};

/// Stages of ROS34PW2.
const S: usize = 4;

/// The diagonal γ of ROS34PW2.
const GAMMA: f64 = 0.435_866_521_508_459;

/// ROS34PW2 in the transformed variables (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Tableau {
    /// Stage times α_i.
    pub(crate) alpha: [f64; S],
    /// Stage arguments a_ij (j < i).
    pub(crate) a: [[f64; S]; S],
    /// Stage couplings c_ij (j < i).
    pub(crate) c: [[f64; S]; S],
    /// Solution weights m_i.
    pub(crate) m: [f64; S],
    /// Error weights m_i − m̂_i.
    pub(crate) e: [f64; S],
}

impl Tableau {
    /// Rang & Angermann's coefficients (their Table "ROS34PW2"), transformed.
    #[allow(clippy::needless_range_loop)] // matrix indices read as the equations
    pub(crate) fn ros34pw2() -> Self {
        let alpha_ij = [
            [0.0; S],
            [0.871_733_043_016_918, 0.0, 0.0, 0.0],
            [0.844_570_600_153_694_2, -0.112_990_642_364_841_85, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
        ];
        let gamma_ij = [
            [GAMMA, 0.0, 0.0, 0.0],
            [-0.871_733_043_016_918, GAMMA, 0.0, 0.0],
            [
                -0.903_380_570_130_440_8,
                0.054_180_672_388_095_326,
                GAMMA,
                0.0,
            ],
            [
                0.242_123_807_060_953_46,
                -1.223_250_583_904_514_7,
                0.545_260_255_335_102_1,
                GAMMA,
            ],
        ];
        let b = [
            0.242_123_807_060_953_46,
            -1.223_250_583_904_514_7,
            1.545_260_255_335_102,
            GAMMA,
        ];
        let b_hat = [
            0.378_109_031_458_193_7,
            -0.096_042_292_212_423_18,
            0.5,
            0.217_933_260_754_229_5,
        ];
        let g = lower_inverse(&gamma_ij);
        let mut t = Tableau {
            alpha: [0.0; S],
            a: [[0.0; S]; S],
            c: [[0.0; S]; S],
            m: [0.0; S],
            e: [0.0; S],
        };
        for i in 0..S {
            t.alpha[i] = alpha_ij[i].iter().sum();
            for j in 0..i {
                t.a[i][j] = (0..S).map(|k| alpha_ij[i][k] * g[k][j]).sum();
                t.c[i][j] = -g[i][j];
            }
            t.m[i] = (0..S).map(|k| b[k] * g[k][i]).sum();
            let m_hat: f64 = (0..S).map(|k| b_hat[k] * g[k][i]).sum();
            t.e[i] = t.m[i] - m_hat;
        }
        t
    }
}

/// Inverse of a lower-triangular matrix (forward substitution on the identity).
#[allow(clippy::needless_range_loop)] // matrix indices read as the equations
fn lower_inverse(l: &[[f64; S]; S]) -> [[f64; S]; S] {
    let mut inv = [[0.0; S]; S];
    for col in 0..S {
        for i in col..S {
            let rhs = if i == col { 1.0 } else { 0.0 };
            let s: f64 = (col..i).map(|k| l[i][k] * inv[k][col]).sum();
            inv[i][col] = (rhs - s) / l[i][i];
        }
    }
    inv
}

/// The ROS34PW2 kernel on the model's stiff blocks.
#[derive(Debug, Clone, Copy)]
pub(crate) struct RosenbrockWKernel {
    tab: Tableau,
    need_jac: bool,
    singular: bool,
    end_ready: bool,
}

impl Default for RosenbrockWKernel {
    fn default() -> Self {
        Self {
            tab: Tableau::ros34pw2(),
            need_jac: true,
            singular: false,
            end_ready: false,
        }
    }
}

/// `u <- (I/(h γ) − J)⁻¹ u`: every state scaled by h γ, then each block's entries solved
/// through its factors from their values before scaling (`tmp`, `gather`: scratch).
fn solve<S2: OdeSystem + ?Sized>(
    sys: &S2,
    h: f64,
    w: &[f64],
    piv: &[usize],
    u: &mut [f64],
    tmp: &mut [f64],
    gather: &mut [f64],
) {
    let hg = h * GAMMA;
    let (mut at, mut p) = (0, 0);
    for block in sys.stiff_blocks() {
        for (k, &i) in block.iter().enumerate() {
            gather[p + k] = u[i];
        }
        p += block.len();
    }
    for v in u.iter_mut() {
        *v *= hg;
    }
    p = 0;
    for block in sys.stiff_blocks() {
        let nb = block.len();
        let g = &mut gather[p..p + nb];
        lu_solve(&w[at..at + nb * nb], &piv[p..p + nb], nb, g, tmp);
        for (k, &i) in block.iter().enumerate() {
            u[i] = g[k];
        }
        at += nb * nb;
        p += nb;
    }
}

impl Kernel for RosenbrockWKernel {
    const ORDER: i32 = 3;

    fn start<S2: OdeSystem + ?Sized>(&mut self, sys: &S2, t: f64, ws: &mut Workspace) -> usize {
        self.need_jac = true;
        self.end_ready = false;
        blocks::start(sys, t, ws)
    }

    fn attempt<S2: OdeSystem + ?Sized>(
        &mut self,
        sys: &S2,
        t: f64,
        h: f64,
        rtol: f64,
        ws: &mut Workspace,
    ) -> (f64, usize) {
        let mut evals = 0;
        if self.need_jac {
            evals += blocks::jacobians(sys, t, rtol, ws);
            self.need_jac = false;
        }
        self.end_ready = false;
        self.singular = !blocks::factor(sys, h * GAMMA, ws);
        if self.singular {
            return (f64::INFINITY, evals);
        }
        let tab = &self.tab;
        let Workspace {
            y,
            y_new: y1,
            y_stage: ys,
            k,
            aux,
            atol,
            w,
            piv,
            ..
        } = ws;
        let [f0, u0, u1, u2, u3, fs, _] = k;
        let [err, tmp, gather, _] = aux;
        let n = y.len();
        for i in 0..S {
            let mut stages = [&mut *u0, &mut *u1, &mut *u2, &mut *u3];
            let (done, rest) = stages.split_at_mut(i);
            let ui = &mut *rest[0];
            if i == 0 {
                ui.copy_from_slice(f0);
            } else {
                for r in 0..n {
                    let mut s = y[r];
                    for (j, uj) in done.iter().enumerate() {
                        s += tab.a[i][j] * uj[r];
                    }
                    ys[r] = s;
                }
                sys.rhs(t + tab.alpha[i] * h, ys, fs);
                evals += 1;
                for r in 0..n {
                    let mut s = fs[r];
                    for (j, uj) in done.iter().enumerate() {
                        s += tab.c[i][j] / h * uj[r];
                    }
                    ui[r] = s;
                }
            }
            solve(sys, h, w, piv, ui, tmp, gather);
        }
        for r in 0..n {
            let u = [u0[r], u1[r], u2[r], u3[r]];
            y1[r] = y[r] + (0..S).map(|i| tab.m[i] * u[i]).sum::<f64>();
            err[r] = (0..S).map(|i| tab.e[i] * u[i]).sum::<f64>();
        }
        let e = error_norm(err, y, y1, rtol, atol);
        let finite = e.is_finite() && y1.iter().all(|v| v.is_finite());
        (if finite { e } else { f64::INFINITY }, evals)
    }

    fn reject_factor(&self, e: f64) -> f64 {
        if self.singular {
            0.5
        } else {
            rejected_step_factor(e, -1.0 / 3.0, 0.9)
        }
    }

    fn accept_factor(&self, e: f64, last_rejected: bool) -> f64 {
        accepted_step_factor(e, -1.0 / 3.0, last_rejected)
    }

    fn prepare_dense<S2: OdeSystem + ?Sized>(
        &mut self,
        sys: &S2,
        t: f64,
        h: f64,
        ws: &mut Workspace,
    ) -> usize {
        blocks::end_rates(sys, t + h, ws, &mut self.end_ready)
    }

    /// Cubic Hermite interpolation between `(y, k[0])` and `(y_new, k[6])` at `theta`, linear
    /// in the block states (`aux[3]`): there `f` multiplies the step's error by the stiffness,
    /// while the linear form's error is `h² |y''| / 8` of the slow motion the stiff state
    /// follows.
    fn dense(&self, theta: f64, h: f64, ws: &mut Workspace) {
        let Workspace {
            y,
            y_new,
            y_out,
            k,
            aux,
            ..
        } = ws;
        crate::rk4::hermite(theta, h, y, &k[0], y_new, &k[6], y_out);
        for (i, m) in aux[3].iter().enumerate() {
            if *m != 0.0 {
                y_out[i] = (1.0 - theta) * y[i] + theta * y_new[i];
            }
        }
    }

    fn accept<S2: OdeSystem + ?Sized>(
        &mut self,
        sys: &S2,
        t_new: f64,
        ws: &mut Workspace,
    ) -> usize {
        self.need_jac = true;
        blocks::commit(sys, t_new, ws, &mut self.end_ready)
    }
}

#[cfg(test)]
#[allow(clippy::needless_range_loop)] // matrix indices read as the equations
mod tests {
    use super::*;

    /// Rosenbrock order conditions (HW II, Table IV.7.1) in the untransformed coefficients
    /// recovered from the transformed ones: β = α + Γ, for order 3 (b) and 2 (b̂).
    #[test]
    fn order_conditions_hold() {
        let t = Tableau::ros34pw2();
        // back-transform: Γ⁻¹ = diag(1/γ) − c, so Γ = (diag(1/γ) − c)⁻¹; α = a Γ; b = m Γ.
        let mut g_inv = [[0.0; S]; S];
        for i in 0..S {
            for j in 0..S {
                g_inv[i][j] = if i == j { 1.0 / GAMMA } else { -t.c[i][j] };
            }
        }
        let gam = lower_inverse(&g_inv);
        let mul = |x: &[f64; S], col: usize| (0..S).map(|k| x[k] * gam[k][col]).sum::<f64>();
        let b: Vec<f64> = (0..S).map(|i| mul(&t.m, i)).collect();
        let m_hat: [f64; S] = std::array::from_fn(|i| t.m[i] - t.e[i]);
        let b_hat: Vec<f64> = (0..S).map(|i| mul(&m_hat, i)).collect();
        let alpha: Vec<[f64; S]> = (0..S)
            .map(|i| std::array::from_fn(|j| mul(&t.a[i], j)))
            .collect();
        let beta: Vec<[f64; S]> = (0..S)
            .map(|i| std::array::from_fn(|j| if j < i { alpha[i][j] + gam[i][j] } else { 0.0 }))
            .collect();
        let beta_sum: Vec<f64> = beta.iter().map(|r| r.iter().sum()).collect();
        let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
        for w in [&b, &b_hat] {
            assert!(close(w.iter().sum(), 1.0));
            let s2: f64 = (0..S).map(|j| w[j] * beta_sum[j]).sum();
            assert!(close(s2, 0.5 - GAMMA), "{s2}");
        }
        let s3a: f64 = (0..S).map(|j| b[j] * t.alpha[j].powi(2)).sum();
        assert!(close(s3a, 1.0 / 3.0), "{s3a}");
        let s3b: f64 = (0..S)
            .map(|j| b[j] * (0..S).map(|k| beta[j][k] * beta_sum[k]).sum::<f64>())
            .sum();
        assert!(close(s3b, 1.0 / 6.0 - GAMMA + GAMMA * GAMMA), "{s3b}");
        // the embedding is not of order 3: its error estimate is not zero
        let e3: f64 = (0..S).map(|j| b_hat[j] * t.alpha[j].powi(2)).sum();
        assert!((e3 - 1.0 / 3.0).abs() > 1e-3);
        // the stage times: 0, 0.8717, 0.7316, 1
        assert!(close(t.alpha[3], 1.0) && close(t.alpha[1], 0.871_733_043_016_918));
    }

    #[test]
    fn lower_inverse_inverts() {
        let l = [
            [2.0, 0.0, 0.0, 0.0],
            [1.0, 3.0, 0.0, 0.0],
            [-1.0, 0.5, 1.0, 0.0],
            [0.3, 2.0, -4.0, 0.5],
        ];
        let inv = lower_inverse(&l);
        for i in 0..S {
            for j in 0..S {
                let p: f64 = (0..S).map(|k| l[i][k] * inv[k][j]).sum();
                assert!((p - if i == j { 1.0 } else { 0.0 }).abs() < 1e-14);
            }
        }
    }
}
