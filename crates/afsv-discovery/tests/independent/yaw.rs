//! Independent implementation of the yaw-plane articulated frame-steered vehicle with
//! hydraulic frame steering (dissertation Chapter 3, Eqs 3.1-3.17, Table 3.1), written from
//! the equations, with the ambiguities resolved as `docs/afs-hydraulics.md` and
//! `docs/afs-yaw-plane.md` state. No toolkit model code is called from here.
//!
//! Units (deliberately not the toolkit's SI-everywhere choice): mechanics in kg, m, s, rad;
//! hydraulics with pressures in **MPa**, volumes in **litres**, flows in L/s, the valve law
//! in its table units (bar, L/min), the housing angle and the spool in **degrees**.
//!
//! State vector `y` (12 entries):
//!
//! | i | state | unit | equation |
//! |---|---|---|---|
//! | 0 | articulation theta = psi_f - psi_r | rad | Eq 3.14 (3rd line) |
//! | 1 | lateral velocity of the front cg v_f | m/s | Eq 3.13 row 1 |
//! | 2 | front yaw rate phi_f | rad/s | Eq 3.13 row 2 |
//! | 3 | rear yaw rate phi_r | rad/s | Eq 3.13 row 3 |
//! | 4..8 | lagged tire slips alpha_1..alpha_4 | rad | Eq 3.16 |
//! | 8 | P_c (left piston side + right rod side), absolute | MPa | Eq 3.4 line 1 |
//! | 9 | P_r (left rod side + right piston side), absolute | MPa | Eq 3.4 line 2 |
//! | 10 | valve housing (= gerotor) angle theta_h | deg | Eq 3.10, rate form |
//! | 11 | lagged spool opening X_eff (only with `valve-lag`) | deg | hidden effect |
//!
//! Modelling choices (documented; each either from the paper or from the model notes):
//! * Eq 3.13 in the **energy-consistent** form: the yaw equations about the joint use I_f,
//!   I_r about the unit cg plus the moment of the cg's inertial force, without adding
//!   m L^2 to the inertia a second time (our own Newton-Euler derivation: eliminating the
//!   joint force from each unit's lateral and yaw balance gives exactly Eq 3.13 with I
//!   instead of I + m L^2; the notes make the same choice).
//! * Axes: x forward, y right, yaw positive in the right-hand turn (docs/records.md), so the
//!   printed equations are used as printed; positive T_s drives theta positive.
//! * Eq 3.3 forces extending-positive for both struts; Eq 3.1 torque; Eq 3.7 volumes with
//!   d = l - l0 for both struts; their theta-derivatives give the flow terms of Eq 3.4.
//! * Valve: normalised opening xi = (|X| - X_0)/(X_lim - X_0) clipped to [0, 1]
//!   (docs/afs-hydraulics.md "Valve opening"); a_m, a_v, a_0 in L/min, bar; the mirror image
//!   of Eqs 3.11-3.12 for X < 0; inlet check valve (no back flow into the supply); the return
//!   orifice is bidirectional (refill from the tank).
//! * Square root regularised as `dp / sqrt(|dp| + 0.02 bar)` (ours; the relative error is
//!   below 0.13 % above 8 bar).
//! * Cavitation floor (ours): a group whose net inflow is negative has its bulk modulus
//!   multiplied by a linear taper from 1 at 50 kPa to 0 at 20 kPa, and the pressure is
//!   clamped at 20 kPa after every step as a safeguard for the explicit integrator.
//! * Standby pressure 1 MPa in both groups at the start (the note's assumption; the paper
//!   gives none).
//! * Integrator: classic fixed-step RK4, 0.5 ms, 20 sub-steps per 100 Hz sample.

use super::records::{write_json, write_record, Column};
use super::rng::Noise;
use std::f64::consts::PI;
use std::path::Path;

const DEG: f64 = PI / 180.0;

/// Vehicle load case of Table 3.1.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum YawLoad {
    /// Rated load.
    Loaded,
    /// Empty.
    Unloaded,
}

