//! The full detection matrix of the discovery workflow, for both models: every catalogue
//! effect hidden alone, with noise, in records from our own truth model and from a
//! different implementation of the same physics; pairs of hidden effects; no effect; and
//! an effect outside the catalogue. Slow (minutes): run by `cargo xtask discover-matrix`
//! (`cargo test --release -p afsv --test discover_matrix -- --ignored --nocapture`).

mod common;
use afsv::discover::hps::HpsStrutModel;
use afsv::discover::yaw::YawPlaneModel;
use afsv::discover::DiscoveryModel;
use afsv::synth::{self, hps_default_size, yaw_default_size, HpsNoise, SynthRecord, YawNoise};
use common::{
    hps_other_implementation, hps_outside_catalogue, run_on, yaw_other_implementation,
    yaw_outside_catalogue,
};

/// What a row expects: these effects named (in any order) with at least this held-out gap
/// shrink, or, for a truth outside the catalogue, nothing named or no large shrink claimed.
enum Expect {
    Named(Vec<String>, f64),
    OutsideCatalogue,
}

struct Row {
    case: String,
    expect: Expect,
    named: Vec<String>,
    shrink: f64,
    secs: f64,
}

impl Row {
    fn ok(&self) -> bool {
        match &self.expect {
            Expect::OutsideCatalogue => self.named.is_empty() || self.shrink < 0.7,
            Expect::Named(want, _) if want.is_empty() => self.named.is_empty(),
            Expect::Named(want, min_shrink) => {
                let mut a = want.clone();
                let mut b = self.named.clone();
                a.sort();
                b.sort();
                a == b && self.shrink >= *min_shrink
            }
        }
    }
}

fn row<M: DiscoveryModel>(
    case: &str,
    expect: Expect,
    build: impl Fn() -> (M, Vec<SynthRecord>),
) -> Row {
    let t = std::time::Instant::now();
    let (model, recs) = build();
    let d = run_on(&model, recs);
    Row {
        case: case.to_string(),
        expect,
        named: d.named,
        shrink: d.gap_shrink,
        secs: t.elapsed().as_secs_f64(),
    }
}

fn table(title: &str, rows: &[Row]) -> bool {
    println!("\n### {title}\n\n| records | named | held-out gap shrink | time (s) | ok |\n|---|---|---|---|---|");
    let mut all = true;
    for r in rows {
        let ok = r.ok();
        all &= ok;
        println!(
            "| {} | {} | {:.1} % | {:.1} | {} |",
            r.case,
            if r.named.is_empty() {
                "-".to_string()
            } else {
                r.named.join(", ")
            },
            100.0 * r.shrink,
            r.secs,
            if ok { "yes" } else { "NO" }
        );
    }
    all
}

/// Issue 6: with our own records every hidden effect is named and the held-out gap shrinks
/// by at least 70 %; with records from another implementation the hidden effect is named
/// (the shrink is printed but not held to 70 %: the noise floor is estimated assuming
/// sample-to-sample independent noise, and band-limited noise makes it read low, so the
/// shrink of those rows is understated).
fn expect_of(effects: &str, ours: bool) -> Expect {
    let min_shrink = if ours { 0.7 } else { 0.0 };
    if effects == "none" {
        Expect::Named(Vec::new(), min_shrink)
    } else {
        Expect::Named(effects.split(',').map(str::to_string).collect(), min_shrink)
    }
}

#[test]
#[ignore = "slow: the full matrix, run by `cargo xtask discover-matrix`"]
fn strut_matrix() {
    let model = HpsStrutModel::new(HpsStrutModel::default_baseline());
    let mut cases: Vec<String> = model.catalogue().iter().map(|e| e.name.clone()).collect();
    cases.push("none".into());
    cases.push("asymmetric-friction,check-valve-lag".into());
    cases.push("gas-fraction,check-valve-lag".into());
    let mut rows = Vec::new();
    for (k, case) in cases.iter().enumerate() {
        rows.push(row(&format!("ours: {case}"), expect_of(case, true), || {
            let hidden = synth::parse_effects(case, &model.catalogue(), hps_default_size).unwrap();
            let recs = synth::hps_records(
                &model,
                &hidden,
                HpsNoise::default_levels(),
                100 + k as u64,
                360.0,
            )
            .unwrap();
            (model.clone(), recs)
        }));
        rows.push(row(
            &format!("other implementation: {case}"),
            expect_of(case, false),
            || hps_other_implementation(case, 150 + k as u64),
        ));
    }
    rows.push(row(
        "outside catalogue: load-cell lag 8 ms",
        Expect::OutsideCatalogue,
        || hps_outside_catalogue(199),
    ));
    assert!(table("hps-strut", &rows));
}

#[test]
#[ignore = "slow: the full matrix, run by `cargo xtask discover-matrix`"]
fn vehicle_matrix() {
    let model = YawPlaneModel::new(YawPlaneModel::default_baseline());
    let mut cases: Vec<String> = model.catalogue().iter().map(|e| e.name.clone()).collect();
    cases.push("none".into());
    cases.push("sensor-backlash,velocity-leakage".into());
    cases.push("strut-coulomb-friction,tire-relaxation".into());
    let mut rows = Vec::new();
    for (k, case) in cases.iter().enumerate() {
        rows.push(row(&format!("ours: {case}"), expect_of(case, true), || {
            let hidden = synth::parse_effects(case, &model.catalogue(), yaw_default_size).unwrap();
            let recs =
                synth::yaw_records(&model, &hidden, YawNoise::default_levels(), 200 + k as u64)
                    .unwrap();
            (model.clone(), recs)
        }));
        rows.push(row(
            &format!("other implementation: {case}"),
            expect_of(case, false),
            || yaw_other_implementation(case, 250 + k as u64),
        ));
    }
    rows.push(row(
        "outside catalogue: 40 ms steering transport delay",
        Expect::OutsideCatalogue,
        || yaw_outside_catalogue(299),
    ));
    assert!(table("yaw-plane", &rows));
}
