//! A run whose step size collapses ends early and names the stiff state
//! (`odeint::OdeError::StepSizeCollapsed`, `VehicleError::Stiff`).

use vehicle_3d::{
    simulate, FrontAxle, Load, RunOptions, Vehicle, VehicleError, VehicleOptions, VehicleParams,
};
use vehicle_components::FlatTerrain;

fn vehicle(p: &VehicleParams, options: VehicleOptions) -> Vehicle {
    let flat = FlatTerrain::new(0.0, 0.8).unwrap();
    Vehicle::new(p, Load::Loaded, options, &flat, 0.5 * p.front_track_m).unwrap()
}

#[test]
fn every_state_has_its_own_name() {
    let options = VehicleOptions {
        front_axle: FrontAxle::Suspended,
        ..VehicleOptions::default()
    };
    let v = vehicle(&VehicleParams::nominal(), options);
    let names: Vec<String> = (0..v.offsets().dim).map(|i| v.state_name(i)).collect();
    for (i, n) in names.iter().enumerate() {
        assert!(!n.starts_with("state ") && !n.contains('?'), "{i}: {n}");
        assert_eq!(names.iter().filter(|m| *m == n).count(), 1, "{n} twice");
    }
    assert!(names.iter().any(|n| n.starts_with("left HPS strut")));
    assert_eq!(names[v.offsets().afs], "steering pressure P_c");
}

#[test]
fn a_stiff_steering_circuit_ends_the_run_early_and_is_named() {
    // an oil a million times stiffer than Table 3.1's (the registry refuses it at read): the steering pressures' time
    // constant falls below a microsecond, and the explicit method's steps with it
    let mut p = VehicleParams::nominal();
    p.steering.bulk_modulus_pa *= 1e6;
    // 20 s take about 36 s of wall time here; 600 s would take 30 times that, and more
    // than ten times the step budget, so the run ends after its first few thousand steps
    let options = VehicleOptions {
        path_length_m: 4000.0,
        ..VehicleOptions::default()
    };
    let v = vehicle(&p, options);
    let run = RunOptions {
        t_end_s: 600.0,
        ..RunOptions::default()
    };
    match simulate(&v, &run) {
        Err(VehicleError::Stiff { state, source }) => {
            assert!(state.starts_with("steering pressure"), "{state}");
            let odeint::OdeError::StepSizeCollapsed { t, .. } = source else {
                panic!("{source}")
            };
            assert!(t < 1.0, "ended at {t} s");
        }
        Ok(r) => panic!("ran to {} s", r.t_s.last().unwrap()),
        Err(e) => panic!("expected the stiff-state error, got {e}"),
    }
}

/// The Rosenbrock-W method on the struts' stiff blocks (`odeint::Solver::Ros34pw2`) gives
/// the Dormand-Prince run at tight tolerance: 3 s of the loaded D1 ride with the nominal
/// HPS on class E ground.
#[test]
fn the_rosenbrock_w_run_agrees_with_dopri5_at_tight_tolerance() {
    use vehicle_3d::scenarios::{RideSpec, OUTPUT_DT_S};
    let p = VehicleParams::nominal();
    let terrain = RideSpec::d1(Load::Loaded, FrontAxle::Suspended)
        .terrain
        .build(&p, 60.0, 1)
        .unwrap();
    let options = VehicleOptions {
        front_axle: FrontAxle::Suspended,
        speed_m_s: 20.0 / 3.6,
        path_length_m: 40.0,
        start_s_m: 15.0,
        ..VehicleOptions::default()
    };
    let v = Vehicle::new(&p, Load::Loaded, options, &terrain, 0.5 * p.front_track_m).unwrap();
    let run = |solver, rtol| RunOptions {
        t_end_s: 3.0,
        output_dt_s: OUTPUT_DT_S,
        rtol,
        solver,
        ..RunOptions::default()
    };
    let reference = simulate(&v, &run(odeint::Solver::Dopri5, 1e-8)).unwrap();
    let w = simulate(&v, &run(odeint::Solver::Ros34pw2, 1e-6)).unwrap();
    let worst = |a: &[f64], b: &[f64]| {
        a.iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max)
    };
    for k in 0..2 {
        let travel = worst(&w.hps_travel_m[k], &reference.hps_travel_m[k]);
        assert!(travel < 2e-5, "strut {k}: travel differs by {travel} m");
    }
    let a = worst(&w.cab_accel_m_s2[2], &reference.cab_accel_m_s2[2]);
    assert!(a < 5e-3, "vertical acceleration differs by {a} m/s2");
}
