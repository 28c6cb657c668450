//! Discovery on vehicle steering records synthesized with hidden effects (issue 6). The
//! full matrix (every catalogue effect) is `cargo xtask discover-matrix`; these run in CI.

mod common;
use afsv::discover::yaw::YawPlaneModel;
use afsv::discover::{Discovery, DiscoveryModel};
use afsv::synth::{parse_effects, yaw_default_size, yaw_records, YawNoise};
use common::{
    assert_named, assert_not_claimed, run_on, summary, yaw_other_implementation,
    yaw_outside_catalogue,
};

fn run(effects: &str, seed: u64) -> Discovery {
    let model = YawPlaneModel::new(YawPlaneModel::default_baseline());
    let hidden = parse_effects(effects, &model.catalogue(), yaw_default_size).unwrap();
    let recs = yaw_records(&model, &hidden, YawNoise::default_levels(), seed).unwrap();
    run_on(&model, recs)
}

#[test]
fn hidden_sensor_backlash_is_named_and_the_gap_shrinks() {
    let d = run("sensor-backlash", 1);
    assert_named(&d, &["sensor-backlash"], 0.7);
    let w = d.final_model.effect_params[0][0].1;
    assert!((w - 0.5).abs() < 0.1, "half width {w}");
}

#[test]
fn vehicle_without_hidden_effect_names_nothing() {
    let d = run("none", 21);
    assert!(d.named.is_empty(), "{}", summary(&d));
}

/// The calibrated baseline trades seal viscous friction for the hidden Coulomb friction;
/// without the attribution check a second, spurious effect was named on these records.
#[test]
fn hidden_coulomb_friction_is_named_alone() {
    let d = run("strut-coulomb-friction", 203);
    assert_named(&d, &["strut-coulomb-friction"], 0.7);
}

fn other_implementation(effects: &str, seed: u64) -> Discovery {
    let (model, recs) = yaw_other_implementation(effects, seed);
    run_on(&model, recs)
}

#[test]
fn other_implementation_still_names_the_hidden_effect() {
    let d = other_implementation("velocity-leakage", 41);
    assert_named(&d, &["velocity-leakage"], 0.7);
}

#[test]
fn other_implementation_without_effect_names_nothing() {
    let d = other_implementation("none", 42);
    assert!(d.named.is_empty(), "{}", summary(&d));
}

#[test]
fn an_effect_outside_the_catalogue_is_not_claimed_as_explained() {
    let (model, recs) = yaw_outside_catalogue(43);
    assert_not_claimed(&run_on(&model, recs));
}
