//! Physics checks of HPS on both axles (`docs/layouts.md`, "HPS on any axle"): each strut's
//! static pressure and travel against a hand calculation from the axle loads, mirrored
//! inputs give mirrored motion, the struts only dissipate energy, and the linear bounce and
//! pitch modes against a hand-derived two-axle model.

mod support;
use support::sampled;

use hps_emulsion::emulsion::emulsion_volume;
use hps_emulsion::StrutParams;
use odeint::OdeSystem;
use vehicle_3d::vehicle::END_STOP_STIFFNESS_N_M;
use vehicle_3d::{FrontAxle, Load, Vehicle, VehicleOptions, VehicleParams};
use vehicle_components::{FlatTerrain, SteerInput};

fn both_axles() -> VehicleParams {
    let mut p = VehicleParams::nominal();
    p.rear_hps = Some(p.default_rear_strut().unwrap());
    p
}

/// [`both_axles`] with no tire damping or tire lag, the speed held by a near-zero gain,
/// and no strut friction (the Eq 5.3 band is not passive sample by sample).
fn quiet_both_axles() -> VehicleParams {
    let mut p = both_axles();
    p.tire.vertical_damping_n_s_per_m = 0.0;
    p.tire.u_max = 1e-12;
    p.tire.u_min = 1e-12;
    p.drive.kp_n_m_per_m_s = 1e-12;
    p.drive.ki_n_m_per_m = 0.0;
    for s in [&mut p.hps, p.rear_hps.as_mut().unwrap()] {
        s.friction.mu_v = 0.0;
        s.friction.f_c = 0.0;
        s.friction.f_s = 0.0;
    }
    p
}

fn vehicle(p: &VehicleParams, load: Load, options: VehicleOptions) -> Vehicle {
    let flat = FlatTerrain::new(0.0, 0.8).unwrap();
    let options = VehicleOptions {
        front_axle: FrontAxle::Suspended,
        ..options
    };
    Vehicle::new(p, load, options, &flat, 0.5 * p.front_track_m).unwrap()
}

