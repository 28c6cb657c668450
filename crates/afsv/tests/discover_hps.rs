//! Discovery on strut bench records synthesized with hidden effects (issue 6). The full
//! matrix (every catalogue effect) is `cargo xtask discover-matrix`; these run in CI.

mod common;
use afsv::discover::hps::HpsStrutModel;
use afsv::discover::{discover, Discovery, DiscoveryModel, DiscoveryOptions};
use afsv::record::Record;
use afsv::synth::{hps_default_size, hps_records, parse_effects, Gaussian, HpsNoise, SynthRecord};
use common::summary;

fn split(recs: Vec<SynthRecord>) -> (Vec<Record>, Vec<Record>) {
    let (hold, train): (Vec<_>, Vec<_>) = recs.into_iter().partition(|r| r.holdout);
    (
        train.into_iter().map(|r| r.record).collect(),
        hold.into_iter().map(|r| r.record).collect(),
    )
}

fn run_on(model: &HpsStrutModel, recs: Vec<SynthRecord>) -> Discovery {
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

fn run(effects: &str, seed: u64) -> Discovery {
    let model = HpsStrutModel::new(HpsStrutModel::default_baseline());
    let hidden = parse_effects(effects, &model.catalogue(), hps_default_size).unwrap();
    let recs = hps_records(&model, &hidden, HpsNoise::default_levels(), seed, 360.0).unwrap();
    run_on(&model, recs)
}

#[test]
fn hidden_gas_heat_transfer_is_named_and_the_gap_shrinks() {
    let d = run("gas-heat-transfer", 1);
    assert_eq!(
        d.named,
        vec!["gas-heat-transfer".to_string()],
        "{}",
        summary(&d)
    );
    assert!(d.gap_shrink >= 0.7, "{}", summary(&d));
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
    let mut named = d.named.clone();
    named.sort();
    assert_eq!(
        named,
        vec![
            "asymmetric-friction".to_string(),
            "check-valve-lag".to_string()
        ],
        "{}",
        summary(&d)
    );
    assert!(d.gap_shrink >= 0.7, "{}", summary(&d));
}

/// Records from a different implementation of the same physics: another integrator and
/// tolerance, nominal values a few percent off, noise band-limited instead of white.
fn other_implementation(effects: &str, seed: u64) -> Discovery {
    let baseline = HpsStrutModel::new(HpsStrutModel::default_baseline());
    let mut truth_params = HpsStrutModel::default_baseline();
    truth_params.p_h0 *= 1.03;
    truth_params.v_g0 *= 0.95;
    truth_params.friction.f_c *= 1.2;
    truth_params.friction.mu_v *= 0.8;
    truth_params.c_b *= 0.95;
    let mut truth = HpsStrutModel::new(truth_params);
    truth.sim.solver = hps_emulsion::Solver::Rosenbrock23;
    truth.sim.rtol = 1e-7;
    let hidden = parse_effects(effects, &truth.catalogue(), hps_default_size).unwrap();
    let mut recs = hps_records(&truth, &hidden, HpsNoise::none(), seed, 360.0).unwrap();
    let mut g = Gaussian::new(seed + 100);
    for r in &mut recs {
        let mut rec = Record::new();
        for name in r.record.names().to_vec() {
            let mut v = r.record.column(&name).unwrap().to_vec();
            match name.as_str() {
                "force_n" => g.add_lowpass(&mut v, 200.0, 50.0, 360.0),
                "p_piston_pa" | "p_rod_pa" => g.add_lowpass(&mut v, 6e3, 50.0, 360.0),
                "displacement_m" => g.add_lowpass(&mut v, 2e-5, 50.0, 360.0),
                _ => {}
            }
            rec.push_column(&name, v).unwrap();
        }
        r.record = rec;
    }
    run_on(&baseline, recs)
}

#[test]
fn other_implementation_still_names_the_hidden_effect() {
    let d = other_implementation("gas-heat-transfer", 21);
    assert_eq!(
        d.named,
        vec!["gas-heat-transfer".to_string()],
        "{}",
        summary(&d)
    );
}

#[test]
fn other_implementation_without_effect_names_nothing() {
    let d = other_implementation("none", 22);
    assert!(d.named.is_empty(), "{}", summary(&d));
}

#[test]
fn an_effect_outside_the_catalogue_is_not_claimed_as_explained() {
    // The load cell lags by 8 ms (signal conditioning): nothing in the catalogue models it.
    let model = HpsStrutModel::new(HpsStrutModel::default_baseline());
    let mut recs = hps_records(&model, &[], HpsNoise::default_levels(), 31, 360.0).unwrap();
    for r in &mut recs {
        let mut rec = Record::new();
        for name in r.record.names().to_vec() {
            let mut v = r.record.column(&name).unwrap().to_vec();
            if name == "force_n" {
                let lag = 3;
                let first = v[0];
                v.rotate_right(lag);
                v[..lag].fill(first);
            }
            rec.push_column(&name, v).unwrap();
        }
        r.record = rec;
    }
    let d = run_on(&model, recs);
    assert!(
        d.named.is_empty() || d.gap_shrink < 0.7,
        "claims {:.2} of a gap it cannot explain: {}",
        d.gap_shrink,
        summary(&d)
    );
}
