//! The Eq 6.19 GA on its smallest budget: the nominal design seeds the population, so with
//! elitism the optimum is never worse than F = 2; the same run ask/tell (its batches and
//! results through their JSON lines, in two shards) reaches the same optimum, bit for bit
//! (determinism and resumption of the GA itself: `optimize`'s tests).

use afsv_design::hps_ask_tell::{
    batch_file, batch_points, evaluate_hps_shard, HpsPhase, HpsPointResult, HpsValues,
};
use afsv_design::{
    optimise_hps, HpsAsk, HpsAskTell, HpsGaSettings, HpsOptimum, HpsProblemDesc, HpsRunState,
};
use std::collections::HashMap;
use vehicle_3d::VehicleParams;

#[test]
fn ga_improves_on_the_nominal_design_and_ask_tell_reaches_the_same_optimum() {
    let p = VehicleParams::nominal();
    let settings = HpsGaSettings {
        population: 4,
        generations: 1,
        reevaluation_seeds: 1,
        reevaluate_roll: false,
        ..HpsGaSettings::default()
    };
    let a = optimise_hps(&p, &settings, &optimize::Silent).unwrap();
    // F of the nominal design is 2 by definition (Eq 6.19 normalises by it)
    assert!(a.objective <= 2.0 + 1e-12, "{}", a.objective);
    assert!(a.feasible);
    assert_eq!(a.evaluations, 4 * 2 + 2);
    for (x, (lo, hi)) in [a.design.a_hc, a.design.a_v, a.design.a_b]
        .into_iter()
        .zip(settings.lower.into_iter().zip(settings.upper))
    {
        assert!((lo..=hi).contains(&x), "{x} outside [{lo}, {hi}]");
    }
    let f = a.optimum_ride.a_wz_m_s2 / a.nominal_ride.a_wz_m_s2
        + a.optimum_ride.d_s_m / a.nominal_ride.d_s_m;
    assert!((f - a.objective).abs() < 1e-12);
    assert!(a.optimum_over_seeds.omega_z_hz > 1.0);
    assert!(a.optimum_over_seeds.sp_drt_m_s2.mean.is_nan());

    let (ours, phases) = ask_tell(&p, &settings);
    assert_eq!(
        phases,
        [
            HpsPhase::Initial,
            HpsPhase::Generation(1),
            HpsPhase::Reevaluation
        ]
    );
    assert_eq!(ours.objective.to_bits(), a.objective.to_bits());
    assert_eq!(ours.design, a.design);
    // every number, bit for bit (the JSON numbers round-trip exactly; NaN is null)
    assert_eq!(
        serde_json::to_string(&ours).unwrap(),
        serde_json::to_string(&a).unwrap()
    );
}

/// The run of `settings` ask/tell, every batch and result through its JSON line, in two
/// shards; the result and the phases asked.
fn ask_tell(p: &VehicleParams, settings: &HpsGaSettings) -> (HpsOptimum, Vec<HpsPhase>) {
    let desc = HpsProblemDesc {
        vehicle: "nominal".into(),
        params: p.clone(),
        settings: settings.clone(),
    };
    let driver = HpsAskTell::new(&desc).unwrap();
    let mut run = HpsRunState::default();
    let mut phases = Vec::new();
    let mut number = 0;
    let sha = "0".repeat(64);
    loop {
        let asked = driver.ask(&run).unwrap();
        let HpsAsk::Evaluate(b) = &asked else {
            break;
        };
        phases.push(b.phase);
        let (header, points) = batch_file(&desc, number, &sha, &asked);
        assert_eq!(points, batch_points(number, b));
        assert!(!header.finished && header.points == points.len() && header.batch == number);
        let header = through(&header);
        let points: Vec<_> = points.iter().map(through).collect();
        let mut by_id: HashMap<String, HpsPointResult> = HashMap::new();
        for i in 1..=2 {
            for r in evaluate_hps_shard(&header, &points, (i, 2), &|| {}) {
                by_id.insert(r.id.clone(), through(&r));
            }
        }
        let told: Vec<Result<HpsValues, String>> =
            points.iter().map(|p| by_id[&p.id].outcome()).collect();
        let before = run.clone();
        assert!(driver
            .tell(&mut run, told[..told.len() - 1].to_vec())
            .is_err());
        assert_eq!(run, before, "a refused tell leaves the state");
        // the state goes through its file too
        driver.tell(&mut run, told).unwrap();
        run = through(&run);
        number += 1;
    }
    let (done, none) = batch_file(&desc, number, &sha, &HpsAsk::Finished);
    assert!(done.finished && done.points == 0 && none.is_empty() && done.phase.is_empty());
    (driver.finish(&run).unwrap(), phases)
}

/// `v` written as a file line and read back.
fn through<T: serde::Serialize + serde::de::DeserializeOwned>(v: &T) -> T {
    serde_json::from_str(&serde_json::to_string(v).unwrap()).unwrap()
}
