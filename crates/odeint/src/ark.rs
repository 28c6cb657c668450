//! Additive Runge-Kutta ARK4(3)6L\[2\]SA (C. A. Kennedy & M. H. Carpenter, "Additive
//! Runge-Kutta schemes for convection-diffusion-reaction equations", *Appl. Numer. Math.*
//! 44, 2003, 139-181), split by components: explicit in every state outside the model's
//! stiff blocks ([`crate::OdeSystem::stiff_blocks`]), singly diagonally implicit in the
//! block states. Six stages, order 4 with an order-3 embedding; the implicit tableau
//! (ESDIRK, γ = 1/4, first stage explicit) is L-stable and stiffly accurate.
//!
//! The split: `f = f_E + f_I` with `f_I` the block rows of `f` (zero elsewhere) and `f_E`
//! the other rows. The two parts share the weights `b`, `b̂` and the nodes `c`; stage `i`
//! has the derivative `f_i = f(t + c_i h, Y_i)`:
//!
//! ```text
//! Y_1 = y
//! Y_i = y + h Σ_{j<i} aE_ij f_j                    explicit rows
//! Y_i = y + h Σ_{j<i} aI_ij f_j + h γ f(Y_i)       block rows, i = 2..6
//! y_1 = y + h Σ b_i f_i,   err = h Σ (b_i − b̂_i) f_i,   h_new = h clamp(0.9 err^(−1/4), 0.2, 5)
//! ```
//!
//! A stage's block rows are solved by Newton's method with the explicit rows held, block by
//! block, with the model's own block rates ([`crate::OdeSystem::block_rhs`]: a strut's
//! rates at its carrier's travel and rate, no vehicle right-hand side) and the block
//! Jacobian at the step's start ([`crate::blocks`]), refreshed at the current iterate when
//! the iteration stalls and the model gives the block's Jacobian
//! ([`crate::OdeSystem::block_jacobian`]); the block rows of `f_i` are then
//! `(Y_i − y − h Σ_{j<i} aI_ij f_j) / (h γ)`, the value the stage equation gives them. One
//! right-hand side per stage evaluates the explicit rows at the solved stage.
//!
//! The iteration starts from the block rates extrapolated linearly in `c` from the last two
//! stages (the first stage's rates for the second stage), and its convergence test reads
//! the estimated remaining error `θ/(1 − θ) ‖Δ‖` with the contraction rate `θ` of the
//! corrections. The first correction has no rate of its own yet, so it takes the last rate
//! measured (RADAU5's `faccon`, relaxed towards 1 as `faccon^0.8` at each convergence, Hairer
//! & Wanner, *Solving ODEs II*, IV.8). On the loaded D1 ride with the nominal HPS these two
//! cut the block evaluations from 118 910 to 103 950 (the previous stage's rates and a
//! first-correction test of `‖Δ‖ <= 0.3 NEWTON_TOL` before; the rate memory alone
//! gave 110 600).
//!
//! Since the
//! explicit tableau's last row is not `b`, `f(t + h, y_1)` is evaluated as the next step's
//! first stage: an accepted step costs six right-hand sides, a rejected one five, plus the
//! Newton iterations' block evaluations.
//!
//! Dense output: the cubic Hermite interpolant of `y`, `y_1` and their rates (`f(t + h, y_1)`
//! is the next step's first stage, evaluated once for both), in every state; a block state
//! through a stiff start-up within the step takes the quadratic through `y`, the fifth stage
//! and `y_1` instead ([`ArkKernel`]'s `dense`). Kennedy & Carpenter's third-order
//! continuous extension from the stages alone read the strut's states (the block rows) so
//! poorly between the steps of the 3-D vehicle's HPS ride that the cab's accelerations,
//! computed from the interpolated states, were four times further from a tight reference
//! than Dormand-Prince's; the Hermite form brings them within Dormand-Prince's.
//!
//! Workspace use: `k[0..6]` the stage derivatives `f_1..f_6` (`k[0] = f(t, y)`), `k[6]`
//! the Newton iterations' block rates, then `f(t + h, y_1)`; `y_stage` the stage argument;
//! `y_out` the Newton corrections; `aux[0]` the error, `aux[1]` solve scratch, `aux[2]` the
//! block rows' known part `y + h Σ aI_ij f_j`, `aux[3]` the block mask.

