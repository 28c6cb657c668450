//! V3 path change (section 6.3, Fig 3.6(b)) with the path-following driver: mirror
//! symmetry, course following, and the peaks against the yaw-plane model's path change at
//! the same speed and load.

use afs_hydraulics::{AfsParams, AfsSystem};
use afsv_dynamics::{Manoeuvre, PathDriver, SimOptions};
use vehicle_3d::scenarios::{path_change, PathChangeMeasures, PathChangeSpec};
use vehicle_3d::{FrontAxle, Load, VehicleParams};

fn run(spec: &PathChangeSpec) -> (vehicle_3d::RunRecord, PathChangeMeasures) {
    path_change(&VehicleParams::nominal(), spec, 0).unwrap()
}

/// Peaks of the yaw-plane model's path change (Chapter 3) at the speed and load of `spec`:
/// articulation (deg), left strut (min, max, m), front yaw rate (deg/s), front lateral
/// acceleration (m/s²), all signed as the 3-D measures.
/// With `tires_of_3d`, the yaw-plane model gets the 3-D model's tire data: the Table 6.2
/// cornering stiffness of its static axle loads (docs/tire-fiala.md) and the 1.2 m
/// relaxation length.
fn yaw_plane_peaks(spec: &PathChangeSpec, tires_of_3d: bool) -> (f64, (f64, f64), f64, f64) {
    let load = match spec.load {
        Load::Loaded => afsv_dynamics::Load::Loaded,
        Load::Unloaded => afsv_dynamics::Load::Unloaded,
    };
    let mut vehicle = afsv_dynamics::VehicleParams::nominal(load);
    if tires_of_3d {
        let per_deg = 180.0 / std::f64::consts::PI;
        let (front, rear) = match spec.load {
            Load::Loaded => (6.8e3, 7.5e3),
            Load::Unloaded => (6.1e3, 3.7e3),
        };
        vehicle.c_alpha_f_n_per_rad = front * per_deg;
        vehicle.c_alpha_r_n_per_rad = rear * per_deg;
        vehicle.relaxation_length_m = 1.2;
    }
    let sys = AfsSystem::new(AfsParams::nominal()).unwrap();
    let man = Manoeuvre::course(
        spec.speed_kmh / 3.6,
        spec.t_end_s,
        PathDriver::new(spec.course()),
        "path_change",
    );
    let r = afsv_dynamics::simulate(&vehicle, &sys, &man, &SimOptions::default()).unwrap();
    let peak = |x: &[f64]| {
        x.iter()
            .fold(0.0f64, |m, v| if v.abs() > m.abs() { *v } else { m })
    };
    let d = &r.strut_left_disp_m;
    (
        peak(&r.articulation_deg),
        (
            d.iter().fold(0.0f64, |m, v| m.min(*v)),
            d.iter().fold(0.0f64, |m, v| m.max(*v)),
        ),
        peak(&r.yaw_rate_front_deg_s),
        peak(&r.lateral_accel_front_m_s2),
    )
}

/// Largest |a - b| relative to the larger magnitude.
fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / a.abs().max(b.abs())
}

