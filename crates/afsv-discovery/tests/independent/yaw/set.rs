//! Record sets of the independent vehicle: manoeuvres, sensor noise, CSV + sidecar files.

use super::*;

/// Measurement noise of the vehicle records (standard deviations).
pub const YAW_NOISE: [(&str, f64); 7] = [
    ("steer_wheel_deg", 0.1),
    ("speed_m_s", 0.05),
    ("articulation_deg", 0.05),
    ("strut_left_disp_m", 1.0e-4),
    ("p_c_pa", 2.0e4),
    ("p_r_pa", 2.0e4),
    ("yaw_rate_front_deg_s", 0.2),
];

/// Record sample rate (Hz).
pub const YAW_SAMPLE_HZ: f64 = 100.0;

/// Manoeuvre kinds, cycled through in every set.
pub const YAW_KINDS: [&str; 4] = ["pulse", "step", "ramp", "sine"];

/// Steering input of a given kind at a speed, sized for a realistic lateral acceleration.
fn manoeuvre(kind: &str, speed_kmh: f64, rng: &mut Noise) -> Steer {
    let u = speed_kmh / 3.6;
    // articulation giving a_y of 1.2-2.0 m/s^2 on a ~5.1 m front-axle-to-rear-axle
    // wheelbase, at most 12 deg; the wheel angle from a steering gain of ~0.035 deg/deg.
    let a_y = rng.range(1.2, 2.0);
    let theta_deg = (5.1 * a_y / (u * u) / DEG).min(12.0);
    let wheel = (theta_deg / 0.035).clamp(40.0, 340.0);
    let sign = if rng.uniform() < 0.5 { -1.0 } else { 1.0 };
    let start_s = 1.0;
    let round1 = |x: f64| (x * 10.0).round() / 10.0;
    match kind {
        "pulse" => Steer::Pulse {
            amp_deg: sign * round1((0.6 * wheel).clamp(30.0, 120.0)),
            dur_s: round1(rng.range(0.2, 0.4)),
            start_s,
        },
        "step" => Steer::Step {
            amp_deg: sign * round1(wheel),
            start_s,
        },
        "ramp" => Steer::Ramp {
            rate_deg_s: sign * round1(rng.range(60.0, 150.0)),
            start_s,
            limit_deg: round1(1.2 * wheel),
        },
        "sine" => Steer::Sine {
            amp_deg: sign * round1(0.8 * wheel),
            freq_hz: (rng.range(0.3, 0.6) * 100.0).round() / 100.0,
            start_s,
            cycles: 2.0,
        },
        other => panic!("unknown manoeuvre {other}"),
    }
}

fn steer_json(s: &Steer) -> serde_json::Value {
    match *s {
        Steer::Pulse {
            amp_deg,
            dur_s,
            start_s,
        } => {
            serde_json::json!({"kind": "pulse", "amplitude_deg": amp_deg, "duration_s": dur_s, "start_s": start_s})
        }
        Steer::Step { amp_deg, start_s } => {
            serde_json::json!({"kind": "step", "amplitude_deg": amp_deg, "start_s": start_s})
        }
        Steer::Ramp {
            rate_deg_s,
            start_s,
            limit_deg,
        } => {
            serde_json::json!({"kind": "ramp", "rate_deg_s": rate_deg_s, "start_s": start_s, "limit_deg": limit_deg})
        }
        Steer::Sine {
            amp_deg,
            freq_hz,
            start_s,
            cycles,
        } => {
            serde_json::json!({"kind": "sine", "amplitude_deg": amp_deg, "frequency_hz": freq_hz, "start_s": start_s, "cycles": cycles})
        }
    }
}

/// Write a vehicle record set: `dir/train/*.csv|json`, `dir/holdout/*.csv|json` and
/// `dir/truth.json`. Records alternate pulse, step, ramp, sine (all four appear in both
/// sets when `n_train >= 4` and `n_holdout >= 4`) and mix loaded/unloaded so each kind
/// appears with both loads over eight records. Training speeds are spread evenly over
/// 15-50 km/h (shuffled over the kinds), held-out speeds drawn inside 20-45 km/h. The
/// truth model is [`YawParams::perturbed`] plus the hidden effect.
pub fn yaw_record_set(
    dir: &Path,
    hidden: Option<(&str, f64)>,
    n_train: usize,
    n_holdout: usize,
    duration_s: f64,
    seed: u64,
) {
    yaw_record_set_of(
        dir,
        YawParams::perturbed,
        hidden,
        (n_train, n_holdout),
        duration_s,
        seed,
    );
}

