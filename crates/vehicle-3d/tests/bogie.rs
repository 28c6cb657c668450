//! Physics checks of the rear walking-beam bogie (`docs/layouts.md`, "The walking-beam
//! bogie"): the statics (tire loads, ride height, strut load and pressure) against a hand
//! calculation, the beam pitch mode against the hand model `omega² = 2 k_t (s/2)² / I_p`,
//! the walking-beam property (a step under one tandem wheel lifts the pivot by half of it
//! and the two wheels keep equal loads), energy (nothing created, the struts only take
//! it) and mirror symmetry. Seconds in total.

mod support;
use support::sampled;

use multibody::Workspace;
use odeint::{Control, Integrator, OdeSystem, Problem, Solver};
use tire_fiala::LoadDeflectionTable;
use vehicle_3d::model::body;
use vehicle_3d::{
    simulate, BogieParams, FrontAxle, Load, RunOptions, Vehicle, VehicleOptions, VehicleParams,
};
use vehicle_components::{FlatTerrain, SteerInput, Terrain};

/// The prototype with the default bogie; `rear_hps` suspends it on one strut per side
/// (the front strut scaled for the side's static load).
fn tandem(rear_hps: bool) -> VehicleParams {
    let mut p = VehicleParams::nominal();
    p.bogie = Some(BogieParams::default());
    if rear_hps {
        p.rear_hps = Some(p.default_rear_strut().unwrap());
    }
    p
}

/// No tire damping, no horizontal tire forces or rolling resistance, the speed held by a
/// near-zero gain, no strut friction: only springs and, with the struts, their orifices.
fn quiet(mut p: VehicleParams) -> VehicleParams {
    p.tire.vertical_damping_n_s_per_m = 0.0;
    p.tire.u_max = 1e-12;
    p.tire.u_min = 1e-12;
    p.tire.rolling_resistance_coefficient = 0.0;
    p.drive.kp_n_m_per_m_s = 1e-12;
    p.drive.ki_n_m_per_m = 0.0;
    p.steering.leak_const = 0.0;
    p.steering.leak_velocity = 0.0;
    p.steering.seal_viscous_n_s_m = 0.0;
    for s in [Some(&mut p.hps), p.rear_hps.as_mut()]
        .into_iter()
        .flatten()
    {
        s.friction.mu_v = 0.0;
        s.friction.f_c = 0.0;
        s.friction.f_s = 0.0;
    }
    p
}

/// The vehicle of `p` loaded on `terrain` (the front axle as `options` says: rigid by
/// default, [`suspended_front`]).
fn vehicle_on<T: Terrain>(p: &VehicleParams, terrain: &T, options: VehicleOptions) -> Vehicle {
    Vehicle::new(p, Load::Loaded, options, terrain, 0.5 * p.front_track_m).unwrap()
}

/// Options with the front HPS.
fn suspended_front(options: VehicleOptions) -> VehicleOptions {
    VehicleOptions {
        front_axle: FrontAxle::Suspended,
        ..options
    }
}

fn vehicle(p: &VehicleParams, options: VehicleOptions) -> Vehicle {
    vehicle_on(p, &FlatTerrain::new(0.0, 0.8).unwrap(), options)
}

/// World position of `b` at the state `y`.
fn position(v: &Vehicle, y: &[f64], b: usize) -> nalgebra::Vector3<f64> {
    let model = v.tree();
    let mut ws = Workspace::new(model);
    let o = v.offsets();
    multibody::update_kinematics(model, &mut ws, &y[o.q..o.v], &y[o.v..o.afs]).unwrap();
    ws.body_position(b)
}

/// Deflection of the table rows `[deflection, load]` at `load`, by linear interpolation.
fn hand_deflection(rows: &[[f64; 2]], load: f64) -> f64 {
    let k = rows.windows(2).position(|w| load <= w[1][1]).unwrap();
    let ([d0, f0], [d1, f1]) = (rows[k], rows[k + 1]);
    d0 + (load - f0) * (d1 - d0) / (f1 - f0)
}

