//! The FFT weighting refuses a sampling rate whose settling padding would not fit in memory
//! (a record with a 1e-14 s step) instead of allocating for minutes.

use perf_measures::iso2631::{weight_fft, Weighting};

#[test]
fn fft_padding_is_bounded() {
    let x: Vec<f64> = (0..200).map(|i| (i as f64 * 0.3).sin()).collect();
    let t = std::time::Instant::now();
    for fs in [1e14, 1e9, f64::MAX] {
        let e = weight_fft(Weighting::Wk, &x, fs).unwrap_err();
        assert!(e.to_string().contains("fs_hz"), "{e}");
    }
    assert!(t.elapsed().as_secs() < 5);
    assert!(weight_fft(Weighting::Wk, &x, 100.0).is_ok());
}

mod window {
    use perf_measures::decay::decay_window;
    use proptest::prelude::*;

    #[test]
    fn windows_outside_the_record_are_errors() {
        let t: Vec<f64> = (0..601).map(|i| i as f64 * 0.005).collect();
        let y: Vec<f64> = t.iter().map(|v| v.sin()).collect();
        for (s, e) in [
            (None, Some(-1.0)),
            (None, Some(0.0)),
            (Some(5.0), None),
            (Some(2.0), Some(1.0)),
        ] {
            let err = decay_window(&t, &y, s, e).unwrap_err().to_string();
            assert!(err.contains("fewer than 2 samples"), "{err}");
        }
        for (s, e) in [
            (Some(f64::NAN), None),
            (None, Some(f64::NAN)),
            (None, Some(f64::INFINITY)),
        ] {
            assert!(decay_window(&t, &y, s, e).is_err());
        }
        assert_eq!(
            decay_window(&t, &y, Some(0.5), Some(1.0)).unwrap(),
            100..201
        );
        assert!(decay_window(&[], &[], None, None).is_err());
        assert!(decay_window(&t, &y[..3], None, None).is_err());
    }

    proptest! {
        #[test]
        fn never_panics(n in 0usize..50, s in proptest::option::of(-10.0f64..10.0), e in proptest::option::of(-10.0f64..10.0)) {
            let t: Vec<f64> = (0..n).map(|i| i as f64 * 0.1).collect();
            let y: Vec<f64> = t.iter().map(|v| (3.0 * v).cos()).collect();
            if let Ok(w) = decay_window(&t, &y, s, e) {
                prop_assert!(w.start + 1 < w.end && w.end <= n);
            }
        }
    }
}
