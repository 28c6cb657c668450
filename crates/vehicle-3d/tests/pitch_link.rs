//! Physics checks of the pitch interconnection of the 3-D vehicle (`docs/layouts.md`,
//! "Pitch interconnection"): on each side the front strut's piston side is joined to the
//! rear strut's rod side and the rear strut's piston side to the front strut's rod side,
//! each line with its accumulator. The linked struts rest at the hand circuit pressures with
//! the plain ride heights, a free pitch is held and a free bounce softened, and a mirrored
//! input gives the mirrored response. The pair's stiffness ratios against the hand model and
//! its energy balance are `hps_emulsion::interconnect`'s tests; the linked vehicle's energy
//! is `vehicle_3d::interconnect`'s.

use hps_emulsion::interconnect::LineParams;
use odeint::OdeSystem;
use vehicle_3d::interconnect::{
    free_response, suspension_pitch_travel_m, Kick, Link, LinkedVehicle,
};
use vehicle_3d::{FrontAxle, Load, Vehicle, VehicleOptions, VehicleParams};
use vehicle_components::FlatTerrain;

fn both_axles() -> VehicleParams {
    let mut p = VehicleParams::nominal();
    p.rear_hps = Some(p.default_rear_strut().unwrap());
    p
}

fn vehicle(p: &VehicleParams, load: Load) -> Vehicle {
    let flat = FlatTerrain::new(0.0, 0.8).unwrap();
    let options = VehicleOptions {
        front_axle: FrontAxle::Suspended,
        path_length_m: 20.0,
        ..VehicleOptions::default()
    };
    Vehicle::new(p, load, options, &flat, 0.5 * p.front_track_m).unwrap()
}