use crate::blocks;
use crate::kernel::{accepted_step_factor, rejected_step_factor, Kernel};
use crate::linalg::lu_solve;
use crate::tolerance::error_norm;
use crate::{OdeSystem, Workspace};

/// Stages of ARK4(3)6L\[2\]SA.
const S: usize = 6;

/// The diagonal of the implicit tableau.
const GAMMA: f64 = 0.25;

/// Newton iterations per stage and block before the block's Jacobian is refreshed (or,
/// after [`MAX_REFRESH`] refreshes, the step refused).
const MAX_NEWTON: usize = 7;

/// A Newton iteration converged when its estimated remaining error is below this fraction
/// of the tolerance (the weighted norm of the error estimate is 1 at the tolerance).
const NEWTON_TOL: f64 = 0.03;

/// `θ/(1 − θ)` assumed for the first correction of a run, before any rate was measured:
/// the first correction then has to be below `0.3 NEWTON_TOL`.
const FIRST_FACCON: f64 = 0.3;

/// A Newton iteration whose corrections shrink by less than this factor has stalled.
const STALLED_RATE: f64 = 0.9;

/// Refreshes of a block's Jacobian at the current iterate per stage, when its Newton
/// iteration stalls, before the step is refused (each also damps the corrections after it,
/// [`REFRESH_DAMPING`]). The strut's orifice law makes the block's
/// stiffness change fiftyfold between a moving strut and zero flow (150-700 s⁻¹ against
/// 3·10⁴ s⁻¹), so the Jacobian of the step's start can be far from the stage's: on the
/// loaded D1 ride with the nominal HPS, 2 200 of 2 750 refused steps were such stalls
/// without the refresh; with up to one refresh 24 853 right-hand sides instead of 43 882,
/// with up to three 23 818.
const MAX_REFRESH: usize = 3;

/// Each refresh of a stalled iteration also damps its later corrections by this factor
/// (0.7, 0.49, 0.34 of the Newton step). Near a flow reversal the strut's orifice law is a
/// regularised `sgn(Δp) √|Δp|`, on which the full Newton step from one side lands as far on
/// the other (`x → −x` for the bare root, a rate of 1 whatever the Jacobian), and damping
/// by `λ` makes that `x → (1 − 2λ) x`. On the loaded D1 ride with the nominal HPS: 313 of the
/// 1 113 refused steps were stalls that the refresh alone left, 31 with the damping; the
/// run took 23 370 right-hand sides instead of 25 414 (0.5: 25 019, 0.6: 23 701, 0.8:
/// 23 577, 0.9: 24 603).
const REFRESH_DAMPING: f64 = 0.7;

/// A block state's dense output leaves the cubic Hermite form when its start rate times the
/// step exceeds this multiple of both its change over the step and its end rate times the
/// step (a stiff start-up, [`ArkKernel`]'s `dense`).
const STIFF_START: f64 = 4.0;

/// The two tableaus (their Table "ARK4(3)6L\[2\]SA": ERK and ESDIRK).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Tableau {
    /// Nodes c_i.
    pub(crate) c: [f64; S],
    /// Explicit stage coefficients aE_ij (j < i).
    pub(crate) ae: [[f64; S]; S],
    /// Implicit stage coefficients aI_ij (j <= i, aI_ii = γ for i >= 1).
    pub(crate) ai: [[f64; S]; S],
    /// Weights b_i (both parts).
    pub(crate) b: [f64; S],
    /// Embedded weights b̂_i (both parts).
    pub(crate) b_hat: [f64; S],
}

