//! The independent yaw-plane implementation (`tests/independent/yaw.rs`, written from
//! Chapter 3 of the dissertation) against the toolkit's model (`afsv_dynamics::simulate`
//! with `afs_hydraulics`), the visibility of each hidden effect, and the record-set
//! generator. The crates are called here only, never inside `tests/independent/`.
//!
//! Measured agreement (nominal Table 3.1, no hidden effect, 50 km/h, NRMSE = RMS
//! difference / standard deviation of the crate's channel, 100 Hz, 10 s): at most 0.30 %
//! (P_c, loaded step), articulation <= 0.10 %, yaw rate <= 0.28 %; the tolerance is 1 %.
//! The sine runs agree to 1e-5. The residual differences are explained, not bugs: the
//! loaded 50 km/h pulse and step reach the cavitation floor, which the two implementations
//! model differently (here 20 kPa with a linear 30 kPa taper, in afs-hydraulics 10 kPa with
//! a 40 kPa smoothstep; with our floor set to theirs the loaded pulse agrees to 0.014 %),
//! and the fixed 0.5 ms RK4 step across the step input and the valve kinks (at 0.1 ms the
//! unloaded step agrees to 0.05 %).

mod independent;

use afs_hydraulics::{AfsExtensions, CoulombFriction, EntrainedAir, SupplyDroop};
use afsv_dynamics::{simulate, Load, Manoeuvre, SimOptions, SteerInput, YawPlaneParams};
use independent::yaw::{
    simulate_yaw, Steer, YawHidden, YawLoad, YawParams, YawRun, YAW_KINDS, YAW_NOISE,
};
use independent::{default_size, yaw_record_set, YAW_EFFECTS};

/// RMS difference over the standard deviation of the reference.
fn nrmse(a: &[f64], reference: &[f64]) -> f64 {
    let n = a.len().min(reference.len());
    let mean = reference[..n].iter().sum::<f64>() / n as f64;
    let var = reference[..n]
        .iter()
        .map(|x| (x - mean).powi(2))
        .sum::<f64>()
        / n as f64;
    rms_diff(a, reference) / var.sqrt().max(1e-300)
}

fn rms_diff(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len().min(b.len());
    ((0..n).map(|i| (a[i] - b[i]).powi(2)).sum::<f64>() / n as f64).sqrt()
}

fn load_of(l: YawLoad) -> Load {
    match l {
        YawLoad::Loaded => Load::Loaded,
        YawLoad::Unloaded => Load::Unloaded,
    }
}

/// The toolkit's model on the same manoeuvre (tight tolerances, 100 Hz output).
fn crate_run(
    load: YawLoad,
    steer: &Steer,
    speed: f64,
    duration: f64,
    ext: AfsExtensions,
) -> YawRun {
    let params = YawPlaneParams::nominal(load_of(load));
    let afs = params.afs_system().unwrap().with_extensions(ext).unwrap();
    let input = match *steer {
        Steer::Pulse {
            amp_deg,
            dur_s,
            start_s,
        } => SteerInput::pulse_deg(amp_deg, dur_s, start_s),
        Steer::Ramp {
            rate_deg_s,
            start_s,
            limit_deg,
        } => SteerInput::Ramp {
            rate_rad_s: rate_deg_s.to_radians(),
            start_s,
            limit_rad: limit_deg.to_radians(),
        },
        // the crate has no sine and no smooth-step input: a 1 ms table (interpolation
        // error < 1e-5 relative)
        Steer::Sine { .. } | Steer::Step { .. } => {
            let t: Vec<f64> = (0..=(duration * 1000.0).round() as usize)
                .map(|k| k as f64 * 1e-3)
                .collect();
            let a = t.iter().map(|&x| steer.deg(x).to_radians()).collect();
            SteerInput::Table {
                time_s: t,
                angle_rad: a,
            }
        }
    };
    let m = Manoeuvre::open_loop(speed, duration, input, steer.kind());
    let opts = SimOptions {
        rtol: 1e-8,
        atol: 1e-10,
        output_dt_s: 0.01,
        max_step_s: 0.002,
        record_energy: false,
        ..SimOptions::default()
    };
    let r = simulate(&params.vehicle, &afs, &m, &opts).unwrap();
    YawRun {
        time_s: r.time_s,
        steer_wheel_deg: r.steer_wheel_deg,
        speed_m_s: r.speed_m_s,
        articulation_deg: r.articulation_deg,
        strut_left_disp_m: r.strut_left_disp_m,
        p_c_pa: r.p_c_pa,
        p_r_pa: r.p_r_pa,
        yaw_rate_front_deg_s: r.yaw_rate_front_deg_s,
    }
}

