//! The tires of a multibody vehicle as one component: their enveloping caches along the
//! tracks, the vertical contact with lift-off and a handling law with its slip lag. Both
//! multibody vehicles use it, the Chapter 2 truck (`roll-truck`, six tires, linear
//! cornering) and the Chapter 6 vehicle (`vehicle-3d`, four or six tires, Fiala).
//!
//! The vehicle keeps its kinematics and hands each tire, in world axes (x forward, y left,
//! z up): the effective wheel centre `c`, the velocity `v` the slips take, the wheel
//! heading `psi_w` as `(sin, cos)` (the vehicle's own rule: the truck's by angle addition,
//! the 3-D vehicle's from `atan2`), the axle direction and spin (Fiala law), and the path
//! frame: the horizontal unit direction `h` of the path coordinate, the point where it is
//! `s_0`, and `s_0`. Per tire, in two steps:
//!
//! 1. [`TireAssembly::contact`]: the path coordinate `s = s_0 + (c - origin) . h`; the
//!    contact on the tire's cached track ([`TireTrack`]: circle-line Eqs 2.2-2.4 or tandem
//!    cams Eqs 6.1-6.3, at a reference or the instantaneous deflection), penetration
//!    `delta` and slope `theta` of the effective line P1P2; the contact normal
//!    `n = -sin(theta) h + cos(theta) z`; the deflection rate
//!    `delta' = (v . h) sin theta - v_z cos theta`; the normal force of Eq 2.1,
//!    `F_n = F_el(delta) + c_t delta' >= 0`, zero out of contact ([`VerticalContact`]), or
//!    with the pieces frozen over an integration step (the truck's kinks,
//!    docs/numerics.md), the in-contact piece `k_0 delta + c_t delta'` (`k_0` the load
//!    curve's first slope, Eq 2.1's `k_t` for a linear spring) or zero;
//! 2. [`Component::evaluate`] ([`TireInput`]): wheel axes `e_x = (cos psi_w, sin psi_w, 0)`,
//!    `e_y = (-sin psi_w, cos psi_w, 0)`, velocities `v_x = v . e_x`, `v_y = v . e_y`, the
//!    regularised speed `u = |v_x|_eff` ([`regularised_speed`]), the loaded radius
//!    `R_l = R - max(delta, 0)` and the contact point `c - R_l n`; then the handling law
//!    ([`HandlingLaw`]):
//!    - linear cornering (Chapter 2, Eqs 2.5-2.7): `F_y = -k F_n atan(V_sy / u)` from the
//!      lagged lateral contact velocity `V_sy` (the state), `d(V_sy)/dt = (v_y - V_sy) u /
//!      sigma_y` (Eq 2.7); the longitudinal force is the drive force the vehicle shares out
//!      ([`TireInput::drive_force`]; the truck's wheels do not spin, note 1.2); the force
//!      `F = F_n n + F_y e_y + F_x t` with the lateral force horizontal and
//!      `t = (cos theta e_x, sin theta)`; no moment;
//!    - Fiala (section 6.2.2): steady slips `kappa_s = (omega R_l - v_x) / u`,
//!      `alpha_s = -atan(v_y / u)` (Eq 3.17), the lagged slips `[kappa, alpha]` (the states)
//!      with `d/dt = (steady - lagged) u / sigma` (Eq 3.16), Fiala forces from `F_n` and the
//!      lagged slips; the force `F = F_x t + F_y l + F_n n` with `t` the unit projection of
//!      `e_x` on the contact plane and `l = n x t`; the moment `M_z n` (aligning) plus the
//!      rolling-resistance moment about the axle, signed with the spin
//!      (`tanh(omega R / ROLLING_SIGN_SPEED_M_S)`, smooth through standstill).
//!
//! The vehicle applies the force at the point and the moment to the wheel's body. The
//! contact frame tilts with the in-plane slope only (the enveloping is single-track); the
//! cross slope does not tilt it. Nothing allocates: the tracks are shared (`Arc`), the
//! tire-to-track map is a fixed-capacity array.