/// Loaded, every tandem tire carries a quarter of the rear axle's 418.64 kN (Table 6.1, note
/// 2.11: 2 x 209.32 kN), the pivots ride at the free radius less that load's deflection, the
/// state is an equilibrium, and each strut carries half the axle less a beam and two wheel
/// ends at the pressure `F / A_hr + p_amb` (Eq 6.9 at rest).
#[test]
fn statics_match_the_hand_calculation() {
    let p = tandem(true);
    let v = vehicle(
        &p,
        suspended_front(VehicleOptions {
            speed_m_s: 1e-9,
            ..Default::default()
        }),
    );
    let rear_axle = 2.0 * 209.32e3;
    let quarter = 0.25 * rear_axle;
    let s = v.statics();
    assert!((s.rear_tire_load_n - quarter).abs() < 10.0, "{s:?}");
    let y = v.initial_state();
    let mut d = vec![0.0; y.len()];
    v.rhs(0.0, &y, &mut d);
    let o = v.offsets();
    let worst = d[o.v..o.afs].iter().fold(0.0f64, |m, x| m.max(x.abs()));
    assert!(worst < 1e-6, "accelerations {:?}", &d[o.v..o.afs]);
    // ride height of the pivots and the wheel centres
    let delta = hand_deflection(&p.tire.load_deflection, quarter);
    let height = p.tire.unloaded_radius_m - delta;
    for b in [
        body::BOGIE_CARRIER_RL,
        body::BOGIE_CARRIER_RR,
        body::WHEEL_RL_LEAD,
        body::WHEEL_RR_TRAIL,
    ] {
        let z = position(&v, &y, b).z;
        assert!((z - height).abs() < 1e-4, "body {b}: {z} against {height}");
    }
    let lead = position(&v, &y, body::WHEEL_RL_LEAD).x;
    let trail = position(&v, &y, body::WHEEL_RL_TRAIL).x;
    assert!((lead - trail - 2.1).abs() < 1e-12);
    // the strut: F = W_r / 2 - (2 m_w + m_b) g, P = F / A_hr + p_amb
    let bogie = p.bogie.unwrap();
    let force = 0.5 * rear_axle - (2.0 * p.wheel_mass_kg + bogie.beam_mass_kg) * p.gravity_m_s2;
    assert!((s.rear_strut_force_n(&p) - force).abs() < 10.0);
    let strut = p.rear_hps.as_ref().unwrap();
    let pressure = force / strut.a_hr + strut.p_amb;
    let rear = v.axle_struts()[1].unwrap();
    for side in 0..2 {
        let states = &y[rear.states(side)];
        assert!(
            (states[1] / pressure - 1.0).abs() < 1e-3,
            "{} against {pressure}",
            states[1]
        );
    }
    // the scaled strut sits at the front strut's static travel (similitude)
    let front = v.axle_struts()[0].unwrap();
    assert!((rear.static_travel_m - front.static_travel_m).abs() < 1e-3);
    // the tire loads a run records at its start (rolling: no run starts at standstill)
    let rolling = vehicle(
        &p,
        suspended_front(VehicleOptions {
            speed_m_s: 3.0,
            ..Default::default()
        }),
    );
    let rec = simulate(
        &rolling,
        &RunOptions {
            t_end_s: 0.01,
            ..Default::default()
        },
    )
    .unwrap();
    assert_eq!(rec.normal_force_n.len(), 6);
    for ch in &rec.normal_force_n[2..] {
        assert!(
            (ch[0] / quarter - 1.0).abs() < 1e-3,
            "{} against {quarter}",
            ch[0]
        );
    }
}

/// The linear modes of the right-hand side's Jacobian (central differences) at the static
/// state rolling at 3 m/s, rigid front axle, tires undamped: the oscillatory modes whose eigenvector is mostly
/// beam pitch (a hundred times more, in rates, than every other velocity with a 3 m lever
/// for the rotations) lie within 0.1 % of the hand model `omega² = 2 k_t (s/2)² / I_p` with the
/// tire's tangent stiffness at the quarter load and `I_p = I_b + 2 m_w (s/2)²`: the beam is
/// pivoted at its cg, so its pitch hardly moves the pivot.
#[test]
fn the_beam_pitch_mode_matches_the_hand_model() {
    let p = quiet(tandem(false));
    let v = vehicle(
        &p,
        VehicleOptions {
            speed_m_s: 3.0,
            ..Default::default()
        },
    );
    let (o, j) = (*v.offsets(), *v.joints());
    let beams = j.beam.unwrap().map(|b| b.1);
    let spins: Vec<usize> = j.spins().iter().map(|s| s.1).collect();
    let mut found = Vec::new();
    for (f, rates) in support::body_modes(&v, &v.initial_state(), 1.0..20.0) {
        let lever = 9.0;
        let pitch: f64 = beams.iter().map(|&k| lever * rates[k]).sum();
        let other: f64 = (0..o.afs - o.v)
            .filter(|k| !beams.contains(k) && !spins.contains(k))
            .map(|k| {
                if (3..6).contains(&k) {
                    rates[k]
                } else {
                    lever * rates[k]
                }
            })
            .sum();
        if pitch > 100.0 * other {
            found.push(f);
        }
    }
    let table = LoadDeflectionTable::new(&p.tire.load_deflection).unwrap();
    let s = v.statics();
    let k_t = table.stiffness(s.rear_tire_deflection_m);
    let hand = p.bogie.unwrap().pitch_frequency_hz(p.wheel_mass_kg, k_t);
    eprintln!("beam pitch modes {found:?} Hz, hand {hand} Hz");
    // one mode per beam (left and right alike)
    assert_eq!(found.len(), 2, "{found:?}");
    for f in found {
        assert!(
            (f / hand - 1.0).abs() < 1e-3,
            "{f} Hz against the hand {hand} Hz"
        );
    }
}

