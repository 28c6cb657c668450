//! The independent strut implementation (`tests/independent/strut.rs`, written from
//! Chapter 5 of the dissertation) against the toolkit's model
//! (`hps_emulsion::simulate_displacement` with `StrutParams::front_axle()`), the visibility
//! of each hidden effect, and the bench record-set generator. The crates are called here
//! only, never inside `tests/independent/`.
//!
//! Measured agreement (Table 6.3, no hidden effect, NRMSE = RMS difference / standard
//! deviation of the crate's channel): 1 Hz +-25 mm: force 0.006 %, P_hc < 0.001 %,
//! P_hr 0.009 %; 6 Hz +-4.8 mm: force 0.007 %, P_hc 0.001 %, P_hr 0.008 %; 0.1 Hz +-50 mm:
//! force 0.007 %, P_hr 0.014 %. The tolerance is 0.1 %. The four hidden effects agree
//! with the crate's extensions to <= 0.011 % as well.
//!
//! Observed in the crate (not changed): with `ValveLag` on, a 0.1 Hz run (Rosenbrock23
//! under `Solver::Auto`) fails with "solver diverged" at rtol 1e-8 / atol 1e-11 (t = 7.5 s)
//! and at rtol 1e-9 / atol 1e-12 (t = 0): the valve target switches discontinuously on
//! sign(P_hc - P_hr), which is exactly zero at the static start. Default tolerances work.

mod independent;

use hps_emulsion::{
    simulate_displacement, AsymmetricFriction, Excitation, GasFractionGrowth, HeatTransfer,
    HpsExtensions, SimOptions, StrutParams, ValveLag,
};
use independent::strut::{
    bench_programme, simulate_strut, BenchTest, StrutData, StrutHidden, StrutRun, STRUT_NOISE,
};
use independent::{default_size, strut_record_set, STRUT_EFFECTS};

fn rms_diff(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len().min(b.len());
    ((0..n).map(|i| (a[i] - b[i]).powi(2)).sum::<f64>() / n as f64).sqrt()
}

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

fn crate_run(t: &BenchTest, ext: &HpsExtensions) -> StrutRun {
    let ex = Excitation::harmonic(t.freq_hz, t.amp_m, t.cycles);
    let opts = SimOptions {
        output_rate_hz: t.sample_hz,
        rtol: 1e-9,
        atol: 1e-12,
        ..SimOptions::default()
    };
    let r = simulate_displacement(&StrutParams::front_axle(), ext, &ex, &opts).unwrap();
    StrutRun {
        time_s: r.time,
        displacement_m: r.displacement,
        velocity_m_s: r.velocity,
        force_n: r.force,
        p_piston_pa: r.p_piston,
        p_rod_pa: r.p_rod,
    }
}

fn compare(mine: &StrutRun, theirs: &StrutRun) -> (f64, String) {
    let n = mine.time_s.len();
    // the crate appends the end time when the grid misses it; compare the common samples
    assert!(theirs.time_s.len() >= n);
    for k in 0..n {
        assert!((mine.time_s[k] - theirs.time_s[k]).abs() < 1e-9);
    }
    let mut worst: f64 = 0.0;
    let mut text = Vec::new();
    for ((name, a), (_, b)) in mine.channels().iter().zip(theirs.channels().iter()) {
        let e = nrmse(a, &b[..n]);
        worst = worst.max(e);
        text.push(format!("{name} {:.4} %", 100.0 * e));
    }
    (worst, text.join(", "))
}

const ONE_HZ: BenchTest = BenchTest {
    freq_hz: 1.0,
    amp_m: 0.025,
    cycles: 5.0,
    sample_hz: 500.0,
};
const SIX_HZ: BenchTest = BenchTest {
    freq_hz: 6.0,
    amp_m: 0.0048,
    cycles: 8.0,
    sample_hz: 1000.0,
};
const SLOW: BenchTest = BenchTest {
    freq_hz: 0.1,
    amp_m: 0.05,
    cycles: 2.0,
    sample_hz: 50.0,
};

