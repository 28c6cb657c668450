//! Physics checks of the 3-D vehicle: the static pose is an equilibrium at the hand-computed
//! tire loads, energy is conserved with every loss off, mirrored inputs give mirrored
//! motion, and a straight run on flat ground stays straight.

use odeint::OdeSystem;
use vehicle_3d::{simulate, FrontAxle, Load, RunOptions, Vehicle, VehicleOptions, VehicleParams};
use vehicle_components::FlatTerrain;
use vehicle_components::SteerInput;

fn flat() -> FlatTerrain {
    FlatTerrain::new(0.0, 0.8).unwrap()
}

fn vehicle(p: &VehicleParams, load: Load, options: VehicleOptions) -> Vehicle {
    Vehicle::new(p, load, options, &flat(), 0.5 * p.front_track_m).unwrap()
}

#[test]
fn static_pose_is_an_equilibrium_at_the_hand_loads() {
    let p = VehicleParams::nominal();
    for axle in [FrontAxle::Rigid, FrontAxle::Suspended] {
        for (load, front, rear) in [
            (Load::Unloaded, 122.69e3, 71.06e3),
            (Load::Loaded, 149.83e3, 209.32e3),
        ] {
            let options = VehicleOptions {
                front_axle: axle,
                // at standstill: no rolling resistance, no drive
                speed_m_s: 1e-9,
                ..Default::default()
            };
            let v = vehicle(&p, load, options);
            let y = v.initial_state();
            let mut d = vec![0.0; y.len()];
            v.rhs(0.0, &y, &mut d);
            let o = v.offsets();
            let worst = d[o.v..o.afs].iter().fold(0.0f64, |m, x| m.max(x.abs()));
            assert!(
                worst < 1e-6,
                "{axle:?} {load:?}: accelerations {:?}",
                &d[o.v..o.afs]
            );
            let rec = simulate(
                &v,
                &RunOptions {
                    t_end_s: 0.1,
                    output_dt_s: 0.1,
                    ..Default::default()
                },
            )
            .unwrap();
            let fz: Vec<f64> = rec.normal_force_n.iter().map(|c| c[0]).collect();
            for (f, hand) in fz.iter().zip([front, front, rear, rear]) {
                assert!((f / hand - 1.0).abs() < 0.005, "{axle:?} {load:?}: {fz:?}");
            }
        }
    }
}

#[test]
fn energy_is_conserved_without_losses() {
    let mut p = VehicleParams::nominal();
    p.tire.vertical_damping_n_s_per_m = 0.0;
    p.tire.u_max = 1e-12;
    p.tire.u_min = 1e-12;
    p.tire.rolling_resistance_coefficient = 0.0;
    p.steering.leak_const = 0.0;
    p.steering.leak_velocity = 0.0;
    p.steering.seal_viscous_n_s_m = 0.0;
    // no drive torque
    p.drive.kp_n_m_per_m_s = 1e-12;
    p.drive.ki_n_m_per_m = 0.0;
    let options = VehicleOptions {
        speed_m_s: 3.0,
        ..Default::default()
    };
    let v = vehicle(&p, Load::Loaded, options);
    let o = *v.offsets();
    let j = *v.joints();
    let mut y = v.initial_state();
    // bounce, pitch, roll, an articulation swing and a rear-unit roll
    y[o.v + 5] = 0.2;
    y[o.v + 1] = 0.05;
    y[o.v] = 0.08;
    y[o.v + j.articulation.1] = 0.05;
    y[o.v + j.rear_roll.unwrap().1] = -0.06;
    let e0 = v.energy(&y).unwrap();
    // fixed RK4 steps of 0.2 ms over 1 s, the energy at every millisecond
    let t_out: Vec<f64> = (1..=1000).map(|i| i as f64 * 1e-3).collect();
    let mut max_dev = 0.0f64;
    odeint::Integrator::new(odeint::Solver::Rk4 { step: 2e-4 }, 1e-6, 1e-6)
        .run(
            &v,
            &odeint::Problem::new(0.0, &y, &t_out),
            &mut odeint::Workspace::new(y.len()),
            |s| {
                max_dev = max_dev.max((v.energy(s.y).unwrap() - e0).abs());
                odeint::Control::Continue
            },
        )
        .unwrap();
    let scale = 0.5 * v.tree().total_mass() * 3.0f64.powi(2);
    assert!(
        max_dev < 1e-6 * scale,
        "energy drift {max_dev} J of {scale} J"
    );
}

/// Mirrored steering pulses give mirrored motion: articulation, rear-unit roll and lateral
/// position of the front unit, integrated with fixed RK4 steps so that both runs take the
/// same steps (an adaptive step controller may accept a step in one run and reject it in the
/// other when an error ratio sits at 1, which moves the runs apart by the tolerance). Rigid
/// front axle: to 1e-9 of the peaks. With the HPS the check valves switch on a pressure
/// comparison, so the round-off that differs between the left and right computations moves a
/// switching instant, and the mirror images agree to 1 % of the peak roll.
#[test]
fn mirrored_pulses_give_mirrored_motion() {
    use odeint::{Control, Integrator, Problem, Solver};
    let p = VehicleParams::nominal();
    let t_out: Vec<f64> = (0..=300).map(|i| i as f64 * 0.01).collect();
    for (axle, tolerance) in [(FrontAxle::Rigid, 1e-9), (FrontAxle::Suspended, 1e-2)] {
        let run = |amp: f64| {
            let options = VehicleOptions {
                front_axle: axle,
                steer: SteerInput::pulse_deg(amp, 0.2, 0.5),
                speed_m_s: 10.0,
                ..Default::default()
            };
            let v = vehicle(&p, Load::Loaded, options);
            let j = *v.joints();
            let y0 = v.initial_state();
            let mut out = Vec::new();
            Integrator::new(Solver::Rk4 { step: 2e-4 }, 1e-6, 1e-6)
                .run(
                    &v,
                    &Problem::new(0.0, &y0, &t_out),
                    &mut odeint::Workspace::new(y0.len()),
                    |s| {
                        out.push([s.y[j.articulation.0], s.y[j.rear_roll.unwrap().0], s.y[1]]);
                        Control::Continue
                    },
                )
                .unwrap();
            out
        };
        let (a, b) = (run(60.0), run(-60.0));
        let peak = |k: usize| a.iter().fold(0.0f64, |m, v| m.max(v[k].abs()));
        let scale = [peak(0), peak(1), peak(2).max(1e-3)];
        assert!(
            scale[0] > 0.01 && scale[1] > 1e-3,
            "the pulse must articulate and roll"
        );
        for (i, (x, y)) in a.iter().zip(&b).enumerate() {
            for k in 0..3 {
                assert!(
                    (x[k] + y[k]).abs() <= tolerance * scale[k],
                    "{axle:?} t = {}: channel {k}: {} vs {}",
                    t_out[i],
                    x[k],
                    y[k]
                );
            }
        }
    }
}

#[test]
fn straight_run_on_flat_ground_stays_straight() {
    let p = VehicleParams::nominal();
    let v = vehicle(&p, Load::Unloaded, VehicleOptions::default());
    let rec = simulate(&v, &RunOptions::default()).unwrap();
    let last = rec.len() - 1;
    assert!(rec.position_m[1][last].abs() < 1e-9);
    assert!(rec.articulation_rad[last].abs() < 1e-12);
    // the PI drive holds the speed within 1 %
    assert!(
        (rec.speed_m_s[last] / (20.0 / 3.6) - 1.0).abs() < 0.01,
        "{}",
        rec.speed_m_s[last]
    );
}
