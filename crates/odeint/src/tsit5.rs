//! Tsitouras 5(4) step with error estimate and 4th-order dense output (Ch. Tsitouras,
//! "Runge-Kutta pairs of order 5(4) satisfying only the first column simplifying
//! assumption", Comput. Math. Appl. 62 (2011) 770-775, Table 1 and the continuous
//! extension of its section 4).
//!
//! Seven stages, FSAL like Dormand-Prince: the propagated solution is the seventh stage's
//! argument (`b_i = a_7i`, `b_7 = 0`), so `k7 = f(t + h, y_new)` is the next step's `k1`.
//! Dormand-Prince's coefficients satisfy `Σ_j a_ij c_j = c_i²/2` for `i ≥ 3` (with
//! `b_2 = 0`); Tsitouras's do not (off by up to 1.3·10⁻² for `i = 2..6`, `b_2 = 0.01`),
//! which frees parameters to make the sixth-order error coefficients smaller: `‖τ⁽⁶⁾‖₂` = 1.39·10⁻⁴ against 3.99·10⁻⁴ for Dormand-Prince, while the embedded
//! fourth-order solution's `‖τ̂⁽⁵⁾‖₂` (what the error estimate sees) is about the same,
//! 1.06·10⁻³ against 1.18·10⁻³ (computed from the coefficients in 40-digit arithmetic;
//! docs/numerics.md, "Tsitouras 5(4)").
//!
//! The step, its error estimate and the step-size factors are the
//! shared seven-stage FSAL kernel's ([`crate::explicit_rk`], as for Dormand-Prince); this
//! module gives the tableau and the dense output, which reads the stages directly, so it
//! needs no preparation: `y(t + θh) = y + h Σ_i b_i(θ) k_i` with the paper's quartic
//! weights `b_i(θ)`, `b_i(1) = b_i`.

use crate::explicit_rk::{FsalKernel, Pair};
use crate::Workspace;

pub(crate) const C2: f64 = 0.161;
pub(crate) const C3: f64 = 0.327;
pub(crate) const C4: f64 = 0.9;
pub(crate) const C5: f64 = 0.9800255409045097;
pub(crate) const A21: f64 = 0.161;
pub(crate) const A31: f64 = -0.008480655492356989;
pub(crate) const A32: f64 = 0.335480655492357;
pub(crate) const A41: f64 = 2.8971530571054935;
pub(crate) const A42: f64 = -6.359448489975075;
pub(crate) const A43: f64 = 4.3622954328695815;
pub(crate) const A51: f64 = 5.325864828439257;
pub(crate) const A52: f64 = -11.748883564062828;
pub(crate) const A53: f64 = 7.4955393428898365;
pub(crate) const A54: f64 = -0.09249506636175525;
pub(crate) const A61: f64 = 5.86145544294642;
pub(crate) const A62: f64 = -12.92096931784711;
pub(crate) const A63: f64 = 8.159367898576159;
pub(crate) const A64: f64 = -0.071584973281401;
pub(crate) const A65: f64 = -0.028269050394068383;
/// `b_1..b_6` of the fifth-order solution (`b_7 = 0`).
pub(crate) const B1: f64 = 0.09646076681806523;
pub(crate) const B2: f64 = 0.01;
pub(crate) const B3: f64 = 0.4798896504144996;
pub(crate) const B4: f64 = 1.379008574103742;
pub(crate) const B5: f64 = -3.290069515436081;
pub(crate) const B6: f64 = 2.324710524099774;
/// `b̂_i − b_i`: the embedded fourth-order solution minus the fifth-order one, per stage.
pub(crate) const E1: f64 = -0.0017800110522257714;
pub(crate) const E2: f64 = -0.0008164344596567469;
pub(crate) const E3: f64 = 0.007880878010261995;
pub(crate) const E4: f64 = -0.1447110071732629;
pub(crate) const E5: f64 = 0.5823571654525552;
pub(crate) const E6: f64 = -0.45808210592918697;
pub(crate) const E7: f64 = 1.0 / 66.0;

