//! The independent vehicle's equations (Eqs 3.1-3.17 with the hidden effects) and their
//! fixed-step RK4 integration.

use super::*;

const N: usize = 12;
const P_CAV_MPA: f64 = 0.02;
const CAV_TAPER_MPA: f64 = 0.03;
const SQRT_REG_BAR: f64 = 0.02;
const COULOMB_V_S: f64 = 0.005;
const AIR_N: f64 = 1.2;
const P_ATM_MPA: f64 = 0.101_325;

/// Constants of one run, precomputed in working units.
struct Model {
    // mechanics (SI)
    m_f: f64,
    m_r: f64,
    i_f: f64,
    i_r: f64,
    l_f1: f64,
    l_f2: f64,
    l_r1: f64,
    l_r2: f64,
    c_f: f64,
    c_r: f64,
    kmz_f: f64,
    kmz_r: f64,
    half_track: f64,
    u: f64,
    lag: f64, // u / sigma (1/s)
    // hydraulics
    l1: f64,
    l2: f64,
    a0: f64,
    l0: f64,
    ac: f64, // m^2
    ar: f64, // m^2
    v0_l: f64,
    ps: f64,
    p0: f64,
    b_mpa: f64,
    mu_v: f64,           // N s/m
    kl0_l: f64,          // L/(s MPa)
    kl_l: f64,           // L/(s MPa) per (m/s)
    gerotor_ml_deg: f64, // k_theta eta_g
    kv: f64,
    x0: f64,
    xlim: f64,
    a0_bar: f64,
    am: f64,
    av: f64,
    hidden: YawHidden,
}

/// Valve orifice law in table units: flow (L/min) per unit normalised opening at dp (bar).
fn valve_lpm(m: &Model, dp_bar: f64) -> f64 {
    let turb = m.am * dp_bar / (dp_bar.abs() + SQRT_REG_BAR).sqrt();
    let lam = m.av * dp_bar * (m.a0_bar * dp_bar.abs()).exp();
    turb + lam
}

struct Aux {
    strut_left_disp: f64,
}

impl Model {
    fn new(p: &YawParams, hidden: YawHidden, speed: f64) -> Self {
        let v = &p.vehicle;
        let s = &p.steering;
        let kn_deg = 1.0e3 / DEG; // kN/deg -> N/rad
        let a0 = s.a0_deg * DEG;
        Self {
            m_f: v.m_f,
            m_r: v.m_r,
            i_f: v.i_f,
            i_r: v.i_r,
            l_f1: v.l_f1,
            l_f2: v.l_f2,
            l_r1: v.l_r1,
            l_r2: v.l_r2,
            c_f: v.c_f_kn_deg * kn_deg,
            c_r: v.c_r_kn_deg * kn_deg,
            kmz_f: v.kmz_f_knm_deg * kn_deg,
            kmz_r: v.kmz_r_knm_deg * kn_deg,
            half_track: v.half_track_m,
            u: speed,
            lag: speed / v.sigma_m,
            l1: s.l1_m,
            l2: s.l2_m,
            a0,
            l0: (s.l1_m * s.l1_m + s.l2_m * s.l2_m - 2.0 * s.l1_m * s.l2_m * a0.cos()).sqrt(),
            ac: s.ac_cm2 * 1e-4,
            ar: s.ar_cm2 * 1e-4,
            v0_l: s.v0_l,
            ps: s.ps_mpa,
            p0: s.p0_mpa,
            b_mpa: s.b_gpa * 1e3,
            mu_v: s.mu_v_kn_s_mm * 1e6,
            // m^3/(s Pa) -> L/(s MPa): x 1e3 L/m^3 x 1e6 Pa/MPa
            kl0_l: s.kl0 * 1e9,
            kl_l: s.kl * 1e9,
            gerotor_ml_deg: s.ktheta_ml_deg * s.eta_g,
            kv: s.kv,
            x0: s.x0_deg,
            xlim: s.xlim_deg,
            a0_bar: s.a0_per_bar,
            am: s.am,
            av: s.av,
            hidden,
        }
    }

    fn bulk(&self, p_mpa: f64) -> f64 {
        match self.hidden {
            YawHidden::EntrainedAir(alpha0) => {
                let p = p_mpa.max(P_CAV_MPA);
                let x = alpha0 / (1.0 - alpha0) * (P_ATM_MPA / p).powf(1.0 / AIR_N);
                (1.0 + x) / (1.0 / self.b_mpa + x / (AIR_N * p))
            }
            _ => self.b_mpa,
        }
    }

