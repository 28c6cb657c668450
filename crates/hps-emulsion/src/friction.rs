//! Seal friction: viscous + Coulomb + Stribeck with the linear hysteresis transition band
//! (Eqs 5.2-5.3).

use crate::params::FrictionParams;

/// Friction levels on the two sides of the motion (N). Symmetric seals (the paper) have
/// `coulomb_comp == coulomb_ext == F_c` and `stiction_comp == stiction_ext == F_s`; the
/// asymmetric-friction extension scales them separately.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrictionLevels {
    /// Coulomb level while compressing (z_s' > 0).
    pub coulomb_comp: f64,
    /// Coulomb level while extending (z_s' < 0).
    pub coulomb_ext: f64,
    /// Stiction level while compressing.
    pub stiction_comp: f64,
    /// Stiction level while extending.
    pub stiction_ext: f64,
}

impl FrictionLevels {
    /// Levels of symmetric seals scaled by `comp` in compression and `ext` in extension.
    pub fn scaled(f: &FrictionParams, comp: f64, ext: f64) -> Self {
        Self {
            coulomb_comp: f.f_c * comp,
            coulomb_ext: f.f_c * ext,
            stiction_comp: f.f_s * comp,
            stiction_ext: f.f_s * ext,
        }
    }
}

/// Seal friction force F_f (N, positive resisting compression) at deflection `z` (m, from the
/// static position, positive in compression) and velocity `zdot` (m/s), band width `v_h` (m/s).
///
/// Outside the band, or inside it while moving away from the static position
/// (`z zdot >= 0`), Eq 5.2:
/// `mu_v zdot + F_c sgn(zdot) + F_s exp(-k_s |zdot|) sgn(zdot)`
/// (the `sgn(x')` of Eq 5.2 is read as `sgn(z_s')`).
/// Inside the band just after a reversal (`z zdot < 0`, `|zdot| < v_h`), Eq 5.3: the force
/// goes linearly from the previous direction's level (at `zdot = 0`) to the Eq 5.2 value at
/// `|zdot| = v_h`. With unequal levels this is `-F_prev + (F_new(v_h) + F_prev) |zdot| / v_h`
/// in the direction of motion, which is Eq 5.3 exactly when the levels are equal.
#[inline]
pub fn friction_force(f: &FrictionParams, lv: &FrictionLevels, z: f64, zdot: f64, v_h: f64) -> f64 {
    let speed = zdot.abs();
    let viscous = f.mu_v * zdot;
    if zdot == 0.0 {
        return 0.0;
    }
    let (c_new, s_new, c_prev, s_prev, sign) = if zdot > 0.0 {
        (
            lv.coulomb_comp,
            lv.stiction_comp,
            lv.coulomb_ext,
            lv.stiction_ext,
            1.0,
        )
    } else {
        (
            lv.coulomb_ext,
            lv.stiction_ext,
            lv.coulomb_comp,
            lv.stiction_comp,
            -1.0,
        )
    };
    if speed >= v_h || z * zdot >= 0.0 {
        // Eq 5.2
        viscous + sign * (c_new + s_new * (-f.k_s * speed).exp())
    } else {
        // Eq 5.3
        let r = speed / v_h;
        let coulomb = -c_prev + (c_new + c_prev) * r;
        let stiction = -s_prev + (s_new * (-f.k_s * v_h).exp() + s_prev) * r;
        viscous + sign * (coulomb + stiction)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fp() -> FrictionParams {
        FrictionParams {
            mu_v: 50.0,
            f_c: 100.0,
            f_s: 60.0,
            k_s: 50.0,
            vh_ratio: 0.1,
            vh_min: 1e-3,
        }
    }

    #[test]
    fn eq_5_2_by_hand() {
        let f = fp();
        let lv = FrictionLevels::scaled(&f, 1.0, 1.0);
        // 0.1 m/s compression: 50*0.1 + 100 + 60 e^-5
        let hand = 5.0 + 100.0 + 60.0 * (-5.0f64).exp();
        assert!((friction_force(&f, &lv, 0.01, 0.1, 0.02) - hand).abs() < 1e-12);
        assert!((friction_force(&f, &lv, -0.01, -0.1, 0.02) + hand).abs() < 1e-12);
    }

    #[test]
    fn eq_5_3_literal_and_continuity() {
        let f = fp();
        let lv = FrictionLevels::scaled(&f, 1.0, 1.0);
        let vh = 0.02;
        for &v in &[0.001, 0.005, 0.0199] {
            // z < 0, zdot > 0: just reversed from extension.
            let lit = f.mu_v * v
                + f.f_c * (2.0 / vh * v - 1.0)
                + f.f_s * ((1.0 + (-f.k_s * vh).exp()) / vh * v - 1.0);
            assert!((friction_force(&f, &lv, -0.01, v, vh) - lit).abs() < 1e-9);
            let lit_neg = -f.mu_v * v
                + f.f_c * (-2.0 / vh * v + 1.0)
                + f.f_s * (-(1.0 + (-f.k_s * vh).exp()) / vh * v + 1.0);
            assert!((friction_force(&f, &lv, 0.01, -v, vh) - lit_neg).abs() < 1e-9);
        }
        // continuous at the band edge
        let a = friction_force(&f, &lv, -0.01, vh * (1.0 - 1e-12), vh);
        let b = friction_force(&f, &lv, -0.01, vh, vh);
        assert!((a - b).abs() < 1e-6);
        // continuous through a reversal at the extreme z > 0: approaching (z zdot > 0) and
        // leaving (z zdot < 0) give the same force at zdot -> 0.
        let before = friction_force(&f, &lv, 0.02, 1e-12, vh);
        let after = friction_force(&f, &lv, 0.02, -1e-12, vh);
        assert!((before - after).abs() < 1e-6, "{before} {after}");
    }

    #[test]
    fn asymmetric_levels_reduce_to_symmetric() {
        let f = fp();
        let a = FrictionLevels::scaled(&f, 1.3, 0.8);
        assert!(
            (friction_force(&f, &a, 0.0, 0.5, 0.02) - (25.0 + 130.0 + 78.0 * (-25.0f64).exp()))
                .abs()
                < 1e-9
        );
        assert!(
            (friction_force(&f, &a, 0.0, -0.5, 0.02) + (25.0 + 80.0 + 48.0 * (-25.0f64).exp()))
                .abs()
                < 1e-9
        );
    }
}
