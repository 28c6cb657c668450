//! Statics: the model's equilibrium is the hand calculation of Table 2.1 (note 1.9,
//! target R2.14), and a perturbed truck driving straight at 40 km/h settles back to it
//! within 0.5 % (30 s). The settling run uses struts at the wheel stations (ratio 1): the
//! calibrated roll stiffness is close to neutral and its roll mode takes minutes to
//! settle, while the static loads do not depend on the ratio.

use odeint::{Control, Integrator, Solver};
use roll_truck::measures::level_ground;
use roll_truck::vehicle::state;
use roll_truck::{ModelOptions, SteerDirection, TruckParams, TruckVehicle};

/// Table 2.1 by hand: 73 840 kg sprung with its cg 2.57 m behind the front axle of a
/// 4.02 m wheel base, 3 900 kg front and 7 800 kg rear unsprung, g = 9.81.
fn hand_loads() -> (f64, f64) {
    let g = 9.81;
    let front = (73_840.0 * g * (4.02 - 2.57) / 4.02 + 3_900.0 * g) / 2.0;
    let rear = (73_840.0 * g * 2.57 / 4.02 + 7_800.0 * g) / 4.0;
    (front, rear)
}

fn straight(strut_spacing_ratio: f64) -> TruckVehicle {
    let mut p = TruckParams::nominal();
    p.strut_spacing_ratio = strut_spacing_ratio;
    let options = ModelOptions {
        direction: SteerDirection::Straight,
        path_length_m: 800.0,
        ..ModelOptions::default()
    };
    TruckVehicle::new(&p, &level_ground(), 1.0, options).unwrap()
}

fn normal_forces(v: &TruckVehicle, y: &[f64]) -> [f64; 6] {
    roll_truck::simulate::tire_state(v, 0.0, y)
        .unwrap()
        .normal_force
}

#[test]
fn static_state_is_an_equilibrium_with_the_hand_loads() {
    let v = straight(TruckParams::nominal().strut_spacing_ratio);
    let y = v.initial_state(40.0 / 3.6);
    let mut dy = [0.0; state::DIM];
    odeint::OdeSystem::rhs(&v, 0.0, &y, &mut dy);
    let vdot = &dy[state::V..state::V + 10];
    assert!(vdot.iter().all(|a| a.abs() < 1e-9), "{vdot:?}");
    let (front, rear) = hand_loads();
    let fz = normal_forces(&v, &y);
    for (i, f) in fz.iter().enumerate() {
        let hand = if i < 2 { front } else { rear };
        assert!((f / hand - 1.0).abs() < 1e-9, "tire {i}: {f} vs {hand}");
    }
    assert!((front / 1e3 - 149.8).abs() < 0.05 && (rear / 1e3 - 134.9).abs() < 0.05);
}

#[test]
fn perturbed_truck_settles_to_the_hand_loads_within_half_a_percent() {
    let v = straight(1.0);
    let mut y = v.initial_state(40.0 / 3.6);
    y[2] += 0.04; // sprung cg 4 cm high
    y[4] = (0.5_f64 * 0.03).sin(); // 0.03 rad roll
    y[3] = (0.5_f64 * 0.03).cos();
    y[7] = 0.02; // front-left carrier up
    y[10] = -0.01; // rear axle roll
    let integrator = Integrator::new(Solver::Dopri5, 1e-6, 1e-8);
    let mut last = y;
    integrator
        .integrate(&v, 0.0, &y, &[0.0, 30.0], |_, s| {
            last.copy_from_slice(s);
            Control::Continue
        })
        .unwrap();
    let (front, rear) = hand_loads();
    let fz = normal_forces(&v, &last);
    for (i, f) in fz.iter().enumerate() {
        let hand = if i < 2 { front } else { rear };
        assert!((f / hand - 1.0).abs() < 0.005, "tire {i}: {f} vs {hand}");
    }
}
