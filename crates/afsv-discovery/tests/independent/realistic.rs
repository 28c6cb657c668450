//! The realistic variant of the independent implementation: the same equations with other
//! readings wherever the paper is silent or ambiguous, as two faithful implementations of
//! the dissertation differ (issue 24). Its settings live here only, never in the discovery
//! code's defaults.
//!
//! Strut (Chapter 5, Table 6.3), against the note's readings of [`StrutData::table_6_3`]:
//!
//! | choice | the note / the crates | this variant |
//! |---|---|---|
//! | friction level (Table 5.1 missing) | F_c 357 N, mu_v 119 N s/m, F_s 238 N | F_c 600 N, mu_v 80 N s/m, F_s 400 N |
//! | friction band v_h | 0.1 v_peak | 0.3 v_peak |
//! | chamber split of the 11.4 L, rod-side dead volume | rod side = annulus x (travel + 10 mm) | annulus x (travel + 40 mm) |
//! | density of the orifice laws (Eq 5.12) | mean of both chambers | upstream chamber |
//! | cavitation floor (rod side) | 5 kPa, taper 20 kPa | 30 kPa, taper 50 kPa |
//! | orifice law near zero pressure drop | regularised over 2 kPa | over 20 kPa (laminar-like) |
//!
//! plus the calibratable parameters perturbed as in [`StrutData::perturbed`].
//!
//! Vehicle (Chapter 3, Table 3.1), against [`YawParams::table_3_1`]:
//!
//! | choice | Table 3.1 / the note | this variant |
//! |---|---|---|
//! | tire lag (relaxation length) | 0.4 m | 0.6 m |
//! | dead volume V_0 | Table 3.1 | x 1.3 |
//! | seal viscous friction | 0.06 kN s/mm | x 1.4 |
//! | orifice (valve) law coefficients a_m, a_v | Table 3.1 | a_m x 1.02, a_v x 0.95 |
//! | return flow-area factor k_v | Table 3.1 | x 1.05 |
//! | standby pressure at the start | 1 MPa | 0.9 MPa |
//!
//! The first three are calibrated by discovery (within their windows); the last three are
//! not. The calibratable parameters are perturbed as in [`YawParams::perturbed`] first.

use super::strut::StrutData;
use super::yaw::{YawLoad, YawParams};

/// The realistic strut: the note's choices replaced as in the module table, with the
/// calibratable parameters perturbed.
pub fn strut() -> StrutData {
    strut_choices(StrutData::perturbed())
}

/// `base` with the choices of the module table.
pub fn strut_choices(mut d: StrutData) -> StrutData {
    d.f_c = 600.0;
    d.mu_v = 80.0;
    d.f_s = 400.0;
    d.vh_ratio = 0.3;
    d.rod_dead_length = 0.040;
    d.upwind_density = true;
    d.floor_mpa = 0.03;
    d.floor_taper_mpa = 0.05;
    d.sqrt_reg_pa = 2.0e4;
    d
}

/// The realistic vehicle of load `load`: the calibratable parameters perturbed as in
/// [`YawParams::perturbed`], the unstated ones set otherwise (tire lag, dead volume, seal
/// friction; calibrated by discovery within their windows), and the readings of
/// [`vehicle_choices`].
pub fn vehicle(load: YawLoad) -> YawParams {
    let mut p = YawParams::perturbed(load);
    p.vehicle.sigma_m = 0.6;
    p.steering.v0_l *= 1.3;
    p.steering.mu_v_kn_s_mm *= 1.4;
    vehicle_choices(p)
}

/// `base` with the readings of the module table that no calibrated parameter covers: the
/// valve (orifice) law coefficients, the return flow-area factor, the standby pressure.
pub fn vehicle_choices(mut p: YawParams) -> YawParams {
    p.steering.am *= 1.02;
    p.steering.av *= 0.95;
    p.steering.kv *= 1.05;
    p.steering.standby_mpa = 0.9;
    p
}
