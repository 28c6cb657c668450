//! Cost of the Chapter 2 ramp-steer run on class E terrain (section 2.3).
//!
//! - `class_e_ramp_steer_sim60s`: 60 s of ramp steer at 40 km/h on the nominal class E
//!   terrain (667 m driven), with a gentler ramp (1.5 deg/s at the steering wheel instead
//!   of 5) so that the truck does not roll over before 60 s; `cargo xtask bench` prints its
//!   real-time factor;
//! - `class_e_ramp_steer_tsit5_sim60s`: the same run with Tsitouras 5(4) in place of
//!   Dormand-Prince (`RunOptions::solver`, docs/numerics.md, "Tsitouras 5(4)");
//! - `class_e_ramp_steer_kinks_sim60s`: the same run with the kinks of the force laws
//!   located as events (`RunOptions::locate_kinks`, docs/numerics.md, "Kinks");
//! - `class_e_ramp_to_rollover`: the nominal ramp until absolute rollover (about 29 s for
//!   seed 1);
//! - `class_e_terrain_and_cache`: synthesis of 800 m of terrain and the enveloping cache,
//!   paid once per terrain seed.

use criterion::{criterion_group, criterion_main, Criterion};
use roll_truck::simulate::simulate_with_stats;
use roll_truck::studies::{rough_terrain, truck_on, TERRAIN_LENGTH_M};
use roll_truck::{simulate, RunOptions, SteerDirection, TruckParams};
use terrain_psd::TwoTrackSpec;

fn bench(c: &mut Criterion) {
    let nominal = TruckParams::nominal();
    let mut gentle = nominal;
    gentle.steering_wheel_rate_deg_s = 1.5;
    let spec = TwoTrackSpec::paper_nominal();
    let options = RunOptions::default();
    let terrain = rough_terrain(&nominal, &spec, TERRAIN_LENGTH_M, 1).unwrap();
    let length = nominal.target_speed_m_s * options.t_end_s * 1.1 + 10.0;
    let mut group = c.benchmark_group("roll_truck");
    group.sample_size(10);
    let vehicle = truck_on(&gentle, &terrain, SteerDirection::Left, length).unwrap();
    let run = simulate(&vehicle, &options).unwrap();
    assert_eq!(run.rollover_s, None, "the gentle ramp must not roll over");
    assert_eq!(*run.t_s.last().unwrap(), options.t_end_s);
    group.bench_function("class_e_ramp_steer_sim60s", |b| {
        b.iter(|| simulate(&vehicle, &options).unwrap().t_s.len())
    });
    let tsit5 = RunOptions {
        solver: odeint::Solver::Tsit5,
        ..options
    };
    group.bench_function("class_e_ramp_steer_tsit5_sim60s", |b| {
        b.iter(|| simulate(&vehicle, &tsit5).unwrap().t_s.len())
    });
    let kinks = RunOptions {
        locate_kinks: true,
        ..options
    };
    for (name, o) in [("as written", &options), ("kinks located", &kinks)] {
        let (_, stats) = simulate_with_stats(&vehicle, o).unwrap();
        let s = stats.integration;
        println!(
            "60 s gentle ramp, {name}: {} right-hand sides, {} accepted and {} rejected steps, {} restarts",
            s.rhs_evals,
            s.accepted,
            s.rejected,
            stats.restarts.len()
        );
    }
    group.bench_function("class_e_ramp_steer_kinks_sim60s", |b| {
        b.iter(|| simulate(&vehicle, &kinks).unwrap().t_s.len())
    });
    let vehicle = truck_on(&nominal, &terrain, SteerDirection::Left, length).unwrap();
    let rollover = simulate(&vehicle, &options).unwrap().rollover_s.unwrap();
    println!("nominal ramp on class E terrain, seed 1: rollover at {rollover:.2} s");
    group.bench_function("class_e_ramp_to_rollover", |b| {
        b.iter(|| simulate(&vehicle, &options).unwrap().t_s.len())
    });
    group.bench_function("class_e_terrain_and_cache", |b| {
        b.iter(|| {
            let t = rough_terrain(&nominal, &spec, TERRAIN_LENGTH_M, 1).unwrap();
            truck_on(&nominal, &t, SteerDirection::Left, length).unwrap()
        })
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
