//! The cab and seat driven through time: the seat's transmissibility
//! against the closed-form base-excitation formula, the power balance over a run, mirrored
//! runs, and the seat measures of a synthetic ride record. The measured D1 numbers of
//! `docs/layouts.md` come from the ignored test at the end:
//! `cargo test --release -p vehicle-3d --lib cab_ride -- --ignored --nocapture`.

use super::{cab_seat_run, seat_ride_measures, CabSeatLayout};
use crate::{RunRecord, VehicleParams};
use std::f64::consts::PI;
use vehicle_components::{CabSeat, FrameMotion, SeatParams};

/// Uniform times of `secs` seconds at `fs` Hz.
fn times(secs: f64, fs: f64) -> Vec<f64> {
    (0..=(secs * fs) as usize).map(|i| i as f64 / fs).collect()
}

/// Amplitude of the `f_hz` line of `x` sampled at `fs` (a whole number of periods).
fn line_amplitude(x: &[f64], f_hz: f64, fs: f64) -> f64 {
    let (mut a, mut b) = (0.0, 0.0);
    for (i, v) in x.iter().enumerate() {
        let w = 2.0 * PI * f_hz * i as f64 / fs;
        a += v * w.sin();
        b += v * w.cos();
    }
    2.0 * (a * a + b * b).sqrt() / x.len() as f64
}

/// The 1-DOF seat on a moving base: `|T| = sqrt((1 + (2 zeta r)^2) / ((1 - r^2)^2 + (2 zeta r)^2))`.
fn base_excitation(f_hz: f64, fn_hz: f64, zeta: f64) -> f64 {
    let r = f_hz / fn_hz;
    ((1.0 + (2.0 * zeta * r).powi(2)) / ((1.0 - r * r).powi(2) + (2.0 * zeta * r).powi(2))).sqrt()
}

#[test]
fn the_seat_transmits_as_the_closed_form_base_excitation() {
    // the generic seat is tuned to 1.5 Hz with zeta 0.3; the seat's ratio over the floor
    // does not depend on how the cab moves the floor
    let cs = CabSeat::generic();
    let fs = 200.0;
    for f in [1.0, 1.5, 3.0, 6.0] {
        let t = times(14.0, fs);
        let frame: Vec<FrameMotion> = t
            .iter()
            .map(|&t| FrameMotion {
                accel_m_s2: [0.0, 0.0, 0.5 * (2.0 * PI * f * t).sin()],
                ..FrameMotion::REST
            })
            .collect();
        let r = cab_seat_run(&cs, &t, &frame).unwrap();
        assert!(
            r.stop_force_n.iter().all(|s| *s == 0.0),
            "{f} Hz hits a stop"
        );
        // the last 6 s, a whole number of periods of every test frequency
        let tail = t.len() - 1 - (6.0 * fs) as usize;
        let seat = line_amplitude(&r.seat_accel_m_s2[tail..t.len() - 1], f, fs);
        let floor = line_amplitude(&r.floor_accel_m_s2[tail..t.len() - 1], f, fs);
        let expect = base_excitation(f, 1.5, 0.3);
        assert!(
            (seat / floor / expect - 1.0).abs() < 2e-3,
            "{f} Hz: {} vs {expect}",
            seat / floor
        );
    }
}

/// A frame motion in every axis: sines at unrelated frequencies.
fn shaking(t: &[f64], flip: f64) -> Vec<FrameMotion> {
    t.iter()
        .map(|&t| {
            let s = |a: f64, f: f64| a * (2.0 * PI * f * t).sin();
            FrameMotion {
                accel_m_s2: [s(0.8, 1.3), flip * s(1.2, 0.9), s(2.0, 2.7) + s(1.0, 7.9)],
                angular_accel_rad_s2: [flip * s(1.5, 3.1), s(1.1, 2.3), flip * s(0.4, 0.7)],
                rate_rad_s: [flip * s(0.1, 3.1), s(0.08, 2.3), flip * s(0.2, 0.7)],
            }
        })
        .collect()
}

