//! Roll (LTR, DRT, SP-DRT, SSF), step-response and steering-efficiency measures.

use perf_measures::{
    ltr, ltr_two_axle, smooth_road_drt, static_stability_factor, steering_power_efficiency,
    step_metrics, sustained_period, MeasureError, SustainedPeriodParams,
};
use proptest::prelude::*;
use std::f64::consts::PI;

#[test]
fn ltr_hand_cases() {
    // |(10-20) + (30-40)| / 100 = 0.2
    let v = ltr_two_axle(&[10.0], &[20.0], &[30.0], &[40.0]).unwrap();
    assert!((v[0] - 0.2).abs() < 1e-12);
    // Inside track lifted off: LTR = 1; negative (penetration-free) forces clamp at zero.
    assert_eq!(ltr(&[0.0, -5.0], &[50.0, 60.0]).unwrap(), 1.0);
    assert!(ltr(&[0.0], &[0.0]).is_err());
    assert!(ltr(&[1.0, 2.0], &[1.0]).is_err());
    assert!(ltr(&[f64::NAN], &[1.0]).is_err());
}

#[test]
fn ssf() {
    assert!((static_stability_factor(1.2, 2.4).unwrap() - 0.5).abs() < 1e-12);
    assert!(static_stability_factor(1.2, 0.0).is_err());
    assert!(static_stability_factor(f64::NAN, 1.0).is_err());
}

#[test]
fn smooth_road_drt_interpolates_first_crossing() {
    let t: Vec<f64> = (0..=2000).map(|i| i as f64 * 0.01).collect();
    let l: Vec<f64> = t.iter().map(|&x| (x / 10.0).min(1.0)).collect();
    let ay: Vec<f64> = t.iter().map(|&x| 0.2 * x).collect();
    let p = smooth_road_drt(&t, &l, &ay, 1.0).unwrap();
    assert!((p.time_s - 10.0).abs() < 1e-9 && (p.lateral_accel_m_s2 - 2.0).abs() < 1e-9);
    let low: Vec<f64> = l.iter().map(|v| v * 0.5).collect();
    assert!(matches!(
        smooth_road_drt(&t, &low, &ay, 1.0),
        Err(MeasureError::NotFound(_))
    ));
    assert!(smooth_road_drt(&t, &l, &ay, 1.5).is_err());
}

/// Synthetic cornering history, 0-41 s at 100 Hz: LTR 0.5 with a 0.1-s spike to 1 at 10 s
/// (like A1, too short), near 1 (0.97) from 30 s to 40 s with dips to 0.8 of 0.2 s at 33 s
/// and 0.3 s at 36 s, then wheel lift-off (LTR = 1) from 40 s to the end (absolute
/// rollover). Lateral acceleration a_y = 0.1 t. The sustained period is [30, 40] s and the
/// SP-DRT = sqrt((40^3 - 30^3) / (3 * 10) * 0.01) = 3.5119 m/s^2.
fn history() -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let t: Vec<f64> = (0..=4100).map(|i| i as f64 * 0.01).collect();
    let l = t
        .iter()
        .map(|&x| {
            let x = (x * 100.0).round() / 100.0;
            if (10.0..10.1).contains(&x) {
                1.0
            } else if x < 30.0 {
                0.5
            } else if x >= 40.0 + 1e-9 {
                1.0
            } else if (33.0 + 1e-9..33.2).contains(&x) || (36.0 + 1e-9..36.3).contains(&x) {
                0.8
            } else {
                0.97
            }
        })
        .collect();
    let ay = t.iter().map(|&x| 0.1 * x).collect();
    (t, l, ay)
}

#[test]
fn sustained_period_of_synthetic_history() {
    let (t, l, ay) = history();
    let sp = sustained_period(&t, &l, &ay, &SustainedPeriodParams::default()).unwrap();
    assert!((sp.start_s - 30.0).abs() < 1e-9, "{sp:?}");
    assert!((sp.end_s - 40.0).abs() < 0.011, "{sp:?}");
    assert_eq!(sp.dips, 2);
    let want = ((40f64.powi(3) - 30f64.powi(3)) / 30.0 * 0.01).sqrt();
    assert!(
        (sp.sp_drt_m_s2 - want).abs() < 2e-3,
        "{} vs {want}",
        sp.sp_drt_m_s2
    );
    assert!((sp.lift_off_start_s.unwrap() - 40.01).abs() < 1e-9);
    assert!(sp.fraction_above_threshold > 0.9 && sp.fraction_above_threshold < 0.96);
    // Not tolerating 0.3-s dips splits the period: the last piece is [36.3, 40].
    let strict = SustainedPeriodParams {
        max_dip_s: 0.25,
        ..Default::default()
    };
    let sp2 = sustained_period(&t, &l, &ay, &strict).unwrap();
    assert!((sp2.start_s - 36.3).abs() < 0.011, "{sp2:?}");
    // Requiring 20 s finds nothing.
    let long = SustainedPeriodParams {
        min_duration_s: 20.0,
        ..Default::default()
    };
    assert!(matches!(
        sustained_period(&t, &l, &ay, &long),
        Err(MeasureError::NotFound(_))
    ));
    // Keeping the lift-off phase extends the period to the end of the record.
    let keep = SustainedPeriodParams {
        lift_off_level: None,
        ..Default::default()
    };
    let sp3 = sustained_period(&t, &l, &ay, &keep).unwrap();
    assert!((sp3.end_s - 41.0).abs() < 1e-9);
    // Invalid parameters.
    let bad = SustainedPeriodParams {
        threshold: f64::NAN,
        ..Default::default()
    };
    assert!(sustained_period(&t, &l, &ay, &bad).is_err());
}

