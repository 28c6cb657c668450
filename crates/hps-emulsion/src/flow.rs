//! Flows between the chambers: turbulent bleed orifices and check valves, laminar leakage
//! (Eq 5.12 = 6.18), with the square root regularised near zero pressure difference.

/// Regularised signed square root `s(dp) = dp / (dp^2 + p_reg^2)^(1/4)` (Pa^0.5).
///
/// Equals `sgn(dp) sqrt(|dp|)` to a relative `p_reg^2 / (4 dp^2)` for `|dp| >> p_reg`, and is
/// linear (finite slope `1/sqrt(p_reg)`) through zero, where the exact law has an infinite
/// slope that makes the system needlessly stiff. With `p_reg = 100 Pa` the difference is below
/// 1e-6 relative once `|dp| > 50 kPa`; its effect on strut outputs is tested (< 0.1 %).
#[inline]
pub fn reg_sqrt(dp: f64, p_reg: f64) -> f64 {
    dp / (dp * dp + p_reg * p_reg).sqrt().sqrt()
}

/// Turbulent orifice flow `C A sqrt(2 |dp| / rho) sgn(dp)` (m^3/s) for total effective area
/// `ca = C n A` (m^2), pressure difference `dp` (Pa) and mean density `rho` (kg/m^3), Eq 5.12.
#[inline]
pub fn orifice_flow(ca: f64, dp: f64, rho: f64, p_reg: f64) -> f64 {
    ca * (2.0 / rho).sqrt() * reg_sqrt(dp, p_reg)
}

/// Check-valve flow of Eq 5.12: orifice flow when `dp = P_hc - P_hr > 0`, zero otherwise
/// (closed when `P_hr >= P_hc`), times the valve opening in [0, 1] (1 without valve lag).
#[inline]
pub fn check_valve_flow(ca: f64, dp: f64, rho: f64, p_reg: f64, opening: f64) -> f64 {
    if dp > 0.0 {
        opening * orifice_flow(ca, dp, rho, p_reg)
    } else {
        0.0
    }
}

/// Total flow from the piston to the rod side of Eq 5.12 (m^3/s):
/// `orifice_flow(ca_b) + check_valve_flow(ca_v, opening) + k_l dp`, with the regularised
/// root and the density factor computed once for both orifice laws. `ca_b`, `ca_v` are the
/// total effective areas `C n A` of the bleed orifices and the check valves (m^2), `k_l` the
/// laminar leakage coefficient (m^3/(Pa s)), `rho` the mean density (kg/m^3).
#[inline]
pub fn piston_to_rod_flow(
    ca_b: f64,
    ca_v: f64,
    opening: f64,
    k_l: f64,
    dp: f64,
    rho: f64,
    p_reg: f64,
) -> f64 {
    let ca = if dp > 0.0 {
        ca_b + opening * ca_v
    } else {
        ca_b
    };
    ca * (2.0 / rho).sqrt() * reg_sqrt(dp, p_reg) + k_l * dp
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn total_flow_is_the_sum_of_the_three_paths() {
        let (ca_b, ca_v, k_l, rho) = (0.7 * 11e-6, 0.6 * 2.0 * 8e-6, 5e-12, 840.0);
        for &dp in &[-2e6, -3e3, -50.0, 0.0, 40.0, 7e3, 1.5e6] {
            for &opening in &[0.0, 0.4, 1.0] {
                let sum = orifice_flow(ca_b, dp, rho, 100.0)
                    + check_valve_flow(ca_v, dp, rho, 100.0, opening)
                    + k_l * dp;
                let q = piston_to_rod_flow(ca_b, ca_v, opening, k_l, dp, rho, 100.0);
                assert!(
                    (q - sum).abs() <= 1e-14 * sum.abs().max(1e-12),
                    "{dp} {opening}"
                );
            }
        }
    }

    #[test]
    fn sqrt_law_far_from_zero() {
        let ca = 0.74 * 11e-6;
        let q = orifice_flow(ca, 1e6, 850.0, 100.0);
        let exact = ca * (2.0 * 1e6 / 850.0f64).sqrt();
        assert!((q - exact).abs() / exact < 1e-8);
        assert!((orifice_flow(ca, -1e6, 850.0, 100.0) + exact).abs() / exact < 1e-8);
        assert!((reg_sqrt(5e4, 100.0) - 5e4f64.sqrt()).abs() / 5e4f64.sqrt() < 1e-6);
    }

    #[test]
    fn check_valve_closed_when_rod_side_higher() {
        assert_eq!(check_valve_flow(1e-5, -10.0, 850.0, 100.0, 1.0), 0.0);
        assert_eq!(check_valve_flow(1e-5, 0.0, 850.0, 100.0, 1.0), 0.0);
        assert!(check_valve_flow(1e-5, 10.0, 850.0, 100.0, 1.0) > 0.0);
        assert_eq!(check_valve_flow(1e-5, 1e5, 850.0, 100.0, 0.0), 0.0);
    }

    #[test]
    fn regularised_root_is_odd_monotone_and_finite_slope() {
        let mut prev = f64::NEG_INFINITY;
        for i in -200..=200 {
            let dp = i as f64 * 3.0;
            let s = reg_sqrt(dp, 100.0);
            assert!(s > prev);
            assert_eq!(s, -reg_sqrt(-dp, 100.0));
            prev = s;
        }
        let slope = (reg_sqrt(1e-3, 100.0) - reg_sqrt(-1e-3, 100.0)) / 2e-3;
        assert!((slope - 0.1).abs() < 1e-6);
    }
}
