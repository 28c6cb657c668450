//! Work against precision of the explicit pairs on the models' own runs (docs/numerics.md,
//! "Tsitouras 5(4)"): right-hand sides and steps of Dormand-Prince and Tsitouras at 3, 1,
//! 1/3 and 1/10 times the model's default tolerance (and of `Auto`, the 3-D vehicle's
//! default, at it; on the 3-D vehicle also of the additive Runge-Kutta method implicit in
//! the struts' states, docs/numerics.md "ARK4(3)6L\[2\]SA"), and the error against a
//! reference run of Dormand-Prince at rtol 1e-10.
//! Right-hand-side counts do not depend on the machine's load. Not a criterion bench: it
//! prints one table (`cargo bench -p afsv-benches --bench work_precision`; a name filter
//! given to `cargo xtask bench` that does not match `work_precision` skips it).
//!
//! - the Chapter 2 truck, class E, the 60 s gentle ramp steer of `ramp_steer.rs`: the
//!   largest error of roll angle (rad) and rear LTR over the 10 ms samples;
//! - the 3-D vehicle's loaded D1 ride (rigid and nominal HPS, seed 1, the runs of
//!   `design_runs.rs`) and the V3 path change with the HPS: the largest error of any state
//!   over the 5 ms samples, in units of its typical magnitude (the scale of the error norm).
//!   On the HPS ride also the additive method with the front carriers' states (and then the
//!   struts' as well) left out of the error norm: the steps the rest of the vehicle would
//!   take if a multirate method resolved those fast states for free (docs/numerics.md,
//!   "What a multirate method could gain at best").

use odeint::{Atol, Control, Integrator, OdeSystem, Problem, Solver, Stats, Workspace};
use roll_truck::simulate::simulate_with_stats;
use roll_truck::studies::{rough_terrain, truck_on, TERRAIN_LENGTH_M};
use roll_truck::{RunOptions as TruckRun, SteerDirection, TruckParams};
use terrain_psd::TwoTrackSpec;
use vehicle_3d::path_change::PathChangeSpec;
use vehicle_3d::scenarios::{RideSpec, OUTPUT_DT_S};
use vehicle_3d::{FrontAxle, Load, RunOptions, Vehicle, VehicleOptions, VehicleParams};
use vehicle_components::{FlatTerrain, PathDriver};

/// Reference tolerance.
const RTOL_REF: f64 = 1e-10;

/// One run of `vehicle` as `vehicle_3d::simulate` integrates it (its static state, per-state
/// tolerances from the typical magnitudes, its step ceiling), returning the counters and
/// the state at every sample.
fn run_3d(
    vehicle: &Vehicle,
    breakpoints: &[f64],
    t_end: f64,
    solver: Solver,
    rtol: f64,
) -> (Stats, Vec<Vec<f64>>) {
    let typical = vehicle.state_layout().typicals().to_vec();
    run_3d_scaled(vehicle, breakpoints, t_end, solver, rtol, typical)
}

/// [`run_3d`] with the error norm's scales `typical` (one per state).
fn run_3d_scaled(
    vehicle: &Vehicle,
    breakpoints: &[f64],
    t_end: f64,
    solver: Solver,
    rtol: f64,
    typical: Vec<f64>,
) -> (Stats, Vec<Vec<f64>>) {
    let integ = Integrator::new(solver, rtol, Atol::scaled(rtol, typical))
        .with_max_step(RunOptions::default().max_step_s);
    let n = (t_end / OUTPUT_DT_S + 1e-9).floor() as usize;
    let t_out: Vec<f64> = (0..=n).map(|i| i as f64 * OUTPUT_DT_S).collect();
    let y0 = vehicle.initial_state();
    let mut ws = Workspace::new(vehicle.dim());
    let mut states = Vec::with_capacity(t_out.len());
    let stats = integ
        .run(
            vehicle,
            &Problem::new(0.0, &y0, &t_out).with_breakpoints(breakpoints),
            &mut ws,
            |s| {
                states.push(s.y.to_vec());
                Control::Continue
            },
        )
        .expect("run");
    (stats, states)
}

fn case_3d(name: &str, vehicle: &Vehicle, breakpoints: &[f64], t_end: f64) {
    let rtol = RunOptions::default().rtol;
    let typical = vehicle.state_layout().typicals().to_vec();
    let (ref_stats, reference) = run_3d(vehicle, breakpoints, t_end, Solver::Dopri5, RTOL_REF);
    let (_, check) = run_3d(vehicle, breakpoints, t_end, Solver::Tsit5, RTOL_REF);
    // largest and root-mean-square error over samples and states, in typical magnitudes
    let err = |states: &[Vec<f64>]| {
        let (mut e, mut sq, mut n) = (0.0f64, 0.0, 0.0);
        for (y, r) in states.iter().zip(&reference) {
            for i in 0..y.len() {
                let d = (y[i] - r[i]).abs() / typical[i];
                e = e.max(d);
                sq += d * d;
                n += 1.0;
            }
        }
        (e, (sq / n).sqrt())
    };
    println!(
        "{name}: reference Dopri5 rtol {RTOL_REF:e}, {} RHS; Tsit5 at the same rtol differs by {:.1e}",
        ref_stats.rhs_evals,
        err(&check).0
    );
    let ark = [3.0, 1.0, 1.0 / 3.0, 0.1].map(|f| (Solver::Ark436, f));
    for (solver, f) in runs().into_iter().chain(ark) {
        if f != 1.0 && solver == Solver::Auto {
            continue;
        }
        let (st, states) = run_3d(vehicle, breakpoints, t_end, solver, rtol * f);
        assert_eq!(states.len(), reference.len());
        let (e, rms) = err(&states);
        println!(
            "| {name} | {} | {:.1e} | {} | {} / {} | {e:.2e} (rms {rms:.2e}) |",
            solver.name(),
            rtol * f,
            st.rhs_evals,
            st.accepted,
            st.rejected,
        );
    }
    // The fast states out of the norm: a scale far above any value they take
    let names = vehicle.state_layout().names();
    for (fast, label) in [
        (&["carrier"][..], "carriers out of the norm"),
        (
            &["carrier", "hps"][..],
            "carriers and struts out of the norm",
        ),
    ] {
        let scaled: Vec<f64> = typical
            .iter()
            .zip(names)
            .map(|(&t, n)| {
                if fast.iter().any(|f| n.contains(f)) {
                    1e9
                } else {
                    t
                }
            })
            .collect();
        if scaled == typical {
            continue;
        }
        let (st, states) = run_3d_scaled(vehicle, breakpoints, t_end, Solver::Ark436, rtol, scaled);
        let (e, rms) = err(&states);
        println!(
            "| {name} | ark436, {label} | {rtol:.1e} | {} | {} / {} | {e:.2e} (rms {rms:.2e}) |",
            st.rhs_evals, st.accepted, st.rejected,
        );
    }
}

