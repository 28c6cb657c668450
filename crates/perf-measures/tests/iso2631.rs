//! ISO 2631-1 weightings and exposure measures against analytic cases.

use perf_measures::iso2631::{
    self, assess_whole_body, crest_factor, daily_exposure_a8, eu_level, health_guidance_zone, mtvv,
    running_rms, vdv, vibration_total_value, weight_fft, weight_iir, Axis, AxisInput, EuLevel,
    FilterMethod, HgczRelation, HgczZone, IirWeighting, KFactors, Weighting,
};
use perf_measures::MeasureError;
use proptest::prelude::*;
use std::f64::consts::PI;

fn sine(amp: f64, f: f64, fs: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| amp * (2.0 * PI * f * i as f64 / fs).sin())
        .collect()
}

fn rms(x: &[f64]) -> f64 {
    (x.iter().map(|v| v * v).sum::<f64>() / x.len() as f64).sqrt()
}

#[test]
fn weighting_check_passes_within_two_percent() {
    let c = iso2631::weighting_check();
    assert_eq!(c.weightings.len(), 6);
    for e in &c.weightings {
        assert!(e.bands >= 17, "{:?}", e);
        assert!(e.max_analog_error_percent < 1.0, "{:?}", e);
        assert!(e.max_iir_error_percent < 2.0, "{:?}", e);
        assert!(e.max_fft_error_percent < 1.0, "{:?}", e);
    }
    assert!(c.pass);
}

#[test]
fn hand_computed_factors() {
    // Wk at 100 Hz: a-v |1+8j| / |1-64 + 8j/0.63| = 0.12545; low pass 1/sqrt(2); upward step
    // ~1 (f >> f6). Table 3 gives 0.0887.
    let w = Weighting::Wk.magnitude(100.0);
    assert!((w - 0.0887).abs() < 0.0005, "{w}");
    // Wj at 0.1 Hz: high pass x = 0.25: 0.0625/sqrt(0.8789 + 0.125) = 0.06238, times the
    // upward step's low-frequency gain (3.75/5.32)^2 = 0.4969 -> 0.0310 (Table 4: 31.0e-3).
    let w = Weighting::Wj.magnitude(0.1);
    assert!((w - 0.0310).abs() < 0.0002, "{w}");
}

#[test]
fn sine_through_wk_at_100_hz_sampling() {
    let fs = 100.0;
    for f in [1.0, 5.0, 16.0, 31.5] {
        let x = sine(2.0, f, fs, 60 * 100);
        let y = weight_fft(Weighting::Wk, &x, fs).unwrap();
        // Skip the start-up transient.
        let aw = rms(&y[1000..]);
        let want = 2.0 / 2f64.sqrt() * Weighting::Wk.magnitude(f);
        assert!((aw / want - 1.0).abs() < 0.005, "f {f}: {aw} vs {want}");
    }
}

#[test]
fn iir_matches_analog_at_high_sampling_rate_and_streams() {
    let fs = 2000.0;
    let f = 8.0;
    let x = sine(1.0, f, fs, 20 * 2000);
    let y = weight_iir(Weighting::Wk, &x, fs).unwrap();
    let aw = rms(&y[10 * 2000..]);
    let want = Weighting::Wk.magnitude(f) / 2f64.sqrt();
    assert!((aw / want - 1.0).abs() < 0.01, "{aw} vs {want}");
    // Block processing in two halves equals one pass.
    let mut a = IirWeighting::new(Weighting::Wd, fs).unwrap();
    let mut b = a.clone();
    let mut one = x.clone();
    a.process_in_place(&mut one);
    let mut two = x.clone();
    let (h1, h2) = two.split_at_mut(7777);
    b.process_in_place(h1);
    b.process_in_place(h2);
    assert_eq!(one, two);
}

#[test]
fn gravity_offset_does_not_change_a_w() {
    let fs = 100.0;
    let x = sine(1.0, 4.0, fs, 6000);
    let g: Vec<f64> = x.iter().map(|v| v + 9.81).collect();
    let a = weight_fft(Weighting::Wk, &x, fs).unwrap();
    let b = weight_fft(Weighting::Wk, &g, fs).unwrap();
    let d = a
        .iter()
        .zip(&b)
        .map(|(p, q)| (p - q).abs())
        .fold(0.0, f64::max);
    assert!(d < 1e-9, "{d}");
}

