//! The velocity-amplitude state `u` that the peak-velocity laws run on (friction band,
//! gas-fraction growth), the gas it moves, and the strut as a `vehicle_components::Component`.

use hps_emulsion::strut::{STATE_U, VELOCITY_ATTACK_S, VELOCITY_RELEASE_S};
use hps_emulsion::*;
use odeint::{Atol, Control, Integrator, OdeSystem};
use std::f64::consts::PI;
use vehicle_components::{Component, StateLayout};

/// The strut driven by `z = A sin(w t)` through its component interface.
struct Harmonic<'a> {
    strut: &'a HpsStrut,
    w: f64,
    a: f64,
}

impl Harmonic<'_> {
    fn motion(&self, t: f64) -> StrutMotion {
        StrutMotion {
            deflection_m: self.a * (self.w * t).sin(),
            velocity_m_s: self.a * self.w * (self.w * t).cos(),
        }
    }
}

impl OdeSystem for Harmonic<'_> {
    fn dim(&self) -> usize {
        self.strut.n_states()
    }
    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        Component::evaluate(self.strut, &self.motion(t), y, dydt);
    }
}

/// Smallest and largest `u` over the last of `cycles` periods, starting at `u0`.
fn amplitude_range(strut: &HpsStrut, f: f64, amp: f64, cycles: f64, u0: f64) -> (f64, f64) {
    let sys = Harmonic {
        strut,
        w: 2.0 * PI * f,
        a: amp,
    };
    let mut y = vec![0.0; strut.n_states()];
    strut.initial_state_at(0.0, u0, &mut y).unwrap();
    let t_end = cycles / f;
    let ts = odeint::output_grid(0.0, t_end, 1.0 / (200.0 * f));
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    let atol = Atol::scaled(1e-9, strut.states().iter().map(|s| s.typical));
    Integrator::new(Solver::Auto, 1e-7, atol)
        .with_max_step(1.0 / (20.0 * f))
        .integrate(&sys, 0.0, &y, &ts, |t, y| {
            if t >= t_end - 1.0 / f {
                lo = lo.min(y[STATE_U]);
                hi = hi.max(y[STATE_U]);
            }
            Control::Continue
        })
        .unwrap();
    (lo, hi)
}

#[test]
fn amplitude_rate_by_hand() {
    // attack: 0.3 m/s against u = 0.1 m/s
    let hand = 0.2 / VELOCITY_ATTACK_S - 0.1 / VELOCITY_RELEASE_S;
    assert!((HpsStrut::amplitude_rate(-0.3, 0.1) - hand).abs() < 1e-12);
    // release only below u
    assert_eq!(
        HpsStrut::amplitude_rate(0.05, 0.1),
        -0.1 / VELOCITY_RELEASE_S
    );
    // at rest from rest nothing moves, and u never turns negative
    assert_eq!(HpsStrut::amplitude_rate(0.0, 0.0), 0.0);
    assert!(HpsStrut::amplitude_rate(1e-6, 0.0) > 0.0);
}

#[test]
fn steady_harmonic_keeps_u_at_the_peak_velocity() {
    let strut = HpsStrut::new(
        &StrutParams::lab(LabConfig::OneOrifice),
        &HpsExtensions::none(),
    )
    .unwrap();
    // The slowest and the fastest laboratory tests (section 5.2), started in steady state.
    for (f, amp) in [(0.1, 0.025), (8.0, 0.2356 / (2.0 * PI * 8.0))] {
        let peak = 2.0 * PI * f * amp;
        let (lo, hi) = amplitude_range(&strut, f, amp, 3.0, peak);
        assert!(
            hi <= peak * (1.0 + 1e-9),
            "{f} Hz: u {hi} above the peak {peak}"
        );
        assert!(lo > 0.95 * peak, "{f} Hz: u fell to {lo} of {peak}");
        if f > 1.0 {
            assert!(lo > 0.995 * peak, "{f} Hz: u fell to {lo} of {peak}");
        }
    }
}

#[test]
fn u_finds_the_peak_from_rest() {
    let strut = HpsStrut::new(&StrutParams::front_axle(), &HpsExtensions::none()).unwrap();
    // 1 Hz, 25 mm: a quarter period is 12 attack time constants.
    let peak = 2.0 * PI * 0.025;
    let (lo, hi) = amplitude_range(&strut, 1.0, 0.025, 2.0, 0.0);
    assert!(
        lo > 0.98 * peak && hi <= peak * (1.0 + 1e-9),
        "{lo} {hi} {peak}"
    );
}

#[test]
fn the_friction_band_follows_u() {
    let p = StrutParams::lab(LabConfig::OneOrifice);
    let strut = HpsStrut::new(&p, &HpsExtensions::none()).unwrap();
    assert_eq!(strut.v_h(0.2), p.friction.v_h(0.2));
    // just after a reversal (z zdot < 0) inside the band the force depends on u
    let mut y = vec![0.0; strut.n_states()];
    strut.initial_state_at(0.01, 0.05, &mut y).unwrap();
    let f_narrow = strut.outputs(0.01, -0.004, &y).friction;
    strut.initial_state_at(0.01, 0.2, &mut y).unwrap();
    let f_wide = strut.outputs(0.01, -0.004, &y).friction;
    assert!(f_narrow != f_wide);
    assert_eq!(strut.outputs(0.01, -0.004, &y).velocity_amplitude, 0.2);
}

