//! Simulation entry point: [`simulate`] runs one [`Manoeuvre`] and returns a [`YawRecord`]
//! with the record channels of docs/records.md plus internal states.

use crate::error::DynError;
use crate::yaw_plane::actuator::{SteeringActuator, MAX_ACTUATOR_STATES};
use crate::yaw_plane::driver::PathDriver;
use crate::yaw_plane::mechanics::{kinetic_energy, Motion};
use crate::yaw_plane::model::{SteerSource, YawPlaneModel};
use crate::yaw_plane::params::VehicleParams;
use crate::EquationForm;
use odeint::{Atol, Control, Integrator, OdeError, Problem, Solver, Workspace};
use serde::{Deserialize, Serialize};
use vehicle_components::SteerInput;

/// A constant-speed manoeuvre: forward speed, duration and steering.
#[derive(Debug, Clone, PartialEq)]
pub struct Manoeuvre {
    /// Constant forward speed of the front unit u_f (m/s), >= 0.
    pub speed_m_s: f64,
    /// Simulated time (s).
    pub duration_s: f64,
    /// Steering-wheel source.
    pub steer: SteerSource,
    /// Short label for the record's metadata (e.g. `pulse`).
    pub label: String,
}

impl Manoeuvre {
    /// Open-loop manoeuvre.
    pub fn open_loop(speed_m_s: f64, duration_s: f64, input: SteerInput, label: &str) -> Self {
        Self {
            speed_m_s,
            duration_s,
            steer: SteerSource::Open(input),
            label: label.to_string(),
        }
    }

    /// Section 3.3 pulse test: 0.2 s half-sine of `amplitude_deg` at t = 0.5 s, 10 s long.
    pub fn pulse(speed_m_s: f64, amplitude_deg: f64) -> Self {
        Self::open_loop(
            speed_m_s,
            10.0,
            SteerInput::pulse_deg(amplitude_deg, 0.2, 0.5),
            "pulse",
        )
    }

    /// Section 3.3 step test: step of `amplitude_deg` at t = 0.5 s, 10 s long.
    pub fn step(speed_m_s: f64, amplitude_deg: f64) -> Self {
        Self::open_loop(
            speed_m_s,
            10.0,
            SteerInput::step_deg(amplitude_deg, 0.5),
            "step",
        )
    }

    /// Closed-loop course with the default driver.
    pub fn course(speed_m_s: f64, duration_s: f64, driver: PathDriver, label: &str) -> Self {
        Self {
            speed_m_s,
            duration_s,
            steer: SteerSource::Driver(driver),
            label: label.to_string(),
        }
    }

    /// Check the numbers.
    pub fn validate(&self) -> Result<(), DynError> {
        if !(self.speed_m_s.is_finite() && self.speed_m_s >= 0.0) {
            return Err(DynError::InvalidInput(format!(
                "speed must be finite and >= 0, got {} m/s",
                self.speed_m_s
            )));
        }
        if !(self.duration_s.is_finite() && self.duration_s > 0.0) {
            return Err(DynError::InvalidInput(format!(
                "duration must be positive, got {} s",
                self.duration_s
            )));
        }
        match &self.steer {
            SteerSource::Open(i) => i.validate()?,
            SteerSource::Driver(d) => d.validate()?,
        }
        Ok(())
    }

    fn breakpoints(&self) -> Vec<f64> {
        match &self.steer {
            SteerSource::Open(i) => i.breakpoints(),
            SteerSource::Driver(_) => Vec::new(),
        }
    }
}