#[test]
fn over_a_run_the_energy_balance_closes_and_the_dampers_only_take_energy() {
    let cs = CabSeat::generic();
    let fs = 1000.0;
    let t = times(6.0, fs);
    let r = cab_seat_run(&cs, &t, &shaking(&t, 1.0)).unwrap();
    assert!(r.dissipation_w.iter().all(|d| *d >= 0.0));
    let dt = 1.0 / fs;
    let trapz = |x: &[f64]| x.windows(2).map(|w| 0.5 * dt * (w[0] + w[1])).sum::<f64>();
    let net: Vec<f64> = r
        .power_in_w
        .iter()
        .zip(&r.dissipation_w)
        .map(|(p, d)| p - d)
        .collect();
    let gained = r.energy_j.last().unwrap() - r.energy_j[0];
    let work = trapz(&net);
    let scale = trapz(&r.power_in_w.iter().map(|p| p.abs()).collect::<Vec<_>>());
    assert!(
        (gained - work).abs() < 1e-4 * scale,
        "E gained {gained} J, net work {work} J (scale {scale} J)"
    );
    assert!(trapz(&r.dissipation_w) > 0.1 * scale);

    // released from a displaced equilibrium onto a frame at rest: the energy only falls
    let t = times(3.0, fs);
    let mut frame = vec![FrameMotion::REST; t.len()];
    frame[0].accel_m_s2 = [1.5, -1.0, 3.0];
    let r = cab_seat_run(&cs, &t, &frame).unwrap();
    for w in r.energy_j[1..].windows(2) {
        assert!(w[1] <= w[0] + 1e-12, "{} -> {}", w[0], w[1]);
    }
    // and settles towards the static equilibrium's energy
    let mut rest = vec![0.0; 8];
    vehicle_components::Component::initial_state(&cs, &FrameMotion::REST, &mut rest);
    let e_rest = cs.energy_j(&rest);
    let e_end = r.energy_j.last().unwrap() - e_rest;
    assert!(
        e_end >= -1e-9 && e_end < 0.05 * (r.energy_j[1] - e_rest),
        "{e_end}"
    );
}

#[test]
fn a_mirrored_frame_motion_gives_the_mirrored_roll_and_the_same_bounce() {
    let cs = CabSeat::generic();
    let t = times(4.0, 200.0);
    let a = cab_seat_run(&cs, &t, &shaking(&t, 1.0)).unwrap();
    let b = cab_seat_run(&cs, &t, &shaking(&t, -1.0)).unwrap();
    let peak = a.cab_roll_pitch_rad[0]
        .iter()
        .fold(0.0f64, |m, v| m.max(v.abs()));
    assert!(peak > 1e-4, "the run must roll the cab: {peak}");
    for i in 0..t.len() {
        assert!((a.cab_roll_pitch_rad[0][i] + b.cab_roll_pitch_rad[0][i]).abs() < 1e-12);
        assert!((a.cab_roll_pitch_rad[1][i] - b.cab_roll_pitch_rad[1][i]).abs() < 1e-12);
        assert!((a.seat_accel_m_s2[i] - b.seat_accel_m_s2[i]).abs() < 1e-9);
        assert!((a.floor_accel_m_s2[i] - b.floor_accel_m_s2[i]).abs() < 1e-9);
    }
}

/// A ride record whose frame only heaves at 4 Hz: a_wz on the frame is `A |W_k(4)| / sqrt 2`
/// and SEAT the seat's closed-form transmissibility at 4 Hz.
#[test]
fn the_seat_measures_of_a_heaving_frame_have_their_closed_forms() {
    let fs = 200.0;
    let t = times(30.0, fs);
    let n = t.len();
    let amp = 1.2;
    let mut rec = RunRecord {
        t_s: t.clone(),
        ..RunRecord::default()
    };
    rec.cab_accel_m_s2 = [
        vec![0.0; n],
        vec![0.0; n],
        t.iter().map(|t| amp * (2.0 * PI * 4.0 * t).sin()).collect(),
    ];
    rec.front_angular_accel_rad_s2 = [vec![0.0; n], vec![0.0; n], vec![0.0; n]];
    rec.front_rate_rad_s = [vec![0.0; n], vec![0.0; n], vec![0.0; n]];
    let p = VehicleParams::nominal();
    let layout = CabSeatLayout::generic();
    let m = seat_ride_measures(&p, &rec, 5.0, &layout).unwrap();
    let frame = amp * vehicle_3d_wk(4.0) / 2f64.sqrt();
    assert!((m.a_wz_frame_m_s2 / frame - 1.0).abs() < 0.01, "{m:?}");
    let expect = base_excitation(4.0, 1.5, 0.3);
    assert!((m.seat.seat / expect - 1.0).abs() < 0.01, "{m:?}");
    assert!(m.a_wz_seat_m_s2 < m.a_wz_floor_m_s2 && m.stop_fraction == 0.0);
    // a record missing a channel is an error, not a panic
    let mut short = rec.clone();
    short.front_rate_rad_s[1].pop();
    assert!(seat_ride_measures(&p, &short, 5.0, &layout).is_err());
    // a seat that cannot move is refused by its ranges, not run
    let stiff = CabSeatLayout {
        seat: SeatParams {
            travel_m: 0.0,
            ..SeatParams::generic()
        },
        ..layout
    };
    assert!(seat_ride_measures(&p, &rec, 5.0, &stiff).is_err());
}

