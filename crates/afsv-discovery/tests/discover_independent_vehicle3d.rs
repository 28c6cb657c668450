//! Discovery on records of the independent 3-D vehicle (`tests/independent/vehicle3d`,
//! issue 24): Chapter 6 written apart from the crates, with its own readings where the
//! paper is silent. The criterion of the issue: on the null set nothing is named; on each
//! set with one hidden catalogue effect, that effect is named first and no other.
//!
//! | test | proves | cost |
//! |---|---|---|
//! | `the_adapter_replays_independent_records_within_a_few_percent` | the adapter reads the independent records (sidecar, ground, steering) and replays a noise-free class C ride and a V3 record at its nominal parameters (the records' own values of the calibrated parameters) within 25 % NRMSE on each sensor axis and 10 % on the speed and the steering channels (measured: ride axes 5.0-12.1 %, speed 4.2 %; V3 steering channels 0.02-0.6 %, its flat-ground pitch and vertical accelerations 11.6 % and 7.7 %), and not within 1 % on every ride axis (the records are not the crate's) | CI, about 1 s |
//! | `independent_null_set_names_nothing`, `independent_second_null_set_names_nothing` (ignored) | 3 ride + 1 V3 records for training and as many held out, no hidden effect (seeds 21 and 31): nothing named | `cargo test --release --workspace --test discover_independent_vehicle3d -- --ignored --nocapture NAME` |
//! | `independent_<effect>_is_named_first` (ignored) | one hidden effect each (mount 0.12 s / zeta 0.15, misalignment 1.5 / -2.0 / 1.0 deg, throttle +-0.6 m/s over 4 s, tire lateral compliance 2.0 mm/kN): that effect named first, no other | same |
// `vehicle3d` (for its `discover_printed`) and `independent` both load the test tree's noise
// source `independent/rng.rs` as a module of their own.
#![allow(clippy::duplicate_mod)]

mod common;
mod independent;
mod vehicle3d;

use afsv_discovery::vehicle3d::{Vehicle3dModel, CHANNELS};
use afsv_discovery::{evaluate_errors, Discovery, DiscoveryModel, Outcome};
use common::{assert_replays_within, summary};
use independent::vehicle3d::{record, records, runs, Hidden3d};
use vehicle3d::{discover_printed, Hidden};
use vehicle_3d::FrontAxle;

/// Ride records and V3 path changes in each of the training and held-out sets (as the
/// crate-made 3-D matrix).
const RIDES: usize = 3;
/// See [`RIDES`].
const CHANGES: usize = 1;

/// The label `discover_printed` prints: the same effect in the crate-made records' terms.
fn label(h: Hidden3d) -> Hidden {
    match h {
        Hidden3d::None => Hidden::None,
        Hidden3d::TireCompliance(c) => Hidden::TireCompliance(c),
        Hidden3d::Mount(t, z) => Hidden::Mount(t, z),
        Hidden3d::Throttle(amp, period) => Hidden::Throttle { amp, period },
        Hidden3d::Misalignment(a) => Hidden::Misalignment(a),
    }
}

fn run(hidden: Hidden3d, seed: u64) -> Discovery {
    let model = Vehicle3dModel::nominal(FrontAxle::Rigid);
    let t0 = std::time::Instant::now();
    let train = records(&runs(RIDES, CHANGES, seed), hidden, seed);
    let hold = records(&runs(RIDES, CHANGES, seed + 50), hidden, seed + 50);
    println!("records written in {:.1} s", t0.elapsed().as_secs_f64());
    let d = discover_printed(&model, &train, &hold, label(hidden)).0;
    for r in &d.readings {
        println!("switch {}: {} ({:?})", r.switch, r.chosen, r.tried);
    }
    d
}

fn named_first_and_alone(d: &Discovery, effect: &str) {
    assert_eq!(
        d.named.first().map(String::as_str),
        Some(effect),
        "{}",
        summary(d)
    );
    assert!(
        d.named.iter().all(|n| n == effect),
        "a wrong effect named too: {:?}\n{}",
        d.named,
        summary(d)
    );
}

#[test]
fn the_adapter_replays_independent_records_within_a_few_percent() {
    let model = Vehicle3dModel::nominal(FrontAxle::Rigid);
    let set = runs(1, 1, 3);
    let recs: Vec<_> = set
        .iter()
        .enumerate()
        .map(|(i, r)| record(r, Hidden3d::None, 0.0, 300 + i as u64))
        .collect();
    for (r, rec) in set.iter().zip(&recs) {
        assert_replays_within(&model, rec, &format!("{:?}", r.ride.map(|(c, _)| c)), true);
    }
}

