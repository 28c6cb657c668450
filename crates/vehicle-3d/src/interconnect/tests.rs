use super::*;
use crate::scenarios::{ride, roll};

#[test]
fn at_the_static_state_the_lines_carry_nothing_and_the_struts_rest() {
    let p = VehicleParams::nominal();
    let flat = FlatTerrain::new(0.0, vehicle_components::DEFAULT_FRICTION).unwrap();
    let options = VehicleOptions {
        front_axle: FrontAxle::Suspended,
        path_length_m: 20.0,
        ..VehicleOptions::default()
    };
    let v = Vehicle::new(&p, Load::Loaded, options, &flat, 0.5 * p.front_track_m).unwrap();
    let mut plain = vec![0.0; v.offsets().dim];
    let y_plain = v.initial_state();
    v.rhs(0.0, &y_plain, &mut plain);
    let linked = LinkedVehicle::new(v, &Link::Roll(LineParams::front_axle_roll())).unwrap();
    let y = linked.initial_state().unwrap();
    let o = *linked.vehicle().offsets();
    assert_eq!(y[..o.dim], y_plain[..]);
    let mut d = vec![0.0; linked.dim()];
    linked.rhs(0.0, &y, &mut d);
    // the mechanical rates are the plain vehicle's, bit for bit
    assert_eq!(d[..o.hps], plain[..o.hps]);
    assert_eq!(
        d[o.hps + 2 * o.hps_states..o.dim],
        plain[o.hps + 2 * o.hps_states..]
    );
    // the struts and lines rest (round-off only)
    let pair = linked.pairs().next().unwrap();
    let strut = &pair.struts()[0];
    for side in 0..2 {
        for k in 0..o.hps_states {
            let r = d[o.hps + side * o.hps_states + k];
            assert!(r.abs() < 1e-9 * strut.state_typical(k), "{side} {k}: {r}");
        }
    }
    assert!(d[o.dim].abs() < 1e-12 && d[o.dim + 1].abs() < 1e-12);
    // the accumulators sit at the static strut pressure
    let p_s = y[o.hps + 1];
    let line = pair.line(0);
    assert!((line.pressure(y[o.dim]) / p_s - 1.0).abs() < 1e-12);
    // a rigid front axle has nothing to link
    let rigid = Vehicle::new(
        &p,
        Load::Loaded,
        VehicleOptions {
            path_length_m: 20.0,
            ..VehicleOptions::default()
        },
        &flat,
        0.5 * p.front_track_m,
    )
    .unwrap();
    assert!(LinkedVehicle::new(rigid, &Link::Roll(LineParams::front_axle_roll())).is_err());
}

#[test]
fn the_link_holds_the_roll_and_softens_the_bounce() {
    // released with a roll rate, the linked front axle rolls less on its struts; released
    // with a vertical velocity, it travels further (the bounce spring is softer)
    let p = VehicleParams::nominal();
    let line = Link::Roll(LineParams::front_axle_roll());
    let t0 = std::time::Instant::now();
    let peak = |x: &[f64], base: f64| x.iter().fold(0.0f64, |m, v| m.max((v - base).abs()));
    let roll = |l| {
        let r = free_response(&p, l, Kick::Roll, 0.3, 1.0).unwrap();
        peak(&suspension_roll_rad(&p, &r), 0.0)
    };
    let bounce = |l| {
        let r = free_response(&p, l, Kick::Bounce, 0.3, 1.0).unwrap();
        let mean: Vec<f64> = (0..r.len())
            .map(|i| 0.5 * (r.hps_travel_m[0][i] + r.hps_travel_m[1][i]))
            .collect();
        peak(&mean, mean[0])
    };
    let (roll0, roll1) = (roll(None), roll(Some(&line)));
    let (bounce0, bounce1) = (bounce(None), bounce(Some(&line)));
    println!(
        "free response, peak suspension roll {:.2} -> {:.2} mrad, peak bounce travel \
         {:.2} -> {:.2} mm ({:.2} s)",
        1e3 * roll0,
        1e3 * roll1,
        1e3 * bounce0,
        1e3 * bounce1,
        t0.elapsed().as_secs_f64()
    );
    assert!(roll1 < 0.85 * roll0, "{roll0} -> {roll1}");
    assert!(bounce1 > 1.2 * bounce0, "{bounce0} -> {bounce1}");
}

