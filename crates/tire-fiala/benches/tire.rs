//! Cost of one force evaluation (target well under 100 ns) and of one enveloping contact
//! per wheel per integration step, on a rough polyline profile.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use tire_fiala::{Envelope, EnvelopeMethod, Fiala, HandlingModel, PolylineProfile, TireParams};

fn forces(c: &mut Criterion) {
    let tire = Fiala::new(&TireParams::nominal()).unwrap();
    let mut k = 0u32;
    c.bench_function("fiala_forces_per_call", |b| {
        b.iter(|| {
            k = k.wrapping_add(1);
            let alpha = (k % 200) as f64 * 1e-3 - 0.1;
            let kappa = (k % 50) as f64 * 2e-3 - 0.05;
            black_box(tire.forces(black_box(150e3), black_box(kappa), black_box(alpha)))
        })
    });
}

fn envelope(c: &mut Criterion) {
    // Deterministic rough profile: 0.05 m spacing over 200 m, sum of sines.
    let xs: Vec<f64> = (0..4001).map(|i| i as f64 * 0.05).collect();
    let zs: Vec<f64> = xs
        .iter()
        .map(|&x| 0.03 * (1.3 * x).sin() + 0.01 * (7.1 * x).sin() + 0.004 * (23.0 * x).cos())
        .collect();
    let profile = PolylineProfile::new(xs, zs).unwrap();
    for (name, method) in [
        ("envelope_cams_per_wheel_step", EnvelopeMethod::TandemCams),
        ("envelope_circle_per_wheel_step", EnvelopeMethod::CircleLine),
    ] {
        let env = Envelope::new(method, 1.0, 0.02).unwrap();
        let mut x = 10.0;
        c.bench_function(name, |b| {
            b.iter(|| {
                x += 0.01; // 10 m/s at a 1 ms step
                if x > 190.0 {
                    x = 10.0;
                }
                black_box(env.contact(&profile, black_box(x), black_box(0.92)))
            })
        });
    }
}

criterion_group!(benches, forces, envelope);
criterion_main!(benches);