/// Hand statics of one strut under `force`: at rest both chambers share one pressure, so
/// `P = F / A_hr + p_amb` (Eq 6.9); the travel follows from the volume the gas (Eq 6.10)
/// and the emulsion (Eq 6.14) take at `P`, `A_hr z = V_g0 + V_c0 + V_r0 - V(P)`. Returns
/// `(P, z)`; on the extension stop (a load below what the strut pushes fully extended) the
/// stop's spring takes the difference and `z` lies `(F(-travel) - F) / k_stop` beyond it.
fn hand_statics(s: &StrutParams, force: f64) -> (f64, f64) {
    let travel_at = |pressure: f64| {
        let v = s.v_g0 * (s.p_h0 / pressure).powf(1.0 / s.n)
            + emulsion_volume(s.v_c0 + s.v_r0, pressure, s.p_h0, s.n, s.beta_h, s.gamma0);
        (s.v_g0 + s.v_c0 + s.v_r0 - v) / s.a_hr
    };
    let p = force / s.a_hr + s.p_amb;
    let z = travel_at(p);
    if z >= -s.travel {
        return (p, z);
    }
    // the pressure at travel `target`, from the same volume law by bisection
    let pressure_at = |target: f64| {
        let (mut lo, mut hi) = (s.p_vap.max(1.0), s.p_h0);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if travel_at(mid) < target {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        lo
    };
    let top = (pressure_at(-s.travel) - s.p_amb) * s.a_hr;
    let z = -s.travel - (top - force) / END_STOP_STIFFNESS_N_M;
    (pressure_at(z), z)
}

#[test]
fn each_strut_settles_at_its_hand_pressure_and_travel() {
    let p = both_axles();
    let w = p.wheel_mass_kg * p.gravity_m_s2;
    // the hand tire loads of note 2.11 (Table 6.1)
    for (load, front_tire, rear_tire) in [
        (Load::Loaded, 149.83e3, 209.32e3),
        (Load::Unloaded, 122.69e3, 71.06e3),
    ] {
        let options = VehicleOptions {
            speed_m_s: 1e-9,
            ..Default::default()
        };
        let v = vehicle(&p, load, options);
        let y = v.initial_state();
        let mut d = vec![0.0; y.len()];
        v.rhs(0.0, &y, &mut d);
        let o = v.offsets();
        let worst = d[o.v..o.afs].iter().fold(0.0f64, |m, x| m.max(x.abs()));
        assert!(worst < 1e-6, "{load:?}: accelerations {:?}", &d[o.v..o.afs]);
        let [front, rear] = v.axle_struts().map(Option::unwrap);
        for (axle, strut, tire) in [
            (front, &p.hps, front_tire),
            (rear, p.rear_hps.as_ref().unwrap(), rear_tire),
        ] {
            let (pressure, z) = hand_statics(strut, tire - w);
            assert!(
                (axle.static_travel_m - z).abs() < 1e-4 * strut.travel,
                "{load:?}: travel {} against the hand {z}",
                axle.static_travel_m
            );
            for side in 0..2 {
                let states = &y[axle.states(side)];
                // P_hr, the rod-side pressure state, equals the piston side's at rest
                assert!(
                    (states[1] / pressure - 1.0).abs() < 1e-3,
                    "{load:?}: {} against {pressure}",
                    states[1]
                );
            }
        }
        // loaded, the scaled rear strut sits where the front one does (similitude)
        if load == Load::Loaded {
            assert!((rear.static_travel_m - front.static_travel_m).abs() < 1e-3);
        } else {
            // unloaded it tops out: the load ratio 3.7 is beyond a passive strut's reach
            assert!(rear.static_travel_m < -p.hps.travel);
        }
    }
}

/// A steering pulse to the right and its mirror to the left: articulation, rear-unit roll
/// and lateral position change sign, and each rear (and front) strut's travel is the other
/// side's of the mirrored run. The check valves switch on a pressure comparison whose
/// round-off differs between the sides, so the images agree to 1 % of the peaks (as the
/// front-HPS check of `tests/physics.rs`).
#[test]
fn a_mirrored_input_gives_the_mirrored_response() {
    let p = both_axles();
    let run = |amp: f64| {
        let options = VehicleOptions {
            steer: SteerInput::pulse_deg(amp, 0.2, 0.5),
            speed_m_s: 10.0,
            ..Default::default()
        };
        let v = vehicle(&p, Load::Loaded, options);
        let j = *v.joints();
        let [front, rear] = v.axle_struts().map(|a| a.unwrap().carriers);
        sampled(&v, &v.initial_state(), 2.0, |y| {
            vec![
                y[j.articulation.0],
                y[j.rear_roll.unwrap().0],
                y[1],
                y[front[0].0],
                y[front[1].0],
                y[rear[0].0],
                y[rear[1].0],
            ]
        })
    };
    let (a, b) = (run(60.0), run(-60.0));
    let peak = |k: usize| a.iter().fold(0.0f64, |m, v| m.max(v[k].abs()));
    assert!(
        peak(0) > 0.01 && peak(1) > 1e-3 && peak(5) > 1e-3,
        "the pulse must articulate, roll and move the rear struts"
    );
    for (x, y) in a.iter().zip(&b) {
        for k in 0..3 {
            assert!(
                (x[k] + y[k]).abs() <= 1e-2 * peak(k),
                "channel {k}: {} vs {}",
                x[k],
                y[k]
            );
        }
        // left of one run is right of the other (the carrier coordinates, static travel aside)
        for (l, r) in [(3, 4), (5, 6)] {
            let scale = peak(l).max(peak(r));
            assert!(
                (x[l] - y[r]).abs() <= 1e-2 * scale,
                "struts {l}/{r}: {} vs {}",
                x[l],
                y[r]
            );
        }
    }
}

/// Every loss but the struts' own off (tire damping, horizontal tire forces, rolling
/// resistance, steering leakage and seal damping, the drive), the vehicle released moving in
/// bounce, pitch and roll on flat ground: the energy of [`Vehicle::energy`] (with the
/// struts' stored energy) never rises from one 10 ms sample to the next (to 1e-4 of the
/// release energy), and
/// the struts' orifices take a good part of it within 1.5 s. The seal friction is off: Eq
/// 5.3's band interpolates from the previous direction's friction level, so just after a
/// reversal the friction pushes along the motion (docs/layouts.md).
#[test]
fn the_struts_only_dissipate() {
    let mut p = quiet_both_axles();
    p.tire.rolling_resistance_coefficient = 0.0;
    p.steering.leak_const = 0.0;
    p.steering.leak_velocity = 0.0;
    p.steering.seal_viscous_n_s_m = 0.0;
    let options = VehicleOptions {
        speed_m_s: 3.0,
        ..Default::default()
    };
    let v = vehicle(&p, Load::Loaded, options);
    let o = *v.offsets();
    let mut y = v.initial_state();
    let e_static = v.energy(&y).unwrap();
    y[o.v + 5] = 0.2;
    y[o.v + 1] = 0.05;
    y[o.v] = 0.08;
    let e0 = v.energy(&y).unwrap();
    let released = e0 - e_static;
    let stored = |y: &[f64]| -> f64 {
        v.axle_struts()
            .into_iter()
            .flatten()
            .map(|a| a.stored_energy(y, o.v).unwrap())
            .sum()
    };
    let both = sampled(&v, &y, 1.5, |y| {
        let e = v.energy(y).unwrap();
        vec![e, e - stored(y)]
    });
    let e: Vec<f64> = both.iter().map(|e| e[0]).collect();
    // the test has teeth: the struts return energy to the vehicle, so the mechanical
    // energy alone rises at times
    let mechanical = both
        .windows(2)
        .fold(f64::MIN, |m, w| m.max(w[1][1] - w[0][1]));
    assert!(mechanical > 0.01 * released, "{mechanical}");
    let rise = e.iter().fold(f64::MIN, |m, x| m.max(x - e0));
    assert!(
        rise < 1e-4 * released,
        "the energy rose by {rise} J of {released} J"
    );
    let lost = e0 - e[e.len() - 1];
    eprintln!("released {released} J, largest rise {rise} J (mechanical alone {mechanical} J), lost {lost} J");
    assert!(
        lost > 0.3 * released,
        "the struts took only {lost} J of {released} J"
    );
}

/// The hand-derived two-axle model: the truck in its vertical plane is one rigid body (the
/// articulation joint is rigid in pitch) of the sprung mass (the parts less the four wheel
/// ends) on one spring per axle, two struts' static stiffness in series with two tires'
/// tangent stiffness at the static loads; unsprung masses left out. Returns the two
/// natural frequencies (Hz), lower first, of
/// `det([[k_f + k_r, -(k_f a + k_r b)], [-(k_f a + k_r b), k_f a² + k_r b²]] - w² diag(m, I)) = 0`
/// with `a`, `b` the axles' signed distances ahead of the sprung cg and `I` its pitch
/// inertia (parallel axes; the wheel ends' spin inertia spins free and is not pitched).
fn hand_bounce_pitch(p: &VehicleParams, v: &Vehicle) -> [f64; 2] {
    let s = v.statics();
    let r = p.tire.unloaded_radius_m;
    let (m_w, i_w) = (p.wheel_mass_kg, p.wheel_spin_inertia_kg_m2);
    // (mass, x ahead of the joint, height, pitch inertia about its own cg)
    let mut parts = vec![(
        p.front_unit.mass_kg,
        p.front_unit.cg_to_joint_m,
        p.front_unit.cg_height_m,
        p.front_unit.pitch_inertia_kg_m2,
    )];
    for q in p.rear_parts(Load::Loaded) {
        parts.push((
            q.mass_kg,
            -q.cg_to_joint_m,
            q.cg_height_m,
            q.pitch_inertia_kg_m2,
        ));
    }
    let (x_f, x_r) = (p.front_axle_to_joint_m, -p.rear_axle_to_joint_m);
    let wheels = [
        (x_f, r - s.front_tire_deflection_m),
        (x_r, r - s.rear_tire_deflection_m),
    ];
    let m = parts.iter().map(|q| q.0).sum::<f64>() - 4.0 * m_w;
    let first = |f: &dyn Fn(f64, f64) -> f64| {
        (parts.iter().map(|q| q.0 * f(q.1, q.2)).sum::<f64>()
            - wheels.iter().map(|w| 2.0 * m_w * f(w.0, w.1)).sum::<f64>())
            / m
    };
    let (x_s, z_s) = (first(&|x, _| x), first(&|_, z| z));
    let arm = |x: f64, z: f64| (x - x_s).powi(2) + (z - z_s).powi(2);
    let inertia = parts.iter().map(|q| q.3 + q.0 * arm(q.1, q.2)).sum::<f64>()
        - wheels
            .iter()
            .map(|w| 2.0 * (i_w + m_w * arm(w.0, w.1)))
            .sum::<f64>();
    let table = tire_fiala::LoadDeflectionTable::new(&p.tire.load_deflection).unwrap();
    let [front, rear] = v.axle_struts().map(Option::unwrap);
    let axle = |a: &vehicle_3d::suspension::AxleStruts, deflection: f64| {
        let (k_s, k_t) = (
            a.strut.static_stiffness(a.static_travel_m).unwrap(),
            table.stiffness(deflection),
        );
        2.0 * k_s * k_t / (k_s + k_t)
    };
    let (k_f, k_r) = (
        axle(front, s.front_tire_deflection_m),
        axle(rear, s.rear_tire_deflection_m),
    );
    let (a, b) = (x_f - x_s, x_r - x_s);
    let (k11, k12, k22) = (k_f + k_r, -(k_f * a + k_r * b), k_f * a * a + k_r * b * b);
    // m I w⁴ - (k11 I + k22 m) w² + k11 k22 - k12² = 0
    let (qa, qb, qc) = (
        m * inertia,
        -(k11 * inertia + k22 * m),
        k11 * k22 - k12 * k12,
    );
    let disc = (qb * qb - 4.0 * qa * qc).sqrt();
    let hz = |w2: f64| w2.sqrt() / (2.0 * std::f64::consts::PI);
    [hz((-qb - disc) / (2.0 * qa)), hz((-qb + disc) / (2.0 * qa))]
}

/// The vehicle's own linear modes at the static state rolling at 3 m/s: the eigenvalues of
/// the right-hand side's Jacobian (central differences), the oscillatory modes (damping
/// ratio below 0.5) between 0.5 and 4 Hz whose eigenvector (inverse iteration) moves the
/// front unit in its vertical plane (bounce and pitch) at least a hundred times more than
/// out of it (lateral, roll, yaw, articulation, rear roll).
/// Their natural frequencies `|lambda| / 2 pi` against [`hand_bounce_pitch`]: within 4 %,
/// what the unsprung masses (2 000 kg per corner on the struts, their hop near 7 Hz) and
/// the strut chambers' compliance behind the orifices, both left out by hand, may move.
/// The losses that have no linearization are off: the struts' Coulomb friction (it sticks
/// at small amplitude), the tires' horizontal forces (slip at standstill) and their
/// damping (so the modes are those of the springs).
#[test]
fn the_bounce_and_pitch_modes_match_the_two_axle_hand_model() {
    let p = quiet_both_axles();
    let options = VehicleOptions {
        speed_m_s: 3.0,
        ..Default::default()
    };
    let v = vehicle(&p, Load::Loaded, options);
    let j = *v.joints();
    let rates = [j.articulation.1, j.rear_roll.unwrap().1];
    let mut found: Vec<f64> = Vec::new();
    // oscillatory modes only: the tire lags relax at v / sigma (real eigenvalues)
    for (f, at) in support::body_modes(&v, &v.initial_state(), 0.5..4.0) {
        let len2 = 9.0; // a 3 m lever for the rotations
        let vertical = at[5] + len2 * at[1];
        let out = at[4] + len2 * (at[0] + at[2] + rates.iter().map(|&k| at[k]).sum::<f64>());
        if vertical > 100.0 * out {
            found.push(f);
        }
    }
    found.sort_by(f64::total_cmp);
    let hand = hand_bounce_pitch(&p, &v);
    eprintln!("vertical-plane modes {found:?} Hz, hand {hand:?} Hz");
    assert_eq!(found.len(), 2, "{found:?}");
    for (model, hand) in found.iter().zip(hand) {
        assert!(
            (model / hand - 1.0).abs() < 0.04,
            "{model} Hz against the hand {hand} Hz"
        );
    }
}

/// The D1 ride (20 km/h, 100 m after a 20 m run-in, m_c 0.3) of the layouts rigid, front
/// HPS, rear HPS and front + rear HPS on class E and C terrain, loaded and unloaded, seeds
/// 1-5: a_wz, the front and rear strut travel, the run time (the table of
/// docs/layouts.md). About a minute:
/// `cargo test --release -p vehicle-3d --test rear_hps -- --ignored --nocapture`.
#[test]
#[ignore]
fn d1_ride_of_the_layouts() {
    use terrain_psd::IsoClass;
    use vehicle_3d::scenarios::{ride_on, ride_tracks, RideSpec, TerrainSpec};
    let seeds = 1..=5u64;
    let rigid_rear = VehicleParams::nominal();
    let rear = both_axles();
    let layouts = [
        ("rigid", FrontAxle::Rigid, &rigid_rear),
        ("front HPS", FrontAxle::Suspended, &rigid_rear),
        ("rear HPS", FrontAxle::Rigid, &rear),
        ("front + rear HPS", FrontAxle::Suspended, &rear),
    ];
    let stat = |x: &[f64]| {
        let n = x.len() as f64;
        let mean = x.iter().sum::<f64>() / n;
        let sd = (x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
        format!("{mean:.3} ± {sd:.3}")
    };
    for load in [Load::Loaded, Load::Unloaded] {
        let v = vehicle(&rear, load, VehicleOptions::default());
        let y = v.initial_state();
        for (name, a) in ["front", "rear"].into_iter().zip(v.axle_struts()) {
            let a = a.unwrap();
            let top = a.strut.static_force(-a.strut.params().travel).unwrap();
            println!(
                "{load} {name}: static travel {:.5} m, pressure {:.4} MPa, stiffness {:.4e} N/m, force fully extended {:.1} kN",
                a.static_travel_m,
                y[a.states(0)][1] / 1e6,
                a.strut.static_stiffness(a.static_travel_m.max(-a.strut.params().travel)).unwrap(),
                top / 1e3
            );
        }
    }
    println!("| class | load | layout | a_wz (m/s²) | front d_s (m) | rear d_s (m) | run time (s) | per seed a_wz |");
    println!("|---|---|---|---|---|---|---|---|");
    for class in [IsoClass::E, IsoClass::C] {
        for load in [Load::Loaded, Load::Unloaded] {
            for (name, front, p) in layouts {
                let spec = RideSpec {
                    terrain: TerrainSpec {
                        class,
                        ..TerrainSpec::default()
                    },
                    ..RideSpec::d1(load, front)
                };
                let (mut awz, mut df, mut dr, mut time) = (vec![], vec![], vec![], vec![]);
                for seed in seeds.clone() {
                    let tracks = ride_tracks(p, &spec, seed).unwrap();
                    let t = std::time::Instant::now();
                    let (_, m) = ride_on(p, &spec, tracks).unwrap();
                    time.push(t.elapsed().as_secs_f64());
                    awz.push(m.a_wz_m_s2);
                    df.extend(m.strut_travel_p2p_m);
                    dr.extend(m.rear_strut_travel_p2p_m);
                }
                let opt = |x: &[f64]| {
                    if x.is_empty() {
                        "-".to_string()
                    } else {
                        stat(x)
                    }
                };
                let each: Vec<String> = awz.iter().map(|a| format!("{a:.3}")).collect();
                println!(
                    "| {class:?} | {load} | {name} | {} | {} | {} | {} | {} |",
                    stat(&awz),
                    opt(&df),
                    opt(&dr),
                    stat(&time),
                    each.join(" / ")
                );
            }
        }
    }
}
