//! Free-decay fit against exact damped oscillations, with noise and few cycles.

use perf_measures::{fit_free_decay, MeasureError};
use proptest::prelude::*;
use rand_chacha::rand_core::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::f64::consts::PI;

struct Case {
    f_n: f64,
    zeta: f64,
    amp: f64,
    offset: f64,
    phase: f64,
}

fn record(c: &Case, fs: f64, duration: f64, noise: f64, seed: u64) -> (Vec<f64>, Vec<f64>) {
    let wn = 2.0 * PI * c.f_n;
    let wd = wn * (1.0 - c.zeta * c.zeta).sqrt();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut gauss = move || {
        let u1 = ((rng.next_u64() >> 11) as f64 + 0.5) / (1u64 << 53) as f64;
        let u2 = ((rng.next_u64() >> 11) as f64 + 0.5) / (1u64 << 53) as f64;
        (-2.0 * u1.ln()).sqrt() * (2.0 * PI * u2).cos()
    };
    let n = (duration * fs).round() as usize + 1;
    let t: Vec<f64> = (0..n).map(|i| 1.3 + i as f64 / fs).collect();
    let y = t
        .iter()
        .map(|&ti| {
            let tau = ti - 1.3;
            c.offset
                + c.amp * (-c.zeta * wn * tau).exp() * (wd * tau + c.phase).cos()
                + noise * gauss()
        })
        .collect();
    (t, y)
}

#[test]
fn exact_oscillation_is_recovered() {
    // Section 6.4 reports a yaw-mode frequency of 2.81 Hz.
    let c = Case {
        f_n: 2.81,
        zeta: 0.12,
        amp: 2.0,
        offset: 0.5,
        phase: 0.3,
    };
    let (t, y) = record(&c, 200.0, 1.2, 0.0, 0);
    let f = fit_free_decay(&t, &y).unwrap();
    assert!((f.natural_frequency_hz / 2.81 - 1.0).abs() < 1e-6, "{f:?}");
    assert!((f.damping_ratio - 0.12).abs() < 1e-6, "{f:?}");
    assert!((f.amplitude - 2.0).abs() < 1e-5 && (f.offset - 0.5).abs() < 1e-6);
    assert!((f.phase_rad - 0.3).abs() < 1e-5);
    assert!(f.rmse < 1e-6 && f.r_squared > 0.999_999);
    let wd = 2.81 * (1.0f64 - 0.0144).sqrt();
    assert!((f.damped_frequency_hz - wd).abs() < 1e-5);
}

#[test]
fn noisy_record_with_large_offset() {
    let c = Case {
        f_n: 1.7,
        zeta: 0.2,
        amp: 5.0,
        offset: -3.0,
        phase: 0.0,
    };
    // 5 % of the amplitude as white noise, 2.5 s (about 4 cycles).
    for seed in 0..5 {
        let (t, y) = record(&c, 100.0, 2.5, 0.25, seed);
        let f = fit_free_decay(&t, &y).unwrap();
        assert!((f.natural_frequency_hz / 1.7 - 1.0).abs() < 0.02, "{f:?}");
        assert!((f.damping_ratio - 0.2).abs() < 0.02, "{f:?}");
        assert!((f.offset + 3.0).abs() < 0.1, "{f:?}");
        assert!(f.natural_frequency_std_hz > 0.0 && f.natural_frequency_std_hz < 0.05);
    }
}

#[test]
fn heavy_damping_and_one_and_a_half_cycles() {
    let c = Case {
        f_n: 0.8,
        zeta: 0.35,
        amp: 1.0,
        offset: 0.2,
        phase: -0.5,
    };
    let (t, y) = record(&c, 50.0, 2.0, 0.01, 7);
    let f = fit_free_decay(&t, &y).unwrap();
    assert!((f.natural_frequency_hz / 0.8 - 1.0).abs() < 0.02, "{f:?}");
    assert!((f.damping_ratio - 0.35).abs() < 0.02, "{f:?}");
}

