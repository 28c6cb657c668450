//! Invariants of the handling models (issue: "Tests of the handling model").

use proptest::prelude::*;
use tire_fiala::{
    ExponentialCornering, Fiala, HandlingModel, LinearCornering, TireForces, TireParams,
    TractionDependentCornering,
};

const DEG: f64 = std::f64::consts::PI / 180.0;

fn tire(c_alpha: f64, c_slip: f64, u_max: f64, u_min: f64, width: f64) -> Fiala {
    let mut p = TireParams::nominal();
    p.cornering_stiffness_table.clear();
    p.cornering_stiffness_n_per_rad = c_alpha;
    p.longitudinal_stiffness_n = c_slip;
    p.u_max = u_max;
    p.u_min = u_min;
    p.width_m = width;
    Fiala::new(&p).unwrap()
}

#[test]
fn small_slip_slopes_equal_the_stiffnesses() {
    let t = tire(4.0e5, 1.0e6, 0.8, 0.6, 0.7);
    let fz = 1.2e5;
    let e = 1e-7;
    let cy = (t.forces(fz, 0.0, e).fy - t.forces(fz, 0.0, -e).fy) / (2.0 * e);
    let cx = (t.forces(fz, e, 0.0).fx - t.forces(fz, -e, 0.0).fx) / (2.0 * e);
    assert!((cy - 4.0e5).abs() / 4.0e5 < 1e-5, "{cy}");
    assert!((cx - 1.0e6).abs() / 1.0e6 < 1e-9, "{cx}");
    // Aligning stiffness: M_z ≈ (2/3) R2 C_alpha alpha (pneumatic trail R2/3 at the origin).
    let cm = t.forces(fz, 0.0, e).mz / e;
    let expect = 2.0 / 3.0 * 0.35 * 4.0e5;
    assert!((cm - expect).abs() / expect < 1e-5, "{cm} vs {expect}");
}

#[test]
fn forces_are_continuous_at_their_critical_slips() {
    let t = tire(4.0e5, 1.0e6, 0.8, 0.6, 0.7);
    let fz = 1.0e5;
    // Lateral: find the critical angle at kappa = 0, probe either side.
    let ac = t.critical_slip_angle(fz, 0.0, 0.3);
    // U depends on alpha, so iterate the fixed point of alpha_c = atan(3 U(alpha_c) F_z / C).
    let mut a = ac;
    for _ in 0..200 {
        a = t.critical_slip_angle(fz, 0.0, a);
    }
    let h = 1e-9;
    let below = t.forces(fz, 0.0, a - h);
    let above = t.forces(fz, 0.0, a + h);
    assert!((below.fy - above.fy).abs() < 1e-3, "{below:?} {above:?}");
    assert!((below.mz - above.mz).abs() < 1e-3);
    assert_eq!(above.mz, 0.0);
    // Longitudinal: kappa_c = U F_z / (2 C_slip) with U = U(kappa_c).
    let mut k = 0.04;
    for _ in 0..200 {
        k = t.critical_slip_ratio(fz, k, 0.0);
    }
    let below = t.forces(fz, k - h, 0.0).fx;
    let above = t.forces(fz, k + h, 0.0).fx;
    assert!((below - above).abs() < 1e-2, "{below} {above}");
}

#[test]
fn sliding_and_zero_slip_limits() {
    let t = tire(4.0e5, 1.0e6, 0.8, 0.6, 0.7);
    let fz = 1.0e5;
    let f0 = t.forces(fz, 0.0, 0.0);
    assert_eq!((f0.fx, f0.fy, f0.mz), (0.0, 0.0, 0.0));
    // 60 deg: S = 1, U = U_min, full sliding.
    let f = t.forces(fz, 0.0, 60.0 * DEG);
    assert!((f.fy - 0.6 * fz).abs() < 1e-9);
    assert_eq!(f.mz, 0.0);
    // 90 deg and beyond (clamped) stay finite and sliding.
    for a in [90.0 * DEG, -90.0 * DEG, 3.0, -3.0] {
        let f = t.forces(fz, 1.0, a);
        assert!(f.fy.is_finite() && f.fx.is_finite());
        assert!((f.fy.abs() - 0.6 * fz).abs() < 1e-6);
    }
    assert_eq!(t.forces(0.0, 0.5, 0.5), TireForces::ZERO);
    assert_eq!(t.forces(-1.0, 0.5, 0.5), TireForces::ZERO);
}