impl YawLoad {
    /// Sidecar name.
    pub fn name(self) -> &'static str {
        match self {
            YawLoad::Loaded => "loaded",
            YawLoad::Unloaded => "unloaded",
        }
    }
}

/// Vehicle columns of Table 3.1 (table units where they are not SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VehicleData {
    /// m_f (kg)
    pub m_f: f64,
    /// m_r (kg)
    pub m_r: f64,
    /// I_f (kg m^2)
    pub i_f: f64,
    /// I_r (kg m^2)
    pub i_r: f64,
    /// L_f1 (m), cg to front axle (as printed, negative)
    pub l_f1: f64,
    /// L_f2 (m), cg to joint
    pub l_f2: f64,
    /// L_r1 (m), rear cg to rear axle
    pub l_r1: f64,
    /// L_r2 (m), rear cg to joint
    pub l_r2: f64,
    /// C_alpha_f per tire (kN/deg)
    pub c_f_kn_deg: f64,
    /// C_alpha_r per tire (kN/deg)
    pub c_r_kn_deg: f64,
    /// k_mzf per tire (kN m/deg)
    pub kmz_f_knm_deg: f64,
    /// k_mzr per tire (kN m/deg)
    pub kmz_r_knm_deg: f64,
    /// sigma_y (m)
    pub sigma_m: f64,
    /// T half track (m)
    pub half_track_m: f64,
}

/// Steering columns of Table 3.1, in table units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteeringData {
    /// A_0 (deg)
    pub a0_deg: f64,
    /// X_0 dead band (deg)
    pub x0_deg: f64,
    /// spool pin limit (deg)
    pub xlim_deg: f64,
    /// l_1 (m)
    pub l1_m: f64,
    /// l_2 (m)
    pub l2_m: f64,
    /// A_c (cm^2)
    pub ac_cm2: f64,
    /// A_r (cm^2)
    pub ar_cm2: f64,
    /// V_0 (L)
    pub v0_l: f64,
    /// P_s (MPa)
    pub ps_mpa: f64,
    /// P_0 (MPa)
    pub p0_mpa: f64,
    /// B_eff (GPa)
    pub b_gpa: f64,
    /// mu_v in kN s/mm (the note's reading of Table 3.1's "0.06")
    pub mu_v_kn_s_mm: f64,
    /// k_l0, m^3/(s Pa)
    pub kl0: f64,
    /// k_l, m^3/(Pa m) (times strut speed in m/s)
    pub kl: f64,
    /// k_theta (mL/deg)
    pub ktheta_ml_deg: f64,
    /// k_v return flow-area factor
    pub kv: f64,
    /// eta_g gerotor efficiency ("n" of the table)
    pub eta_g: f64,
    /// a_0 (1/bar)
    pub a0_per_bar: f64,
    /// a_m ((L/min)/sqrt(bar)) per unit normalised opening
    pub am: f64,
    /// a_v ((L/min)/bar) per unit normalised opening
    pub av: f64,
    /// standby pressure at the start (MPa)
    pub standby_mpa: f64,
}

/// Parameters of one vehicle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct YawParams {
    /// Vehicle columns.
    pub vehicle: VehicleData,
    /// Steering columns.
    pub steering: SteeringData,
}

/// The fixed perturbations of the record generator (fraction of nominal).
pub const YAW_PERTURBATION: [(&str, f64); 8] = [
    ("bulk_modulus", -0.08),
    ("dead_volume", 0.06),
    ("seal_viscous_mu_v", 0.12),
    ("leak_constant_k_l0", 0.10),
    ("leak_velocity_k_l", -0.07),
    ("relaxation_length_sigma", 0.15),
    ("cornering_stiffness_both_axles", -0.05),
    ("yaw_inertia_both_units", 0.04),
];

fn perturbation(name: &str) -> f64 {
    YAW_PERTURBATION
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, v)| 1.0 + v)
        .expect("known perturbation")
}

