//! Cost of the Chapter 6 design runs (section 6.4); `cargo xtask bench` prints their
//! real-time factors from the `_sim..s` suffixes.
//!
//! - `d1_ride_{rigid,hps}_{loaded,unloaded}_sim21p6s`: D1, 120 m (20 m run-in + 100 m) of
//!   class E terrain at 20 km/h, seed 1, the terrain and enveloping cache built outside;
//! - `d3_yaw_pulse_rigid_sim5s`: D3, the 0.2 s pulse at 50 km/h on smooth ground;
//! - `d1_ride_hps_loaded_ros34pw2_sim21p6s`: the same HPS run with the Rosenbrock-W method
//!   on the struts' stiff blocks instead of Dormand-Prince (docs/numerics.md);
//! - `d1_ride_hps_loaded_dopri5_sim21p6s`: the same run explicit in every state
//!   (Dormand-Prince) instead of `Auto`'s additive Runge-Kutta method, implicit in the
//!   struts' states (docs/numerics.md, "ARK4(3)6L\[2\]SA");
//! - `d1_ride_{rigid,hps}_loaded_tsit5_sim21p6s`: the loaded runs with Tsitouras 5(4) in
//!   place of `Auto` (Dormand-Prince on the rigid axle, the additive Runge-Kutta method on
//!   the HPS; docs/numerics.md, "Tsitouras 5(4)");
//! - `rhs_{rigid,hps}`: one right-hand-side evaluation;
//! - `d1_terrain_and_cache`: synthesis of the terrain and the four tandem-cam caches, paid
//!   once per seed;
//! - `v3_path_change_{rigid,hps}_loaded_sim20s`: V3, the path change of section 6.3 with the
//!   pure-pursuit driver, smooth ground, 15.3 km/h, 20 s (`scenarios::path_change`, what
//!   `afsv vehicle path-change` runs), flat-ground caches included.

use criterion::{criterion_group, criterion_main, Criterion};
use odeint::OdeSystem;
use vehicle_3d::scenarios::{path_change, PathChangeSpec, RideSpec, OUTPUT_DT_S};
use vehicle_3d::{simulate, FrontAxle, Load, RunOptions, Vehicle, VehicleOptions, VehicleParams};
use vehicle_components::FlatTerrain;
use vehicle_components::SteerInput;

fn bench(c: &mut Criterion) {
    let p = VehicleParams::nominal();
    let speed = 20.0 / 3.6;
    let terrain = RideSpec::d1(Load::Loaded, FrontAxle::Rigid)
        .terrain
        .build(&p, 200.0, 1)
        .unwrap();
    let ride = |load, axle| {
        let options = VehicleOptions {
            front_axle: axle,
            speed_m_s: speed,
            path_length_m: 125.0,
            start_s_m: 15.0,
            ..VehicleOptions::default()
        };
        Vehicle::new(&p, load, options, &terrain, 0.5 * p.front_track_m).unwrap()
    };
    let run = RunOptions {
        t_end_s: 120.0 / speed,
        output_dt_s: OUTPUT_DT_S,
        ..RunOptions::default()
    };
    let mut group = c.benchmark_group("vehicle_3d");
    group.sample_size(10);
    for (axle, a) in [(FrontAxle::Rigid, "rigid"), (FrontAxle::Suspended, "hps")] {
        for (load, l) in [(Load::Loaded, "loaded"), (Load::Unloaded, "unloaded")] {
            let v = ride(load, axle);
            group.bench_function(format!("d1_ride_{a}_{l}_sim21p6s"), |b| {
                b.iter(|| simulate(&v, &run).unwrap().len())
            });
        }
        let v = ride(Load::Loaded, axle);
        let t = RunOptions {
            solver: odeint::Solver::Tsit5,
            ..run
        };
        group.bench_function(format!("d1_ride_{a}_loaded_tsit5_sim21p6s"), |b| {
            b.iter(|| simulate(&v, &t).unwrap().len())
        });
        if axle == FrontAxle::Suspended {
            let w = RunOptions {
                solver: odeint::Solver::Ros34pw2,
                ..run
            };
            group.bench_function("d1_ride_hps_loaded_ros34pw2_sim21p6s", |b| {
                b.iter(|| simulate(&v, &w).unwrap().len())
            });
            let explicit = RunOptions {
                solver: odeint::Solver::Dopri5,
                ..run
            };
            group.bench_function("d1_ride_hps_loaded_dopri5_sim21p6s", |b| {
                b.iter(|| simulate(&v, &explicit).unwrap().len())
            });
        }
        let y = v.initial_state();
        let mut d = vec![0.0; y.len()];
        group.bench_function(format!("rhs_{a}"), |b| {
            b.iter(|| {
                v.rhs(0.0, &y, &mut d);
                d[0]
            })
        });
    }
    let flat = FlatTerrain::new(0.0, vehicle_components::DEFAULT_FRICTION).unwrap();
    let options = VehicleOptions {
        speed_m_s: 50.0 / 3.6,
        steer: SteerInput::pulse_deg(30.0, 0.2, 1.0),
        path_length_m: 80.0,
        ..VehicleOptions::default()
    };
    let yaw = Vehicle::new(&p, Load::Loaded, options, &flat, 0.5 * p.front_track_m).unwrap();
    let pulse = RunOptions {
        t_end_s: 5.0,
        output_dt_s: OUTPUT_DT_S,
        ..RunOptions::default()
    };
    group.bench_function("d3_yaw_pulse_rigid_sim5s", |b| {
        b.iter(|| simulate(&yaw, &pulse).unwrap().len())
    });
    for (axle, a) in [(FrontAxle::Rigid, "rigid"), (FrontAxle::Suspended, "hps")] {
        let spec = PathChangeSpec::v3(Load::Loaded, axle);
        group.bench_function(format!("v3_path_change_{a}_loaded_sim20s"), |b| {
            b.iter(|| path_change(&p, &spec, 1).unwrap().0.len())
        });
    }
    group.bench_function("d1_terrain_and_cache", |b| {
        b.iter(|| {
            let t = RideSpec::d1(Load::Loaded, FrontAxle::Rigid)
                .terrain
                .build(&p, 200.0, 1)
                .unwrap();
            let options = VehicleOptions {
                speed_m_s: speed,
                path_length_m: 125.0,
                start_s_m: 15.0,
                ..VehicleOptions::default()
            };
            Vehicle::new(&p, Load::Loaded, options, &t, 0.5 * p.front_track_m).unwrap()
        })
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
