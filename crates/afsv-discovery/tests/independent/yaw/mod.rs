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

mod model;
mod set;

pub use model::{simulate_yaw, YAW_STEP_S};
#[allow(unused_imports)]
pub use set::{yaw_record_set, yaw_record_set_of, YAW_KINDS, YAW_NOISE, YAW_SAMPLE_HZ};