use std::sync::Arc;

use arrayvec::ArrayVec;
use nalgebra::Vector3;
use vehicle_components::{ChannelInfo, Component, StateInfo};

use crate::effective_track::{TireTrack, TrackContact};
use crate::error::{positive, TireError};
use crate::fiala::Fiala;
use crate::model::HandlingModel;
use crate::params::TireParams;
use crate::relaxation::{
    contact_velocity_lag_rate, lag_rate, regularised_speed, Relaxation, CONTACT_VELOCITY_LAG_STATE,
    SLIP_LAG_STATES,
};
use crate::vertical::VerticalContact;

/// Largest number of tires of one assembly.
pub const MAX_TIRES: usize = 8;

/// Speed (m/s) over which the rolling-resistance moment of the Fiala law changes sign at
/// standstill: the moment is signed with `tanh(omega R / ROLLING_SIGN_SPEED_M_S)`.
pub const ROLLING_SIGN_SPEED_M_S: f64 = 0.1;

/// The lag state of the linear cornering law, one per tire.
const CONTACT_VELOCITY_LAG_STATES: [StateInfo; 1] = [CONTACT_VELOCITY_LAG_STATE];

/// Chapter 2's lateral law (Eqs 2.5-2.7): cornering stiffness linear in the load,
/// `k_ty = coefficient F_n`, and the lateral contact velocity lagged over `sigma_y`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearCorneringLaw {
    coefficient_per_rad: f64,
    relaxation_length_m: f64,
}

impl LinearCorneringLaw {
    /// The coefficient `k_ty / F_z` (1/rad, > 0; the line through the Table 2.3 point) and
    /// the lateral relaxation length `sigma_y` (m, > 0).
    pub fn new(coefficient_per_rad: f64, relaxation_length_m: f64) -> Result<Self, TireError> {
        Ok(Self {
            coefficient_per_rad: positive("cornering_coefficient_per_rad", coefficient_per_rad)?,
            relaxation_length_m: positive("relaxation_length_m", relaxation_length_m)?,
        })
    }

    /// Lateral force of Eqs 2.5-2.6, `F_y = -k_ty(F_z) alpha` with `alpha = atan(V_sy / u)`,
    /// `u` the regularised forward speed: zero for `F_z = 0`, linear in `F_z` of either
    /// sign (a tire frozen in contact past its lift-off keeps a smooth law).
    #[inline]
    pub fn lateral_force(&self, normal_force: f64, v_sy: f64, regularised_speed: f64) -> f64 {
        let alpha = (v_sy / regularised_speed).atan();
        -self.coefficient_per_rad * normal_force * alpha
    }
}

/// Chapter 6's handling (section 6.2.2): Fiala forces and moments from the lagged slips
/// (Eqs 3.16-3.17, Table 6.2).
#[derive(Debug, Clone, PartialEq)]
pub struct FialaLaw {
    model: Fiala,
    relaxation: Relaxation,
}

impl FialaLaw {
    /// From a validated tire parameter set (its Fiala set and relaxation lengths).
    pub fn new(params: &TireParams) -> Result<Self, TireError> {
        Ok(Self {
            model: Fiala::new(params)?,
            relaxation: Relaxation::from_params(params)?,
        })
    }

    /// The Fiala model.
    pub fn model(&self) -> &Fiala {
        &self.model
    }
}

/// How a tire's contact turns into handling forces (module docs).
#[derive(Debug, Clone, PartialEq)]
pub enum HandlingLaw {
    /// Chapter 2: linear cornering, lagged lateral contact velocity, a given drive force.
    LinearCornering(LinearCorneringLaw),
    /// Chapter 6: Fiala with lagged slips, aligning and rolling-resistance moments.
    Fiala(FialaLaw),
}

/// The path coordinate's frame: `s = coordinate + (c - origin) . direction`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PathFrame {
    /// Horizontal unit direction `h` of the path at the vehicle.
    pub direction: Vector3<f64>,
    /// The point whose path coordinate is `coordinate` (m, world).
    pub origin: Vector3<f64>,
    /// Path coordinate of `origin` (m).
    pub coordinate: f64,
}