fn growth_strut() -> HpsStrut {
    let ext = HpsExtensions {
        gas_fraction_growth: Some(GasFractionGrowth { k_gamma: 0.1 }),
        ..HpsExtensions::none()
    };
    HpsStrut::new(&StrutParams::lab(LabConfig::TwoOrifices), &ext).unwrap()
}

#[test]
fn grown_gas_fraction_is_that_of_with_gamma0() {
    let strut = growth_strut();
    let p = strut.params();
    let at = strut.params_at(0.2);
    let hand = p.with_gamma0(p.gamma0 + 0.1 * 0.2).unwrap();
    for (a, b) in [
        (at.gamma0, hand.gamma0),
        (at.v_g0, hand.v_g0),
        (at.v_c0, hand.v_c0),
        (at.v_r0, hand.v_r0),
    ] {
        assert!((a - b).abs() <= 1e-15 * b.abs().max(1e-12), "{a} {b}");
    }
    // the total gas charge (free + entrapped, at P_h0) is conserved
    let (oc, or) = p.oil_volumes();
    let charge = |q: &StrutParams| q.v_g0 + q.gamma0 * (oc + or);
    assert!((charge(&at) - charge(p)).abs() < 1e-15);
    // a very large u is capped where the free gas still covers the stroke
    let cap = strut.params_at(1e6);
    assert!(cap.v_g0 > cap.a_hr * cap.travel && cap.gamma0 < 0.5);
    assert!(cap.validate().is_ok());
}

#[test]
fn gas_moved_by_the_growth_law_leaves_at_constant_pressure() {
    let strut = growth_strut();
    let mut y = vec![0.0; strut.n_states()];
    let mut d = vec![0.0; strut.n_states()];
    // At rest in equilibrium at z = 0 with u = 0.2 m/s: only the release moves u, and with it
    // gas from the emulsion back into the free volume. No pressure may jump.
    strut.initial_state_at(0.0, 0.2, &mut y).unwrap();
    let before = strut.outputs(0.0, 0.0, &y);
    strut.derivatives(0.0, 0.0, &y, &mut d);
    assert!(d[STATE_U] < 0.0 && d[0] > 0.0, "{d:?}");
    let h = 1.0;
    let moved: Vec<f64> = y.iter().zip(&d).map(|(a, b)| a + h * b).collect();
    let after = strut.outputs(0.0, 0.0, &moved);
    let dp = (after.p_piston - before.p_piston) / before.p_piston;
    assert!(dp.abs() < 1e-9, "piston pressure moved by {dp:e}");
    assert!((after.p_rod - before.p_rod).abs() < 1e-9 * before.p_rod);
    // Without the transfer term the same change of V_g0 at fixed V_g would have moved P_hc
    // by n dV_g0/V_g0.
    let p_hand =
        strut.params().n * (strut.params_at(moved[STATE_U]).v_g0 / strut.params_at(0.2).v_g0 - 1.0);
    assert!(p_hand.abs() > 1e-5, "{p_hand}");
}

#[test]
fn the_strut_is_a_component() {
    let strut = growth_strut();
    let mut layout = StateLayout::new();
    let block = layout.add("strut", Component::states(&strut)).unwrap();
    assert_eq!(layout.range(block).len(), strut.n_states());
    let motion = StrutMotion {
        deflection_m: 0.012,
        velocity_m_s: -0.15,
    };
    let mut y = vec![0.0; strut.n_states()];
    Component::initial_state(&strut, &motion, &mut y);
    assert_eq!(y[STATE_U], 0.15);
    let mut d_comp = vec![0.0; strut.n_states()];
    let out = Component::evaluate(&strut, &motion, &y, &mut d_comp);
    let mut d = vec![0.0; strut.n_states()];
    strut.derivatives(0.012, -0.15, &y, &mut d);
    assert_eq!(d, d_comp);
    assert_eq!(out, strut.outputs(0.012, -0.15, &y));
    let mut row = vec![f64::NAN; strut.channels().len()];
    strut.record(&out, &mut row);
    assert!(row.iter().all(|x| x.is_finite()));
    assert_eq!(row[0], out.force);
    // a deflection beyond the travel starts at the travel end, not with an error
    let far = StrutMotion {
        deflection_m: 10.0,
        velocity_m_s: 0.0,
    };
    Component::initial_state(&strut, &far, &mut y);
    let mut at_end = vec![0.0; strut.n_states()];
    strut
        .initial_state_at(strut.params().travel, 0.0, &mut at_end)
        .unwrap();
    assert_eq!(y, at_end);
}
