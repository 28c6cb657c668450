//! Energy check of the printed equations (issue: "with tires, leakage and friction switched
//! off, total kinetic energy plus hydraulic energy must be conserved").

use afs_hydraulics::{AfsParams, AfsSystem};
use afsv_dynamics::yaw_plane::mechanics::{kinetic_energy, Motion};
use afsv_dynamics::{
    EquationForm, SteerInput, SteerSource, SteeringActuator, VehicleParams, YawPlaneModel,
};
use odeint::{Atol, Control, Integrator, Solver};

fn lossless() -> (VehicleParams, AfsSystem) {
    let mut v = VehicleParams::loaded();
    v.c_alpha_f_n_per_rad = 0.0;
    v.c_alpha_r_n_per_rad = 0.0;
    v.k_mz_f_nm_per_rad = 0.0;
    v.k_mz_r_nm_per_rad = 0.0;
    let mut a = AfsParams::nominal();
    a.leak_const = 0.0;
    a.leak_velocity = 0.0;
    a.seal_viscous_n_s_m = 0.0;
    (v, AfsSystem::new(a).unwrap())
}

/// Runs a free articulation oscillation (initial front yaw rate, valve centred) and returns
/// the largest relative deviation of KE + E_hyd - W_traction from its initial value.
fn energy_drift(speed: f64, form: EquationForm) -> f64 {
    let (v, sys) = lossless();
    let steer = SteerSource::Open(SteerInput::None);
    let model = YawPlaneModel::new(&v, &sys, speed, &steer, form);
    let mut y0 = model.initial_state(0.0);
    y0[2] = 0.3; // front yaw rate (rad/s)
    let t_out = odeint::output_grid(0.0, 3.0, 1e-4);
    let mut e0 = None;
    let mut worst: f64 = 0.0;
    let mut work = 0.0;
    let mut last: Option<(f64, f64)> = None; // (t, traction power)
    let mut d = vec![0.0; y0.len()];
    let act0 = model.layout().act0;
    let atol = Atol::scaled(1e-12, (0..y0.len()).map(|i| model.state_typical(i)));
    Integrator::new(Solver::Dopri5, 1e-11, atol)
        .integrate(&model, 0.0, &y0, &t_out, |t, y| {
            let e = model.evaluate(t, y, &mut d);
            let m = Motion {
                theta: y[0],
                u_f: speed,
                v_f: y[1],
                r_f: y[2],
                r_r: y[3],
            };
            let state = [y[act0], y[act0 + 1], y[act0 + 2]];
            let power = e.acc.traction_force * speed;
            if let Some((tp, pp)) = last {
                work += 0.5 * (power + pp) * (t - tp);
            }
            last = Some((t, power));
            let total = kinetic_energy(&v, &m) + sys.energy(y[0], 0.0, &state) - work;
            let base = *e0.get_or_insert(total);
            // Scale by the initial kinetic energy of the yaw motion (~2 kJ).
            worst = worst.max((total - base).abs());
            Control::Continue
        })
        .unwrap();
    let m0 = Motion {
        theta: 0.0,
        u_f: speed,
        v_f: 0.0,
        r_f: 0.3,
        r_r: 0.0,
    };
    let m_still = Motion { r_f: 0.0, ..m0 };
    let yaw_ke = kinetic_energy(&v, &m0) - kinetic_energy(&v, &m_still);
    let rel = worst / yaw_ke;
    eprintln!("{form:?} at {speed:.2} m/s: max |E - E0| / E_yaw = {rel:.3e}");
    rel
}

#[test]
fn energy_consistent_form_conserves_energy_at_rest_and_at_speed() {
    let d0 = energy_drift(0.0, EquationForm::EnergyConsistent);
    assert!(d0 < 5e-4, "relative energy drift at u = 0: {d0:e}");
    let d1 = energy_drift(50.0 / 3.6, EquationForm::EnergyConsistent);
    assert!(
        d1 < 1e-3,
        "relative energy drift at 50 km/h (traction work counted): {d1:e}"
    );
}

#[test]
fn printed_eq_3_13_does_not_conserve_energy() {
    let d = energy_drift(0.0, EquationForm::PaperEq313);
    assert!(
        d > 0.05,
        "printed form should violate the energy balance, drift {d:e}"
    );
}