/// One wheel's kinematics, as the vehicle computes them (world axes, SI).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Wheel {
    /// Effective wheel centre (m): its path coordinate and height set the contact, the
    /// force acts one loaded radius below it along the contact normal.
    pub centre: Vector3<f64>,
    /// Velocity (m/s) whose components the deflection rate and the slips take.
    pub velocity: Vector3<f64>,
    /// `(sin psi_w, cos psi_w)` of the wheel heading psi_w (from x towards y).
    pub heading: (f64, f64),
    /// Axle direction (unit), the rolling-resistance moment's axis (Fiala law).
    pub axle: Vector3<f64>,
    /// Spin omega about the axle (rad/s), positive rolling forward (Fiala law; the
    /// Chapter 2 truck's wheels do not spin).
    pub spin: f64,
}

/// A tire's contact at one instant: step 1 of the module docs.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Contact {
    /// Penetration and slope of the effective line from the tire's track.
    pub track: TrackContact,
    /// Contact normal `n = -sin(theta) h + cos(theta) z`.
    pub normal: Vector3<f64>,
    /// Deflection rate `delta'` (m/s) with the effective line held fixed.
    pub deflection_rate: f64,
    /// Normal force F_n (N), Eq 2.1 (or its frozen piece).
    pub normal_force: f64,
}

/// What the handling step takes: the wheel, its contact and the drive.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct TireInput {
    /// The wheel's kinematics.
    pub wheel: Wheel,
    /// Its contact ([`TireAssembly::contact`]).
    pub contact: Contact,
    /// Longitudinal force at the contact (N) of the linear cornering law: the drive force's
    /// share of this tire. The Fiala law takes F_x from the slip ratio (its drive is a
    /// torque on the wheel) and does not read it.
    pub drive_force: f64,
}

/// Contact quantities of one tire, for records and measures.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct TireContact {
    /// Normal force F_n (N).
    pub normal_force: f64,
    /// Penetration delta (m), positive in contact.
    pub deflection: f64,
    /// Slope theta of the effective line (rad).
    pub slope: f64,
    /// Forward velocity of the wheel v_x (m/s).
    pub forward_velocity: f64,
    /// Lateral velocity of the wheel v_y (m/s).
    pub lateral_velocity: f64,
    /// Steady-state slips `[kappa_s, alpha_s]` of Eq 3.17 (Fiala law; zero under linear
    /// cornering, which lags the lateral velocity instead).
    pub slip_steady: [f64; 2],
    /// Longitudinal force F_x (N).
    pub fx: f64,
    /// Lateral force F_y (N).
    pub fy: f64,
    /// Wheel spin omega (rad/s).
    pub spin: f64,
}

/// Force and moment of one tire in world axes, with its contact quantities.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TireOutput {
    /// Force on the wheel (N).
    pub force: Vector3<f64>,
    /// Where it acts (m): one loaded radius below the centre along the contact normal.
    pub point: Vector3<f64>,
    /// Moment on the wheel (N m): aligning plus rolling resistance (zero under linear
    /// cornering).
    pub moment: Vector3<f64>,
    /// Contact quantities.
    pub contact: TireContact,
}

const CHANNELS: [ChannelInfo; 8] = [
    ChannelInfo::new("force_x_n", "N"),
    ChannelInfo::new("force_y_n", "N"),
    ChannelInfo::new("force_z_n", "N"),
    ChannelInfo::new("normal_force_n", "N"),
    ChannelInfo::new("deflection_m", "m"),
    ChannelInfo::new("longitudinal_force_n", "N"),
    ChannelInfo::new("lateral_force_n", "N"),
    ChannelInfo::new("lateral_velocity_m_s", "m/s"),
];

/// The tires of one vehicle (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct TireAssembly {
    tracks: Arc<[TireTrack]>,
    track_of: ArrayVec<usize, MAX_TIRES>,
    radius: f64,
    vertical: VerticalContact,
    /// The in-contact piece `[k_0, c_t]` of the frozen vertical law.
    piece: [f64; 2],
    /// `c_t / k_0`, the contact margin's time constant.
    damping_over_stiffness: f64,
    law: HandlingLaw,
}

