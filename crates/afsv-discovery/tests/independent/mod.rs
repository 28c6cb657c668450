//! A second, independent implementation of the yaw-plane AFS vehicle (Chapter 3) and the
//! hydro-pneumatic strut with gas-oil emulsion (Chapter 5), written from the dissertation's
//! equations in the test tree, plus record-set generators with hidden effects. It calls no
//! model code of the toolkit's crates, so records made here test the discovery workflow on
//! data the model code did not produce.
//!
//! Used by `tests/independent_yaw.rs` and `tests/independent_strut.rs` (each `mod independent;`),
//! which also hold the cross-checks against the crates' models.
#![allow(dead_code)]
// Index loops over the state vectors read like the equations (RK4 stages, 3x3 solve).
#![allow(clippy::needless_range_loop)]

pub mod realistic;
pub mod records;
pub mod rng;
pub mod strut;
pub mod vehicle3d;
pub mod yaw;

#[allow(unused_imports)]
pub use strut::{strut_record_set, strut_record_set_of, STRUT_EFFECTS};
#[allow(unused_imports)]
pub use yaw::{yaw_record_set, yaw_record_set_of, YAW_EFFECTS};

/// A realistic size for a hidden effect, clearly visible above the record noise:
/// backlash 0.3 deg, droop 9e8 Pa s/m^3, strut Coulomb friction 3 kN, entrained air 1 %,
/// valve lag 40 ms; gas heat-transfer tau 2 s, gas-fraction growth 0.1 s/m, friction
/// asymmetry 2 (compression factor; the extension factor is 0.5), check-valve lag 10 ms.
pub fn default_size(name: &str) -> f64 {
    match name {
        "sensor-backlash" => 0.3,
        "supply-droop" => 9.0e8,
        "strut-coulomb-friction" => 3.0e3,
        "entrained-air" => 0.01,
        "valve-lag" => 0.04,
        "gas-heat-transfer" => 2.0,
        "gas-fraction-growth" => 0.1,
        "asymmetric-friction" => 2.0,
        "check-valve-lag" => 0.01,
        other => panic!("unknown hidden effect `{other}`"),
    }
}

/// A fresh folder for a record set under cargo's per-test temporary directory.
pub fn scratch(name: &str) -> std::path::PathBuf {
    let d = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("independent-{name}"));
    let _ = std::fs::remove_dir_all(&d);
    d
}

/// Every file of a record set written by [`yaw_record_set`] or [`strut_record_set`] (train,
/// holdout, truth.json) with its bytes, in a fixed order, for determinism checks.
pub fn set_files(dir: &std::path::Path) -> Vec<(String, Vec<u8>)> {
    let mut v = Vec::new();
    for sub in ["train", "holdout"] {
        let mut names: Vec<_> = std::fs::read_dir(dir.join(sub))
            .unwrap()
            .map(|e| e.unwrap().file_name().into_string().unwrap())
            .collect();
        names.sort();
        for n in names {
            v.push((
                format!("{sub}/{n}"),
                std::fs::read(dir.join(sub).join(&n)).unwrap(),
            ));
        }
    }
    v.push((
        "truth.json".into(),
        std::fs::read(dir.join("truth.json")).unwrap(),
    ));
    v
}
