//! The vehicle as one ODE system (section 6.2): the multibody tree of [`crate::model`], the
//! strut-space AFS (Eqs 6.6-6.8), the HPS on the front and optionally the rear axle
//! (Eqs 6.9-6.18, [`crate::suspension`]), four Fiala tires (six with the rear bogie,
//! [`crate::bogie`]) with
//! relaxation on cached tandem-cam tracks (Eqs 6.1-6.3, Table 6.2), and the PI drive.
//!
//! State `y = [q, v, AFS (P_c, P_r, theta_h), tire lags (kappa, alpha) x 4 (x 6), front HPS
//! states x 2 (front HPS only), rear HPS states x 2 (rear HPS only), speed-error integral,
//! path coordinate, steering-wheel angle (driver only)]`, laid out in one
//! `StateLayout` from the components' states (module `state_layout`); [`Offsets`] gives
//! the blocks as plain indices.
//!
//! One right-hand-side evaluation, allocation free:
//! 1. kinematics of the tree;
//! 2. strut lengths and rates from the mount points, the AFS flows and strut forces
//!    (`AfsSystem` through `vehicle_components::Component::evaluate`), applied along the
//!    strut axes ([`crate::steering`]);
//! 3. with the HPS, each strut's force from its travel `z_s = z_static + c` (c the carrier
//!    coordinate, positive up = compression; `HpsStrut` through `Component::evaluate`),
//!    acting between its unit and the carrier;
//! 4. per tire (`tire_fiala::TireAssembly` with the Fiala law on the tracks of
//!    [`crate::tires`]): the contact on its effective track, the normal force with damping
//!    (Eq 2.1 form with the nonlinear load curve), the slips and their lags, the Fiala
//!    forces and moments, applied at the contact point;
//! 5. one drive torque for all wheels from the PI law ([`crate::params::DriveParams`]);
//! 6. with the path-following driver ([`VehicleOptions::driver`], section 3.4.1), the
//!    steering-wheel rate `PathDriver::wheel_rate(theta_d, theta)` from the front-axle
//!    centre (the mid-point of the front wheel centres) and the front unit's heading,
//!    mapped into the course frame ([`course_frame`]);
//! 7. forward dynamics (the articulated-body algorithm, `multibody::forward_dynamics_aba`),
//!    `qdot` from `v`.
//!
//! A dynamics failure writes NaN derivatives, which the integrator reports as a divergence
//! with time and state.

use std::cell::RefCell;
use std::sync::Arc;

use afs_hydraulics::{AfsSystem, StrutInput};
use hps_emulsion::HpsStrut;
use multibody::{Model, Workspace};
use nalgebra::Vector3;
use tire_fiala::{
    EnvelopeMethod, FialaLaw, HandlingLaw, LoadDeflectionTable, PathFrame, TireAssembly,
    TireContact, TireInput, VerticalContact, Wheel,
};
use vehicle_components::{Component, Course, PathDriver, StateLayout, SteerInput, Terrain};

use crate::error::{finite, positive, rejected, VehicleError};
use crate::model::{
    body, build_tree, tire_mounts, tire_names, FrontAxle, Layout, TireMount, MAX_TIRES,
};
use crate::params::{Load, VehicleParams};
use crate::state_layout::{add_drive_states, add_tire_states, add_tree_states, STRUT_LABELS};
use crate::statics::Statics;
use crate::steering::{apply_strut_forces, strut_geometry, StrutGeometry};
use crate::suspension::AxleStruts;
use crate::tires::{CamSpacing, TireTracks};

mod energy;
mod rollover;

/// Stiffness of the front-strut end stops beyond the Table 6.3 travel of +-120 mm (N/m).
/// Assumption: 2e8 N/m, with [`END_STOP_DAMPING_N_S_M`]; the dissertation gives no end
/// stops. The stop must hold the rod within the 10 mm oil margin of the rod-side chamber
/// (`StrutParams::front_axle`): a softer 2e7 N/m stop let a top-out of the -30 % A_hc strut
/// of Table 6.4 run 9 mm past the travel, leaving 1 mm of oil, a state so stiff that the D2
/// runs reached the integrator's step limit. 2e8 N/m stops it within 3 mm.
pub const END_STOP_STIFFNESS_N_M: f64 = 2.0e8;

