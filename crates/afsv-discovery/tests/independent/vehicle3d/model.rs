//! The independent 3-D vehicle's equations of motion (Kane's form over Euler-angle
//! coordinates, Jacobians by central differences of the pose), its tires, steering
//! hydraulics, drive and driver, and the fixed-step RK4 integration. Module docs of
//! [`super`] for the formulation and the choices.

use super::*;
use crate::independent::strut::{VehicleStrut, STRUT_MAX_STEP_S, STRUT_STATES};

/// Integration step (s).
pub const STEP_S: f64 = 0.0005;

/// Integration step with the HPS front axle (s): the strut's own bound
/// ([`STRUT_MAX_STEP_S`], the rod-side chamber near zero pressure drop).
pub const STEP_HPS_S: f64 = STRUT_MAX_STEP_S;

/// Coordinates of the two units: x, y, z of the front cg, yaw, pitch, roll of the front
/// unit (Z-Y-X), articulation theta, rear-unit roll; then the travels of the front-left and
/// front-right wheel carriers along the front unit's z (up positive, from the static
/// position; held at zero with a rigid front axle).
const NQ: usize = 10;
/// Angle coordinates (the five after the position).
const NA: usize = 5;
/// The first carrier coordinate.
pub const CARRIER: usize = 8;
/// Points of the pose: rear cg, four wheel centres (the front ones on their carriers), cab
/// point, two front strut mounts, two hitch strut mounts, the two front wheel centres at
/// their static places in the unit (positions relative to the front cg, world axes).
const NP: usize = 12;
/// Pose: front rotation (9), rear rotation (9), the points (3 NP).
const NPOSE: usize = 18 + 3 * NP;

// state layout
pub const U: usize = NQ; // generalized speeds (time derivatives of q)
pub const SPIN: usize = 2 * NQ; // four wheel spin rates (rad/s)
pub const KAPPA: usize = SPIN + 4; // lagged slip ratios
pub const ALPHA: usize = KAPPA + 4; // lagged slip angles (rad, sliding left positive)
pub const PC: usize = ALPHA + 4; // P_c (Pa)
pub const PR: usize = PC + 1; // P_r (Pa)
pub const THETA_H: usize = PR + 1; // valve housing angle (deg)
pub const PI_INT: usize = THETA_H + 1; // integral of the speed error (m)
pub const STEER: usize = PI_INT + 1; // steering-wheel angle (rad), the driver's state
pub const HPS: usize = STEER + 1; // the left then the right front strut's states
/// Number of states.
pub const N: usize = HPS + 2 * STRUT_STATES;

const P_CAV: f64 = 2.0e4;
const CAV_TAPER: f64 = 3.0e4;
const SQRT_REG_BAR: f64 = 0.02;
const V_MIN: f64 = 0.5;

type V3 = [f64; 3];
type M3 = [[f64; 3]; 3];

fn mul(a: &M3, b: &M3) -> M3 {
    let mut c = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            c[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
        }
    }
    c
}

fn mv(a: &M3, v: &V3) -> V3 {
    [
        a[0][0] * v[0] + a[0][1] * v[1] + a[0][2] * v[2],
        a[1][0] * v[0] + a[1][1] * v[1] + a[1][2] * v[2],
        a[2][0] * v[0] + a[2][1] * v[1] + a[2][2] * v[2],
    ]
}

fn mtv(a: &M3, v: &V3) -> V3 {
    [
        a[0][0] * v[0] + a[1][0] * v[1] + a[2][0] * v[2],
        a[0][1] * v[0] + a[1][1] * v[1] + a[2][1] * v[2],
        a[0][2] * v[0] + a[1][2] * v[1] + a[2][2] * v[2],
    ]
}

fn dot(a: &V3, b: &V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: &V3, b: &V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn add(a: &V3, b: &V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn scale(a: &V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}

fn rx(a: f64) -> M3 {
    let (s, c) = a.sin_cos();
    [[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]]
}

fn ry(a: f64) -> M3 {
    let (s, c) = a.sin_cos();
    [[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]]
}

fn rz(a: f64) -> M3 {
    let (s, c) = a.sin_cos();
    [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]
}

fn rot_of(p: &[f64; NPOSE], at: usize) -> M3 {
    let mut r = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            r[i][j] = p[at + 3 * i + j];
        }
    }
    r
}

fn point_of(p: &[f64; NPOSE], k: usize) -> V3 {
    let a = 18 + 3 * k;
    [p[a], p[a + 1], p[a + 2]]
}

/// The axial vector of the skew part of `s` (s = [w]x for a skew matrix).
fn vee(s: &M3) -> V3 {
    [
        0.5 * (s[2][1] - s[1][2]),
        0.5 * (s[0][2] - s[2][0]),
        0.5 * (s[1][0] - s[0][1]),
    ]
}

/// `a b^T` for flat 3x3 blocks read as matrices.
fn mul_bt(a: &M3, b: &M3) -> M3 {
    let mut c = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            c[i][j] = a[i][0] * b[j][0] + a[i][1] * b[j][1] + a[i][2] * b[j][2];
        }
    }
    c
}

/// Constant geometry and data of one run.
pub struct Model {
    pub d: Data,
    /// Joint relative to the front cg, front axes.
    joint_f: V3,
    /// Rear cg relative to the joint, rear axes; rear mass and inertia about its cg.
    rear_cg: V3,
    m_r: f64,
    i_r: M3,
    i_f: M3,
    /// Wheel centres: FL, FR in front axes from the front cg; RL, RR in rear axes from the
    /// joint.
    wheel: [V3; 4],
    cab: V3,
    mount_f: [V3; 2],
    mount_h: [V3; 2],
    l0: f64,
    /// Static tire deflections front, rear (m).
    defl: [f64; 2],
    rolling_ff: f64,
    /// The front struts with the HPS: the strut, the static travel (m), its static states.
    hps: Option<(VehicleStrut, f64, [f64; STRUT_STATES])>,
    pub run: RunInput,
}