/// Flat ground with a plateau of `height` on the left track from `from` to `to` (path
/// coordinate x).
struct Plateau {
    height: f64,
    from: f64,
    to: f64,
}

impl Terrain for Plateau {
    fn height(&self, x: f64, y: f64) -> f64 {
        if y > 0.0 && (self.from..=self.to).contains(&x) {
            self.height
        } else {
            0.0
        }
    }

    fn friction(&self, _x: f64, _y: f64) -> f64 {
        0.8
    }
}

/// The walking-beam property, at rest: a 60 mm plateau under the left leading wheel only
/// (its path coordinate 5.48 m at the start; the trailing wheel at 3.38 m and the front
/// wheel at 9.55 m stand clear of it) pitches the left beam by `h / s`, lifts its pivot by
/// `h / 2` from the static pose on flat ground, and the two wheels keep equal loads (the
/// pivot at the beam's cg: no moment can shift load between them), together the side's
/// flat-ground load. A rigid tandem would put the side's load on the raised wheel. The
/// tires are strongly damped so the vehicle settles in 4 s (damping does not move an
/// equilibrium); the loads follow from the settled tire deflections.
#[test]
fn a_step_under_one_tandem_wheel_lifts_the_pivot_by_half_and_shares_the_load() {
    let mut p = tandem(false);
    p.tire.vertical_damping_n_s_per_m = 3e5;
    let h = 0.06;
    let step = Plateau {
        height: h,
        from: 4.5,
        to: 6.5,
    };
    let options = VehicleOptions {
        speed_m_s: 1e-6,
        ..Default::default()
    };
    let v = vehicle_on(&p, &step, options.clone());
    let flat = vehicle(&p, options);
    let y0 = v.initial_state();
    let mut y = y0.clone();
    Integrator::new(Solver::Dopri5, 3e-5, 1e-8)
        .run(
            &v,
            &Problem::new(0.0, &y0, &[4.0]),
            &mut odeint::Workspace::new(y0.len()),
            |s| {
                y.copy_from_slice(s.y);
                Control::Continue
            },
        )
        .unwrap();
    let table = LoadDeflectionTable::new(&p.tire.load_deflection).unwrap();
    let r = p.tire.unloaded_radius_m;
    let load = |b: usize, ground: f64| table.load(r - (position(&v, &y, b).z - ground));
    let (lead, trail) = (
        load(body::WHEEL_RL_LEAD, h),
        load(body::WHEEL_RL_TRAIL, 0.0),
    );
    let side_flat = 2.0 * flat.statics().rear_tire_load_n;
    eprintln!("on the step: lead {lead} N, trail {trail} N; flat side {side_flat} N");
    assert!(
        (lead - trail).abs() < 2e-3 * side_flat,
        "lead {lead} N, trail {trail} N"
    );
    assert!(((lead + trail) / side_flat - 1.0).abs() < 0.03);
    // equal loads, equal deflections: the leading wheel centre stands `h` above the
    // trailing one (the beam's turn relative to the rear unit also holds the unit's pitch)
    let rise = position(&v, &y, body::WHEEL_RL_LEAD).z - position(&v, &y, body::WHEEL_RL_TRAIL).z;
    assert!(
        (rise / h - 1.0).abs() < 0.01,
        "the leading wheel {rise} m above the trailing"
    );
    let beam = v.joints().beam.unwrap()[0].0;
    let y_flat = flat.initial_state();
    let lift = position(&v, &y, body::BOGIE_CARRIER_RL).z
        - position(&flat, &y_flat, body::BOGIE_CARRIER_RL).z;
    // half the step, plus what the tires extend as the side sheds load to the other side
    let extension = table.deflection_at(0.5 * side_flat) - table.deflection_at(lead);
    eprintln!(
        "beam pitch {} rad (relative to the rear unit), pivot lift {lift} m, tire extension {extension} m",
        y[beam]
    );
    assert!(
        (lift - 0.5 * h - extension).abs() < 5e-4,
        "pivot lift {lift} m against {} m",
        0.5 * h + extension
    );
}