/// Damping of the front-strut end stops while engaged (N s/m).
pub const END_STOP_DAMPING_N_S_M: f64 = 2.0e4;

/// Force of a strut end stop (N, compressive positive) at travel `z` and rate `zdot`
/// beyond `travel`: a linear spring with damping, never pulling.
#[inline]
pub fn end_stop_force(z: f64, zdot: f64, travel: f64) -> f64 {
    let over = z.abs() - travel;
    if over <= 0.0 {
        return 0.0;
    }
    let sign = z.signum();
    let f = END_STOP_STIFFNESS_N_M * over + END_STOP_DAMPING_N_S_M * zdot * sign;
    sign * f.max(0.0)
}

/// The pose of the front-axle centre in the frame of `course` (the yaw-plane driver's:
/// x along the approach, y to the right, heading from x towards y, front axle starting at
/// `course.start()`), from the world position `(x, y)` (y left), the front-axle centre's
/// world x at the start `axle_x0` (its start y is 0) and the front unit's world heading
/// (from x towards the left). Returns `(x_c, y_c, psi_c)`.
#[inline]
pub fn course_frame(
    course: &Course,
    axle_x0: f64,
    x: f64,
    y: f64,
    heading: f64,
) -> (f64, f64, f64) {
    let (x_s, y_s) = course.start();
    (x - axle_x0 + x_s, y_s - y, -heading)
}

/// The unit horizontal direction `(cos ψ, sin ψ, 0)` of a body axis whose world x and y
/// components are `(x, y)` (the axis projected on the ground; ψ its heading), without the
/// angle: `(x, y, 0) / √(x² + y²)`. The axis is a rotation's column, so `x² + y²` is 1 on
/// level ground and near it whenever the body is not standing on end.
#[inline]
fn ground_direction(x: f64, y: f64) -> Vector3<f64> {
    let len = (x * x + y * y).sqrt();
    Vector3::new(x / len, y / len, 0.0)
}

/// Largest state dimension (HPS on both axles with the rear bogie, 70 states, and every
/// strut extension on stay below it).
pub const MAX_DIM: usize = 96;

/// How the vehicle is set up for a run.
#[derive(Debug, Clone, PartialEq)]
pub struct VehicleOptions {
    /// Front axle rigid (the prototype) or on the HPS.
    pub front_axle: FrontAxle,
    /// Steering-wheel angle history (rad, positive = right-hand turn).
    pub steer: SteerInput,
    /// Target speed of the PI drive, also the initial speed (m/s).
    pub speed_m_s: f64,
    /// Path length the effective tracks cover beyond the start (m).
    pub path_length_m: f64,
    /// Path coordinate of the front unit's cg at the start (m).
    pub start_s_m: f64,
    /// Grid spacing of the enveloping cache (m). Default 0.05 m, the terrain's own sample
    /// spacing: a_wz moves 0.3 % when it is halved and 1 % when it is doubled (D1, three
    /// seeds, `docs/vehicle-3d.md`).
    pub track_grid_m: f64,
    /// Profile sampling step of the enveloping (m). Default 0.05 m: 0.02 m changes a_wz by
    /// 0.1 % at 2.5 times the cache cost.
    pub envelope_sample_m: f64,
    /// Enveloping method: tandem cams (section 6.2.2) by default.
    pub envelope: EnvelopeMethod,
    /// Where the tandem cams stand (section 6.2.2, Eqs 6.1-6.3): spaced at the static
    /// deflection (the default) or at the instantaneous one ([`crate::tires::CamSpacing`]).
    pub cam_spacing: CamSpacing,
    /// Lock the rear-unit roll joint (for the yaw-mode analysis): its roll follows the
    /// front unit's.
    pub lock_rear_roll: bool,
    /// Path-following driver of the steering wheel (pure pursuit, section 3.4.1, the
    /// yaw-plane model's `PathDriver`): the steering-wheel angle becomes a state with
    /// `d(theta_sw)/dt = PathDriver::wheel_rate(theta_d, theta)`, starting at 0 with the
    /// front-axle centre at the course start. Needs `steer = SteerInput::None`; the path
    /// change course only (the steady turn's lap bookkeeping needs an unwrapped heading,
    /// which the floating base does not carry).
    pub driver: Option<PathDriver>,
    /// Mechanisms the paper's model lacks (a speed setpoint over time, the HPS strut
    /// extensions): off by default ([`crate::field`]).
    pub field: crate::field::FieldEffects,
}