#[test]
fn path_change_follows_the_course_and_matches_the_yaw_plane_model() {
    for load in [Load::Loaded, Load::Unloaded] {
        let spec = PathChangeSpec::v3(load, FrontAxle::Rigid);
        let (rec, m) = run(&spec);
        let (theta, strut, r, ay) = yaw_plane_peaks(&spec, false);
        eprintln!(
            "{load:?} 3-D {m:?}\n    yaw plane {:?}",
            (theta, strut, r, ay)
        );
        // follows the course (measured 0.24 m loaded, 0.48 m unloaded) and ends in the
        // new lane; the yaw-plane model allows 1.5 m for pure pursuit's corner cutting
        assert!(
            m.max_deviation_m < 1.0,
            "{load:?}: deviation {}",
            m.max_deviation_m
        );
        assert!(
            (m.final_offset_m - 4.5).abs() < 0.1,
            "{load:?}: {}",
            m.final_offset_m
        );
        // the driver steers: the wheel turns right first, then back through zero
        let sw = &rec.steer_wheel_rad;
        assert!(sw.iter().any(|a| *a > 0.1) && sw.iter().any(|a| *a < -0.1));
        // Cross-model check. Shared: the driver, the axle distances (1.68 / 3.44 m), the
        // steering hydraulics, the course and speed, so the yaw rate and lateral
        // acceleration, which the path and speed fix, agree closely (measured within 4 %
        // loaded, 8 % unloaded): 12 % allowed. Different: Fiala tires with load-dependent
        // cornering stiffness and 1.2 m relaxation (Table 6.2) against Table 3.1's linear
        // tires with 0.4 m, the Table 6.1 masses against Table 3.1's, rear-unit roll. The
        // articulation a path needs depends on the front and rear slip, so it and the strut
        // travel that follows it differ more (3-D 13 % lower loaded, 16 % unloaded): 25 %
        // allowed. Every peak has the same sign in both models.
        for (what, a, b, tol) in [
            ("articulation", m.peak_articulation_deg, theta, 0.25),
            ("left strut min", m.strut_left_range_m.0, strut.0, 0.25),
            ("left strut max", m.strut_left_range_m.1, strut.1, 0.25),
            ("yaw rate", m.peak_yaw_rate_deg_s, r, 0.12),
            ("lateral acceleration", m.peak_lateral_accel_m_s2, ay, 0.12),
        ] {
            assert!(a * b > 0.0, "{load:?} {what}: signs differ, {a} vs {b}");
            assert!(rel(a, b) < tol, "{load:?} {what}: 3-D {a} vs yaw plane {b}");
        }
        // The articulation gap is the tire data: given the 3-D model's cornering stiffness
        // and relaxation length, the yaw-plane model's loaded peaks agree within 4 %
        // (measured 0.3 % articulation, 0.7 % yaw rate, 4 % lateral acceleration): 6 %
        // allowed. Unloaded the 3-D truck still turns harder (measured +6 % articulation,
        // +10 % yaw rate, +11 % lateral acceleration; not traced: lateral load transfer,
        // rear-unit roll and Fiala saturation on the light unloaded rear axle are not in the
        // yaw-plane model): 15 % allowed.
        let (theta, _, r, ay) = yaw_plane_peaks(&spec, true);
        let tol = match load {
            Load::Loaded => 0.06,
            Load::Unloaded => 0.15,
        };
        for (what, a, b) in [
            ("articulation", m.peak_articulation_deg, theta),
            ("yaw rate", m.peak_yaw_rate_deg_s, r),
            ("lateral acceleration", m.peak_lateral_accel_m_s2, ay),
        ] {
            eprintln!("{load:?} {what}, same tire data: 3-D {a:.3}, yaw plane {b:.3}");
            assert!(rel(a, b) < tol, "{load:?} {what}: 3-D {a} vs yaw plane {b}");
        }
    }
}

#[test]
fn a_left_path_change_mirrors_a_right_one() {
    let right = PathChangeSpec::v3(Load::Loaded, FrontAxle::Rigid);
    let left = PathChangeSpec {
        offset_m: -right.offset_m,
        ..right
    };
    let (rr, mr) = run(&right);
    let (rl, ml) = run(&left);
    let tol = 1e-6;
    for (what, a, b) in [
        (
            "articulation",
            mr.peak_articulation_deg,
            -ml.peak_articulation_deg,
        ),
        ("yaw rate", mr.peak_yaw_rate_deg_s, -ml.peak_yaw_rate_deg_s),
        (
            "lateral acceleration",
            mr.peak_lateral_accel_m_s2,
            -ml.peak_lateral_accel_m_s2,
        ),
        ("deviation", mr.max_deviation_m, ml.max_deviation_m),
        ("final offset", mr.final_offset_m, -ml.final_offset_m),
    ] {
        assert!(rel(a, b) < tol, "{what}: {a} vs {b}");
    }
    // the left strut of one run is the right strut of the mirrored one
    let range = |d: &[f64]| {
        (
            d.iter().fold(0.0f64, |m, v| m.min(*v)),
            d.iter().fold(0.0f64, |m, v| m.max(*v)),
        )
    };
    let right_strut_of_left_run = range(&rl.strut_disp_m[1]);
    assert!(rel(mr.strut_left_range_m.0, right_strut_of_left_run.0) < tol);
    assert!(rel(mr.strut_left_range_m.1, right_strut_of_left_run.1) < tol);
    // and the lateral positions mirror sample by sample
    let scale = 4.5;
    for (a, b) in rr.front_axle_m[1].iter().zip(&rl.front_axle_m[1]) {
        assert!((a + b).abs() < tol * scale, "{a} vs {b}");
    }
}

