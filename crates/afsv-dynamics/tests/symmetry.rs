//! Mirror symmetry, switchable tire lag, and the power balance as a property.

use afs_hydraulics::{AfsParams, AfsSystem};
use afsv_dynamics::yaw_plane::mechanics::{
    accelerations, kinetic_energy, Loads, Motion, UnitGeometry,
};
use afsv_dynamics::{
    simulate, EquationForm, Load, Manoeuvre, SimOptions, SteerInput, VehicleParams,
};
use proptest::prelude::*;

#[test]
fn mirrored_steering_gives_mirrored_response() {
    let sys = AfsSystem::new(AfsParams::nominal()).unwrap();
    for load in Load::ALL {
        let v = VehicleParams::nominal(load);
        let o = SimOptions::default();
        let a = simulate(&v, &sys, &Manoeuvre::step(50.0 / 3.6, 30.0), &o).unwrap();
        let b = simulate(&v, &sys, &Manoeuvre::step(50.0 / 3.6, -30.0), &o).unwrap();
        let peak = a
            .articulation_deg
            .iter()
            .fold(0.0f64, |m, x| m.max(x.abs()));
        for i in 0..a.time_s.len() {
            assert!((a.articulation_deg[i] + b.articulation_deg[i]).abs() < 1e-3 * peak);
            assert!((a.p_c_pa[i] - b.p_r_pa[i]).abs() < 1e-3 * 1e7);
        }
    }
}

#[test]
fn relaxation_length_zero_removes_the_lag_states() {
    let sys = AfsSystem::new(AfsParams::nominal()).unwrap();
    let mut v = VehicleParams::loaded();
    let man = Manoeuvre::open_loop(50.0 / 3.6, 4.0, SteerInput::step_deg(30.0, 0.5), "step");
    let lag = simulate(&v, &sys, &man, &SimOptions::default()).unwrap();
    v.relaxation_length_m = 0.0;
    let nolag = simulate(&v, &sys, &man, &SimOptions::default()).unwrap();
    assert_eq!(lag.states.len(), nolag.states.len() + 4);
    assert!(!nolag.states.iter().any(|(n, _)| n.starts_with("slip_")));
    // Same steady articulation (the lag only shapes the transient), different transient.
    let n = lag.time_s.len() - 1;
    assert!((lag.articulation_deg[n] - nolag.articulation_deg[n]).abs() < 0.02);
    let dy: f64 = lag
        .yaw_rate_front_deg_s
        .iter()
        .zip(&nolag.yaw_rate_front_deg_s)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(dy > 1e-3);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    /// dKE/dt = T_s dtheta/dt + F_x u_f + tire power for any state (energy-consistent form).
    #[test]
    fn power_balance_holds(theta in -0.6f64..0.6, u in 0.0f64..20.0, v in -1.0f64..1.0,
                           rf in -0.5f64..0.5, rr in -0.5f64..0.5, ts in -3e5f64..3e5,
                           yf in -5e4f64..5e4, yr in -5e4f64..5e4, loaded in any::<bool>()) {
        let p = if loaded { VehicleParams::loaded() } else { VehicleParams::unloaded() };
        let g = UnitGeometry::new(&p, EquationForm::EnergyConsistent);
        let m = Motion { theta, u_f: u, v_f: v, r_f: rf, r_r: rr };
        let f = Loads { y_front: yf, y_rear: yr, steering_torque: ts, ..Loads::default() };
        let a = accelerations(&g, &m, &f);
        let h = 1e-6;
        let step = |s: f64| Motion {
            theta: theta + s * h * (rf - rr),
            v_f: v + s * h * a.dv_f,
            r_f: rf + s * h * a.dr_f,
            r_r: rr + s * h * a.dr_r,
            ..m
        };
        let dke = (kinetic_energy(&p, &step(1.0)) - kinetic_energy(&p, &step(-1.0))) / (2.0 * h);
        // Tire power: lateral force times the axle's lateral velocity in its unit frame.
        let (_, v_r) = afsv_dynamics::yaw_plane::mechanics::rear_velocities(&g, &m);
        let p_tires = yf * (v + p.l_f1_m * rf) + yr * (v_r - p.l_r1_m * rr);
        let power = ts * (rf - rr) + a.traction_force * u + p_tires;
        prop_assert!((dke - power).abs() < 1e-5 * (power.abs() + 1e3), "{} vs {}", dke, power);
    }
}
