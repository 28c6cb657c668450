//! The truck as one ODE system: multibody tree + struts + tires + driver, state
//! `[q (11), v (10), V_sy (6), speed-error integral, path coordinate]`.
//!
//! One right-hand-side evaluation: kinematics of the tree; strut forces in joint space
//! ([`crate::suspension`]); the tires through `tire_fiala::TireAssembly` (linear cornering
//! law): per tire the contact on its side's cached effective track and the normal force of
//! Eq 2.1 (or its frozen piece), then, with the rear drive shared by the rear tires' loads,
//! the lateral force of Eqs 2.5-2.6 from the lagged contact velocity and the lag of
//! Eq 2.7; forces applied at the contact points; forward dynamics (the articulated-body
//! algorithm, `multibody::forward_dynamics_aba`); `qdot` from `v`; the PI integral; the path
//! coordinate `ds/dt = v . h` (h the sprung-mass heading). Nothing allocates.
//!
//! A dynamics failure (a mass matrix that is not positive definite) writes NaN
//! derivatives, which the integrator reports as a divergence with time and state.

use std::cell::{Cell, RefCell};
use std::sync::Arc;

use multibody::Workspace;
use nalgebra::Vector3;
use tire_fiala::{
    EffectiveTrack, Envelope, HandlingLaw, LinearCorneringLaw, LoadDeflectionTable, PathFrame,
    TireAssembly, TireInput, TireTrack, Track, VerticalContact,
};
use vehicle_components::{Component, StateInfo, StateLayout, Terrain};

use crate::driver::{RampSteer, SpeedController, SteerDirection};
use crate::error::{positive, TruckError};
use crate::model::{body, build_tree, TireMount, NQ, NV};
use crate::params::TruckParams;
use crate::statics::Statics;
use crate::suspension::Suspension;
use crate::tires::circle_line_envelope;

/// Offsets of the state blocks: the plain indices of [`truck_states`], fixed at compile
/// time so the right-hand side works on fixed-size arrays.
pub mod state {
    /// Configuration q (11).
    pub const Q: usize = 0;
    /// Velocities v (10).
    pub const V: usize = 11;
    /// Lagged lateral contact velocities V_sy of the six tires (Eq 2.7).
    pub const LAG: usize = 21;
    /// Integral of the speed error (m).
    pub const PI: usize = 27;
    /// Path coordinate of the sprung cg (m).
    pub const PATH: usize = 28;
    /// State dimension.
    pub const DIM: usize = 29;
}

/// The joints after the floating base, in the tree's order ([`crate::model`]): the front
/// carriers' travels, the rear axle's bounce and roll (typical 0.05 m or rad, rates 0.1).
const JOINTS: [[StateInfo; 2]; 4] = [
    [
        StateInfo::new("front_left_carrier_m", "m", 0.05),
        StateInfo::new("front_left_carrier_rate_m_s", "m/s", 0.1),
    ],
    [
        StateInfo::new("front_right_carrier_m", "m", 0.05),
        StateInfo::new("front_right_carrier_rate_m_s", "m/s", 0.1),
    ],
    [
        StateInfo::new("rear_bounce_m", "m", 0.05),
        StateInfo::new("rear_bounce_rate_m_s", "m/s", 0.1),
    ],
    [
        StateInfo::new("rear_roll_rad", "rad", 0.05),
        StateInfo::new("rear_roll_rate_rad_s", "rad/s", 0.1),
    ],
];

/// The truck's state vector as one [`StateLayout`] (module docs; its blocks start at the
/// indices of [`state`]): the floating base of the sprung mass (`vehicle_run::states`, its
/// velocity typical 1 m/s), the joints, each tire's lagged lateral contact velocity of
/// Eq 2.7 (`tire_fiala::relaxation::CONTACT_VELOCITY_LAG_STATE`, in
/// [`crate::model::TIRE_NAMES`] order) and the drive's states. Every state has its name
/// with unit, its unit and the typical magnitude that sets its absolute tolerance.
pub fn truck_states() -> Result<StateLayout, TruckError> {
    let mut l = StateLayout::new();
    l.add("base", &vehicle_run::states::FLOATING_Q)?;
    l.add("", &JOINTS.map(|j| j[0]))?;
    l.add("base", &vehicle_run::states::floating_v(0.1, 1.0))?;
    l.add("", &JOINTS.map(|j| j[1]))?;
    for name in crate::model::TIRE_NAMES {
        l.add(name, &[tire_fiala::relaxation::CONTACT_VELOCITY_LAG_STATE])?;
    }
    l.add("", &vehicle_run::states::DRIVE)?;
    Ok(l)
}

