//! 10 s pulse scenario of section 3.3 (loaded, 50 km/h, 30 deg half-sine of 0.2 s): the
//! full `simulate` call including the 200 Hz record; `cargo xtask bench` turns the
//! `_sim10s` suffix into a real-time factor.

use afs_hydraulics::{AfsParams, AfsSystem};
use afsv_dynamics::{simulate, Manoeuvre, SimOptions, VehicleParams};
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    let sys = AfsSystem::new(AfsParams::nominal()).unwrap();
    let v = VehicleParams::loaded();
    let man = Manoeuvre::pulse(50.0 / 3.6, 30.0);
    let opts = SimOptions::default();
    c.bench_function("yaw_pulse_sim10s", |b| {
        b.iter(|| simulate(black_box(&v), &sys, &man, &opts).unwrap())
    });
    let coarse = SimOptions {
        output_dt_s: 0.01,
        ..SimOptions::default()
    };
    c.bench_function("yaw_pulse_100hz_sim10s", |b| {
        b.iter(|| simulate(black_box(&v), &sys, &man, &coarse).unwrap())
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