/// Dense-output weights `b_i(θ) = Σ_j R[i][j] θ^(j+1)` (the paper's continuous extension,
/// expanded), stage by stage.
pub(crate) const R: [[f64; 4]; 7] = [
    [
        1.0,
        -2.763706197274826,
        2.9132554618219126,
        -1.053_088_497_729_021_6,
    ],
    [0.0, 0.131_7, -0.223_4, 0.101_7],
    [
        0.0,
        3.9302962368947516,
        -5.941033872131505,
        2.490627285651253,
    ],
    [
        0.0,
        -12.411077166933676,
        30.33818863028232,
        -16.548102889244902,
    ],
    [0.0, 37.50931341651104, -88.1789048947664, 47.37952196281928],
    [
        0.0,
        -27.896526289197286,
        65.09189467479366,
        -34.87065786149661,
    ],
    [0.0, 1.5, -4.0, 2.5],
];

/// Tsitouras's tableau and dense output.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Tsitouras;

/// The Tsitouras 5(4) kernel.
pub(crate) type Tsit5Kernel = FsalKernel<Tsitouras>;

impl Pair for Tsitouras {
    const C: [f64; 4] = [C2, C3, C4, C5];
    const A2: f64 = A21;
    const A3: [f64; 2] = [A31, A32];
    const A4: [f64; 3] = [A41, A42, A43];
    const A5: [f64; 4] = [A51, A52, A53, A54];
    const A6: [f64; 5] = [A61, A62, A63, A64, A65];
    const B: [f64; 6] = [B1, B2, B3, B4, B5, B6];
    const E: [f64; 7] = [E1, E2, E3, E4, E5, E6, E7];

    fn prepare_dense(_h: f64, _ws: &mut Workspace) -> usize {
        0
    }

