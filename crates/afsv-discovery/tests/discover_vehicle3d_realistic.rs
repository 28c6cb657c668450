//! Discovery on records of the realistic 3-D variant (`tests/vehicle3d/realistic.rs`, issue
//! 24): the 3-D vehicle with other readings wherever Chapter 6 is silent, mostly in what the
//! adapter does not calibrate (tire curve and friction, slip stiffness, wheel-end mass,
//! sensor position, drive torque limit, enveloping step, the steering's unstated choices).
//! The criterion: on the null set nothing is named ("nothing missing" or "model-form
//! discrepancy"); on each effect set no wrong effect is named, and the hidden one is named
//! first or a model-form discrepancy is reported.
//!
//! | test | proves | cost |
//! |---|---|---|
//! | `the_realistic_variant_differs_from_the_model_by_a_few_percent` | a realistic ride record replayed by the adapter at the records' own values of the calibrated parameters leaves a few % NRMSE on the sensor axes (so the variant cannot silently become kind), and a record of the mild variant (`tests/vehicle3d::VARIANT`) on the same ground below 1 % | CI, about 1 s |
//! | `realistic_readings_one_at_a_time` (ignored) | prints each channel's NRMSE of each reading alone (on the mild variant), on the 3 + 1 runs of the null set, at the records' calibrated values | seconds |
//! | `realistic_channel_errors` (ignored) | prints each channel's NRMSE of the 3 + 1 null set at the nominal model and at the records' calibrated values | seconds |
//! | `tire_compliance_on_rides_by_reading` (ignored) | prints the lateral compliance that fits the tire set's ride records best at the records' calibrated values, for the mild variant, the realistic one and each reading alone | about a minute of CPU |
//! | `realistic_null_set_names_nothing`, `realistic_second_null_set_names_nothing`, `realistic_ride_null_set_names_nothing` (ignored) | three null sets (3 + 1 records, seeds 21 and 31; 5 ride records, seed 32): nothing named | `cargo test --release --workspace --test discover_vehicle3d_realistic -- --ignored --nocapture`, about 100 s of CPU each |
//! | `realistic_<effect>_is_named_first_or_a_discrepancy` (ignored) | each rigid-axle catalogue effect: no wrong name, the hidden one first or a discrepancy | same |
//! | `strut_readings_one_at_a_time` (ignored) | prints each channel's NRMSE of a ride and a V3 record of the HPS vehicle for each strut reading alone | seconds |
//! | `realistic_hps_gas_temperature_is_named_first_or_a_discrepancy` (ignored) | the front-axle HPS with every strut reading (records written at rtol 3e-7, `READINGS_HPS`), gas heat transfer at tau 1 s hidden: no wrong name, the gas temperature first or a discrepancy | about 30 min of CPU (the HPS replays run at 1e-7) |
//! | `strut_readings_gas_path_change_probe` (ignored) | prints whether the HPS gas set's V3 record can be written with each strut reading alone, all but one, and all (with all, the integrator stops: too many steps at 9.7 s) | about 150 s of CPU |

mod common;
mod vehicle3d;

use afsv_discovery::vehicle3d::{value, Vehicle3dModel, CHANNELS};
use afsv_discovery::Outcome;
use afsv_discovery::{evaluate_errors, Discovery, DiscoveryModel};
use afsv_records::Record;
use common::summary;
use vehicle3d::realistic::{
    hps_params, params, Readings, READINGS, READINGS_HPS, STRUT_READINGS, VEHICLE_READINGS,
};
use vehicle3d::{discover_printed, record_read, records_read, runs, Hidden, RunSpec};
use vehicle_3d::{FrontAxle, Load, VehicleParams};

/// Ride records and V3 path changes in each of the training and held-out sets (as the
/// other 3-D matrix).
const RIDES: usize = 3;
/// See [`RIDES`].
const CHANGES: usize = 1;

/// The adapter's calibrated parameters at their values in `p` (the records' truth).
fn truth_baseline(model: &Vehicle3dModel, p: &VehicleParams) -> Vec<f64> {
    model
        .baseline_params()
        .iter()
        .map(|s| value(p, &s.name).unwrap())
        .collect()
}

/// Each compared channel's NRMSE of `baseline` on `recs` (`None`: not compared).
fn channel_nrmse(model: &Vehicle3dModel, recs: &[Record], baseline: &[f64]) -> Vec<Option<f64>> {
    evaluate_errors(model, recs, baseline, &[])
        .unwrap()
        .iter()
        .map(|c| c.nrmse)
        .collect()
}