#[test]
fn driver_options_are_checked() {
    use afsv_dynamics::{Course, SteerInput};
    use vehicle_3d::{Vehicle, VehicleOptions};
    let p = VehicleParams::nominal();
    let flat =
        vehicle_components::FlatTerrain::new(0.0, vehicle_components::DEFAULT_FRICTION).unwrap();
    let build = |o: VehicleOptions| Vehicle::new(&p, Load::Loaded, o, &flat, 1.0).map(|_| ());
    let driver = Some(PathDriver::new(Course::path_change_fig_3_6()));
    let ok = VehicleOptions {
        driver,
        ..VehicleOptions::default()
    };
    build(ok.clone()).unwrap();
    let both = VehicleOptions {
        steer: SteerInput::pulse_deg(30.0, 0.2, 1.0),
        ..ok.clone()
    };
    assert!(build(both).unwrap_err().to_string().contains("`steer`"));
    let turn = VehicleOptions {
        driver: Some(PathDriver::new(Course::steady_turn_fig_3_6())),
        ..ok.clone()
    };
    assert!(build(turn).unwrap_err().to_string().contains("`driver`"));
    let mut slow = PathDriver::new(Course::path_change_fig_3_6());
    slow.rate_gain_per_s = 0.0;
    let bad = VehicleOptions {
        driver: Some(slow),
        ..ok
    };
    assert!(build(bad)
        .unwrap_err()
        .to_string()
        .contains("rate_gain_per_s"));
}

#[test]
fn the_course_frame_puts_the_front_axle_at_the_course_start() {
    use afsv_dynamics::Course;
    use vehicle_3d::vehicle::course_frame;
    let c = Course::path_change_fig_3_6();
    // world x = axle start (2.0 m), y = 0, heading 0: the course start (-20, 0)
    assert_eq!(course_frame(&c, 2.0, 2.0, 0.0, 0.0), (-20.0, 0.0, 0.0));
    // 1 m to the left in the world is 1 m left (-1, y right) on the course; a left heading
    // is a negative course heading
    assert_eq!(course_frame(&c, 2.0, 7.0, 1.0, 0.1), (-15.0, -1.0, -0.1));
}

/// The V3 path change with the front struts roll-linked (`path_change_linked`): the two
/// lines' circuits mirror between a right and a left path change (each line is the other's
/// mirror), and the link stiffens the front unit's roll on its struts against the unlinked
/// HPS run of the same strut, with the course still followed.
#[test]
fn a_roll_linked_path_change_mirrors_and_rolls_less_on_its_struts() {
    use hps_emulsion::LineParams;
    use vehicle_3d::interconnect::suspension_roll_rad;
    use vehicle_3d::path_change::path_change_linked;
    let p = VehicleParams::nominal();
    let right = PathChangeSpec::v3(Load::Loaded, FrontAxle::Suspended);
    let left = PathChangeSpec {
        offset_m: -right.offset_m,
        ..right
    };
    let line = LineParams::front_axle_roll();
    let (rr, mr) = path_change_linked(&p, &right, 0, &line).unwrap();
    let (rl, ml) = path_change_linked(&p, &left, 0, &line).unwrap();
    // the two runs take their own adaptive steps (the mirrored line states enter the error
    // norm in the other order), so they mirror to the integrator's tolerance, not to
    // round-off as the rigid runs above
    let tol = 1e-3;
    assert!(rel(mr.peak_articulation_deg, -ml.peak_articulation_deg) < tol);
    assert!(rel(mr.peak_yaw_rate_deg_s, -ml.peak_yaw_rate_deg_s) < tol);
    assert!(rel(mr.final_offset_m, -ml.final_offset_m) < tol);
    // line 0 of one run (left piston side to right rod side) is line 1 of the mirrored run
    let scale = rr.node_pressure_pa[0][0];
    for (a, b) in rr.node_pressure_pa[0].iter().zip(&rl.node_pressure_pa[1]) {
        assert!((a - b).abs() < tol * scale, "{a} vs {b}");
    }
    let peak = |x: &[f64]| x.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let (free, _) = path_change(&p, &right, 0).unwrap();
    let roll_linked = peak(&suspension_roll_rad(&p, &rr.record));
    let roll_free = peak(&suspension_roll_rad(&p, &free));
    assert!(
        roll_linked < 0.5 * roll_free,
        "suspension roll {roll_linked} rad linked against {roll_free} rad unlinked"
    );
    assert!(
        mr.max_deviation_m < 0.5,
        "deviation {} m",
        mr.max_deviation_m
    );
    assert!(rel(mr.final_offset_m, right.offset_m) < 0.1);
}