#[test]
fn combined_value_eq_1_1() {
    let av = vibration_total_value([0.3, 0.4, 0.5], &KFactors::health()).unwrap();
    assert!((av - 0.74f64.sqrt()).abs() < 1e-12);
    let av = vibration_total_value([0.3, 0.4, 0.0], &KFactors::comfort()).unwrap();
    assert!((av - 0.5).abs() < 1e-12);
    assert!(vibration_total_value([f64::NAN, 0.0, 0.0], &KFactors::health()).is_err());
}

#[test]
fn sine_statistics() {
    let fs = 200.0;
    let a = 1.5;
    let x = sine(a, 2.0, fs, 200 * 64); // 64 s, whole periods
    assert!((crest_factor(&x).unwrap() - 2f64.sqrt()).abs() < 1e-3);
    // Running RMS over 1 s = 2 whole periods: a/sqrt(2) everywhere.
    let r = running_rms(&x, fs, 1.0).unwrap();
    assert_eq!(r.len(), x.len() - 200 + 1);
    assert!(r.iter().all(|v| (v - a / 2f64.sqrt()).abs() < 1e-9));
    // VDV = a (3/8)^(1/4) T^(1/4) (mean of sin^4 = 3/8).
    let want = a * (3.0f64 / 8.0).powf(0.25) * 64f64.powf(0.25);
    assert!((vdv(&x, fs).unwrap() / want - 1.0).abs() < 1e-9);
}

#[test]
fn mtvv_of_a_burst() {
    let fs = 100.0;
    let mut x = vec![0.0; 3000];
    // 2-s burst of amplitude 4 at 5 Hz: 1-s RMS inside it is 4/sqrt(2).
    for (i, v) in x.iter_mut().enumerate().skip(1000).take(200) {
        *v = 4.0 * (2.0 * PI * 5.0 * i as f64 / fs).sin();
    }
    let m = mtvv(&x, fs).unwrap();
    assert!((m - 4.0 / 2f64.sqrt()).abs() < 1e-9, "{m}");
    assert!(mtvv(&x[..50], fs).is_err());
}

#[test]
fn daily_exposure_and_eu_values() {
    assert!((daily_exposure_a8(1.0, 2.0).unwrap() - 0.5).abs() < 1e-12);
    assert!((daily_exposure_a8(0.7, 8.0).unwrap() - 0.7).abs() < 1e-12);
    assert_eq!(eu_level(0.49), EuLevel::BelowAction);
    assert_eq!(eu_level(0.5), EuLevel::AboveAction);
    assert_eq!(eu_level(1.15), EuLevel::AboveLimit);
    assert!(daily_exposure_a8(1.0, 0.0).is_err());
    assert!(daily_exposure_a8(f64::NAN, 1.0).is_err());
}

#[test]
fn caution_zone() {
    let z = health_guidance_zone(8.0, HgczRelation::SqrtTime).unwrap();
    assert!((z.lower_m_s2 - 0.433).abs() < 1e-3 && (z.upper_m_s2 - 0.866).abs() < 1e-3);
    let z4 = health_guidance_zone(2.0, HgczRelation::SqrtTime).unwrap();
    assert!((z4.lower_m_s2 / z.lower_m_s2 - 2.0).abs() < 1e-12);
    let z10 = health_guidance_zone(1.0 / 6.0, HgczRelation::SqrtTime).unwrap();
    assert!((z10.lower_m_s2 - 3.0).abs() < 1e-9 && (z10.upper_m_s2 - 6.0).abs() < 1e-9);
    let zb2 = health_guidance_zone(8.0, HgczRelation::FourthRootTime).unwrap();
    assert!((zb2.lower_m_s2 - 0.45).abs() < 1e-12 && (zb2.upper_m_s2 - 0.9).abs() < 1e-12);
    // Section 6.4: a_wz = 1.26 and 1.15 m/s^2 exceed the 8-h zone.
    assert_eq!(z.classify(1.26), HgczZone::Above);
    assert_eq!(z.classify(1.15), HgczZone::Above);
    assert_eq!(z.classify(0.6), HgczZone::Within);
    assert_eq!(z.classify(0.2), HgczZone::Below);
    assert!(
        !health_guidance_zone(30.0, HgczRelation::SqrtTime)
            .unwrap()
            .within_figure_range
    );
    assert!(health_guidance_zone(-1.0, HgczRelation::SqrtTime).is_err());
}