/// Numerical and modelling options of a run.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SimOptions {
    /// Integration method: [`Solver::Dopri5`] by default (chosen by measurement,
    /// docs/afs-yaw-plane.md); [`Solver::Auto`] also picks Dopri5 (the model is not stiff).
    pub solver: Solver,
    /// Relative tolerance (adaptive methods).
    pub rtol: f64,
    /// Absolute tolerance per typical magnitude: state `i` gets
    /// `atol * YawPlaneModel::state_typical(i)` (1 for states in rad, m/s, m; 1 MPa for the
    /// chamber pressures, which are integrated in Pa).
    pub atol: f64,
    /// Largest step (s) of the adaptive methods.
    pub max_step_s: f64,
    /// Output sample interval (s).
    pub output_dt_s: f64,
    /// Equation form of Eq 3.13.
    pub form: EquationForm,
    /// A run whose articulation exceeds this magnitude (deg) is reported as diverged
    /// (jackknife / snaking instability).
    pub max_articulation_deg: f64,
    /// Initial articulation angle (rad).
    pub initial_articulation_rad: f64,
    /// Record the energy channels (`kinetic_energy_j`, `actuator_energy_j`). With entrained
    /// air the stored hydraulic energy is a quadrature per output sample, 100x the cost of
    /// the integration itself; fits that only compare measured channels switch it off.
    /// When off, both channels are empty and left out of [`YawRecord::columns`].
    #[serde(default = "record_energy_default")]
    pub record_energy: bool,
    /// Which channels the run records ([`Recording::Full`] by default).
    #[serde(default)]
    pub recording: Recording,
}

/// Which channels a run records. The integration, its output grid and its divergence
/// checks are the same in every mode: a channel recorded in two modes has the same values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Recording {
    /// Every channel of [`YawRecord`] and every state.
    #[default]
    Full,
    /// Only the channels the section 3.3 measures read (the decay fit of the pulse run, the
    /// step metrics and the Eq 4.7 efficiency of the step run): `time_s`,
    /// `articulation_deg`, `articulation_rate_deg_s`, `steering_torque_nm`,
    /// `q_supply_m3_s` and `supply_pressure_pa`, on the full output grid. Each sample
    /// evaluates the actuator alone (no tire forces, no accelerations); every other
    /// channel, the energy channels (whatever [`SimOptions::record_energy`] says) and
    /// [`YawRecord::states`] stay empty.
    Measures,
}

fn record_energy_default() -> bool {
    true
}

impl Default for SimOptions {
    fn default() -> Self {
        Self {
            solver: Solver::Dopri5,
            rtol: 1e-5,
            atol: 1e-6,
            max_step_s: 0.05,
            output_dt_s: 0.005,
            form: EquationForm::EnergyConsistent,
            max_articulation_deg: 60.0,
            initial_articulation_rad: 0.0,
            record_energy: true,
            recording: Recording::Full,
        }
    }
}

impl SimOptions {
    /// Check the numbers.
    pub fn validate(&self) -> Result<(), DynError> {
        for (name, v) in [
            ("rtol", self.rtol),
            ("atol", self.atol),
            ("max_step_s", self.max_step_s),
            ("output_dt_s", self.output_dt_s),
            ("max_articulation_deg", self.max_articulation_deg),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Err(DynError::InvalidInput(format!(
                    "option `{name}` must be positive and finite, got {v}"
                )));
            }
        }
        if let Solver::Rk4 { step } = self.solver {
            if !(step.is_finite() && step > 0.0) {
                return Err(DynError::InvalidInput(format!(
                    "option `solver.rk4.step` must be positive and finite, got {step}"
                )));
            }
        }
        if !self.initial_articulation_rad.is_finite() {
            return Err(DynError::InvalidInput(
                "option `initial_articulation_rad` must be finite".into(),
            ));
        }
        Ok(())
    }
}

/// Solver counters of a run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct SolverStats {
    /// Right-hand-side evaluations (excluding output evaluation).
    pub rhs_evals: usize,
    /// Accepted steps.
    pub accepted: usize,
    /// Rejected steps.
    pub rejected: usize,
}