impl Tableau {
    /// Kennedy & Carpenter's rational coefficients as the nearest `f64`.
    pub(crate) fn ark436l2sa() -> Self {
        let mut ae = [[0.0; S]; S];
        ae[1][0] = 0.5;
        ae[2][..2].copy_from_slice(&[13861.0 / 62500.0, 6889.0 / 62500.0]);
        ae[3][..3].copy_from_slice(&[
            -116_923_316_275.0 / 2_393_684_061_468.0,
            -2_731_218_467_317.0 / 15_368_042_101_831.0,
            9_408_046_702_089.0 / 11_113_171_139_209.0,
        ]);
        ae[4][..4].copy_from_slice(&[
            -451_086_348_788.0 / 2_902_428_689_909.0,
            -2_682_348_792_572.0 / 7_519_795_681_897.0,
            12_662_868_775_082.0 / 11_960_479_115_383.0,
            3_355_817_975_965.0 / 11_060_851_509_271.0,
        ]);
        ae[5][..5].copy_from_slice(&[
            647_845_179_188.0 / 3_216_320_057_751.0,
            73_281_519_250.0 / 8_382_639_484_533.0,
            552_539_513_391.0 / 3_454_668_386_233.0,
            3_354_512_671_639.0 / 8_306_763_924_573.0,
            4040.0 / 17871.0,
        ]);
        let b = [
            82889.0 / 524_892.0,
            0.0,
            15625.0 / 83664.0,
            69875.0 / 102_672.0,
            -2260.0 / 8211.0,
            GAMMA,
        ];
        let mut ai = [[0.0; S]; S];
        ai[1][..2].copy_from_slice(&[GAMMA, GAMMA]);
        ai[2][..3].copy_from_slice(&[8611.0 / 62500.0, -1743.0 / 31250.0, GAMMA]);
        ai[3][..4].copy_from_slice(&[
            5_012_029.0 / 34_652_500.0,
            -654_441.0 / 2_922_500.0,
            174_375.0 / 388_108.0,
            GAMMA,
        ]);
        ai[4][..5].copy_from_slice(&[
            15_267_082_809.0 / 155_376_265_600.0,
            -71_443_401.0 / 120_774_400.0,
            730_878_875.0 / 902_184_768.0,
            2_285_395.0 / 8_070_912.0,
            GAMMA,
        ]);
        ai[5] = b;
        Tableau {
            c: [0.0, 0.5, 83.0 / 250.0, 31.0 / 50.0, 17.0 / 20.0, 1.0],
            ae,
            ai,
            b,
            b_hat: [
                4_586_570_599.0 / 29_645_900_160.0,
                0.0,
                178_811_875.0 / 945_068_544.0,
                814_220_225.0 / 1_159_782_912.0,
                -3_700_637.0 / 11_593_932.0,
                61727.0 / 225_920.0,
            ],
        }
    }
}

/// Why the last attempt failed before its error could be estimated.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Failure {
    None,
    /// An iteration matrix `I/(hγ) − J_b` was singular.
    Singular,
    /// A stage's Newton iteration diverged or did not converge in [`MAX_NEWTON`] steps.
    Newton,
}

/// The ARK4(3)6L\[2\]SA kernel on the model's stiff blocks.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ArkKernel {
    tab: Tableau,
    need_jac: bool,
    failure: Failure,
    /// `f(t + h, y_1)` of the step just taken is in `k[6]` (the dense output needed it).
    end_ready: bool,
    /// `θ/(1 − θ)` of the last measured Newton contraction rate (module docs).
    faccon: f64,
}

impl Default for ArkKernel {
    fn default() -> Self {
        Self {
            tab: Tableau::ark436l2sa(),
            need_jac: true,
            failure: Failure::None,
            end_ready: false,
            faccon: FIRST_FACCON,
        }
    }
}

/// The buffers one stage's Newton iteration works in.
struct Newton<'a> {
    /// Step size times γ.
    hg: f64,
    rtol: f64,
    atol: &'a [f64],
    /// The factored iteration matrices and their pivots, packed ([`blocks::factor`]).
    w: &'a mut [f64],
    piv: &'a mut [usize],
    jac: &'a mut [f64],
    /// The block rows' known part of the stage equation, by state index.
    known: &'a [f64],
    /// Block rates (or the whole right-hand side when the model has no block rates).
    rates: &'a mut [f64],
    /// Corrections.
    delta: &'a mut [f64],
    /// Solve scratch.
    tmp: &'a mut [f64],
    /// `θ/(1 − θ)` of the last measured contraction rate θ (RADAU5's `faccon`).
    faccon: &'a mut f64,
}