const LOADS: [YawLoad; 2] = [YawLoad::Loaded, YawLoad::Unloaded];

fn worst_channel(mine: &YawRun, theirs: &YawRun) -> (f64, Vec<(String, f64)>) {
    assert_eq!(mine.time_s.len(), theirs.time_s.len());
    for (a, b) in mine.time_s.iter().zip(&theirs.time_s) {
        assert!((a - b).abs() < 1e-9, "sample times differ: {a} vs {b}");
    }
    let mut worst: f64 = 0.0;
    let mut per = Vec::new();
    for ((name, a), (_, b)) in mine.channels().iter().zip(theirs.channels().iter()) {
        if *name == "speed_m_s" {
            continue; // constant in both
        }
        let e = nrmse(a, b);
        worst = worst.max(e);
        per.push((name.to_string(), e));
    }
    (worst, per)
}

#[test]
fn agrees_with_the_crate_model_on_pulse_step_and_sine_for_both_loads() {
    let speed = 50.0 / 3.6;
    let cases = [
        Steer::Pulse {
            amp_deg: 30.0,
            dur_s: 0.2,
            start_s: 0.5,
        },
        Steer::Step {
            amp_deg: 30.0,
            start_s: 0.5,
        },
        Steer::Sine {
            amp_deg: 60.0,
            freq_hz: 0.5,
            start_s: 0.5,
            cycles: 2.0,
        },
    ];
    let mut failures = Vec::new();
    for load in LOADS {
        for s in &cases {
            let mine = simulate_yaw(
                &YawParams::table_3_1(load),
                YawHidden::None,
                s,
                speed,
                10.0,
                100.0,
            );
            let theirs = crate_run(load, s, speed, 10.0, AfsExtensions::default());
            let (worst, per) = worst_channel(&mine, &theirs);
            println!("{} {}: {}", load.name(), s.kind(), fmt(&per));
            if worst >= 0.01 {
                failures.push(format!("{} {}: {}", load.name(), s.kind(), fmt(&per)));
            }
        }
    }
    assert!(failures.is_empty(), "NRMSE >= 1 %: {failures:#?}");
}

