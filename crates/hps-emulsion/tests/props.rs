//! Invariants of the constitutive laws.

use hps_emulsion::emulsion::emulsion;
use hps_emulsion::friction::{friction_force, FrictionLevels};
use hps_emulsion::*;
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Symmetric seals: F_f(-z, -v) = -F_f(z, v), and friction never drives the motion
    /// outside the post-reversal band.
    #[test]
    fn friction_is_odd(z in -0.05f64..0.05, v in -0.5f64..0.5, vh in 0.001f64..0.05) {
        let f = StrutParams::lab(LabConfig::OneOrifice).friction;
        let lv = FrictionLevels::scaled(&f, 1.0, 1.0);
        let a = friction_force(&f, &lv, z, v, vh);
        let b = friction_force(&f, &lv, -z, -v, vh);
        prop_assert!((a + b).abs() < 1e-9);
        if v.abs() >= vh || z * v >= 0.0 {
            prop_assert!(a * v >= 0.0);
        }
    }

    /// Emulsion: gas fraction falls and bulk modulus rises with pressure, beta <= beta_h.
    #[test]
    fn emulsion_monotone(p in 0.05e6f64..20e6, dp in 1e3f64..1e6, g0 in 0.0f64..0.49) {
        let a = emulsion(p, 1e6, 1.4, 1.7e9, 850.0, g0);
        let b = emulsion(p + dp, 1e6, 1.4, 1.7e9, 850.0, g0);
        prop_assert!(b.gamma <= a.gamma);
        prop_assert!(b.beta >= a.beta * (1.0 - 1e-12));
        prop_assert!(a.beta <= 1.7e9 * (1.0 + 1e-12) && a.beta > 0.0);
        prop_assert!(a.rho > 0.0 && a.rho <= 850.0 / (1.0 - (p - 1e6) / 1.7e9) + 1e-9);
    }

    /// Static force rises with deflection (positive static stiffness) for any gas fraction.
    #[test]
    fn static_force_monotone(g0 in 0.0f64..0.1, z in -0.06f64..0.06) {
        let p = StrutParams::lab(LabConfig::TwoOrifices).with_gamma0(g0).unwrap();
        let s = HpsStrut::new(&p, &HpsExtensions::none()).unwrap();
        prop_assert!(s.static_force(z + 1e-3).unwrap() > s.static_force(z).unwrap());
    }
}
