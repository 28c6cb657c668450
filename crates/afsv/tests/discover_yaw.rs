//! Discovery on vehicle steering records synthesized with hidden effects (issue 6). The
//! full matrix (every catalogue effect) is `cargo xtask discover-matrix`; these run in CI.

mod common;
use afsv::discover::yaw::YawPlaneModel;
use afsv::discover::{discover, Discovery, DiscoveryModel, DiscoveryOptions};
use afsv::synth::{parse_effects, yaw_default_size, yaw_records, YawNoise};
use common::summary;

fn run(effects: &str, seed: u64) -> Discovery {
    let model = YawPlaneModel::new(YawPlaneModel::default_baseline());
    let hidden = parse_effects(effects, &model.catalogue(), yaw_default_size).unwrap();
    let recs = yaw_records(&model, &hidden, YawNoise::default_levels(), seed).unwrap();
    let (hold, train): (Vec<_>, Vec<_>) = recs.into_iter().partition(|r| r.holdout);
    let train: Vec<_> = train.into_iter().map(|r| r.record).collect();
    let hold: Vec<_> = hold.into_iter().map(|r| r.record).collect();
    discover(
        &model,
        &train,
        &hold,
        &[],
        &[],
        &DiscoveryOptions::default(),
        &(),
    )
    .unwrap()
}

#[test]
fn hidden_sensor_backlash_is_named_and_the_gap_shrinks() {
    let d = run("sensor-backlash", 1);
    assert_eq!(
        d.named,
        vec!["sensor-backlash".to_string()],
        "{}",
        summary(&d)
    );
    assert!(d.gap_shrink >= 0.7, "{}", summary(&d));
    let w = d.final_model.effect_params[0][0].1;
    assert!((w - 0.5).abs() < 0.1, "half width {w}");
}

#[test]
fn vehicle_without_hidden_effect_names_nothing() {
    let d = run("none", 21);
    assert!(d.named.is_empty(), "{}", summary(&d));
}