impl Default for VehicleOptions {
    fn default() -> Self {
        Self {
            front_axle: FrontAxle::Rigid,
            steer: SteerInput::None,
            speed_m_s: 20.0 / 3.6,
            path_length_m: 150.0,
            start_s_m: 10.0,
            track_grid_m: 0.05,
            envelope_sample_m: 0.05,
            envelope: EnvelopeMethod::TandemCams,
            cam_spacing: CamSpacing::Static,
            lock_rear_roll: false,
            driver: None,
            field: crate::field::FieldEffects::default(),
        }
    }
}

/// Offsets of the state blocks (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Offsets {
    /// Configuration q.
    pub q: usize,
    /// Velocities v.
    pub v: usize,
    /// AFS states P_c, P_r, theta_h.
    pub afs: usize,
    /// Tire lags, `(kappa, alpha)` per tire in [`crate::model::TIRE_NAMES`] order.
    pub tires: usize,
    /// Front HPS states, left then right (none without the HPS).
    pub hps: usize,
    /// States per front HPS strut (0 without the HPS).
    pub hps_states: usize,
    /// Rear HPS states, left then right (none without the rear HPS).
    pub rear_hps: usize,
    /// States per rear HPS strut (0 without the rear HPS).
    pub rear_hps_states: usize,
    /// Integral of the speed error (m).
    pub pi: usize,
    /// Path coordinate of the front unit's cg (m).
    pub path: usize,
    /// Steering-wheel angle of the path-following driver (rad; None without a driver).
    pub driver: Option<usize>,
    /// State dimension.
    pub dim: usize,
}

/// Joint coordinate indices in `q` and `v` of the tree.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Joints {
    /// Articulation theta: q and v index.
    pub articulation: (usize, usize),
    /// Rear-unit roll (None when locked).
    pub rear_roll: Option<(usize, usize)>,
    /// Wheel spins, q and v index, per tire; the first [`Joints::tires`] are used
    /// ([`Joints::spins`]).
    pub spin: [(usize, usize); MAX_TIRES],
    /// Number of tires: 4, or 6 with the rear bogie.
    pub tires: usize,
    /// The bogie's beam pitches (rear bogie only), left then right.
    pub beam: Option<[(usize, usize); 2]>,
    /// Front carriers (HPS only), left then right.
    pub carrier: Option<[(usize, usize); 2]>,
    /// Rear carriers (rear HPS only), left then right.
    pub rear_carrier: Option<[(usize, usize); 2]>,
}

impl Joints {
    /// The wheel spins' q and v indices, per tire in [`crate::model::tire_names`] order.
    pub fn spins(&self) -> &[(usize, usize)] {
        &self.spin[..self.tires]
    }
}

