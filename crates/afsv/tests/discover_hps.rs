//! Discovery on strut bench records synthesized with hidden effects (issue 6 tests).

use afsv::discover::hps::HpsStrutModel;
use afsv::discover::{discover, DiscoveryModel, DiscoveryOptions};
use afsv::synth::{hps_default_size, hps_records, parse_effects, HpsNoise};

fn run(effects: &str, seed: u64) -> afsv::discover::Discovery {
    let model = HpsStrutModel::new(HpsStrutModel::default_baseline());
    let hidden = parse_effects(effects, &model.catalogue(), hps_default_size).unwrap();
    let recs = hps_records(&model, &hidden, HpsNoise::default_levels(), seed, 360.0).unwrap();
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

fn summary(d: &afsv::discover::Discovery) -> String {
    let mut s = format!("named {:?}, shrink {:.3}\n", d.named, d.gap_shrink);
    for st in &d.steps {
        for c in &st.candidates {
            s += &format!(
                "  {} gain {:.4} bic_drop {:.1} {:?}\n",
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

#[test]
fn strut_effects_are_named_one_at_a_time() {
    let mut results = Vec::new();
    for (effect, seed) in [
        ("gas-heat-transfer", 1),
        ("gas-fraction", 2),
        ("asymmetric-friction", 3),
        ("check-valve-lag", 4),
    ] {
        let d = run(effect, seed);
        eprintln!("{effect}: {}", summary(&d));
        results.push((effect, d));
    }
    for (effect, d) in &results {
        assert_eq!(d.named, vec![effect.to_string()], "{}", summary(d));
        assert!(d.gap_shrink >= 0.7, "{effect}: {}", summary(d));
    }
}

#[test]
fn strut_without_hidden_effect_names_nothing() {
    let d = run("none", 11);
    assert!(d.named.is_empty(), "{}", summary(&d));
}