    fn dense(theta: f64, h: f64, ws: &mut Workspace) {
        let Workspace { y, y_out, k, .. } = ws;
        let mut w = [0.0; 7];
        for (wi, r) in w.iter_mut().zip(&R) {
            *wi = h * theta * (r[0] + theta * (r[1] + theta * (r[2] + theta * r[3])));
        }
        let [k1, k2, k3, k4, k5, k6, k7] = k;
        for i in 0..y.len() {
            y_out[i] = y[i]
                + (w[0] * k1[i]
                    + w[1] * k2[i]
                    + w[2] * k3[i]
                    + w[3] * k4[i]
                    + w[4] * k5[i]
                    + w[5] * k6[i]
                    + w[6] * k7[i]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Butcher tableau `(A, b, b̂)` of the pair, stage `i` in row `i`.
    fn tableau() -> ([[f64; 7]; 7], [f64; 7], [f64; 7]) {
        let mut a = [[0.0; 7]; 7];
        a[1][0] = A21;
        a[2][..2].copy_from_slice(&[A31, A32]);
        a[3][..3].copy_from_slice(&[A41, A42, A43]);
        a[4][..4].copy_from_slice(&[A51, A52, A53, A54]);
        a[5][..5].copy_from_slice(&[A61, A62, A63, A64, A65]);
        let b = [B1, B2, B3, B4, B5, B6, 0.0];
        a[6] = b;
        let e = [E1, E2, E3, E4, E5, E6, E7];
        let mut bh = [0.0; 7];
        for i in 0..7 {
            bh[i] = b[i] + e[i];
        }
        (a, b, bh)
    }

    fn mul(u: [f64; 7], v: [f64; 7]) -> [f64; 7] {
        std::array::from_fn(|i| u[i] * v[i])
    }

    fn apply(a: &[[f64; 7]; 7], v: [f64; 7]) -> [f64; 7] {
        std::array::from_fn(|i| (0..7).map(|j| a[i][j] * v[j]).sum())
    }

    fn dot(u: [f64; 7], v: [f64; 7]) -> f64 {
        (0..7).map(|i| u[i] * v[i]).sum()
    }

    /// The elementary weights' vectors `Φ(τ)` of the 17 rooted trees of order 1 to 5 with
    /// their `1/γ(τ)` (HNW I, Table II.2.2), from `A` and `c = A 1`.
    fn trees(a: &[[f64; 7]; 7]) -> Vec<(usize, [f64; 7], f64)> {
        let one = [1.0; 7];
        let c = apply(a, one);
        let c2 = mul(c, c);
        let c3 = mul(c2, c);
        let ac = apply(a, c);
        let ac2 = apply(a, c2);
        let aac = apply(a, ac);
        vec![
            (1, one, 1.0),
            (2, c, 1.0 / 2.0),
            (3, c2, 1.0 / 3.0),
            (3, ac, 1.0 / 6.0),
            (4, c3, 1.0 / 4.0),
            (4, mul(c, ac), 1.0 / 8.0),
            (4, ac2, 1.0 / 12.0),
            (4, aac, 1.0 / 24.0),
            (5, mul(c3, c), 1.0 / 5.0),
            (5, mul(c2, ac), 1.0 / 10.0),
            (5, mul(ac, ac), 1.0 / 20.0),
            (5, mul(c, ac2), 1.0 / 15.0),
            (5, mul(c, aac), 1.0 / 30.0),
            (5, apply(a, c3), 1.0 / 20.0),
            (5, apply(a, mul(c, ac)), 1.0 / 40.0),
            (5, apply(a, ac2), 1.0 / 60.0),
            (5, apply(a, aac), 1.0 / 120.0),
        ]
    }

    #[test]
    fn the_nodes_are_the_row_sums() {
        let (a, ..) = tableau();
        let c = [0.0, C2, C3, C4, C5, 1.0, 1.0];
        for i in 0..7 {
            let s: f64 = a[i].iter().sum();
            assert!((s - c[i]).abs() < 1e-14, "row {i}: {s} against {}", c[i]);
        }
    }

    #[test]
    fn order_conditions_hold_to_order_5_and_4_embedded() {
        let (a, b, bh) = tableau();
        let trees = trees(&a);
        assert_eq!(trees.len(), 17);
        for (k, (order, phi, inv_gamma)) in trees.iter().enumerate() {
            let r = dot(b, *phi) - inv_gamma;
            assert!(
                r.abs() < 1e-12,
                "tree {k} (order {order}): b residual {r:e}"
            );
            let rh = dot(bh, *phi) - inv_gamma;
            if *order <= 4 {
                assert!(
                    rh.abs() < 1e-12,
                    "tree {k} (order {order}): b̂ residual {rh:e}"
                );
            }
        }
        // the embedded solution is of order 4 only: some fifth-order condition fails
        let worst = trees
            .iter()
            .filter(|t| t.0 == 5)
            .map(|(_, phi, g)| (dot(bh, *phi) - g).abs())
            .fold(0.0, f64::max);
        assert!(worst > 1e-5, "b̂ is of order 5? {worst:e}");
    }

    #[test]
    fn dense_weights_give_order_4_at_every_theta_and_the_step_at_theta_1() {
        let (a, b, _) = tableau();
        let trees = trees(&a);
        for j in 0..=20 {
            let theta = j as f64 / 20.0;
            let w: [f64; 7] = std::array::from_fn(|i| {
                let r = R[i];
                theta * (r[0] + theta * (r[1] + theta * (r[2] + theta * r[3])))
            });
            for (k, (order, phi, inv_gamma)) in trees.iter().enumerate().filter(|t| t.1 .0 <= 4) {
                let want = theta.powi(*order as i32) * inv_gamma;
                let r = dot(w, *phi) - want;
                assert!(r.abs() < 1e-12, "θ = {theta}, tree {k}: residual {r:e}");
            }
            if j == 20 {
                for i in 0..7 {
                    assert!((w[i] - b[i]).abs() < 1e-12, "b_{}(1) = {}", i + 1, w[i]);
                }
            }
        }
    }
}
