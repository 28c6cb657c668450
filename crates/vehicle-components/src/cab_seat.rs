//! The cab on elastomer mounts and the operator's suspension seat, driven by the motion of
//! the frame they sit on (issue 23, "cab and seat suspension"; `docs/layouts.md`).
//!
//! **Model.** Coordinates relative to the frame, in the frame's body axes (x forward,
//! y left, z up), small motions:
//!
//! - the cab: bounce `z` (m) of the centre O of its mount plane, roll `phi` and pitch `theta`
//!   (rad) about O. Its mounts are vertical spring-dampers at `(x_i, y_i)` from O, stiff
//!   horizontally, so a mount moves by `u_i = z + phi y_i - theta x_i` and a point at height
//!   `h` by `(h theta, -h phi, z + phi y - theta x)`;
//! - the seat: suspension travel `s` (m, up positive, 0 at mid-travel) of the suspended mass
//!   over the cab floor at `(x_s, y_s)`, spring `F = k_s (d_0 - s)` preloaded by the weight
//!   adjustment (`d_0 = m g / k_s`: the seat rides at mid-travel under its static load),
//!   damper `-c_s s'`, elastic end stops `k_stop` beyond `±travel / 2`;
//! - optionally a cushion: the operator's seated mass on a spring-damper over the seat's
//!   suspended part, compression `c` (m, from the unloaded cushion).
//!
//! With the generalised coordinates `q = (z, phi, theta, s[, c])`, each point mass `m_P`
//! at `r_P = (x_P, y_P, h_P)` from O with vertical Jacobian `J_P` and the cab's inertias
//! `I_xx`, `I_yy` about its own centre of mass, Lagrange's equations in the frame's axes are
//!
//! ```text
//!   M q'' = Q,    M = sum_P m_P (J_P J_P^T + h_P^2 (e_phi e_phi^T + e_theta e_theta^T))
//!                     + I_xx e_phi e_phi^T + I_yy e_theta e_theta^T
//!   Q = - sum_P m_P [ J_P (a_Pz + g) + h_P a_Px e_theta - h_P a_Py e_phi ]
//!       - I_xx alpha_x e_phi - I_yy alpha_y e_theta                        (frame, gravity)
//!       + g (sum_P m_P h_P) (phi e_phi + theta e_theta)        (the cab's overturning term)
//!       - sum_i (k_i u_i + c_i u_i') (e_z + y_i e_phi - x_i e_theta)                (mounts)
//!       + (k_s (d_0 - s) - c_s s' + F_stop) e_s  -  (k_c c + c_c c') e_c     (seat, cushion)
//! ```
//!
//! with `a_P = a_O + alpha x r_P + omega x (omega x r_P)` the frame's acceleration at the
//! point (kinematic, gravity not included) and `g` along the frame's -z.
//!
//! **One-way coupling.** The frame's motion drives the cab and seat; their reaction on the
//! frame is left out. The vehicle model's front unit already carries the cab's mass and
//! inertia rigidly, so the neglected load is only the difference between a mounted and a
//! rigid cab, `m (a_cab - a_frame) = m a_frame (T - 1)` with `T` the cab's transmissibility
//! at that frequency (and the same with the cab's rocking inertia about the mount plane for
//! pitch and roll). The frame's acceleration is then in error by about `mu |T - 1|`, with
//! `mu` the ratio of the cab-and-seat mass (or rocking inertia) to the front unit's:
//! for the generic cab on the prototype, `mu = 1 180 kg / 21 t = 0.056` in bounce and
//! `1 510 kg m² / 41 000 kg m² = 0.037` in pitch (a seat on the centreline does not feel
//! the cab's roll). Far below the cab's modes `T -> 1` and the error vanishes. Near them
//! it does not: with the generic, lightly damped mounts the cab's pitch transmissibility
//! peaks at `|T| = 5.3` (4.7 Hz) and its bounce at 3.5 (7.1 Hz), where the neglected
//! reaction reaches `mu |T - 1|`, about 0.16 of the frame's motion, and the one-way model
//! overstates the cab's resonant motion (a real frame would be loaded and the resonance
//! damped). Over a D1 ride the floor's a_wz is 1.4-1.7 times the frame's, an average
//! `|T - 1|` of 0.4-0.7 and an error of a few percent (`docs/layouts.md`).
//!
//! Other assumptions: small relative motion (linear kinematics); gravity along the frame's
//! z (the frame's tilt, a few degrees on rough ground, changes the vertical gravity term by
//! under 0.1 %); the frame's rotation rate enters only through the point accelerations (the
//! Coriolis and centrifugal terms of the relative motion, `omega` times relative rates of
//! millimetres per second, are left out); mounts and cushion linear; stops elastic (their
//! rubber's damping left out); the operator's seated mass is a point at the seat.
//!
//! **Energy.** With `E = T_rel + V` (`T_rel = q'^T M q' / 2`; `V` the springs, stops, the
//! weight in the frame's field and the overturning term), `dE/dt = P_in - D`: `P_in` the
//! power of the frame's inertial forces, `D = sum c_i u_i'^2 + c_s s'^2 + c_c c'^2 >= 0`.
//! The passive elements never create energy.