/// What one evaluation computes besides the derivatives.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Snapshot {
    /// Per tire in [`crate::model::tire_names`] order; the first
    /// [`Vehicle::tire_mounts`]`.len()` are used (the rest stay at their default).
    pub tires: [TireContact; MAX_TIRES],
    /// Steering-wheel angle (rad).
    pub steer_wheel_rad: f64,
    /// Strut extensions d_L, d_R from l_0 (m).
    pub strut_disp_m: [f64; 2],
    /// Strut forces F_L, F_R (N, positive extending).
    pub strut_force_n: [f64; 2],
    /// P_c, P_r (Pa).
    pub pressure_pa: [f64; 2],
    /// HPS travel z_s, left and right (m, compression positive; 0 without the HPS).
    pub hps_travel_m: [f64; 2],
    /// HPS forces (N, compressive positive; 0 without the HPS).
    pub hps_force_n: [f64; 2],
    /// Rear HPS travel, left and right (m, compression positive; 0 without the rear HPS).
    pub rear_hps_travel_m: [f64; 2],
    /// Rear HPS forces (N, compressive positive; 0 without the rear HPS).
    pub rear_hps_force_n: [f64; 2],
    /// Mean forward speed of the wheel centres (m/s), the controlled speed.
    pub speed_m_s: f64,
    /// Drive torque per wheel (N m).
    pub drive_torque_n_m: f64,
    /// Rate of the path coordinate (m/s).
    pub path_rate_m_s: f64,
    /// Heading of the front unit (rad, from x towards y).
    pub heading_rad: f64,
}

/// The vehicle on a terrain, ready to integrate (module docs).
#[derive(Debug)]
pub struct Vehicle {
    pub(crate) params: VehicleParams,
    pub(crate) load: Load,
    pub(crate) statics: Statics,
    pub(crate) options: VehicleOptions,
    pub(crate) model: Model,
    pub(crate) layout: Layout,
    pub(crate) ws: RefCell<Workspace>,
    /// Names, units and typical magnitudes of the states (module `state_layout`).
    states: StateLayout,
    pub(crate) offsets: Offsets,
    pub(crate) joints: Joints,
    /// The tire mounts ([`crate::model::tire_mounts`]: four, or six with the bogie).
    pub(crate) mounts: &'static [TireMount],
    afs: AfsSystem,
    l0: f64,
    /// The front struts (front HPS only).
    front_struts: Option<AxleStruts>,
    /// The rear struts (rear HPS only).
    rear_struts: Option<AxleStruts>,
    /// Each strut's states: the blocks the Rosenbrock-W method treats implicitly.
    stiff_blocks: Vec<Vec<usize>>,
    /// The tires on their effective tracks, Fiala law, in [`crate::model::tire_names`] order.
    tires: TireAssembly,
    rolling_torque_n_m: f64,
}

impl Vehicle {
    /// The vehicle of `params` with `load` on `terrain`, its left tires on the line
    /// `y = +half_width`, its right tires on `y = -half_width` (for terrain-psd's
    /// `TwoTrackTerrain`, half its track width). Validates everything and builds the
    /// enveloping caches.
    pub fn new<T: Terrain>(
        params: &VehicleParams,
        load: Load,
        options: VehicleOptions,
        terrain: &T,
        half_width: f64,
    ) -> Result<Self, VehicleError> {
        let tracks = TireTracks::build(params, load, &options, terrain, half_width)?;
        Self::on_tracks(params, load, options, Arc::new(tracks))
    }