/// Root mean square of the compared channels' NRMSEs in the groups of [`CHANNELS`]: the
/// speed, the six sensor axes, the steering channels of the path change.
fn groups(e: &[Option<f64>]) -> [f64; 3] {
    let rms = |r: std::ops::Range<usize>| {
        let v: Vec<f64> = r.filter_map(|i| e[i]).collect();
        (v.iter().map(|x| x * x).sum::<f64>() / v.len().max(1) as f64).sqrt()
    };
    [rms(0..1), rms(7..13), rms(1..7)]
}

fn print_channels(what: &str, e: &[Option<f64>]) {
    let mut line = format!("{what}:");
    for (name, x) in CHANNELS.iter().zip(e) {
        if let Some(x) = x {
            line += &format!(" {name}={x:.4}");
        }
    }
    let [s, a, st] = groups(e);
    println!("{line}\n  groups: speed {s:.4}, sensor axes {a:.4}, steering {st:.4}");
}

#[test]
fn the_realistic_variant_differs_from_the_model_by_a_few_percent() {
    let model = Vehicle3dModel::nominal(FrontAxle::Rigid);
    let run = RunSpec {
        load: Load::Loaded,
        ride: Some((terrain_psd::IsoClass::E, 7)),
        speed_kmh: 20.0,
        duration_s: 3.0,
    };
    let rec = |p: &VehicleParams, readings: Readings| {
        record_read(FrontAxle::Rigid, p, readings, &run, Hidden::None, 0.0, 7)
    };
    let real = params();
    let realistic = [rec(&real, READINGS)];
    let e = channel_nrmse(&model, &realistic, &truth_baseline(&model, &real));
    print_channels("realistic at its calibrated values", &e);
    let [_, axes, _] = groups(&e);
    // measured 0.080 (2026-12-06): x 0.138, y 0.059, z 0.067, roll 0.034, pitch 0.053, yaw
    // 0.086 (the mild variant of `tests/vehicle3d::VARIANT` leaves 0.0003 on the null set's
    // runs, `realistic_channel_errors`)
    assert!(
        (0.02..0.15).contains(&axes),
        "the sensor axes differ by {axes:.4}, not a few %"
    );
    let mild = vehicle3d::variant();
    let kind = [rec(&mild, Readings::default())];
    let e = channel_nrmse(&model, &kind, &truth_baseline(&model, &mild));
    let [_, axes, _] = groups(&e);
    assert!(axes < 0.01, "the mild variant's record: {axes:.4}");
}

#[test]
#[ignore]
fn realistic_readings_one_at_a_time() {
    let model = Vehicle3dModel::nominal(FrontAxle::Rigid);
    for (k, run) in runs(RIDES, CHANGES, 21).iter().enumerate() {
        let rec = |p: &VehicleParams, readings: Readings| {
            [record_read(
                FrontAxle::Rigid,
                p,
                readings,
                run,
                Hidden::None,
                0.0,
                7,
            )]
        };
        let kind = vehicle3d::variant();
        let base = truth_baseline(&model, &kind);
        for (name, read) in VEHICLE_READINGS {
            let mut p = kind.clone();
            read(&mut p);
            print_channels(
                &format!("run {k}: {name}"),
                &channel_nrmse(&model, &rec(&p, Readings::default()), &base),
            );
        }
        print_channels(
            &format!("run {k}: enveloping step"),
            &channel_nrmse(&model, &rec(&kind, READINGS), &base),
        );
        print_channels(
            &format!("run {k}: all"),
            &channel_nrmse(&model, &rec(&params(), READINGS), &base),
        );
    }
}

#[test]
#[ignore]
fn realistic_channel_errors() {
    let model = Vehicle3dModel::nominal(FrontAxle::Rigid);
    let set = runs(RIDES, CHANGES, 21);
    let real = params();
    let recs: Vec<Record> = set
        .iter()
        .enumerate()
        .map(|(i, r)| {
            record_read(
                FrontAxle::Rigid,
                &real,
                READINGS,
                r,
                Hidden::None,
                0.0,
                i as u64,
            )
        })
        .collect();
    let nominal: Vec<f64> = model.baseline_params().iter().map(|s| s.initial).collect();
    print_channels("nominal model", &channel_nrmse(&model, &recs, &nominal));
    print_channels(
        "the records' calibrated values",
        &channel_nrmse(&model, &recs, &truth_baseline(&model, &real)),
    );
    let kind = vehicle3d::variant();
    let recs: Vec<Record> = set
        .iter()
        .enumerate()
        .map(|(i, r)| vehicle3d::record(FrontAxle::Rigid, &kind, r, Hidden::None, 0.0, i as u64))
        .collect();
    print_channels(
        "the mild variant at its calibrated values",
        &channel_nrmse(&model, &recs, &truth_baseline(&model, &kind)),
    );
}

