//! Cost of one right-hand-side evaluation of the AFS component.
use afs_hydraulics::{
    AfsExtensions, AfsInput, AfsParams, AfsSystem, CoulombFriction, EntrainedAir, SupplyDroop,
};
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    let sys = AfsSystem::new(AfsParams::nominal()).expect("nominal parameters are valid");
    let state = [6.0e6, 1.5e6, 0.05];
    let input = AfsInput {
        theta: 0.03,
        theta_dot: 0.2,
        steer_wheel: 0.2,
    };
    let mut d = [0.0; 3];
    c.bench_function("afs_derivatives_baseline", |b| {
        b.iter(|| {
            let o = sys.derivatives(black_box(&input), black_box(&state), &mut d);
            black_box((o.torque, d[0]))
        })
    });
    let ext = AfsExtensions {
        supply_droop: Some(SupplyDroop {
            droop_pa_s_per_m3: 9.0e8,
        }),
        coulomb_friction: Some(CoulombFriction {
            force_n: 2000.0,
            velocity_scale_m_s: 1e-3,
        }),
        entrained_air: Some(EntrainedAir {
            air_fraction_atm: 0.01,
            polytropic_index: 1.0,
            atmospheric_pressure_pa: 101_325.0,
        }),
        valve_lag: None,
        constant_leakage_only: false,
    };
    let sys_ext = sys.clone().with_extensions(ext).expect("valid extensions");
    c.bench_function("afs_derivatives_all_extensions", |b| {
        b.iter(|| {
            let o = sys_ext.derivatives(black_box(&input), black_box(&state), &mut d);
            black_box((o.torque, d[0]))
        })
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