impl YawParams {
    /// Table 3.1 nominal values.
    pub fn table_3_1(load: YawLoad) -> Self {
        let vehicle = match load {
            YawLoad::Loaded => VehicleData {
                m_f: 21_000.0,
                m_r: 52_220.0,
                i_f: 42_000.0,
                i_r: 104_000.0,
                l_f1: -0.45,
                l_f2: 2.13,
                l_r1: 1.13,
                l_r2: 2.31,
                c_f_kn_deg: 4.5,
                c_r_kn_deg: 4.9,
                kmz_f_knm_deg: 3.8,
                kmz_r_knm_deg: 4.7,
                sigma_m: 0.4,
                half_track_m: 1.14,
            },
            YawLoad::Unloaded => VehicleData {
                m_f: 21_000.0,
                m_r: 18_500.0,
                i_f: 42_000.0,
                i_r: 31_000.0,
                l_f1: -0.45,
                l_f2: 2.13,
                l_r1: 0.60,
                l_r2: 2.84,
                c_f_kn_deg: 4.1,
                c_r_kn_deg: 2.54,
                kmz_f_knm_deg: 2.35,
                kmz_r_knm_deg: 1.43,
                sigma_m: 0.4,
                half_track_m: 1.14,
            },
        };
        let steering = SteeringData {
            a0_deg: 76.5,
            x0_deg: 2.1,
            xlim_deg: 8.1,
            l1_m: 1.96,
            l2_m: 0.64,
            ac_cm2: 95.0,
            ar_cm2: 57.0,
            v0_l: 7.6,
            ps_mpa: 13.5,
            p0_mpa: 0.1,
            b_gpa: 1.6,
            mu_v_kn_s_mm: 0.06,
            kl0: 1.3e-13,
            kl: 1.8e-10,
            ktheta_ml_deg: 8.34,
            kv: 0.7,
            eta_g: 0.9,
            a0_per_bar: -0.0074,
            am: 0.94,
            av: 4.8,
            standby_mpa: 1.0,
        };
        Self { vehicle, steering }
    }

    /// The "real vehicle" of the records: Table 3.1 with [`YAW_PERTURBATION`] applied.
    /// Masses, geometry and valve data stay at Table 3.1.
    pub fn perturbed(load: YawLoad) -> Self {
        let mut p = Self::table_3_1(load);
        p.steering.b_gpa *= perturbation("bulk_modulus");
        p.steering.v0_l *= perturbation("dead_volume");
        p.steering.mu_v_kn_s_mm *= perturbation("seal_viscous_mu_v");
        p.steering.kl0 *= perturbation("leak_constant_k_l0");
        p.steering.kl *= perturbation("leak_velocity_k_l");
        p.vehicle.sigma_m *= perturbation("relaxation_length_sigma");
        let c = perturbation("cornering_stiffness_both_axles");
        p.vehicle.c_f_kn_deg *= c;
        p.vehicle.c_r_kn_deg *= c;
        let i = perturbation("yaw_inertia_both_units");
        p.vehicle.i_f *= i;
        p.vehicle.i_r *= i;
        p
    }

    /// JSON for truth.json.
    pub fn json(&self) -> serde_json::Value {
        let v = &self.vehicle;
        let s = &self.steering;
        serde_json::json!({
            "m_f_kg": v.m_f, "m_r_kg": v.m_r, "i_f_kg_m2": v.i_f, "i_r_kg_m2": v.i_r,
            "l_f1_m": v.l_f1, "l_f2_m": v.l_f2, "l_r1_m": v.l_r1, "l_r2_m": v.l_r2,
            "c_alpha_f_kn_per_deg": v.c_f_kn_deg, "c_alpha_r_kn_per_deg": v.c_r_kn_deg,
            "k_mz_f_knm_per_deg": v.kmz_f_knm_deg, "k_mz_r_knm_per_deg": v.kmz_r_knm_deg,
            "relaxation_length_m": v.sigma_m, "half_track_m": v.half_track_m,
            "a0_deg": s.a0_deg, "dead_band_deg": s.x0_deg, "spool_limit_deg": s.xlim_deg,
            "l1_m": s.l1_m, "l2_m": s.l2_m, "piston_area_cm2": s.ac_cm2, "annulus_area_cm2": s.ar_cm2,
            "dead_volume_l": s.v0_l, "supply_pressure_mpa": s.ps_mpa, "reservoir_pressure_mpa": s.p0_mpa,
            "bulk_modulus_gpa": s.b_gpa, "seal_viscous_kn_s_per_mm": s.mu_v_kn_s_mm,
            "leak_const_m3_s_pa": s.kl0, "leak_velocity_m3_pa_m": s.kl,
            "gerotor_ml_per_deg": s.ktheta_ml_deg, "return_factor_kv": s.kv, "gerotor_efficiency": s.eta_g,
            "valve_a0_per_bar": s.a0_per_bar, "valve_am_lpm_sqrt_bar": s.am, "valve_av_lpm_bar": s.av,
            "standby_pressure_mpa": s.standby_mpa,
        })
    }
}

