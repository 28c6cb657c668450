//! One complete tire on any [`Terrain`] (Chrono::Vehicle's `ChTire` in component form):
//! enveloping ([`Envelope`], Eqs 2.2-2.4 / 6.1-6.3), vertical contact with lift-off
//! ([`VerticalContact`], Eq 2.1), Fiala handling ([`Fiala`], section 6.2.2) and first-order
//! slip lag ([`Relaxation`], Eqs 2.7 / 3.16), composed as a
//! [`vehicle_components::Component`].
//!
//! Per evaluation, for the wheel centre `r = (x, y, z)`, its velocity `v`, heading `psi`
//! (yaw of the wheel plane from x towards y) and spin `omega`:
//!
//! 1. wheel axes on the ground: `e_x = (cos psi, sin psi, 0)`, `e_y = (-sin psi, cos psi, 0)`;
//!    the wheel's line is the terrain under `s e_x + l e_y` with `l = r . e_y`, and the wheel
//!    sits at `s_c = r . e_x` on it (for `psi = 0` this is exactly `Track { terrain, y }`);
//! 2. effective contact on that line: deflection delta, effective elevation z_eff and slope
//!    theta (Eqs 2.2-2.4 or 6.1-6.3);
//! 3. deflection rate with the effective line held fixed,
//!    `d(delta)/dt = -(v_z cos theta - v_x sin theta)`, `v_x = v . e_x`, and the normal force
//!    `F_n = F_el(delta) + c_t d(delta)/dt >= 0` (Eq 2.1), zero out of contact;
//! 4. steady-state slips with the regularised speed `|V_x|_eff` of
//!    [`regularised_speed`]: `kappa_s = (omega R_l - v_x) / |V_x|_eff` with the loaded
//!    radius `R_l = R - max(delta, 0)`, and `alpha_s = -atan(v_y / |V_x|_eff)` (Eq 3.17),
//!    `v_y = v . e_y`;
//! 5. the states are the lagged slips `[kappa, alpha]`, `d/dt = (steady - lagged) |V_x|_eff
//!    / sigma` (Eq 3.16);
//! 6. Fiala forces from `F_n` and the lagged slips, with the terrain's friction coefficient
//!    mu at the contact point as the peak friction: `U_max -> mu`, `U_min -> mu U_min / U_max`
//!    ([`Fiala::forces_on_surface`] with scale `mu / U_max`);
//! 7. force on the wheel in the terrain frame, `F = F_x t + F_y e_y + F_n n`, with the
//!    contact-plane axes of the effective slope: `t = cos theta e_x + sin theta e_z`,
//!    `n = -sin theta e_x + cos theta e_z`.
//!
//! The contact frame tilts with the in-plane slope only (the enveloping is a single-track,
//! in-plane model); the cross slope of the terrain does not tilt it.

use vehicle_components::{ChannelInfo, Component, StateInfo, Terrain};

use crate::envelope::{EffectiveContact, Envelope, EnvelopeMethod};
use crate::error::TireError;
use crate::fiala::Fiala;
use crate::model::TireForces;
use crate::params::TireParams;
use crate::relaxation::{regularised_speed, Relaxation, SLIP_LAG_STATES};
use crate::terrain::Profile;
use crate::vertical::VerticalContact;

/// The wheel as the vehicle gives it to the tire (terrain frame, SI).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct WheelInput {
    /// Wheel-centre position `[x, y, z]` (m).
    pub position: [f64; 3],
    /// Wheel-centre velocity `[v_x, v_y, v_z]` (m/s).
    pub velocity: [f64; 3],
    /// Heading psi of the wheel plane (rad), from x towards y.
    pub heading: f64,
    /// Spin omega about the axle (rad/s), positive rolling forward.
    pub spin: f64,
}

/// What the tire gives back: forces on the wheel and the contact quantities.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TireOutput {
    /// Force on the wheel in the terrain frame `[F_x, F_y, F_z]` (N), applied at `point`.
    pub force: [f64; 3],
    /// Contact point, the midpoint of P1P2 on the wheel's line (m, terrain frame).
    pub point: [f64; 3],
    /// Forces and moments in the wheel's contact axes (`fx` along `t`, `fy` along `e_y`,
    /// aligning and rolling-resistance moments), see [`TireForces`].
    pub wheel_forces: TireForces,
    /// Normal force F_n (N), along the contact normal.
    pub normal_force: f64,
    /// Deflection rate d(delta)/dt (m/s).
    pub deflection_rate: f64,
    /// Steady-state slip ratio kappa_s (-).
    pub slip_ratio_steady: f64,
    /// Steady-state slip angle alpha_s (rad).
    pub slip_angle_steady: f64,
    /// Terrain friction coefficient at the contact point (-).
    pub friction: f64,
    /// The effective contact on the wheel's line (its x coordinates are along the line).
    pub contact: EffectiveContact,
}

const CHANNELS: [ChannelInfo; 8] = [
    ChannelInfo::new("force_x_n", "N"),
    ChannelInfo::new("force_y_n", "N"),
    ChannelInfo::new("force_z_n", "N"),
    ChannelInfo::new("normal_force_n", "N"),
    ChannelInfo::new("deflection_m", "m"),
    ChannelInfo::new("aligning_moment_n_m", "N m"),
    ChannelInfo::new("slip_ratio_steady", "-"),
    ChannelInfo::new("slip_angle_steady_rad", "rad"),
];

/// The terrain under the wheel's line `s e_x + l e_y` as a profile in `s`.
struct WheelLine<'a, T> {
    terrain: &'a T,
    cos: f64,
    sin: f64,
    lateral: f64,
}

