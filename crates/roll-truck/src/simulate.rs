//! A ramp-steer run to absolute rollover (section 2.3): the truck starts at static
//! equilibrium at the target speed, the ramp starts at `ramp_start_s` (a breakpoint), and
//! the run ends at absolute rollover, located as a terminal `odeint` event on the
//! rollover margin (whole-vehicle cg over the plane through the outer contact centres),
//! or at `t_end_s`. [`RunOptions::locate_kinks`] integrates between the kinks of the
//! force laws instead ([`simulate_with_stats`]).

use std::cell::{Cell, RefCell};

use odeint::{Control, Direction, Event, OdeError, Problem, SampleKind, Solver};
use serde::Serialize;
use vehicle_run::{RunSettings, RunSpan};

use crate::error::TruckError;
use crate::model::NV;
use crate::vehicle::{state, Pieces, TireState, TruckVehicle};

/// Largest number of output samples of one run.
pub const MAX_SAMPLES: usize = 1_000_000;

/// Step budget (accepted and rejected) of one run, over all its pieces.
const MAX_STEPS: usize = 1_000_000;

/// Run settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunOptions {
    /// End time if the truck does not roll over (s).
    pub t_end_s: f64,
    /// Output interval (s).
    pub output_dt_s: f64,
    /// Relative tolerance of the integrator.
    pub rtol: f64,
    /// Record the sprung-cg channels ([`RunRecord::sprung_lateral_accel_m_s2`] and the
    /// sensor channel): one forward-dynamics solve per output sample, about a quarter
    /// more run time, so off by default and on for single runs and the truck comparison.
    pub acceleration_channels: bool,
    /// Largest step (s).
    pub max_step_s: f64,
    /// Locate the kinks of the piecewise force laws (bump stops, tire lift-off and
    /// touchdown) as events and restart the integrator there, each law frozen on its piece
    /// in between ([`simulate_with_stats`], docs/numerics.md, "Kinks"). Off by default: the
    /// laws as written, and the step control meets the kinks. Measured on the class E
    /// ramp steer it takes 8 % more right-hand sides at the same accuracy, since few of
    /// the rejected steps come from the kinks (docs/roll-truck.md, "Speed").
    pub locate_kinks: bool,
    /// Integration method. Default [`Solver::Dopri5`] (docs/numerics.md, "Tsitouras 5(4)",
    /// for the comparison with [`Solver::Tsit5`]).
    pub solver: Solver,
}

