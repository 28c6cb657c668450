//! Whole runs: mirror symmetry of left and right ramps (level ground, and rough terrain
//! with its tracks swapped), determinism per terrain seed, a straight run that stays
//! straight, and bad inputs rejected with the field named.

use roll_truck::measures::level_ground;
use roll_truck::studies::{rough_terrain, truck_on};
use roll_truck::{simulate, ModelOptions, RunOptions, SteerDirection, TruckParams, TruckVehicle};
use terrain_psd::{SurfaceParams, TwoTrackProfile, TwoTrackSpec, TwoTrackTerrain};

fn smooth(direction: SteerDirection) -> TruckVehicle {
    let options = ModelOptions {
        direction,
        ..ModelOptions::default()
    };
    TruckVehicle::new(&TruckParams::nominal(), &level_ground(), 1.0, options).unwrap()
}

/// Largest mirror mismatches of two runs over the samples both have before `t_max`:
/// rollover time, a_y (m/s²), LTR, roll (rad), tire load (N).
fn mirror_errors(a: &roll_truck::RunRecord, b: &roll_truck::RunRecord, t_max: f64) -> [f64; 5] {
    let (ra, rb) = (a.rollover_s.unwrap(), b.rollover_s.unwrap());
    let mut e = [(ra - rb).abs(), 0.0, 0.0, 0.0, 0.0];
    let n = a.t_s.iter().take_while(|t| **t <= t_max).count();
    for i in 0..n.min(b.t_s.len()) {
        e[1] = e[1].max((a.lateral_accel_m_s2[i] + b.lateral_accel_m_s2[i]).abs());
        e[2] = e[2].max((a.ltr[i] - b.ltr[i]).abs());
        e[3] = e[3].max((a.roll_rad[i] + b.roll_rad[i]).abs());
        // left tires of one run carry the loads of the right tires of the other
        for (l, r) in [(0, 1), (2, 5), (3, 4)] {
            e[4] = e[4].max((a.normal_force_n[l][i] - b.normal_force_n[r][i]).abs());
        }
    }
    e
}

#[test]
fn left_and_right_ramps_mirror_on_level_ground() {
    let opts = RunOptions::default();
    let left = simulate(&smooth(SteerDirection::Left), &opts).unwrap();
    let right = simulate(&smooth(SteerDirection::Right), &opts).unwrap();
    assert!(
        left.lateral_accel_m_s2.iter().any(|a| *a > 2.0),
        "a left turn"
    );
    let e = mirror_errors(&left, &right, f64::INFINITY);
    assert!(
        e[0] < 1e-4 && e[1] < 1e-3 && e[2] < 1e-5 && e[3] < 1e-5 && e[4] < 10.0,
        "{e:?}"
    );
}

#[test]
fn left_and_right_ramps_mirror_on_swapped_rough_tracks() {
    let p = TruckParams::nominal();
    let spec = TwoTrackSpec::paper_nominal();
    let terrain = rough_terrain(&p, &spec, 500.0, 7).unwrap();
    let profile = terrain.profile();
    let swapped = TwoTrackTerrain::new(
        TwoTrackProfile {
            dx_m: profile.dx_m,
            left_m: profile.right_m.clone(),
            right_m: profile.left_m.clone(),
        },
        SurfaceParams {
            ..*terrain.params()
        },
    )
    .unwrap();
    // tight tolerance: the two runs take different adaptive steps, and on rough ground
    // the integration error of the default rtol (1e-4) shows as percent-level differences;
    // at 1e-7 the roll difference is still integration error (4.96e-5 to 1.9e-4 rad as
    // round-off moves the steps), at 1e-8 it is 4e-6 to 1e-5
    let opts = RunOptions {
        rtol: 1e-8,
        ..RunOptions::default()
    };
    let a = simulate(
        &truck_on(&p, &terrain, SteerDirection::Left, 480.0).unwrap(),
        &opts,
    );
    let b = simulate(
        &truck_on(&p, &swapped, SteerDirection::Right, 480.0).unwrap(),
        &opts,
    );
    let (a, b) = (a.unwrap(), b.unwrap());
    let e = mirror_errors(&a, &b, a.rollover_s.unwrap() - 1.0);
    assert!(
        e[0] < 1e-4 && e[1] < 2e-3 && e[2] < 2e-3 && e[3] < 1e-4 && e[4] < 1e3,
        "{e:?}"
    );
}