#[test]
fn a_fit_at_the_noise_earns_its_numbers_and_a_second_mode_does_not() {
    let c = Case {
        f_n: 1.7,
        zeta: 0.2,
        amp: 5.0,
        offset: -3.0,
        phase: 0.0,
    };
    let (t, y) = record(&c, 100.0, 2.5, 0.25, 3);
    let f = fit_free_decay(&t, &y).unwrap();
    assert!(f.problems().is_empty(), "{:?}", f.problems());
    assert!((f.noise_rms / 0.25 - 1.0).abs() < 0.3, "{f:?}");
    // A second, lightly damped mode at 4.3 Hz with 20 % of the amplitude, on a quieter
    // record (0.02 of noise): one decaying mode no longer describes it.
    let (t, y) = record(&c, 100.0, 2.5, 0.02, 3);
    let y2: Vec<f64> = t
        .iter()
        .zip(&y)
        .map(|(ti, v)| {
            let tau = ti - 1.3;
            v + 1.0 * (-0.05 * 2.0 * PI * 4.3 * tau).exp() * (2.0 * PI * 4.3 * tau).cos()
        })
        .collect();
    let f = fit_free_decay(&t, &y2).unwrap();
    let p = f.problems();
    assert!(
        p.iter().any(|m| m.contains("times the noise")),
        "{p:?} {f:?}"
    );
    // Less than 1.5 cycles: flagged.
    let (t, y) = record(&c, 100.0, 0.7, 0.01, 4);
    let f = fit_free_decay(&t, &y).unwrap();
    assert!(f.problems().iter().any(|m| m.contains("cycles")), "{f:?}");
}

#[test]
fn growing_oscillation_has_negative_damping() {
    let c = Case {
        f_n: 3.0,
        zeta: -0.03,
        amp: 0.5,
        offset: 0.0,
        phase: 1.0,
    };
    let (t, y) = record(&c, 200.0, 2.0, 0.0, 0);
    let f = fit_free_decay(&t, &y).unwrap();
    assert!((f.damping_ratio + 0.03).abs() < 1e-5, "{f:?}");
}

#[test]
fn bad_records_are_errors() {
    let t: Vec<f64> = (0..50).map(|i| i as f64 * 0.01).collect();
    assert!(matches!(
        fit_free_decay(&t, &[1.0; 50]),
        Err(MeasureError::Fit(_))
    ));
    let mut y = vec![0.0; 50];
    y[3] = f64::NAN;
    assert!(matches!(
        fit_free_decay(&t, &y),
        Err(MeasureError::NonFinite { .. })
    ));
    assert!(matches!(
        fit_free_decay(&t[..5], &y[..5]),
        Err(MeasureError::TooShort { .. })
    ));
    assert!(fit_free_decay(&t, &y[..40]).is_err());
    let mut tb = t.clone();
    tb[10] = tb[9];
    assert!(matches!(
        fit_free_decay(&tb, &[0.0; 50]),
        Err(MeasureError::NonMonotonicTime { index: 10 })
    ));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]
    #[test]
    fn fit_recovers_parameters(
        f_n in 0.5f64..5.0,
        zeta in 0.02f64..0.5,
        amp in 0.1f64..10.0,
        offset in -2.0f64..2.0,
        phase in -3.0f64..3.0,
        cycles in 2.0f64..6.0,
    ) {
        let c = Case { f_n, zeta, amp, offset, phase };
        let fs = 40.0 * f_n;
        let (t, y) = record(&c, fs, cycles / f_n, 0.0, 0);
        let f = fit_free_decay(&t, &y).unwrap();
        prop_assert!((f.natural_frequency_hz / f_n - 1.0).abs() < 1e-3, "{:?}", f);
        prop_assert!((f.damping_ratio - zeta).abs() < 1e-3, "{:?}", f);
    }
}
