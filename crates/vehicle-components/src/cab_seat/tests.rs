//! Physics of the cab on mounts and the suspension seat: statics and linear modes against hand calculation, the power balance and mirror symmetry
//! at arbitrary states. The run-level checks (transmissibility against the closed-form
//! base-excitation formula, energy over a run, mirrored runs) are in
//! `crates/vehicle-3d/src/cab_ride/tests.rs`, which integrates the component.

use super::{
    CabParams, CabSeat, Cushion, FrameMotion, SeatParams, BOUNCE, CUSHION, PITCH, ROLL, SEAT,
};
use crate::{Component, ComponentError};
use proptest::prelude::*;
use std::f64::consts::PI;

const G: f64 = 9.81;

fn at_rest(cs: &CabSeat) -> Vec<f64> {
    let mut x = vec![0.0; cs.n_states()];
    cs.initial_state(&FrameMotion::REST, &mut x);
    x
}

#[test]
fn statics_a_central_seat_sinks_the_cab_evenly() {
    let cab = CabParams::generic();
    let seat = SeatParams {
        x_m: 0.0,
        ..SeatParams::generic()
    };
    let cs = CabSeat::new(cab, seat, G).unwrap();
    let x = at_rest(&cs);
    let k = cab.mounts[0].stiffness_n_per_m;
    // hand: the whole weight over four equal mounts, no tilt
    let w = (cab.mass_kg + seat.suspended_mass_kg) * G;
    for u in cs.mount_displacements_m(&x) {
        assert!(
            (u + w / (4.0 * k)).abs() < 1e-12,
            "{u} vs {}",
            -w / (4.0 * k)
        );
    }
    assert!(x[ROLL].abs() < 1e-15 && x[PITCH].abs() < 1e-15);
    // the weight adjustment: mid-travel, the spring compressed by m g / k_s (97 mm here)
    assert_eq!(x[SEAT], 0.0);
    let d0 = seat.suspended_mass_kg * G / seat.stiffness_n_per_m;
    assert!((cs.seat_preload_m() - d0).abs() < 1e-15);
    assert!((d0 - G / (2.0 * PI * 1.5f64).powi(2)).abs() < 1e-12);
    // an equilibrium: nothing moves
    let mut d = vec![1.0; x.len()];
    let out = cs.evaluate(&FrameMotion::REST, &x, &mut d);
    assert!(d.iter().all(|v| v.abs() < 1e-9), "{d:?}");
    assert!(out.floor_accel_m_s2.abs() < 1e-9 && out.seat_accel_m_s2.abs() < 1e-9);
}

#[test]
fn statics_a_seat_behind_the_mounts_pitches_the_cab_nose_up() {
    let cab = CabParams::generic();
    let seat = SeatParams::generic();
    let cs = CabSeat::new(cab, seat, G).unwrap();
    let x = at_rest(&cs);
    let (k, a) = (cab.mounts[0].stiffness_n_per_m, cab.mounts[0].x_m);
    let (m_c, m_s) = (cab.mass_kg, seat.suspended_mass_kg);
    // hand: bounce from the total weight; pitch from the seat's moment m_s g x_s against
    // the mounts' 4 k a^2 less the overturning g (m_c h + m_s h_s)
    let z = -(m_c + m_s) * G / (4.0 * k);
    let k_pitch = 4.0 * k * a * a - G * (m_c * cab.cg_height_m + m_s * seat.height_m);
    let theta = m_s * G * seat.x_m / k_pitch;
    assert!(theta < 0.0);
    assert!((x[BOUNCE] - z).abs() < 1e-12);
    assert!((x[PITCH] - theta).abs() < 1e-12, "{} vs {theta}", x[PITCH]);
    let u = cs.mount_displacements_m(&x);
    // front mounts (x = +a) less compressed than the rear ones
    assert!((u[0] - (z - theta * a)).abs() < 1e-12 && (u[2] - (z + theta * a)).abs() < 1e-12);
    assert!(u[0] > u[2]);
    // force balance of the mounts: they carry the whole weight
    let total: f64 = u.iter().map(|d| -k * d).sum();
    assert!((total / ((m_c + m_s) * G) - 1.0).abs() < 1e-12);
}