fn arb_tire() -> impl Strategy<Value = Fiala> {
    (
        1e3..1e7f64,
        1e3..1e8f64,
        0.05..1.5f64,
        0.0..1.0f64,
        0.05..2.0f64,
    )
        .prop_map(|(ca, cs, umax, frac, w)| tire(ca, cs, umax, umax * (0.05 + 0.95 * frac), w))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn bounded_finite_and_odd(
        t in arb_tire(),
        fz in -1e6..1e7f64,
        kappa in -1.0..1.0f64,
        alpha in -std::f64::consts::FRAC_PI_2..std::f64::consts::FRAC_PI_2,
    ) {
        let f = t.forces(fz, kappa, alpha);
        prop_assert!(f.fx.is_finite() && f.fy.is_finite() && f.mz.is_finite() && f.my.is_finite());
        if fz <= 0.0 {
            prop_assert_eq!(f, TireForces::ZERO);
        } else {
            let u = t.friction(kappa, alpha);
            prop_assert!(f.fy.abs() <= u * fz * (1.0 + 1e-12));
            prop_assert!(f.fx.abs() <= u * fz * (1.0 + 1e-12));
            prop_assert!(f.mz * alpha >= 0.0);
            prop_assert!(f.fy * alpha >= 0.0 && f.fx * kappa >= 0.0);
        }
        // Odd symmetry in alpha and in kappa.
        let fa = t.forces(fz, kappa, -alpha);
        prop_assert_eq!(fa.fy, -f.fy);
        prop_assert_eq!(fa.mz, -f.mz);
        prop_assert_eq!(fa.fx, f.fx);
        let fk = t.forces(fz, -kappa, alpha);
        prop_assert_eq!(fk.fx, -f.fx);
        prop_assert_eq!(fk.fy, f.fy);
    }

    #[test]
    fn extreme_slips_never_nan(t in arb_tire(), fz in 1.0..1e7f64, sk in prop::bool::ANY, sa in prop::bool::ANY) {
        let kappa = if sk { 1.0 } else { -1.0 };
        let alpha = if sa { std::f64::consts::FRAC_PI_2 } else { -std::f64::consts::FRAC_PI_2 };
        for (k, a) in [(kappa, alpha), (0.0, alpha), (kappa, 0.0), (1e6 * kappa, 10.0 * alpha)] {
            let f = t.forces(fz, k, a);
            prop_assert!(f.fx.is_finite() && f.fy.is_finite() && f.mz.is_finite() && f.my.is_finite());
        }
    }

    #[test]
    fn other_laws_are_finite_and_odd(
        c in 1e3..1e7f64, kmz in 0.0..1e6f64, a in 0.01..2.0f64, b in 0.1..50.0f64,
        fz in -1e6..1e7f64, kappa in -1.0..1.0f64, alpha in -1.6..1.6f64,
    ) {
        let lin = LinearCornering::new(c, kmz).unwrap();
        let exp = ExponentialCornering::new(a, b).unwrap();
        let tr = TractionDependentCornering::new(c, -1e-6, 1e6, a).unwrap();
        let models: [&dyn HandlingModel; 3] = [&lin, &exp, &tr];
        for m in models {
            let f = m.forces(fz, kappa, alpha);
            let g = m.forces(fz, kappa, -alpha);
            prop_assert!(f.fy.is_finite() && f.fx.is_finite() && f.mz.is_finite());
            prop_assert_eq!(f.fy, -g.fy);
            if fz <= 0.0 { prop_assert_eq!(f, TireForces::ZERO); }
        }
        if fz > 0.0 {
            prop_assert!(exp.lateral_force(fz, alpha).abs() <= a * fz);
        }
    }
}
