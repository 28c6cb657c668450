//! The Table 6.4 shapes on one seed at +30 %: a larger piston area stiffens the damping (a_wz
//! up), a larger bleed orifice softens it (a_wz down), the check valve barely matters.

use afsv_design::{hps_sensitivity, HpsVariable, StudyScope};
use vehicle_3d::VehicleParams;

#[test]
fn table_6_4_shapes_at_plus_30_percent() {
    let p = VehicleParams::nominal();
    let scope = StudyScope {
        roll: false,
        yaw: false,
    };
    let s = hps_sensitivity(&p, &[0.3], &[5], scope, &|_| {}).unwrap();
    assert_eq!(s.rows.len(), 3);
    let nominal = s.nominal.a_wz_unloaded_m_s2.mean;
    let at = |v: HpsVariable| {
        s.rows
            .iter()
            .find(|r| r.variable == v)
            .unwrap()
            .measures
            .a_wz_unloaded_m_s2
            .mean
    };
    assert!(at(HpsVariable::PistonArea) > 1.1 * nominal);
    assert!(at(HpsVariable::BleedArea) < nominal);
    assert!((at(HpsVariable::CheckValveArea) / nominal - 1.0).abs() < 0.02);
    // measures outside the scope are NaN, not zero
    assert!(s.nominal.omega_z_hz.is_nan() && s.nominal.sp_drt_m_s2.n == 0);
    // bad requests are refused before any run
    assert!(hps_sensitivity(&p, &[0.3], &[], scope, &|_| {}).is_err());
    assert!(hps_sensitivity(&p, &[-1.5], &[1], scope, &|_| {}).is_err());
}
