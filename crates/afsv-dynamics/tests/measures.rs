//! Measures of section 3.3 / 4.3.1, tolerance convergence, cavitation floor, divergence.

use afs_hydraulics::{AfsParams, AfsSystem};
use afsv_dynamics::analysis::{gain_efficiency_correlation, measures_for, steady_turn_decay};
use afsv_dynamics::{
    simulate, yaw_measures, DynError, EquationForm, EquivalentTorsion, Load, Manoeuvre,
    MeasureSpec, SimOptions, Solver, VehicleParams,
};

const U50: f64 = 50.0 / 3.6;

#[test]
fn nominal_measures_are_physical_for_both_loads() {
    for load in Load::ALL {
        let m = yaw_measures(load, U50).unwrap();
        eprintln!("{}", serde_json::to_string(&m).unwrap());
        assert!(m.natural_frequency_hz > 1.0 && m.natural_frequency_hz < 15.0);
        assert!(m.damping_ratio > 0.0 && m.damping_ratio < 0.5);
        assert!(m.decay_fit_r_squared > 0.95);
        // Volume-regulated valve: gain close to the kinematic ratio k_theta eta_g / (A_c h + A_r h).
        let sys = AfsSystem::new(AfsParams::nominal()).unwrap();
        let kin = sys.kinematic_steering_ratio(0.0);
        assert!(
            (m.steering_gain - kin).abs() < 0.3 * kin,
            "gain {} vs kinematic {kin}",
            m.steering_gain
        );
        assert!(m.rise_time_s > 0.02 && m.rise_time_s < 2.0);
        assert!(m.overshoot_percent > 0.0 && m.overshoot_percent < 100.0);
        assert!(m.power_efficiency > 0.0 && m.power_efficiency < 1.0);
    }
}

#[test]
fn printed_form_lowers_the_yaw_mode_frequency() {
    let mut spec = MeasureSpec::default();
    let v = VehicleParams::loaded();
    let a = AfsParams::nominal();
    let e = measures_for(&v, &a, Some(Load::Loaded), U50, &spec).unwrap();
    spec.options.form = EquationForm::PaperEq313;
    let p = measures_for(&v, &a, Some(Load::Loaded), U50, &spec).unwrap();
    eprintln!(
        "loaded: energy-consistent {:.3} Hz, printed {:.3} Hz",
        e.natural_frequency_hz, p.natural_frequency_hz
    );
    // Extra m L^2 in the yaw inertias: much lower frequency.
    assert!(p.natural_frequency_hz < 0.75 * e.natural_frequency_hz);
}

#[test]
fn halving_the_tolerance_changes_frequency_and_gain_by_less_than_half_a_percent() {
    let v = VehicleParams::loaded();
    let a = AfsParams::nominal();
    let mut spec = MeasureSpec::default();
    let m1 = measures_for(&v, &a, None, U50, &spec).unwrap();
    spec.options.rtol *= 0.5;
    spec.options.atol *= 0.5;
    let m2 = measures_for(&v, &a, None, U50, &spec).unwrap();
    let df = (m1.natural_frequency_hz / m2.natural_frequency_hz - 1.0).abs();
    let dg = (m1.steering_gain / m2.steering_gain - 1.0).abs();
    let dz = (m1.damping_ratio / m2.damping_ratio - 1.0).abs();
    eprintln!("tolerance halved: frequency {df:.2e}, gain {dg:.2e}, damping {dz:.2e}");
    assert!(df < 5e-3 && dg < 5e-3, "df {df}, dg {dg}");
    // The explicit and the implicit solver agree too.
    spec.options.solver = Solver::Rosenbrock23;
    spec.options.rtol = 1e-5;
    spec.options.atol = 1e-7;
    let m3 = measures_for(&v, &a, None, U50, &spec).unwrap();
    assert!((m3.natural_frequency_hz / m2.natural_frequency_hz - 1.0).abs() < 5e-3);
    assert!((m3.steering_gain / m2.steering_gain - 1.0).abs() < 5e-3);
}