/// How the truck is put on its terrain.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModelOptions {
    /// Ramp direction.
    pub direction: SteerDirection,
    /// Path length the effective tracks cover beyond the start (m).
    pub path_length_m: f64,
    /// Path coordinate of the sprung cg at the start (m), so the rear wheels start on the
    /// profile.
    pub start_s_m: f64,
    /// Grid spacing of the enveloping cache (m).
    pub track_grid_m: f64,
    /// Profile sampling step of the circle-line enveloping (m).
    pub envelope_sample_m: f64,
}

impl Default for ModelOptions {
    fn default() -> Self {
        Self {
            direction: SteerDirection::Left,
            path_length_m: 700.0,
            start_s_m: 5.0,
            track_grid_m: 0.1,
            envelope_sample_m: 0.1,
        }
    }
}

/// Forces and contact quantities of one evaluation.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct TireState {
    /// Normal force F_z (N), Eq 2.1.
    pub normal_force: [f64; 6],
    /// Lateral force F_y (N), Eq 2.5.
    pub lateral_force: [f64; 6],
    /// Rate of each tire's lagged lateral contact velocity (m/s^2), Eq 2.7.
    pub lag_rate: [f64; 6],
    /// Tire deflection (m).
    pub deflection: [f64; 6],
    /// Sum of the horizontal tire forces along the heading's lateral axis (N).
    pub lateral_total: f64,
    /// Drive force (N).
    pub drive_force: f64,
    /// Forward speed of the rear axle centre along the heading (m/s): the controlled speed.
    pub speed: f64,
    /// Speed of the sprung cg along the heading (m/s): the rate of the path coordinate.
    pub path_rate: f64,
    /// The unit vector `[cos psi, sin psi]` of the sprung mass's heading psi: its x axis
    /// projected on the ground.
    pub heading_axis: [f64; 2],
    /// Contact margin of each tire (m), `min(delta, delta + (c_t / k_t) d(delta)/dt)`: the
    /// tire carries load (Eq 2.1 with `delta > 0` and `k_t delta + c_t d(delta)/dt > 0`)
    /// exactly when it is positive. The switching function of lift-off and touchdown.
    pub contact_margin: [f64; 6],
}

/// Which piece of each piecewise force law holds: the bump stops of the four struts and
/// the contact of the six tires. Frozen over an integration step
/// ([`TruckVehicle::freeze`]), each law is smooth; the driver locates where the state
/// leaves the pieces and restarts there (docs/numerics.md, "Kinks").
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Pieces {
    /// Per strut ([`Suspension::compressions`] order): `1` on the compression stop, `-1` on
    /// the extension stop, `0` in free travel ([`crate::suspension::Strut::piece`]).
    pub stops: [i8; 4],
    /// Per tire ([`crate::model::TIRE_NAMES`] order): in contact, `F_z = k_t delta + c_t
    /// d(delta)/dt`; else `F_z = 0`.
    pub contact: [bool; 6],
}

/// Number of switching functions: four struts, six tires.
pub const SWITCHES: usize = 10;

/// How far (m) the state goes beyond the edge of its pieces before the switching functions
/// ([`TruckVehicle::switching`]) cross zero: on the new pieces they then start at least
/// twice this inside, so a crossing located to rounding never leaves the run on an edge
/// where no crossing is seen (a change of about 1e-9 of a 0.1 m travel, 0.01 N of a
/// bump-stop force).
pub const SWITCH_HYSTERESIS_M: f64 = 1e-9;

/// The truck on a terrain, ready to integrate (module docs).
#[derive(Debug)]
pub struct TruckVehicle {
    pub(crate) params: TruckParams,
    pub(crate) suspension: Suspension,
    pub(crate) model: multibody::Model,
    pub(crate) ws: RefCell<Workspace>,
    /// The frozen pieces of the force laws, or `None` for the laws as written.
    pieces: Cell<Option<Pieces>>,
    pub(crate) mounts: [TireMount; 6],
    /// Names, units and typical magnitudes of the states ([`truck_states`]).
    states: StateLayout,
    /// The six tires on the two sides' effective tracks (left, right), linear cornering.
    tires: TireAssembly,
    pub(crate) steer: RampSteer,
    speed: SpeedController,
    pub(crate) options: ModelOptions,
}