/// Time histories of one run. The first eight columns are the record channels of
/// docs/records.md (sign convention: positive = right-hand turn); the rest are internal.
/// A channel the run's [`Recording`] mode leaves out is empty.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct YawRecord {
    /// Time (s).
    pub time_s: Vec<f64>,
    /// Steering-wheel angle (deg).
    pub steer_wheel_deg: Vec<f64>,
    /// Forward speed of the front unit (m/s).
    pub speed_m_s: Vec<f64>,
    /// Articulation angle (deg).
    pub articulation_deg: Vec<f64>,
    /// Left-strut displacement, positive extending (m).
    pub strut_left_disp_m: Vec<f64>,
    /// P_c chamber-group pressure (Pa, absolute).
    pub p_c_pa: Vec<f64>,
    /// P_r chamber-group pressure (Pa, absolute).
    pub p_r_pa: Vec<f64>,
    /// Front-unit yaw rate (deg/s).
    pub yaw_rate_front_deg_s: Vec<f64>,
    /// Rear-unit yaw rate (deg/s).
    pub yaw_rate_rear_deg_s: Vec<f64>,
    /// Articulation rate (deg/s).
    pub articulation_rate_deg_s: Vec<f64>,
    /// Front-cg lateral velocity (m/s).
    pub lateral_velocity_front_m_s: Vec<f64>,
    /// Front-cg lateral acceleration (m/s^2).
    pub lateral_accel_front_m_s2: Vec<f64>,
    /// Rear-cg lateral acceleration (m/s^2).
    pub lateral_accel_rear_m_s2: Vec<f64>,
    /// Ground x of the front cg (m).
    pub x_m: Vec<f64>,
    /// Ground y of the front cg, to the right (m).
    pub y_m: Vec<f64>,
    /// Front-unit heading (deg).
    pub heading_front_deg: Vec<f64>,
    /// Mean front slip angle (deg).
    pub slip_front_deg: Vec<f64>,
    /// Mean rear slip angle (deg).
    pub slip_rear_deg: Vec<f64>,
    /// Steering torque about the joint (N m).
    pub steering_torque_nm: Vec<f64>,
    /// Supply flow into the struts (m^3/s).
    pub q_supply_m3_s: Vec<f64>,
    /// Supply power P_s q (W).
    pub supply_power_w: Vec<f64>,
    /// Longitudinal force holding u_f constant (N).
    pub traction_force_n: Vec<f64>,
    /// Kinetic energy of both units (J); empty unless [`SimOptions::record_energy`].
    pub kinetic_energy_j: Vec<f64>,
    /// Energy stored in the actuator (J); empty unless [`SimOptions::record_energy`].
    pub actuator_energy_j: Vec<f64>,
    /// Every integrated state in SI units, `(name, values)`; see [`crate::yaw_plane::model`] for
    /// the layout.
    pub states: Vec<(String, Vec<f64>)>,
    /// Solver counters.
    pub stats: SolverStats,
    /// Supply pressure at the valve (Pa), for the efficiency of Eq 4.7.
    pub supply_pressure_pa: Vec<f64>,
}

impl YawRecord {
    /// All recorded scalar channels in record order, `(column name, values)`; internal
    /// states follow with a `state_` prefix. Channels the run did not record (empty) are
    /// left out.
    pub fn columns(&self) -> Vec<(String, &[f64])> {
        let mut c: Vec<(String, &[f64])> = vec![
            ("time_s".into(), &self.time_s),
            ("steer_wheel_deg".into(), &self.steer_wheel_deg),
            ("speed_m_s".into(), &self.speed_m_s),
            ("articulation_deg".into(), &self.articulation_deg),
            ("strut_left_disp_m".into(), &self.strut_left_disp_m),
            ("p_c_pa".into(), &self.p_c_pa),
            ("p_r_pa".into(), &self.p_r_pa),
            ("yaw_rate_front_deg_s".into(), &self.yaw_rate_front_deg_s),
            ("yaw_rate_rear_deg_s".into(), &self.yaw_rate_rear_deg_s),
            (
                "articulation_rate_deg_s".into(),
                &self.articulation_rate_deg_s,
            ),
            (
                "lateral_velocity_front_m_s".into(),
                &self.lateral_velocity_front_m_s,
            ),
            (
                "lateral_accel_front_m_s2".into(),
                &self.lateral_accel_front_m_s2,
            ),
            (
                "lateral_accel_rear_m_s2".into(),
                &self.lateral_accel_rear_m_s2,
            ),
            ("x_m".into(), &self.x_m),
            ("y_m".into(), &self.y_m),
            ("heading_front_deg".into(), &self.heading_front_deg),
            ("slip_front_deg".into(), &self.slip_front_deg),
            ("slip_rear_deg".into(), &self.slip_rear_deg),
            ("steering_torque_nm".into(), &self.steering_torque_nm),
            ("q_supply_m3_s".into(), &self.q_supply_m3_s),
            ("supply_power_w".into(), &self.supply_power_w),
            ("supply_pressure_pa".into(), &self.supply_pressure_pa),
            ("traction_force_n".into(), &self.traction_force_n),
            ("kinetic_energy_j".into(), &self.kinetic_energy_j),
            ("actuator_energy_j".into(), &self.actuator_energy_j),
        ];
        for (name, v) in &self.states {
            c.push((format!("state_{name}"), v.as_slice()));
        }
        c.retain(|(_, v)| !v.is_empty());
        c
    }

