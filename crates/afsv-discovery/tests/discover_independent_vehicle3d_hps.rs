//! Discovery on records of the independent 3-D vehicle with the front-axle HPS
//! (`tests/independent/vehicle3d`, `Data::nominal_hps`, issue 24): Chapter 6 with the
//! Chapter 5 strut of `tests/independent/strut.rs` at each front wheel, written apart from
//! the crates. The criterion of the issue: on the null set nothing is named; with the
//! strut gas exchanging heat with the strut body (a gas-temperature state relaxing to the
//! wall's with time constant tau, adiabatic between), `hps-gas-temperature` is named first
//! and no other.
//!
//! | test | proves | cost |
//! |---|---|---|
//! | `the_adapter_replays_independent_hps_records` | the HPS adapter (`Vehicle3dModel::nominal(FrontAxle::Suspended)`) reads the independent HPS records (sidecar `front_axle: suspended`) and replays a noise-free class C ride and a V3 record at its nominal parameters within 25 % NRMSE on each sensor axis and 10 % on the speed and the steering channels, and not within 1 % on every ride axis | CI, a few seconds |
//! | `independent_hps_null_set_names_nothing`, `independent_hps_second_null_set_names_nothing` (ignored) | 3 ride + 1 V3 records for training and as many held out (the sibling files' sets), polytropic gas (seeds 41 and 51): nothing named | `cargo test --release --workspace --test discover_independent_vehicle3d_hps -- --ignored --nocapture NAME`; 307-325 s CPU, 15-17 min wall on the shared machine |
//! | `independent_hps_gas_temperature_is_named_first` (ignored) | the same sets with the gas heat transfer at tau = 1 s (seed 42, the crate-made row's size): `hps-gas-temperature` named first, no other, its fitted tau within 15 % of the truth. Failed until each experiment kind got its own channel scale (a model-form discrepancy, tau 0.86 s and then 2.09 s, held-out gain 2.25 % and 3.7 %); since then named, tau 1.047 s, held-out gain 63 % (docs/discovery.md, "The independent 3-D implementation") | same; 755-808 s CPU, 7 min wall on a nearly idle machine, 34 min on the shared one |
//! | `gas_time_constant_profile` (ignored) | prints each record's mean squared NRMSE without the gas effect and along its tau: polytropic records at the nominal parameters, gas records of the gas row's training and held-out sets at the nominal parameters and at its calibrated baseline | same; about 3 min wall on the loaded machine |
//! | `gas_gain_by_channel` (ignored) | prints each experiment kind's channel spreads over the gas row's held-out set, and each channel's NRMSE over that set with the whole set's scales and as the workflow weighs it (each kind by its own spread), at the calibrated baseline of the gas row's run with the whole set's scales, without the gas and at tau 0.86 and 1 s, and the held-out gain (1.8 / 1.9 % with the whole set's scales, 49 % with each kind's) | same; 10-20 s |
// `vehicle3d` (for its `discover_printed`) and `independent` both load the test tree's noise
// source `independent/rng.rs` as a module of their own.
#![allow(clippy::duplicate_mod)]

mod common;
mod independent;
mod vehicle3d;

use afsv_discovery::vehicle3d::Vehicle3dModel;
use afsv_discovery::{evaluate_errors, Discovery, DiscoveryModel, Outcome};
use afsv_records::Record;
use common::{assert_replays_within, summary};
use independent::vehicle3d::{record_hps, records_hps, runs};
use vehicle3d::{discover_printed, Hidden};
use vehicle_3d::FrontAxle;

/// Ride records and V3 path changes in each of the training and held-out sets (as the
/// sibling files).
const RIDES: usize = 3;
/// See [`RIDES`].
const CHANGES: usize = 1;

/// The hidden gas heat transfer's time constant (s): the crate-made row's
/// (`discover_vehicle3d::hidden_hps_gas_temperature_is_named_first`).
const GAS_TAU_S: f64 = 1.0;

fn run(gas_tau_s: Option<f64>, seed: u64) -> Discovery {
    let model = Vehicle3dModel::nominal(FrontAxle::Suspended);
    let t0 = std::time::Instant::now();
    let train = records_hps(&runs(RIDES, CHANGES, seed), gas_tau_s, seed);
    let hold = records_hps(&runs(RIDES, CHANGES, seed + 50), gas_tau_s, seed + 50);
    println!("records written in {:.1} s", t0.elapsed().as_secs_f64());
    let label = gas_tau_s.map_or(Hidden::None, Hidden::GasHeat);
    discover_printed(&model, &train, &hold, label).0
}

