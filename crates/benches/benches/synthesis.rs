//! Criterion benches: two-track synthesis of 100 m at 0.05 m (the paper's nominal terrain) and
//! Welch / cross-spectrum estimates of the result.
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use terrain_psd::{cross_spectrum, synthesize, welch_psd, TwoTrackSpec, WelchConfig};

fn bench(c: &mut Criterion) {
    let spec = TwoTrackSpec::paper_nominal();
    c.bench_function("synthesize two tracks 100 m @ 0.05 m", |b| {
        b.iter(|| synthesize(black_box(&spec), 100.0, 0.05, black_box(7)).unwrap())
    });
    c.bench_function("synthesize two tracks 2000 m @ 0.05 m", |b| {
        b.iter(|| synthesize(black_box(&spec), 2000.0, 0.05, black_box(7)).unwrap())
    });
    let p = synthesize(&spec, 100.0, 0.05, 7).unwrap();
    let cfg = WelchConfig::new(256);
    c.bench_function("welch psd 100 m (2001 samples, 256-sample segments)", |b| {
        b.iter(|| welch_psd(black_box(&p.left_m), 0.05, &cfg).unwrap())
    });
    let long = synthesize(&spec, 2000.0, 0.05, 7).unwrap();
    let cfg = WelchConfig::new(2048);
    c.bench_function(
        "cross spectrum + coherence 2000 m (2048-sample segments)",
        |b| b.iter(|| cross_spectrum(black_box(&long.left_m), &long.right_m, 0.05, &cfg).unwrap()),
    );
}

criterion_group!(benches, bench);
criterion_main!(benches);
