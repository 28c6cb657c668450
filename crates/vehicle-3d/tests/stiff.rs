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

/// The state layout names every state once, with a unit and a typical magnitude, in the
/// blocks the right-hand side reads at its offsets: both axles suspended, with the driver.
#[test]
fn every_state_has_its_own_name_in_its_block() {
    let mut p = VehicleParams::nominal();
    p.rear_hps = Some(p.hps);
    let options = VehicleOptions {
        front_axle: FrontAxle::Suspended,
        driver: Some(vehicle_components::PathDriver::new(
            vehicle_components::Course::path_change_fig_3_6(),
        )),
        ..VehicleOptions::default()
    };
    let v = vehicle(&p, options);
    let (l, o) = (v.state_layout(), v.offsets());
    assert_eq!(l.len(), o.dim);
    let names: Vec<String> = (0..o.dim).map(|i| v.state_name(i)).collect();
    for (i, n) in names.iter().enumerate() {
        assert_eq!(names.iter().filter(|m| *m == n).count(), 1, "{n} twice");
        assert!(!l.units()[i].is_empty() && l.typicals()[i] > 0.0, "{n}");
    }
    let at = |name: &str| l.index_of(name).unwrap_or_else(|| panic!("{name}"));
    let j = v.joints();
    assert_eq!(at("base_x_m"), o.q);
    assert_eq!(at("articulation_rad"), j.articulation.0);
    assert_eq!(at("base_roll_rate_rad_s"), o.v);
    assert_eq!(at("articulation_rate_rad_s"), o.v + j.articulation.1);
    assert_eq!(at("front_right_spin_rate_rad_s"), o.v + j.spin[1].1);
    assert_eq!(at("rear_left_carrier_m"), j.rear_carrier.unwrap()[0].0);
    assert_eq!(at("steering_p_c_pa"), o.afs);
    assert_eq!(at("front_left_slip_ratio"), o.tires);
    assert_eq!(at("rear_right_slip_angle_rad"), o.tires + 7);
    assert_eq!(at("front_left_hps_gas_volume_m3"), o.hps);
    assert_eq!(at("front_right_hps_gas_volume_m3"), o.hps + o.hps_states);
    assert_eq!(at("rear_left_hps_gas_volume_m3"), o.rear_hps);
    assert_eq!(at("speed_error_integral_m"), o.pi);
    assert_eq!(at("path_m"), o.path);
    assert_eq!(Some(at("driver_steer_wheel_rad")), o.driver);
    // the absolute tolerances: small joint motions, spinning wheels, MPa pressures
    assert_eq!(l.typicals()[j.spin[0].0], 10.0);
    assert_eq!(l.typicals()[j.articulation.0], 0.05);
    assert_eq!(l.typicals()[o.afs], 1e6);
    assert_eq!(v.state_name(o.dim), format!("state {}", o.dim));
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
            assert!(state.starts_with("steering_p_"), "{state}");
            let odeint::OdeError::StepSizeCollapsed { t, .. } = source else {
                panic!("{source}")
            };
            assert!(t < 1.0, "ended at {t} s");
        }
        Ok(r) => panic!("ran to {} s", r.t_s.last().unwrap()),
        Err(e) => panic!("expected the stiff-state error, got {e}"),
    }
}

/// The methods implicit in the struts' stiff blocks, the Rosenbrock-W method
/// (`odeint::Solver::Ros34pw2`) and the additive Runge-Kutta method (`Ark436`, Newton on
/// the struts' own rates), give the Dormand-Prince run at tight tolerance: 3 s of the
/// loaded D1 ride with the nominal HPS on class E ground.
#[test]
fn the_implicit_block_runs_agree_with_dopri5_at_tight_tolerance() {
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
    let worst = |a: &[f64], b: &[f64]| {
        a.iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max)
    };
    for solver in [odeint::Solver::Ros34pw2, odeint::Solver::Ark436] {
        let w = simulate(&v, &run(solver, 1e-6)).unwrap();
        for k in 0..2 {
            let travel = worst(&w.hps_travel_m[k], &reference.hps_travel_m[k]);
            assert!(
                travel < 2e-5,
                "{solver:?}, strut {k}: travel differs by {travel} m"
            );
        }
        // measured: 3.3e-4 m/s² (ROS34PW2) and 3.7e-4 (ARK, whose quadratic dense output in
        // the struts' states gave 5.5e-3 before the cubic Hermite form)
        let a = worst(&w.cab_accel_m_s2[2], &reference.cab_accel_m_s2[2]);
        assert!(
            a < 1e-3,
            "{solver:?}: vertical acceleration differs by {a} m/s2"
        );
    }
}

/// A strut block's own rates (`OdeSystem::block_rhs`, what the additive Runge-Kutta
/// method's Newton iterations evaluate) are the right-hand side's rows of that block, to
/// the bit, for both axles' struts away from the static state.
#[test]
fn a_strut_block_rates_are_the_right_hand_side_rows() {
    use odeint::OdeSystem;
    let mut p = VehicleParams::nominal();
    p.rear_hps = Some(p.hps);
    let options = VehicleOptions {
        front_axle: FrontAxle::Suspended,
        ..VehicleOptions::default()
    };
    let v = vehicle(&p, options);
    let mut y = v.initial_state();
    // move every carrier and strut state off its static value
    let o = *v.offsets();
    for (k, yk) in y.iter_mut().enumerate().skip(o.v).take(o.afs - o.v) {
        *yk += 0.01 * (k as f64).sin();
    }
    for b in v.stiff_blocks() {
        for (c, &i) in b.iter().enumerate() {
            y[i] *= 1.0 + 0.002 * (c as f64 + 1.0);
        }
    }
    let mut d = vec![0.0; v.dim()];
    v.rhs(0.3, &y, &mut d);
    assert_eq!(v.stiff_blocks().len(), 4);
    for (block, rows) in v.stiff_blocks().iter().enumerate() {
        let mut out = vec![f64::NAN; rows.len()];
        assert!(v.block_rhs(0.3, &y, block, &mut out));
        let want: Vec<f64> = rows.iter().map(|&i| d[i]).collect();
        assert_eq!(out, want, "block {block}");
        assert!(out.iter().all(|x| x.is_finite() && *x != 0.0), "{out:?}");
    }
    let mut out = [0.0; 3];
    assert!(!v.block_rhs(0.3, &y, 4, &mut out));
}
