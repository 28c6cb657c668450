//! Cost of the Chapter 2 ramp-steer run on class E terrain (section 2.3): the terrain
//! synthesis, the enveloping cache and the run to absolute rollover (at most 60 s of
//! simulated time on 800 m of terrain). `cargo xtask bench` reports the real-time
//! factor (simulated seconds per wall-clock second).

use criterion::{criterion_group, criterion_main, Criterion};
use roll_truck::studies::{rough_terrain, truck_on, TERRAIN_LENGTH_M};
use roll_truck::{simulate, RunOptions, SteerDirection, TruckParams};
use terrain_psd::TwoTrackSpec;

fn bench(c: &mut Criterion) {
    let p = TruckParams::nominal();
    let spec = TwoTrackSpec::paper_nominal();
    let options = RunOptions::default();
    let terrain = rough_terrain(&p, &spec, TERRAIN_LENGTH_M, 1).unwrap();
    let length = p.target_speed_m_s * options.t_end_s * 1.1 + 10.0;
    let mut group = c.benchmark_group("roll_truck");
    group.sample_size(10);
    group.bench_function("class_e_terrain_and_cache", |b| {
        b.iter(|| {
            let t = rough_terrain(&p, &spec, TERRAIN_LENGTH_M, 1).unwrap();
            truck_on(&p, &t, SteerDirection::Left, length).unwrap()
        })
    });
    let vehicle = truck_on(&p, &terrain, SteerDirection::Left, length).unwrap();
    let simulated = *simulate(&vehicle, &options).unwrap().t_s.last().unwrap();
    println!("ramp-steer run on class E terrain: {simulated:.2} s simulated (rollover)");
    group.bench_function("class_e_ramp_steer_run", |b| {
        b.iter(|| simulate(&vehicle, &options).unwrap().t_s.len())
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