impl Default for RunOptions {
    fn default() -> Self {
        Self {
            t_end_s: 60.0,
            output_dt_s: 0.01,
            rtol: 1e-4,
            acceleration_channels: false,
            max_step_s: 0.02,
            locate_kinks: false,
            solver: Solver::Dopri5,
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

/// The recorded channels of a run, one entry per output sample (and the rollover instant).
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct RunRecord {
    /// Time (s).
    pub t_s: Vec<f64>,
    /// Road-wheel steering angle (rad).
    pub steer_rad: Vec<f64>,
    /// Forward speed of the rear axle (m/s), the controlled speed.
    pub speed_m_s: Vec<f64>,
    /// Horizontal lateral acceleration of the whole-vehicle cg in the heading frame
    /// (m/s²): the sum of the tire forces' lateral components over the total mass.
    pub lateral_accel_m_s2: Vec<f64>,
    /// LTR of the whole truck (Eq 2.11). With every wheel off the ground there is no load
    /// to transfer: such a sample reads 0 and is marked in [`RunRecord::airborne`].
    pub ltr: Vec<f64>,
    /// Whether every tire is off the ground (a jump on rough terrain).
    pub airborne: Vec<bool>,
    /// Horizontal lateral acceleration of the sprung-mass cg in the heading frame (m/s²):
    /// the kinematic acceleration of that point (forward dynamics at the sample), which
    /// includes the sprung mass's roll motion. Empty unless
    /// [`RunOptions::acceleration_channels`].
    pub sprung_lateral_accel_m_s2: Vec<f64>,
    /// What a lateral accelerometer fixed to the sprung mass at its cg reads (m/s²): the
    /// specific force `a - g` along the sprung body's y axis. Rolled by `phi`, it reads
    /// about `a_y cos(phi) + g sin(phi)`. Empty unless
    /// [`RunOptions::acceleration_channels`].
    pub sprung_sensor_lateral_accel_m_s2: Vec<f64>,
    /// Roll angle of the sprung mass (rad): right-handed about the forward axis, positive
    /// with the left side up.
    pub roll_rad: Vec<f64>,
    /// Rollover margin (m): cg distance inside the outer contact line.
    pub rollover_margin_m: Vec<f64>,
    /// Drive force (N).
    pub drive_force_n: Vec<f64>,
    /// Whether a strut is on its bump stop (any of the four).
    pub on_bump_stop: Vec<bool>,
    /// Tire normal forces (N) in [`crate::model::TIRE_NAMES`] order.
    pub normal_force_n: [Vec<f64>; 6],
    /// Time of absolute rollover (s), if reached.
    pub rollover_s: Option<f64>,
}

/// One output sample from the state `y` at `t`; its tire state.
fn push_sample(
    vehicle: &TruckVehicle,
    t: f64,
    y: &[f64],
    channels: bool,
    rec: &mut RunRecord,
) -> Option<TireState> {
    let mut ws = vehicle.ws.borrow_mut();
    let mut tau = [0.0; NV];
    // The integrator only hands out states at which the right-hand side succeeded (a
    // failure there is a divergence error), so this evaluation succeeds too.
    let tires = vehicle.apply_forces(t, y, &mut ws, &mut tau).ok()?;
    if channels {
        let (sprung, sensor) = sprung_accelerations(vehicle, &mut ws, &tau, tires.heading_axis);
        rec.sprung_lateral_accel_m_s2.push(sprung);
        rec.sprung_sensor_lateral_accel_m_s2.push(sensor);
    }
    let fz = &tires.normal_force;
    let left = [fz[0], fz[2] + fz[3]];
    let right = [fz[1], fz[4] + fz[5]];
    // Eq 2.11 is undefined without load (`perf_measures::roll::ltr` refuses a zero total):
    // an airborne sample transfers none.
    let airborne = fz.iter().all(|&f| f <= 0.0);
    let ltr = perf_measures::roll::ltr(&left, &right).unwrap_or(0.0);
    let rot = ws.body_rotation(crate::model::body::SPRUNG);
    let s = vehicle.suspension.compressions(&[y[7], y[8], y[9], y[10]]);
    let stop = s[..2].iter().any(|&x| vehicle.suspension.front.on_stop(x))
        || s[2..].iter().any(|&x| vehicle.suspension.rear.on_stop(x));
    rec.t_s.push(t);
    rec.steer_rad.push(vehicle.steer.angle(t));
    rec.speed_m_s.push(tires.speed);
    rec.lateral_accel_m_s2
        .push(tires.lateral_total / vehicle.model.total_mass());
    rec.ltr.push(ltr);
    rec.airborne.push(airborne);
    rec.roll_rad.push(rot[(2, 1)].atan2(rot[(2, 2)]));
    rec.rollover_margin_m.push(vehicle.rollover_margin_ws(&ws));
    rec.drive_force_n.push(tires.drive_force);
    rec.on_bump_stop.push(stop);
    for (ch, f) in rec.normal_force_n.iter_mut().zip(fz) {
        ch.push(*f);
    }
    Some(tires)
}

/// The sprung cg's horizontal lateral acceleration in the heading frame and the specific
/// force along the sprung y axis (m/s²), from the forward dynamics (the articulated-body
/// algorithm, as in the right-hand side) at the kinematics and external forces in `ws`
/// (NaN if the dynamics fail).
fn sprung_accelerations(
    vehicle: &TruckVehicle,
    ws: &mut multibody::Workspace,
    tau: &[f64; NV],
    heading_axis: [f64; 2],
) -> (f64, f64) {
    let model = &vehicle.model;
    let mut vdot = [0.0; NV];
    match multibody::forward_dynamics_aba(model, ws, tau) {
        Ok(a) => vdot.copy_from_slice(a.as_slice()),
        Err(_) => return (f64::NAN, f64::NAN),
    }
    if multibody::update_accelerations(model, ws, &vdot).is_err() {
        return (f64::NAN, f64::NAN);
    }
    let sprung = crate::model::body::SPRUNG;
    let a = ws.point_acceleration(sprung, &nalgebra::Vector3::zeros());
    let lat = nalgebra::Vector3::new(-heading_axis[1], heading_axis[0], 0.0);
    let specific = a - model.gravity();
    let body_y = ws.body_rotation(sprung).column(1).into_owned();
    (a.dot(&lat), specific.dot(&body_y))
}

/// One restart of a run at a located kink ([`RunOptions::locate_kinks`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KinkRestart {
    /// Time (s).
    pub t_s: f64,
    /// The switch that crossed ([`crate::vehicle::SWITCHES`] order: struts 0-3, tires
    /// 4-9), or `None` for a restart at an output sample that found the state outside its
    /// pieces (a switch that crossed and came back inside one step).
    pub switch: Option<usize>,
    /// The pieces before the restart.
    pub before: Pieces,
    /// The pieces after it.
    pub after: Pieces,
    /// The state there.
    pub state: [f64; state::DIM],
}

/// The work of one run, summed over its pieces between located kinks.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RunStats {
    /// Right-hand sides, accepted and rejected steps, located events (kinks and rollover).
    pub integration: odeint::Stats,
    /// The restarts at located kinks, in time order (empty without
    /// [`RunOptions::locate_kinks`]).
    pub restarts: Vec<KinkRestart>,
}

/// Integrate `vehicle` from its static state at the target speed (module docs).
pub fn simulate(vehicle: &TruckVehicle, options: &RunOptions) -> Result<RunRecord, TruckError> {
    simulate_with_stats(vehicle, options).map(|(rec, _)| rec)
}

/// Restores the laws as written when a run ends, however it ends.
struct Thaw<'a>(&'a TruckVehicle);