/// Names of the hidden effects of the vehicle records.
pub const YAW_EFFECTS: [&str; 5] = [
    "sensor-backlash",
    "supply-droop",
    "strut-coulomb-friction",
    "entrained-air",
    "valve-lag",
];

/// A hidden effect of the vehicle (at most one per record set).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum YawHidden {
    /// Baseline (full paper model).
    None,
    /// Play in the articulation sensor link, half width (deg); measurement only.
    SensorBacklash(f64),
    /// Supply pressure droop r (Pa per m^3/s): P_s,eff = P_s - r q_supply.
    SupplyDroop(f64),
    /// Dry seal friction per strut F_c tanh(v / 5 mm/s), F_c in N.
    StrutCoulomb(f64),
    /// Entrained air volume fraction at atmospheric pressure (-), Merritt law, n = 1.2.
    EntrainedAir(f64),
    /// First-order lag of the valve opening, time constant (s).
    ValveLag(f64),
}

impl YawHidden {
    /// From a catalogue name and size.
    pub fn from_name(name: &str, size: f64) -> Self {
        match name {
            "sensor-backlash" => YawHidden::SensorBacklash(size),
            "supply-droop" => YawHidden::SupplyDroop(size),
            "strut-coulomb-friction" => YawHidden::StrutCoulomb(size),
            "entrained-air" => YawHidden::EntrainedAir(size),
            "valve-lag" => YawHidden::ValveLag(size),
            other => panic!("unknown yaw-plane hidden effect `{other}` (known: {YAW_EFFECTS:?})"),
        }
    }

    /// Unit of the size parameter.
    pub fn unit(name: &str) -> &'static str {
        match name {
            "sensor-backlash" => "deg (half width)",
            "supply-droop" => "Pa s/m^3",
            "strut-coulomb-friction" => "N per strut (v_s = 5 mm/s)",
            "entrained-air" => "air volume fraction at 1 atm (polytropic n = 1.2)",
            "valve-lag" => "s (first-order time constant)",
            _ => "?",
        }
    }
}

/// Steering-wheel input (degrees, seconds).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Steer {
    /// Half-sine pulse.
    Pulse {
        /// peak (deg)
        amp_deg: f64,
        /// duration (s)
        dur_s: f64,
        /// start (s)
        start_s: f64,
    },
    /// Step.
    Step {
        /// size (deg)
        amp_deg: f64,
        /// time (s)
        start_s: f64,
    },
    /// Ramp to a hold.
    Ramp {
        /// rate (deg/s), signed
        rate_deg_s: f64,
        /// start (s)
        start_s: f64,
        /// held magnitude (deg)
        limit_deg: f64,
    },
    /// Sine of whole cycles, zero before and after.
    Sine {
        /// amplitude (deg)
        amp_deg: f64,
        /// frequency (Hz)
        freq_hz: f64,
        /// start (s)
        start_s: f64,
        /// number of cycles
        cycles: f64,
    },
}

