//! A run of the vehicle: from the static equilibrium at the target speed, integrated with
//! `odeint` (Dormand-Prince 5(4) on rigid axles, ARK4(3)6L\[2\]SA implicit in the struts'
//! states on suspended ones, per-state absolute tolerances from typical magnitudes,
//! breakpoints at the steering input's kinks), recorded on a uniform output grid. With
//! `stop_at_rollover` the run ends at the rear unit's absolute rollover (L1843, point C),
//! located as a terminal event on [`Vehicle`]'s rollover margin.
//!
//! Signs of the record: world axes x forward, y left, z up; the articulation angle is the
//! paper's theta (positive in a right-hand turn); the front unit's accelerations are in its
//! own body axes (x forward, y left, z up) at the a_wz point; rates and angular
//! accelerations are right-handed about those axes (a left turn has a positive yaw rate).
//! [`crate::channels`] converts them to the `afsv-v1` record convention (docs/records.md).

use odeint::{Control, Direction, Event, OdeSystem, Problem, SampleKind, Solver};
use serde::Serialize;
use vehicle_run::{RunSettings, RunSpan};

use crate::error::{rejected, VehicleError};
use crate::model::body;
use crate::vehicle::{Vehicle, MAX_DIM};

/// Largest number of output samples of one run.
pub const MAX_SAMPLES: usize = 2_000_000;

/// Run settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunOptions {
    /// End time (s).
    pub t_end_s: f64,
    /// Output interval (s).
    pub output_dt_s: f64,
    /// Relative tolerance. Default 3e-5: at 1e-4 the steering pressures overshoot the
    /// cavitation floor after a sharp pulse (to -31 kPa absolute, measured), at 3e-5 they
    /// stay on it (10 kPa).
    pub rtol: f64,
    /// Largest step (s).
    pub max_step_s: f64,
    /// End the run at the rear unit's absolute rollover.
    pub stop_at_rollover: bool,
    /// Integration method. Default [`Solver::Auto`]: Dormand-Prince on a vehicle without
    /// struts, the additive Runge-Kutta method [`Solver::Ark436`] (implicit in each HPS
    /// strut's states) on one with them (docs/numerics.md, "Choosing the method").
    pub solver: Solver,
}

impl Default for RunOptions {
    fn default() -> Self {
        Self {
            t_end_s: 10.0,
            output_dt_s: 0.005,
            rtol: 3e-5,
            max_step_s: 0.03,
            stop_at_rollover: false,
            solver: Solver::Auto,
        }
    }
}

impl RunSettings for RunOptions {
    const MAX_SAMPLES: usize = MAX_SAMPLES;

    fn span(&self) -> RunSpan {
        RunSpan {
            t_end_s: self.t_end_s,
            output_dt_s: self.output_dt_s,
            rtol: self.rtol,
            max_step_s: self.max_step_s,
        }
    }
}