/// [`yaw_record_set`] with the truth's vehicle per load from `params` and
/// `(n_train, n_holdout)` records.
pub fn yaw_record_set_of(
    dir: &Path,
    params: fn(YawLoad) -> YawParams,
    hidden: Option<(&str, f64)>,
    (n_train, n_holdout): (usize, usize),
    duration_s: f64,
    seed: u64,
) {
    let effect = match hidden {
        Some((name, size)) => YawHidden::from_name(name, size),
        None => YawHidden::None,
    };
    let mut rng = Noise::new(seed, 0x0079_6177);
    // training speeds: evenly spread, shuffled (Fisher-Yates)
    let mut speeds: Vec<f64> = (0..n_train)
        .map(|i| {
            if n_train > 1 {
                15.0 + 35.0 * i as f64 / (n_train - 1) as f64
            } else {
                30.0
            }
        })
        .collect();
    for i in (1..speeds.len()).rev() {
        let j = (rng.next_u64() % (i as u64 + 1)) as usize;
        speeds.swap(i, j);
    }
    let mut plan = Vec::new();
    for (i, sp) in speeds.iter().enumerate() {
        let load = if (i + i / 4) % 2 == 0 {
            YawLoad::Loaded
        } else {
            YawLoad::Unloaded
        };
        plan.push(("train", i, load, (sp * 10.0).round() / 10.0));
    }
    for j in 0..n_holdout {
        let load = if (j + j / 4) % 2 == 0 {
            YawLoad::Unloaded
        } else {
            YawLoad::Loaded
        };
        let sp = (rng.range(20.0, 45.0) * 10.0).round() / 10.0;
        plan.push(("holdout", j, load, sp));
    }
    let mut listing = Vec::new();
    for (set, i, load, speed_kmh) in plan {
        let kind = YAW_KINDS[i % 4];
        let steer = manoeuvre(kind, speed_kmh, &mut rng);
        let params = params(load);
        let run = simulate_yaw(
            &params,
            effect,
            &steer,
            speed_kmh / 3.6,
            duration_s,
            YAW_SAMPLE_HZ,
        );
        let name = format!(
            "yaw_{i:02}_{kind}_{}_{}kmh",
            load.name(),
            format!("{speed_kmh}").replace('.', "p")
        );
        let stream = if set == "train" { 1000 } else { 2000 } + i as u64;
        let mut noise = Noise::new(seed, stream);
        let mut chans: Vec<Vec<f64>> = run.channels().iter().map(|(_, v)| v.to_vec()).collect();
        for (c, (_, sd)) in chans.iter_mut().zip(YAW_NOISE.iter()) {
            noise.add(c, *sd);
        }
        let decimals = [3, 3, 3, 5, 0, 0, 3];
        let mut cols = vec![Column {
            name: "time_s",
            values: &run.time_s,
            decimals: 2,
        }];
        for (k, (nm, _)) in YAW_NOISE.iter().enumerate() {
            cols.push(Column {
                name: nm,
                values: &chans[k],
                decimals: decimals[k],
            });
        }
        let sidecar = serde_json::json!({
            "sample_rate_hz": YAW_SAMPLE_HZ,
            "load": load.name(),
            "speed_kmh": speed_kmh,
            "manoeuvre": kind,
            "sign_convention": "afsv-v1",
            "source": "independent implementation (tests/independent)",
            "units": {"time_s": "s", "steer_wheel_deg": "deg", "speed_m_s": "m/s",
                      "articulation_deg": "deg", "strut_left_disp_m": "m", "p_c_pa": "Pa",
                      "p_r_pa": "Pa", "yaw_rate_front_deg_s": "deg/s"},
        });
        write_record(&dir.join(set), &name, &cols, &sidecar);
        listing.push(serde_json::json!({
            "set": set, "name": name, "load": load.name(), "speed_kmh": speed_kmh,
            "steer": steer_json(&steer),
        }));
    }
    let truth = serde_json::json!({
        "model": "yaw-plane",
        "source": "independent implementation (tests/independent/yaw.rs)",
        "hidden_effect": match hidden {
            Some((name, size)) => serde_json::json!({"name": name, "size": size, "unit": YawHidden::unit(name)}),
            None => serde_json::Value::Null,
        },
        "note": "truth = the full paper model (tire relaxation Eq 3.16 and velocity leakage Eq 3.6 present) at the perturbed parameters",
        "perturbations": YAW_PERTURBATION.iter().map(|(n, v)| (n.to_string(), serde_json::json!(v))).collect::<serde_json::Map<_, _>>(),
        "parameters": {"loaded": params(YawLoad::Loaded).json(),
                       "unloaded": params(YawLoad::Unloaded).json()},
        "noise_sd": YAW_NOISE.iter().map(|(n, v)| (n.to_string(), serde_json::json!(v))).collect::<serde_json::Map<_, _>>(),
        "duration_s": duration_s,
        "seed": seed,
        "integrator": {"method": "classic RK4, fixed step", "step_s": YAW_STEP_S},
        "records": listing,
    });
    write_json(&dir.join("truth.json"), &truth);
}