    /// The vehicle on tracks built before ([`TireTracks::build`]) for the same tire, load
    /// case and path: variants of a design that share the terrain, the tire and the load
    /// (a sensitivity study, an optimisation) build the enveloping cache once.
    pub fn on_tracks(
        params: &VehicleParams,
        load: Load,
        options: VehicleOptions,
        tracks: Arc<TireTracks>,
    ) -> Result<Self, VehicleError> {
        params.validate()?;
        options.steer.validate()?;
        positive("speed_m_s", options.speed_m_s)?;
        positive("path_length_m", options.path_length_m)?;
        positive("track_grid_m", options.track_grid_m)?;
        positive("envelope_sample_m", options.envelope_sample_m)?;
        finite("start_s_m", options.start_s_m)?;
        if let Some(d) = &options.driver {
            d.validate()?;
            if let Course::SteadyTurn { radius_m, .. } = d.course {
                return Err(rejected(
                    "driver",
                    radius_m,
                    "the 3-D vehicle's driver follows the path change course only",
                ));
            }
            if options.steer != SteerInput::None {
                return Err(rejected(
                    "steer",
                    f64::NAN,
                    "must be SteerInput::None when the driver steers",
                ));
            }
        }
        let statics = Statics::of(params, load)?;
        tracks.check(params, &statics, &options)?;
        let (model, layout) = build_tree(
            params,
            load,
            &statics,
            options.front_axle,
            options.lock_rear_roll,
        )?;
        let q_of = |b: usize| model.q_offset(b);
        let v_of = |b: usize| model.v_offset(b);
        let joint = |b: usize| (q_of(b), v_of(b));
        let bogie = params.bogie.is_some();
        let mounts = tire_mounts(bogie);
        let mut spin = [(0, 0); MAX_TIRES];
        for (s, m) in spin.iter_mut().zip(mounts) {
            *s = joint(m.wheel);
        }
        let rear_carriers = if bogie {
            [body::BOGIE_CARRIER_RL, body::BOGIE_CARRIER_RR]
        } else {
            [body::CARRIER_RL, body::CARRIER_RR]
        };
        let joints = Joints {
            articulation: joint(body::HITCH),
            rear_roll: (!options.lock_rear_roll).then(|| joint(body::REAR)),
            spin,
            tires: mounts.len(),
            beam: bogie.then(|| [joint(body::BEAM_RL), joint(body::BEAM_RR)]),
            carrier: match options.front_axle {
                FrontAxle::Rigid => None,
                FrontAxle::Suspended => Some([joint(body::CARRIER_FL), joint(body::CARRIER_FR)]),
            },
            rear_carrier: params.rear_hps.map(|_| rear_carriers.map(joint)),
        };
        let afs = AfsSystem::new(params.steering.clone())?;
        let mut states = StateLayout::new();
        add_tree_states(&mut states, &joints, model.nq(), model.nv())?;
        let afs_at = states.len();
        states.add("steering", Component::states(&afs))?;
        let tires_at = add_tire_states(&mut states, tire_names(bogie))?;
        let hps_at = states.len();
        let front_struts = match joints.carrier {
            None => None,
            Some(c) => Some(AxleStruts::new(
                &params.hps,
                &options.field.hps,
                statics.front_strut_force_n(params),
                c,
                hps_at,
            )?),
        };
        if let Some(a) = &front_struts {
            a.add_states(&mut states, STRUT_LABELS[0])?;
        }
        let rear_at = states.len();
        let rear_struts = match (joints.rear_carrier, &params.rear_hps) {
            (Some(c), Some(strut)) => Some(AxleStruts::new(
                strut,
                &options.field.hps,
                statics.rear_strut_force_n(params),
                c,
                rear_at,
            )?),
            _ => None,
        };
        if let Some(a) = &rear_struts {
            a.add_states(&mut states, STRUT_LABELS[1])?;
        }
        let (pi, driver) = add_drive_states(&mut states, options.driver.is_some())?;
        let offsets = Offsets {
            q: 0,
            v: model.nq(),
            afs: afs_at,
            tires: tires_at,
            hps: hps_at,
            hps_states: front_struts.as_ref().map_or(0, AxleStruts::n_states),
            rear_hps: rear_at,
            rear_hps_states: rear_struts.as_ref().map_or(0, AxleStruts::n_states),
            pi,
            path: pi + 1,
            driver,
            dim: states.len(),
        };
        if offsets.dim > MAX_DIM {
            return Err(rejected("hps", offsets.dim as f64, "too many states"));
        }
        let l0 = afs.initial_strut_length();
        let radius = params.tire.unloaded_radius_m;
        let vertical = VerticalContact::new(
            LoadDeflectionTable::new(&params.tire.load_deflection)?,
            params.tire.vertical_damping_n_s_per_m,
        )?;
        let (mean_load, mean_deflection) = statics.mean_tire_load_and_deflection(params);
        // the rolling-resistance moment of the tires is signed smoothly with the spin
        // (`tires::ROLLING_SIGN_SPEED_M_S`): so is its feed-forward
        let rolling_sign = (options.speed_m_s / tire_fiala::ROLLING_SIGN_SPEED_M_S).tanh();
        let rolling_torque_n_m = rolling_sign
            * params.tire.rolling_resistance_coefficient
            * (radius - mean_deflection)
            * mean_load;
        let track_of: Vec<usize> = mounts.iter().map(TireMount::track).collect();
        let tires = TireAssembly::new(
            tracks.shared(),
            &track_of,
            radius,
            vertical,
            HandlingLaw::Fiala(FialaLaw::new(&params.tire)?),
        )?;
        let ws = RefCell::new(Workspace::new(&model));
        Ok(Self {
            params: params.clone(),
            load,
            statics,
            options,
            model,
            layout,
            ws,
            states,
            offsets,
            joints,
            mounts,
            afs,
            l0,
            front_struts,
            rear_struts,
            stiff_blocks: crate::stiff_block::strut_blocks(&offsets),
            tires,
            rolling_torque_n_m,
        })
    }