impl Newton<'_> {
    /// Block `b`'s Jacobian at the current iterate `(t, ys)` from the model
    /// ([`OdeSystem::block_jacobian`]) and its iteration matrix refactored (`at`, `p`: its
    /// place in the packed matrices and pivots). `false` when the model has no Jacobian of
    /// its own (differencing the whole right-hand side would cost a step's worth) or the
    /// matrix is singular.
    fn refresh<S2: OdeSystem + ?Sized>(
        &mut self,
        sys: &S2,
        t: f64,
        ys: &[f64],
        b: usize,
        (at, p, nb): (usize, usize, usize),
    ) -> bool {
        let jb = &mut self.jac[at..at + nb * nb];
        sys.block_jacobian(t, ys, b, jb)
            && blocks::factor_block(
                jb,
                self.hg,
                &mut self.w[at..at + nb * nb],
                &mut self.piv[p..p + nb],
            )
    }

    /// Solve `Y_b = known_b + hγ f_b(t, Y)` for every block's rows of `ys` in place, the
    /// other rows held. Returns the whole right-hand sides evaluated (none when the model
    /// gives its block rates), `Err` with the same count when an iteration fails.
    fn solve<S2: OdeSystem + ?Sized>(
        &mut self,
        sys: &S2,
        t: f64,
        ys: &mut [f64],
    ) -> Result<usize, usize> {
        let mut evals = 0;
        let (mut at, mut p) = (0, 0);
        for (b, block) in sys.stiff_blocks().iter().enumerate() {
            let nb = block.len();
            let mut previous = f64::INFINITY;
            let mut iteration = 0;
            let mut refreshed = 0;
            let mut damping = 1.0;
            loop {
                let own = sys.block_rhs(t, ys, b, &mut self.rates[..nb]);
                if !own {
                    sys.rhs(t, ys, self.rates);
                    evals += 1;
                }
                // residual / (hγ) = (Y − known)/(hγ) − f(Y); correction −(I/(hγ) − J)⁻¹ of it
                for (c, &r) in block.iter().enumerate() {
                    let f = if own { self.rates[c] } else { self.rates[r] };
                    self.delta[c] = (ys[r] - self.known[r]) / self.hg - f;
                }
                let d = &mut self.delta[..nb];
                lu_solve(
                    &self.w[at..at + nb * nb],
                    &self.piv[p..p + nb],
                    nb,
                    d,
                    self.tmp,
                );
                // the step taken may be damped; the convergence test reads the full Newton
                // correction, the distance still to go
                let mut sum = 0.0;
                for (c, &r) in block.iter().enumerate() {
                    ys[r] -= damping * d[c];
                    let scale = self.atol[r] + self.rtol * ys[r].abs();
                    sum += (d[c] / scale).powi(2);
                }
                let norm = (sum / nb as f64).sqrt();
                if !norm.is_finite() {
                    return Err(evals);
                }
                let rate = norm / previous;
                let converged = if iteration == 0 {
                    *self.faccon * norm <= NEWTON_TOL
                } else {
                    if rate < STALLED_RATE {
                        *self.faccon = rate / (1.0 - rate);
                    }
                    rate < STALLED_RATE && rate / (1.0 - rate) * norm <= NEWTON_TOL
                };
                if converged {
                    *self.faccon = self.faccon.max(f64::EPSILON).powf(0.8);
                    break;
                }
                if iteration > 0 && rate >= STALLED_RATE || iteration + 1 == MAX_NEWTON {
                    if refreshed == MAX_REFRESH || !self.refresh(sys, t, ys, b, (at, p, nb)) {
                        return Err(evals);
                    }
                    refreshed += 1;
                    damping *= REFRESH_DAMPING;
                    iteration = 0;
                    previous = f64::INFINITY;
                    continue;
                }
                previous = norm;
                iteration += 1;
            }
            at += nb * nb;
            p += nb;
        }
        Ok(evals)
    }
}