fn fmt(per: &[(String, f64)]) -> String {
    per.iter()
        .map(|(n, e)| format!("{n} {:.3} %", 100.0 * e))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Three hidden effects also exist in afs-hydraulics as extensions: the two independent
/// implementations of those agree too (a 60 deg step at 30 km/h).
#[test]
fn shared_effects_agree_with_the_crate_extensions() {
    let s = Steer::Step {
        amp_deg: 60.0,
        start_s: 0.5,
    };
    let speed = 30.0 / 3.6;
    let cases = [
        (
            "supply-droop",
            AfsExtensions {
                supply_droop: Some(SupplyDroop {
                    droop_pa_s_per_m3: default_size("supply-droop"),
                }),
                ..Default::default()
            },
        ),
        (
            "strut-coulomb-friction",
            AfsExtensions {
                coulomb_friction: Some(CoulombFriction {
                    force_n: default_size("strut-coulomb-friction"),
                    velocity_scale_m_s: 0.005,
                }),
                ..Default::default()
            },
        ),
        (
            "entrained-air",
            AfsExtensions {
                entrained_air: Some(EntrainedAir {
                    air_fraction_atm: default_size("entrained-air"),
                    polytropic_index: 1.2,
                    atmospheric_pressure_pa: 101_325.0,
                }),
                ..Default::default()
            },
        ),
    ];
    for load in LOADS {
        for (name, ext) in &cases {
            let h = YawHidden::from_name(name, default_size(name));
            let mine = simulate_yaw(&YawParams::table_3_1(load), h, &s, speed, 8.0, 100.0);
            let theirs = crate_run(load, &s, speed, 8.0, *ext);
            let (worst, per) = worst_channel(&mine, &theirs);
            println!("{} {name}: {}", load.name(), fmt(&per));
            assert!(worst < 0.01, "{} {name}: {}", load.name(), fmt(&per));
        }
    }
}

/// Each hidden effect at its default size changes some channel by more than twice
/// that channel's record noise (RMS), on manoeuvres like those of the record sets.
/// Weakest measured: sensor backlash 0.3 deg at 4.9x the articulation noise.
#[test]
fn each_hidden_effect_changes_the_outputs_beyond_the_noise() {
    let runs = [
        (
            YawLoad::Loaded,
            25.0,
            Steer::Step {
                amp_deg: 120.0,
                start_s: 1.0,
            },
        ),
        (
            YawLoad::Unloaded,
            40.0,
            Steer::Sine {
                amp_deg: 60.0,
                freq_hz: 0.4,
                start_s: 1.0,
                cycles: 2.0,
            },
        ),
        (
            YawLoad::Loaded,
            45.0,
            Steer::Pulse {
                amp_deg: 45.0,
                dur_s: 0.3,
                start_s: 1.0,
            },
        ),
    ];
    for name in YAW_EFFECTS {
        let hidden = YawHidden::from_name(name, default_size(name));
        let mut best = (0.0, String::new());
        for (load, kmh, steer) in &runs {
            let p = YawParams::perturbed(*load);
            let base = simulate_yaw(&p, YawHidden::None, steer, kmh / 3.6, 8.0, 100.0);
            let with = simulate_yaw(&p, hidden, steer, kmh / 3.6, 8.0, 100.0);
            for (((ch, a), (_, b)), (_, sd)) in with
                .channels()
                .iter()
                .zip(base.channels().iter())
                .zip(YAW_NOISE.iter())
            {
                let ratio = rms_diff(a, b) / sd;
                if ratio > best.0 {
                    best = (
                        ratio,
                        format!("{} {kmh} km/h {} {ch}", load.name(), steer.kind()),
                    );
                }
            }
        }
        println!(
            "{name} ({}): largest RMS change / noise = {:.1} ({})",
            default_size(name),
            best.0,
            best.1
        );
        assert!(
            best.0 > 2.0,
            "{name}: RMS change only {:.2} x noise",
            best.0
        );
    }
}

#[test]
fn record_set_has_the_expected_files_sidecars_and_is_deterministic() {
    let a = independent::scratch("yaw-a");
    let b = independent::scratch("yaw-b");
    let c = independent::scratch("yaw-c");
    yaw_record_set(&a, Some(("valve-lag", 0.04)), 8, 4, 8.0, 11);
    yaw_record_set(&b, Some(("valve-lag", 0.04)), 8, 4, 8.0, 11);
    yaw_record_set(&c, Some(("valve-lag", 0.04)), 8, 4, 8.0, 12);
    let fa = independent::set_files(&a);
    assert_eq!(
        fa,
        independent::set_files(&b),
        "same seed must give identical bytes"
    );
    assert_ne!(
        fa,
        independent::set_files(&c),
        "another seed must give other noise"
    );

    let header = "time_s,steer_wheel_deg,speed_m_s,articulation_deg,strut_left_disp_m,p_c_pa,p_r_pa,yaw_rate_front_deg_s";
    let mut train_speeds = Vec::new();
    for (set, n) in [("train", 8usize), ("holdout", 4)] {
        let csvs: Vec<_> = fa
            .iter()
            .filter(|(p, _)| p.starts_with(&format!("{set}/")) && p.ends_with(".csv"))
            .collect();
        assert_eq!(csvs.len(), n, "{set}: {n} records");
        let mut kinds = std::collections::BTreeSet::new();
        let mut loads = std::collections::BTreeSet::new();
        for (path, bytes) in csvs {
            let text = String::from_utf8(bytes.clone()).unwrap();
            assert!(!text.contains("valve") && !text.contains("lag"));
            let mut lines = text.lines();
            assert_eq!(lines.next().unwrap(), header);
            let rows: Vec<Vec<f64>> = lines
                .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
                .collect();
            assert_eq!(rows.len(), 801, "{path}: 8 s at 100 Hz");
            assert!((rows[1][0] - 0.01).abs() < 1e-12);
            let json_path = a.join(path.replace(".csv", ".json"));
            let side_text = std::fs::read_to_string(&json_path).unwrap();
            assert!(
                !side_text.contains("valve") && !side_text.contains("lag"),
                "hidden effect leaked into {json_path:?}"
            );
            let side: serde_json::Value = serde_json::from_str(&side_text).unwrap();
            assert_eq!(side["sample_rate_hz"], 100.0);
            assert_eq!(side["sign_convention"], "afsv-v1");
            assert_eq!(
                side["source"],
                "independent implementation (tests/independent)"
            );
            let kmh = side["speed_kmh"].as_f64().unwrap();
            assert!((15.0..=50.0).contains(&kmh));
            // the recorded speed is the sidecar's, with noise
            let mean_u = rows.iter().map(|r| r[2]).sum::<f64>() / rows.len() as f64;
            assert!(
                (mean_u - kmh / 3.6).abs() < 0.02,
                "{path}: mean speed {mean_u}"
            );
            if set == "train" {
                train_speeds.push(kmh);
            } else {
                let (lo, hi) = train_speeds
                    .iter()
                    .fold((f64::MAX, f64::MIN), |(l, h), &x| (l.min(x), h.max(x)));
                assert!(
                    kmh > lo && kmh < hi,
                    "held-out speed {kmh} outside training {lo}..{hi}"
                );
            }
            kinds.insert(side["manoeuvre"].as_str().unwrap().to_string());
            loads.insert(side["load"].as_str().unwrap().to_string());
            // a right-hand turn sign check on every record: articulation follows the wheel
            let corr: f64 = rows.iter().map(|r| r[1] * r[3]).sum();
            assert!(corr > 0.0, "{path}: articulation against the wheel");
        }
        assert_eq!(kinds.len(), 4, "{set}: all four manoeuvres, got {kinds:?}");
        for k in YAW_KINDS {
            assert!(kinds.contains(k));
        }
        assert_eq!(loads.len(), 2, "{set}: both loads");
    }
    let truth: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(a.join("truth.json")).unwrap()).unwrap();
    assert_eq!(truth["hidden_effect"]["name"], "valve-lag");
    assert_eq!(truth["hidden_effect"]["size"], 0.04);
    assert_eq!(truth["records"].as_array().unwrap().len(), 12);
    assert!(
        truth["parameters"]["loaded"]["bulk_modulus_gpa"]
            .as_f64()
            .unwrap()
            < 1.6
    );

    // without a hidden effect, truth.json says so
    let d = independent::scratch("yaw-none");
    yaw_record_set(&d, None, 4, 4, 3.0, 5);
    let truth: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("truth.json")).unwrap()).unwrap();
    assert!(truth["hidden_effect"].is_null());
    for dir in [a, b, c, d] {
        let _ = std::fs::remove_dir_all(dir);
    }
}