/// The lateral compliance (mm/kN) of the grid 0.5..3.0 that fits `recs` best at the
/// records' calibrated values `base`, with the summed squared NRMSE at each grid point.
fn best_compliance(model: &Vehicle3dModel, recs: &[Record], base: &[f64]) -> (f64, Vec<f64>) {
    let e = model
        .catalogue()
        .iter()
        .position(|c| c.name == "tire-lateral-compliance")
        .unwrap();
    let grid: Vec<f64> = (1..=12).map(|i| 0.25 * i as f64).collect();
    let errs: Vec<f64> = grid
        .iter()
        .map(|c| {
            let v = [*c];
            let act = [afsv_discovery::ActiveEffect {
                index: e,
                values: &v,
            }];
            evaluate_errors(model, recs, base, &act)
                .unwrap()
                .iter()
                .filter_map(|c| c.nrmse)
                .map(|x| x * x)
                .sum()
        })
        .collect();
    let k = (0..grid.len())
        .min_by(|a, b| errs[*a].total_cmp(&errs[*b]))
        .unwrap();
    (grid[k], errs)
}

#[test]
#[ignore]
fn tire_compliance_on_rides_by_reading() {
    let model = Vehicle3dModel::nominal(FrontAxle::Rigid);
    let hidden = Hidden::TireCompliance(2.0);
    let rides: Vec<RunSpec> = runs(RIDES, CHANGES, 22).into_iter().take(RIDES).collect();
    let make = |p: &VehicleParams, readings: Readings| {
        records_read(FrontAxle::Rigid, p, readings, &rides, hidden, 22)
    };
    let mild = vehicle3d::variant();
    let base = truth_baseline(&model, &mild);
    let (c, _) = best_compliance(&model, &make(&mild, Readings::default()), &base);
    println!("mild variant: best compliance {c} (truth 2.0)");
    let (c, errs) = best_compliance(&model, &make(&params(), READINGS), &base);
    println!("realistic: best compliance {c}; errors {errs:.4?}");
    for (name, read) in VEHICLE_READINGS {
        let mut p = mild.clone();
        read(&mut p);
        let (c, _) = best_compliance(&model, &make(&p, Readings::default()), &base);
        println!("mild variant with only {name}: best compliance {c}");
    }
}

#[test]
#[ignore]
fn strut_readings_one_at_a_time() {
    let axle = FrontAxle::Suspended;
    let model = Vehicle3dModel::nominal(axle);
    let set = runs(RIDES, CHANGES, 26);
    for k in [1, 3] {
        let rec = |p: &VehicleParams| {
            [record_read(
                axle,
                p,
                READINGS,
                &set[k],
                Hidden::None,
                0.0,
                7,
            )]
        };
        let real = params();
        let base = truth_baseline(&model, &real);
        print_channels(
            &format!("run {k}: vehicle readings only"),
            &channel_nrmse(&model, &rec(&real), &base),
        );
        for (name, read) in STRUT_READINGS {
            let mut p = real.clone();
            read(&mut p);
            print_channels(
                &format!("run {k}: and {name}"),
                &channel_nrmse(&model, &rec(&p), &base),
            );
        }
        print_channels(
            &format!("run {k}: all"),
            &channel_nrmse(&model, &rec(&hps_params()), &base),
        );
    }
}

/// Whether the V3 record of the HPS gas set (seed 27, `hps-gas-temperature` at tau 1 s)
/// can be written with each strut reading alone, with all but one and with all of them (rtol
/// 1e-7).
#[test]
#[ignore]
fn strut_readings_gas_path_change_probe() {
    let axle = FrontAxle::Suspended;
    let run = runs(RIDES, CHANGES, 27)[3];
    let real = params();
    let mut cases: Vec<(String, VehicleParams)> = vec![("vehicle readings".into(), real.clone())];
    for (name, read) in STRUT_READINGS {
        let mut p = real.clone();
        read(&mut p);
        cases.push((name.to_string(), p));
    }
    for (k, (name, _)) in STRUT_READINGS.iter().enumerate() {
        let mut p = real.clone();
        for (_, (_, read)) in STRUT_READINGS.iter().enumerate().filter(|(j, _)| *j != k) {
            read(&mut p);
        }
        cases.push((format!("all but {name}"), p));
    }
    cases.push(("all".into(), hps_params()));
    for (name, p) in cases {
        let t0 = std::time::Instant::now();
        let ok = std::panic::catch_unwind(|| {
            record_read(axle, &p, READINGS, &run, Hidden::GasHeat(1.0), 0.0, 7)
        })
        .is_ok();
        println!("{name}: ok {ok} in {:.1} s", t0.elapsed().as_secs_f64());
    }
}

