//! The full detection matrix of the discovery workflow: every catalogue effect of both
//! models hidden alone, with noise. Slow (minutes): run by `cargo xtask discover-matrix`
//! (`cargo test --release -p afsv --test discover_matrix -- --ignored --nocapture`).

use afsv::discover::hps::HpsStrutModel;
use afsv::discover::yaw::YawPlaneModel;
use afsv::discover::{discover, DiscoveryModel, DiscoveryOptions};
use afsv::synth::{self, HpsNoise, SynthRecord, YawNoise};

fn detect<M: DiscoveryModel>(model: &M, recs: Vec<SynthRecord>) -> (Vec<String>, f64) {
    let (hold, train): (Vec<_>, Vec<_>) = recs.into_iter().partition(|r| r.holdout);
    let train: Vec<_> = train.into_iter().map(|r| r.record).collect();
    let hold: Vec<_> = hold.into_iter().map(|r| r.record).collect();
    let d = discover(
        model,
        &train,
        &hold,
        &[],
        &[],
        &DiscoveryOptions::default(),
        &(),
    )
    .unwrap();
    (d.named, d.gap_shrink)
}

fn table(rows: &[(String, Vec<String>, f64, f64)]) -> bool {
    println!("\n| hidden | named | held-out gap shrink | time (s) | ok |\n|---|---|---|---|---|");
    let mut all = true;
    for (hidden, named, shrink, secs) in rows {
        let ok = if hidden == "none" {
            named.is_empty()
        } else {
            named == &vec![hidden.clone()] && *shrink >= 0.7
        };
        all &= ok;
        println!(
            "| {hidden} | {} | {:.1} % | {secs:.1} | {} |",
            if named.is_empty() {
                "-".to_string()
            } else {
                named.join(", ")
            },
            100.0 * shrink,
            if ok { "yes" } else { "NO" }
        );
    }
    all
}

#[test]
#[ignore = "slow: the full matrix, run by `cargo xtask discover-matrix`"]
fn strut_matrix() {
    let model = HpsStrutModel::new(HpsStrutModel::default_baseline());
    let mut rows = Vec::new();
    let mut names: Vec<String> = model.catalogue().iter().map(|e| e.name.clone()).collect();
    names.push("none".into());
    for (k, name) in names.iter().enumerate() {
        let t = std::time::Instant::now();
        let hidden =
            synth::parse_effects(name, &model.catalogue(), synth::hps_default_size).unwrap();
        let recs = synth::hps_records(
            &model,
            &hidden,
            HpsNoise::default_levels(),
            100 + k as u64,
            360.0,
        )
        .unwrap();
        let (named, shrink) = detect(&model, recs);
        rows.push((name.clone(), named, shrink, t.elapsed().as_secs_f64()));
    }
    assert!(table(&rows));
}

#[test]
#[ignore = "slow: the full matrix, run by `cargo xtask discover-matrix`"]
fn vehicle_matrix() {
    let model = YawPlaneModel::new(YawPlaneModel::default_baseline());
    let mut rows = Vec::new();
    let mut names: Vec<String> = model.catalogue().iter().map(|e| e.name.clone()).collect();
    names.push("none".into());
    for (k, name) in names.iter().enumerate() {
        let t = std::time::Instant::now();
        let hidden =
            synth::parse_effects(name, &model.catalogue(), synth::yaw_default_size).unwrap();
        let recs = synth::yaw_records(&model, &hidden, YawNoise::default_levels(), 200 + k as u64)
            .unwrap();
        let (named, shrink) = detect(&model, recs);
        rows.push((name.clone(), named, shrink, t.elapsed().as_secs_f64()));
    }
    assert!(table(&rows));
}