/// The caches built as the run reaches them (how the studies build them) give the run of
/// the caches built at once, to the bit; the run stops at 8 s, a sixth of the path.
#[test]
fn a_truck_with_caches_built_on_demand_runs_as_one_built_at_once() {
    let p = TruckParams::nominal();
    let terrain = rough_terrain(&p, &TwoTrackSpec::paper_nominal(), 500.0, 5).unwrap();
    let opts = RunOptions {
        t_end_s: 8.0,
        ..RunOptions::default()
    };
    let at_once = truck_on(&p, &terrain, SteerDirection::Left, 480.0).unwrap();
    let half_width = 0.5 * terrain.params().track_width_m;
    let model = *at_once.options();
    let later = TruckVehicle::on_demand(&p, std::sync::Arc::new(terrain), half_width, model);
    let (a, b) = (simulate(&at_once, &opts), simulate(&later.unwrap(), &opts));
    assert_eq!(a.unwrap(), b.unwrap());
}

#[test]
fn same_seed_same_run_other_seed_other_run() {
    let p = TruckParams::nominal();
    let spec = TwoTrackSpec::paper_nominal();
    let opts = RunOptions::default();
    let run = |seed: u64| {
        let t = rough_terrain(&p, &spec, 500.0, seed).unwrap();
        simulate(
            &truck_on(&p, &t, SteerDirection::Left, 480.0).unwrap(),
            &opts,
        )
        .unwrap()
    };
    let (a, b, c) = (run(3), run(3), run(4));
    assert_eq!(a, b);
    assert_ne!(a.ltr, c.ltr);
}

#[test]
fn straight_run_on_level_ground_stays_straight() {
    let v = smooth(SteerDirection::Straight);
    let opts = RunOptions {
        t_end_s: 20.0,
        ..RunOptions::default()
    };
    let rec = simulate(&v, &opts).unwrap();
    assert_eq!(rec.rollover_s, None);
    // the sprung-cg channels are recorded only on request
    assert!(rec.sprung_lateral_accel_m_s2.is_empty());
    assert!(rec.ltr.iter().all(|l| l.abs() < 1e-9));
    assert!(rec.lateral_accel_m_s2.iter().all(|a| a.abs() < 1e-9));
    assert!(rec.roll_rad.iter().all(|r| r.abs() < 1e-9));
    let v_end = *rec.speed_m_s.last().unwrap();
    assert!((v_end - 40.0 / 3.6).abs() < 1e-3, "speed {v_end}");
}

#[test]
fn bad_inputs_are_rejected_with_the_field_named() {
    let mut p = TruckParams::nominal();
    p.tire_free_radius_m = -1.0;
    let e = TruckVehicle::new(&p, &level_ground(), 1.0, ModelOptions::default()).unwrap_err();
    assert!(e.to_string().contains("tire_free_radius_m"), "{e}");
    let options = ModelOptions {
        track_grid_m: 0.0,
        ..ModelOptions::default()
    };
    let e = TruckVehicle::new(&TruckParams::nominal(), &level_ground(), 1.0, options);
    assert!(e.unwrap_err().to_string().contains("track_grid_m"));
    let opts = RunOptions {
        output_dt_s: 1e-9,
        ..RunOptions::default()
    };
    let e = simulate(&smooth(SteerDirection::Left), &opts).unwrap_err();
    assert!(e.to_string().contains("output_dt_s"), "{e}");
}