impl Steer {
    /// Wheel angle (deg) at t.
    pub fn deg(&self, t: f64) -> f64 {
        match *self {
            Steer::Pulse {
                amp_deg,
                dur_s,
                start_s,
            } => {
                let s = (t - start_s) / dur_s;
                if (0.0..=1.0).contains(&s) {
                    amp_deg * (PI * s).sin()
                } else {
                    0.0
                }
            }
            Steer::Step { amp_deg, start_s } => {
                // A driver's step: the wheel turns at 800 deg/s (no faster than 0.1 s), as
                // fast as a hand can, not in zero time. An ideal step cannot be replayed
                // from 100 Hz samples by any implementation.
                let rise = (amp_deg.abs() / 800.0).max(0.1);
                let s = ((t - start_s) / rise).clamp(0.0, 1.0);
                amp_deg * s * s * (3.0 - 2.0 * s)
            }
            Steer::Ramp {
                rate_deg_s,
                start_s,
                limit_deg,
            } => {
                if t <= start_s {
                    0.0
                } else {
                    (rate_deg_s * (t - start_s)).clamp(-limit_deg, limit_deg)
                }
            }
            Steer::Sine {
                amp_deg,
                freq_hz,
                start_s,
                cycles,
            } => {
                let s = (t - start_s) * freq_hz;
                if s > 0.0 && s < cycles {
                    amp_deg * (2.0 * PI * s).sin()
                } else {
                    0.0
                }
            }
        }
    }

    /// Manoeuvre kind.
    pub fn kind(&self) -> &'static str {
        match self {
            Steer::Pulse { .. } => "pulse",
            Steer::Step { .. } => "step",
            Steer::Ramp { .. } => "ramp",
            Steer::Sine { .. } => "sine",
        }
    }
}

/// Record channels (vehicle steering test of docs/records.md), true values (no noise).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct YawRun {
    /// time (s)
    pub time_s: Vec<f64>,
    /// steering-wheel angle (deg)
    pub steer_wheel_deg: Vec<f64>,
    /// forward speed (m/s)
    pub speed_m_s: Vec<f64>,
    /// articulation (deg), as the sensor reads it
    pub articulation_deg: Vec<f64>,
    /// left strut displacement (m, + extension)
    pub strut_left_disp_m: Vec<f64>,
    /// P_c (Pa abs)
    pub p_c_pa: Vec<f64>,
    /// P_r (Pa abs)
    pub p_r_pa: Vec<f64>,
    /// front yaw rate (deg/s)
    pub yaw_rate_front_deg_s: Vec<f64>,
}

