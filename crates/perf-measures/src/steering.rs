//! Steering power efficiency of the hydraulic articulated frame steering (Eq 4.7).

use crate::error::{finite_series, invalid, same_len, time_series, MeasureError};
use crate::signal::trapz_unchecked;

/// Steering power efficiency `eta = integral(T_s theta_dot dt) / integral(P_s q dt)`
/// (Eq 4.7): useful work of the struts on the articulation joint over the hydraulic energy
/// delivered by the steering valve. `torque_nm` is the steering torque `T_s` (N m),
/// `theta_dot_rad_s` the articulation rate, `supply_pressure_pa` the supply pressure `P_s`
/// (Pa) and `flow_m3_s` the valve flow `q` to the struts (m^3/s). Both integrals use the
/// trapezoidal rule on the common time base `t` (s).
pub fn steering_power_efficiency(
    t: &[f64],
    torque_nm: &[f64],
    theta_dot_rad_s: &[f64],
    supply_pressure_pa: &[f64],
    flow_m3_s: &[f64],
) -> Result<f64, MeasureError> {
    time_series(t, 2)?;
    for (name, x) in [
        ("torque_nm", torque_nm),
        ("theta_dot_rad_s", theta_dot_rad_s),
        ("supply_pressure_pa", supply_pressure_pa),
        ("flow_m3_s", flow_m3_s),
    ] {
        same_len("t", t, name, x)?;
        finite_series(name, x, 2)?;
    }
    let useful: Vec<f64> = torque_nm
        .iter()
        .zip(theta_dot_rad_s)
        .map(|(a, b)| a * b)
        .collect();
    let supplied: Vec<f64> = supply_pressure_pa
        .iter()
        .zip(flow_m3_s)
        .map(|(a, b)| a * b)
        .collect();
    let den = trapz_unchecked(t, &supplied);
    if den.is_nan() || den <= 0.0 {
        return Err(invalid(
            "supply_pressure_pa * flow_m3_s",
            format!("the supplied hydraulic energy {den} J must be > 0"),
        ));
    }
    Ok(trapz_unchecked(t, &useful) / den)
}