mod linalg;
mod params;
pub mod registry;

pub use params::{CabMount, CabParams, Cushion, SeatParams};

use crate::component::{ChannelInfo, Component, StateInfo};
use crate::error::ComponentError;
use linalg::{generalized_eigenvalues, inverse_spd, mul, Mat, N_MAX};
use params::in_range;

/// Index of the bounce coordinate `z` in `q`.
pub const BOUNCE: usize = 0;
/// Index of the cab roll `phi`.
pub const ROLL: usize = 1;
/// Index of the cab pitch `theta`.
pub const PITCH: usize = 2;
/// Index of the seat travel `s`.
pub const SEAT: usize = 3;
/// Index of the cushion compression `c` (with a cushion).
pub const CUSHION: usize = 4;

/// The frame's motion at the centre O of the cab's mount plane, in the frame's body axes:
/// kinematic acceleration (gravity not included), angular acceleration and rate.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FrameMotion {
    /// Acceleration of the frame's point O, x, y, z (m/s²).
    pub accel_m_s2: [f64; 3],
    /// Angular acceleration about x, y, z (rad/s²).
    pub angular_accel_rad_s2: [f64; 3],
    /// Angular rate about x, y, z (rad/s).
    pub rate_rad_s: [f64; 3],
}

impl FrameMotion {
    /// The frame at rest.
    pub const REST: FrameMotion = FrameMotion {
        accel_m_s2: [0.0; 3],
        angular_accel_rad_s2: [0.0; 3],
        rate_rad_s: [0.0; 3],
    };

    /// The frame's acceleration at the point `r` from O: `a_O + alpha x r + omega x (omega x r)`.
    pub fn point_accel(&self, r: [f64; 3]) -> [f64; 3] {
        let w = self.rate_rad_s;
        let wr = cross(w, r);
        let t = cross(self.angular_accel_rad_s2, r);
        let c = cross(w, wr);
        [
            self.accel_m_s2[0] + t[0] + c[0],
            self.accel_m_s2[1] + t[1] + c[1],
            self.accel_m_s2[2] + t[2] + c[2],
        ]
    }

    /// The motion mirrored in the x-z plane (y -> -y): lateral acceleration, roll and yaw
    /// change sign.
    pub fn mirrored(&self) -> Self {
        let m = |v: [f64; 3]| [v[0], -v[1], v[2]];
        let p = |v: [f64; 3]| [-v[0], v[1], -v[2]];
        Self {
            accel_m_s2: m(self.accel_m_s2),
            angular_accel_rad_s2: p(self.angular_accel_rad_s2),
            rate_rad_s: p(self.rate_rad_s),
        }
    }
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// What the cab and seat give back at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CabSeatOutput {
    /// Vertical acceleration of the cab floor at the seat base (m/s², kinematic).
    pub floor_accel_m_s2: f64,
    /// Vertical acceleration on the seat pan, the operator's (m/s², kinematic).
    pub seat_accel_m_s2: f64,
    /// Seat suspension travel from mid-travel (m, up positive).
    pub seat_travel_m: f64,
    /// Force of the end stops on the seat (N, up positive; 0 within the travel).
    pub stop_force_n: f64,
    /// Cab roll relative to the frame (rad).
    pub cab_roll_rad: f64,
    /// Cab pitch relative to the frame (rad).
    pub cab_pitch_rad: f64,
    /// Power of the frame's inertial forces on the relative motion, `P_in` (W).
    pub power_in_w: f64,
    /// Power dissipated in the dampers, `D >= 0` (W).
    pub dissipation_w: f64,
}

