//! Discovery on strut bench records: synthesized by the toolkit's own model with hidden
//! effects, and written by the independent implementation in `tests/independent`. The full
//! matrix is `cargo xtask discover-matrix`; these run in CI.

mod common;
mod independent;

use afsv_discovery::hps::HpsStrutModel;
use afsv_discovery::synth::{hps_default_size, hps_records, parse_effects, HpsNoise};
use afsv_discovery::{Discovery, DiscoveryModel};
use common::{
    assert_named, assert_not_claimed, hps_outside_catalogue, run_dir, run_on, scratch, summary,
};

fn run(effects: &str, seed: u64) -> Discovery {
    let model = HpsStrutModel::nominal();
    let hidden = parse_effects(effects, &model.catalogue(), hps_default_size).unwrap();
    let recs = hps_records(&model, &hidden, HpsNoise::default_levels(), seed, 360.0).unwrap();
    run_on(&model, recs)
}

/// Discovery on the independent implementation's 7-record bench programme.
fn independent(hidden: Option<&str>, seed: u64) -> Discovery {
    let dir = scratch(&format!("ind-strut-{}-{seed}", hidden.unwrap_or("none")));
    let h = hidden.map(|e| (e, independent::default_size(e)));
    independent::strut_record_set(&dir, h, seed);
    let d = run_dir(&HpsStrutModel::nominal(), &dir);
    std::fs::remove_dir_all(&dir).unwrap();
    d
}

#[test]
fn hidden_gas_heat_transfer_is_named_and_the_gap_shrinks() {
    let d = run("gas-heat-transfer", 1);
    assert_named(&d, &["gas-heat-transfer"], 0.7);
    let tau = d.final_model.effect_params[0][0].value;
    assert!((tau - 3.0).abs() < 0.5, "tau {tau}");
}

#[test]
fn two_hidden_strut_effects_are_both_named() {
    let d = run("asymmetric-friction,check-valve-lag", 12);
    assert_named(&d, &["asymmetric-friction", "check-valve-lag"], 0.7);
}

#[test]
fn independent_records_with_gas_heat_transfer_name_it_first() {
    let d = independent(Some("gas-heat-transfer"), 21);
    assert_eq!(
        d.named.first().map(String::as_str),
        Some("gas-heat-transfer"),
        "{}",
        summary(&d)
    );
    assert!(d.gap_shrink >= 0.7, "{}", summary(&d));
}

#[test]
fn independent_records_without_a_hidden_effect_name_nothing() {
    let d = independent(None, 22);
    assert!(d.named.is_empty(), "{}", summary(&d));
}

#[test]
fn an_effect_outside_the_catalogue_is_not_claimed_as_explained() {
    let (model, recs) = hps_outside_catalogue(31);
    assert_not_claimed(&run_on(&model, recs));
}
