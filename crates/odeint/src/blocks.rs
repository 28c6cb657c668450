//! The model's stiff diagonal blocks ([`crate::OdeSystem::stiff_blocks`]) as the implicit
//! kernels use them: their Jacobians packed one after the other, the iteration matrices
//! `I/(h γ) − J_b` factored block by block, and the mask of block states. Shared by the
//! Rosenbrock-W method ([`crate::Solver::Ros34pw2`]) and the additive Runge-Kutta method
//! ([`crate::Solver::Ark436`]).
//!
//! Both end a step at `y_1` with the cubic Hermite dense output, whose end rates
//! `f(t + h, y_1)` are the next step's first stage: [`start`], [`end_rates`] and [`commit`]
//! evaluate them once for both.
//!
//! Workspace use: `jac` the packed block Jacobians, `w` their factored iteration matrices,
//! `piv` their pivots (packed), `aux[3]` the mask (1 on a block state, else 0), `k[0]` the
//! step's first stage `f(t, y)`, `k[6]` the end rates.

use crate::linalg::lu_factor;
use crate::{OdeSystem, Workspace};

/// Each block's Jacobian at `(t, ws.y)`, packed row-major one after the other into
/// `ws.jac`: the model's own ([`OdeSystem::block_jacobian`]) or forward differences of the
/// whole right-hand side over the block's states, from `ws.k[0] = f(t, y)` (scratch
/// `ws.y_stage`, `ws.k[6]`). Returns RHS calls.
pub(crate) fn jacobians<S: OdeSystem + ?Sized>(
    sys: &S,
    t: f64,
    rtol: f64,
    ws: &mut Workspace,
) -> usize {
    let Workspace {
        y,
        y_stage: ys,
        k,
        atol,
        jac,
        ..
    } = ws;
    let [f0, .., f1] = k;
    let mut at = 0;
    let mut evals = 0;
    for (b, block) in sys.stiff_blocks().iter().enumerate() {
        let nb = block.len();
        let jb = &mut jac[at..at + nb * nb];
        at += nb * nb;
        if sys.block_jacobian(t, y, b, jb) {
            continue;
        }
        for (c, &j) in block.iter().enumerate() {
            let yj = y[j];
            let dy = f64::EPSILON.sqrt() * yj.abs().max(atol[j] / rtol).max(1e-8);
            ys.copy_from_slice(y);
            ys[j] = yj + dy;
            sys.rhs(t, ys, f1);
            evals += 1;
            for (r, &i) in block.iter().enumerate() {
                jb[r * nb + c] = (f1[i] - f0[i]) / dy;
            }
        }
    }
    evals
}

/// Factor `I/hg − J_b` of every block into `ws.w` (pivots packed in `ws.piv`), `hg` the
/// step times the method's diagonal coefficient; `false` if one is singular.
pub(crate) fn factor<S: OdeSystem + ?Sized>(sys: &S, hg: f64, ws: &mut Workspace) -> bool {
    let (mut at, mut p) = (0, 0);
    for block in sys.stiff_blocks() {
        let nb = block.len();
        let (jb, wb) = (&ws.jac[at..at + nb * nb], &mut ws.w[at..at + nb * nb]);
        if !factor_block(jb, hg, wb, &mut ws.piv[p..p + nb]) {
            return false;
        }
        at += nb * nb;
        p += nb;
    }
    true
}

/// Factor `I/hg − J_b` of one block (`jb` its Jacobian, row-major, `piv.len()` states) into
/// `wb` and `piv`; `false` if singular.
pub(crate) fn factor_block(jb: &[f64], hg: f64, wb: &mut [f64], piv: &mut [usize]) -> bool {
    let nb = piv.len();
    let inv = 1.0 / hg;
    for r in 0..nb {
        for c in 0..nb {
            wb[r * nb + c] = if r == c { inv } else { 0.0 } - jb[r * nb + c];
        }
    }
    lu_factor(wb, piv, nb)
}

/// Mark the block states in `ws.aux[3]` (1 on a block state, 0 elsewhere).
pub(crate) fn mark<S: OdeSystem + ?Sized>(sys: &S, ws: &mut Workspace) {
    let mask = &mut ws.aux[3];
    mask.fill(0.0);
    for &i in sys.stiff_blocks().iter().flatten() {
        mask[i] = 1.0;
    }
}

/// (Re)start at `(t, ws.y)`: mark the block states and evaluate the first stage
/// `ws.k[0] = f(t, y)`. Returns RHS calls.
pub(crate) fn start<S: OdeSystem + ?Sized>(sys: &S, t: f64, ws: &mut Workspace) -> usize {
    mark(sys, ws);
    sys.rhs(t, &ws.y, &mut ws.k[0]);
    1
}

/// The end rates `f(t_end, y_1)` of the step just taken into `ws.k[6]`, once per step
/// (`ready` says they are there). Returns RHS calls.
pub(crate) fn end_rates<S: OdeSystem + ?Sized>(
    sys: &S,
    t_end: f64,
    ws: &mut Workspace,
    ready: &mut bool,
) -> usize {
    if *ready {
        return 0;
    }
    sys.rhs(t_end, &ws.y_new, &mut ws.k[6]);
    *ready = true;
    1
}

/// Commit the step (`ws.y <- ws.y_new`) and set the next step's first stage
/// `ws.k[0] = f(t_new, y)`: the end rates when [`end_rates`] left them (`ready`, cleared),
/// else evaluated. Returns RHS calls.
pub(crate) fn commit<S: OdeSystem + ?Sized>(
    sys: &S,
    t_new: f64,
    ws: &mut Workspace,
    ready: &mut bool,
) -> usize {
    ws.y.copy_from_slice(&ws.y_new);
    let [f0, .., f_end] = &mut ws.k;
    if std::mem::take(ready) {
        f0.copy_from_slice(f_end);
        0
    } else {
        sys.rhs(t_new, &ws.y, f0);
        1
    }
}