/// A point mass of the model: mass, position from O, vertical Jacobian.
#[derive(Debug, Clone, Copy, PartialEq)]
struct PointMass {
    mass: f64,
    r: [f64; 3],
    jz: [f64; N_MAX],
}

/// The cab on mounts with the suspension seat: a [`Component`] of `2 n` states
/// (`n = 4`, or 5 with a cushion) driven by [`FrameMotion`] (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct CabSeat {
    cab: CabParams,
    seat: SeatParams,
    gravity: f64,
    n: usize,
    points: [PointMass; 3],
    n_points: usize,
    mass: Mat,
    mass_inv: Mat,
    stiffness: Mat,
    stiffness_inv: Mat,
    preload_m: f64,
}

const STATES_4: [StateInfo; 8] = [
    StateInfo::new("cab_bounce_m", "m", 0.005),
    StateInfo::new("cab_roll_rad", "rad", 0.005),
    StateInfo::new("cab_pitch_rad", "rad", 0.005),
    StateInfo::new("seat_travel_m", "m", 0.02),
    StateInfo::new("cab_bounce_rate_m_per_s", "m/s", 0.05),
    StateInfo::new("cab_roll_rate_rad_per_s", "rad/s", 0.05),
    StateInfo::new("cab_pitch_rate_rad_per_s", "rad/s", 0.05),
    StateInfo::new("seat_travel_rate_m_per_s", "m/s", 0.2),
];

const STATES_5: [StateInfo; 10] = [
    StateInfo::new("cab_bounce_m", "m", 0.005),
    StateInfo::new("cab_roll_rad", "rad", 0.005),
    StateInfo::new("cab_pitch_rad", "rad", 0.005),
    StateInfo::new("seat_travel_m", "m", 0.02),
    StateInfo::new("cushion_m", "m", 0.005),
    StateInfo::new("cab_bounce_rate_m_per_s", "m/s", 0.05),
    StateInfo::new("cab_roll_rate_rad_per_s", "rad/s", 0.05),
    StateInfo::new("cab_pitch_rate_rad_per_s", "rad/s", 0.05),
    StateInfo::new("seat_travel_rate_m_per_s", "m/s", 0.2),
    StateInfo::new("cushion_rate_m_per_s", "m/s", 0.05),
];

const CHANNELS: [ChannelInfo; 8] = [
    ChannelInfo::new("floor_accel_z_m_s2", "m/s^2"),
    ChannelInfo::new("seat_accel_z_m_s2", "m/s^2"),
    ChannelInfo::new("seat_travel_m", "m"),
    ChannelInfo::new("seat_stop_force_n", "N"),
    ChannelInfo::new("cab_roll_rad", "rad"),
    ChannelInfo::new("cab_pitch_rad", "rad"),
    ChannelInfo::new("cab_power_in_w", "W"),
    ChannelInfo::new("cab_dissipation_w", "W"),
];

/// Generalised forces of one evaluation.
struct Forces {
    total: [f64; N_MAX],
    power_in: f64,
    dissipation: f64,
    stop: f64,
}