/// What one run is driven by.
pub struct RunInput {
    /// Target speed (m/s).
    pub speed: f64,
    /// The driver's throttle: setpoint swing (m/s) and period (s), if hidden.
    pub throttle: Option<(f64, f64)>,
    /// Extra lateral compliance of the tires (m/N), if hidden.
    pub compliance_m_per_n: f64,
    /// Steering: the path-following driver (offset to the right, m; negative left) or a
    /// steering-wheel history (time s, angle rad), or none.
    pub steer: Steering,
    /// The cam bases of the left and right tracks (rides), `None` on smooth ground.
    pub ground: Option<[CamTrack; 2]>,
}

/// How the steering wheel moves.
#[derive(Debug, Clone, PartialEq)]
pub enum Steering {
    /// Held straight.
    None,
    /// The pure-pursuit driver on the V3 course with this offset (m, right positive).
    Driver(f64),
    /// A steering-wheel history (s, rad), linear between samples.
    Table(Vec<f64>, Vec<f64>),
}

/// The base of a cam of radius R sliding along one track, on a uniform grid from s = 0.
pub struct CamTrack {
    dx: f64,
    base: Vec<f64>,
}

impl CamTrack {
    /// The lowest point of a circle of radius `r` resting on the profile `z` (spacing
    /// `dx`), at every profile sample.
    pub fn new(z: &[f64], dx: f64, r: f64) -> Self {
        let w = (r / dx).floor() as isize;
        let n = z.len() as isize;
        let base = (0..n)
            .map(|k| {
                let mut best = f64::NEG_INFINITY;
                for m in (k - w).max(0)..=(k + w).min(n - 1) {
                    let xi = (m - k) as f64 * dx;
                    let h = z[m as usize] - (r - (r * r - xi * xi).max(0.0).sqrt());
                    best = best.max(h);
                }
                best
            })
            .collect();
        Self { dx, base }
    }

    /// Deflection (Eq 6.1) and slope (Eq 6.3) of a wheel of free radius `r` with its centre
    /// at height `z_c` over path coordinate `s`: two cams at `s -+ a`, `a` the half contact
    /// length of the circle at the central cam's deflection; `z_oi` the mean of their
    /// bases (Eq 6.2).
    pub fn contact(&self, s: f64, z_c: f64, r: f64) -> (f64, f64) {
        let b0 = self.at(s);
        let d0 = r - (z_c - b0);
        let half = if d0 > 0.0 {
            (r * r - (r - d0) * (r - d0)).max(0.0).sqrt()
        } else {
            0.0
        };
        let (zoi, theta) = if half < 1e-4 {
            (b0, 0.0)
        } else {
            let (z1, z2) = (self.at(s - half), self.at(s + half));
            (0.5 * (z1 + z2), ((z2 - z1) / (2.0 * half)).atan())
        };
        ((zoi - (z_c - r)) / theta.cos(), theta)
    }

    /// Base height at `s`, linear between the samples.
    fn at(&self, s: f64) -> f64 {
        let f = (s / self.dx).max(0.0);
        let i = (f.floor() as usize).min(self.base.len() - 2);
        let t = (f - i as f64).min(1.0);
        self.base[i] + t * (self.base[i + 1] - self.base[i])
    }
}

/// What one evaluation reports besides the derivatives.
#[derive(Debug, Clone, Copy, Default)]
pub struct Outputs {
    pub steer_rad: f64,
    pub speed: f64,
    pub theta: f64,
    pub d_left: f64,
    pub pc: f64,
    pub pr: f64,
    /// Front-unit body rates (rad/s) and angular accelerations (rad/s^2).
    pub rate_body: V3,
    pub ang_acc_body: V3,
    /// Cab-point acceleration, front body axes, kinematic (m/s^2).
    pub cab_acc_body: V3,
    /// Horizontal lateral acceleration of the front cg (left positive).
    pub front_lat: f64,
    /// Tire normal forces FL, FR, RL, RR (N).
    pub fz: [f64; 4],
    /// With the HPS: the front struts' travels (m, compression positive from the charge
    /// position), forces (N, with the end stop's) and piston-side pressures (Pa), left then
    /// right; zero with a rigid front axle.
    pub strut_travel: [f64; 2],
    pub strut_force: [f64; 2],
    pub strut_pc: [f64; 2],
}