/// The recorded channels of a run (module docs for the signs).
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct RunRecord {
    /// Time (s).
    pub t_s: Vec<f64>,
    /// Steering-wheel angle (rad).
    pub steer_wheel_rad: Vec<f64>,
    /// Mean wheel-centre forward speed (m/s), the controlled speed.
    pub speed_m_s: Vec<f64>,
    /// Articulation angle theta (rad).
    pub articulation_rad: Vec<f64>,
    /// Rear-unit roll relative to the front unit (rad).
    pub rear_roll_rad: Vec<f64>,
    /// Front-unit roll, pitch, yaw rates about its body axes (rad/s).
    pub front_rate_rad_s: [Vec<f64>; 3],
    /// Front-unit angular accelerations about its body axes (rad/s²).
    pub front_angular_accel_rad_s2: [Vec<f64>; 3],
    /// Acceleration of the a_wz point in the front unit's body axes (m/s², kinematic:
    /// gravity not included).
    pub cab_accel_m_s2: [Vec<f64>; 3],
    /// Horizontal lateral acceleration of the front unit's cg (m/s², left positive).
    pub front_lateral_accel_m_s2: Vec<f64>,
    /// Horizontal lateral acceleration of the rear unit's cg with payload, along the rear
    /// unit's horizontal y axis (m/s², left positive).
    pub rear_lateral_accel_m_s2: Vec<f64>,
    /// Load transfer ratio of the rear axle, `(F_zL - F_zR) / (F_zL + F_zR)` (signed; with
    /// the bogie each side's two tires summed).
    pub rear_ltr: Vec<f64>,
    /// Rear-unit rollover margin (m).
    pub rollover_margin_m: Vec<f64>,
    /// Steering-strut extensions d_L, d_R (m).
    pub strut_disp_m: [Vec<f64>; 2],
    /// P_c, P_r (Pa).
    pub pressure_pa: [Vec<f64>; 2],
    /// HPS travel z_s, left and right (m, compression positive).
    pub hps_travel_m: [Vec<f64>; 2],
    /// Rear HPS travel z_s, left and right (m, compression positive; 0 on a rigid rear
    /// axle).
    pub rear_hps_travel_m: [Vec<f64>; 2],
    /// Tire normal forces (N) in [`crate::model::tire_names`] order: four channels, six
    /// with the rear bogie.
    pub normal_force_n: Vec<Vec<f64>>,
    /// Drive torque per wheel (N m).
    pub drive_torque_n_m: Vec<f64>,
    /// Position of the front unit's cg, x and y (m).
    pub position_m: [Vec<f64>; 2],
    /// Position of the front-axle centre (the mid-point of the front wheel centres), x and
    /// y (m): the point the path-following driver steers.
    pub front_axle_m: [Vec<f64>; 2],
    /// Heading of the front unit (rad, from x towards y, wrapped to ±π).
    pub heading_rad: Vec<f64>,
    /// Time of the rear unit's absolute rollover (s), if reached.
    pub rollover_s: Option<f64>,
}

impl RunRecord {
    /// Number of samples.
    pub fn len(&self) -> usize {
        self.t_s.len()
    }

    /// Whether the record is empty.
    pub fn is_empty(&self) -> bool {
        self.t_s.is_empty()
    }
}

/// One output sample from the state `y` at `t`.
fn push_sample(vehicle: &Vehicle, t: f64, y: &[f64], rec: &mut RunRecord) {
    let mut ws = vehicle.ws.borrow_mut();
    let mut dydt = [0.0; MAX_DIM];
    let o = vehicle.offsets;
    // The integrator only hands out states at which the right-hand side succeeded (a
    // failure there is a divergence error), so this evaluation succeeds too.
    let Ok(snap) = vehicle.evaluate(t, y, &mut ws, &mut dydt[..o.dim]) else {
        return;
    };
    if multibody::update_accelerations(&vehicle.model, &mut ws, &dydt[o.v..o.afs]).is_err() {
        return;
    }
    let layout = &vehicle.layout;
    let rot = ws.body_rotation(body::FRONT);
    let cab = rot.transpose() * ws.point_acceleration(body::FRONT, &layout.cab);
    let vel = ws.body_velocity(body::FRONT);
    let angular_accel = multibody::spatial::angular(&ws.body_acceleration(body::FRONT));
    let lateral = |b: usize, point: &nalgebra::Vector3<f64>| {
        let r = ws.body_rotation(b);
        let (x, y) = (r[(0, 0)], r[(1, 0)]);
        let len = x.hypot(y);
        let a = ws.point_acceleration(b, point);
        (-y * a.x + x * a.y) / len
    };
    let front_lat = lateral(body::FRONT, &nalgebra::Vector3::zeros());
    let rear_lat = lateral(body::REAR, &layout.rear_cg);
    let n_tires = vehicle.mounts.len();
    let fz = snap.tires.map(|c| c.normal_force);
    let (mut left, mut right) = (0.0, 0.0);
    for (m, f) in vehicle.mounts.iter().zip(fz) {
        match (m.front, m.left) {
            (false, true) => left += f,
            (false, false) => right += f,
            _ => {}
        }
    }
    let rear_sum = left + right;
    let ltr = if rear_sum > 0.0 {
        (left - right) / rear_sum
    } else {
        0.0
    };
    let j = &vehicle.joints;
    rec.t_s.push(t);
    rec.steer_wheel_rad.push(snap.steer_wheel_rad);
    rec.speed_m_s.push(snap.speed_m_s);
    rec.articulation_rad.push(y[j.articulation.0]);
    rec.rear_roll_rad
        .push(j.rear_roll.map_or(0.0, |(qi, _)| y[qi]));
    for k in 0..3 {
        rec.front_rate_rad_s[k].push(vel[k]);
        rec.front_angular_accel_rad_s2[k].push(angular_accel[k]);
        rec.cab_accel_m_s2[k].push(cab[k]);
    }
    rec.front_lateral_accel_m_s2.push(front_lat);
    rec.rear_lateral_accel_m_s2.push(rear_lat);
    rec.rear_ltr.push(ltr);
    rec.rollover_margin_m
        .push(vehicle.rear_rollover_margin(&ws));
    for k in 0..2 {
        rec.strut_disp_m[k].push(snap.strut_disp_m[k]);
        rec.pressure_pa[k].push(snap.pressure_pa[k]);
        rec.hps_travel_m[k].push(snap.hps_travel_m[k]);
        rec.rear_hps_travel_m[k].push(snap.rear_hps_travel_m[k]);
        rec.position_m[k].push(ws.body_position(body::FRONT)[k]);
        rec.front_axle_m[k].push(
            0.5 * (ws.body_position(body::WHEEL_FL)[k] + ws.body_position(body::WHEEL_FR)[k]),
        );
    }
    rec.heading_rad.push(snap.heading_rad);
    for (ch, f) in rec.normal_force_n.iter_mut().zip(&fz[..n_tires]) {
        ch.push(*f);
    }
    rec.drive_torque_n_m.push(snap.drive_torque_n_m);
}