#[test]
fn the_adapter_replays_independent_hps_records() {
    let model = Vehicle3dModel::nominal(FrontAxle::Suspended);
    let set = runs(1, 1, 3);
    for (i, r) in set.iter().enumerate() {
        let rec = record_hps(r, None, 0.0, 400 + i as u64);
        assert_eq!(rec.meta["front_axle"], "suspended");
        let label = format!("{:?}", r.ride.map(|(c, _)| c));
        assert_replays_within(&model, &rec, &label, r.ride.is_some());
    }
}

#[test]
#[ignore]
fn independent_hps_null_set_names_nothing() {
    let d = run(None, 41);
    assert!(d.named.is_empty(), "{}", summary(&d));
    assert!(!matches!(d.outcome, Outcome::Named { .. }));
}

#[test]
#[ignore]
fn independent_hps_second_null_set_names_nothing() {
    let d = run(None, 51);
    assert!(d.named.is_empty(), "{}", summary(&d));
    assert!(!matches!(d.outcome, Outcome::Named { .. }));
}

#[test]
#[ignore]
fn independent_hps_gas_temperature_is_named_first() {
    let d = run(Some(GAS_TAU_S), 42);
    assert_eq!(
        d.named.first().map(String::as_str),
        Some("hps-gas-temperature"),
        "{}",
        summary(&d)
    );
    assert!(
        d.named.iter().all(|n| n == "hps-gas-temperature"),
        "a wrong effect named too: {:?}\n{}",
        d.named,
        summary(&d)
    );
    // The named effect is the records' gas, not a proxy at another time constant.
    let tau = d.final_model.effect_params[0][0].value;
    assert!(
        (tau - GAS_TAU_S).abs() <= 0.15 * GAS_TAU_S,
        "tau {tau} s (truth {GAS_TAU_S} s)\n{}",
        summary(&d)
    );
}

/// The calibrated baseline of `independent_hps_gas_temperature_is_named_first` (its printed
/// result of 2026-12-06, seed 42, with the whole set's channel scales and before the
/// `cam-spacing` switch: the default reading, which [`evaluate_errors`] replays), for
/// [`gas_time_constant_profile`] and [`gas_gain_by_channel`].
const GAS_ROW_CALIBRATED: [f64; 8] = [
    0.9866902196711811,
    9250.426058108647,
    35929.35999767154,
    1.2424975703825847,
    1864.683682439319,
    0.029700451271601137,
    576.5584927109567,
    455.37830403100287,
];

/// Prints each record's mean squared NRMSE (over its compared channels) of the adapter's
/// replay without the gas effect and with `hps-gas-temperature` along tau: on the
/// polytropic records of seed 42 at the nominal parameters, and on the gas records of the
/// gas row's training (42) and held-out (92) sets at the nominal parameters and at the gas
/// row's calibrated baseline: whether the catalogue's form takes up what the records' gas
/// does, and where the calibration leaves it (`cargo test --release --workspace --test
/// discover_independent_vehicle3d_hps -- --ignored --nocapture gas_time_constant_profile`,
/// a few minutes).
#[test]
#[ignore]
fn gas_time_constant_profile() {
    let model = Vehicle3dModel::nominal(FrontAxle::Suspended);
    let nominal: Vec<f64> = model.baseline_params().iter().map(|s| s.initial).collect();
    let e = model
        .catalogue()
        .iter()
        .position(|c| c.name == "hps-gas-temperature")
        .unwrap();
    let cases: [(Option<f64>, u64, &[f64], &str); 5] = [
        (None, 42, &nominal, "polytropic seed 42, nominal"),
        (Some(GAS_TAU_S), 42, &nominal, "gas seed 42, nominal"),
        (
            Some(GAS_TAU_S),
            42,
            &GAS_ROW_CALIBRATED,
            "gas seed 42, calibrated",
        ),
        (Some(GAS_TAU_S), 92, &nominal, "gas seed 92, nominal"),
        (
            Some(GAS_TAU_S),
            92,
            &GAS_ROW_CALIBRATED,
            "gas seed 92, calibrated",
        ),
    ];
    for (hidden, seed, baseline, label) in cases {
        let set = runs(RIDES, CHANGES, seed);
        let recs = records_hps(&set, hidden, seed);
        let mut totals = [0.0; 7];
        for (r, rec) in set.iter().zip(&recs) {
            let mean_sq = |act: &[afsv_discovery::ActiveEffect]| -> f64 {
                let errs =
                    evaluate_errors(&model, std::slice::from_ref(rec), baseline, act).unwrap();
                let v: Vec<f64> = errs.iter().filter_map(|c| c.nrmse).map(|x| x * x).collect();
                v.iter().sum::<f64>() / v.len() as f64
            };
            let none = mean_sq(&[]);
            totals[0] += none;
            let mut line = format!(
                "{label}: {:?} {} km/h {}: none {none:.4e}",
                r.ride.map(|(c, _)| c),
                r.speed_kmh,
                if r.loaded { "loaded" } else { "unloaded" },
            );
            for (k, tau) in [0.3, 0.5, 1.0, 2.0, 5.0, 20.0].into_iter().enumerate() {
                let v = [tau];
                let act = [afsv_discovery::ActiveEffect {
                    index: e,
                    values: &v,
                }];
                let x = mean_sq(&act);
                totals[k + 1] += x;
                line += &format!(" tau {tau}: {x:.4e}");
            }
            println!("{line}");
        }
        println!("{label}: sums none, tau 0.3 ... 20: {totals:?}");
    }
}