impl Drop for Thaw<'_> {
    fn drop(&mut self) {
        self.0.freeze(None);
    }
}

/// A state `(t, y)` with its tire state and rollover margin.
type Probed = (f64, [f64; state::DIM], TireState, f64);

/// The tire state and rollover margin at `(t, y)`, remembered for the last state: the two
/// event functions and the observer ask for the same state in turn.
struct Probe<'a> {
    vehicle: &'a TruckVehicle,
    last: RefCell<Option<Probed>>,
}

impl Probe<'_> {
    fn at(&self, t: f64, y: &[f64]) -> Result<(TireState, f64), TruckError> {
        if let Some((t0, y0, tires, margin)) = &*self.last.borrow() {
            if *t0 == t && y0[..] == *y {
                return Ok((*tires, *margin));
            }
        }
        let mut ws = self.vehicle.ws.borrow_mut();
        let mut tau = [0.0; NV];
        let tires = self
            .vehicle
            .apply_forces(t, y, &mut ws, &mut tau)
            .map_err(|source| TruckError::Dynamics { t, source })?;
        let margin = self.vehicle.rollover_margin_ws(&ws);
        let mut key = [0.0; state::DIM];
        key.copy_from_slice(y);
        *self.last.borrow_mut() = Some((t, key, tires, margin));
        Ok((tires, margin))
    }
}