#[test]
fn statics_a_cushion_is_compressed_by_the_operator() {
    let seat = SeatParams {
        suspended_mass_kg: 25.0,
        cushion: Some(Cushion::tuned(55.0, 4.0, 0.25)),
        ..SeatParams::generic()
    };
    let cs = CabSeat::new(CabParams::generic(), seat, G).unwrap();
    assert_eq!(cs.n_dof(), 5);
    let x = at_rest(&cs);
    let c = seat.cushion.unwrap();
    assert!((x[CUSHION] + 55.0 * G / c.stiffness_n_per_m).abs() < 1e-12);
    assert!(x[SEAT].abs() < 1e-15);
    let w = (CabParams::generic().mass_kg + 80.0) * G;
    assert!((x[BOUNCE] + w / (4.0 * 550e3)).abs() < 1e-12);
    let mut d = vec![1.0; x.len()];
    cs.evaluate(&FrameMotion::REST, &x, &mut d);
    assert!(d.iter().all(|v| v.abs() < 1e-9), "{d:?}");
}

/// Hand-derived modes with the seat above O (no lever on roll and pitch): bounce and seat
/// from `m_c m_s l^2 - (4 k m_s + k_s (m_c + m_s)) l + 4 k k_s = 0` (relative coordinates,
/// `M = [[m_c + m_s, m_s], [m_s, m_s]]`, `K = diag(4 k, k_s)`); roll and pitch
/// `l = (4 k b^2 - g (m_c h + m_s h_s)) / (I + m_c h^2 + m_s h_s^2)`.
#[test]
fn linear_modes_match_the_hand_derived_model() {
    let cab = CabParams::generic();
    let seat = SeatParams {
        x_m: 0.0,
        ..SeatParams::generic()
    };
    let cs = CabSeat::new(cab, seat, G).unwrap();
    let (k, a, b) = (550e3, 0.8, 0.65);
    let (m_c, m_s, k_s) = (cab.mass_kg, seat.suspended_mass_kg, seat.stiffness_n_per_m);
    let (h, h_s) = (cab.cg_height_m, seat.height_m);
    let (qa, qb, qc) = (
        m_c * m_s,
        -(4.0 * k * m_s + k_s * (m_c + m_s)),
        4.0 * k * k_s,
    );
    let disc = (qb * qb - 4.0 * qa * qc).sqrt();
    let over = G * (m_c * h + m_s * h_s);
    let rot = m_c * h * h + m_s * h_s * h_s;
    let mut expect = [
        (-qb - disc) / (2.0 * qa),
        (-qb + disc) / (2.0 * qa),
        (4.0 * k * b * b - over) / (cab.roll_inertia_kg_m2 + rot),
        (4.0 * k * a * a - over) / (cab.pitch_inertia_kg_m2 + rot),
    ]
    .map(|l: f64| l.sqrt() / (2.0 * PI));
    expect.sort_by(f64::total_cmp);
    let got = cs.linear_modes_hz();
    for (g, e) in got.iter().zip(expect) {
        assert!((g / e - 1.0).abs() < 1e-6, "{got:?} vs {expect:?}");
    }
    // the seat mode is the seat's own 1.5 Hz, lowered slightly by the cab's compliance
    assert!(got[0] < 1.5 && got[0] > 1.45, "{got:?}");
}

fn seat_variants() -> [CabSeat; 2] {
    [
        CabSeat::generic(),
        CabSeat::new(
            CabParams::generic(),
            SeatParams {
                suspended_mass_kg: 25.0,
                y_m: 0.15,
                cushion: Some(Cushion::tuned(55.0, 4.0, 0.25)),
                ..SeatParams::generic()
            },
            G,
        )
        .unwrap(),
    ]
}