/// Released moving in bounce, pitch, roll and both beams' pitch on flat ground (the
/// release of `tests/rear_hps.rs` plus the beams) with every loss but the struts' orifices
/// off: with rigid axles and the rigid tandem the energy of [`Vehicle::energy`] stays at its
/// release value (to 1e-4 of the released energy, sample by sample and over 1 s: beams and
/// tires are passive); with HPS on the front axle and the tandem it never rises above the
/// release value (to 1e-4, the criterion of `tests/rear_hps.rs`) and the struts take a good
/// part of it.
#[test]
fn the_bogie_creates_no_energy() {
    for rear_hps in [false, true] {
        let p = quiet(tandem(rear_hps));
        let options = VehicleOptions {
            speed_m_s: 3.0,
            ..Default::default()
        };
        let v = vehicle(
            &p,
            if rear_hps {
                suspended_front(options)
            } else {
                options
            },
        );
        let (o, j) = (*v.offsets(), *v.joints());
        let mut y = v.initial_state();
        let e_static = v.energy(&y).unwrap();
        y[o.v + 5] = 0.2;
        y[o.v + 1] = 0.05;
        y[o.v] = 0.08;
        let [left, right] = j.beam.unwrap();
        y[o.v + left.1] = 0.3;
        y[o.v + right.1] = -0.2;
        let e0 = v.energy(&y).unwrap();
        let released = e0 - e_static;
        let e: Vec<f64> = sampled(&v, &y, 1.0, |y| vec![v.energy(y).unwrap()])
            .into_iter()
            .map(|e| e[0])
            .collect();
        let rise = e.iter().fold(f64::MIN, |m, x| m.max(x - e0));
        let step = e.windows(2).fold(f64::MIN, |m, w| m.max(w[1] - w[0]));
        let lost = e0 - e[e.len() - 1];
        eprintln!(
            "rear hps {rear_hps}: released {released} J, largest rise over the release {rise} J, \
             between samples {step} J, lost {lost} J"
        );
        assert!(
            rise < 1e-4 * released,
            "the energy rose by {rise} J of {released} J"
        );
        if rear_hps {
            assert!(
                lost > 0.2 * released,
                "the struts took {lost} J of {released} J"
            );
        } else {
            assert!(
                step < 1e-4 * released,
                "a sample gained {step} J of {released} J"
            );
            assert!(lost.abs() < 1e-4 * released, "{lost} J of {released} J");
        }
    }
}

/// A steering pulse to the right and its mirror to the left on the suspended tandem: the
/// articulation changes sign, and each side's beam pitch and strut travel is the other
/// side's of the mirrored run (to 1 % of the peaks: the steering check valves switch on
/// pressure comparisons whose round-off differs between the sides).
#[test]
fn a_mirrored_input_gives_the_mirrored_beams() {
    let p = tandem(true);
    let run = |amp: f64| {
        let v = vehicle(
            &p,
            suspended_front(VehicleOptions {
                steer: SteerInput::pulse_deg(amp, 0.2, 0.5),
                speed_m_s: 10.0,
                ..Default::default()
            }),
        );
        let j = *v.joints();
        let [bl, br] = j.beam.unwrap();
        let [cl, cr] = j.rear_carrier.unwrap();
        sampled(&v, &v.initial_state(), 1.5, |y| {
            vec![y[j.articulation.0], y[bl.0], y[br.0], y[cl.0], y[cr.0]]
        })
    };
    let (a, b) = (run(60.0), run(-60.0));
    let peak = |k: usize| a.iter().fold(0.0f64, |m, v| m.max(v[k].abs()));
    assert!(
        peak(0) > 0.01 && peak(1) > 1e-5 && peak(3) > 1e-4,
        "the pulse must articulate and move the bogie"
    );
    for (x, y) in a.iter().zip(&b) {
        assert!((x[0] + y[0]).abs() <= 1e-2 * peak(0));
        for (l, r) in [(1, 2), (3, 4)] {
            let scale = peak(l).max(peak(r));
            assert!(
                (x[l] - y[r]).abs() <= 1e-2 * scale,
                "{l}/{r}: {} vs {}",
                x[l],
                y[r]
            );
        }
    }
}