/// [`simulate`] with the integrator's work. With [`RunOptions::locate_kinks`] the run is a
/// sequence of integrations, each with the pieces of the force laws frozen
/// ([`TruckVehicle::freeze`]) and a terminal event on the smallest switching function
/// ([`TruckVehicle::switching`]); at its crossing, [`crate::vehicle::SWITCH_HYSTERESIS_M`]
/// beyond the edge, the run restarts on the pieces that hold there, with the mean step of
/// the piece before. The step budget (10⁶) holds for the whole run.
pub fn simulate_with_stats(
    vehicle: &TruckVehicle,
    options: &RunOptions,
) -> Result<(RunRecord, RunStats), TruckError> {
    let n = options.validate()?;
    let _thaw = Thaw(vehicle);
    let span = options.span();
    let t_out = span.output_times(n);
    let probe = Probe {
        vehicle,
        last: RefCell::new(None),
    };
    let pieces = Cell::new(None);
    let switching = |t: f64, y: &[f64]| {
        let (tires, _) = probe.at(t, y).ok()?;
        Some(vehicle.switching(y, &tires, &pieces.get()?))
    };
    // with the kinks located the two events share one evaluation; alone, the margin needs
    // only the kinematics
    let margin = |t: f64, y: &[f64]| {
        let m = if options.locate_kinks {
            probe.at(t, y).map(|(_, m)| m)
        } else {
            vehicle
                .rollover_margin(y)
                .map_err(|source| TruckError::Dynamics { t, source })
        };
        m.unwrap_or(f64::NAN)
    };
    let kink = |t: f64, y: &[f64]| switching(t, y).map_or(f64::NAN, |(g, _)| g);
    let events = [
        Event::new(&margin, Direction::Falling).terminal(),
        Event::new(&kink, Direction::Falling).terminal(),
    ];
    let n_events = if options.locate_kinks { 2 } else { 1 };
    let breakpoints = [vehicle.params.ramp_start_s];
    let typical = vehicle.state_layout().typicals().iter().copied();
    let mut integrator = vehicle_run::integrator(options.solver, &span, typical);
    let mut ws = odeint::Workspace::with_events(state::DIM, 2);
    let mut rec = RunRecord::default();
    let mut stats = RunStats::default();
    let (mut t0, mut y0) = (0.0, vehicle.initial_state(vehicle.params.target_speed_m_s));
    let mut next_out = 0;
    if options.locate_kinks {
        let (tires, _) = probe.at(t0, &y0)?;
        pieces.set(Some(vehicle.pieces_at(&y0, &tires)));
    }
    loop {
        let used = stats.integration.accepted + stats.integration.rejected;
        if used >= MAX_STEPS {
            return Err(OdeError::TooManySteps {
                max_steps: MAX_STEPS,
                t: t0,
                state: y0.to_vec(),
            }
            .into());
        }
        integrator.max_steps = MAX_STEPS - used;
        vehicle.freeze(pieces.get());
        let problem = Problem::new(t0, &y0, &t_out[next_out..])
            .with_breakpoints(&breakpoints)
            .with_events(&events[..n_events]);
        let mut restart = None;
        let mut emitted = 0;
        let mut y_next = [0.0; state::DIM];
        let piece_stats = integrator
            .run(vehicle, &problem, &mut ws, |s| {
                if s.kind == SampleKind::Event(1) {
                    restart = Some((s.t, switching(s.t, s.y).map(|(_, i)| i)));
                    y_next.copy_from_slice(s.y);
                    return Control::Stop;
                }
                let tires = push_sample(vehicle, s.t, s.y, options.acceleration_channels, &mut rec);
                emitted += 1;
                if let SampleKind::Event(_) = s.kind {
                    rec.rollover_s = Some(s.t);
                    return Control::Continue;
                }
                // a switch that crossed and came back inside one step: restart on the pieces
                // that hold here
                let outside = tires
                    .zip(pieces.get())
                    .is_some_and(|(tires, p)| vehicle.switching(s.y, &tires, &p).0 < 0.0);
                if outside {
                    restart = Some((s.t, None));
                    y_next.copy_from_slice(s.y);
                    return Control::Stop;
                }
                Control::Continue
            })
            .map_err(|e| vehicle_run::run_error(e, |i| vehicle.state_name(i)))?;
        add(&mut stats.integration, &piece_stats);
        next_out += emitted;
        let (Some((t, switch)), Some(before)) = (restart, pieces.get()) else {
            return Ok((rec, stats));
        };
        let (tires, _) = probe.at(t, &y_next)?;
        let after = vehicle.pieces_at(&y_next, &tires);
        stats.restarts.push(KinkRestart {
            t_s: t,
            switch,
            before,
            after,
            state: y_next,
        });
        pieces.set(Some(after));
        // the mean step of the piece (its last step ended early at the kink); a piece of
        // one step keeps the starting step it had
        if piece_stats.accepted > 1 {
            let h = (t - t0) / (piece_stats.accepted as f64 - 0.5);
            integrator.first_step = Some(h.min(options.max_step_s));
        }
        t0 = t;
        y0 = y_next;
    }
}

/// `total += piece`, counter by counter.
fn add(total: &mut odeint::Stats, piece: &odeint::Stats) {
    total.rhs_evals += piece.rhs_evals;
    total.accepted += piece.accepted;
    total.rejected += piece.rejected;
    total.events += piece.events;
}

/// Forces and contact quantities of `vehicle` at `(t, y)` (one right-hand-side
/// evaluation's tire state).
pub fn tire_state(
    vehicle: &TruckVehicle,
    t: f64,
    y: &[f64],
) -> Result<crate::vehicle::TireState, TruckError> {
    let mut ws = vehicle.ws.borrow_mut();
    let mut tau = [0.0; NV];
    vehicle
        .apply_forces(t, y, &mut ws, &mut tau)
        .map_err(|source| TruckError::Dynamics { t, source })
}