#[test]
#[ignore]
fn independent_null_set_names_nothing() {
    let d = run(Hidden3d::None, 21);
    assert!(d.named.is_empty(), "{}", summary(&d));
    assert!(!matches!(d.outcome, Outcome::Named { .. }));
}

#[test]
#[ignore]
fn independent_second_null_set_names_nothing() {
    let d = run(Hidden3d::None, 31);
    assert!(d.named.is_empty(), "{}", summary(&d));
    assert!(!matches!(d.outcome, Outcome::Named { .. }));
}

#[test]
#[ignore]
fn independent_mount_compliance_is_named_first() {
    let d = run(Hidden3d::Mount(0.12, 0.15), 22);
    named_first_and_alone(&d, "mount-compliance");
}

#[test]
#[ignore]
fn independent_sensor_misalignment_is_named_first() {
    let d = run(Hidden3d::Misalignment([1.5, -2.0, 1.0]), 23);
    named_first_and_alone(&d, "sensor-misalignment");
}

#[test]
#[ignore]
fn independent_driver_throttle_is_named_first() {
    let d = run(Hidden3d::Throttle(0.6, 4.0), 24);
    named_first_and_alone(&d, "driver-throttle");
}

#[test]
#[ignore]
fn independent_tire_lateral_compliance_is_named_first() {
    let d = run(Hidden3d::TireCompliance(2.0), 25);
    named_first_and_alone(&d, "tire-lateral-compliance");
}

/// Prints each compared channel's NRMSE on the null set's training and held-out records
/// (3 % noise included) at the adapter's nominal parameters, which are the records' own
/// values of the calibrated set, and under each reading of `cam-spacing`: where the
/// model-form difference sits
/// (`cargo test --release --workspace --test discover_independent_vehicle3d -- --ignored
/// --nocapture independent_null_set_channel_errors`, seconds).
#[test]
#[ignore]
fn independent_null_set_channel_errors() {
    let model = Vehicle3dModel::nominal(FrontAxle::Rigid);
    let baseline: Vec<f64> = model.baseline_params().iter().map(|s| s.initial).collect();
    for seed in [21, 71] {
        let set = runs(RIDES, CHANGES, seed);
        let recs = records(&set, Hidden3d::None, seed);
        for (r, rec) in set.iter().zip(&recs) {
            let errors =
                evaluate_errors(&model, std::slice::from_ref(rec), &baseline, &[]).unwrap();
            let mut line = format!(
                "seed {seed}, {:?} {} km/h {}:",
                r.ride.map(|(c, _)| c),
                r.speed_kmh,
                if r.loaded { "loaded" } else { "unloaded" }
            );
            for (name, e) in CHANNELS.iter().zip(&errors) {
                if let Some(x) = e.nrmse {
                    line += &format!(" {name} {:.1} %", 100.0 * x);
                }
            }
            println!("{line}");
            // both readings of `cam-spacing`, the same normalisation (the record's own
            // standard deviation, the skipped start left out)
            let prep = model.prepare(rec).unwrap();
            let skip = model.skip_samples(rec);
            for (k, reading) in ["static", "instantaneous"].iter().enumerate() {
                let ch = model
                    .simulate_with_readings(&prep, &baseline, &[], &[k])
                    .unwrap();
                let mut line = format!("  cams {reading}:");
                for (name, y) in CHANNELS.iter().zip(&ch) {
                    let (Some(y), Some(x)) = (y, rec.column(name)) else {
                        continue;
                    };
                    line += &format!(" {name} {:.1} %", 100.0 * nrmse(&y[skip..], &x[skip..]));
                }
                println!("{line}");
            }
        }
    }
}

/// RMS of `y - x` over the standard deviation of `x`.
fn nrmse(y: &[f64], x: &[f64]) -> f64 {
    let n = x.len().min(y.len()) as f64;
    let mean = x.iter().sum::<f64>() / n;
    let sd = (x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n).sqrt();
    let rms = (y.iter().zip(x).map(|(a, b)| (a - b).powi(2)).sum::<f64>() / n).sqrt();
    rms / sd
}