/// Integrate `vehicle` from its static state at the target speed (module docs).
pub fn simulate(vehicle: &Vehicle, options: &RunOptions) -> Result<RunRecord, VehicleError> {
    options.validate()?;
    let (y0, typical) = initial_run(vehicle)?;
    simulate_system(vehicle, vehicle, &y0, typical, options, |_, _| {})
}

/// The start of a run of `vehicle`: its static state at the target speed (refused when the
/// struts have no static equilibrium) and every state's typical magnitude.
pub(crate) fn initial_run(vehicle: &Vehicle) -> Result<(Vec<f64>, Vec<f64>), VehicleError> {
    let y0 = vehicle.initial_state();
    if y0.iter().any(|v| !v.is_finite()) {
        return Err(rejected(
            "hps",
            f64::NAN,
            "no static equilibrium of the struts",
        ));
    }
    Ok((y0, vehicle.state_layout().typicals().to_vec()))
}

/// Integrate `sys` from `y0` and record it as `vehicle`'s run: `sys` is the vehicle or a
/// system that extends its state with states appended after the vehicle's (a hydraulic
/// interconnection, [`crate::interconnect`]); `typical` holds every state's typical
/// magnitude; `extra` sees the time and the whole state at every recorded sample.
pub(crate) fn simulate_system<S: OdeSystem>(
    vehicle: &Vehicle,
    sys: &S,
    y0: &[f64],
    typical: Vec<f64>,
    options: &RunOptions,
    mut extra: impl FnMut(f64, &[f64]),
) -> Result<RunRecord, VehicleError> {
    let n = options.validate()?;
    let span = options.span();
    let dim = vehicle.offsets.dim;
    let t_out = span.output_times(n);
    let margin = |_t: f64, y: &[f64]| -> f64 { vehicle.rear_rollover_margin_at(y) };
    let events = [Event::new(&margin, Direction::Falling).terminal()];
    let breakpoints = vehicle.options.steer.breakpoints();
    let mut problem = Problem::new(0.0, y0, &t_out).with_breakpoints(&breakpoints);
    if options.stop_at_rollover {
        problem = problem.with_events(&events);
    }
    let integrator = vehicle_run::integrator(options.solver, &span, typical);
    let mut ws = odeint::Workspace::with_events(sys.dim(), 1);
    let mut rec = RunRecord {
        normal_force_n: vec![Vec::new(); vehicle.mounts.len()],
        ..RunRecord::default()
    };
    integrator
        .run(sys, &problem, &mut ws, |s| {
            push_sample(vehicle, s.t, &s.y[..dim], &mut rec);
            extra(s.t, s.y);
            if let SampleKind::Event(_) = s.kind {
                rec.rollover_s = Some(s.t);
            }
            Control::Continue
        })
        .map_err(|e| vehicle_run::run_error(e, |i| vehicle.state_name(i)))?;
    Ok(rec)
}
