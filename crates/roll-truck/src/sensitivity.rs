//! Sensitivity of the sustained period ΔT and of the class A → E ratio ΔT(E) / ΔT(A) to the
//! two things chapter 2 does not state (issue 28): the steering ramp rate and the rule that
//! detects the sustained period of near-unity LTR.
//!
//! Every truck runs the ramp steer at each rate of [`RAMP_RATES_DEG_S`] on class A and
//! class E terrain (w = 2, 0.02-5 cycles/m, m_c = 0.3) over the same seeds, to absolute
//! rollover. Each record is then measured under each rule of [`DetectionRule::ALL`]: the
//! rule changes only the post-processing, so all rules see the same runs. The terrain is
//! [`SENSITIVITY_TERRAIN_M`] long for every rate (the synthesis depends on the length, so
//! the rates share their terrains; the 5 deg/s cells therefore differ from the 800 m
//! terrains of [`crate::studies`] by the seed scatter). Each run lasts until rollover or
//! [`ramp_duration_s`].

use perf_measures::roll::SustainedPeriodParams;
use serde::Serialize;
use terrain_psd::IsoClass;

use crate::driver::SteerDirection;
use crate::error::TruckError;
use crate::measures::roll_measures;
use crate::params::TruckParams;
use crate::simulate::RunOptions;
use crate::studies::{run_case_on, Stat, MAX_SEEDS};

/// Steering-wheel ramp rates of the sensitivity (deg/s): half, equal to and twice the
/// assumed 5 deg/s.
pub const RAMP_RATES_DEG_S: [f64; 3] = [2.5, 5.0, 10.0];

/// Length of the synthesized terrain of every sensitivity run (m): a run of
/// [`ramp_duration_s`] at the slowest rate (122 s at 40 km/h, 1356 m) with margins.
pub const SENSITIVITY_TERRAIN_M: f64 = 1600.0;

/// Steering-wheel angle (deg) the ramp reaches at the end of a run: 290 deg, so 5 deg/s
/// from t = 2 s ends at the default 60 s. Both built-in trucks roll over well before it.
pub const RAMP_SPAN_DEG: f64 = 290.0;

/// Duration (s) of a run of the truck `p` at its steering-wheel rate: the ramp start plus
/// [`RAMP_SPAN_DEG`] over the rate.
pub fn ramp_duration_s(p: &TruckParams) -> f64 {
    p.ramp_start_s + RAMP_SPAN_DEG / p.steering_wheel_rate_deg_s
}

/// A detection rule of the sustained period: the LTR threshold and the longest dip below it
/// that does not break the period (both unstated in chapter 2). The minimum duration (1 s)
/// and the excluded lift-off phase (LTR >= 0.999) are those of the default rule.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum DetectionRule {
    /// LTR >= 0.95, dips up to 0.5 s ([`SustainedPeriodParams::default`]).
    Default,
    /// LTR >= 0.98, dips up to 0.2 s.
    Strict,
    /// LTR >= 0.90, dips up to 1.0 s.
    Loose,
}

impl DetectionRule {
    /// The three rules.
    pub const ALL: [DetectionRule; 3] = [Self::Default, Self::Strict, Self::Loose];

    /// Its parameters.
    pub fn params(self) -> SustainedPeriodParams {
        let (threshold, max_dip_s) = match self {
            Self::Default => return SustainedPeriodParams::default(),
            Self::Strict => (0.98, 0.2),
            Self::Loose => (0.90, 1.0),
        };
        SustainedPeriodParams {
            threshold,
            max_dip_s,
            ..SustainedPeriodParams::default()
        }
    }

    /// Name as printed.
    pub fn name(self) -> &'static str {
        match self {
            Self::Default => "default",
            Self::Strict => "strict",
            Self::Loose => "loose",
        }
    }
}

/// One cell of the sensitivity: a truck, a ramp rate and a rule.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SensitivityCell {
    /// Truck name.
    pub truck: String,
    /// Steering-wheel ramp rate (deg/s).
    pub ramp_rate_deg_s: f64,
    /// Detection rule.
    pub rule: DetectionRule,
    /// Its LTR threshold.
    pub threshold: f64,
    /// Its longest tolerated dip (s).
    pub max_dip_s: f64,
    /// ΔT on class A (s) over the seeds that gave a period.
    pub class_a_s: Stat,
    /// ΔT on class E (s).
    pub class_e_s: Stat,
    /// SP-DRT on class E (g).
    pub sp_drt_e_g: Stat,
    /// ΔT(E) / ΔT(A) of the means (the chapter's × 6.4).
    pub ratio_e_over_a: f64,
}

/// The ΔT and SP-DRT of one run under each rule, in [`DetectionRule::ALL`] order.
type RuleMeasures = [(Option<f64>, Option<f64>); 3];