/// D1 and D2 with and without the roll link (the numbers of docs/layouts.md):
/// `cargo test --release -p vehicle-3d --lib interconnect -- --ignored --nocapture`.
#[test]
#[ignore]
fn d1_and_d2_with_and_without_the_link() {
    let p = VehicleParams::nominal();
    let lines = LineParams::front_axle_roll();
    let line = Link::Roll(lines);
    let spec = RideSpec::d1(Load::Loaded, FrontAxle::Suspended);
    // the PSD peak of the suspension roll angle over the measured window (the ride
    // measures' method for the vertical and pitch peaks)
    let roll_peak = |r: &RunRecord| {
        let i0 = r
            .t_s
            .partition_point(|&t| t < RUN_IN_M / (spec.speed_kmh / 3.6));
        crate::scenarios::psd_peak(&suspension_roll_rad(&p, r)[i0..], 1.0 / OUTPUT_DT_S).unwrap()
    };
    for seed in 1..=5u64 {
        let (r0, m0) = ride(&p, &spec, seed).unwrap();
        let (l1, m1) = ride_linked(&p, &spec, seed, line).unwrap();
        let r1 = l1.record;
        let rms = |x: &[f64]| (x.iter().map(|v| v * v).sum::<f64>() / x.len() as f64).sqrt();
        println!(
            "D1 seed {seed}: a_wz {:.3} -> {:.3}, travel p-p {:.3} -> {:.3} m, vertical peak {:.2} -> {:.2} Hz, pitch peak {:.2} -> {:.2} Hz, roll peak {:.2} -> {:.2} Hz, susp. roll RMS {:.2} -> {:.2} mrad",
            m0.a_wz_m_s2,
            m1.a_wz_m_s2,
            m0.strut_travel_p2p_m.unwrap(),
            m1.strut_travel_p2p_m.unwrap(),
            m0.vertical_peak_hz,
            m1.vertical_peak_hz,
            m0.pitch_peak_hz,
            m1.pitch_peak_hz,
            roll_peak(&r0),
            roll_peak(&r1),
            1e3 * rms(&suspension_roll_rad(&p, &r0)),
            1e3 * rms(&suspension_roll_rad(&p, &r1)),
        );
    }
    let spec = RollSpec::d2(FrontAxle::Suspended);
    for seed in 1..=3u64 {
        let (r0, m0) = roll(&p, &spec, seed).unwrap();
        let (l1, m1) = roll_linked(&p, &spec, seed, line).unwrap();
        let r1 = &l1.record;
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
        // when a node first falls to the precharge (the bladder would reach its stop)
        let below = (0..r1.len()).find(|&i| {
            l1.node_pressure_pa[0][i].min(l1.node_pressure_pa[1][i]) <= lines.precharge_pa
        });
        if let Some(i) = below {
            println!(
                "D2 seed {seed}: a node at the precharge from t = {:.2} s, rear a_y {:.2} m/s²",
                r1.t_s[i], r1.rear_lateral_accel_m_s2[i]
            );
        }
        let peak = |r: &RunRecord| {
            suspension_roll_rad(&p, r)
                .iter()
                .fold(0.0f64, |m, v| m.max(v.abs()))
        };
        println!(
            "D2 seed {seed}: SP-DRT {:.3} -> {:.3} m/s², rollover {:?} -> {:?} s, peak a_y {:.2} -> {:.2}, peak susp. roll {:.1} -> {:.1} mrad, node pressures {:.2}-{:.2} MPa (precharge {:.2})",
            m0.sp_drt_m_s2,
            m1.sp_drt_m_s2,
            m0.rollover_s,
            m1.rollover_s,
            m0.peak_ay_m_s2,
            m1.peak_ay_m_s2,
            1e3 * peak(&r0),
            1e3 * peak(r1),
            lo / 1e6,
            hi / 1e6,
            lines.precharge_pa / 1e6,
        );
    }
}

/// Frequency (Hz) from the mean spacing of the first `k` local extrema of `x` after `t0`.
fn extrema_frequency(t: &[f64], x: &[f64], k: usize) -> f64 {
    let ext: Vec<f64> = (1..x.len() - 1)
        .filter(|&i| (x[i] - x[i - 1]) * (x[i + 1] - x[i]) < 0.0)
        .map(|i| t[i])
        .take(k)
        .collect();
    assert_eq!(ext.len(), k, "too few extrema");
    (k - 1) as f64 / (2.0 * (ext[k - 1] - ext[0]))
}