fn vehicle_3d_wk(f: f64) -> f64 {
    perf_measures::Weighting::Wk.magnitude(f)
}

/// The D1 numbers of `docs/layouts.md`: the prototype loaded at 20 km/h on class E, rigid
/// and with the nominal front HPS, over seeds 1-5, with the generic cab and seat, and with
/// the generic seat on a stiffly mounted cab (mounts 100 times stiffer, 10 times more
/// damped: the cab moves with the frame and only the seat acts), and with a softer seat on
/// the generic cab (1.0 Hz, damping ratio 0.4, 150 mm travel).
#[test]
#[ignore = "measurement for docs/layouts.md (thirty ride runs, about 20 s on two cores)"]
fn d1_with_the_generic_cab_and_seat() {
    use super::{ride_with_seat_over_seeds, SeatRideMeasures};
    use crate::scenarios::{RideSpec, Spread};
    use crate::{FrontAxle, Load};
    let p = VehicleParams::nominal();
    let generic = CabSeatLayout::generic();
    let mut stiff = generic;
    for m in &mut stiff.cab.mounts {
        m.stiffness_n_per_m *= 100.0;
        m.damping_n_s_per_m *= 10.0;
    }
    let mut soft = generic;
    soft.seat.stiffness_n_per_m = 80.0 * (2.0 * PI * 1.0f64).powi(2);
    soft.seat.damping_n_s_per_m = 2.0 * 0.4 * (soft.seat.stiffness_n_per_m * 80.0).sqrt();
    soft.seat.travel_m = 0.15;
    for (name, layout) in [
        ("generic cab", generic),
        ("stiff cab", stiff),
        ("soft seat", soft),
    ] {
        let cs = layout.build(&p).unwrap();
        println!("{name}: modes (Hz) {:?}", cs.linear_modes_hz());
    }
    let seeds: Vec<u64> = (1..=5).collect();
    for axle in [FrontAxle::Rigid, FrontAxle::Suspended] {
        for (name, layout) in [
            ("generic cab", generic),
            ("stiff cab", stiff),
            ("soft seat", soft),
        ] {
            let spec = RideSpec::d1(Load::Loaded, axle);
            let runs = ride_with_seat_over_seeds(&p, &spec, &seeds, &layout).unwrap();
            let col = |f: &dyn Fn(&SeatRideMeasures) -> f64| {
                let v: Vec<f64> = runs.iter().map(|(_, s)| f(s)).collect();
                let s = Spread::of(&v).unwrap();
                format!("{:.3} ± {:.3}", s.mean, s.sd)
            };
            println!(
                "{axle:?}, {name}: a_wz frame {} | floor {} | seat {} m/s2 | SEAT {} | seat travel p2p {} m | on stops {} | crest seat {} | VDV ratio {}",
                col(&|s| s.a_wz_frame_m_s2),
                col(&|s| s.a_wz_floor_m_s2),
                col(&|s| s.a_wz_seat_m_s2),
                col(&|s| s.seat.seat),
                col(&|s| s.seat_travel_p2p_m),
                col(&|s| s.stop_fraction),
                col(&|s| s.seat.crest_factor_seat),
                col(&|s| s.seat.seat_vdv),
            );
            for (seed, (m, s)) in seeds.iter().zip(&runs) {
                assert_eq!(m.a_wz_m_s2, s.a_wz_frame_m_s2);
                println!(
                    "  seed {seed}: frame {:.3}, floor {:.3}, seat {:.3}, SEAT {:.3}",
                    s.a_wz_frame_m_s2, s.a_wz_floor_m_s2, s.a_wz_seat_m_s2, s.seat.seat
                );
            }
        }
    }
}