impl Model {
    pub fn new(d: Data, run: RunInput) -> Self {
        let h_j = d.joint_height;
        let joint_f = [-d.front_cg_to_joint, 0.0, h_j - d.front_cg_height];
        let (m_r, x_r, z_r, i_r) = d.rear_body();
        let rear_cg = [-x_r, 0.0, z_r - h_j];
        let i_f = [
            [d.front_inertia[0], 0.0, 0.0],
            [0.0, d.front_inertia[1], 0.0],
            [0.0, 0.0, d.front_inertia[2]],
        ];
        let loads = d.static_tire_loads(m_r, x_r);
        let defl = [d.deflection(loads[0]), d.deflection(loads[1])];
        let r = d.radius;
        let ht = 0.5 * d.track;
        let fx = d.front_axle_to_joint - d.front_cg_to_joint;
        let fz = r - defl[0] - d.front_cg_height;
        let rz_ = r - defl[1] - h_j;
        let wheel = [
            [fx, ht, fz],
            [fx, -ht, fz],
            [-d.rear_axle_to_joint, ht, rz_],
            [-d.rear_axle_to_joint, -ht, rz_],
        ];
        let cab = [
            d.cab_point[0] - d.front_cg_to_joint,
            d.cab_point[1],
            d.cab_point[2] - d.front_cg_height,
        ];
        let s = &d.steering;
        let phi = (90.0 - s.a0_deg).to_radians();
        let mount_f = [
            add(&joint_f, &[s.l1 * phi.cos(), s.l1 * phi.sin(), 0.0]),
            add(&joint_f, &[s.l1 * phi.cos(), -s.l1 * phi.sin(), 0.0]),
        ];
        let mount_h = [[0.0, s.l2, 0.0], [0.0, -s.l2, 0.0]];
        let a0 = s.a0_deg.to_radians();
        let l0 = (s.l1 * s.l1 + s.l2 * s.l2 - 2.0 * s.l1 * s.l2 * a0.cos()).sqrt();
        let mean_load = 0.5 * (loads[0] + loads[1]);
        // the drive's feed-forward: the rolling-resistance force f_r F_z of the mean static
        // load times the lever arm of a contact force about the axle (the loaded radius),
        // or the free radius of the rolling-resistance moment (`feed_forward_free_radius`)
        let lever = if d.feed_forward_free_radius {
            r
        } else {
            r - 0.5 * (defl[0] + defl[1])
        };
        let rolling_ff = d.rolling_resistance * lever * mean_load;
        // the struts carry the front tire load less the wheel end's weight at rest
        let hps = d.hps.map(|h| {
            let strut = VehicleStrut::new(&h.strut, h.gas_tau_s);
            let (z, states) = strut.static_state(loads[0] - h.wheel_end_mass * d.gravity);
            (strut, z, states)
        });
        Self {
            d,
            joint_f,
            rear_cg,
            m_r,
            i_r,
            i_f,
            wheel,
            cab,
            mount_f,
            mount_h,
            l0,
            defl,
            rolling_ff,
            hps,
            run,
        }
    }

    /// The pose at angles `a` = (yaw, pitch, roll, theta, rear roll) and carrier travels
    /// `c` (left, right).
    fn pose(&self, a: &[f64], c: &[f64]) -> [f64; NPOSE] {
        let rf = mul(&mul(&rz(a[0]), &ry(a[1])), &rx(a[2]));
        let rh = mul(&rf, &rz(a[3]));
        let rr = mul(&rh, &rx(a[4]));
        let mut p = [0.0; NPOSE];
        for i in 0..3 {
            for j in 0..3 {
                p[3 * i + j] = rf[i][j];
                p[9 + 3 * i + j] = rr[i][j];
            }
        }
        let joint = mv(&rf, &self.joint_f);
        let mut put = |k: usize, v: V3| {
            p[18 + 3 * k..21 + 3 * k].copy_from_slice(&v);
        };
        put(0, add(&joint, &mv(&rr, &self.rear_cg)));
        put(1, mv(&rf, &add(&self.wheel[0], &[0.0, 0.0, c[0]])));
        put(2, mv(&rf, &add(&self.wheel[1], &[0.0, 0.0, c[1]])));
        put(3, add(&joint, &mv(&rr, &self.wheel[2])));
        put(4, add(&joint, &mv(&rr, &self.wheel[3])));
        put(5, mv(&rf, &self.cab));
        put(6, mv(&rf, &self.mount_f[0]));
        put(7, mv(&rf, &self.mount_f[1]));
        put(8, add(&joint, &mv(&rh, &self.mount_h[0])));
        put(9, add(&joint, &mv(&rh, &self.mount_h[1])));
        put(10, mv(&rf, &self.wheel[0]));
        put(11, mv(&rf, &self.wheel[1]));
        p
    }

    /// The initial state at the target speed (module docs).
    pub fn initial(&self) -> [f64; N] {
        let mut y = [0.0; N];
        y[2] = self.d.front_cg_height;
        y[U] = self.run.speed;
        let r = self.d.radius;
        for i in 0..4 {
            y[SPIN + i] = self.run.speed / (r - self.defl[i / 2]);
        }
        y[PC] = self.d.steering.standby;
        y[PR] = self.d.steering.standby;
        if let Some((_, _, states)) = &self.hps {
            for side in 0..2 {
                let at = HPS + side * STRUT_STATES;
                y[at..at + STRUT_STATES].copy_from_slice(states);
            }
        }
        y
    }

    /// The integration step: [`STEP_S`], or [`STEP_HPS_S`] with the HPS.
    pub fn step(&self) -> f64 {
        if self.hps.is_some() {
            STEP_HPS_S
        } else {
            STEP_S
        }
    }

    /// The static travel of the front struts (m, compression positive from the charge
    /// position) and their static states, with the HPS.
    pub fn strut_static(&self) -> Option<(f64, [f64; STRUT_STATES])> {
        self.hps.as_ref().map(|(_, z, s)| (*z, *s))
    }

    fn steer_at(&self, t: f64, y: &[f64; N]) -> f64 {
        match &self.run.steer {
            Steering::None => 0.0,
            Steering::Driver(_) => y[STEER],
            Steering::Table(ts, xs) => {
                if t <= ts[0] {
                    return xs[0];
                }
                let k = ts.partition_point(|v| *v <= t);
                if k >= ts.len() {
                    return xs[xs.len() - 1];
                }
                let (t0, t1) = (ts[k - 1], ts[k]);
                xs[k - 1] + (xs[k] - xs[k - 1]) * (t - t0) / (t1 - t0)
            }
        }
    }

    /// Valve law in table units: L/min per unit opening at dp (bar).
    fn valve_lpm(&self, dp_bar: f64) -> f64 {
        let s = &self.d.steering;
        s.am * dp_bar / (dp_bar.abs() + SQRT_REG_BAR).sqrt()
            + s.av * dp_bar * (s.a0_per_bar * dp_bar.abs()).exp()
    }