impl TireAssembly {
    /// The tires reading `tracks` (shared with other assemblies on the same ground), tire
    /// `i` on track `track_of[i]` (at most [`MAX_TIRES`] tires, every index naming a track),
    /// free radius `radius_m` (m, > 0), vertical law `vertical` and handling law `law`.
    pub fn new(
        tracks: Arc<[TireTrack]>,
        track_of: &[usize],
        radius_m: f64,
        vertical: VerticalContact,
        law: HandlingLaw,
    ) -> Result<Self, TireError> {
        if track_of.is_empty() || track_of.len() > MAX_TIRES {
            return Err(TireError::InvalidParameter {
                field: "track_of",
                value: track_of.len() as f64,
                reason: "must give 1 to MAX_TIRES (8) tires",
            });
        }
        if let Some(&bad) = track_of.iter().find(|&&t| t >= tracks.len()) {
            return Err(TireError::InvalidParameter {
                field: "track_of",
                value: bad as f64,
                reason: "names no track",
            });
        }
        let stiffness = vertical.load_deflection().stiffness(0.0);
        let damping = vertical.damping();
        Ok(Self {
            tracks,
            track_of: track_of.iter().copied().collect(),
            radius: positive("unloaded_radius_m", radius_m)?,
            vertical,
            piece: [stiffness, damping],
            damping_over_stiffness: damping / stiffness,
            law,
        })
    }

    /// Number of tires.
    pub fn len(&self) -> usize {
        self.track_of.len()
    }

    /// Whether there are no tires (never, for a validated assembly).
    pub fn is_empty(&self) -> bool {
        self.track_of.is_empty()
    }

    /// The tracks.
    pub fn tracks(&self) -> &Arc<[TireTrack]> {
        &self.tracks
    }

    /// The free radius R (m).
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// The vertical contact law.
    pub fn vertical(&self) -> &VerticalContact {
        &self.vertical
    }

    /// The handling law.
    pub fn law(&self) -> &HandlingLaw {
        &self.law
    }

    /// Contact, deflection rate and normal force of tire `tire` (step 1 of the module
    /// docs). `frozen`: `None` for Eq 2.1 as written, `Some(true)` for the in-contact piece
    /// extended linearly, `Some(false)` for the lifted piece (zero).
    #[inline]
    pub fn contact(
        &self,
        tire: usize,
        wheel: &Wheel,
        path: &PathFrame,
        frozen: Option<bool>,
    ) -> Contact {
        let c = &wheel.centre;
        let h = &path.direction;
        let s = path.coordinate + (c - path.origin).dot(h);
        let track = self.tracks[self.track_of[tire]].contact(s, c.z);
        let (sin, cos) = (track.sin_slope, track.cos_slope);
        let v = &wheel.velocity;
        let rate = v.dot(h) * sin - v.z * cos;
        let delta = track.deflection;
        let normal_force = match frozen {
            None => self.vertical.normal_force(delta, rate),
            Some(true) => self.piece[0] * delta + self.piece[1] * rate,
            Some(false) => 0.0,
        };
        Contact {
            track,
            normal: Vector3::new(-sin * h.x, -sin * h.y, cos),
            deflection_rate: rate,
            normal_force,
        }
    }

    /// Contact margin (m) `min(delta, delta + (c_t / k_0) delta')`: with a linear spring
    /// (Eq 2.1) the tire carries load exactly when it is positive, the switching function
    /// of lift-off and touchdown.
    #[inline]
    pub fn contact_margin(&self, contact: &Contact) -> f64 {
        let delta = contact.track.deflection;
        delta.min(delta + self.damping_over_stiffness * contact.deflection_rate)
    }
}

impl Component for TireAssembly {
    type Input = TireInput;
    type Output = TireOutput;