/// The block rows of the error estimate passed through `(I − hγ J_b)⁻¹` (Hairer & Wanner,
/// *Solving ODEs II*, IV.8, the filtered estimate of RADAU5 and of SDIRK codes): a stiff
/// state's raw estimate carries its fast rates, which the stiff dynamics damp within the
/// step, and would hold the step to the explicit stability bound; the filter leaves the
/// estimate of slow motion (`h |λ| << 1`) as it is. `scratch`, `tmp`: block-length scratch.
fn filter_block_errors<S2: OdeSystem + ?Sized>(
    sys: &S2,
    hg: f64,
    w: &[f64],
    piv: &[usize],
    err: &mut [f64],
    scratch: &mut [f64],
    tmp: &mut [f64],
) {
    let (mut at, mut p) = (0, 0);
    for block in sys.stiff_blocks() {
        let nb = block.len();
        let x = &mut scratch[..nb];
        for (c, &r) in block.iter().enumerate() {
            x[c] = err[r] / hg;
        }
        lu_solve(&w[at..at + nb * nb], &piv[p..p + nb], nb, x, tmp);
        for (c, &r) in block.iter().enumerate() {
            err[r] = x[c];
        }
        at += nb * nb;
        p += nb;
    }
}

impl Kernel for ArkKernel {
    const ORDER: i32 = 4;

    fn start<S2: OdeSystem + ?Sized>(&mut self, sys: &S2, t: f64, ws: &mut Workspace) -> usize {
        self.need_jac = true;
        self.end_ready = false;
        blocks::start(sys, t, ws)
    }

