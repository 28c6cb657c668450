//! Record sets of the independent implementation in `tests/independent` for runs outside
//! the test suite: timing rows of `cargo xtask bench`, and folders for manual runs of
//! `afsv discover`. Both ignored in the suite.

mod common;
mod independent;

use afsv_discovery::hps::HpsStrutModel;
use afsv_discovery::yaw::YawPlaneModel;
use std::path::PathBuf;

/// Write every record set (vehicle 32 + 32 records of 20 s, strut bench programme), each
/// with one hidden effect or none: `AFSV_INDEPENDENT_DIR=/tmp/ind cargo test --release
/// -p afsv-discovery --test discover_independent -- --ignored write_sets`.
#[test]
#[ignore = "writes record folders for manual runs"]
fn write_sets() {
    let dir =
        PathBuf::from(std::env::var("AFSV_INDEPENDENT_DIR").expect("set AFSV_INDEPENDENT_DIR"));
    let yaw = std::iter::once(None).chain(independent::YAW_EFFECTS.iter().copied().map(Some));
    for (k, e) in yaw.enumerate() {
        let hidden = e.map(|e| (e, independent::default_size(e)));
        let sub = dir.join(format!("yaw-{}", e.unwrap_or("none")));
        independent::yaw_record_set(&sub, hidden, 32, 32, 20.0, 100 + k as u64);
    }
    let strut = std::iter::once(None).chain(independent::STRUT_EFFECTS.iter().copied().map(Some));
    for (k, e) in strut.enumerate() {
        let hidden = e.map(|e| (e, independent::default_size(e)));
        let sub = dir.join(format!("strut-{}", e.unwrap_or("none")));
        independent::strut_record_set(&sub, hidden, 200 + k as u64);
    }
}

/// Wall time of whole discovery runs on independent records: a vehicle set of 32 + 32
/// records (20 s at 100 Hz, both loads, 15-50 km/h) with a hidden valve lag, and the
/// 7-record strut bench programme (0.1-8 Hz) with hidden gas heat transfer. Printed as
/// `cargo xtask bench` rows; nothing is asserted about the time.
#[test]
#[ignore = "timing rows of `cargo xtask bench`"]
fn timing() {
    let dir = common::scratch("discover-timing");
    independent::yaw_record_set(&dir.join("yaw"), Some(("valve-lag", 0.04)), 32, 32, 20.0, 7);
    independent::strut_record_set(&dir.join("strut"), Some(("gas-heat-transfer", 2.0)), 8);
    let t = std::time::Instant::now();
    let d = common::run_dir(&YawPlaneModel::nominal(), &dir.join("yaw"));
    let yaw_s = t.elapsed().as_secs_f64();
    let t = std::time::Instant::now();
    let s = common::run_dir(&HpsStrutModel::nominal(), &dir.join("strut"));
    let strut_s = t.elapsed().as_secs_f64();
    println!(
        "bench-row discover_yaw_plane_64_records {yaw_s:.1} s (named {:?}, shrink {:.3})",
        d.named, d.gap_shrink
    );
    println!(
        "bench-row discover_hps_strut_7_records {strut_s:.1} s (named {:?}, shrink {:.3})",
        s.named, s.gap_shrink
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Write the realistic variant's record sets (`tests/independent/realistic.rs`: other
/// readings of what the paper leaves open), each with one hidden effect or none: the strut
/// bench programme and a vehicle set of N + N records of 20 s (N from
/// `AFSV_INDEPENDENT_RECORDS`, default 32): `AFSV_INDEPENDENT_DIR=/tmp/real cargo test
/// --release -p afsv-discovery --test discover_independent -- --ignored write_realistic_sets`.
#[test]
#[ignore = "writes record folders for manual runs"]
fn write_realistic_sets() {
    let dir =
        PathBuf::from(std::env::var("AFSV_INDEPENDENT_DIR").expect("set AFSV_INDEPENDENT_DIR"));
    let n: usize = std::env::var("AFSV_INDEPENDENT_RECORDS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(32);
    let strut = std::iter::once(None).chain(independent::STRUT_EFFECTS.iter().copied().map(Some));
    for (k, e) in strut.enumerate() {
        let hidden = e.map(|e| (e, independent::default_size(e)));
        let sub = dir.join(format!("strut-{}", e.unwrap_or("none")));
        let d = independent::realistic::strut();
        independent::strut_record_set_of(&sub, &d, hidden, 400 + k as u64);
    }
    let yaw = std::iter::once(None).chain(independent::YAW_EFFECTS.iter().copied().map(Some));
    for (k, e) in yaw.enumerate() {
        let hidden = e.map(|e| (e, independent::default_size(e)));
        let sub = dir.join(format!("yaw-{}", e.unwrap_or("none")));
        let v = independent::realistic::vehicle;
        independent::yaw_record_set_of(&sub, v, hidden, (n, n), 20.0, 300 + k as u64);
    }
}