fn track_index(m: &TireMount) -> usize {
    usize::from(!m.left)
}

impl TruckVehicle {
    /// The truck of `params` on `terrain`, its left tires on the line `y = +half_width`,
    /// its right tires on `y = -half_width` (for terrain-psd's `TwoTrackTerrain`, half its
    /// track width). Validates the parameters and options and builds the enveloping cache
    /// (the two sides in parallel).
    pub fn new<T: Terrain + Sync>(
        params: &TruckParams,
        terrain: &T,
        half_width: f64,
        options: ModelOptions,
    ) -> Result<Self, TruckError> {
        Self::assemble(params, options, |range, deflection, envelope| {
            let build = |y: f64| {
                EffectiveTrack::build(
                    &Track { terrain, y },
                    range,
                    options.track_grid_m,
                    envelope,
                    deflection,
                )
            };
            // the two sides' caches are independent: built side by side
            let (left, right) = rayon::join(|| build(half_width), || build(-half_width));
            Ok([left?, right?])
        })
    }

    /// [`TruckVehicle::new`] for a run that may stop early (a ramp steer ends at rollover):
    /// each side's enveloping cache is built in order, a chunk at a time, as the run first
    /// reads it (`tire_fiala::EffectiveTrack::on_demand`), the same values to the bit. The
    /// truck holds `terrain` until the caches are built to the end.
    pub fn on_demand<T: Terrain + Send + Sync + 'static>(
        params: &TruckParams,
        terrain: Arc<T>,
        half_width: f64,
        options: ModelOptions,
    ) -> Result<Self, TruckError> {
        Self::assemble(params, options, |range, deflection, envelope| {
            let build = |y: f64| {
                let profile = Track {
                    terrain: Arc::clone(&terrain),
                    y,
                };
                EffectiveTrack::on_demand(
                    profile,
                    range,
                    options.track_grid_m,
                    envelope,
                    deflection,
                )
            };
            Ok([build(half_width)?, build(-half_width)?])
        })
    }

    /// The truck with the left and right caches `tracks(path range, reference deflection,
    /// circle-line envelope)` gives, after the parameters and options are checked.
    fn assemble(
        params: &TruckParams,
        options: ModelOptions,
        tracks: impl FnOnce(
            (f64, f64),
            f64,
            &Envelope,
        ) -> Result<[EffectiveTrack; 2], tire_fiala::TireError>,
    ) -> Result<Self, TruckError> {
        params.validate()?;
        positive("path_length_m", options.path_length_m)?;
        positive("envelope_sample_m", options.envelope_sample_m)?;
        if !options.start_s_m.is_finite() {
            return Err(crate::error::rejected(
                "start_s_m",
                options.start_s_m,
                "must be finite",
            ));
        }
        let (model, mounts) = build_tree(params)?;
        let statics = Statics::of(params);
        let margin = params.wheelbase_m + 2.0 * params.tire_free_radius_m;
        let range = (
            options.start_s_m - margin,
            options.start_s_m + options.path_length_m + margin,
        );
        let deflection = 0.5 * (statics.front_tire_deflection_m + statics.rear_tire_deflection_m);
        let envelope = circle_line_envelope(params.tire_free_radius_m, options.envelope_sample_m)?;
        let tracks = tracks(range, deflection, &envelope)?;
        let tracks: Arc<[TireTrack]> = Arc::new(tracks.map(TireTrack::Static));
        let vertical = VerticalContact::new(
            LoadDeflectionTable::linear(params.tire_vertical_stiffness_n_per_m)?,
            params.tire_vertical_damping_n_s_per_m,
        )?;
        let law = LinearCorneringLaw::new(
            params.cornering_coefficient_per_rad(),
            params.relaxation_length_m,
        )?;
        let tires = TireAssembly::new(
            tracks,
            &mounts.map(|m| track_index(&m)),
            params.tire_free_radius_m,
            vertical,
            HandlingLaw::LinearCornering(law),
        )?;
        let ws = RefCell::new(Workspace::new(&model));
        Ok(Self {
            params: *params,
            suspension: Suspension::new(params),
            model,
            ws,
            pieces: Cell::new(None),
            mounts,
            states: truck_states()?,
            tires,
            steer: RampSteer::new(params, options.direction),
            speed: SpeedController::new(params),
            options,
        })
    }

    /// The parameters.
    pub fn params(&self) -> &TruckParams {
        &self.params
    }

    /// The options.
    pub fn options(&self) -> &ModelOptions {
        &self.options
    }

    /// The multibody tree.
    pub fn tree(&self) -> &multibody::Model {
        &self.model
    }

    /// The struts.
    pub fn suspension(&self) -> &Suspension {
        &self.suspension
    }

    /// The state vector's layout: every state's name, unit and typical magnitude, in
    /// order ([`truck_states`]).
    pub fn state_layout(&self) -> &StateLayout {
        &self.states
    }

    /// Name of state `i` in messages (a collapsing step names its state).
    pub fn state_name(&self, i: usize) -> String {
        vehicle_run::states::state_name(&self.states, i)
    }

    /// The tire mounts, in [`crate::model::TIRE_NAMES`] order.
    pub fn mounts(&self) -> &[TireMount; 6] {
        &self.mounts
    }

    /// The static equilibrium at forward speed `speed` (m/s) along +x: joints at zero, lag
    /// states and the PI integral at rest, path coordinate at the start.
    pub fn initial_state(&self, speed: f64) -> [f64; state::DIM] {
        let mut y = [0.0; state::DIM];
        y[2] = self.params.cg_height_m;
        y[3] = 1.0;
        y[state::V + 3] = speed;
        y[state::PATH] = self.options.start_s_m;
        y
    }

    /// Joint coordinates the struts act on, from a slice of `q` or `v` starting at the
    /// first joint.
    fn strut_joints(x: &[f64]) -> [f64; 4] {
        [x[0], x[1], x[2], x[3]]
    }

    /// Updates the kinematics at `y` and applies all external forces to the workspace;
    /// writes the joint forces into `tau` and returns the tire state. Allocation free.
    pub(crate) fn apply_forces(
        &self,
        t: f64,
        y: &[f64],
        ws: &mut Workspace,
        tau: &mut [f64; NV],
    ) -> Result<TireState, multibody::DynamicsError> {
        let (q, v) = (&y[state::Q..state::Q + NQ], &y[state::V..state::V + NV]);
        multibody::update_kinematics(&self.model, ws, q, v)?;
        let dq = Self::strut_joints(&v[6..]);
        let pieces = self.pieces.get();
        let f = match pieces {
            Some(p) => self
                .suspension
                .forces_on(&Self::strut_joints(&q[7..]), &dq, &p.stops),
            None => self.suspension.forces(&Self::strut_joints(&q[7..]), &dq),
        };
        tau.fill(0.0);
        tau[6..].copy_from_slice(&self.suspension.joint_forces(&f));
        let rot = ws.body_rotation(body::SPRUNG);
        // the heading's unit vector: the body's x axis projected on the ground and
        // normalised (the same as `cos`/`sin` of its `atan2`, without the three calls)
        let norm = (rot[(0, 0)] * rot[(0, 0)] + rot[(1, 0)] * rot[(1, 0)]).sqrt();
        let h = Vector3::new(rot[(0, 0)] / norm, rot[(1, 0)] / norm, 0.0);
        let lat = Vector3::new(-h.y, h.x, 0.0);
        let origin = ws.body_position(body::SPRUNG);
        // The controller reads the drive axle's speed (a wheel-speed signal): the sprung
        // cg's speed includes pitch motion, and a drive force at the ground reacting to it
        // would feed the pitch mode.
        let speed = ws
            .point_velocity(body::REAR_AXLE, &Vector3::zeros())
            .dot(&h);
        let mut out = TireState {
            heading_axis: [h.x, h.y],
            speed,
            path_rate: ws.point_velocity(body::SPRUNG, &Vector3::zeros()).dot(&h),
            drive_force: self.speed.force(speed, y[state::PI]),
            ..TireState::default()
        };
        // wheel headings: the front wheels steered, the rear ones along the heading
        // by angle addition: psi + steer angle
        let (sin_s, cos_s) = self.steer.angle(t).sin_cos();
        let front = (h.y * cos_s + h.x * sin_s, h.x * cos_s - h.y * sin_s);
        let path = PathFrame {
            direction: h,
            origin,
            coordinate: y[state::PATH],
        };
        // the tires' inputs, filled in place: wheel and contact first (the rear tires'
        // loads share the drive), then the drive force
        let mut inputs = [TireInput::default(); 6];
        let mut rear_load = 0.0;
        for (i, (m, input)) in self.mounts.iter().zip(&mut inputs).enumerate() {
            // the effective wheel centre: the column above the hanging point (zero length
            // at the nominal roll centres)
            let w = &mut input.wheel;
            w.centre = ws.point_position(m.body, &m.point);
            w.centre.z += m.column_m;
            w.velocity = ws.point_velocity(m.body, &m.point);
            w.heading = if m.front { front } else { (h.y, h.x) };
            let frozen = pieces.map(|p| p.contact[i]);
            let c = self.tires.contact(i, w, &path, frozen);
            out.contact_margin[i] = self.tires.contact_margin(&c);
            out.normal_force[i] = c.normal_force;
            out.deflection[i] = c.track.deflection;
            if !m.front {
                rear_load += c.normal_force;
            }
            input.contact = c;
        }
        for (i, (m, input)) in self.mounts.iter().zip(&mut inputs).enumerate() {
            // (written so a NaN load gives a NaN share, as the integrator expects)
            if !(m.front || rear_load <= 0.0) {
                input.drive_force = out.drive_force * out.normal_force[i] / rear_load;
            }
            let lag = state::LAG + i;
            let tire = Component::evaluate(
                &self.tires,
                input,
                &y[lag..lag + 1],
                &mut out.lag_rate[i..i + 1],
            );
            // by value: the output's other fields, unused here, then need no memory
            let (force, point) = (tire.force, tire.point);
            ws.apply_force_world(m.body, &force, &point);
            out.lateral_force[i] = tire.contact.fy;
            out.lateral_total += force.dot(&lat);
        }
        Ok(out)
    }

    /// Freeze the pieces of the force laws (`Some`): every evaluation until the next call
    /// uses those pieces, extended linearly beyond their ranges, whatever the state; `None`
    /// restores the laws as written. [`crate::simulate()`] freezes them between the located
    /// kinks (docs/numerics.md, "Kinks").
    pub fn freeze(&self, pieces: Option<Pieces>) {
        self.pieces.set(pieces);
    }

    /// The pieces that hold at `y` under the laws as written, given its tire state.
    pub fn pieces_at(&self, y: &[f64], tires: &TireState) -> Pieces {
        Pieces {
            stops: self
                .suspension
                .pieces(&Self::strut_joints(&y[state::Q + 7..])),
            contact: tires.contact_margin.map(|w| w > 0.0),
        }
    }

    /// The switching functions of `pieces` at `y` (m): per strut the distance of its
    /// compression inside its piece's range ([`crate::suspension::Strut::switching`]), per
    /// tire its contact margin, negated for a tire off the ground, each plus
    /// [`SWITCH_HYSTERESIS_M`]. All are positive while `y` stays inside `pieces`; the
    /// smallest and its index ([`SWITCHES`] order).
    pub fn switching(&self, y: &[f64], tires: &TireState, pieces: &Pieces) -> (f64, usize) {
        let s = self
            .suspension
            .compressions(&Self::strut_joints(&y[state::Q + 7..]));
        let stops = (0..4).map(|i| self.suspension.strut(i).switching(s[i], pieces.stops[i]));
        let tires = (0..6).map(|i| {
            let w = tires.contact_margin[i];
            if pieces.contact[i] {
                w
            } else {
                -w
            }
        });
        stops
            .chain(tires)
            .enumerate()
            .map(|(i, g)| (g + SWITCH_HYSTERESIS_M, i))
            .fold((f64::INFINITY, 0), |a, b| if b.0 < a.0 { b } else { a })
    }

    /// Mechanical energy (J) at state `y`: kinetic + gravitational + strut springs and
    /// bump stops + tire springs (`k_t delta^2 / 2` in contact). Conserved with every
    /// damper off, no drive and no lateral tire force (`tests/energy.rs`).
    pub fn energy(&self, y: &[f64]) -> Result<f64, TruckError> {
        let mut ws = self.ws.borrow_mut();
        let mut tau = [0.0; NV];
        let tires = self
            .apply_forces(0.0, y, &mut ws, &mut tau)
            .map_err(|source| TruckError::Dynamics { t: 0.0, source })?;
        let dynamics = |source| TruckError::Dynamics { t: 0.0, source };
        let kinetic = multibody::kinetic_energy(&self.model, &ws).map_err(dynamics)?;
        let gravity = multibody::potential_energy(&self.model, &ws).map_err(dynamics)?;
        let q = &y[state::Q..state::Q + NQ];
        let struts = self.suspension.energy(&Self::strut_joints(&q[7..]));
        let k = self.params.tire_vertical_stiffness_n_per_m;
        let tire: f64 = tires
            .deflection
            .iter()
            .map(|d| 0.5 * k * d.max(0.0).powi(2))
            .sum();
        Ok(kinetic + gravity + struts + tire)
    }

    /// The rollover margin ([`TruckVehicle::rollover_margin_ws`]) at `y`, from the
    /// kinematics alone (no tire or strut forces).
    pub(crate) fn rollover_margin(&self, y: &[f64]) -> Result<f64, multibody::DynamicsError> {
        let mut ws = self.ws.borrow_mut();
        let (q, v) = (&y[state::Q..state::Q + NQ], &y[state::V..state::V + NV]);
        multibody::update_kinematics(&self.model, &mut ws, q, v)?;
        Ok(self.rollover_margin_ws(&ws))
    }

    /// Signed horizontal distance (m) of the whole-vehicle cg inside the nearer of the two
    /// vertical planes through the outer front and outer rear contact centres of each side:
    /// absolute rollover when it reaches zero (section 2.3, L648). Needs current
    /// kinematics in `ws`.
    pub(crate) fn rollover_margin_ws(&self, ws: &Workspace) -> f64 {
        // The callers have just updated the kinematics, the only failure condition.
        let Ok(cg) = multibody::centre_of_mass(&self.model, ws) else {
            return f64::NAN;
        };
        let side = |front: usize, rear: usize, inward: f64| {
            let f = ws.point_position(self.mounts[front].body, &self.mounts[front].point);
            let r = ws.point_position(self.mounts[rear].body, &self.mounts[rear].point);
            let (dx, dy) = (f.x - r.x, f.y - r.y);
            let len = dx.hypot(dy);
            // inward normal: right of the line for the left side, left for the right side
            let (nx, ny) = (inward * dy / len, -inward * dx / len);
            (cg.x - r.x) * nx + (cg.y - r.y) * ny
        };
        side(0, 2, 1.0).min(side(1, 5, -1.0))
    }
}