/// The plausible truck on the smooth ramp: its stops engage later and its DRT is higher
/// than the calibrated truck's; the a_y channels agree with each other before the stops
/// (sprung cg against whole vehicle; the sprung-fixed sensor reads `a_y cos(phi) + g
/// sin(phi)`).
#[test]
fn plausible_truck_and_the_lateral_acceleration_channels_on_the_smooth_ramp() {
    let p = TruckParams::plausible();
    let (front, rear) = p.bump_stop_roll_angles_deg();
    assert!(
        (front - 10.3).abs() < 0.05 && (rear - 8.93).abs() < 0.05,
        "{front} {rear}"
    );
    let v = TruckVehicle::new(&p, &level_ground(), 1.0, ModelOptions::default()).unwrap();
    let opts = RunOptions {
        acceleration_channels: true,
        ..RunOptions::default()
    };
    let rec = simulate(&v, &opts).unwrap();
    let m = roll_truck::measures::roll_measures(&p, &rec, &Default::default()).unwrap();
    let drt = m.drt_g.unwrap();
    assert!(drt > 0.36 && drt < 0.42, "plausible smooth DRT {drt}");
    let first_stop = m.first_bump_stop_s.unwrap();
    assert!(first_stop > 20.0, "first stop at {first_stop} s");
    assert!(m.peak_ay_before_stop_g <= m.peak_ay_g);
    let g = p.gravity_m_s2;
    let mut checked = 0;
    for i in 0..rec.t_s.len() {
        let (t, ay) = (rec.t_s[i], rec.lateral_accel_m_s2[i]);
        if t < 10.0 || t > first_stop {
            continue;
        }
        let (sprung, sensor, phi) = (
            rec.sprung_lateral_accel_m_s2[i],
            rec.sprung_sensor_lateral_accel_m_s2[i],
            rec.roll_rad[i],
        );
        assert!(
            (sprung - ay).abs() < 0.02 * ay.abs() + 0.01,
            "t {t}: {sprung} vs {ay}"
        );
        let expected = sprung * phi.cos() + g * phi.sin();
        assert!(
            (sensor - expected).abs() < 0.02,
            "t {t}: {sensor} vs {expected}"
        );
        checked += 1;
    }
    assert!(checked > 1000, "{checked} samples");
}

#[test]
fn a_measured_road_equal_to_a_synthesized_terrain_gives_its_run_and_a_short_one_is_refused() {
    use perf_measures::roll::SustainedPeriodParams;
    use roll_truck::studies::{road_length_needed_m, run_case_on, run_case_on_road, TERRAIN_DX_M};
    let p = TruckParams::nominal();
    let spec = TwoTrackSpec::paper_nominal();
    let opts = RunOptions {
        t_end_s: 6.0,
        ..RunOptions::default()
    };
    let sp = SustainedPeriodParams::default();
    let length = 120.0;
    let synthesized = run_case_on(
        &p,
        Some(&spec),
        2,
        length,
        SteerDirection::Right,
        &opts,
        &sp,
    )
    .unwrap();
    let profile = terrain_psd::synthesize(&spec, length, TERRAIN_DX_M, 2).unwrap();
    let road = run_case_on_road(&p, profile.clone(), SteerDirection::Right, &opts, &sp).unwrap();
    assert_eq!(road, synthesized);
    // the road must cover the run: the start, the path 10 % over plus 10 m, a wheelbase and
    // a tire diameter
    let need = road_length_needed_m(&p, &opts);
    let by_hand =
        5.0 + p.target_speed_m_s * 6.0 * 1.1 + 10.0 + p.wheelbase_m + 2.0 * p.tire_free_radius_m;
    assert!((need - by_hand).abs() < 1e-9, "{need} vs {by_hand}");
    let n = (need / TERRAIN_DX_M) as usize - 1;
    let short = TwoTrackProfile {
        dx_m: TERRAIN_DX_M,
        left_m: profile.left_m[..n].to_vec(),
        right_m: profile.right_m[..n].to_vec(),
    };
    let e = run_case_on_road(&p, short, SteerDirection::Right, &opts, &sp)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("needs") && e.contains(&format!("{need:.1} m")),
        "{e}"
    );
}
