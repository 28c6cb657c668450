//! The design scenarios on one terrain seed: the orderings the dissertation reports, the
//! convergence of a_wz in the integrator tolerance, and the measures' plumbing.

use vehicle_3d::scenarios::{ride, ride_measures, yaw, RideSpec, Spread, YawSpec, RUN_IN_M};
use vehicle_3d::vehicle::end_stop_force;
use vehicle_3d::{simulate, FrontAxle, Load, RunOptions, Vehicle, VehicleOptions, VehicleParams};

#[test]
fn unloaded_rides_rougher_and_the_hps_smooths_the_ride() {
    let p = VehicleParams::nominal();
    let awz = |load, axle| ride(&p, &RideSpec::d1(load, axle), 7).unwrap().1;
    let (u, l) = (
        awz(Load::Unloaded, FrontAxle::Rigid),
        awz(Load::Loaded, FrontAxle::Rigid),
    );
    assert!(u.a_wz_m_s2 > l.a_wz_m_s2, "{u:?} {l:?}");
    // the Wk weighting passes less than the unweighted band
    assert!(u.a_wz_m_s2 < u.a_z_rms_m_s2);
    assert!(u.strut_travel_p2p_m.is_none());
    let h = awz(Load::Unloaded, FrontAxle::Suspended);
    assert!(h.a_wz_m_s2 < 0.9 * u.a_wz_m_s2, "{h:?} vs {u:?}");
    let ds = h.strut_travel_p2p_m.unwrap();
    assert!(ds > 0.0 && ds < 0.24, "{ds}");
}

#[test]
fn a_wz_is_converged_in_the_integrator_tolerance() {
    let p = VehicleParams::nominal();
    let spec = RideSpec::d1(Load::Loaded, FrontAxle::Rigid);
    let terrain = spec.terrain.build(&p, 200.0, 3).unwrap();
    let speed = spec.speed_kmh / 3.6;
    let options = VehicleOptions {
        speed_m_s: speed,
        path_length_m: 125.0,
        start_s_m: 15.0,
        ..VehicleOptions::default()
    };
    let v = Vehicle::new(&p, Load::Loaded, options, &terrain, 0.5 * p.front_track_m).unwrap();
    let run = |rtol: f64, max_step_s: f64| {
        let rec = simulate(
            &v,
            &RunOptions {
                t_end_s: 120.0 / speed,
                rtol,
                max_step_s,
                ..RunOptions::default()
            },
        )
        .unwrap();
        ride_measures(&rec, RUN_IN_M / speed, FrontAxle::Rigid, false).unwrap()
    };
    let d = RunOptions::default();
    let (fast, fine) = (run(d.rtol, d.max_step_s), run(1e-7, 0.005));
    assert!(
        (fast.a_wz_m_s2 / fine.a_wz_m_s2 - 1.0).abs() < 0.01,
        "{fast:?} vs {fine:?}"
    );
}

#[test]
fn the_pulse_gives_a_decaying_yaw_oscillation() {
    let p = VehicleParams::nominal();
    let (rec, m) = yaw(&p, &YawSpec::d3(FrontAxle::Rigid), 0).unwrap();
    assert!(m.omega_z_hz > 2.0 && m.omega_z_hz < 10.0, "{m:?}");
    assert!(m.damping_ratio > 0.0 && m.damping_ratio < 1.0, "{m:?}");
    // a positive (right-hand) pulse articulates positively first
    let first = rec
        .articulation_rad
        .iter()
        .find(|a| a.abs() > 1e-3)
        .unwrap();
    assert!(*first > 0.0);
}

#[test]
fn spread_and_end_stops_by_hand() {
    let s = Spread::of(&[1.0, 2.0, 3.0]).unwrap();
    assert_eq!((s.mean, s.sd, s.n), (2.0, 1.0, 3));
    assert!(Spread::of(&[]).is_err() && Spread::of(&[f64::NAN]).is_err());
    let none = Spread::of_measured(&[]).unwrap();
    assert!(none.mean.is_nan() && none.sd.is_nan() && none.n == 0);
    assert_eq!(
        Spread::of_measured(&[1.0, 3.0]).unwrap(),
        Spread::of(&[1.0, 3.0]).unwrap()
    );
    assert_eq!(end_stop_force(0.1, 1.0, 0.12), 0.0);
    // 10 mm past the travel at 2e8 N/m
    assert!((end_stop_force(0.13, 0.0, 0.12) - 2.0e6).abs() < 1e-3);
    assert!((end_stop_force(-0.13, 0.0, 0.12) + 2.0e6).abs() < 1e-3);
    // rebounding fast off the stop: the damper may not pull
    assert_eq!(end_stop_force(0.121, -20.0, 0.12), 0.0);
}

#[test]
fn shared_tracks_give_the_same_run_and_refuse_another_load() {
    use vehicle_3d::scenarios::{ride_on, ride_tracks};
    let p = VehicleParams::nominal();
    let spec = RideSpec::d1(Load::Loaded, FrontAxle::Rigid);
    let tracks = ride_tracks(&p, &spec, 2).unwrap();
    let (_, shared) = ride_on(&p, &spec, tracks.clone()).unwrap();
    let (_, own) = ride(&p, &spec, 2).unwrap();
    assert_eq!(shared, own);
    let unloaded = RideSpec::d1(Load::Unloaded, FrontAxle::Rigid);
    let err = ride_on(&p, &unloaded, tracks).unwrap_err().to_string();
    assert!(err.contains("tracks"), "{err}");
}

/// The rollover event (its function reads the kinematics alone) ends a D2 run where the
/// rear unit's margin, as the record computes it after the force evaluation, crosses zero.
#[test]
fn the_rollover_event_stops_the_run_at_zero_margin() {
    use vehicle_3d::scenarios::{roll, RollSpec};
    let p = VehicleParams::nominal();
    for axle in [FrontAxle::Rigid, FrontAxle::Suspended] {
        let (rec, m) = roll(&p, &RollSpec::d2(axle), 1).unwrap();
        let t_roll = rec.rollover_s.expect("D2 seed 1 rolls over");
        assert_eq!(m.rollover_s, Some(t_roll));
        assert_eq!(
            *rec.t_s.last().unwrap(),
            t_roll,
            "{axle:?}: the run ends at the event"
        );
        let margin = &rec.rollover_margin_m;
        let last = margin[margin.len() - 1];
        assert!(last.abs() < 1e-6, "{axle:?}: margin {last} m at the event");
        // the samples before it are inside the margin (the crossing falls between samples)
        assert!(
            margin[..margin.len() - 1].iter().all(|&x| x > 0.0),
            "{axle:?}"
        );
    }
}