    #[allow(clippy::needless_range_loop)] // stage indices read as the equations
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
        self.failure = Failure::None;
        self.end_ready = false;
        let hg = h * GAMMA;
        if !blocks::factor(sys, hg, ws) {
            self.failure = Failure::Singular;
            return (f64::INFINITY, evals);
        }
        let tab = &self.tab;
        let Workspace {
            y,
            y_new,
            y_stage: ys,
            y_out: delta,
            k,
            aux,
            atol,
            w,
            piv,
            jac,
            ..
        } = ws;
        let [err, tmp, known, _] = aux;
        let (stages, scratch) = k.split_at_mut(S);
        let n = y.len();
        for i in 1..S {
            let (done, current) = stages.split_at_mut(i);
            // every row with the explicit tableau, `y + h Σ_j aE_ij f_j` (summed over `j` in
            // order, row by row as one pass per stage); the block rows are redone below
            for (j, fj) in done.iter().enumerate() {
                let a = tab.ae[i][j];
                if j == 0 {
                    ys.iter_mut().zip(fj).for_each(|(s, f)| *s = a * f);
                } else {
                    ys.iter_mut().zip(fj).for_each(|(s, f)| *s += a * f);
                }
            }
            ys.iter_mut()
                .zip(y.iter())
                .for_each(|(s, y)| *s = y + h * *s);
            // the block rows: their known part `y + h Σ_j aI_ij f_j`, and the predictor: the
            // stage's rates extrapolated linearly in `c` from the last two stages' (the
            // first stage's rates for the second stage)
            for &r in sys.stiff_blocks().iter().flatten() {
                let mut s = 0.0;
                for j in 0..i {
                    s += tab.ai[i][j] * done[j][r];
                }
                known[r] = y[r] + h * s;
                let rate = if i >= 2 {
                    let (c0, c1) = (tab.c[i - 2], tab.c[i - 1]);
                    let w = (tab.c[i] - c1) / (c1 - c0);
                    done[i - 1][r] + w * (done[i - 1][r] - done[i - 2][r])
                } else {
                    done[0][r]
                };
                ys[r] = known[r] + hg * rate;
            }
            let ti = t + tab.c[i] * h;
            let mut newton = Newton {
                hg,
                rtol,
                atol,
                w: &mut w[..],
                piv: &mut piv[..],
                jac: &mut jac[..],
                known,
                rates: &mut scratch[0],
                delta,
                tmp,
                faccon: &mut self.faccon,
            };
            match newton.solve(sys, ti, ys) {
                Ok(e) => evals += e,
                Err(e) => {
                    self.failure = Failure::Newton;
                    return (f64::INFINITY, evals + e);
                }
            }
            let fi = &mut current[0];
            sys.rhs(ti, ys, fi);
            evals += 1;
            for &r in sys.stiff_blocks().iter().flatten() {
                fi[r] = (ys[r] - known[r]) / hg;
            }
        }
        for r in 0..n {
            let (mut s, mut e) = (0.0, 0.0);
            for i in 0..S {
                s += tab.b[i] * stages[i][r];
                e += (tab.b[i] - tab.b_hat[i]) * stages[i][r];
            }
            y_new[r] = y[r] + h * s;
            err[r] = h * e;
        }
        filter_block_errors(sys, hg, w, piv, err, delta, tmp);
        let e = error_norm(err, y, y_new, rtol, atol);
        let finite = e.is_finite() && y_new.iter().all(|v| v.is_finite());
        (if finite { e } else { f64::INFINITY }, evals)
    }

    fn reject_factor(&self, e: f64) -> f64 {
        match self.failure {
            Failure::Singular => 0.5,
            Failure::Newton => 0.25,
            Failure::None => rejected_step_factor(e, -0.25, 0.9),
        }
    }

    fn accept_factor(&self, e: f64, last_rejected: bool) -> f64 {
        accepted_step_factor(e, -0.25, last_rejected)
    }

    /// `f(t + h, y_1)` into `k[6]`: the dense output's end rates, and the next step's
    /// first stage ([`Kernel::accept`] takes it from there).
    fn prepare_dense<S2: OdeSystem + ?Sized>(
        &mut self,
        sys: &S2,
        t: f64,
        h: f64,
        ws: &mut Workspace,
    ) -> usize {
        blocks::end_rates(sys, t + h, ws, &mut self.end_ready)
    }

    /// The cubic Hermite interpolant of the step's end values and rates (`rk4::hermite`,
    /// as RK4 and ROS34PW2), `f(t, y)` and `f_1 = f(t + h, y_1)`: order 3 in every state.
    ///
    /// A block state through a stiff start-up within the step (its rate at the start more
    /// than [`STIFF_START`] times both its change over the step and its end rate, in steps)
    /// takes the quadratic through `y`, the fifth stage `Y_5` and `y_1` instead: the start
    /// rate of a fast transient the step has damped would swing the cubic far outside
    /// `[y, y_1]`. The fifth stage (c = 17/20, stage order 2,
    /// `Y_5 = y + h Σ_{j<=5} aI_5j f_j`) keeps −0.157 of such a start-up on `y' = λ y`,
    /// `h λ → −∞`, as little as a linear interpolant keeps at θ = 0.85.
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
        let c5 = self.tab.c[4];
        let l = [
            (theta - c5) * (theta - 1.0) / c5,
            theta * (theta - 1.0) / (c5 * (c5 - 1.0)),
            theta * (theta - c5) / (1.0 - c5),
        ];
        for (r, m) in aux[3].iter().enumerate() {
            let (f0, f1) = (h * k[0][r], h * k[6][r]);
            let change = y_new[r] - y[r];
            if *m != 0.0 && f0.abs() > STIFF_START * change.abs().max(f1.abs()) {
                let y5 = y[r] + h * (0..5).map(|j| self.tab.ai[4][j] * k[j][r]).sum::<f64>();
                y_out[r] = l[0] * y[r] + l[1] * y5 + l[2] * y_new[r];
            }
        }
    }

    /// `f(t + h, y_1)`, the next step's first stage: the dense output's end rates when it
    /// evaluated them.
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

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-12
    }

    /// `Σ_i w_i Π` over the elementary weights of the trees up to order 4, each part alone
    /// and mixed: `x` and `y` are the stage matrices of the two levels of a tree.
    fn tree_sums(w: &[f64; S], x: &[[f64; S]; S], y: &[[f64; S]; S], c: &[f64; S]) -> [f64; 8] {
        let xc = |i: usize| (0..S).map(|j| x[i][j] * c[j]).sum::<f64>();
        let xc2 = |i: usize| (0..S).map(|j| x[i][j] * c[j] * c[j]).sum::<f64>();
        let xyc = |i: usize| {
            (0..S)
                .map(|j| x[i][j] * (0..S).map(|k| y[j][k] * c[k]).sum::<f64>())
                .sum::<f64>()
        };
        let sum = |f: &dyn Fn(usize) -> f64| (0..S).map(|i| w[i] * f(i)).sum::<f64>();
        [
            sum(&|_| 1.0),
            sum(&|i| c[i]),
            sum(&|i| c[i] * c[i]),
            sum(&xc),
            sum(&|i| c[i].powi(3)),
            sum(&|i| c[i] * xc(i)),
            sum(&xc2),
            sum(&xyc),
        ]
    }

    const EXACT: [f64; 8] = [
        1.0,
        0.5,
        1.0 / 3.0,
        1.0 / 6.0,
        0.25,
        1.0 / 8.0,
        1.0 / 12.0,
        1.0 / 24.0,
    ];

    /// Both tableaus share the nodes (row sums); the weights satisfy the eight order-4
    /// conditions for each part alone and the coupling conditions of the mixed trees; the
    /// embedding those of order 3 and not all of order 4; the implicit part is stiffly
    /// accurate with γ on its diagonal.
    #[test]
    fn order_conditions_hold() {
        let t = Tableau::ark436l2sa();
        for i in 0..S {
            assert!(close(t.ae[i].iter().sum(), t.c[i]), "explicit row {i}");
            assert!(close(t.ai[i].iter().sum(), t.c[i]), "implicit row {i}");
            for j in i..S {
                assert_eq!(t.ae[i][j], 0.0);
            }
            if i > 0 {
                assert_eq!(t.ai[i][i], GAMMA);
            }
        }
        assert_eq!(t.ai[S - 1], t.b);
        for (x, y) in [
            (&t.ae, &t.ae),
            (&t.ai, &t.ai),
            (&t.ae, &t.ai),
            (&t.ai, &t.ae),
        ] {
            let s = tree_sums(&t.b, x, y, &t.c);
            for (k, (got, want)) in s.iter().zip(EXACT).enumerate() {
                assert!(close(*got, want), "tree {k}: {got} against {want}");
            }
            let s_hat = tree_sums(&t.b_hat, x, y, &t.c);
            for k in 0..4 {
                assert!(close(s_hat[k], EXACT[k]), "embedded tree {k}");
            }
        }
        let s_hat = tree_sums(&t.b_hat, &t.ae, &t.ae, &t.c);
        let off: f64 = (4..8).map(|k| (s_hat[k] - EXACT[k]).abs()).sum();
        assert!(off > 1e-4, "the embedding is of order 3 only: {off}");
    }

    /// On `y' = λ y` with `h λ → −∞` the implicit stages keep `R_i(∞) y`: the last is 0
    /// (L-stable, stiffly accurate), the fifth −0.157 (what the dense output of a block
    /// state keeps of a stiff start-up), the second −1 (a trapezoidal stage, left out of
    /// the dense output).
    #[test]
    fn stiff_limits_of_the_stages() {
        let t = Tableau::ark436l2sa();
        let z = -1e12;
        let mut y = [1.0; S];
        for i in 1..S {
            let s: f64 = (0..i).map(|j| t.ai[i][j] * y[j]).sum();
            y[i] = (1.0 + z * s) / (1.0 - z * GAMMA);
        }
        assert!(y[S - 1].abs() < 1e-9, "{y:?}");
        assert!((y[4] + 0.1565).abs() < 1e-3, "{y:?}");
        assert!((y[1] + 1.0).abs() < 1e-9, "{y:?}");
    }
}
