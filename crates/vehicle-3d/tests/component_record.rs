//! Every component's own channels along a run (`vehicle_3d::component_record`): the run's
//! record is `simulate`'s bit for bit, one row per sample, and the channels carry the run's
//! own values (the chamber pressures of the record, the struts' static loads at the start).

use vehicle_3d::component_record::{component_channels, simulate_components};
use vehicle_3d::{
    simulate, FrontAxle, Load, RunOptions, Statics, Vehicle, VehicleOptions, VehicleParams,
};
use vehicle_components::{FlatTerrain, SteerInput};

fn run_options() -> RunOptions {
    RunOptions {
        t_end_s: 1.5,
        ..RunOptions::default()
    }
}

fn vehicle(p: &VehicleParams, axle: FrontAxle) -> Vehicle {
    let flat = FlatTerrain::new(0.0, 0.8).unwrap();
    let options = VehicleOptions {
        front_axle: axle,
        speed_m_s: 5.0,
        steer: SteerInput::pulse_deg(30.0, 0.2, 0.3),
        path_length_m: 20.0,
        ..VehicleOptions::default()
    };
    Vehicle::new(p, Load::Loaded, options, &flat, 0.5 * p.front_track_m).unwrap()
}

#[test]
fn both_axles_suspended_record_every_strut_and_the_run_is_unchanged() {
    let mut p = VehicleParams::nominal();
    p.rear_hps = Some(p.default_rear_strut().unwrap());
    let v = vehicle(&p, FrontAxle::Suspended);
    let (record, rec) = simulate_components(&v, &run_options()).unwrap();
    assert_eq!(record, simulate(&v, &run_options()).unwrap());
    assert_eq!(rec.len(), record.len());
    // time, the steering's 10 channels, 8 per strut
    assert_eq!(rec.channels().len(), 1 + 10 + 4 * 8);
    assert_eq!(rec.column("time_s").unwrap(), &record.t_s[..]);
    // the chamber pressures are the run record's, bit for bit
    assert_eq!(
        rec.column("steering_p_c_pa").unwrap(),
        &record.pressure_pa[0][..]
    );
    assert_eq!(
        rec.column("steering_p_r_pa").unwrap(),
        &record.pressure_pa[1][..]
    );
    // at the start each strut carries its axle's static load (Eq 6.9 at rest)
    let s = Statics::of(&p, Load::Loaded).unwrap();
    for (name, load) in [
        ("hps_front_left_force_n", s.front_strut_force_n(&p)),
        ("hps_front_right_force_n", s.front_strut_force_n(&p)),
        ("hps_rear_left_force_n", s.rear_strut_force_n(&p)),
        ("hps_rear_right_force_n", s.rear_strut_force_n(&p)),
    ] {
        let f0 = rec.column(name).unwrap()[0];
        assert!((f0 / load - 1.0).abs() < 1e-6, "{name}: {f0} vs {load}");
    }
    // the steering pulse moves the struts: the gas volumes change, and stay positive
    for name in [
        "hps_front_left_gas_volume_m3",
        "hps_rear_right_gas_volume_m3",
    ] {
        let g = rec.column(name).unwrap();
        assert!(g.iter().all(|&x| x > 0.0));
        assert!(g.iter().any(|&x| (x - g[0]).abs() > 1e-9 * g[0]), "{name}");
    }
}

#[test]
fn a_rigid_vehicle_records_the_steering_only() {
    let p = VehicleParams::nominal();
    let v = vehicle(&p, FrontAxle::Rigid);
    let names = component_channels(&v).unwrap();
    assert_eq!(names.len(), 11);
    assert!(names.names().iter().all(|n| !n.starts_with("hps_")));
    let (record, rec) = simulate_components(&v, &run_options()).unwrap();
    assert_eq!(rec.len(), record.len());
    assert!(rec
        .column("steering_supply_power_w")
        .unwrap()
        .iter()
        .all(|x| x.is_finite()));
}