#[test]
fn the_bounce_frequency_falls_as_the_square_root_of_the_wheel_rates() {
    // the front struts' free bounce (seal friction off, so the small motion is linear)
    // against the hand model: struts in series with the tires, the frequency ratio
    // sqrt(k_w,linked / k_w,plain)
    let mut p = VehicleParams::nominal();
    p.hps.friction.mu_v = 0.0;
    p.hps.friction.f_c = 0.0;
    p.hps.friction.f_s = 0.0;
    let lines = LineParams::front_axle_roll();
    let line = Link::Roll(lines);
    let freq = |l: Option<&Link>| {
        let r = free_response(&p, l, Kick::Bounce, 0.05, 4.0).unwrap();
        let mean: Vec<f64> = (0..r.len())
            .map(|i| 0.5 * (r.hps_travel_m[0][i] + r.hps_travel_m[1][i]))
            .collect();
        extrema_frequency(&r.t_s, &mean, 6)
    };
    let (f0, f1) = (freq(None), freq(Some(&line)));
    // hand: the strut stiffnesses at the static pressure, the tire's tangent stiffness
    let statics = crate::Statics::of(&p, Load::Loaded).unwrap();
    let strut = HpsStrut::new(&p.hps, &Default::default()).unwrap();
    let z =
        crate::statics::strut_static_deflection(&strut, statics.front_strut_force_n(&p)).unwrap();
    let p_s = strut.static_pressure(z).unwrap();
    let mut s = vec![0.0; strut.n_states()];
    strut.initial_state(z, &mut s).unwrap();
    let c0 = strut.chamber_compliances(z, &s);
    let k0 = p.hps.a_hr.powi(2) / (c0.piston + c0.rod);
    let pair = CrossCoupledPair::new(
        [0, 1].map(|_| HpsStrut::ported(&sealed_piston(&p.hps), &Default::default()).unwrap()),
        &lines,
    )
    .unwrap();
    let kb = pair.mode_stiffness([p_s; 2], [z; 2], [1.0, 1.0]).unwrap();
    let table = tire_fiala::LoadDeflectionTable::new(&p.tire.load_deflection).unwrap();
    let d = statics.front_tire_deflection_m;
    let kt = (table.load(d + 1e-4) - table.load(d - 1e-4)) / 2e-4;
    let series = |k: f64| k * kt / (k + kt);
    let hand = (series(kb) / series(k0)).sqrt();
    println!(
        "free bounce {f0:.3} -> {f1:.3} Hz, ratio {:.3}, hand {hand:.3} (k_s {:.0} -> {:.0} \
         kN/m, k_t {:.0} kN/m)",
        f1 / f0,
        k0 / 1e3,
        kb / 1e3,
        kt / 1e3
    );
    assert!((f1 / f0 / hand - 1.0).abs() < 0.05, "{} {hand}", f1 / f0);
    // the roll mode (the front unit's roll with the rear unit's and the tires') rises
    let roll = |l: Option<&Link>| {
        let r = free_response(&p, l, Kick::Roll, 0.05, 2.0).unwrap();
        extrema_frequency(&r.t_s, &r.front_rate_rad_s[0], 6)
    };
    let (r0, r1) = (roll(None), roll(Some(&line)));
    println!("free roll {r0:.3} -> {r1:.3} Hz");
    assert!(r1 > 1.05 * r0, "{r0} {r1}");
}

#[test]
fn with_struts_on_both_axles_the_rear_struts_keep_their_own_blocks() {
    let mut p = VehicleParams::nominal();
    p.rear_hps = Some(p.default_rear_strut().unwrap());
    let flat = FlatTerrain::new(0.0, vehicle_components::DEFAULT_FRICTION).unwrap();
    let options = VehicleOptions {
        front_axle: FrontAxle::Suspended,
        path_length_m: 20.0,
        ..VehicleOptions::default()
    };
    let v = Vehicle::new(&p, Load::Loaded, options, &flat, 0.5 * p.front_track_m).unwrap();
    let own: Vec<Vec<usize>> = v.stiff_blocks().to_vec();
    assert_eq!(own.len(), 4, "two front and two rear struts");
    let y = v.initial_state();
    let linked = LinkedVehicle::new(v, &Link::Roll(LineParams::front_axle_roll())).unwrap();
    let blocks = linked.stiff_blocks();
    assert_eq!(blocks.len(), 3, "the linked pair, then the two rear struts");
    assert_eq!(blocks[1..], own[2..]);
    // a rear block's Jacobian is the vehicle's own, the pair's is the pair's
    let yl = linked.initial_state().unwrap();
    for (b, vehicle_block) in [(1, 2), (2, 3)] {
        let n = blocks[b].len();
        let (mut mine, mut theirs) = (vec![0.0; n * n], vec![0.0; n * n]);
        assert!(linked.block_jacobian(0.0, &yl, b, &mut mine));
        assert!(linked
            .vehicle()
            .block_jacobian(0.0, &y, vehicle_block, &mut theirs));
        assert_eq!(mine, theirs);
    }
    let mut pair = vec![0.0; blocks[0].len().pow(2)];
    assert!(linked.block_jacobian(0.0, &yl, 0, &mut pair));
    assert!(pair.iter().all(|v| v.is_finite()) && pair.iter().any(|v| *v != 0.0));
    assert!(!linked.block_jacobian(0.0, &yl, 3, &mut pair));
}

