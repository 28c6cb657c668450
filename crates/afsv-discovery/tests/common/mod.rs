//! Helpers shared by the discovery tests: running the workflow on synthesized records or on
//! record folders, and the record sets of the robustness cases (an effect outside the
//! catalogue). Each test crate uses a subset.
#![allow(dead_code)]

use afsv_discovery::hps::HpsStrutModel;
use afsv_discovery::synth::{hps_records, yaw_records, HpsNoise, SynthRecord, YawNoise};
use afsv_discovery::yaw::YawPlaneModel;
use afsv_discovery::{discover, Discovery, DiscoveryModel, DiscoveryOptions};
use afsv_records::Record;

/// Assert that exactly `effects` were named (in any order) and the held-out gap shrank by
/// at least `min_shrink`; on failure, show every candidate's score.
pub fn assert_named(d: &Discovery, effects: &[&str], min_shrink: f64) {
    let mut named = d.named.clone();
    named.sort();
    let mut want: Vec<String> = effects.iter().map(|e| e.to_string()).collect();
    want.sort();
    assert_eq!(named, want, "{}", summary(d));
    assert!(d.gap_shrink >= min_shrink, "{}", summary(d));
}

/// Assert the honest answer for a truth outside the catalogue: nothing named, or a shrink
/// that admits only part of the gap is explained.
pub fn assert_not_claimed(d: &Discovery) {
    assert!(
        d.named.is_empty() || d.gap_shrink < 0.7,
        "claims {:.2} of a gap it cannot explain: {}",
        d.gap_shrink,
        summary(d)
    );
}

/// Split synthesized records into (training, held-out) by their role.
pub fn split(recs: Vec<SynthRecord>) -> (Vec<Record>, Vec<Record>) {
    let (hold, train): (Vec<_>, Vec<_>) = recs.into_iter().partition(|r| r.holdout);
    (
        train.into_iter().map(|r| r.record).collect(),
        hold.into_iter().map(|r| r.record).collect(),
    )
}

/// The whole workflow with default options on synthesized records.
pub fn run_on<M: DiscoveryModel>(model: &M, recs: Vec<SynthRecord>) -> Discovery {
    let (train, hold) = split(recs);
    discover(
        model,
        &train,
        &hold,
        &[],
        &[],
        &DiscoveryOptions::default(),
        &(),
    )
    .unwrap()
}

/// Replace every column of each record by `f(name, values)`.
pub fn map_columns(recs: &mut [SynthRecord], mut f: impl FnMut(&str, &mut Vec<f64>)) {
    for r in recs {
        let mut rec = Record::new();
        for name in r.record.names().to_vec() {
            let mut v = r.record.column(&name).unwrap().to_vec();
            f(&name, &mut v);
            rec.push_column(&name, v).unwrap();
        }
        rec.meta = r.record.meta.clone();
        r.record = rec;
    }
}

/// One line per candidate and round: what a failing assertion should show.
pub fn summary(d: &Discovery) -> String {
    let mut s = format!("named {:?}, shrink {:.3}\n", d.named, d.gap_shrink);
    for st in &d.steps {
        for c in &st.candidates {
            s += &format!(
                "  {} gain {:?} bic_drop {:?} {:?}\n",
                c.effect,
                c.holdout_gain,
                c.bic_drop,
                c.outcome
                    .as_ref()
                    .map(|o| o.effect_params.clone())
                    .map_err(|e| e.clone())
            );
        }
    }
    s
}

/// Strut records sampled at `rate_hz` whose truth differs outside the catalogue: the load
/// cell lags by 8 ms (signal conditioning; rounded to whole samples, 8.3 ms at 120 and
/// 360 Hz), with default noise.
pub fn hps_outside_catalogue(seed: u64, rate_hz: f64) -> (HpsStrutModel, Vec<SynthRecord>) {
    let model = HpsStrutModel::nominal();
    let mut recs = hps_records(&model, &[], HpsNoise::default_levels(), seed, rate_hz).unwrap();
    let lag = (0.008 * rate_hz).round().max(1.0) as usize;
    map_columns(&mut recs, |name, v| {
        if name == "force_n" {
            let first = v[0];
            v.rotate_right(lag);
            v[..lag].fill(first);
        }
    });
    (model, recs)
}

/// Vehicle records whose truth differs outside the catalogue: the P_c pressure transducer
/// reads 0.3 MPa high (a zero offset after a temperature change). No effect of the
/// catalogue shifts one chamber's reading alone.
pub fn yaw_outside_catalogue(seed: u64) -> (YawPlaneModel, Vec<SynthRecord>) {
    let model = YawPlaneModel::nominal();
    let mut recs = yaw_records(&model, &[], YawNoise::default_levels(), seed).unwrap();
    map_columns(&mut recs, |name, v| {
        if name == "p_c_pa" {
            v.iter_mut().for_each(|p| *p += 3.0e5);
        }
    });
    (model, recs)
}

