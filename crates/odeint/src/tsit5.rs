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
//! Workspace use: `k[0..7]` the stages k1..k7, `aux[0]` the error estimate, `y_stage` the
//! sixth stage's argument (at `c_6 = 1`, kept to the end of the step for the stiffness test,
//! [`crate::stiffness`], as with Dormand-Prince). The dense output reads the stages
//! directly, so it needs no preparation: `y(t + θh) = y + h Σ_i b_i(θ) k_i` with the
//! paper's quartic weights `b_i(θ)`, `b_i(1) = b_i`.

use crate::kernel::Kernel;
use crate::stiffness::StiffnessWatch;
use crate::tolerance::error_norm;
use crate::{OdeSystem, Workspace};

pub(crate) const C2: f64 = 0.161;
pub(crate) const C3: f64 = 0.327;
pub(crate) const C4: f64 = 0.9;
pub(crate) const C5: f64 = 0.980_025_540_904_509_685_729_810_286_287;
pub(crate) const A21: f64 = 0.161;
pub(crate) const A31: f64 = -0.008_480_655_492_356_988_544_426_874_250_230_77;
pub(crate) const A32: f64 = 0.335_480_655_492_356_988_544_426_874_250_230_77;
pub(crate) const A41: f64 = 2.897_153_057_105_493_432_130_432_594_192_938_76;
pub(crate) const A42: f64 = -6.359_448_489_975_074_843_148_159_912_383_825_63;
pub(crate) const A43: f64 = 4.362_295_432_869_581_411_017_727_318_190_886_86;
pub(crate) const A51: f64 = 5.325_864_828_439_256_604_428_877_920_840_511_32;
pub(crate) const A52: f64 = -11.748_883_564_062_827_877_747_170_339_785_772_96;
pub(crate) const A53: f64 = 7.495_539_342_889_836_208_304_604_784_564_358_16;
pub(crate) const A54: f64 = -0.092_495_066_361_755_249_256_502_079_332_071_92;
pub(crate) const A61: f64 = 5.861_455_442_946_420_028_659_251_486_982_647_89;
pub(crate) const A62: f64 = -12.920_969_317_847_109_291_706_118_681_783_359_40;
pub(crate) const A63: f64 = 8.159_367_898_576_158_643_180_400_794_539_253_49;
pub(crate) const A64: f64 = -0.071_584_973_281_400_997_224_530_542_525_829_74;
pub(crate) const A65: f64 = -0.028_269_050_394_068_382_909_003_057_212_712_24;
/// `b_1..b_6` of the fifth-order solution (`b_7 = 0`).
pub(crate) const B1: f64 = 0.096_460_766_818_065_229_518_167_313_165_128_76;
pub(crate) const B2: f64 = 0.01;
pub(crate) const B3: f64 = 0.479_889_650_414_499_574_775_249_532_290_596_52;
pub(crate) const B4: f64 = 1.379_008_574_103_741_893_192_274_821_856_872_77;
pub(crate) const B5: f64 = -3.290_069_515_436_080_679_901_047_585_711_363_85;
pub(crate) const B6: f64 = 2.324_710_524_099_773_982_415_355_918_398_765_80;
/// `b̂_i − b_i`: the embedded fourth-order solution minus the fifth-order one, per stage.
pub(crate) const E1: f64 = -1.780_011_052_225_771_443_378_550_607_539_534_78e-3;
pub(crate) const E2: f64 = -8.164_344_596_567_469_032_236_360_633_546_862_40e-4;
pub(crate) const E3: f64 = 7.880_878_010_261_996_010_314_727_672_526_304_24e-3;
pub(crate) const E4: f64 = -0.144_711_007_173_262_907_537_165_147_972_635_117;
pub(crate) const E5: f64 = 0.582_357_165_452_555_225_019_937_610_652_042_179;
pub(crate) const E6: f64 = -0.458_082_105_929_186_946_661_636_518_832_554_297;
pub(crate) const E7: f64 = 1.0 / 66.0;

/// Dense-output weights `b_i(θ) = Σ_j R[i][j] θ^(j+1)` (the paper's continuous extension,
/// expanded), stage by stage.
pub(crate) const R: [[f64; 4]; 7] = [
    [
        1.0,
        -2.763_706_197_274_825_911_336_735_930_481_400_26,
        2.913_255_461_821_912_743_750_680_993_068_08,
        -1.053_088_497_729_021_6,
    ],
    [0.0, 0.131_7, -0.223_4, 0.101_7],
    [
        0.0,
        3.930_296_236_894_751_528_506_874_467_098_133_98,
        -5.941_033_872_131_504_734_702_492_025_894_580_01,
        2.490_627_285_651_252_793,
    ],
    [
        0.0,
        -12.411_077_166_933_676_983_734_381_540_685_453_5,
        30.338_188_630_282_321_598_172_990_369_183_657_6,
        -16.548_102_889_244_902_72,
    ],
    [
        0.0,
        37.509_313_416_511_039_194_969_039_653_345_196_3,
        -88.178_904_894_766_401_101_427_669_354_120_981_7,
        47.379_521_962_819_281_22,
    ],
    [
        0.0,
        -27.896_526_289_197_287_805_948_263_144_598_643_9,
        65.091_894_674_793_671_526_290_219_287_165_536_6,
        -34.870_657_861_496_609_74,
    ],
    [0.0, 1.5, -4.0, 2.5],
];

/// The Tsitouras 5(4) kernel with the stiffness test of [`crate::stiffness`].
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Tsit5Kernel {
    /// Step of the last attempt.
    h: f64,
    /// Stiffness test.
    watch: StiffnessWatch,
}

impl Kernel for Tsit5Kernel {
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
            y1[i] = y[i]
                + h * (B1 * k1[i] + B2 * k2[i] + B3 * k3[i] + B4 * k4[i] + B5 * k5[i] + B6 * k6[i]);
        }
        sys.rhs(t + h, y1, k7);
        for i in 0..n {
            err[i] = h
                * (E1 * k1[i]
                    + E2 * k2[i]
                    + E3 * k3[i]
                    + E4 * k4[i]
                    + E5 * k5[i]
                    + E6 * k6[i]
                    + E7 * k7[i]);
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
        _h: f64,
        _ws: &mut Workspace,
    ) -> usize {
        0
    }

    fn dense(&self, theta: f64, h: f64, ws: &mut Workspace) {
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