#[test]
fn the_linked_struts_rest_at_the_hand_pressures_and_the_plain_ride_heights() {
    let p = both_axles();
    let link = Link::pitch_of(&p).unwrap();
    for load in [Load::Loaded, Load::Unloaded] {
        let v = vehicle(&p, load);
        let o = *v.offsets();
        let y_plain = v.initial_state();
        let mut plain = vec![0.0; o.dim];
        v.rhs(0.0, &y_plain, &mut plain);
        let [front, rear] = v.axle_struts().map(Option::unwrap);
        let (tf, tr) = (front.static_travel_m, rear.static_travel_m);
        // the plain struts' static pressures: by hand `F / A_hr + p_amb` (tests/rear_hps.rs)
        let (pf, pr) = (y_plain[o.hps + 1], y_plain[o.rear_hps + 1]);
        let linked = LinkedVehicle::new(v, &link).unwrap();
        let y = linked.initial_state().unwrap();
        // hand circuit pressures, Eq 5.1 for both struts (docs/layouts.md)
        let (f, r) = (p.hps, p.rear_hps.unwrap());
        let d = f.a_hc * r.a_hc - f.a_ann() * r.a_ann();
        let hand = [
            pf + (pr - pf) * f.a_ann() * r.a_hr / d,
            pr - (pr - pf) * r.a_ann() * f.a_hr / d,
        ];
        println!(
            "{load:?}: plain static pressures front {:.4} rear {:.4} MPa, travels {:.2} {:.2} mm; \
             circuits: front piston / rear rod {:.4} MPa, rear piston / front rod {:.4} MPa",
            pf / 1e6,
            pr / 1e6,
            1e3 * tf,
            1e3 * tr,
            hand[0] / 1e6,
            hand[1] / 1e6
        );
        let mut d = vec![0.0; linked.dim()];
        linked.rhs(0.0, &y, &mut d);
        let n = o.hps_states;
        let nr = o.rear_hps_states;
        for side in 0..2 {
            let (fs, rs) = (o.hps + side * n, o.rear_hps + side * nr);
            // each circuit: the piston side of one strut, the rod side of the other, the node
            let pairs = [(fs, rs + 1, 0), (rs, fs + 1, 1)];
            for (piston_at, rod_at, k) in pairs {
                let line = linked.line_state(side, k);
                let pair = linked.pairs().nth(side).unwrap();
                let strut = &pair.struts()[k];
                let (pc, _) = strut.chamber_pressures(&y[piston_at..piston_at + strut.n_states()]);
                assert!((pc / hand[k] - 1.0).abs() < 1e-9, "{side} {k}: {pc}");
                assert_eq!(y[rod_at], hand[k]);
                assert!((pair.line(k).pressure(y[line]) / hand[k] - 1.0).abs() < 1e-12);
                assert!(d[line].abs() < 1e-12, "{}", d[line]);
            }
        }
        if load == Load::Loaded {
            // the similar rear strut rests at the front's pressure (to round-off: the two
            // static solves differ in the last bits): the circuits keep it, and the state
            // is the plain vehicle's
            assert!((pf / pr - 1.0).abs() < 1e-12, "{pf} {pr}");
            for (a, b) in y[..o.dim].iter().zip(&y_plain) {
                assert!((a - b).abs() <= 1e-12 * b.abs(), "{a} {b}");
            }
        }
        // the ride heights are the plain ones (the carriers at zero), every strut carries its
        // plain force: the accelerations are the plain vehicle's static ones
        let strut_states = o.hps..o.rear_hps + 2 * nr;
        for i in (0..o.dim).filter(|i| !strut_states.contains(i)) {
            assert_eq!(y[i], y_plain[i], "state {i}");
        }
        for i in o.v..o.afs {
            assert!(
                (d[i] - plain[i]).abs() < 1e-6,
                "acceleration {i}: {} {}",
                d[i],
                plain[i]
            );
        }
        for (k, at) in [o.hps, o.hps + n, o.rear_hps, o.rear_hps + nr]
            .into_iter()
            .enumerate()
        {
            let strut = &linked.pairs().next().unwrap().struts()[k / 2];
            for j in 0..strut.n_states() {
                assert!(
                    d[at + j].abs() < 1e-9 * strut.state_typical(j),
                    "strut {k} state {j}: {}",
                    d[at + j]
                );
            }
        }
    }
    // the pitch link needs struts on both axles, and says so
    let front_only = VehicleParams::nominal();
    assert!(Link::pitch_of(&front_only).is_err());
    let lines = LineParams::side_pitch(1.457).unwrap();
    let e =
        LinkedVehicle::new(vehicle(&front_only, Load::Loaded), &Link::Pitch(lines)).unwrap_err();
    assert!(e.to_string().contains("both axles"), "{e}");
    let mut bad = lines;
    bad[1].accumulator_volume_m3 = f64::NAN;
    let e = LinkedVehicle::new(vehicle(&p, Load::Loaded), &Link::Pitch(bad)).unwrap_err();
    assert!(e.to_string().contains("accumulator_volume_m3"), "{e}");
}

fn peak(x: &[f64]) -> f64 {
    x.iter().fold(0.0f64, |m, v| m.max((v - x[0]).abs()))
}

#[test]
fn the_link_holds_the_pitch_and_softens_the_bounce() {
    // released with a pitch rate, the linked vehicle pitches less on its struts; released
    // with a vertical velocity, the struts travel further (the bounce spring is softer)
    let p = both_axles();
    let link = Link::pitch_of(&p).unwrap();
    let t0 = std::time::Instant::now();
    let pitch = |l| {
        peak(&suspension_pitch_travel_m(
            &free_response(&p, l, Kick::Pitch, 0.1, 1.0).unwrap(),
        ))
    };
    let bounce = |l| {
        let r = free_response(&p, l, Kick::Bounce, 0.3, 1.0).unwrap();
        let mean: Vec<f64> = (0..r.len())
            .map(|i| {
                0.25 * (r.hps_travel_m[0][i]
                    + r.hps_travel_m[1][i]
                    + r.rear_hps_travel_m[0][i]
                    + r.rear_hps_travel_m[1][i])
            })
            .collect();
        peak(&mean)
    };
    let (pitch0, pitch1) = (pitch(None), pitch(Some(&link)));
    let (bounce0, bounce1) = (bounce(None), bounce(Some(&link)));
    println!(
        "free response, peak suspension pitch travel {:.2} -> {:.2} mm, peak bounce travel \
         {:.2} -> {:.2} mm ({:.2} s)",
        1e3 * pitch0,
        1e3 * pitch1,
        1e3 * bounce0,
        1e3 * bounce1,
        t0.elapsed().as_secs_f64()
    );
    assert!(pitch1 < 0.85 * pitch0, "{pitch0} -> {pitch1}");
    assert!(bounce1 > 1.1 * bounce0, "{bounce0} -> {bounce1}");
}