/// Keep every `k`-th sample of every column (a record sampled `k` times slower), with the
/// sidecar's `sample_rate_hz` divided by `k`.
pub fn decimate(rec: &Record, k: usize) -> Record {
    let mut out = Record::new();
    for name in rec.names() {
        let v = rec
            .column(name)
            .unwrap()
            .iter()
            .step_by(k)
            .copied()
            .collect();
        out.push_column(name, v).unwrap();
    }
    out.meta = rec.meta.clone();
    if let Some(rate) = rec.meta.get("sample_rate_hz").and_then(|r| r.as_f64()) {
        out.meta["sample_rate_hz"] = (rate / k as f64).into();
    }
    out
}

/// Records of `dir/train` and `dir/holdout` (as written by `afsv synth` or
/// `tests/independent`), read as the CLI reads them.
pub fn read_set(dir: &std::path::Path) -> (Vec<Record>, Vec<Record>, Vec<String>, Vec<String>) {
    let read = |sub: &str| {
        let mut files: Vec<_> = std::fs::read_dir(dir.join(sub))
            .unwrap()
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "csv"))
            .collect();
        files.sort();
        let names = files
            .iter()
            .map(|f| f.file_stem().unwrap().to_string_lossy().into_owned())
            .collect();
        (
            files.iter().map(|f| Record::read(f).unwrap()).collect(),
            names,
        )
    };
    let (train, tn) = read("train");
    let (hold, hn) = read("holdout");
    (train, hold, tn, hn)
}

/// The whole workflow with default options on the record set in `dir`.
pub fn run_dir<M: DiscoveryModel>(model: &M, dir: &std::path::Path) -> Discovery {
    run_dir_decimated(model, dir, 1)
}

/// [`run_dir`] on the records of `dir` with every `k`-th sample kept ([`decimate`]).
pub fn run_dir_decimated<M: DiscoveryModel>(
    model: &M,
    dir: &std::path::Path,
    k: usize,
) -> Discovery {
    run_dir_decimated_with(model, dir, k, &DiscoveryOptions::default())
}

/// [`run_dir_decimated`] with the options `opts`.
pub fn run_dir_decimated_with<M: DiscoveryModel>(
    model: &M,
    dir: &std::path::Path,
    k: usize,
    opts: &DiscoveryOptions,
) -> Discovery {
    let (train, hold, tn, hn) = read_set(dir);
    let every =
        |recs: Vec<Record>| -> Vec<Record> { recs.iter().map(|r| decimate(r, k)).collect() };
    let (train, hold) = (every(train), every(hold));
    discover(model, &train, &hold, &tn, &hn, opts, &()).unwrap()
}

/// A fresh scratch folder under the system temp dir, unique per test and process.
pub fn scratch(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("afsv-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Replay `rec` with the 3-D `model` at its nominal baseline and print each channel's NRMSE
/// after `label`. Panics on a sensor axis above 25 % or another channel above 10 %, and, when
/// `not_too_close`, on a record whose every cab axis replays within 1 % (records from an
/// independent implementation do not agree that well).
pub fn assert_replays_within(
    model: &afsv_discovery::vehicle3d::Vehicle3dModel,
    rec: &Record,
    label: &str,
    not_too_close: bool,
) {
    use afsv_discovery::vehicle3d::CHANNELS;
    let baseline: Vec<f64> = model.baseline_params().iter().map(|s| s.initial).collect();
    let errors =
        afsv_discovery::evaluate_errors(model, std::slice::from_ref(rec), &baseline, &[]).unwrap();
    let mut line = format!("{label}:");
    let mut bad = Vec::new();
    for (name, e) in CHANNELS.iter().zip(&errors) {
        let Some(x) = e.nrmse else { continue };
        line += &format!(" {name} {:.2} %", 100.0 * x);
        let sensor_axis = name.starts_with("cab_") || name.ends_with("accel_rad_s2");
        if x > if sensor_axis { 0.25 } else { 0.10 } {
            bad.push((name, x));
        }
    }
    println!("{line}");
    assert!(bad.is_empty(), "{bad:?}");
    if not_too_close {
        let sensor: Vec<f64> = CHANNELS
            .iter()
            .zip(&errors)
            .filter(|(n, _)| n.starts_with("cab_"))
            .filter_map(|(_, e)| e.nrmse)
            .collect();
        assert!(
            sensor.iter().any(|x| *x > 0.01),
            "the independent records replay too well to be independent: {sensor:?}"
        );
    }
}