    /// Derivatives at (t, y); with `out`, the recorded quantities too.
    pub fn rhs(&self, t: f64, y: &[f64; N], dy: &mut [f64; N], out: Option<&mut Outputs>) {
        let d = &self.d;
        let a = &y[3..CARRIER];
        let ua = &y[U + 3..U + CARRIER];
        let c = &y[CARRIER..NQ];
        let cd = &y[U + CARRIER..U + NQ];
        let origin = [y[0], y[1], y[2]];
        let p0 = self.pose(a, c);
        // Jacobians of the pose with respect to the five angles
        let jac = self.pose_jacobian(a, c);
        // velocity-product terms: second directional differences along the angle rates
        let eps = 1e-3;
        let mut ap = [0.0; NA];
        let mut am = [0.0; NA];
        for j in 0..NA {
            ap[j] = a[j] + eps * ua[j];
            am[j] = a[j] - eps * ua[j];
        }
        let (pp, pm) = (self.pose(&ap, c), self.pose(&am, c));
        let mut first = [0.0; NPOSE];
        let mut second = [0.0; NPOSE];
        for k in 0..NPOSE {
            first[k] = (pp[k] - pm[k]) / (2.0 * eps);
            second[k] = (pp[k] - 2.0 * p0[k] + pm[k]) / (eps * eps);
        }
        // angular-velocity Jacobians and bias accelerations of the two units
        let omega_cols = |at: usize| -> [V3; NA] {
            let r = rot_of(&p0, at);
            let mut c = [[0.0; 3]; NA];
            for j in 0..NA {
                let dr = rot_of(&jac[j], at);
                c[j] = vee(&mul_bt(&dr, &r));
            }
            c
        };
        let wf_cols = omega_cols(0);
        let wr_cols = omega_cols(9);
        let ang_bias = |at: usize| -> V3 {
            let r = rot_of(&p0, at);
            let r1 = rot_of(&first, at);
            let r2 = rot_of(&second, at);
            let s1 = mul_bt(&r2, &r);
            let s2 = mul_bt(&r1, &r1);
            let mut s = [[0.0; 3]; 3];
            for i in 0..3 {
                for j in 0..3 {
                    s[i][j] = s1[i][j] + s2[i][j];
                }
            }
            vee(&s)
        };
        let point_col = |k: usize, j: usize| -> V3 {
            let a = 18 + 3 * k;
            [jac[j][a], jac[j][a + 1], jac[j][a + 2]]
        };
        // the front unit's z axis (world), the carriers' direction
        let ez = [p0[2], p0[5], p0[8]];
        let point_vel = |k: usize| -> V3 {
            let mut v = [y[U], y[U + 1], y[U + 2]];
            for j in 0..NA {
                v = add(&v, &scale(&point_col(k, j), ua[j]));
            }
            if self.hps.is_some() && (k == 1 || k == 2) {
                v = add(&v, &scale(&ez, cd[k - 1]));
            }
            v
        };
        let point_bias = |k: usize| -> V3 {
            let a = 18 + 3 * k;
            [second[a], second[a + 1], second[a + 2]]
        };
        let omega = |cols: &[V3; NA]| -> V3 {
            let mut w = [0.0; 3];
            for j in 0..NA {
                w = add(&w, &scale(&cols[j], ua[j]));
            }
            w
        };
        let rf = rot_of(&p0, 0);
        let rr = rot_of(&p0, 9);
        let wf = omega(&wf_cols);
        let wr = omega(&wr_cols);

        let mut mm = [[0.0; NQ]; NQ];
        let mut q = [0.0; NQ];
        // generalized force of a world force at point k (None: the front cg)
        let force_at = |q: &mut [f64; NQ], k: Option<usize>, f: &V3| {
            q[0] += f[0];
            q[1] += f[1];
            q[2] += f[2];
            if let Some(k) = k {
                for j in 0..NA {
                    q[3 + j] += dot(f, &point_col(k, j));
                }
            }
        };
        let moment_on = |q: &mut [f64; NQ], cols: &[V3; NA], m: &V3| {
            for j in 0..NA {
                q[3 + j] += dot(m, &cols[j]);
            }
        };

        // ---- inertia and gravity (Kane): front unit
        let g = d.gravity;
        {
            let iw = mul(&mul(&rf, &self.i_f), &transpose(&rf));
            for i in 0..3 {
                mm[i][i] += d.front_mass;
            }
            for i in 0..NA {
                for j in 0..NA {
                    mm[3 + i][3 + j] += dot(&wf_cols[i], &mv(&iw, &wf_cols[j]));
                }
            }
            let ab = ang_bias(0);
            let iw_w = mv(&iw, &wf);
            let m_in = add(&mv(&iw, &ab), &cross(&wf, &iw_w));
            moment_on(&mut q, &wf_cols, &scale(&m_in, -1.0));
            force_at(&mut q, None, &[0.0, 0.0, -d.front_mass * g]);
        }
        // rear unit with payload
        {
            let iw = mul(&mul(&rr, &self.i_r), &transpose(&rr));
            let mut jv = [[0.0; NQ]; 3];
            for i in 0..3 {
                jv[i][i] = 1.0;
                for j in 0..NA {
                    jv[i][3 + j] = point_col(0, j)[i];
                }
            }
            for i in 0..NQ {
                for j in 0..NQ {
                    mm[i][j] += self.m_r
                        * (jv[0][i] * jv[0][j] + jv[1][i] * jv[1][j] + jv[2][i] * jv[2][j]);
                }
            }
            for i in 0..NA {
                for j in 0..NA {
                    mm[3 + i][3 + j] += dot(&wr_cols[i], &mv(&iw, &wr_cols[j]));
                }
            }
            let ab = ang_bias(9);
            let iw_w = mv(&iw, &wr);
            let m_in = add(&mv(&iw, &ab), &cross(&wr, &iw_w));
            moment_on(&mut q, &wr_cols, &scale(&m_in, -1.0));
            let f = add(
                &[0.0, 0.0, -self.m_r * g],
                &scale(&point_bias(0), -self.m_r),
            );
            force_at(&mut q, Some(0), &f);
        }

        // ---- front wheel ends on their carriers and the HPS struts (Chapter 5, Table 6.3)
        // between the unit and each carrier
        let mut struts = [[0.0; 2]; 3];
        match (&self.hps, &d.hps) {
            (Some((strut, z_static, _)), Some(h)) => {
                let mw = h.wheel_end_mass;
                let ez_dot = [first[2], first[5], first[8]];
                for side in 0..2 {
                    // the wheel end is part of the Table 6.1 unit at its static place (point
                    // 10 + side): taken out there, put in on its carrier (point 1 + side)
                    for (k, sign, on_carrier) in [(10 + side, -1.0, false), (1 + side, 1.0, true)] {
                        let mut jv = [[0.0; NQ]; 3];
                        for i in 0..3 {
                            jv[i][i] = 1.0;
                            for j in 0..NA {
                                jv[i][3 + j] = point_col(k, j)[i];
                            }
                            if on_carrier {
                                jv[i][CARRIER + side] = ez[i];
                            }
                        }
                        for i in 0..NQ {
                            for j in 0..NQ {
                                mm[i][j] += sign
                                    * mw
                                    * (jv[0][i] * jv[0][j]
                                        + jv[1][i] * jv[1][j]
                                        + jv[2][i] * jv[2][j]);
                            }
                        }
                        // velocity-product acceleration: the angle rates' (second
                        // differences) and the carrier's Coriolis term 2 (d e_z/dt) c'
                        let mut bias = point_bias(k);
                        if on_carrier {
                            bias = add(&bias, &scale(&ez_dot, 2.0 * cd[side]));
                        }
                        let f = scale(&add(&[0.0, 0.0, -g], &scale(&bias, -1.0)), sign * mw);
                        for i in 0..NQ {
                            q[i] += jv[0][i] * f[0] + jv[1][i] * f[1] + jv[2][i] * f[2];
                        }
                    }
                    let z = z_static + c[side];
                    let at = HPS + side * STRUT_STATES;
                    let ys = &y[at..at + STRUT_STATES];
                    strut.rhs(z, cd[side], ys, &mut dy[at..at + STRUT_STATES]);
                    let f =
                        strut.force(z, cd[side], ys) + h.end_stop(z, cd[side], strut.data().travel);
                    // compressive positive: it pushes the unit up and the carrier down, an
                    // internal force of the carrier's slide (its generalized force only)
                    q[CARRIER + side] -= f;
                    struts[0][side] = z;
                    struts[1][side] = f;
                    struts[2][side] = ys[0] * 1e6;
                }
            }
            _ => {
                // rigid front axle: the carriers held at zero, no strut states
                for k in CARRIER..NQ {
                    mm[k][k] = 1.0;
                }
                dy[HPS..].fill(0.0);
            }
        }

        // ---- steering struts (Eqs 6.6-6.8) and hydraulics (Eqs 3.5-3.12)
        let s = &d.steering;
        let steer = self.steer_at(t, y);
        let mut ext = [0.0; 2];
        let mut rate = [0.0; 2];
        let mut axis = [[0.0; 3]; 2];
        for k in 0..2 {
            let pf = point_of(&p0, 6 + k);
            let ph = point_of(&p0, 8 + k);
            let dl = [pf[0] - ph[0], pf[1] - ph[1], pf[2] - ph[2]];
            let l = dot(&dl, &dl).sqrt();
            let e = scale(&dl, 1.0 / l);
            let vf = point_vel(6 + k);
            let vh = point_vel(8 + k);
            rate[k] = dot(&e, &[vf[0] - vh[0], vf[1] - vh[1], vf[2] - vh[2]]);
            ext[k] = l - self.l0;
            axis[k] = e;
        }
        let (pc, pr) = (y[PC], y[PR]);
        let v1 = (s.v0 + s.ac * ext[0] - s.ar * ext[1]).max(0.02 * s.v0);
        let v2 = (s.v0 - s.ar * ext[0] + s.ac * ext[1]).max(0.02 * s.v0);
        let dv1 = s.ac * rate[0] - s.ar * rate[1];
        let dv2 = -s.ar * rate[0] + s.ac * rate[1];
        let q_leak = (2.0 * s.kl0 + s.kl * (rate[0].abs() + rate[1].abs())) * (pc - pr);
        let x = steer.to_degrees() - y[THETA_H];
        let xi = ((x.abs() - s.x0_deg) / (s.xlim_deg - s.x0_deg)).clamp(0.0, 1.0);
        let (mut in_c, mut in_r, mut q_g) = (0.0, 0.0, 0.0);
        if xi > 0.0 {
            let supply = |p_fed: f64| -> f64 {
                let dp = s.ps - p_fed;
                if dp <= 0.0 {
                    0.0
                } else {
                    xi * self.valve_lpm(dp / 1e5) / 60.0e3
                }
            };
            if x > 0.0 {
                let qs = supply(pc);
                in_c = qs;
                in_r = -s.kv * xi * self.valve_lpm((pr - s.p0) / 1e5) / 60.0e3;
                q_g = qs;
            } else {
                let qs = supply(pr);
                in_r = qs;
                in_c = -s.kv * xi * self.valve_lpm((pc - s.p0) / 1e5) / 60.0e3;
                q_g = -qs;
            }
        }
        dy[THETA_H] = q_g * 1e6 / (s.ktheta_ml_deg * s.eta_g);
        let net_c = in_c - dv1 - q_leak;
        let net_r = in_r - dv2 + q_leak;
        let taper = |p: f64, net: f64| -> f64 {
            if net < 0.0 && d.cavitation {
                ((p - P_CAV) / CAV_TAPER).clamp(0.0, 1.0)
            } else {
                1.0
            }
        };
        dy[PC] = s.bulk * taper(pc, net_c) / v1 * net_c;
        dy[PR] = s.bulk * taper(pr, net_r) / v2 * net_r;
        let forces = [
            s.ac * pc - s.ar * pr - s.mu_v * rate[0],
            s.ac * pr - s.ar * pc - s.mu_v * rate[1],
        ];
        for k in 0..2 {
            let f = scale(&axis[k], forces[k]);
            for j in 0..NA {
                q[3 + j] += dot(&f, &point_col(6 + k, j)) - dot(&f, &point_col(8 + k, j));
            }
        }

        // ---- tires (section 6.2.2) and the drive
        let mut speed = 0.0;
        let mut fzs = [0.0; 4];
        let target = self.run.speed
            + self.run.throttle.map_or(0.0, |(amp, per)| {
                amp * (std::f64::consts::TAU * t / per).sin()
            });
        // the controlled speed: the mean forward speed of the wheel centres in their
        // contact planes (the cams' lines)
        let mut contacts = [(0.0, 0.0); 4];
        let mut vx_sum = 0.0;
        for i in 0..4 {
            let r_unit = if i < 2 { &rf } else { &rr };
            let c = add(&origin, &point_of(&p0, 1 + i));
            contacts[i] = match &self.run.ground {
                None => (d.radius - c[2], 0.0),
                Some(tracks) => tracks[i % 2].contact(START_S_M + c[0], c[2], d.radius),
            };
            let v = point_vel(1 + i);
            let hx = [r_unit[0][0], r_unit[1][0]];
            let hn = (hx[0] * hx[0] + hx[1] * hx[1]).sqrt();
            let th = contacts[i].1;
            vx_sum += th.cos() * (v[0] * hx[0] + v[1] * hx[1]) / hn + th.sin() * v[2];
        }
        speed += 0.25 * vx_sum;
        let error = target - speed;
        let torque =
            (self.rolling_ff + d.kp * error + d.ki * y[PI_INT]).clamp(-d.max_torque, d.max_torque);
        dy[PI_INT] = error;
        for i in 0..4 {
            let r_unit = if i < 2 { &rf } else { &rr };
            let v = point_vel(1 + i);
            let hx = [r_unit[0][0], r_unit[1][0]];
            let hn = (hx[0] * hx[0] + hx[1] * hx[1]).sqrt();
            let xt = [hx[0] / hn, hx[1] / hn, 0.0];
            let yt = [-xt[1], xt[0], 0.0];
            let e_a = [r_unit[0][1], r_unit[1][1], r_unit[2][1]];
            let r0 = d.radius;
            // enveloping: the cam bases under the wheel (Eqs 6.1-6.3)
            let (defl, theta_s) = contacts[i];
            let cth = theta_s.cos();
            if defl <= 0.0 {
                // airborne: the lags relax towards zero, the spin keeps its drive
                dy[KAPPA + i] = -y[KAPPA + i] * y[U].abs().max(V_MIN) / d.relax_x;
                dy[ALPHA + i] = -y[ALPHA + i] * y[U].abs().max(V_MIN) / d.relax_y;
                dy[SPIN + i] = torque / d.spin_inertia;
                continue;
            }
            // the wheel centre's approach to the cams' line along its normal
            let defl_rate = dot(&v, &xt) * theta_s.sin() - v[2] * cth;
            let fz = (d.load_curve(defl) + d.tire_damping * defl_rate).max(0.0);
            fzs[i] = fz;
            // contact frame tilted by the effective slope along the wheel's heading
            let n = [-theta_s.sin() * xt[0], -theta_s.sin() * xt[1], cth];
            let xc = [cth * xt[0], cth * xt[1], theta_s.sin()];
            let vx = dot(&v, &xc);
            let vy = dot(&v, &yt);
            let rl = r0 - defl;
            let den = vx.abs().max(V_MIN);
            let kappa_ss = (y[SPIN + i] * rl - vx) / den;
            let alpha_ss = vy.atan2(den);
            let c_alpha = d.cornering_stiffness(fz);
            let sigma_y = d.relax_y + self.run.compliance_m_per_n * c_alpha;
            dy[KAPPA + i] = (kappa_ss - y[KAPPA + i]) * den / d.relax_x;
            dy[ALPHA + i] = (alpha_ss - y[ALPHA + i]) * den / sigma_y;
            let (fx, fy_abs, mz) = if d.horizontal_forces {
                d.fiala(fz, y[KAPPA + i], y[ALPHA + i], c_alpha)
            } else {
                (0.0, 0.0, 0.0)
            };
            let fy = -fy_abs;
            let f = add(&add(&scale(&xc, fx), &scale(&yt, fy)), &scale(&n, fz));
            let rc = scale(&n, -rl);
            let m_rr = -d.rolling_resistance * r0 * fz * (y[SPIN + i] / 0.1).tanh();
            let m_ext = add(&cross(&rc, &f), &add(&scale(&n, mz), &scale(&e_a, m_rr)));
            let about_axle = dot(&m_ext, &e_a);
            dy[SPIN + i] = (about_axle + torque) / d.spin_inertia;
            // the body: the force at the centre, the moments but the one about the axle,
            // the drive's reaction
            // and the gyroscopic reaction of the spinning wheel turned with its unit
            let w_unit = if i < 2 { &wf } else { &wr };
            let gyro = cross(w_unit, &scale(&e_a, d.spin_inertia * y[SPIN + i]));
            let m_body = add(
                &add(&m_ext, &scale(&e_a, -about_axle - torque)),
                &scale(&gyro, -1.0),
            );
            force_at(&mut q, Some(1 + i), &f);
            if i < 2 && self.hps.is_some() {
                q[CARRIER + i] += dot(&f, &ez);
            }
            moment_on(&mut q, if i < 2 { &wf_cols } else { &wr_cols }, &m_body);
        }

        // ---- solve M u' = Q
        let acc = solve(mm, q);
        dy[..NQ].copy_from_slice(&y[U..U + NQ]);
        dy[U..U + NQ].copy_from_slice(&acc);

        // ---- driver (section 3.4.1): pure pursuit on the front-axle centre
        let axle = {
            let a0 = point_of(&p0, 1);
            let a1 = point_of(&p0, 2);
            [
                origin[0] + 0.5 * (a0[0] + a1[0]),
                origin[1] + 0.5 * (a0[1] + a1[1]),
            ]
        };
        let heading = rf[1][0].atan2(rf[0][0]);
        dy[STEER] = 0.0;
        if let Steering::Driver(offset) = self.run.steer {
            let x0 = d.front_axle_to_joint - d.front_cg_to_joint;
            let xc = axle[0] - x0;
            let yc = -axle[1];
            let psi = -heading;
            let ld = (d.preview_time * speed).max(d.min_preview);
            let (px, py) = (xc + ld, course_offset(xc + ld, offset));
            let (ddx, ddy) = (px - xc, py - yc);
            let eta = ddy.atan2(ddx) - psi;
            let dist = (ddx * ddx + ddy * ddy).sqrt().max(1e-6);
            let kappa = 2.0 * eta.sin() / dist;
            let ka = kappa * d.front_axle_to_joint;
            let arg = (kappa * d.rear_axle_to_joint / (1.0 + ka * ka).sqrt()).clamp(-1.0, 1.0);
            let desired = ka.atan() + arg.asin();
            dy[STEER] =
                (d.driver_gain * (desired - y[6])).clamp(-d.driver_max_rate, d.driver_max_rate);
        }

        if let Some(o) = out {
            // accelerations of the recorded points
            let mut alpha_f = ang_bias(0);
            let mut a_cab = add(&[acc[0], acc[1], acc[2]], &point_bias(5));
            for j in 0..NA {
                alpha_f = add(&alpha_f, &scale(&wf_cols[j], acc[3 + j]));
                a_cab = add(&a_cab, &scale(&point_col(5, j), acc[3 + j]));
            }
            let hx = [rf[0][0], rf[1][0]];
            let hn = (hx[0] * hx[0] + hx[1] * hx[1]).sqrt();
            *o = Outputs {
                steer_rad: steer,
                speed,
                theta: y[6],
                d_left: ext[0],
                pc,
                pr,
                rate_body: mtv(&rf, &wf),
                ang_acc_body: mtv(&rf, &alpha_f),
                cab_acc_body: mtv(&rf, &a_cab),
                front_lat: (-hx[1] * acc[0] + hx[0] * acc[1]) / hn,
                fz: fzs,
                strut_travel: struts[0],
                strut_force: struts[1],
                strut_pc: struts[2],
            };
        }
    }