impl CabSeat {
    /// The cab and seat under gravity `gravity_m_s2`, every field checked (the field is
    /// named in the error); the mounts must carry the cab's overturning term (roll and pitch
    /// stiffness above `g sum m_P h_P`).
    #[allow(clippy::needless_range_loop)] // the mass and stiffness matrices by index
    pub fn new(
        cab: CabParams,
        seat: SeatParams,
        gravity_m_s2: f64,
    ) -> Result<Self, ComponentError> {
        cab.validate()?;
        seat.validate()?;
        in_range(
            "gravity_m_s2",
            gravity_m_s2,
            0.1,
            20.0,
            "must be finite and within [0.1, 20] m/s²",
        )?;
        let n = if seat.cushion.is_some() { 5 } else { 4 };
        let floor = |extra: [f64; 2]| {
            let mut j = [0.0; N_MAX];
            j[BOUNCE] = 1.0;
            j[ROLL] = seat.y_m;
            j[PITCH] = -seat.x_m;
            j[SEAT] = extra[0];
            j[CUSHION] = extra[1];
            j
        };
        let seat_r = [seat.x_m, seat.y_m, seat.height_m];
        let mut cab_j = [0.0; N_MAX];
        cab_j[BOUNCE] = 1.0;
        let blank = PointMass {
            mass: 0.0,
            r: [0.0; 3],
            jz: [0.0; N_MAX],
        };
        let mut points = [
            PointMass {
                mass: cab.mass_kg,
                r: [0.0, 0.0, cab.cg_height_m],
                jz: cab_j,
            },
            PointMass {
                mass: seat.suspended_mass_kg,
                r: seat_r,
                jz: floor([1.0, 0.0]),
            },
            blank,
        ];
        let mut n_points = 2;
        if let Some(c) = &seat.cushion {
            points[2] = PointMass {
                mass: c.occupant_mass_kg,
                r: seat_r,
                jz: floor([1.0, 1.0]),
            };
            n_points = 3;
        }
        let mut mass = [[0.0; N_MAX]; N_MAX];
        for p in &points[..n_points] {
            for i in 0..n {
                for j in 0..n {
                    mass[i][j] += p.mass * p.jz[i] * p.jz[j];
                }
            }
            mass[ROLL][ROLL] += p.mass * p.r[2] * p.r[2];
            mass[PITCH][PITCH] += p.mass * p.r[2] * p.r[2];
        }
        mass[ROLL][ROLL] += cab.roll_inertia_kg_m2;
        mass[PITCH][PITCH] += cab.pitch_inertia_kg_m2;
        let overturning: f64 = points[..n_points]
            .iter()
            .map(|p| p.mass * p.r[2])
            .sum::<f64>()
            * gravity_m_s2;
        let mut stiffness = [[0.0; N_MAX]; N_MAX];
        for m in &cab.mounts {
            let b = [1.0, m.y_m, -m.x_m];
            for i in 0..3 {
                for j in 0..3 {
                    stiffness[i][j] += m.stiffness_n_per_m * b[i] * b[j];
                }
            }
        }
        stiffness[ROLL][ROLL] -= overturning;
        stiffness[PITCH][PITCH] -= overturning;
        stiffness[SEAT][SEAT] = seat.stiffness_n_per_m;
        if let Some(c) = &seat.cushion {
            stiffness[CUSHION][CUSHION] = c.stiffness_n_per_m;
        }
        let mass_inv = inverse_spd(&mass, n).ok_or(ComponentError::InvalidParameter {
            field: "cab.mass_kg",
            value: cab.mass_kg,
            reason: "the mass matrix is not positive definite",
        })?;
        let stiffness_inv =
            inverse_spd(&stiffness, n).ok_or(ComponentError::InvalidParameter {
                field: "cab.mounts",
                value: overturning,
                reason: "the mounts' roll or pitch stiffness does not exceed the overturning term g sum m h (value) of the cab and seat: spread or stiffen the mounts",
            })?;
        Ok(Self {
            preload_m: seat.total_mass_kg() * gravity_m_s2 / seat.stiffness_n_per_m,
            cab,
            seat,
            gravity: gravity_m_s2,
            n,
            points,
            n_points,
            mass,
            mass_inv,
            stiffness,
            stiffness_inv,
        })
    }

    /// The generic cab and seat ([`CabParams::generic`], [`SeatParams::generic`]) under
    /// 9.81 m/s².
    pub fn generic() -> Self {
        Self::new(CabParams::generic(), SeatParams::generic(), 9.81)
            .expect("the generic cab and seat are valid")
    }

    /// The cab's parameters.
    pub fn cab(&self) -> &CabParams {
        &self.cab
    }

    /// The seat's parameters.
    pub fn seat(&self) -> &SeatParams {
        &self.seat
    }

    /// Number of generalised coordinates `n` (4, or 5 with a cushion); the state is
    /// `(q, q')`.
    pub fn n_dof(&self) -> usize {
        self.n
    }

    /// Compression of the seat spring at mid-travel, `d_0 = m g / k_s` (m): the static
    /// deflection the weight adjustment takes up.
    pub fn seat_preload_m(&self) -> f64 {
        self.preload_m
    }

    /// Vertical displacement `u_i = z + phi y_i - theta x_i` of each mount (m, from the
    /// unloaded mount; negative in compression) in `state`.
    pub fn mount_displacements_m(&self, state: &[f64]) -> [f64; 4] {
        self.cab
            .mounts
            .map(|m| state[BOUNCE] + state[ROLL] * m.y_m - state[PITCH] * m.x_m)
    }