impl<T: Terrain> Profile for WheelLine<'_, T> {
    #[inline]
    fn height_at(&self, s: f64) -> f64 {
        self.terrain.height(
            s * self.cos - self.lateral * self.sin,
            s * self.sin + self.lateral * self.cos,
        )
    }
}

/// Enveloping + vertical + handling + relaxation of one tire on terrain `T` (module docs).
/// `T` may be a reference, so several tires share one terrain.
#[derive(Debug, Clone, PartialEq)]
pub struct TireAssembly<T> {
    terrain: T,
    envelope: Envelope,
    vertical: VerticalContact,
    handling: Fiala,
    relaxation: Relaxation,
}

impl<T: Terrain> TireAssembly<T> {
    /// From a validated parameter set, the enveloping method and its profile sampling step
    /// `sample_spacing` (m, > 0; see [`Envelope::new`]).
    pub fn new(
        params: &TireParams,
        method: EnvelopeMethod,
        sample_spacing: f64,
        terrain: T,
    ) -> Result<Self, TireError> {
        Ok(Self {
            terrain,
            envelope: Envelope::new(method, params.unloaded_radius_m, sample_spacing)?,
            vertical: VerticalContact::from_params(params)?,
            handling: Fiala::new(params)?,
            relaxation: Relaxation::from_params(params)?,
        })
    }

    /// The terrain.
    pub fn terrain(&self) -> &T {
        &self.terrain
    }

    /// The enveloping settings.
    pub fn envelope(&self) -> &Envelope {
        &self.envelope
    }

    /// The handling model.
    pub fn handling(&self) -> &Fiala {
        &self.handling
    }

    /// Contact, normal force and steady slips: steps 1-4 of the module docs.
    fn kinematics(&self, input: &WheelInput) -> Kinematics {
        let (sin, cos) = input.heading.sin_cos();
        let [x, y, z] = input.position;
        let [vx, vy, vz] = input.velocity;
        let line = WheelLine {
            terrain: &self.terrain,
            cos,
            sin,
            lateral: -x * sin + y * cos,
        };
        let s_c = x * cos + y * sin;
        let contact = self.envelope.contact(&line, s_c, z);
        let v_long = vx * cos + vy * sin;
        let v_lat = -vx * sin + vy * cos;
        let (slope_sin, slope_cos) = contact.slope.sin_cos();
        let deflection_rate = -(vz * slope_cos - v_long * slope_sin);
        let normal_force = self
            .vertical
            .normal_force(contact.deflection, deflection_rate);
        let speed = regularised_speed(v_long);
        let loaded_radius = self.envelope.radius() - contact.deflection.max(0.0);
        let s_m = contact.x_mid();
        let point = [
            s_m * cos - line.lateral * sin,
            s_m * sin + line.lateral * cos,
            contact.z_eff,
        ];
        Kinematics {
            contact,
            point,
            cos,
            sin,
            v_long,
            normal_force,
            deflection_rate,
            steady: [
                (input.spin * loaded_radius - v_long) / speed,
                -(v_lat / speed).atan(),
            ],
        }
    }
}

/// Intermediate results of [`TireAssembly::kinematics`].
struct Kinematics {
    contact: EffectiveContact,
    point: [f64; 3],
    cos: f64,
    sin: f64,
    v_long: f64,
    normal_force: f64,
    deflection_rate: f64,
    steady: [f64; 2],
}

impl<T: Terrain> Component for TireAssembly<T> {
    type Input = WheelInput;
    type Output = TireOutput;

    /// `[slip_ratio, slip_angle_rad]`, the lagged slips of Eq 3.16.
    fn states(&self) -> &[StateInfo] {
        &SLIP_LAG_STATES
    }

    fn channels(&self) -> &[ChannelInfo] {
        &CHANNELS
    }

    /// The steady-state slips: the lag is at rest.
    fn initial_state(&self, input: &WheelInput, state: &mut [f64]) {
        state.copy_from_slice(&self.kinematics(input).steady);
    }

    fn evaluate(&self, input: &WheelInput, state: &[f64], d_state: &mut [f64]) -> TireOutput {
        let k = self.kinematics(input);
        let lagged = [state[0], state[1]];
        d_state.copy_from_slice(&self.relaxation.rates(lagged, k.steady, k.v_long));
        let friction = self.terrain.friction(k.point[0], k.point[1]);
        let scale = friction / self.handling.peak_friction();
        let f = self
            .handling
            .forces_on_surface(k.normal_force, lagged[0], lagged[1], scale);
        let (slope_sin, slope_cos) = k.contact.slope.sin_cos();
        // t = cos(theta) e_x + sin(theta) e_z, n = -sin(theta) e_x + cos(theta) e_z.
        let along = f.fx * slope_cos - k.normal_force * slope_sin;
        let force = [
            along * k.cos - f.fy * k.sin,
            along * k.sin + f.fy * k.cos,
            f.fx * slope_sin + k.normal_force * slope_cos,
        ];
        TireOutput {
            force,
            point: k.point,
            wheel_forces: f,
            normal_force: k.normal_force,
            deflection_rate: k.deflection_rate,
            slip_ratio_steady: k.steady[0],
            slip_angle_steady: k.steady[1],
            friction,
            contact: k.contact,
        }
    }

    fn record(&self, output: &TireOutput, row: &mut [f64]) {
        row.copy_from_slice(&[
            output.force[0],
            output.force[1],
            output.force[2],
            output.normal_force,
            output.contact.deflection,
            output.wheel_forces.mz,
            output.slip_ratio_steady,
            output.slip_angle_steady,
        ]);
    }
}