#[test]
fn whole_body_assessment_of_sines() {
    let fs = 100.0;
    let n = 100 * 120;
    let x = sine(0.5, 1.0, fs, n);
    let z = sine(1.0, 5.0, fs, n);
    let inputs = [
        AxisInput {
            axis: Axis::X,
            weighting: Axis::X.health_weighting(),
            accel: &x,
        },
        AxisInput {
            axis: Axis::Z,
            weighting: Axis::Z.health_weighting(),
            accel: &z,
        },
    ];
    let a = assess_whole_body(&inputs, fs, 8.0, KFactors::health(), FilterMethod::Fft).unwrap();
    let awx = 0.5 / 2f64.sqrt() * Weighting::Wd.magnitude(1.0);
    let awz = 1.0 / 2f64.sqrt() * Weighting::Wk.magnitude(5.0);
    assert!((a.axes[0].a_w / awx - 1.0).abs() < 0.01);
    assert!((a.axes[1].a_w / awz - 1.0).abs() < 0.01);
    let av = ((1.4 * awx).powi(2) + awz.powi(2)).sqrt();
    assert!((a.a_v / av - 1.0).abs() < 0.01);
    assert_eq!(a.governing_axis, Axis::Z);
    assert!((a.a8 - a.axes[1].a_w).abs() < 1e-12);
    assert_eq!(a.eu_level, EuLevel::AboveAction);
    // Duplicate axis and empty input are errors.
    assert!(
        assess_whole_body(&inputs[..0], fs, 8.0, KFactors::health(), FilterMethod::Fft).is_err()
    );
    let dup = [inputs[0], inputs[0]];
    assert!(assess_whole_body(&dup, fs, 8.0, KFactors::health(), FilterMethod::Fft).is_err());
}

#[test]
fn bad_inputs_are_errors() {
    assert!("wz".parse::<Weighting>().is_err());
    assert_eq!("WK".parse::<Weighting>().unwrap(), Weighting::Wk);
    assert!(weight_fft(Weighting::Wk, &[1.0, f64::NAN, 2.0], 100.0).is_err());
    assert!(weight_fft(Weighting::Wk, &[1.0, 2.0], 0.0).is_err());
    assert!(matches!(
        weight_fft(Weighting::Wk, &[1.0], 100.0),
        Err(MeasureError::TooShort { .. })
    ));
    assert!(IirWeighting::new(Weighting::Wk, 20.0).is_err());
    assert!(IirWeighting::new(Weighting::Wk, f64::NAN).is_err());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    #[test]
    fn a_w_scales_linearly(scale in 0.01f64..100.0, f in 0.5f64..20.0, seed in 0u64..1000) {
        let fs = 100.0;
        let n = 2000;
        let phase = seed as f64 * 0.37;
        let x: Vec<f64> = (0..n)
            .map(|i| (2.0 * PI * f * i as f64 / fs + phase).sin() + 0.3 * (0.7 * i as f64).cos())
            .collect();
        let xs: Vec<f64> = x.iter().map(|v| v * scale).collect();
        for w in [Weighting::Wk, Weighting::Wd] {
            let a = rms(&weight_fft(w, &x, fs).unwrap());
            let b = rms(&weight_fft(w, &xs, fs).unwrap());
            prop_assert!((b / (scale * a) - 1.0).abs() < 1e-9);
        }
    }

    #[test]
    fn magnitude_is_finite_and_bounded(f in 0.01f64..1000.0) {
        for w in Weighting::ALL {
            let m = w.magnitude(f);
            prop_assert!(m.is_finite() && (0.0..1.1).contains(&m), "{w} {f} {m}");
        }
    }
}