    /// End-stop force on the seat (N) at travel `s` (m).
    fn stop_force(&self, s: f64) -> f64 {
        let half = 0.5 * self.seat.travel_m;
        let k = self.seat.stop_stiffness_n_per_m;
        if s > half {
            -k * (s - half)
        } else if s < -half {
            k * (-half - s)
        } else {
            0.0
        }
    }

    fn forces(&self, u: &FrameMotion, q: &[f64], v: &[f64]) -> Forces {
        let n = self.n;
        let g = self.gravity;
        let mut frame = [0.0; N_MAX];
        let mut total = [0.0; N_MAX];
        let mut overturning = 0.0;
        for p in &self.points[..self.n_points] {
            let a = u.point_accel(p.r);
            for j in 0..n {
                frame[j] -= p.mass * p.jz[j] * a[2];
                total[j] -= p.mass * p.jz[j] * g;
            }
            frame[PITCH] -= p.mass * p.r[2] * a[0];
            frame[ROLL] += p.mass * p.r[2] * a[1];
            overturning += p.mass * p.r[2] * g;
        }
        frame[ROLL] -= self.cab.roll_inertia_kg_m2 * u.angular_accel_rad_s2[0];
        frame[PITCH] -= self.cab.pitch_inertia_kg_m2 * u.angular_accel_rad_s2[1];
        total[ROLL] += overturning * q[ROLL];
        total[PITCH] += overturning * q[PITCH];
        let mut dissipation = 0.0;
        for m in &self.cab.mounts {
            let d = q[BOUNCE] + q[ROLL] * m.y_m - q[PITCH] * m.x_m;
            let r = v[BOUNCE] + v[ROLL] * m.y_m - v[PITCH] * m.x_m;
            let f = -m.stiffness_n_per_m * d - m.damping_n_s_per_m * r;
            dissipation += m.damping_n_s_per_m * r * r;
            total[BOUNCE] += f;
            total[ROLL] += f * m.y_m;
            total[PITCH] -= f * m.x_m;
        }
        let stop = self.stop_force(q[SEAT]);
        total[SEAT] += self.seat.stiffness_n_per_m * (self.preload_m - q[SEAT])
            - self.seat.damping_n_s_per_m * v[SEAT]
            + stop;
        dissipation += self.seat.damping_n_s_per_m * v[SEAT] * v[SEAT];
        if let Some(c) = &self.seat.cushion {
            total[CUSHION] -= c.stiffness_n_per_m * q[CUSHION] + c.damping_n_s_per_m * v[CUSHION];
            dissipation += c.damping_n_s_per_m * v[CUSHION] * v[CUSHION];
        }
        let mut power_in = 0.0;
        for j in 0..n {
            total[j] += frame[j];
            power_in += frame[j] * v[j];
        }
        Forces {
            total,
            power_in,
            dissipation,
            stop,
        }
    }

    /// Energy of the relative motion, `E = q'^T M q' / 2 + V(q)` (J; module docs): its rate
    /// is `P_in - D` along any motion.
    pub fn energy_j(&self, state: &[f64]) -> f64 {
        let n = self.n;
        let (q, v) = state.split_at(n);
        let mut vv = [0.0; N_MAX];
        vv[..n].copy_from_slice(v);
        let mv = mul(&self.mass, n, &vv);
        let kinetic = 0.5 * (0..n).map(|j| v[j] * mv[j]).sum::<f64>();
        let mounts: f64 = self
            .mount_displacements_m(state)
            .iter()
            .zip(&self.cab.mounts)
            .map(|(d, m)| 0.5 * m.stiffness_n_per_m * d * d)
            .sum();
        let seat = 0.5 * self.seat.stiffness_n_per_m * (q[SEAT] - self.preload_m).powi(2);
        let half = 0.5 * self.seat.travel_m;
        let pen = (q[SEAT].abs() - half).max(0.0);
        let stops = 0.5 * self.seat.stop_stiffness_n_per_m * pen * pen;
        let cushion = self
            .seat
            .cushion
            .map_or(0.0, |c| 0.5 * c.stiffness_n_per_m * q[CUSHION] * q[CUSHION]);
        let mut weight = 0.0;
        for p in &self.points[..self.n_points] {
            let lift: f64 = (0..n).map(|j| p.jz[j] * q[j]).sum();
            let tilt = 0.5 * p.r[2] * (q[ROLL] * q[ROLL] + q[PITCH] * q[PITCH]);
            weight += p.mass * self.gravity * (lift - tilt);
        }
        kinetic + mounts + seat + stops + cushion + weight
    }