/// Solver and factor on the model's default tolerance of every run.
fn runs() -> Vec<(Solver, f64)> {
    let mut v = Vec::new();
    for f in [3.0, 1.0, 1.0 / 3.0, 0.1] {
        for s in [Solver::Dopri5, Solver::Tsit5] {
            v.push((s, f));
        }
    }
    v.push((Solver::Auto, 1.0));
    v
}

fn truck() {
    let nominal = TruckParams::nominal();
    let mut gentle = nominal;
    gentle.steering_wheel_rate_deg_s = 1.5;
    let spec = TwoTrackSpec::paper_nominal();
    let options = TruckRun::default();
    let terrain = rough_terrain(&nominal, &spec, TERRAIN_LENGTH_M, 1).expect("terrain");
    let length = nominal.target_speed_m_s * options.t_end_s * 1.1 + 10.0;
    let vehicle = truck_on(&gentle, &terrain, SteerDirection::Left, length).expect("truck");
    let run = |solver, rtol| {
        simulate_with_stats(
            &vehicle,
            &TruckRun {
                solver,
                rtol,
                ..options
            },
        )
        .expect("truck run")
    };
    let (reference, ref_stats) = run(Solver::Dopri5, RTOL_REF);
    let err = |rec: &roll_truck::RunRecord| {
        let mut e = (0.0f64, 0.0f64);
        for i in 0..reference.t_s.len() {
            e.0 = e.0.max((rec.roll_rad[i] - reference.roll_rad[i]).abs());
            e.1 = e.1.max((rec.ltr[i] - reference.ltr[i]).abs());
        }
        e
    };
    let (check, _) = run(Solver::Tsit5, RTOL_REF);
    println!(
        "truck: reference Dopri5 rtol {RTOL_REF:e}, {} RHS; Tsit5 at the same rtol differs by {:.1e} rad, {:.1e} LTR",
        ref_stats.integration.rhs_evals,
        err(&check).0,
        err(&check).1
    );
    for (solver, f) in runs() {
        if solver == Solver::Auto {
            continue;
        }
        let (rec, st) = run(solver, options.rtol * f);
        assert_eq!(rec.t_s.len(), reference.t_s.len());
        let (roll, ltr) = err(&rec);
        let s = st.integration;
        println!(
            "| truck class E ramp steer 60 s | {} | {:.1e} | {} | {} / {} | - | roll {roll:.2e} rad, LTR {ltr:.2e} |",
            solver.name(),
            options.rtol * f,
            s.rhs_evals,
            s.accepted,
            s.rejected
        );
    }
}

fn vehicle_3d() {
    let p = VehicleParams::nominal();
    let speed = 20.0 / 3.6;
    let terrain = RideSpec::d1(Load::Loaded, FrontAxle::Rigid)
        .terrain
        .build(&p, 200.0, 1)
        .expect("terrain");
    for (axle, a) in [(FrontAxle::Rigid, "rigid"), (FrontAxle::Suspended, "HPS")] {
        let options = VehicleOptions {
            front_axle: axle,
            speed_m_s: speed,
            path_length_m: 125.0,
            start_s_m: 15.0,
            ..VehicleOptions::default()
        };
        let bp = options.steer.breakpoints();
        let v = Vehicle::new(&p, Load::Loaded, options, &terrain, 0.5 * p.front_track_m)
            .expect("vehicle");
        case_3d(&format!("D1 ride loaded {a}"), &v, &bp, 120.0 / speed);
    }
    let spec = PathChangeSpec::v3(Load::Loaded, FrontAxle::Suspended);
    let speed = spec.speed_kmh / 3.6;
    let options = VehicleOptions {
        front_axle: spec.front_axle,
        speed_m_s: speed,
        driver: Some(PathDriver::new(spec.course())),
        path_length_m: speed * spec.t_end_s + 5.0,
        ..VehicleOptions::default()
    };
    let bp = options.steer.breakpoints();
    let flat = FlatTerrain::new(0.0, vehicle_components::DEFAULT_FRICTION).expect("flat");
    let v = Vehicle::new(&p, spec.load, options, &flat, 0.5 * p.front_track_m).expect("v3");
    case_3d("V3 path change loaded HPS", &v, &bp, spec.t_end_s);
}

fn main() {
    let filters: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with('-'))
        .collect();
    if !filters.is_empty()
        && !filters
            .iter()
            .any(|f| "work_precision".contains(f.as_str()))
    {
        return;
    }
    println!("| run | solver | rtol | RHS calls | accepted / rejected | error |");
    println!("|---|---|---|---|---|---|");
    truck();
    vehicle_3d();
}