impl YawRun {
    /// The channels by record name.
    pub fn channels(&self) -> [(&'static str, &[f64]); 7] {
        [
            ("steer_wheel_deg", &self.steer_wheel_deg),
            ("speed_m_s", &self.speed_m_s),
            ("articulation_deg", &self.articulation_deg),
            ("strut_left_disp_m", &self.strut_left_disp_m),
            ("p_c_pa", &self.p_c_pa),
            ("p_r_pa", &self.p_r_pa),
            ("yaw_rate_front_deg_s", &self.yaw_rate_front_deg_s),
        ]
    }
}

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

/// Measurement noise of the vehicle records (standard deviations).
pub const YAW_NOISE: [(&str, f64); 7] = [
    ("steer_wheel_deg", 0.1),
    ("speed_m_s", 0.05),
    ("articulation_deg", 0.05),
    ("strut_left_disp_m", 1.0e-4),
    ("p_c_pa", 2.0e4),
    ("p_r_pa", 2.0e4),
    ("yaw_rate_front_deg_s", 0.2),
];

/// Record sample rate (Hz).
pub const YAW_SAMPLE_HZ: f64 = 100.0;

/// Manoeuvre kinds, cycled through in every set.
pub const YAW_KINDS: [&str; 4] = ["pulse", "step", "ramp", "sine"];

/// Steering input of a given kind at a speed, sized for a realistic lateral acceleration.
fn manoeuvre(kind: &str, speed_kmh: f64, rng: &mut Noise) -> Steer {
    let u = speed_kmh / 3.6;
    // articulation giving a_y of 1.2-2.0 m/s^2 on a ~5.1 m front-axle-to-rear-axle
    // wheelbase, at most 12 deg; the wheel angle from a steering gain of ~0.035 deg/deg.
    let a_y = rng.range(1.2, 2.0);
    let theta_deg = (5.1 * a_y / (u * u) / DEG).min(12.0);
    let wheel = (theta_deg / 0.035).clamp(40.0, 340.0);
    let sign = if rng.uniform() < 0.5 { -1.0 } else { 1.0 };
    let start_s = 1.0;
    let round1 = |x: f64| (x * 10.0).round() / 10.0;
    match kind {
        "pulse" => Steer::Pulse {
            amp_deg: sign * round1((0.6 * wheel).clamp(30.0, 120.0)),
            dur_s: round1(rng.range(0.2, 0.4)),
            start_s,
        },
        "step" => Steer::Step {
            amp_deg: sign * round1(wheel),
            start_s,
        },
        "ramp" => Steer::Ramp {
            rate_deg_s: sign * round1(rng.range(60.0, 150.0)),
            start_s,
            limit_deg: round1(1.2 * wheel),
        },
        "sine" => Steer::Sine {
            amp_deg: sign * round1(0.8 * wheel),
            freq_hz: (rng.range(0.3, 0.6) * 100.0).round() / 100.0,
            start_s,
            cycles: 2.0,
        },
        other => panic!("unknown manoeuvre {other}"),
    }
}

fn steer_json(s: &Steer) -> serde_json::Value {
    match *s {
        Steer::Pulse {
            amp_deg,
            dur_s,
            start_s,
        } => {
            serde_json::json!({"kind": "pulse", "amplitude_deg": amp_deg, "duration_s": dur_s, "start_s": start_s})
        }
        Steer::Step { amp_deg, start_s } => {
            serde_json::json!({"kind": "step", "amplitude_deg": amp_deg, "start_s": start_s})
        }
        Steer::Ramp {
            rate_deg_s,
            start_s,
            limit_deg,
        } => {
            serde_json::json!({"kind": "ramp", "rate_deg_s": rate_deg_s, "start_s": start_s, "limit_deg": limit_deg})
        }
        Steer::Sine {
            amp_deg,
            freq_hz,
            start_s,
            cycles,
        } => {
            serde_json::json!({"kind": "sine", "amplitude_deg": amp_deg, "frequency_hz": freq_hz, "start_s": start_s, "cycles": cycles})
        }
    }
}

/// Write a vehicle record set: `dir/train/*.csv|json`, `dir/holdout/*.csv|json` and
/// `dir/truth.json`. Records alternate pulse, step, ramp, sine (all four appear in both
/// sets when `n_train >= 4` and `n_holdout >= 4`) and mix loaded/unloaded so each kind
/// appears with both loads over eight records. Training speeds are spread evenly over
/// 15-50 km/h (shuffled over the kinds), held-out speeds drawn inside 20-45 km/h. The
/// truth model is [`YawParams::perturbed`] plus the hidden effect.
pub fn yaw_record_set(
    dir: &Path,
    hidden: Option<(&str, f64)>,
    n_train: usize,
    n_holdout: usize,
    duration_s: f64,
    seed: u64,
) {
    let effect = match hidden {
        Some((name, size)) => YawHidden::from_name(name, size),
        None => YawHidden::None,
    };
    let mut rng = Noise::new(seed, 0x0079_6177);
    // training speeds: evenly spread, shuffled (Fisher-Yates)
    let mut speeds: Vec<f64> = (0..n_train)
        .map(|i| {
            if n_train > 1 {
                15.0 + 35.0 * i as f64 / (n_train - 1) as f64
            } else {
                30.0
            }
        })
        .collect();
    for i in (1..speeds.len()).rev() {
        let j = (rng.next_u64() % (i as u64 + 1)) as usize;
        speeds.swap(i, j);
    }
    let mut plan = Vec::new();
    for (i, sp) in speeds.iter().enumerate() {
        let load = if (i + i / 4) % 2 == 0 {
            YawLoad::Loaded
        } else {
            YawLoad::Unloaded
        };
        plan.push(("train", i, load, (sp * 10.0).round() / 10.0));
    }
    for j in 0..n_holdout {
        let load = if (j + j / 4) % 2 == 0 {
            YawLoad::Unloaded
        } else {
            YawLoad::Loaded
        };
        let sp = (rng.range(20.0, 45.0) * 10.0).round() / 10.0;
        plan.push(("holdout", j, load, sp));
    }
    let mut listing = Vec::new();
    for (set, i, load, speed_kmh) in plan {
        let kind = YAW_KINDS[i % 4];
        let steer = manoeuvre(kind, speed_kmh, &mut rng);
        let params = YawParams::perturbed(load);
        let run = simulate_yaw(
            &params,
            effect,
            &steer,
            speed_kmh / 3.6,
            duration_s,
            YAW_SAMPLE_HZ,
        );
        let name = format!(
            "yaw_{i:02}_{kind}_{}_{}kmh",
            load.name(),
            format!("{speed_kmh}").replace('.', "p")
        );
        let stream = if set == "train" { 1000 } else { 2000 } + i as u64;
        let mut noise = Noise::new(seed, stream);
        let mut chans: Vec<Vec<f64>> = run.channels().iter().map(|(_, v)| v.to_vec()).collect();
        for (c, (_, sd)) in chans.iter_mut().zip(YAW_NOISE.iter()) {
            noise.add(c, *sd);
        }
        let decimals = [3, 3, 3, 5, 0, 0, 3];
        let mut cols = vec![Column {
            name: "time_s",
            values: &run.time_s,
            decimals: 2,
        }];
        for (k, (nm, _)) in YAW_NOISE.iter().enumerate() {
            cols.push(Column {
                name: nm,
                values: &chans[k],
                decimals: decimals[k],
            });
        }
        let sidecar = serde_json::json!({
            "sample_rate_hz": YAW_SAMPLE_HZ,
            "load": load.name(),
            "speed_kmh": speed_kmh,
            "manoeuvre": kind,
            "sign_convention": "afsv-v1",
            "source": "independent implementation (tests/independent)",
            "units": {"time_s": "s", "steer_wheel_deg": "deg", "speed_m_s": "m/s",
                      "articulation_deg": "deg", "strut_left_disp_m": "m", "p_c_pa": "Pa",
                      "p_r_pa": "Pa", "yaw_rate_front_deg_s": "deg/s"},
        });
        write_record(&dir.join(set), &name, &cols, &sidecar);
        listing.push(serde_json::json!({
            "set": set, "name": name, "load": load.name(), "speed_kmh": speed_kmh,
            "steer": steer_json(&steer),
        }));
    }
    let truth = serde_json::json!({
        "model": "yaw-plane",
        "source": "independent implementation (tests/independent/yaw.rs)",
        "hidden_effect": match hidden {
            Some((name, size)) => serde_json::json!({"name": name, "size": size, "unit": YawHidden::unit(name)}),
            None => serde_json::Value::Null,
        },
        "note": "truth = the full paper model (tire relaxation Eq 3.16 and velocity leakage Eq 3.6 present) at the perturbed parameters",
        "perturbations": YAW_PERTURBATION.iter().map(|(n, v)| (n.to_string(), serde_json::json!(v))).collect::<serde_json::Map<_, _>>(),
        "parameters": {"loaded": YawParams::perturbed(YawLoad::Loaded).json(),
                       "unloaded": YawParams::perturbed(YawLoad::Unloaded).json()},
        "noise_sd": YAW_NOISE.iter().map(|(n, v)| (n.to_string(), serde_json::json!(v))).collect::<serde_json::Map<_, _>>(),
        "duration_s": duration_s,
        "seed": seed,
        "integrator": {"method": "classic RK4, fixed step", "step_s": YAW_STEP_S},
        "records": listing,
    });
    write_json(&dir.join("truth.json"), &truth);
}