fn motion(v: &[f64]) -> FrameMotion {
    FrameMotion {
        accel_m_s2: [v[0], v[1], v[2]],
        angular_accel_rad_s2: [v[3], v[4], v[5]],
        rate_rad_s: [v[6], v[7], v[8]],
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// `dE/dt` along the flow of `evaluate` (a central difference of the piecewise quadratic
    /// energy, exact up to round-off) is `P_in - D` with `D >= 0`, at any state, in or beyond
    /// the seat's travel, for any frame motion.
    #[test]
    fn the_power_balance_holds_and_dampers_only_dissipate(
        which in 0usize..2,
        q in proptest::collection::vec(-0.02f64..0.02, 5),
        v in proptest::collection::vec(-0.5f64..0.5, 5),
        s in prop_oneof![-0.045f64..0.045, 0.055f64..0.09, -0.09f64..-0.055],
        u in proptest::collection::vec(-5.0f64..5.0, 9),
    ) {
        let cs = &seat_variants()[which];
        let n = cs.n_dof();
        let mut x: Vec<f64> = q[..n].iter().chain(&v[..n]).copied().collect();
        x[SEAT] = s;
        let input = motion(&u);
        let mut d = vec![0.0; 2 * n];
        let out = cs.evaluate(&input, &x, &mut d);
        prop_assert!(out.dissipation_w >= 0.0);
        let eps = 1e-5;
        let step = |sign: f64| -> Vec<f64> {
            x.iter().zip(&d).map(|(xi, di)| xi + sign * eps * di).collect()
        };
        let rate = (cs.energy_j(&step(1.0)) - cs.energy_j(&step(-1.0))) / (2.0 * eps);
        let scale = 1.0 + out.power_in_w.abs() + out.dissipation_w;
        prop_assert!(
            (rate - (out.power_in_w - out.dissipation_w)).abs() < 1e-6 * scale,
            "dE/dt {} vs P_in - D {}", rate, out.power_in_w - out.dissipation_w
        );
    }

    /// A mirrored frame motion (y -> -y) on a mirrored state gives the mirrored derivative:
    /// roll and its rate change sign, bounce, pitch and the seat do not.
    #[test]
    fn mirrored_inputs_give_mirrored_motion(
        q in proptest::collection::vec(-0.02f64..0.02, 4),
        v in proptest::collection::vec(-0.5f64..0.5, 4),
        u in proptest::collection::vec(-5.0f64..5.0, 9),
    ) {
        let cs = CabSeat::generic();
        let x: Vec<f64> = q.iter().chain(&v).copied().collect();
        let mut xm = x.clone();
        xm[ROLL] = -x[ROLL];
        xm[4 + ROLL] = -x[4 + ROLL];
        let input = motion(&u);
        let (mut d, mut dm) = (vec![0.0; 8], vec![0.0; 8]);
        let out = cs.evaluate(&input, &x, &mut d);
        let outm = cs.evaluate(&input.mirrored(), &xm, &mut dm);
        for i in 0..8 {
            let sign = if i % 4 == ROLL { -1.0 } else { 1.0 };
            prop_assert!((dm[i] - sign * d[i]).abs() <= 1e-12 * (1.0 + d[i].abs()), "state {}", i);
        }
        prop_assert!((outm.seat_accel_m_s2 - out.seat_accel_m_s2).abs() < 1e-9);
        prop_assert!((outm.cab_roll_rad + out.cab_roll_rad).abs() < 1e-15);
    }
}

#[test]
fn every_constructor_checks_its_ranges_and_names_the_field() {
    let field = |r: Result<CabSeat, ComponentError>| match r {
        Err(ComponentError::InvalidParameter { field, .. }) => field,
        other => panic!("expected a named field, got {other:?}"),
    };
    let mut cab = CabParams::generic();
    cab.mounts[2].stiffness_n_per_m = f64::NAN;
    assert_eq!(
        field(CabSeat::new(cab, SeatParams::generic(), G)),
        "cab.mounts[2].stiffness_n_per_m"
    );
    let seat = SeatParams {
        stop_stiffness_n_per_m: 1.0,
        ..SeatParams::generic()
    };
    assert_eq!(
        field(CabSeat::new(CabParams::generic(), seat, G)),
        "seat.stop_stiffness_n_per_m"
    );
    let seat = SeatParams {
        cushion: Some(Cushion::tuned(-5.0, 4.0, 0.2)),
        ..SeatParams::generic()
    };
    assert_eq!(
        field(CabSeat::new(CabParams::generic(), seat, G)),
        "seat.cushion.occupant_mass_kg"
    );
    // mounts bunched on a line cannot hold the cab in roll
    let mut cab = CabParams::generic();
    for m in &mut cab.mounts {
        m.y_m = 0.0;
    }
    assert_eq!(
        field(CabSeat::new(cab, SeatParams::generic(), G)),
        "cab.mounts"
    );
    assert_eq!(
        field(CabSeat::new(
            CabParams::generic(),
            SeatParams::generic(),
            0.0
        )),
        "gravity_m_s2"
    );
}

#[test]
fn the_component_contract_holds() {
    for cs in seat_variants() {
        for s in cs.states() {
            s.check().unwrap();
        }
        assert_eq!(cs.n_states(), 2 * cs.n_dof());
        let x = at_rest(&cs);
        let mut d = vec![0.0; x.len()];
        let out = cs.evaluate(&FrameMotion::REST, &x, &mut d);
        let mut row = vec![f64::NAN; cs.channels().len()];
        cs.record(&out, &mut row);
        assert!(row.iter().all(|v| v.is_finite()));
    }
}