    /// The pose's Jacobian with respect to the five angles `a`, by central differences
    /// (step 1e-6 rad): row `j` is the derivative of every pose entry along angle `j`.
    fn pose_jacobian(&self, a: &[f64], c: &[f64]) -> [[f64; NPOSE]; NA] {
        let h = 1e-6;
        let mut jac = [[0.0; NPOSE]; NA];
        for j in 0..NA {
            let mut ap = [0.0; NA];
            let mut am = [0.0; NA];
            ap.copy_from_slice(a);
            am.copy_from_slice(a);
            ap[j] += h;
            am[j] -= h;
            let (pp, pm) = (self.pose(&ap, c), self.pose(&am, c));
            for k in 0..NPOSE {
                jac[j][k] = (pp[k] - pm[k]) / (2.0 * h);
            }
        }
        jac
    }

    /// Kinetic, gravitational, tire-spring and hydraulic energy (J) at `y` (the energy
    /// check; tires on smooth ground); with the HPS also the wheel ends' motion on their
    /// carriers and the struts' stored energy, which is written for the lossless strut
    /// only ([`VehicleStrut::lossless_work`], from the static travel; within the travel).
    pub fn energy(&self, y: &[f64; N]) -> f64 {
        let d = &self.d;
        let a = &y[3..CARRIER];
        let ua = &y[U + 3..U + CARRIER];
        let p0 = self.pose(a, &y[CARRIER..NQ]);
        let jac = self.pose_jacobian(a, &y[CARRIER..NQ]);
        let mut v = [0.0f64; NPOSE];
        for j in 0..NA {
            for k in 0..NPOSE {
                v[k] += jac[j][k] * ua[j];
            }
        }
        let rf = rot_of(&p0, 0);
        let rr = rot_of(&p0, 9);
        let wf = vee(&mul_bt(&rot_of(&v, 0), &rf));
        let wr = vee(&mul_bt(&rot_of(&v, 9), &rr));
        let i_fw = mul(&mul(&rf, &self.i_f), &transpose(&rf));
        let i_rw = mul(&mul(&rr, &self.i_r), &transpose(&rr));
        let vf = [y[U], y[U + 1], y[U + 2]];
        let vr = add(&vf, &point_of(&v, 0));
        let kin = 0.5 * d.front_mass * dot(&vf, &vf)
            + 0.5 * dot(&wf, &mv(&i_fw, &wf))
            + 0.5 * self.m_r * dot(&vr, &vr)
            + 0.5 * dot(&wr, &mv(&i_rw, &wr))
            + (0..4)
                .map(|i| 0.5 * d.spin_inertia * y[SPIN + i] * y[SPIN + i])
                .sum::<f64>();
        let rear_z = y[2] + point_of(&p0, 0)[2];
        let grav = d.gravity * (d.front_mass * y[2] + self.m_r * rear_z);
        let mut tire = 0.0;
        for i in 0..4 {
            let cz = y[2] + point_of(&p0, 1 + i)[2];
            let defl = d.radius - cz;
            if defl > 0.0 {
                tire += d.load_energy(defl);
            }
        }
        let s = &d.steering;
        let mut ext = [0.0; 2];
        for k in 0..2 {
            let pf = point_of(&p0, 6 + k);
            let ph = point_of(&p0, 8 + k);
            let dl = [pf[0] - ph[0], pf[1] - ph[1], pf[2] - ph[2]];
            ext[k] = dot(&dl, &dl).sqrt() - self.l0;
        }
        // closed groups with dp = -B dV / V: U(V) = -p0 (V - V0) + B (V ln(V/V0) - V + V0)
        let hyd = |v: f64, p: f64| -> f64 {
            // the reference state of each group is its volume at the standby pressure
            let v_ref = v * ((p - s.standby) / s.bulk).exp();
            -s.standby * (v - v_ref) + s.bulk * (v * (v / v_ref).ln() - v + v_ref)
        };
        let v1 = s.v0 + s.ac * ext[0] - s.ar * ext[1];
        let v2 = s.v0 - s.ar * ext[0] + s.ac * ext[1];
        let mut suspension = 0.0;
        if let (Some((strut, z_static, states)), Some(h)) = (&self.hps, &d.hps) {
            let mw = h.wheel_end_mass;
            let ez = [rf[0][2], rf[1][2], rf[2][2]];
            for side in 0..2 {
                // the wheel end out of the unit at its static place, in on its carrier
                let v0 = add(&vf, &point_of(&v, 10 + side));
                let vw = add(
                    &add(&vf, &point_of(&v, 1 + side)),
                    &scale(&ez, y[U + CARRIER + side]),
                );
                suspension += 0.5 * mw * (dot(&vw, &vw) - dot(&v0, &v0))
                    + mw * d.gravity * (point_of(&p0, 1 + side)[2] - point_of(&p0, 10 + side)[2]);
                let c = y[CARRIER + side];
                suspension += strut.lossless_work(*z_static, states, z_static + c, 50);
            }
        }
        kin + grav + tire + hyd(v1, y[PC]) + hyd(v2, y[PR]) + suspension
    }
}