fn second_order_step(k: f64, f_n: f64, zeta: f64, t: &[f64], t0: f64) -> Vec<f64> {
    let wn = 2.0 * PI * f_n;
    let wd = wn * (1.0 - zeta * zeta).sqrt();
    t.iter()
        .map(|&x| {
            let tau = x - t0;
            if tau < 0.0 {
                0.0
            } else {
                k * (1.0
                    - (-zeta * wn * tau).exp()
                        * ((wd * tau).cos() + zeta / (1.0 - zeta * zeta).sqrt() * (wd * tau).sin()))
            }
        })
        .collect()
}

#[test]
fn step_metrics_of_second_order_response() {
    let (f_n, zeta) = (1.0, 0.3);
    let t: Vec<f64> = (0..=3000).map(|i| i as f64 * 0.01).collect();
    let y = second_order_step(9.0, f_n, zeta, &t, 1.0);
    let m = step_metrics(&t, &y, 1.0, 30.0).unwrap();
    let wd = 2.0 * PI * f_n * (1.0 - zeta * zeta).sqrt();
    let s = (1.0 - zeta * zeta).sqrt();
    let rise = (PI - (s / zeta).atan()) / wd;
    let os = 100.0 * (-PI * zeta / s).exp();
    assert!((m.gain - 0.3).abs() < 1e-4, "{m:?}");
    assert!(
        (m.rise_time_s - rise).abs() < 2e-3,
        "{} vs {rise}",
        m.rise_time_s
    );
    assert!(
        (m.overshoot_percent - os).abs() < 0.05,
        "{} vs {os}",
        m.overshoot_percent
    );
    assert!((m.peak_time_s - 1.0 - PI / wd).abs() < 0.011);
    // Negative steer: same metrics, negative gain.
    let yn: Vec<f64> = y.iter().map(|v| -v).collect();
    let mn = step_metrics(&t, &yn, 1.0, -30.0).unwrap();
    assert!((mn.gain - 0.3).abs() < 1e-4 && (mn.overshoot_percent - os).abs() < 0.05);
    // Errors.
    assert!(step_metrics(&t, &y, 1.0, 0.0).is_err());
    assert!(step_metrics(&t, &y, 100.0, 30.0).is_err());
    assert!(matches!(
        step_metrics(&t, &vec![0.0; t.len()], 1.0, 30.0),
        Err(MeasureError::NotFound(_))
    ));
}

#[test]
fn steering_efficiency_eq_4_7() {
    let t: Vec<f64> = (0..=100).map(|i| i as f64 * 0.01).collect();
    let n = t.len();
    let eta = steering_power_efficiency(
        &t,
        &vec![1000.0; n],
        &vec![0.1; n],
        &vec![1e7; n],
        &vec![2e-5; n],
    )
    .unwrap();
    assert!((eta - 0.5).abs() < 1e-12);
    // Linearly rising torque: integral T dt = 500 * 1 s -> eta = 50 / 200.
    let tq: Vec<f64> = t.iter().map(|x| 1000.0 * x).collect();
    let eta =
        steering_power_efficiency(&t, &tq, &vec![0.1; n], &vec![1e7; n], &vec![2e-5; n]).unwrap();
    assert!((eta - 0.25).abs() < 1e-12);
    assert!(
        steering_power_efficiency(&t, &tq, &vec![0.1; n], &vec![0.0; n], &vec![2e-5; n]).is_err()
    );
    assert!(
        steering_power_efficiency(&t, &tq[..50], &vec![0.1; n], &vec![1e7; n], &vec![2e-5; n])
            .is_err()
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    #[test]
    fn ltr_is_bounded_and_mirror_symmetric(f in proptest::collection::vec(0.0f64..1e6, 4)) {
        prop_assume!(f.iter().sum::<f64>() > 1.0);
        let a = ltr(&[f[0], f[1]], &[f[2], f[3]]).unwrap();
        let b = ltr(&[f[2], f[3]], &[f[0], f[1]]).unwrap();
        prop_assert!((0.0..=1.0).contains(&a));
        prop_assert!((a - b).abs() < 1e-12);
    }

    #[test]
    fn step_gain_scales_with_output(k in 0.01f64..100.0, zeta in 0.1f64..0.9) {
        let t: Vec<f64> = (0..=4000).map(|i| i as f64 * 0.01).collect();
        let y = second_order_step(k, 0.7, zeta, &t, 0.5);
        let m = step_metrics(&t, &y, 0.5, 2.0).unwrap();
        prop_assert!((m.gain / (k / 2.0) - 1.0).abs() < 1e-3);
        prop_assert!(m.overshoot_percent >= 0.0 && m.rise_time_s > 0.0);
    }
}