/// A linked ride of a vehicle with rear struts measures the rear struts' travel too, as
/// the plain ride does, from the same record channel (either link).
#[test]
fn a_linked_ride_measures_the_rear_struts_travel() {
    use vehicle_3d::interconnect::ride_linked;
    use vehicle_3d::scenarios::{RideSpec, RUN_IN_M};
    let p = both_axles();
    let spec = RideSpec {
        speed_kmh: 30.0,
        length_m: 12.0,
        ..RideSpec::d1(Load::Loaded, FrontAxle::Suspended)
    };
    for link in [
        Link::Roll(LineParams::front_axle_roll()),
        Link::pitch_of(&p).unwrap(),
    ] {
        let (run, m) = ride_linked(&p, &spec, 1, link).unwrap();
        let rec = &run.record;
        let i0 = rec
            .t_s
            .partition_point(|&t| t < RUN_IN_M / (spec.speed_kmh / 3.6));
        let p2p = |z: &[f64]| {
            let w = &z[i0..];
            w.iter().fold(f64::MIN, |a, b| a.max(*b)) - w.iter().fold(f64::MAX, |a, b| a.min(*b))
        };
        let expected = p2p(&rec.rear_hps_travel_m[0]).max(p2p(&rec.rear_hps_travel_m[1]));
        let rear = m.rear_strut_travel_p2p_m.expect("rear strut travel");
        assert!(expected > 1e-4, "{link:?}: the rear struts did not move");
        assert_eq!(rear, expected, "{link:?}");
    }
}

#[test]
fn a_mirrored_roll_gives_the_mirrored_response() {
    // a roll kick and its mirror on the pitch-linked vehicle: each strut's travel is the
    // other side's of the mirrored run, the roll rate changes sign
    let p = both_axles();
    let link = Link::pitch_of(&p).unwrap();
    let run = |s: f64| free_response(&p, Some(&link), Kick::Roll, s, 1.0).unwrap();
    let (a, b) = (run(0.2), run(-0.2));
    let scale = |x: &[f64]| peak(x).max(1e-6);
    for (la, rb) in [
        (&a.hps_travel_m[0], &b.hps_travel_m[1]),
        (&a.hps_travel_m[1], &b.hps_travel_m[0]),
        (&a.rear_hps_travel_m[0], &b.rear_hps_travel_m[1]),
        (&a.rear_hps_travel_m[1], &b.rear_hps_travel_m[0]),
    ] {
        let s = scale(la);
        assert!(s > 1e-4, "the roll must move the struts");
        for (x, y) in la.iter().zip(rb.iter()) {
            assert!((x - y).abs() <= 1e-2 * s, "{x} vs {y} (peak {s})");
        }
    }
    let s = scale(&a.front_rate_rad_s[0]);
    for (x, y) in a.front_rate_rad_s[0].iter().zip(&b.front_rate_rad_s[0]) {
        assert!((x + y).abs() <= 1e-2 * s, "{x} vs {y}");
    }
}