/// Prints each channel's standard deviation over the ride records and over the V3 record of
/// the gas row's held-out set (seed 92), and each channel's NRMSE over that set with the
/// whole set's scales and as the workflow weighs it (each experiment kind by its own spread,
/// `Vehicle3dModel::scaling_group`), at [`GAS_ROW_CALIBRATED`], without the gas effect and
/// with it at 0.86 s (the fit of that run) and the truth's 1 s, and the sample-weighted mean
/// square over the channels: the held-out gain the significance rule sees (`cargo test
/// --release --workspace --test discover_independent_vehicle3d_hps -- --ignored --nocapture
/// gas_gain_by_channel`, under a minute).
#[test]
#[ignore]
fn gas_gain_by_channel() {
    let model = Vehicle3dModel::nominal(FrontAxle::Suspended);
    let e = model
        .catalogue()
        .iter()
        .position(|c| c.name == "hps-gas-temperature")
        .unwrap();
    let set = runs(RIDES, CHANGES, 92);
    let recs = records_hps(&set, Some(GAS_TAU_S), 92);
    for ch in model.channels() {
        let spread = |ride: bool| {
            let v: Vec<f64> = set
                .iter()
                .zip(&recs)
                .filter(|(r, _)| r.ride.is_some() == ride)
                .filter_map(|(_, rec)| rec.column(&ch))
                .flatten()
                .copied()
                .collect();
            afsv_discovery::signature::std_dev(&v)
        };
        println!(
            "{ch}: standard deviation over the rides {:.4e}, over the V3 {:.4e}",
            spread(true),
            spread(false)
        );
    }
    let rides: Vec<Record> = set
        .iter()
        .zip(&recs)
        .filter(|(r, _)| r.ride.is_some())
        .map(|(_, rec)| rec.clone())
        .collect();
    let changes: Vec<Record> = set
        .iter()
        .zip(&recs)
        .filter(|(r, _)| r.ride.is_none())
        .map(|(_, rec)| rec.clone())
        .collect();
    // `evaluate_errors` scales by the spread of the records it is given: the whole set at
    // once is the whole set's scaling, each kind apart the workflow's.
    let weightings: [(&str, Vec<&[Record]>); 2] = [
        ("whole set's scales", vec![&recs[..]]),
        ("each kind's scales", vec![&rides[..], &changes[..]]),
    ];
    for (weighting, parts) in weightings {
        let mut base = None;
        for tau in [None, Some(0.86), Some(1.0)] {
            let v = [tau.unwrap_or(0.0)];
            let act = [afsv_discovery::ActiveEffect {
                index: e,
                values: &v,
            }];
            let act: &[afsv_discovery::ActiveEffect] = if tau.is_some() { &act } else { &[] };
            let (mut sq, mut n) = (0.0, 0usize);
            let mut line = format!("{weighting}, tau {tau:?}:");
            for part in &parts {
                let errs = evaluate_errors(&model, part, &GAS_ROW_CALIBRATED, act).unwrap();
                line += " |";
                for c in &errs {
                    if let Some(x) = c.nrmse {
                        sq += x * x * c.samples as f64;
                        n += c.samples;
                        line += &format!(" {} {:.2} %", c.channel, 100.0 * x);
                    }
                }
            }
            let ms = sq / n as f64;
            let b = *base.get_or_insert(ms);
            println!(
                "{line}\n  mean square {ms:.4e} (gain {:.1} %)",
                100.0 * (1.0 - ms / b)
            );
        }
    }
}