#[test]
fn the_linked_yaw_run_refuses_rough_ground() {
    let p = VehicleParams::nominal();
    let spec = YawSpec {
        terrain: Some(crate::scenarios::TerrainSpec::default()),
        ..YawSpec::d3(FrontAxle::Suspended)
    };
    // a line design alone is the front roll link
    let e = yaw_linked(&p, &spec, &LineParams::front_axle_roll()).unwrap_err();
    assert!(e.to_string().contains("smooth ground"), "{e}");
}

/// The pitch-linked vehicle with every loss but the lines' ports off (tire damping and
/// horizontal forces, rolling resistance, steering leakage and seals, drive, strut
/// friction; the sealed pistons have no orifice), released moving in bounce, pitch and
/// roll on flat ground: the energy of [`Vehicle::energy`] (with the struts' stored energy)
/// plus every line's stored energy ([`hps_emulsion::HydraulicLine::stored_energy`]) never
/// rises from one 10 ms sample to the next beyond the bookkeeping bound below, and the
/// ports take a good part of it. The bound: a line counts its oil as pure oil of bulk
/// modulus `beta_h`, a strut chamber its emulsion's specific energy `e(P)` per kg (Eqs
/// 6.14-6.16, from `P_h0`); oil that crosses a port changes the count by `rho e(P)` per m^3
/// without any work, at most `max |rho e| x` the oil a line moves (here under 1e-3 of the
/// released energy).
#[test]
fn the_pitch_lines_only_dissipate() {
    let mut p = VehicleParams::nominal();
    p.rear_hps = Some(p.default_rear_strut().unwrap());
    p.tire.vertical_damping_n_s_per_m = 0.0;
    p.tire.u_max = 1e-12;
    p.tire.u_min = 1e-12;
    p.drive.kp_n_m_per_m_s = 1e-12;
    p.drive.ki_n_m_per_m = 0.0;
    p.tire.rolling_resistance_coefficient = 0.0;
    p.steering.leak_const = 0.0;
    p.steering.leak_velocity = 0.0;
    p.steering.seal_viscous_n_s_m = 0.0;
    for s in [&mut p.hps, p.rear_hps.as_mut().unwrap()] {
        s.friction.mu_v = 0.0;
        s.friction.f_c = 0.0;
        s.friction.f_s = 0.0;
    }
    let flat = FlatTerrain::new(0.0, 0.8).unwrap();
    let options = VehicleOptions {
        front_axle: FrontAxle::Suspended,
        speed_m_s: 3.0,
        path_length_m: 20.0,
        ..VehicleOptions::default()
    };
    let v = Vehicle::new(&p, Load::Loaded, options, &flat, 0.5 * p.front_track_m).unwrap();
    let linked = LinkedVehicle::new(v, &Link::pitch_of(&p).unwrap()).unwrap();
    let v = linked.vehicle();
    let o = *v.offsets();
    let energy = |y: &[f64]| -> f64 {
        let lines: f64 = linked
            .pairs()
            .enumerate()
            .flat_map(|(i, pair)| (0..2).map(move |k| (i, k, pair)))
            .map(|(i, k, pair)| pair.line(k).stored_energy(y[linked.line_state(i, k)]))
            .sum();
        v.energy(&y[..o.dim]).unwrap() + lines
    };
    let mut y = linked.initial_state().unwrap();
    let e_static = energy(&y);
    y[o.v + 5] = 0.2;
    y[o.v + 1] = 0.05;
    y[o.v] = 0.08;
    let e0 = energy(&y);
    let released = e0 - e_static;
    let mut e = Vec::new();
    let t0 = std::time::Instant::now();
    let run = RunOptions {
        t_end_s: 1.5,
        output_dt_s: 0.01,
        ..RunOptions::default()
    };
    let mut t = v.state_layout().typicals().to_vec();
    t.extend_from_slice(&y[o.dim..]);
    simulate_system(v, &linked, &y, t, &run, |_, y| e.push(energy(y))).unwrap();
    let rise = e.windows(2).fold(f64::MIN, |m, w| m.max(w[1] - w[0]));
    let lost = e0 - e[e.len() - 1];
    println!(
        "pitch-linked, released {released:.1} J: largest rise between samples {rise:.3} J, \
         lost {lost:.1} J in 1.5 s ({:.2} s)",
        t0.elapsed().as_secs_f64()
    );
    assert!(
        rise < 1e-3 * released,
        "the energy rose by {rise} J of {released} J"
    );
    assert!(
        lost > 0.2 * released,
        "the lines took only {lost} J of {released} J"
    );
}