    /// One tire's lag states: the lagged lateral contact velocity (linear cornering,
    /// Eq 2.7) or the lagged slips `[kappa, alpha]` (Fiala, Eq 3.16).
    fn states(&self) -> &[StateInfo] {
        match self.law {
            HandlingLaw::LinearCornering(_) => &CONTACT_VELOCITY_LAG_STATES,
            HandlingLaw::Fiala(_) => &SLIP_LAG_STATES,
        }
    }

    fn channels(&self) -> &[ChannelInfo] {
        &CHANNELS
    }

    /// The lags at rest: the lateral velocity, or the steady-state slips.
    fn initial_state(&self, input: &TireInput, state: &mut [f64]) {
        let mut scratch = [0.0; 2];
        let n = state.len();
        let out = self.evaluate(input, &[0.0; 2][..n], &mut scratch[..n]);
        match self.law {
            HandlingLaw::LinearCornering(_) => state[0] = out.contact.lateral_velocity,
            HandlingLaw::Fiala(_) => state.copy_from_slice(&out.contact.slip_steady),
        }
    }

    /// Step 2 of the module docs for one tire with lag states `state`.
    #[inline]
    fn evaluate(&self, input: &TireInput, state: &[f64], d_state: &mut [f64]) -> TireOutput {
        let w = &input.wheel;
        let c = &input.contact;
        let (sin_w, cos_w) = w.heading;
        let e_x = Vector3::new(cos_w, sin_w, 0.0);
        let e_y = Vector3::new(-sin_w, cos_w, 0.0);
        let v = &w.velocity;
        let (v_x, v_y) = (v.dot(&e_x), v.dot(&e_y));
        let u = regularised_speed(v_x);
        let fz = c.normal_force;
        let n = c.normal;
        let delta = c.track.deflection;
        let loaded_radius = self.radius - delta.max(0.0);
        let point = w.centre - n * loaded_radius;
        let mut contact = TireContact {
            normal_force: fz,
            deflection: delta,
            slope: c.track.slope,
            forward_velocity: v_x,
            lateral_velocity: v_y,
            spin: w.spin,
            ..TireContact::default()
        };
        match &self.law {
            HandlingLaw::LinearCornering(law) => {
                let fy = law.lateral_force(fz, state[0], u);
                let fx = input.drive_force;
                let (sin, cos) = (c.track.sin_slope, c.track.cos_slope);
                let tangent = Vector3::new(cos * e_x.x, cos * e_x.y, sin);
                let force = n * fz + e_y * fy + tangent * fx;
                d_state[0] = contact_velocity_lag_rate(state[0], v_y, u, law.relaxation_length_m);
                (contact.fx, contact.fy) = (fx, fy);
                TireOutput {
                    force,
                    point,
                    moment: Vector3::zeros(),
                    contact,
                }
            }
            HandlingLaw::Fiala(law) => {
                let spin = w.spin;
                let steady = [(spin * loaded_radius - v_x) / u, -(v_y / u).atan()];
                let f = law.model.forces(fz, state[0], state[1]);
                let t = (e_x - n * e_x.dot(&n)).normalize();
                let l = n.cross(&t);
                let force = t * f.fx + l * f.fy + n * fz;
                let rolling_sign = (spin * self.radius / ROLLING_SIGN_SPEED_M_S).tanh();
                let moment = n * f.yaw_moment_z_up() + w.axle * (f.my * rolling_sign);
                let r = &law.relaxation;
                d_state[0] = lag_rate(state[0], steady[0], u, r.longitudinal_length);
                d_state[1] = lag_rate(state[1], steady[1], u, r.lateral_length);
                (contact.slip_steady, contact.fx, contact.fy) = (steady, f.fx, f.fy);
                TireOutput {
                    force,
                    point,
                    moment,
                    contact,
                }
            }
        }
    }

    fn record(&self, output: &TireOutput, row: &mut [f64]) {
        let c = &output.contact;
        row.copy_from_slice(&[
            output.force.x,
            output.force.y,
            output.force.z,
            c.normal_force,
            c.deflection,
            c.fx,
            c.fy,
            c.lateral_velocity,
        ]);
    }
}
