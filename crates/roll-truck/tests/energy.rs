//! Energy conservation of the whole truck with dampers and tire damping off, no drive
//! and no lateral tire force (relaxation length so long that the lag states stay at zero):
//! kinetic + gravitational + strut + bump-stop + tire-spring energy is constant, at the
//! nominal roll centres and with the front tires hanging from the ground point of their
//! carriers and the rear roll joint 0.4 m above the axle.

use odeint::{Control, Integrator, Solver};
use roll_truck::measures::level_ground;
use roll_truck::{ModelOptions, SteerDirection, TruckParams, TruckVehicle};

#[test]
fn conservative_truck_keeps_its_energy() {
    let mut moved = TruckParams::nominal();
    moved.front_roll_centre_height_m = 0.0;
    moved.rear_roll_centre_height_m += 0.4;
    for p in [TruckParams::nominal(), moved] {
        keeps_its_energy(p);
    }
}

fn keeps_its_energy(mut p: TruckParams) {
    p.front_damping_n_s_per_m = 0.0;
    p.rear_damping_n_s_per_m = 0.0;
    p.tire_vertical_damping_n_s_per_m = 0.0;
    p.speed_kp_n_per_m_s = 0.0;
    p.speed_ki_n_per_m = 0.0;
    p.relaxation_length_m = 1.0e9;
    let options = ModelOptions {
        direction: SteerDirection::Straight,
        path_length_m: 40.0,
        ..ModelOptions::default()
    };
    let v = TruckVehicle::new(&p, &level_ground(), 1.0, options).unwrap();
    let mut y = v.initial_state(3.0);
    // roll, pitch and yaw rates, bounce, carrier and axle motions (body coordinates)
    let v0 = [0.15, -0.05, 0.02, 3.0, 0.0, 0.2, 0.3, -0.2, 0.25, 0.4];
    y[11..21].copy_from_slice(&v0);
    y[7] = 0.03;
    y[10] = 0.02;
    let e0 = v.energy(&y).unwrap();
    let scale = v.energy(&v.initial_state(0.0)).unwrap();
    let perturbation = e0 - scale;
    assert!(perturbation > 1e3, "perturbation energy {perturbation}");
    let integrator = Integrator::new(Solver::Dopri5, 1e-10, 1e-12);
    let t_out: Vec<f64> = (0..=40).map(|i| 0.1 * i as f64).collect();
    let mut worst = 0.0_f64;
    integrator
        .integrate(&v, 0.0, &y, &t_out, |_, s| {
            worst = worst.max((v.energy(s).unwrap() - e0).abs());
            Control::Continue
        })
        .unwrap();
    assert!(
        worst < 1e-5 * perturbation,
        "energy drift {worst} J of a {perturbation} J perturbation"
    );
}