/// Run the sensitivity for `trucks` (name, parameters) over `seeds`, in parallel with
/// rayon; `progress(done, total)` after every run. Cells in truck, rate, rule order. A run
/// that fails counts as a seed without a period; if every run fails the first error is
/// returned.
pub fn run_sensitivity(
    trucks: &[(String, TruckParams)],
    seeds: &[u64],
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Vec<SensitivityCell>, TruckError> {
    use rayon::prelude::*;
    use std::sync::atomic::{AtomicUsize, Ordering};
    if seeds.is_empty() || seeds.len() > MAX_SEEDS {
        return Err(crate::error::rejected(
            "seeds",
            seeds.len() as f64,
            "a study needs 1 to 1000 terrain seeds",
        ));
    }
    let classes = [IsoClass::A, IsoClass::E];
    let mut jobs = Vec::new();
    for (t, (_, p)) in trucks.iter().enumerate() {
        p.validate()?;
        for rate in RAMP_RATES_DEG_S {
            for class in classes {
                jobs.extend(seeds.iter().map(|s| (t, rate, class, *s)));
            }
        }
    }
    let done = AtomicUsize::new(0);
    let total = jobs.len();
    let results: Vec<Result<RuleMeasures, TruckError>> = jobs
        .par_iter()
        .map(|&(t, rate, class, seed)| {
            let r = one_run(&trucks[t].1, rate, class, seed);
            progress(done.fetch_add(1, Ordering::Relaxed) + 1, total);
            r
        })
        .collect();
    if let Some(Err(e)) = results
        .first()
        .filter(|_| results.iter().all(|r| r.is_err()))
    {
        return Err(e.clone());
    }
    let mut cells = Vec::new();
    for (t, (name, _)) in trucks.iter().enumerate() {
        for rate in RAMP_RATES_DEG_S {
            let of = |class: IsoClass| -> Vec<&RuleMeasures> {
                jobs.iter()
                    .zip(&results)
                    .filter(|((jt, jr, jc, _), _)| *jt == t && *jr == rate && *jc == class)
                    .filter_map(|(_, r)| r.as_ref().ok())
                    .collect()
            };
            let (a, e) = (of(IsoClass::A), of(IsoClass::E));
            for (k, rule) in DetectionRule::ALL.into_iter().enumerate() {
                let class_a_s = Stat::of(a.iter().map(|m| m[k].0));
                let class_e_s = Stat::of(e.iter().map(|m| m[k].0));
                let sp = rule.params();
                cells.push(SensitivityCell {
                    truck: name.clone(),
                    ramp_rate_deg_s: rate,
                    rule,
                    threshold: sp.threshold,
                    max_dip_s: sp.max_dip_s,
                    ratio_e_over_a: class_e_s.mean / class_a_s.mean,
                    class_a_s,
                    class_e_s,
                    sp_drt_e_g: Stat::of(e.iter().map(|m| m[k].1)),
                });
            }
        }
    }
    Ok(cells)
}

/// One run of `p` at `rate` on `class` terrain, measured under every rule.
fn one_run(
    p: &TruckParams,
    rate: f64,
    class: IsoClass,
    seed: u64,
) -> Result<RuleMeasures, TruckError> {
    let p = TruckParams {
        steering_wheel_rate_deg_s: rate,
        ..*p
    };
    let spec = terrain_psd::TwoTrackSpec::new(
        terrain_psd::PowerLawPsd::new(class.alpha_r(), 2.0)?,
        terrain_psd::Band::new(0.02, 5.0)?,
        terrain_psd::CoherenceModel::piecewise(0.3)?,
    )?;
    let options = RunOptions {
        t_end_s: ramp_duration_s(&p),
        ..RunOptions::default()
    };
    let run = run_case_on(
        &p,
        Some(&spec),
        seed,
        SENSITIVITY_TERRAIN_M,
        SteerDirection::Left,
        &options,
        &SustainedPeriodParams::default(),
    )?;
    let mut out = [(None, None); 3];
    for (slot, rule) in out.iter_mut().zip(DetectionRule::ALL) {
        let m = roll_measures(&p, &run.record, &rule.params())?;
        *slot = (m.sustained_period_s, m.sp_drt_g);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rules_are_valid_and_ordered_by_strictness() {
        let [d, s, l] = DetectionRule::ALL.map(|r| r.params());
        for p in [d, s, l] {
            p.validate().unwrap();
        }
        assert_eq!(d, SustainedPeriodParams::default());
        assert!(s.threshold > d.threshold && d.threshold > l.threshold);
        assert!(s.max_dip_s < d.max_dip_s && d.max_dip_s < l.max_dip_s);
    }

    #[test]
    fn the_default_rate_runs_for_the_default_duration() {
        let p = TruckParams::nominal();
        assert_eq!(ramp_duration_s(&p), RunOptions::default().t_end_s);
        // the slowest run fits on the terrain
        let slow = TruckParams {
            steering_wheel_rate_deg_s: RAMP_RATES_DEG_S[0],
            ..p
        };
        let path = p.target_speed_m_s * ramp_duration_s(&slow) * 1.1 + 10.0;
        assert!(path + 20.0 < SENSITIVITY_TERRAIN_M, "{path}");
    }
}