/// The sign conventions of docs/records.md on a positive (right-hand) step: positive
/// articulation, yaw rate and left-strut extension, P_c > P_r once steered.
#[test]
fn positive_wheel_is_a_right_hand_turn() {
    let s = Steer::Step {
        amp_deg: 90.0,
        start_s: 0.5,
    };
    let r = simulate_yaw(
        &YawParams::table_3_1(YawLoad::Loaded),
        YawHidden::None,
        &s,
        20.0 / 3.6,
        6.0,
        100.0,
    );
    let last = r.time_s.len() - 1;
    assert!(r.articulation_deg[last] > 1.0);
    assert!(r.yaw_rate_front_deg_s[last] > 0.0);
    assert!(r.strut_left_disp_m[last] > 0.0);
    assert!(r.p_c_pa[last] > r.p_r_pa[last]);
}

/// The realistic variant (`tests/independent/realistic.rs`) at Table 3.1 differs from the
/// crate's model by a few percent, as two faithful implementations do, not by the 0.3 % of
/// the note's readings.
#[test]
fn the_realistic_variant_differs_from_the_crate_by_a_few_percent() {
    let speed = 30.0 / 3.6;
    let cases = [
        Steer::Pulse {
            amp_deg: 30.0,
            dur_s: 0.2,
            start_s: 0.5,
        },
        Steer::Sine {
            amp_deg: 60.0,
            freq_hz: 0.5,
            start_s: 0.5,
            cycles: 2.0,
        },
    ];
    let mut all = Vec::new();
    for load in LOADS {
        for s in &cases {
            let p = independent::realistic::vehicle_choices(YawParams::table_3_1(load));
            let mine = simulate_yaw(&p, YawHidden::None, s, speed, 10.0, 100.0);
            let theirs = crate_run(load, s, speed, 10.0, AfsExtensions::default());
            let (_, per) = worst_channel(&mine, &theirs);
            println!("realistic {} {}: {}", load.name(), s.kind(), fmt(&per));
            all.extend(per.into_iter().map(|(_, e)| e));
        }
    }
    let mean = all.iter().sum::<f64>() / all.len() as f64;
    println!("mean NRMSE {:.2} %", 100.0 * mean);
    assert!((0.01..0.1).contains(&mean), "mean NRMSE {mean}");
}