#[test]
fn agrees_with_the_crate_model_at_1_and_6_hz() {
    for t in [ONE_HZ, SIX_HZ, SLOW] {
        let mine = simulate_strut(&StrutData::table_6_3(), StrutHidden::None, &t);
        let theirs = crate_run(&t, &HpsExtensions::none());
        let (worst, text) = compare(&mine, &theirs);
        println!("{} Hz +-{} mm: {text}", t.freq_hz, t.amp_m * 1e3);
        assert!(worst < 1e-3, "{} Hz: {text}", t.freq_hz);
    }
}

/// The crate has all four hidden effects as extensions: the independent versions agree.
#[test]
fn hidden_effects_agree_with_the_crate_extensions() {
    let none = HpsExtensions::none();
    let cases = [
        (
            "gas-heat-transfer",
            HpsExtensions {
                heat_transfer: Some(HeatTransfer {
                    tau: default_size("gas-heat-transfer"),
                    kappa: 1.4,
                }),
                ..none
            },
        ),
        (
            "gas-fraction-growth",
            HpsExtensions {
                gas_fraction_growth: Some(GasFractionGrowth {
                    k_gamma: default_size("gas-fraction-growth"),
                }),
                ..none
            },
        ),
        (
            "asymmetric-friction",
            HpsExtensions {
                asymmetric_friction: Some(AsymmetricFriction {
                    compression: default_size("asymmetric-friction"),
                    extension: 1.0 / default_size("asymmetric-friction"),
                }),
                ..none
            },
        ),
        (
            "check-valve-lag",
            HpsExtensions {
                valve_lag: Some(ValveLag {
                    tau: default_size("check-valve-lag"),
                }),
                ..none
            },
        ),
    ];
    for t in [ONE_HZ, SIX_HZ] {
        for (name, ext) in &cases {
            let h = StrutHidden::from_name(name, default_size(name));
            let mine = simulate_strut(&StrutData::table_6_3(), h, &t);
            let theirs = crate_run(&t, ext);
            let (worst, text) = compare(&mine, &theirs);
            println!("{} Hz {name}: {text}", t.freq_hz);
            assert!(worst < 1e-3, "{} Hz {name}: {text}", t.freq_hz);
        }
    }
}

