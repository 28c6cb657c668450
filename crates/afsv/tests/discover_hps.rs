//! Discovery on strut bench records synthesized with hidden effects (issue 6). The full
//! matrix (every catalogue effect) is `cargo xtask discover-matrix`; these run in CI.

mod common;
use afsv::discover::hps::HpsStrutModel;
use afsv::discover::{Discovery, DiscoveryModel};
use afsv::synth::{hps_default_size, hps_records, parse_effects, HpsNoise};
use common::{
    assert_named, assert_not_claimed, hps_other_implementation, hps_outside_catalogue, run_on,
    summary,
};

fn run(effects: &str, seed: u64) -> Discovery {
    let model = HpsStrutModel::new(HpsStrutModel::default_baseline());
    let hidden = parse_effects(effects, &model.catalogue(), hps_default_size).unwrap();
    let recs = hps_records(&model, &hidden, HpsNoise::default_levels(), seed, 360.0).unwrap();
    run_on(&model, recs)
}

#[test]
fn hidden_gas_heat_transfer_is_named_and_the_gap_shrinks() {
    let d = run("gas-heat-transfer", 1);
    assert_named(&d, &["gas-heat-transfer"], 0.7);
    let tau = d.final_model.effect_params[0][0].1;
    assert!((tau - 3.0).abs() < 0.5, "tau {tau}");
}

#[test]
fn strut_without_hidden_effect_names_nothing() {
    let d = run("none", 11);
    assert!(d.named.is_empty(), "{}", summary(&d));
}

#[test]
fn two_hidden_strut_effects_are_both_named() {
    let d = run("asymmetric-friction,check-valve-lag", 12);
    assert_named(&d, &["asymmetric-friction", "check-valve-lag"], 0.7);
}

fn other_implementation(effects: &str, seed: u64) -> Discovery {
    let (model, recs) = hps_other_implementation(effects, seed);
    run_on(&model, recs)
}

#[test]
fn other_implementation_still_names_the_hidden_effect() {
    let d = other_implementation("gas-heat-transfer", 21);
    assert_named(&d, &["gas-heat-transfer"], 0.0);
}

#[test]
fn other_implementation_without_effect_names_nothing() {
    let d = other_implementation("none", 22);
    assert!(d.named.is_empty(), "{}", summary(&d));
}

#[test]
fn an_effect_outside_the_catalogue_is_not_claimed_as_explained() {
    let (model, recs) = hps_outside_catalogue(31);
    assert_not_claimed(&run_on(&model, recs));
}