#[test]
fn chamber_pressures_stay_above_the_cavitation_floor_during_the_pulse() {
    let a = AfsParams::nominal();
    let sys = AfsSystem::new(a.clone()).unwrap();
    for load in Load::ALL {
        // A hard 60 deg pulse at 50 km/h drives the low-pressure group towards vacuum.
        let r = simulate(
            &VehicleParams::nominal(load),
            &sys,
            &Manoeuvre::pulse(U50, 60.0),
            &SimOptions::default(),
        )
        .unwrap();
        let pmin = r
            .p_c_pa
            .iter()
            .chain(&r.p_r_pa)
            .fold(f64::INFINITY, |m, &p| m.min(p));
        eprintln!("{load:?}: minimum chamber pressure {pmin:.0} Pa");
        assert!(pmin >= a.cavitation_pressure_pa - 1.0, "pmin {pmin}");
    }
}

#[test]
fn a_diverging_run_reports_time_and_state() {
    // Negative joint stiffness: the articulation runs away (jackknife).
    let act = EquivalentTorsion {
        stiffness: -2.0e6,
        damping: 0.0,
        steer_ratio: 0.05,
    };
    let err = simulate(
        &VehicleParams::loaded(),
        &act,
        &Manoeuvre::pulse(U50, 10.0),
        &SimOptions::default(),
    )
    .unwrap_err();
    match &err {
        DynError::Diverged { t, state, .. } => {
            assert!(*t > 0.5 && *t < 10.0);
            assert!(state.contains("articulation_rad="));
        }
        other => panic!("expected divergence, got {other}"),
    }
    assert!(err.to_string().contains("diverged at t ="));
}

#[test]
fn gain_efficiency_correlation_over_leakage_sweep() {
    let g = gain_efficiency_correlation(Load::Loaded, U50, &MeasureSpec::default()).unwrap();
    eprintln!("{g:?}");
    // Fig 4.7: r^2 > 0.99; more leakage, lower gain and efficiency.
    assert!(g.r_squared > 0.99, "r2 {}", g.r_squared);
    assert!(g.steering_gain.windows(2).all(|w| w[1] < w[0]));
    assert!(g.power_efficiency.windows(2).all(|w| w[1] < w[0]));
}

#[test]
fn steady_turn_articulation_decays_slowly_with_leakage() {
    let opts = SimOptions::default();
    let d = steady_turn_decay(Load::Loaded, 13.4 / 3.6, 300.0, 10.0, &opts).unwrap();
    eprintln!("{d:?}");
    assert!(
        d.drift_deg_s < 0.0,
        "leakage must let the articulation decay"
    );
    assert!(d.drift_deg_s.abs() * d.window_s < 0.05 * d.articulation_start_deg);
    // Without leakage it holds.
    let mut a = AfsParams::nominal();
    a.leak_const = 0.0;
    a.leak_velocity = 0.0;
    let sys = AfsSystem::new(a).unwrap();
    let man = Manoeuvre::open_loop(
        13.4 / 3.6,
        20.0,
        afsv_dynamics::SteerInput::Ramp {
            rate_rad_s: 300f64.to_radians(),
            start_s: 0.0,
            limit_rad: 300f64.to_radians(),
        },
        "hold",
    );
    let r = simulate(&VehicleParams::loaded(), &sys, &man, &opts).unwrap();
    let n = r.articulation_deg.len();
    let i5 = r.time_s.iter().position(|&t| t >= 10.0).unwrap();
    let no_leak = r.articulation_deg[n - 1] - r.articulation_deg[i5];
    eprintln!("no leakage: change {no_leak:e} deg over 10 s");
    assert!(no_leak.abs() < 0.2 * d.drift_deg_s.abs() * d.window_s);
}