/// One discovery on a realistic training set of `seed` and a held-out set of `seed + 50`,
/// printed with the calibrated baseline's per-channel NRMSE on the held-out records.
fn run(hidden: Hidden, seed: u64) -> Discovery {
    run_sets(hidden, RIDES, CHANGES, seed)
}

/// [`run`] on `rides` ride records and `changes` V3 path changes per set.
fn run_sets(hidden: Hidden, rides: usize, changes: usize, seed: u64) -> Discovery {
    run_axle(
        FrontAxle::Rigid,
        &params(),
        READINGS,
        hidden,
        rides,
        changes,
        seed,
    )
}

/// [`run_sets`] on the front axle `axle` with the truth `p` written with `readings`.
fn run_axle(
    axle: FrontAxle,
    p: &VehicleParams,
    readings: Readings,
    hidden: Hidden,
    rides: usize,
    changes: usize,
    seed: u64,
) -> Discovery {
    let model = Vehicle3dModel::nominal(axle);
    let train = records_read(axle, p, readings, &runs(rides, changes, seed), hidden, seed);
    let hold_seed = seed + 50;
    let hold = records_read(
        axle,
        p,
        readings,
        &runs(rides, changes, hold_seed),
        hidden,
        hold_seed,
    );
    let (d, _) = discover_printed(&model, &train, &hold, hidden);
    println!(
        "truth of the calibrated set {:?}",
        truth_baseline(&model, p)
    );
    print_channels(
        "held-out records at the calibrated baseline",
        &channel_nrmse(&model, &hold, &d.calibrated.baseline),
    );
    d
}

/// The criterion on an effect set: no wrong effect named, and `effect` named first
/// or a model-form discrepancy reported.
fn right_first_or_discrepancy(d: &Discovery, effect: &str) {
    let wrong: Vec<&String> = d.named.iter().filter(|n| *n != effect).collect();
    assert!(wrong.is_empty(), "wrong names {wrong:?}: {}", summary(d));
    match d.named.first() {
        Some(first) => assert_eq!(first, effect, "{}", summary(d)),
        None => assert!(
            matches!(d.outcome, Outcome::ModelFormDiscrepancy { .. }),
            "{effect} is neither named nor a discrepancy reported: {}",
            summary(d)
        ),
    }
}

#[test]
#[ignore]
fn realistic_null_set_names_nothing() {
    let d = run(Hidden::None, 21);
    assert!(d.named.is_empty(), "{}", summary(&d));
    assert!(!matches!(d.outcome, Outcome::Named { .. }));
}

#[test]
#[ignore]
fn realistic_second_null_set_names_nothing() {
    let d = run(Hidden::None, 31);
    assert!(d.named.is_empty(), "{}", summary(&d));
    assert!(!matches!(d.outcome, Outcome::Named { .. }));
}

#[test]
#[ignore]
fn realistic_ride_null_set_names_nothing() {
    let d = run_sets(Hidden::None, 5, 0, 32);
    assert!(d.named.is_empty(), "{}", summary(&d));
    assert!(!matches!(d.outcome, Outcome::Named { .. }));
}

#[test]
#[ignore]
fn realistic_mount_compliance_is_named_first_or_a_discrepancy() {
    let d = run(Hidden::Mount(0.12, 0.15), 23);
    right_first_or_discrepancy(&d, "mount-compliance");
}

#[test]
#[ignore]
fn realistic_tire_lateral_compliance_is_named_first_or_a_discrepancy() {
    let d = run(Hidden::TireCompliance(2.0), 22);
    right_first_or_discrepancy(&d, "tire-lateral-compliance");
}

#[test]
#[ignore]
fn realistic_sensor_misalignment_is_named_first_or_a_discrepancy() {
    let d = run(Hidden::Misalignment([1.5, -2.0, 1.0]), 25);
    right_first_or_discrepancy(&d, "sensor-misalignment");
}

#[test]
#[ignore]
fn realistic_driver_throttle_is_named_first_or_a_discrepancy() {
    let d = run(
        Hidden::Throttle {
            amp: 0.6,
            period: 4.0,
        },
        24,
    );
    right_first_or_discrepancy(&d, "driver-throttle");
}

#[test]
#[ignore]
fn realistic_hps_gas_temperature_is_named_first_or_a_discrepancy() {
    let d = run_axle(
        FrontAxle::Suspended,
        &hps_params(),
        READINGS_HPS,
        Hidden::GasHeat(1.0),
        RIDES,
        CHANGES,
        27,
    );
    right_first_or_discrepancy(&d, "hps-gas-temperature");
}
