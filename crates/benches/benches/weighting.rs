//! Weighting a 10-minute, 100 Hz seat-acceleration record (60 000 samples).

use criterion::{criterion_group, criterion_main, Criterion};
use perf_measures::iso2631::{
    assess_whole_body, weight_fft, weight_iir, Axis, AxisInput, FilterMethod, KFactors, Weighting,
};
use std::hint::black_box;

fn record(n: usize, fs: f64) -> Vec<f64> {
    // Deterministic broadband signal: a few incommensurate sines plus a chirp.
    (0..n)
        .map(|i| {
            let t = i as f64 / fs;
            9.81 + 0.8 * (2.0 * std::f64::consts::PI * 1.3 * t).sin()
                + 0.5 * (2.0 * std::f64::consts::PI * 4.7 * t).sin()
                + 0.3 * (2.0 * std::f64::consts::PI * (0.5 + 0.04 * t) * t).sin()
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let fs = 100.0;
    let x = record(60_000, fs);
    c.bench_function("wk_weighting_sim600s", |b| {
        b.iter(|| weight_fft(Weighting::Wk, black_box(&x), fs).unwrap())
    });
    c.bench_function("wk_iir_weighting_sim600s", |b| {
        b.iter(|| weight_iir(Weighting::Wk, black_box(&x), fs).unwrap())
    });
    c.bench_function("wbv_assess_3axis_sim600s", |b| {
        b.iter(|| {
            let inputs = [Axis::X, Axis::Y, Axis::Z].map(|axis| AxisInput {
                axis,
                weighting: axis.health_weighting(),
                accel: &x,
            });
            assess_whole_body(&inputs, fs, 8.0, KFactors::health(), FilterMethod::Fft).unwrap()
        })
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