    /// The channels `recording` fills, each with room for `n` samples, so that a run
    /// allocates nothing per output sample.
    fn reserve(&mut self, recording: Recording, record_energy: bool, n: usize) {
        let measures = [
            &mut self.time_s,
            &mut self.articulation_deg,
            &mut self.articulation_rate_deg_s,
            &mut self.steering_torque_nm,
            &mut self.q_supply_m3_s,
            &mut self.supply_pressure_pa,
        ];
        measures.into_iter().for_each(|v| v.reserve_exact(n));
        if recording == Recording::Measures {
            return;
        }
        let rest = [
            &mut self.steer_wheel_deg,
            &mut self.speed_m_s,
            &mut self.strut_left_disp_m,
            &mut self.p_c_pa,
            &mut self.p_r_pa,
            &mut self.yaw_rate_front_deg_s,
            &mut self.yaw_rate_rear_deg_s,
            &mut self.lateral_velocity_front_m_s,
            &mut self.lateral_accel_front_m_s2,
            &mut self.lateral_accel_rear_m_s2,
            &mut self.x_m,
            &mut self.y_m,
            &mut self.heading_front_deg,
            &mut self.slip_front_deg,
            &mut self.slip_rear_deg,
            &mut self.traction_force_n,
        ];
        rest.into_iter().for_each(|v| v.reserve_exact(n));
        if record_energy {
            self.kinetic_energy_j.reserve_exact(n);
            self.actuator_energy_j.reserve_exact(n);
        }
    }

    /// Articulation angle in rad.
    pub fn articulation_rad(&self) -> Vec<f64> {
        self.articulation_deg
            .iter()
            .map(|d| d.to_radians())
            .collect()
    }

    /// Articulation rate in rad/s.
    pub fn articulation_rate_rad_s(&self) -> Vec<f64> {
        self.articulation_rate_deg_s
            .iter()
            .map(|d| d.to_radians())
            .collect()
    }
}