    /// The parameters.
    pub fn params(&self) -> &VehicleParams {
        &self.params
    }

    /// The load case.
    pub fn load(&self) -> Load {
        self.load
    }

    /// The hand statics of the load case.
    pub fn statics(&self) -> &Statics {
        &self.statics
    }

    /// The options.
    pub fn options(&self) -> &VehicleOptions {
        &self.options
    }

    /// The multibody tree.
    pub fn tree(&self) -> &Model {
        &self.model
    }

    /// Points of the layout.
    pub fn layout(&self) -> &Layout {
        &self.layout
    }

    /// State block offsets.
    pub fn offsets(&self) -> &Offsets {
        &self.offsets
    }

    /// Joint coordinate indices.
    pub fn joints(&self) -> &Joints {
        &self.joints
    }

    /// The tire mounts in [`crate::model::tire_names`] order: four, or six with the bogie.
    pub fn tire_mounts(&self) -> &'static [TireMount] {
        self.mounts
    }

    /// The state vector's layout: every state's name, unit and typical magnitude, in
    /// order (module `state_layout`).
    pub fn state_layout(&self) -> &StateLayout {
        &self.states
    }

    /// Name of state `i` in messages (a divergence names the state that left): its name
    /// in [`Vehicle::state_layout`], `state i` past its end (a state an extension appends,
    /// [`crate::interconnect`]).
    pub fn state_name(&self, i: usize) -> String {
        vehicle_run::states::state_name(&self.states, i)
    }

    /// Static deflection of the front struts (m, compression positive; 0 without the HPS).
    pub fn hps_static_travel_m(&self) -> f64 {
        self.front_struts
            .as_ref()
            .map_or(0.0, |a| a.static_travel_m)
    }

    /// The front-axle strut (None without the HPS).
    pub fn hps_strut(&self) -> Option<&HpsStrut> {
        self.front_struts.as_ref().map(|a| &a.strut)
    }

    /// The struts of the front and the rear axle, each when suspended.
    pub fn axle_struts(&self) -> [Option<&AxleStruts>; 2] {
        [self.front_struts.as_ref(), self.rear_struts.as_ref()]
    }

    /// The steering hydraulics.
    pub fn steering(&self) -> &AfsSystem {
        &self.afs
    }

    /// The static equilibrium at the target speed: the front unit's cg at its Table 6.1
    /// height, level, moving along +x; wheels rolling without slip; joints at zero; AFS at
    /// its standby pressures; struts at their static travel; PI integral at zero.
    pub fn initial_state(&self) -> Vec<f64> {
        let o = &self.offsets;
        let mut y = vec![0.0; o.dim];
        let speed = self.options.speed_m_s;
        y[2] = self.params.front_unit.cg_height_m;
        y[3] = 1.0;
        y[o.v + 3] = speed;
        let r = self.params.tire.unloaded_radius_m;
        for (i, m) in self.mounts.iter().enumerate() {
            let d = if m.front {
                self.statics.front_tire_deflection_m
            } else {
                self.statics.rear_tire_deflection_m
            };
            y[o.v + self.joints.spin[i].1] = speed / (r - d);
        }
        y[o.afs..o.afs + 3].copy_from_slice(&self.afs.initial_state(0.0));
        for axle in self.axle_struts().into_iter().flatten() {
            axle.initial_state(&mut y);
        }
        y[o.path] = self.options.start_s_m;
        y
    }

    /// Updates the kinematics at `y` and applies all external forces to the workspace;
    /// writes the joint forces into `tau` and the derivatives of the non-mechanical states
    /// into `dydt` (its q and v blocks untouched). Allocation free.
    pub(crate) fn apply_forces(
        &self,
        t: f64,
        y: &[f64],
        ws: &mut Workspace,
        tau: &mut [f64],
        dydt: &mut [f64],
    ) -> Result<Snapshot, multibody::DynamicsError> {
        let o = &self.offsets;
        let (q, v) = (&y[o.q..o.v], &y[o.v..o.afs]);
        multibody::update_kinematics(&self.model, ws, q, v)?;
        tau.fill(0.0);
        let mut snap = Snapshot::default();

        // steering struts (Eqs 6.6-6.8)
        let (g, input) = self.steering_input(t, y, ws);
        let steer = input.steer_wheel;
        let afs = Component::evaluate(
            &self.afs,
            &input,
            &y[o.afs..o.tires],
            &mut dydt[o.afs..o.tires],
        );
        apply_strut_forces(ws, &g, [afs.force_left, afs.force_right]);
        snap.steer_wheel_rad = steer;
        snap.strut_disp_m = [input.disp_left, input.disp_right];
        snap.strut_force_n = [afs.force_left, afs.force_right];
        snap.pressure_pa = [afs.p_c, afs.p_r];

        // axle struts (Eqs 6.9-6.18)
        if let Some(front) = &self.front_struts {
            (snap.hps_travel_m, snap.hps_force_n) = front.apply(y, o.v, tau, dydt);
        }
        if let Some(rear) = &self.rear_struts {
            (snap.rear_hps_travel_m, snap.rear_hps_force_n) = rear.apply(y, o.v, tau, dydt);
        }

        // tires (Eqs 6.1-6.3, Table 6.2) and the drive
        let rot = ws.body_rotation(body::FRONT);
        let heading = rot[(1, 0)].atan2(rot[(0, 0)]);
        let h = ground_direction(rot[(0, 0)], rot[(1, 0)]);
        let path = PathFrame {
            direction: h,
            origin: ws.body_position(body::FRONT),
            coordinate: y[o.path],
        };
        let mut speed = 0.0;
        // 1/4 exactly for four tires (the bits of the four-wheel vehicle)
        let share = 1.0 / self.mounts.len() as f64;
        for (i, m) in self.mounts.iter().enumerate() {
            // the wheel's heading: the carrier's x axis projected on the ground; its axle:
            // the carrier's y axis
            let carrier = ws.body_rotation(m.carrier);
            let along = ground_direction(carrier[(0, 0)], carrier[(1, 0)]);
            let heading = (along.y, along.x);
            let axle = carrier.column(1).into_owned();
            let omega =
                ws.body_rotation(m.wheel) * multibody::spatial::angular(&ws.body_velocity(m.wheel));
            let wheel = Wheel {
                centre: ws.body_position(m.wheel),
                velocity: ws.point_velocity(m.wheel, &Vector3::zeros()),
                heading,
                axle,
                spin: omega.dot(&axle),
            };
            let input = TireInput {
                contact: self.tires.contact(i, &wheel, &path, None),
                wheel,
                drive_force: 0.0,
            };
            let at = o.tires + 2 * i;
            let out =
                Component::evaluate(&self.tires, &input, &y[at..at + 2], &mut dydt[at..at + 2]);
            let (force, point, moment) = (out.force, out.point, out.moment);
            ws.apply_force_world(m.wheel, &force, &point);
            ws.apply_moment_world(m.wheel, &moment);
            speed += share * out.contact.forward_velocity;
            snap.tires[i] = out.contact;
        }
        let d = &self.params.drive;
        let error = self.options.field.target_speed(t, self.options.speed_m_s) - speed;
        let torque =
            (self.rolling_torque_n_m + d.kp_n_m_per_m_s * error + d.ki_n_m_per_m * y[o.pi])
                .clamp(-d.max_torque_n_m, d.max_torque_n_m);
        for &(_, vi) in self.joints.spins() {
            tau[vi] += torque;
        }
        dydt[o.pi] = error;
        let path_rate = ws.point_velocity(body::FRONT, &Vector3::zeros()).dot(&h);
        dydt[o.path] = path_rate;
        if let (Some(driver), Some(i)) = (&self.options.driver, o.driver) {
            let axle = 0.5 * (ws.body_position(body::WHEEL_FL) + ws.body_position(body::WHEEL_FR));
            let p = &self.params;
            let (x, y_c, psi) =
                course_frame(&driver.course, p.front_axle_x_m(), axle.x, axle.y, heading);
            let desired = driver.desired_articulation(
                x,
                y_c,
                psi,
                speed,
                p.front_axle_to_joint_m,
                p.rear_axle_to_joint_m,
            );
            dydt[i] = driver.wheel_rate(desired, y[self.joints.articulation.0]);
        }
        snap.speed_m_s = speed;
        snap.drive_torque_n_m = torque;
        snap.path_rate_m_s = path_rate;
        snap.heading_rad = heading;
        Ok(snap)
    }

    /// The steering struts' geometry at the kinematics of `y` in `ws` and what the steering
    /// hydraulics get from it (Eqs 6.6-6.8): the extensions from `l0`, their rates and the
    /// steering-wheel angle (the driver's state, else the input's at `t`).
    #[inline]
    pub(crate) fn steering_input(
        &self,
        t: f64,
        y: &[f64],
        ws: &Workspace,
    ) -> (StrutGeometry, StrutInput) {
        let g: StrutGeometry = strut_geometry(ws, &self.layout);
        let steer = match self.offsets.driver {
            Some(i) => y[i],
            None => self.options.steer.angle(t),
        };
        let input = StrutInput {
            disp_left: g.length[0] - self.l0,
            disp_right: g.length[1] - self.l0,
            vel_left: g.rate[0],
            vel_right: g.rate[1],
            steer_wheel: steer,
        };
        (g, input)
    }

    /// Full evaluation at `(t, y)`: derivatives into `dydt` and the snapshot. Leaves the
    /// joint accelerations and body accelerations in the workspace for point accelerations.
    pub(crate) fn evaluate(
        &self,
        t: f64,
        y: &[f64],
        ws: &mut Workspace,
        dydt: &mut [f64],
    ) -> Result<Snapshot, multibody::DynamicsError> {
        let o = self.offsets;
        let mut tau = [0.0; MAX_DIM];
        let tau = &mut tau[..self.model.nv()];
        let snap = self.apply_forces(t, y, ws, tau, dydt)?;
        let vdot = multibody::forward_dynamics_aba(&self.model, ws, tau)?;
        dydt[o.v..o.afs].copy_from_slice(vdot.as_slice());
        self.model
            .velocity_to_qdot(&y[o.q..o.v], &y[o.v..o.afs], &mut dydt[o.q..o.v]);
        Ok(snap)
    }
}

impl odeint::OdeSystem for Vehicle {
    fn dim(&self) -> usize {
        self.offsets.dim
    }

    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        let mut ws = self.ws.borrow_mut();
        if self.evaluate(t, y, &mut ws, dydt).is_err() {
            dydt.fill(f64::NAN);
        }
    }

    fn stiff_blocks(&self) -> &[Vec<usize>] {
        &self.stiff_blocks
    }

    fn block_jacobian(&self, _t: f64, y: &[f64], block: usize, jac: &mut [f64]) -> bool {
        self.strut_block_jacobian(y, block, jac)
    }

    fn block_rhs(&self, _t: f64, y: &[f64], block: usize, out: &mut [f64]) -> bool {
        self.strut_block_rates(y, block, out)
    }
}
