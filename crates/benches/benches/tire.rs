//! Cost of one force evaluation (target well under 100 ns), of one enveloping contact per
//! wheel per integration step on a rough polyline profile, and of one tire of the tire
//! assembly (contact on its cached track, Fiala law) per wheel per integration step.

use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::Vector3;
use std::hint::black_box;
use std::sync::Arc;
use tire_fiala::{
    EffectiveTrack, Envelope, EnvelopeMethod, Fiala, FialaLaw, HandlingLaw, HandlingModel,
    PathFrame, PolylineProfile, TireAssembly, TireInput, TireParams, TireTrack, Track,
    VerticalContact, Wheel,
};
use vehicle_components::{Component, Terrain, DEFAULT_FRICTION};

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

/// The bench profile's sum of sines, with a gentle cross slope.
struct Rough;

impl Terrain for Rough {
    fn height(&self, x: f64, y: f64) -> f64 {
        0.03 * (1.3 * x).sin() + 0.01 * (7.1 * x).sin() + 0.004 * (23.0 * x).cos() + 0.01 * y
    }
    fn friction(&self, _x: f64, _y: f64) -> f64 {
        DEFAULT_FRICTION
    }
}

fn assembly(c: &mut Criterion) {
    let p = TireParams::nominal();
    let envelope = Envelope::new(EnvelopeMethod::TandemCams, 1.0, 0.02).unwrap();
    let profile = Track {
        terrain: Rough,
        y: 1.14,
    };
    let track = EffectiveTrack::build(&profile, (0.0, 200.0), 0.05, &envelope, 0.08).unwrap();
    let tire = TireAssembly::new(
        Arc::new([TireTrack::Static(track)]),
        &[0],
        1.0,
        VerticalContact::from_params(&p).unwrap(),
        HandlingLaw::Fiala(FialaLaw::new(&p).unwrap()),
    )
    .unwrap();
    let path = PathFrame {
        direction: Vector3::x(),
        origin: Vector3::zeros(),
        coordinate: 0.0,
    };
    let mut x = 10.0;
    let mut d = [0.0; 2];
    c.bench_function("tire_assembly_cached_per_wheel_step", |b| {
        b.iter(|| {
            x += 0.01;
            if x > 190.0 {
                x = 10.0;
            }
            let wheel = Wheel {
                centre: Vector3::new(x, 1.14, 0.92),
                velocity: Vector3::new(10.0, 0.3, 0.0),
                heading: 0.05f64.sin_cos(),
                axle: Vector3::new(-0.05f64.sin(), 0.05f64.cos(), 0.0),
                spin: 10.5,
            };
            let input = TireInput {
                contact: tire.contact(0, black_box(&wheel), &path, None),
                wheel,
                drive_force: 0.0,
            };
            black_box(tire.evaluate(black_box(&input), black_box(&[0.01, 0.02]), &mut d))
        })
    });
}

criterion_group!(benches, forces, envelope, assembly);
criterion_main!(benches);
