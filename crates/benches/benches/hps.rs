//! Real-time factor of the strut: 10 cycles at 8 Hz (1.25 s simulated) with 360 Hz output.

use criterion::{criterion_group, criterion_main, Criterion};
use hps_emulsion::*;
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    let front = StrutParams::front_axle();
    let lab = StrutParams::lab(LabConfig::OneOrifice);
    let exc = Excitation::harmonic(8.0, 0.0075, 10.0);
    let o = SimOptions::default();
    c.bench_function("hps_8hz_10cycles_sim1.25s", |b| {
        b.iter(|| {
            simulate_displacement(black_box(&front), &HpsExtensions::none(), &exc, &o).unwrap()
        })
    });
    c.bench_function("hps_lab1_8hz_10cycles_sim1.25s", |b| {
        b.iter(|| simulate_displacement(black_box(&lab), &HpsExtensions::none(), &exc, &o).unwrap())
    });
    let slow = Excitation::harmonic(0.1, 0.025, 1.0);
    c.bench_function("hps_0p1hz_1cycle_sim10s", |b| {
        b.iter(|| {
            simulate_displacement(black_box(&front), &HpsExtensions::none(), &slow, &o).unwrap()
        })
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
