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