/// Each hidden effect at its default size changes some channel of the bench programme by
/// more than twice that channel's noise (RMS; over a whole record
/// such a systematic change is far above what noise explains). Weakest measured:
/// asymmetric friction 2x / 0.5x at 2.9x the load-cell noise (0.1 Hz).
#[test]
fn each_hidden_effect_changes_the_outputs_beyond_the_noise() {
    let d = StrutData::perturbed();
    let programme = bench_programme();
    let base: Vec<StrutRun> = programme
        .iter()
        .map(|(t, _)| simulate_strut(&d, StrutHidden::None, t))
        .collect();
    for name in STRUT_EFFECTS {
        let h = StrutHidden::from_name(name, default_size(name));
        let mut best = (0.0, String::new());
        for ((t, _), b) in programme.iter().zip(&base) {
            let with = simulate_strut(&d, h, t);
            for (((ch, x), (_, y)), (_, sd)) in with
                .channels()
                .iter()
                .zip(b.channels().iter())
                .zip(STRUT_NOISE.iter())
            {
                let ratio = rms_diff(x, y) / sd;
                if ratio > best.0 {
                    best = (ratio, format!("{} Hz {ch}", t.freq_hz));
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
    let a = independent::scratch("strut-a");
    let b = independent::scratch("strut-b");
    let c = independent::scratch("strut-c");
    strut_record_set(&a, Some(("gas-heat-transfer", 2.0)), 3);
    strut_record_set(&b, Some(("gas-heat-transfer", 2.0)), 3);
    strut_record_set(&c, Some(("gas-heat-transfer", 2.0)), 4);
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

    let header = "time_s,displacement_m,velocity_m_s,force_n,p_piston_pa,p_rod_pa";
    let mut freqs = std::collections::BTreeMap::new();
    for (path, bytes) in fa.iter().filter(|(p, _)| p.ends_with(".csv")) {
        let text = String::from_utf8(bytes.clone()).unwrap();
        let mut lines = text.lines();
        assert_eq!(lines.next().unwrap(), header);
        let rows: Vec<Vec<f64>> = lines
            .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
            .collect();
        let side_text = std::fs::read_to_string(a.join(path.replace(".csv", ".json"))).unwrap();
        assert!(
            !side_text.contains("heat"),
            "hidden effect leaked into {path}"
        );
        let side: serde_json::Value = serde_json::from_str(&side_text).unwrap();
        assert_eq!(side["sign_convention"], "afsv-v1");
        assert_eq!(
            side["source"],
            "independent implementation (tests/independent)"
        );
        let rate = side["sample_rate_hz"].as_f64().unwrap();
        let f = side["frequency_hz"].as_f64().unwrap();
        let cycles = side["cycles"].as_f64().unwrap();
        assert_eq!(
            rows.len(),
            (cycles / f * rate).round() as usize + 1,
            "{path}"
        );
        assert!((rows[1][0] - 1.0 / rate).abs() < 1e-9);
        // compression raises the gas pressure: force and P_hc follow the displacement
        let zf: f64 = rows.iter().map(|r| r[1] * (r[3] - rows[0][3])).sum();
        assert!(zf > 0.0, "{path}: force against the displacement");
        assert!(
            rows.iter().all(|r| r[4] > 1e6 && r[5] > 1e5),
            "{path}: pressures"
        );
        freqs.insert(path.clone(), f);
    }
    let train: Vec<f64> = freqs
        .iter()
        .filter(|(p, _)| p.starts_with("train/"))
        .map(|(_, f)| *f)
        .collect();
    let held: Vec<f64> = freqs
        .iter()
        .filter(|(p, _)| p.starts_with("holdout/"))
        .map(|(_, f)| *f)
        .collect();
    assert_eq!(train.len(), 5);
    assert_eq!(held.len(), 2);
    let (lo, hi) = train
        .iter()
        .fold((f64::MAX, f64::MIN), |(l, h), &x| (l.min(x), h.max(x)));
    assert!(lo <= 0.1 && hi >= 8.0);
    assert!(
        held.iter().all(|&f| f > lo && f < hi),
        "held-out tests inside the training range"
    );

    let truth: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(a.join("truth.json")).unwrap()).unwrap();
    assert_eq!(truth["hidden_effect"]["name"], "gas-heat-transfer");
    assert_eq!(truth["hidden_effect"]["size"], 2.0);
    assert_eq!(truth["records"].as_array().unwrap().len(), 7);
    assert!((truth["parameters"]["gamma0"].as_f64().unwrap() - 0.022).abs() < 1e-12);
    for dir in [a, b, c] {
        let _ = std::fs::remove_dir_all(dir);
    }
}

/// The realistic variant (`tests/independent/realistic.rs`) at Table 6.3 differs from the
/// crate's model by a few percent, as two faithful implementations do (issue 24: about 3 %
/// force NRMSE on the front-axle strut), not by the 0.01 % of the note's readings.
#[test]
fn the_realistic_variant_differs_from_the_crate_by_a_few_percent() {
    let d = independent::realistic::strut_choices(StrutData::table_6_3());
    let mut force = Vec::new();
    for t in [ONE_HZ, SIX_HZ, SLOW] {
        let mine = simulate_strut(&d, StrutHidden::None, &t);
        let theirs = crate_run(&t, &HpsExtensions::none());
        let (worst, text) = compare(&mine, &theirs);
        println!("realistic {} Hz +-{} mm: {text}", t.freq_hz, t.amp_m * 1e3);
        force.push(nrmse(&mine.force_n, &theirs.force_n[..mine.force_n.len()]));
        assert!(worst < 0.3, "{text}");
    }
    let mean = force.iter().sum::<f64>() / force.len() as f64;
    assert!((0.01..0.1).contains(&mean), "mean force NRMSE {mean}");
}