/// D1 and D2 of the two-axle HPS vehicle with and without the pitch link (the numbers of
/// docs/layouts.md): `cargo test --release -p vehicle-3d --test pitch_link -- --ignored
/// --nocapture`.
#[test]
#[ignore]
fn d1_and_d2_with_and_without_the_pitch_link() {
    use vehicle_3d::interconnect::{ride_linked, roll_linked};
    use vehicle_3d::scenarios::{ride, roll, RideSpec, RollSpec};
    let p = both_axles();
    let link = Link::pitch_of(&p).unwrap();
    let spec = RideSpec::d1(Load::Loaded, FrontAxle::Suspended);
    let rms = |x: &[f64]| {
        let m = x.iter().sum::<f64>() / x.len() as f64;
        (x.iter().map(|v| (v - m) * (v - m)).sum::<f64>() / x.len() as f64).sqrt()
    };
    let i0 = |r: &vehicle_3d::RunRecord| {
        r.t_s
            .partition_point(|&t| t < vehicle_3d::scenarios::RUN_IN_M / (spec.speed_kmh / 3.6))
    };
    for seed in 1..=5u64 {
        let (r0, m0) = ride(&p, &spec, seed).unwrap();
        let (l1, m1) = ride_linked(&p, &spec, seed, link).unwrap();
        let r1 = &l1.record;
        let pitch = |r: &vehicle_3d::RunRecord| rms(&suspension_pitch_travel_m(r)[i0(r)..]);
        let lo = l1
            .node_pressure_pa
            .iter()
            .flatten()
            .fold(f64::MAX, |m, v| m.min(*v));
        println!(
            "D1 seed {seed}: a_wz {:.3} -> {:.3}, front travel p-p {:.3} -> {:.3} m, vertical peak {:.2} -> {:.2} Hz, pitch peak {:.2} -> {:.2} Hz, susp. pitch travel RMS {:.2} -> {:.2} mm, lowest node {:.2} MPa",
            m0.a_wz_m_s2,
            m1.a_wz_m_s2,
            m0.strut_travel_p2p_m.unwrap(),
            m1.strut_travel_p2p_m.unwrap(),
            m0.vertical_peak_hz,
            m1.vertical_peak_hz,
            m0.pitch_peak_hz,
            m1.pitch_peak_hz,
            1e3 * pitch(&r0),
            1e3 * pitch(r1),
            lo / 1e6
        );
    }
    let spec = RollSpec::d2(FrontAxle::Suspended);
    for seed in 1..=3u64 {
        let (_, m0) = roll(&p, &spec, seed).unwrap();
        let (l1, m1) = roll_linked(&p, &spec, seed, link).unwrap();
        let lo = l1
            .node_pressure_pa
            .iter()
            .flatten()
            .fold(f64::MAX, |m, v| m.min(*v));
        let hi = l1
            .node_pressure_pa
            .iter()
            .flatten()
            .fold(0.0f64, |m, v| m.max(*v));
        println!(
            "D2 seed {seed}: SP-DRT {:.3} -> {:.3} m/s², rollover {:?} -> {:?} s, node pressures {:.2}-{:.2} MPa",
            m0.sp_drt_m_s2, m1.sp_drt_m_s2, m0.rollover_s, m1.rollover_s, lo / 1e6, hi / 1e6
        );
    }
}

/// Each stiff block's own rates (`OdeSystem::block_rhs`: a linked pair's evaluate, the
/// additive Runge-Kutta method's Newton iterations) are the linked vehicle's right-hand
/// side rows of that block, to the bit, with the pitch link (two pair blocks) and the roll
/// link (one pair block beside the rear struts' own blocks), away from the static state.
#[test]
fn a_linked_block_rates_are_the_right_hand_side_rows() {
    let p = both_axles();
    for link in [
        Link::pitch_of(&p).unwrap(),
        Link::Roll(LineParams::front_axle_roll()),
    ] {
        let linked = LinkedVehicle::new(vehicle(&p, Load::Loaded), &link).unwrap();
        let mut y = linked.initial_state().unwrap();
        for (k, yk) in y.iter_mut().enumerate() {
            *yk *= 1.0 + 1e-3 * (k as f64).sin();
        }
        let mut d = vec![0.0; linked.dim()];
        linked.rhs(0.2, &y, &mut d);
        let blocks = linked.stiff_blocks();
        for (b, rows) in blocks.iter().enumerate() {
            let mut out = vec![f64::NAN; rows.len()];
            assert!(
                linked.block_rhs(0.2, &y, b, &mut out),
                "{link:?}, block {b}"
            );
            let want: Vec<f64> = rows.iter().map(|&i| d[i]).collect();
            assert_eq!(out, want, "{link:?}, block {b}");
        }
        let mut out = [0.0; 16];
        assert!(!linked.block_rhs(0.2, &y, blocks.len(), &mut out));
    }
}
