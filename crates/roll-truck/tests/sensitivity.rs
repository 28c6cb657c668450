//! The sensitivity of ΔT to the ramp rate and the detection rule on one seed of the
//! calibrated truck (six runs): a slower ramp holds the LTR near unity longer, the default
//! rule at the default rate is the plain measure of the same run, and a stricter rule finds
//! no longer period than the default one.

use roll_truck::sensitivity::{run_sensitivity, DetectionRule, SENSITIVITY_TERRAIN_M};
use roll_truck::studies::run_case_on;
use roll_truck::{RunOptions, SteerDirection, TruckParams};
use terrain_psd::{Band, CoherenceModel, IsoClass, PowerLawPsd, TwoTrackSpec};

#[test]
fn slower_ramps_and_looser_rules_give_longer_periods() {
    let p = TruckParams::nominal();
    let cells = run_sensitivity(&[("calibrated".into(), p)], &[1], &|_, _| {}).unwrap();
    assert_eq!(cells.len(), 9);
    let cell = |rate: f64, rule: DetectionRule| {
        cells
            .iter()
            .find(|c| c.ramp_rate_deg_s == rate && c.rule == rule)
            .unwrap()
    };
    let (slow, fast) = (
        cell(2.5, DetectionRule::Default).class_a_s.mean,
        cell(10.0, DetectionRule::Default).class_a_s.mean,
    );
    assert!(
        slow > 2.0 * fast,
        "class A ΔT {slow} s at 2.5 deg/s, {fast} s at 10"
    );
    let d = cell(5.0, DetectionRule::Default);
    let strict = cell(5.0, DetectionRule::Strict).class_a_s;
    assert!(strict.n == 0 || strict.mean <= d.class_a_s.mean);
    // the default cell is the default measure of the same run
    let spec = TwoTrackSpec::new(
        PowerLawPsd::new(IsoClass::E.alpha_r(), 2.0).unwrap(),
        Band::new(0.02, 5.0).unwrap(),
        CoherenceModel::piecewise(0.3).unwrap(),
    )
    .unwrap();
    let run = run_case_on(
        &p,
        Some(&spec),
        1,
        SENSITIVITY_TERRAIN_M,
        SteerDirection::Left,
        &RunOptions::default(),
        &Default::default(),
    )
    .unwrap();
    assert_eq!(Some(d.class_e_s.mean), run.measures.sustained_period_s);
    assert_eq!(d.ratio_e_over_a, d.class_e_s.mean / d.class_a_s.mean);
}