impl odeint::OdeSystem for TruckVehicle {
    fn dim(&self) -> usize {
        state::DIM
    }

    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        let mut ws = self.ws.borrow_mut();
        let mut tau = [0.0; NV];
        let Ok(tires) = self.apply_forces(t, y, &mut ws, &mut tau) else {
            dydt.fill(f64::NAN);
            return;
        };
        let Ok(vdot) = multibody::forward_dynamics_aba(&self.model, &mut ws, &tau) else {
            dydt.fill(f64::NAN);
            return;
        };
        dydt[state::V..state::V + NV].copy_from_slice(vdot.as_slice());
        self.model.velocity_to_qdot(
            &y[state::Q..state::Q + NQ],
            &y[state::V..state::V + NV],
            &mut dydt[state::Q..state::Q + NQ],
        );
        dydt[state::LAG..state::LAG + 6].copy_from_slice(&tires.lag_rate);
        dydt[state::PI] = self.speed.error(tires.speed);
        dydt[state::PATH] = tires.path_rate;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_layout_puts_every_block_at_its_offset() {
        let l = truck_states().unwrap();
        assert_eq!(l.len(), state::DIM);
        let at = |name: &str| l.index_of(name).unwrap_or_else(|| panic!("{name}"));
        assert_eq!(at("base_x_m"), state::Q);
        assert_eq!(at("front_left_carrier_m"), state::Q + 7);
        assert_eq!(at("rear_roll_rad"), state::Q + NQ - 1);
        assert_eq!(at("base_roll_rate_rad_s"), state::V);
        assert_eq!(at("rear_roll_rate_rad_s"), state::V + NV - 1);
        assert_eq!(at("front_left_lateral_velocity_lag_m_s"), state::LAG);
        assert_eq!(
            at("rear_right_outer_lateral_velocity_lag_m_s"),
            state::LAG + 5
        );
        assert_eq!(at("speed_error_integral_m"), state::PI);
        assert_eq!(at("path_m"), state::PATH);
        // the absolute tolerances: the sprung mass's velocity at 1 m/s, its rates at 0.1
        assert_eq!(l.typicals()[state::V + 3], 1.0);
        assert_eq!(l.typicals()[state::V], 0.1);
        assert_eq!(l.typicals()[state::Q + 7], 0.05);
    }
}