    /// Supply flow (L/s) into the fed group at pressure `p_fed` (MPa), with the inlet check
    /// valve and, if hidden, the supply droop solved by bisection.
    fn supply_flow(&self, xi: f64, p_fed: f64) -> f64 {
        let q_at = |ps_eff: f64| -> f64 {
            let dp = ps_eff - p_fed;
            if dp <= 0.0 {
                0.0
            } else {
                xi * valve_lpm(self, dp * 10.0) / 60.0
            }
        };
        match self.hidden {
            YawHidden::SupplyDroop(r) if r > 0.0 => {
                // q = q_at(P_s - r q); r in Pa s/m^3, q in L/s -> MPa drop r q 1e-3 1e-6
                let k = r * 1e-9;
                let (mut lo, mut hi) = (0.0, q_at(self.ps));
                if hi == 0.0 {
                    return 0.0;
                }
                for _ in 0..50 {
                    let mid = 0.5 * (lo + hi);
                    if mid - q_at(self.ps - k * mid) > 0.0 {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                0.5 * (lo + hi)
            }
            _ => q_at(self.ps),
        }
    }

    fn rhs(&self, t: f64, y: &[f64; N], steer: &Steer, dy: &mut [f64; N]) -> Aux {
        let (theta, v_f, r_f, r_r) = (y[0], y[1], y[2], y[3]);
        let u = self.u;
        let thd = r_f - r_r;

        // ---- joint kinematics, Eq 3.14
        let (s, c) = theta.sin_cos();
        let w = v_f - self.l_f2 * r_f; // joint lateral velocity, front frame
        let u_r = u * c - w * s;
        let v_r = u * s + w * c - self.l_r2 * r_r;

        // ---- tires, Eqs 3.15-3.17 (tires 1, 3 left: u + T phi)
        let tt = self.half_track;
        let vf_ax = v_f + self.l_f1 * r_f;
        let vr_ax = v_r - self.l_r1 * r_r;
        let steady = [
            -(vf_ax / (u + tt * r_f)).atan(),
            -(vf_ax / (u - tt * r_f)).atan(),
            -(vr_ax / (u_r + tt * r_r)).atan(),
            -(vr_ax / (u_r - tt * r_r)).atan(),
        ];
        for i in 0..4 {
            dy[4 + i] = (steady[i] - y[4 + i]) * self.lag;
        }
        let af = y[4] + y[5];
        let ar = y[6] + y[7];
        let (yf, yr) = (self.c_f * af, self.c_r * ar);
        let (mzf, mzr) = (self.kmz_f * af, self.kmz_r * ar);

        // ---- strut kinematics, Eqs 3.2, 3.8
        let p12 = self.l1 * self.l2;
        let q12 = self.l1 * self.l1 + self.l2 * self.l2;
        let (sl, cl) = (self.a0 + theta).sin_cos();
        let (sr, cr) = (self.a0 - theta).sin_cos();
        let len_l = (q12 - 2.0 * p12 * cl).sqrt();
        let len_r = (q12 - 2.0 * p12 * cr).sqrt();
        let h_l = p12 * sl / len_l;
        let h_r = p12 * sr / len_r;
        let d_l = len_l - self.l0;
        let d_r = len_r - self.l0;

        // ---- volumes, Eq 3.7 (litres)
        let v1 = (self.v0_l + 1e3 * (self.ac * d_l - self.ar * d_r)).max(0.02 * self.v0_l);
        let v2 = (self.v0_l - 1e3 * (self.ar * d_l - self.ac * d_r)).max(0.02 * self.v0_l);
        let dv1 = 1e3 * (self.ac * h_l + self.ar * h_r) * thd;
        let dv2 = -1e3 * (self.ar * h_l + self.ac * h_r) * thd;

        // ---- leakage, Eqs 3.5-3.6 (L/s)
        let (pc, pr) = (y[8], y[9]);
        let vel_l = h_l * thd; // left strut extension speed
        let vel_r = -h_r * thd; // right strut extension speed
        let k_sum = 2.0 * self.kl0_l + self.kl_l * (vel_l.abs() + vel_r.abs());
        let q_leak = k_sum * (pc - pr);

        // ---- valve, Eqs 3.9-3.12
        let x_cmd = steer.deg(t) - y[10];
        let x = match self.hidden {
            YawHidden::ValveLag(tau) => {
                dy[11] = (x_cmd - y[11]) / tau;
                y[11]
            }
            _ => {
                dy[11] = 0.0;
                x_cmd
            }
        };
        let xi = ((x.abs() - self.x0) / (self.xlim - self.x0)).clamp(0.0, 1.0);
        let (mut in_c, mut in_r, mut q_gerotor) = (0.0, 0.0, 0.0);
        if xi > 0.0 {
            if x > 0.0 {
                let qs = self.supply_flow(xi, pc);
                let qd = self.kv * xi * valve_lpm(self, (pr - self.p0) * 10.0) / 60.0;
                in_c = qs;
                in_r = -qd;
                q_gerotor = qs;
            } else {
                let qs = self.supply_flow(xi, pr);
                let qd = self.kv * xi * valve_lpm(self, (pc - self.p0) * 10.0) / 60.0;
                in_r = qs;
                in_c = -qd;
                q_gerotor = -qs;
            }
        }
        // Eq 3.10 in rate form: housing angle (deg) per delivered volume (mL)
        dy[10] = q_gerotor * 1e3 / self.gerotor_ml_deg;

        // ---- continuity, Eq 3.4, with the cavitation taper
        let net_c = in_c - dv1 - q_leak;
        let net_r = in_r - dv2 + q_leak;
        let taper = |p: f64, net: f64| -> f64 {
            if net < 0.0 {
                ((p - P_CAV_MPA) / CAV_TAPER_MPA).clamp(0.0, 1.0)
            } else {
                1.0
            }
        };
        dy[8] = self.bulk(pc) * taper(pc, net_c) / v1 * net_c;
        dy[9] = self.bulk(pr) * taper(pr, net_r) / v2 * net_r;

        // ---- strut forces, Eq 3.3, and torque, Eq 3.1 (N, N m; pressures in Pa)
        let (pc_pa, pr_pa) = (pc * 1e6, pr * 1e6);
        let mut f_l = self.ac * pc_pa - self.ar * pr_pa - self.mu_v * vel_l;
        let mut f_r = self.ac * pr_pa - self.ar * pc_pa - self.mu_v * vel_r;
        if let YawHidden::StrutCoulomb(fc) = self.hidden {
            f_l -= fc * (vel_l / COULOMB_V_S).tanh();
            f_r -= fc * (vel_r / COULOMB_V_S).tanh();
        }
        let torque = f_l * h_l - f_r * h_r;

        // ---- rigid bodies, Eq 3.13 (energy-consistent), solved for (dv_f, dphi_f, dphi_r).
        // The residual of the three equations is affine in the accelerations: build the
        // matrix from unit vectors.
        let resid = |acc: [f64; 3]| -> [f64; 3] {
            let (dvf, drf, drr) = (acc[0], acc[1], acc[2]);
            let dw = dvf - self.l_f2 * drf;
            let du_r = -(u * s + w * c) * thd - s * dw;
            let dv_r = u_r * thd + c * dw - self.l_r2 * drr;
            let a_fy = dvf + u * r_f;
            let a_rx = du_r - v_r * r_r;
            let a_ry = dv_r + u_r * r_r;
            [
                self.m_f * a_fy + self.m_r * (a_ry * c - a_rx * s) - yf - yr * c,
                self.i_f * drf + self.m_f * a_fy * self.l_f2 - yf * (self.l_f1 + self.l_f2) + mzf
                    - torque,
                self.i_r * drr - self.m_r * a_ry * self.l_r2
                    + yr * (self.l_r1 + self.l_r2)
                    + mzr
                    + torque,
            ]
        };
        let r0 = resid([0.0; 3]);
        let mut a = [[0.0; 3]; 3];
        for j in 0..3 {
            let mut e = [0.0; 3];
            e[j] = 1.0;
            let rj = resid(e);
            for i in 0..3 {
                a[i][j] = rj[i] - r0[i];
            }
        }
        let acc = solve3(a, [-r0[0], -r0[1], -r0[2]]);
        dy[0] = thd;
        dy[1] = acc[0];
        dy[2] = acc[1];
        dy[3] = acc[2];
        Aux {
            strut_left_disp: d_l,
        }
    }
}

/// Gaussian elimination with partial pivoting, 3 x 3.
fn solve3(mut a: [[f64; 3]; 3], mut b: [f64; 3]) -> [f64; 3] {
    for k in 0..3 {
        let mut piv = k;
        for i in k + 1..3 {
            if a[i][k].abs() > a[piv][k].abs() {
                piv = i;
            }
        }
        a.swap(k, piv);
        b.swap(k, piv);
        for i in k + 1..3 {
            let f = a[i][k] / a[k][k];
            let row_k = a[k];
            for (aij, akj) in a[i].iter_mut().zip(row_k.iter()).skip(k) {
                *aij -= f * akj;
            }
            b[i] -= f * b[k];
        }
    }
    let mut x = [0.0; 3];
    for k in (0..3).rev() {
        let mut s = b[k];
        for j in k + 1..3 {
            s -= a[k][j] * x[j];
        }
        x[k] = s / a[k][k];
    }
    x
}

/// Integration step (s) of [`simulate_yaw`].
pub const YAW_STEP_S: f64 = 0.0005;

/// Simulate one constant-speed run; outputs at `sample_hz` from t = 0 to `duration_s`.
pub fn simulate_yaw(
    p: &YawParams,
    hidden: YawHidden,
    steer: &Steer,
    speed_m_s: f64,
    duration_s: f64,
    sample_hz: f64,
) -> YawRun {
    let m = Model::new(p, hidden, speed_m_s);
    let sub = ((1.0 / sample_hz) / YAW_STEP_S).round().max(1.0) as usize;
    let h = 1.0 / sample_hz / sub as f64;
    let n_out = (duration_s * sample_hz).round() as usize + 1;
    let mut y = [0.0; N];
    y[8] = p.steering.standby_mpa;
    y[9] = p.steering.standby_mpa;
    let backlash = match hidden {
        YawHidden::SensorBacklash(wd) => Some(wd),
        _ => None,
    };
    let mut sensor_deg = y[0] / DEG;
    let mut run = YawRun::default();
    let mut dy = [0.0; N];
    let (mut k1, mut k2, mut k3, mut k4) = ([0.0; N], [0.0; N], [0.0; N], [0.0; N]);
    for k in 0..n_out {
        let t = k as f64 / sample_hz;
        let aux = m.rhs(t, &y, steer, &mut dy);
        run.time_s.push(t);
        run.steer_wheel_deg.push(steer.deg(t));
        run.speed_m_s.push(speed_m_s);
        run.articulation_deg.push(if backlash.is_some() {
            sensor_deg
        } else {
            y[0] / DEG
        });
        run.strut_left_disp_m.push(aux.strut_left_disp);
        run.p_c_pa.push(y[8] * 1e6);
        run.p_r_pa.push(y[9] * 1e6);
        run.yaw_rate_front_deg_s.push(y[2] / DEG);
        if k + 1 == n_out {
            break;
        }
        for j in 0..sub {
            let ts = t + j as f64 * h;
            m.rhs(ts, &y, steer, &mut k1);
            let mut yt = [0.0; N];
            for i in 0..N {
                yt[i] = y[i] + 0.5 * h * k1[i];
            }
            m.rhs(ts + 0.5 * h, &yt, steer, &mut k2);
            for i in 0..N {
                yt[i] = y[i] + 0.5 * h * k2[i];
            }
            m.rhs(ts + 0.5 * h, &yt, steer, &mut k3);
            for i in 0..N {
                yt[i] = y[i] + h * k3[i];
            }
            m.rhs(ts + h, &yt, steer, &mut k4);
            for i in 0..N {
                y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
            }
            y[8] = y[8].max(P_CAV_MPA);
            y[9] = y[9].max(P_CAV_MPA);
            if let Some(wd) = backlash {
                // play element: the sensor moves only when the link takes up the play
                let th = y[0] / DEG;
                if th - sensor_deg > wd {
                    sensor_deg = th - wd;
                } else if th - sensor_deg < -wd {
                    sensor_deg = th + wd;
                }
            }
        }
        assert!(
            y.iter().all(|v| v.is_finite()) && y[0].abs() < 60.0 * DEG,
            "independent yaw model diverged at t = {t}: {y:?}"
        );
    }
    run
}