    /// Natural frequencies of the undamped motion about the static state (Hz, ascending):
    /// the stiffness `K = -M d(q'')/dq` of [`Component::evaluate`] by central differences,
    /// then `K v = omega^2 M v`.
    pub fn linear_modes_hz(&self) -> Vec<f64> {
        let n = self.n;
        let mut x0 = vec![0.0; 2 * n];
        self.initial_state(&FrameMotion::REST, &mut x0);
        let mut d = vec![0.0; 2 * n];
        let mut k = [[0.0; N_MAX]; N_MAX];
        let h = 1e-6;
        for j in 0..n {
            let mut col = [0.0; N_MAX];
            for (sign, w) in [(1.0, -0.5 / h), (-1.0, 0.5 / h)] {
                let mut x = x0.clone();
                x[j] += sign * h;
                self.evaluate(&FrameMotion::REST, &x, &mut d);
                for i in 0..n {
                    col[i] += w * d[n + i];
                }
            }
            let mc = mul(&self.mass, n, &col);
            for i in 0..n {
                k[i][j] = mc[i];
            }
        }
        let mut ks = k;
        for i in 0..n {
            for j in 0..n {
                ks[i][j] = 0.5 * (k[i][j] + k[j][i]);
            }
        }
        generalized_eigenvalues(&ks, &self.mass, n)
            .expect("the mass matrix is positive definite (checked at construction)")
            .into_iter()
            .map(|l| l.max(0.0).sqrt() / (2.0 * std::f64::consts::PI))
            .collect()
    }
}

impl Component for CabSeat {
    type Input = FrameMotion;
    type Output = CabSeatOutput;

    fn states(&self) -> &[StateInfo] {
        if self.n == 5 {
            &STATES_5
        } else {
            &STATES_4
        }
    }

    fn channels(&self) -> &[ChannelInfo] {
        &CHANNELS
    }

    /// The equilibrium of the linear part under gravity and the constant frame motion
    /// `input`: `K q = Q(input, q = 0, q' = 0)`, at rest relative to the frame.
    fn initial_state(&self, input: &FrameMotion, state: &mut [f64]) {
        let n = self.n;
        let zero = [0.0; N_MAX];
        let f = self.forces(input, &zero[..n], &zero[..n]);
        let q = mul(&self.stiffness_inv, n, &f.total);
        state[..n].copy_from_slice(&q[..n]);
        state[n..].fill(0.0);
    }

    fn evaluate(&self, input: &FrameMotion, state: &[f64], d_state: &mut [f64]) -> CabSeatOutput {
        let n = self.n;
        let (q, v) = state.split_at(n);
        let f = self.forces(input, q, v);
        let acc = mul(&self.mass_inv, n, &f.total);
        d_state[..n].copy_from_slice(v);
        d_state[n..].copy_from_slice(&acc[..n]);
        let seat_point = self.points[1].r;
        let base = input.point_accel(seat_point)[2];
        let floor = base + acc[BOUNCE] + acc[ROLL] * seat_point[1] - acc[PITCH] * seat_point[0];
        let top = self.points[self.n_points - 1].jz;
        let seat = base + (0..n).map(|j| top[j] * acc[j]).sum::<f64>();
        CabSeatOutput {
            floor_accel_m_s2: floor,
            seat_accel_m_s2: seat,
            seat_travel_m: q[SEAT],
            stop_force_n: f.stop,
            cab_roll_rad: q[ROLL],
            cab_pitch_rad: q[PITCH],
            power_in_w: f.power_in,
            dissipation_w: f.dissipation,
        }
    }

    fn record(&self, o: &CabSeatOutput, row: &mut [f64]) {
        row.copy_from_slice(&[
            o.floor_accel_m_s2,
            o.seat_accel_m_s2,
            o.seat_travel_m,
            o.stop_force_n,
            o.cab_roll_rad,
            o.cab_pitch_rad,
            o.power_in_w,
            o.dissipation_w,
        ]);
    }
}

#[cfg(test)]
mod tests;