fn describe_state(names: &[String], y: &[f64]) -> String {
    names
        .iter()
        .zip(y)
        .map(|(n, v)| format!("{n}={v:.6e}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Most output samples (`duration_s / output_dt_s`) one [`simulate`] run produces.
pub const MAX_OUTPUT_SAMPLES: f64 = 1e6;

/// Run one manoeuvre of the yaw-plane vehicle with the given articulation actuator
/// (normally [`afs_hydraulics::AfsSystem`]).
///
/// The integrator is restarted at every kink or jump of the steering input (pulse start
/// and end, step time) so that no step straddles it. A solver failure, a non-finite state
/// or an articulation beyond `options.max_articulation_deg` returns
/// [`DynError::Diverged`] with the time and the named state.
pub fn simulate<A: SteeringActuator>(
    vehicle: &VehicleParams,
    actuator: &A,
    manoeuvre: &Manoeuvre,
    options: &SimOptions,
) -> Result<YawRecord, DynError> {
    vehicle.validate()?;
    manoeuvre.validate()?;
    options.validate()?;
    if actuator.n_states() > MAX_ACTUATOR_STATES {
        return Err(DynError::InvalidInput(format!(
            "actuator has {} states, at most {MAX_ACTUATOR_STATES} supported",
            actuator.n_states()
        )));
    }
    let model = YawPlaneModel::new(
        vehicle,
        actuator,
        manoeuvre.speed_m_s,
        &manoeuvre.steer,
        options.form,
    );
    let names = model.state_names();
    let layout = model.layout();
    let samples = manoeuvre.duration_s / options.output_dt_s;
    if samples.is_nan() || samples > MAX_OUTPUT_SAMPLES {
        return Err(DynError::InvalidInput(format!(
            "`duration_s` / `output_dt_s` = {samples:e} output samples, at most {MAX_OUTPUT_SAMPLES:e}"
        )));
    }
    let grid = odeint::output_grid(0.0, manoeuvre.duration_s, options.output_dt_s);
    let t_end = *grid.last().expect("grid has t0");
    let mut cuts: Vec<f64> = manoeuvre
        .breakpoints()
        .into_iter()
        .filter(|&b| b > 0.0 && b < t_end)
        .collect();
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();

    let mut rec = YawRecord::default();
    let n_out = grid.len();
    let full = options.recording == Recording::Full;
    rec.reserve(options.recording, options.record_energy, n_out);
    let n_states = if full { layout.dim } else { 0 };
    let mut states: Vec<Vec<f64>> = vec![Vec::with_capacity(n_out); n_states];
    let mut scratch = vec![0.0; layout.dim];
    let max_theta = options.max_articulation_deg.to_radians();

    let y0 = model.initial_state(options.initial_articulation_rad);
    let mut failure: Option<DynError> = None;
    let observe = |s: odeint::Sample<'_>| -> Control {
        let (t, y) = (s.t, s.y);
        if y[0].abs() > max_theta || !y.iter().all(|v| v.is_finite()) {
            failure = Some(DynError::Diverged {
                t,
                reason: format!(
                    "articulation {:.2} deg beyond the {:.0} deg bound (jackknife/snaking) or non-finite state",
                    y[0].to_degrees(),
                    options.max_articulation_deg
                ),
                state: describe_state(&names, y),
            });
            return Control::Stop;
        }
        if !full {
            record_measures(&mut rec, &model, t, y, &mut scratch);
            return Control::Continue;
        }
        let e = model.evaluate(t, y, &mut scratch);
        let m = Motion {
            theta: y[0],
            u_f: manoeuvre.speed_m_s,
            v_f: y[1],
            r_f: y[2],
            r_r: y[3],
        };
        rec.time_s.push(t);
        rec.steer_wheel_deg.push(e.steer_wheel.to_degrees());
        rec.speed_m_s.push(manoeuvre.speed_m_s);
        rec.articulation_deg.push(y[0].to_degrees());
        rec.strut_left_disp_m.push(e.actuator.strut_left_disp);
        rec.p_c_pa.push(e.actuator.p_c);
        rec.p_r_pa.push(e.actuator.p_r);
        rec.yaw_rate_front_deg_s.push(y[2].to_degrees());
        rec.yaw_rate_rear_deg_s.push(y[3].to_degrees());
        rec.articulation_rate_deg_s.push(e.theta_dot.to_degrees());
        rec.lateral_velocity_front_m_s.push(y[1]);
        rec.lateral_accel_front_m_s2.push(e.acc.a_y_front);
        rec.lateral_accel_rear_m_s2.push(e.acc.a_y_rear);
        rec.x_m.push(y[4]);
        rec.y_m.push(y[5]);
        rec.heading_front_deg.push(y[6].to_degrees());
        rec.slip_front_deg
            .push((0.5 * (e.alpha[0] + e.alpha[1])).to_degrees());
        rec.slip_rear_deg
            .push((0.5 * (e.alpha[2] + e.alpha[3])).to_degrees());
        rec.steering_torque_nm.push(e.actuator.torque);
        rec.q_supply_m3_s.push(e.actuator.q_supply);
        rec.supply_power_w.push(e.actuator.supply_power);
        rec.supply_pressure_pa.push(e.actuator.supply_pressure);
        rec.traction_force_n.push(e.acc.traction_force);
        if options.record_energy {
            rec.kinetic_energy_j.push(kinetic_energy(vehicle, &m));
            rec.actuator_energy_j.push(model.actuator.energy(
                y[0],
                e.steer_wheel,
                &y[model.actuator_range()],
            ));
        }
        for (i, s) in states.iter_mut().enumerate() {
            s.push(y[i]);
        }
        Control::Continue
    };
    let problem = Problem::new(0.0, &y0, &grid).with_breakpoints(&cuts);
    let atol = Atol::scaled(
        options.atol,
        (0..layout.dim).map(|i| model.state_typical(i)),
    );
    let res = Integrator::new(options.solver, options.rtol, atol)
        .with_max_step(options.max_step_s)
        .run(&model, &problem, &mut Workspace::new(layout.dim), observe);
    if let Some(f) = failure.take() {
        return Err(f);
    }
    let stats = match res {
        Ok(s) => SolverStats {
            rhs_evals: s.rhs_evals,
            accepted: s.accepted,
            rejected: s.rejected,
        },
        Err(e) => return Err(map_ode_error(e, &names)),
    };
    rec.stats = stats;
    if full {
        rec.states = names.into_iter().zip(states).collect();
    }
    Ok(rec)
}

/// One output sample of [`Recording::Measures`]: the articulation and, from the actuator
/// alone, the Eq 4.7 channels. The actuator sees the same (theta, theta_dot, steering-wheel
/// angle, actuator states) as in [`YawPlaneModel::evaluate`], so its outputs are those of
/// a full record.
fn record_measures<A: SteeringActuator>(
    rec: &mut YawRecord,
    model: &YawPlaneModel<'_, A>,
    t: f64,
    y: &[f64],
    scratch: &mut [f64],
) {
    let theta_dot = y[2] - y[3];
    let act = model.actuator_range();
    let out = model.actuator.evaluate(
        y[0],
        theta_dot,
        model.steer_wheel(t, y),
        &y[act.clone()],
        &mut scratch[act],
    );
    rec.time_s.push(t);
    rec.articulation_deg.push(y[0].to_degrees());
    rec.articulation_rate_deg_s.push(theta_dot.to_degrees());
    rec.steering_torque_nm.push(out.torque);
    rec.q_supply_m3_s.push(out.q_supply);
    rec.supply_pressure_pa.push(out.supply_pressure);
}

fn map_ode_error(e: OdeError, names: &[String]) -> DynError {
    match e {
        OdeError::Diverged { t, h, state } => DynError::Diverged {
            t,
            reason: format!(
                "integrator step size collapsed (h = {h:.3e} s) or state became non-finite"
            ),
            state: describe_state(names, &state),
        },
        OdeError::TooManySteps {
            max_steps,
            t,
            state,
        } => DynError::Diverged {
            t,
            reason: format!("step limit of {max_steps} reached"),
            state: describe_state(names, &state),
        },
        OdeError::StepSizeCollapsed {
            t,
            h,
            projected_steps,
            dominant_state,
            state,
            ..
        } => DynError::Diverged {
            t,
            reason: format!(
                "step size collapsed (h = {h:.3e} s, about {projected_steps:.1e} steps to finish); state `{}` dominates the error: it is stiff or its parameters are absurd",
                names.get(dominant_state).map_or("?", String::as_str)
            ),
            state: describe_state(names, &state),
        },
        OdeError::InvalidInput(m) => DynError::InvalidInput(m),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::yaw_plane::analysis::{measures_for, MeasureSpec};
    use crate::yaw_plane::driver::{Course, PathDriver};
    use crate::yaw_plane::params::{Load, YawPlaneParams};
    use proptest::prelude::*;

    /// Run `man` in both modes; the measures-only record must hold exactly the full
    /// record's values in its six channels and nothing else.
    fn assert_same_channels(p: &YawPlaneParams, man: &Manoeuvre, form: EquationForm) {
        let sys = p.afs_system().unwrap();
        let full_opts = SimOptions {
            form,
            ..SimOptions::default()
        };
        let only_opts = SimOptions {
            recording: Recording::Measures,
            ..full_opts
        };
        let full = simulate(&p.vehicle, &sys, man, &full_opts).unwrap();
        let only = simulate(&p.vehicle, &sys, man, &only_opts).unwrap();
        assert_eq!(only.stats, full.stats);
        let kept = [
            "time_s",
            "articulation_deg",
            "articulation_rate_deg_s",
            "steering_torque_nm",
            "q_supply_m3_s",
            "supply_pressure_pa",
        ];
        let got = only.columns();
        let names: Vec<&str> = got.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(names, kept);
        assert!(only.states.is_empty() && only.kinetic_energy_j.is_empty());
        let all = full.columns();
        for (name, values) in got {
            let (_, want) = all.iter().find(|(n, _)| *n == name).unwrap();
            assert_eq!(values, *want, "{name}");
        }
        // The whole output grid, not a truncated run.
        assert!(only.time_s.len() as f64 >= man.duration_s / full_opts.output_dt_s);
    }

    #[test]
    fn measures_only_channels_equal_the_full_record_open_loop_and_with_the_driver() {
        let loaded = YawPlaneParams::nominal(Load::Loaded);
        let unloaded = YawPlaneParams::nominal(Load::Unloaded);
        let form = EquationForm::EnergyConsistent;
        assert_same_channels(&loaded, &Manoeuvre::pulse(50.0 / 3.6, 30.0), form);
        assert_same_channels(&unloaded, &Manoeuvre::step(30.0 / 3.6, -20.0), form);
        assert_same_channels(
            &loaded,
            &Manoeuvre::step(50.0 / 3.6, 30.0),
            EquationForm::PaperEq313,
        );
        // Closed loop: the steering-wheel angle is a state of the driver.
        let driver = PathDriver::new(Course::steady_turn_fig_3_6());
        let turn = Manoeuvre::course(15.0 / 3.6, 8.0, driver, "steady_turn");
        assert_same_channels(&loaded, &turn, form);
    }

    /// Every number of two measure sets agrees to `rel` relative.
    fn assert_close(a: &serde_json::Value, b: &serde_json::Value, rel: f64) {
        let (a, b) = (a.as_object().unwrap(), b.as_object().unwrap());
        assert_eq!(a.len(), b.len());
        for (k, va) in a {
            match (va.as_f64(), b[k].as_f64()) {
                (Some(x), Some(y)) => {
                    assert!(x.is_finite(), "{k} = {x}");
                    assert!(
                        (x - y).abs() <= rel * x.abs().max(y.abs()),
                        "{k}: {x} vs {y}"
                    );
                }
                _ => assert_eq!(va, &b[k], "{k}"),
            }
        }
    }

    #[test]
    fn measures_from_the_measures_only_record_equal_those_of_the_full_record() {
        for load in Load::ALL {
            let p = YawPlaneParams::nominal(load);
            let mut spec = MeasureSpec::default();
            let full = measures_for(&p.vehicle, &p.afs, Some(load), 40.0 / 3.6, &spec).unwrap();
            spec.options.recording = Recording::Measures;
            let only = measures_for(&p.vehicle, &p.afs, Some(load), 40.0 / 3.6, &spec).unwrap();
            let (full, only) = (
                serde_json::to_value(full).unwrap(),
                serde_json::to_value(only).unwrap(),
            );
            assert_close(&full, &only, 1e-12);
        }
    }

    #[test]
    fn recording_defaults_to_full_in_option_files() {
        let mut v = serde_json::to_value(SimOptions::default()).unwrap();
        assert_eq!(v["recording"], "full");
        v.as_object_mut().unwrap().remove("recording");
        let back: SimOptions = serde_json::from_value(v).unwrap();
        assert_eq!(back.recording, Recording::Full);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(12))]
        #[test]
        fn measures_only_channels_equal_the_full_record_for_any_pulse(
            speed_kmh in 5.0f64..60.0,
            peak_deg in -60.0f64..60.0,
            start_s in 0.0f64..2.0,
        ) {
            let man = Manoeuvre::open_loop(
                speed_kmh / 3.6,
                4.0,
                SteerInput::pulse_deg(peak_deg, 0.2, start_s),
                "pulse",
            );
            let p = YawPlaneParams::nominal(Load::Loaded);
            assert_same_channels(&p, &man, EquationForm::EnergyConsistent);
        }
    }
}
