//! Helpers shared by the discovery tests: running the workflow on synthesized records, and
//! the record sets of the issue-6 robustness cases (another implementation of the same
//! physics, an effect outside the catalogue). Each test crate uses a subset.
#![allow(dead_code)]

use afsv::discover::hps::HpsStrutModel;
use afsv::discover::yaw::YawPlaneModel;
use afsv::discover::{discover, Discovery, DiscoveryModel, DiscoveryOptions};
use afsv::record::Record;
use afsv::synth::{
    hps_default_size, hps_records, parse_effects, yaw_default_size, yaw_records, Gaussian,
    HpsNoise, SynthRecord, YawNoise,
};
use afsv_dynamics::SolverKind;

/// Assert that exactly `effects` were named (in any order) and the held-out gap shrank by
/// at least `min_shrink`; on failure, show every candidate's score.
pub fn assert_named(d: &Discovery, effects: &[&str], min_shrink: f64) {
    let mut named = d.named.clone();
    named.sort();
    let mut want: Vec<String> = effects.iter().map(|e| e.to_string()).collect();
    want.sort();
    assert_eq!(named, want, "{}", summary(d));
    assert!(d.gap_shrink >= min_shrink, "{}", summary(d));
}

/// Assert the honest answer for a truth outside the catalogue: nothing named, or a shrink
/// that admits only part of the gap is explained.
pub fn assert_not_claimed(d: &Discovery) {
    assert!(
        d.named.is_empty() || d.gap_shrink < 0.7,
        "claims {:.2} of a gap it cannot explain: {}",
        d.gap_shrink,
        summary(d)
    );
}

/// Split synthesized records into (training, held-out) by their role.
pub fn split(recs: Vec<SynthRecord>) -> (Vec<Record>, Vec<Record>) {
    let (hold, train): (Vec<_>, Vec<_>) = recs.into_iter().partition(|r| r.holdout);
    (
        train.into_iter().map(|r| r.record).collect(),
        hold.into_iter().map(|r| r.record).collect(),
    )
}

/// The whole workflow with default options on synthesized records.
pub fn run_on<M: DiscoveryModel>(model: &M, recs: Vec<SynthRecord>) -> Discovery {
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

/// Replace every column of each record by `f(name, values)`.
pub fn map_columns(recs: &mut [SynthRecord], mut f: impl FnMut(&str, &mut Vec<f64>)) {
    for r in recs {
        let mut rec = Record::new();
        for name in r.record.names().to_vec() {
            let mut v = r.record.column(&name).unwrap().to_vec();
            f(&name, &mut v);
            rec.push_column(&name, v).unwrap();
        }
        rec.meta = r.record.meta.clone();
        r.record = rec;
    }
}

/// One line per candidate and round: what a failing assertion should show.
pub fn summary(d: &Discovery) -> String {
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

/// Strut records from a different implementation of the same physics: another integrator
/// and tolerance, nominal values a few percent off, noise band-limited instead of white.
/// Returns the default discovery baseline and the records.
pub fn hps_other_implementation(effects: &str, seed: u64) -> (HpsStrutModel, Vec<SynthRecord>) {
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
    map_columns(&mut recs, |name, v| match name {
        "force_n" => g.add_lowpass(v, 200.0, 50.0, 360.0),
        "p_piston_pa" | "p_rod_pa" => g.add_lowpass(v, 6e3, 50.0, 360.0),
        "displacement_m" => g.add_lowpass(v, 2e-5, 50.0, 360.0),
        _ => {}
    });
    (baseline, recs)
}

/// Strut records whose truth differs outside the catalogue: the load cell lags by 8 ms
/// (signal conditioning), with default noise.
pub fn hps_outside_catalogue(seed: u64) -> (HpsStrutModel, Vec<SynthRecord>) {
    let model = HpsStrutModel::new(HpsStrutModel::default_baseline());
    let mut recs = hps_records(&model, &[], HpsNoise::default_levels(), seed, 360.0).unwrap();
    map_columns(&mut recs, |name, v| {
        if name == "force_n" {
            let lag = 3;
            let first = v[0];
            v.rotate_right(lag);
            v[..lag].fill(first);
        }
    });
    (model, recs)
}

/// Vehicle records from a different implementation of the same physics: fixed-step RK4
/// instead of adaptive Dormand-Prince, nominal values a few percent off (including the
/// masses and inertias, which are not calibrated), and band-limited instead of white noise.
pub fn yaw_other_implementation(effects: &str, seed: u64) -> (YawPlaneModel, Vec<SynthRecord>) {
    let baseline = YawPlaneModel::new(YawPlaneModel::default_baseline());
    let mut p = YawPlaneModel::default_baseline();
    p.afs.bulk_modulus_pa *= 0.9;
    p.afs.dead_volume_m3 *= 1.1;
    p.afs.seal_viscous_n_s_m *= 1.2;
    p.afs.leak_const *= 1.3;
    p.vehicle.c_alpha_f_n_per_rad *= 0.95;
    p.vehicle.c_alpha_r_n_per_rad *= 0.95;
    p.vehicle.m_f_kg *= 1.02;
    p.vehicle.i_r_kg_m2 *= 0.98;
    let mut truth = YawPlaneModel::new(p);
    truth.sim.solver = SolverKind::Rk4;
    truth.sim.rk4_step_s = 2.5e-4;
    let hidden = parse_effects(effects, &truth.catalogue(), yaw_default_size).unwrap();
    let mut recs = yaw_records(&truth, &hidden, YawNoise::none(), seed).unwrap();
    let mut g = Gaussian::new(seed + 100);
    map_columns(&mut recs, |name, v| match name {
        "articulation_deg" => g.add_lowpass(v, 0.05, 30.0, 200.0),
        "strut_left_disp_m" => g.add_lowpass(v, 1e-4, 30.0, 200.0),
        "p_c_pa" | "p_r_pa" => g.add_lowpass(v, 2e4, 30.0, 200.0),
        "yaw_rate_front_deg_s" => g.add_lowpass(v, 0.2, 30.0, 200.0),
        "steer_wheel_deg" => g.add_lowpass(v, 0.02, 30.0, 200.0),
        _ => {}
    });
    (baseline, recs)
}

/// Vehicle records whose truth differs outside the catalogue: a 40 ms transport delay
/// between the steering wheel and the valve (a pilot line or a steer-by-wire bus), so the
/// recorded wheel angle leads what the valve saw. Nothing in the catalogue delays the input.
pub fn yaw_outside_catalogue(seed: u64) -> (YawPlaneModel, Vec<SynthRecord>) {
    let model = YawPlaneModel::new(YawPlaneModel::default_baseline());
    let mut recs = yaw_records(&model, &[], YawNoise::default_levels(), seed).unwrap();
    let lead = 8; // samples at 200 Hz
    map_columns(&mut recs, |name, v| {
        if name == "steer_wheel_deg" {
            let last = v[v.len() - 1];
            v.rotate_left(lead);
            let n = v.len();
            v[n - lead..].fill(last);
        }
    });
    (model, recs)
}
