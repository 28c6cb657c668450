//! Flow volume-regulated steering valve (Eqs 3.9-3.12, 4.6).
//!
//! The relative spool angle X = theta_sw - theta_h (Eq 3.9) opens the valve beyond the dead
//! band X_0. We use the normalised opening xi = (|X| - X_0)/(X_lim - X_0) clipped to [0, 1]
//! (Ch. 4: "X is the effective opening area"), which with the Table 4.1 coefficients in
//! L/min and bar gives 221 L/min at 80 bar fully open (see `docs/afs-hydraulics.md`).
//! X > X_0 feeds the P_c group and drains P_r (right-hand turn, Fig 3.3); X < -X_0 is the
//! mirror image (feeds P_r, drains P_c).

/// Normalised valve opening xi in [0, 1] for relative spool angle `x` (rad), dead band
/// `dead_band` and spool travel limit `limit` (rad): the factor (X - X_0) of Eqs 3.11-3.12
/// divided by its full-travel value, with the ±8.1 deg pin as saturation.
#[inline]
pub fn normalised_opening(x: f64, dead_band: f64, limit: f64) -> f64 {
    ((x.abs() - dead_band) / (limit - dead_band)).clamp(0.0, 1.0)
}

/// Laminar-turbulent orifice characteristic per unit opening (m³/s), Eqs 3.11/4.6:
/// g(ΔP) = a_m · ΔP/(ΔP²+δ²)^{1/4} + a_v · ΔP · exp(a_0 |ΔP|).
///
/// The first term is the turbulent sqrt(ΔP) law regularised near ΔP = 0 (width `delta`,
/// finite slope a_m/sqrt(δ) instead of an infinite one); g is odd in ΔP, so a negative
/// pressure difference gives a reverse flow of the same size.
#[inline]
pub fn orifice_flow(dp: f64, a0: f64, am: f64, av: f64, delta: f64) -> f64 {
    let turb = am * dp / (dp * dp + delta * delta).sqrt().sqrt();
    let lam = av * dp * (a0 * dp.abs()).exp();
    turb + lam
}

/// Derivative dg/dΔP of [`orifice_flow`] (m³/(s·Pa)); used by the supply-droop solver.
#[inline]
pub fn orifice_flow_slope(dp: f64, a0: f64, am: f64, av: f64, delta: f64) -> f64 {
    let s = dp * dp + delta * delta;
    let q = s.sqrt().sqrt();
    // d/dΔ [Δ s^{-1/4}] = s^{-1/4} - Δ² s^{-5/4}/2
    let turb = am * (1.0 / q - 0.5 * dp * dp / (s * q));
    let lam = av * (a0 * dp.abs()).exp() * (1.0 + a0 * dp.abs());
    turb + lam
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn opening_dead_band_and_saturation() {
        let d = 2.0_f64.to_radians();
        let l = 8.0_f64.to_radians();
        assert_eq!(normalised_opening(1.0_f64.to_radians(), d, l), 0.0);
        assert_eq!(normalised_opening(-1.9_f64.to_radians(), d, l), 0.0);
        assert!((normalised_opening(5.0_f64.to_radians(), d, l) - 0.5).abs() < 1e-12);
        assert!((normalised_opening(-5.0_f64.to_radians(), d, l) - 0.5).abs() < 1e-12);
        assert_eq!(normalised_opening(20.0_f64.to_radians(), d, l), 1.0);
    }

    #[test]
    fn orifice_is_odd_and_slope_matches_finite_difference() {
        let (a0, am, av, dl) = (-7.4e-8, 4.95e-8, 8.0e-10, 1.0e4);
        for dp in [-3.0e6, -2.0e4, 0.0, 5.0e3, 8.0e6, 1.3e7] {
            let g = orifice_flow(dp, a0, am, av, dl);
            assert!((g + orifice_flow(-dp, a0, am, av, dl)).abs() <= 1e-20);
            let h = 1.0 + dp.abs() * 1e-6;
            let fd = (orifice_flow(dp + h, a0, am, av, dl) - orifice_flow(dp - h, a0, am, av, dl))
                / (2.0 * h);
            let an = orifice_flow_slope(dp, a0, am, av, dl);
            assert!(
                (fd - an).abs() <= 1e-6 * an.abs() + 1e-16,
                "dp {dp}: {fd} vs {an}"
            );
        }
        // far from zero the regularised term is the square root law
        let dp = 8.0e6;
        let turb = am * dp / (dp * dp + dl * dl).sqrt().sqrt();
        assert!((turb / (am * dp.sqrt()) - 1.0).abs() < 1e-6);
    }
}
