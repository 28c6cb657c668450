//! The design measures of a vehicle whose front struts are interconnected (`[link]`) run the
//! linked struts: each measure equals the linked run of `vehicle_3d::interconnect` to the
//! bit, and an assessment without the front-axle HPS refuses a link.

use afsv_design::design_3d::{assess, measure};
use hps_emulsion::interconnect::LineParams;
use vehicle_3d::interconnect::{ride_linked, roll_linked, yaw_linked, Link};
use vehicle_3d::scenarios::{RideSpec, RollSpec, YawSpec};
use vehicle_3d::{FrontAxle, Load, VehicleParams};

#[test]
fn linked_design_measures_are_the_linked_runs() {
    let p = VehicleParams::nominal();
    let link = Link::Roll(LineParams::front_axle_roll());
    let axle = FrontAxle::Suspended;
    let m = measure(&p, &[axle], &[Load::Loaded], &[1], Some(link), &|_| {})
        .unwrap()
        .pop()
        .unwrap();
    let ride = ride_linked(&p, &RideSpec::d1(Load::Loaded, axle), 1, link)
        .unwrap()
        .1;
    let roll = roll_linked(&p, &RollSpec::d2(axle), 1, link).unwrap().1;
    let yaw = yaw_linked(&p, &YawSpec::d3(axle), link).unwrap().1;
    let r = m.ride_of(Load::Loaded).unwrap();
    assert_eq!(r.a_wz_m_s2.mean, ride.a_wz_m_s2);
    assert_eq!(r.strut_travel_m.map(|t| t.mean), ride.strut_travel_p2p_m);
    assert_eq!(m.sp_drt_m_s2.mean, roll.sp_drt_m_s2);
    assert_eq!(m.yaw.omega_z_hz, yaw.omega_z_hz);
}

#[test]
fn a_link_needs_the_front_axle_hps() {
    let p = VehicleParams::nominal();
    let link = Link::Roll(LineParams::front_axle_roll());
    let e = assess(&p, false, &[1], Some(link), &|_| {}).unwrap_err();
    assert!(e.contains("[link]"), "{e}");
}