fn transpose(a: &M3) -> M3 {
    [
        [a[0][0], a[1][0], a[2][0]],
        [a[0][1], a[1][1], a[2][1]],
        [a[0][2], a[1][2], a[2][2]],
    ]
}

/// The V3 course (yaw-plane course of docs): 20 m approach, then a half-cosine offset of
/// `offset` m (right positive) over 18 m.
pub fn course_offset(x: f64, offset: f64) -> f64 {
    let (approach, gate) = (20.0, 18.0);
    if x <= approach {
        0.0
    } else if x >= approach + gate {
        offset
    } else {
        0.5 * offset * (1.0 - (std::f64::consts::PI * (x - approach) / gate).cos())
    }
}

/// Gaussian elimination with partial pivoting.
fn solve(mut a: [[f64; NQ]; NQ], mut b: [f64; NQ]) -> [f64; NQ] {
    for k in 0..NQ {
        let mut piv = k;
        for i in k + 1..NQ {
            if a[i][k].abs() > a[piv][k].abs() {
                piv = i;
            }
        }
        a.swap(k, piv);
        b.swap(k, piv);
        for i in k + 1..NQ {
            let f = a[i][k] / a[k][k];
            for j in k..NQ {
                a[i][j] -= f * a[k][j];
            }
            b[i] -= f * b[k];
        }
    }
    let mut x = [0.0; NQ];
    for k in (0..NQ).rev() {
        let mut s = b[k];
        for j in k + 1..NQ {
            s -= a[k][j] * x[j];
        }
        x[k] = s / a[k][k];
    }
    x
}

/// One RK4 step of `h` from `t`.
pub fn rk4(m: &Model, t: f64, y: &mut [f64; N], h: f64) {
    let (mut k1, mut k2, mut k3, mut k4) = ([0.0; N], [0.0; N], [0.0; N], [0.0; N]);
    let mut yt = [0.0; N];
    m.rhs(t, y, &mut k1, None);
    for i in 0..N {
        yt[i] = y[i] + 0.5 * h * k1[i];
    }
    m.rhs(t + 0.5 * h, &yt, &mut k2, None);
    for i in 0..N {
        yt[i] = y[i] + 0.5 * h * k2[i];
    }
    m.rhs(t + 0.5 * h, &yt, &mut k3, None);
    for i in 0..N {
        yt[i] = y[i] + h * k3[i];
    }
    m.rhs(t + h, &yt, &mut k4, None);
    for i in 0..N {
        y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
    if m.d.cavitation {
        y[PC] = y[PC].max(P_CAV);
        y[PR] = y[PR].max(P_CAV);
    }
    if let Some((strut, _, _)) = &m.hps {
        for side in 0..2 {
            let at = HPS + side * STRUT_STATES;
            strut.clamp(&mut y[at..at + STRUT_STATES]);
        }
    }
}

/// Simulate from `y0` for `duration` s, recording at `hz`: the outputs at each sample and
/// the state at the end.
pub fn simulate(
    m: &Model,
    y0: [f64; N],
    duration: f64,
    hz: f64,
) -> (Vec<f64>, Vec<Outputs>, [f64; N]) {
    let sub = ((1.0 / hz) / m.step()).round().max(1.0) as usize;
    let h = 1.0 / hz / sub as f64;
    let n_out = (duration * hz).round() as usize + 1;
    let mut y = y0;
    let mut dy = [0.0; N];
    let mut ts = Vec::with_capacity(n_out);
    let mut outs = Vec::with_capacity(n_out);
    for k in 0..n_out {
        let t = k as f64 / hz;
        let mut o = Outputs::default();
        m.rhs(t, &y, &mut dy, Some(&mut o));
        ts.push(t);
        outs.push(o);
        if k + 1 == n_out {
            break;
        }
        for j in 0..sub {
            rk4(m, t + j as f64 * h, &mut y, h);
        }
        assert!(
            y.iter().all(|v| v.is_finite()) && y[6].abs() < 1.0,
            "independent 3-D model diverged at t = {t}"
        );
    }
    (ts, outs, y)
}
