//! Independent implementation of the hydro-pneumatic strut with gas-oil emulsion
//! (dissertation Chapter 5, Eqs 5.1-5.12; front-axle strut of Table 6.3), written from the
//! equations with the conventions of `docs/hps-emulsion.md` and docs/records.md. No toolkit model
//! code is called from here.
//!
//! Units: pressures in **MPa**, volumes in **litres**, flows in L/s, areas in m^2, forces in N.
//!
//! State vector (4 entries):
//!
//! | i | state | unit | equation |
//! |---|---|---|---|
//! | 0 | piston-side (gas) pressure P_hc, absolute | MPa | Eqs 5.4 + 5.5 |
//! | 1 | rod-side pressure P_hr, absolute | MPa | Eq 5.6 |
//! | 2 | gas temperature ratio T_g / T_0 (only with `gas-heat-transfer`) | - | hidden effect |
//! | 3 | check-valve opening x_v in [0, 1] (only with `check-valve-lag`) | - | hidden effect |
//!
//! We integrate the gas pressure rather than the gas volume: from Eq 5.4,
//! dV_g = -V_g/(n P_hc) dP_hc, so Eq 5.5 becomes
//! `P_hc' = (A_hc z' - q) / (V_g/(n P_hc) + V_c/beta_c)`, with q = q_b + q_c + q_l (Eq 5.12).
//!
//! Conventions and choices:
//! * z_s positive in compression from the static mid-stroke position, force positive when
//!   compressive, absolute pressures (docs/records.md). Eq 5.7's `x` is z_s.
//! * Eq 5.1 with absolute pressures: the outer rod end sees the atmosphere, so
//!   F = P_hc A_hc - P_hr (A_hc - A_hr) - p_atm A_hr + F_f (docs/hps-emulsion.md, item 5).
//! * Eq 5.3 band only after a reversal (z z' < 0), v_h = max(0.1 v_peak, 1 mm/s)
//!   (the note's reading of "v_h grows with peak velocity"); in the band the force moves
//!   linearly from minus the previous direction's level to the new direction's Eq 5.2 value.
//! * Emulsion volumes V_c0, V_r0 = oil volumes x (1 + gamma_0); the oil split puts
//!   A_ann (travel + 10 mm) in the rod chamber (the note's choice; Table 6.3 has only the total).
//! * Both emulsions referenced to P_h0 (Eqs 5.8-5.11 with the chamber's own pressure),
//!   mean density for both orifice laws (Eq 5.12).
//! * Friction of the front-axle strut: the lab strut's values scaled by the perimeter
//!   ratio 2.38 (the note): mu_v 119 N s/m, F_c 357 N, F_s 238 N, k_s 50 s/m.
//! * Square roots regularised as dp (dp^2 + (2 kPa)^2)^(-1/4) (our own regularisation scale);
//!   rod-side cavitation floor: a falling P_hr is tapered linearly to zero from 25 kPa to
//!   5 kPa and clamped at 5 kPa after each step.
//! * Integrator: classic RK4, fixed step <= 0.1 ms (stability of the rod-side chamber with
//!   the orifices near zero pressure drop needs < 0.3 ms), sub-stepped between samples.

use super::records::{write_json, write_record, Column};
use super::rng::Noise;
use std::f64::consts::PI;
use std::path::Path;

/// Front-axle strut data (Table 6.3 and the note's completions), in our units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StrutData {
    /// piston area A_hc (m^2)
    pub a_hc: f64,
    /// rod area A_hr (m^2)
    pub a_hr: f64,
    /// number of bleed orifices n_b
    pub n_b: f64,
    /// bleed orifice area (mm^2)
    pub a_b_mm2: f64,
    /// bleed discharge coefficient C_b
    pub c_b: f64,
    /// number of check valves n_v
    pub n_v: f64,
    /// check-valve area (mm^2)
    pub a_v_mm2: f64,
    /// check-valve discharge coefficient C_v
    pub c_v: f64,
    /// leakage coefficient k_l (m^3/(Pa s))
    pub k_l: f64,
    /// oil bulk modulus beta_h (MPa)
    pub beta_h_mpa: f64,
    /// oil density rho_h (kg/m^3)
    pub rho_h: f64,
    /// static (charge) pressure P_h0 (MPa, absolute)
    pub p_h0_mpa: f64,
    /// free gas volume at P_h0, V_g0 (L)
    pub v_g0_l: f64,
    /// total oil volume (L)
    pub oil_l: f64,
    /// initial gas fraction gamma_0 (-)
    pub gamma0: f64,
    /// polytropic exponent n
    pub n: f64,
    /// viscous friction mu_v (N s/m)
    pub mu_v: f64,
    /// Coulomb friction F_c (N)
    pub f_c: f64,
    /// stiction F_s (N)
    pub f_s: f64,
    /// Stribeck coefficient k_s (s/m)
    pub k_s: f64,
    /// v_h / v_peak
    pub vh_ratio: f64,
    /// smallest v_h (m/s)
    pub vh_min: f64,
    /// half travel (m)
    pub travel: f64,
    /// rod-chamber dead length (m) at full extension
    pub rod_dead_length: f64,
    /// Density of the orifice laws (Eq 5.12): the upstream chamber's (`true`) or the mean
    /// of both (`false`, the note's reading); Eq 5.6's density ratio is kept.
    pub upwind_density: bool,
    /// Rod-side cavitation floor (MPa, absolute).
    pub floor_mpa: f64,
    /// Width of the taper above the floor (MPa).
    pub floor_taper_mpa: f64,
    /// Regularisation pressure of the orifice square roots (Pa): a laminar-like law below it.
    pub sqrt_reg_pa: f64,
}

/// The fixed perturbations of the record generator (fraction of nominal).
pub const STRUT_PERTURBATION: [(&str, f64); 7] = [
    ("polytropic_exponent_n", -0.04),
    ("static_pressure_p_h0", 0.03),
    ("gas_volume_v_g0", -0.06),
    ("coulomb_friction_f_c", 0.12),
    ("viscous_friction_mu_v", 0.10),
    ("bleed_discharge_c_b", -0.07),
    ("gas_fraction_gamma0", 0.10),
];

fn factor(name: &str) -> f64 {
    1.0 + STRUT_PERTURBATION
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, v)| *v)
        .expect("known perturbation")
}

impl StrutData {
    /// Table 6.3 front-axle strut.
    pub fn table_6_3() -> Self {
        Self {
            a_hc: 0.038,
            a_hr: 0.0254,
            n_b: 4.0,
            a_b_mm2: 11.0,
            c_b: 0.7,
            n_v: 2.0,
            a_v_mm2: 8.0,
            c_v: 0.6,
            k_l: 5e-12,
            beta_h_mpa: 1700.0,
            rho_h: 850.0,
            p_h0_mpa: 5.8,
            v_g0_l: 4.5,
            oil_l: 11.4,
            gamma0: 0.02,
            n: 1.4,
            mu_v: 119.0,
            f_c: 357.0,
            f_s: 238.0,
            k_s: 50.0,
            vh_ratio: 0.1,
            vh_min: 0.001,
            travel: 0.12,
            rod_dead_length: 0.010,
            upwind_density: false,
            floor_mpa: P_FLOOR_MPA,
            floor_taper_mpa: FLOOR_TAPER_MPA,
            sqrt_reg_pa: SQRT_REG_PA,
        }
    }

    /// The "real strut" of the records: Table 6.3 with [`STRUT_PERTURBATION`].
    pub fn perturbed() -> Self {
        let mut p = Self::table_6_3();
        p.n *= factor("polytropic_exponent_n");
        p.p_h0_mpa *= factor("static_pressure_p_h0");
        p.v_g0_l *= factor("gas_volume_v_g0");
        p.f_c *= factor("coulomb_friction_f_c");
        p.mu_v *= factor("viscous_friction_mu_v");
        p.c_b *= factor("bleed_discharge_c_b");
        p.gamma0 *= factor("gas_fraction_gamma0");
        p
    }

    /// JSON for truth.json.
    pub fn json(&self) -> serde_json::Value {
        serde_json::json!({
            "a_hc_m2": self.a_hc, "a_hr_m2": self.a_hr, "n_b": self.n_b, "a_b_mm2": self.a_b_mm2,
            "c_b": self.c_b, "n_v": self.n_v, "a_v_mm2": self.a_v_mm2, "c_v": self.c_v,
            "k_l_m3_pa_s": self.k_l, "beta_h_mpa": self.beta_h_mpa, "rho_h_kg_m3": self.rho_h,
            "p_h0_mpa": self.p_h0_mpa, "v_g0_l": self.v_g0_l, "oil_l": self.oil_l,
            "gamma0": self.gamma0, "n": self.n, "mu_v_n_s_m": self.mu_v, "f_c_n": self.f_c,
            "f_s_n": self.f_s, "k_s_s_m": self.k_s, "vh_ratio": self.vh_ratio, "vh_min_m_s": self.vh_min,
            "travel_m": self.travel, "rod_dead_length_m": self.rod_dead_length,
            "upwind_density": self.upwind_density, "floor_mpa": self.floor_mpa,
            "floor_taper_mpa": self.floor_taper_mpa, "sqrt_reg_pa": self.sqrt_reg_pa,
        })
    }
}

/// Names of the hidden effects of the strut records.
pub const STRUT_EFFECTS: [&str; 4] = [
    "gas-heat-transfer",
    "gas-fraction-growth",
    "asymmetric-friction",
    "check-valve-lag",
];

/// A hidden effect of the strut.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StrutHidden {
    /// Baseline (full Eqs 5.1-5.12).
    None,
    /// Gas energy balance with wall exchange, time constant tau (s), kappa = 1.4.
    GasHeatTransfer(f64),
    /// gamma_0,eff = gamma_0 + k_gamma v_peak, k_gamma (s/m); the gas comes from the free volume.
    GasFractionGrowth(f64),
    /// Friction levels x f in compression and x 1/f in extension.
    AsymmetricFriction(f64),
    /// First-order check-valve opening, time constant tau (s).
    CheckValveLag(f64),
}

impl StrutHidden {
    /// From a catalogue name and size.
    pub fn from_name(name: &str, size: f64) -> Self {
        match name {
            "gas-heat-transfer" => StrutHidden::GasHeatTransfer(size),
            "gas-fraction-growth" => StrutHidden::GasFractionGrowth(size),
            "asymmetric-friction" => StrutHidden::AsymmetricFriction(size),
            "check-valve-lag" => StrutHidden::CheckValveLag(size),
            other => panic!("unknown strut hidden effect `{other}` (known: {STRUT_EFFECTS:?})"),
        }
    }

    /// Unit of the size.
    pub fn unit(name: &str) -> &'static str {
        match name {
            "gas-heat-transfer" => "s (thermal time constant, kappa = 1.4)",
            "gas-fraction-growth" => "s/m (gamma_0 += k v_peak)",
            "asymmetric-friction" => "factor (compression x f, extension x 1/f)",
            "check-valve-lag" => "s (first-order time constant)",
            _ => "?",
        }
    }
}

/// One harmonic bench test z = A sin(2 pi f t) from the static position.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BenchTest {
    /// frequency (Hz)
    pub freq_hz: f64,
    /// amplitude (m)
    pub amp_m: f64,
    /// periods
    pub cycles: f64,
    /// sample rate (Hz)
    pub sample_hz: f64,
}

/// Record channels (strut bench test of docs/records.md), true values.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct StrutRun {
    /// time (s)
    pub time_s: Vec<f64>,
    /// z_s (m, + compression)
    pub displacement_m: Vec<f64>,
    /// z_s' (m/s)
    pub velocity_m_s: Vec<f64>,
    /// force (N, + compressive)
    pub force_n: Vec<f64>,
    /// P_hc (Pa abs)
    pub p_piston_pa: Vec<f64>,
    /// P_hr (Pa abs)
    pub p_rod_pa: Vec<f64>,
}

impl StrutRun {
    /// The channels by record name (time excluded).
    pub fn channels(&self) -> [(&'static str, &[f64]); 5] {
        [
            ("displacement_m", &self.displacement_m),
            ("velocity_m_s", &self.velocity_m_s),
            ("force_n", &self.force_n),
            ("p_piston_pa", &self.p_piston_pa),
            ("p_rod_pa", &self.p_rod_pa),
        ]
    }
}

const NS: usize = 4;
const P_ATM_MPA: f64 = 0.101_325;
const SQRT_REG_PA: f64 = 2.0e3;
const P_FLOOR_MPA: f64 = 0.005;
const FLOOR_TAPER_MPA: f64 = 0.02;
const KAPPA: f64 = 1.4;

/// Integration step bound (s).
pub const STRUT_MAX_STEP_S: f64 = 1.0e-4;

struct Strut {
    d: StrutData,
    a_ann: f64,
    v_g0: f64,
    v_c0: f64,
    v_r0: f64,
    gamma0: f64,
    cab: f64, // C_b n_b A_b (m^2)
    cav: f64, // C_v n_v A_v (m^2)
    v_h: f64,
    comp: f64,
    ext: f64,
    heat_tau: Option<f64>,
    valve_tau: Option<f64>,
}

struct Emul {
    rho: f64,
    beta: f64, // MPa
}

fn reg_sqrt_pa(dp_pa: f64, reg_pa: f64) -> f64 {
    dp_pa / (dp_pa * dp_pa + reg_pa * reg_pa).sqrt().sqrt()
}

impl Strut {
    fn new(d: &StrutData, hidden: StrutHidden, v_peak: f64) -> Self {
        let a_ann = d.a_hc - d.a_hr;
        let oil_r = a_ann * (d.travel + d.rod_dead_length) * 1e3; // L
        let oil_c = d.oil_l - oil_r;
        let mut gamma0 = d.gamma0;
        let mut v_g0 = d.v_g0_l;
        if let StrutHidden::GasFractionGrowth(k) = hidden {
            let g = d.gamma0 + k * v_peak;
            // the extra entrapped gas is taken from the free gas (total gas kept)
            v_g0 -= (g - d.gamma0) * d.oil_l;
            gamma0 = g;
        }
        let (comp, ext) = match hidden {
            StrutHidden::AsymmetricFriction(f) => (f, 1.0 / f),
            _ => (1.0, 1.0),
        };
        Self {
            a_ann,
            v_g0,
            v_c0: oil_c * (1.0 + gamma0),
            v_r0: oil_r * (1.0 + gamma0),
            gamma0,
            cab: d.c_b * d.n_b * d.a_b_mm2 * 1e-6,
            cav: d.c_v * d.n_v * d.a_v_mm2 * 1e-6,
            v_h: (d.vh_ratio * v_peak).max(d.vh_min),
            comp,
            ext,
            heat_tau: match hidden {
                StrutHidden::GasHeatTransfer(t) => Some(t),
                _ => None,
            },
            valve_tau: match hidden {
                StrutHidden::CheckValveLag(t) => Some(t),
                _ => None,
            },
            d: *d,
        }
    }

    /// Eqs 5.8-5.11 at chamber pressure p (MPa).
    fn emulsion(&self, p: f64) -> Emul {
        let d = &self.d;
        let oil = 1.0 - (p - d.p_h0_mpa) / d.beta_h_mpa;
        let gamma = self.gamma0 * (d.p_h0_mpa / p).powf(1.0 / d.n) / oil;
        let rho = d.rho_h / (oil * (1.0 + gamma));
        let beta = d.n * (1.0 + gamma) * p * d.beta_h_mpa / (d.n * p + gamma * d.beta_h_mpa);
        Emul { rho, beta }
    }

    /// Eqs 5.2-5.3 (with the asymmetry factors).
    fn friction(&self, z: f64, zd: f64) -> f64 {
        let d = &self.d;
        if zd == 0.0 {
            return 0.0;
        }
        let level = |f: f64, v: f64| f * (d.f_c + d.f_s * (-d.k_s * v).exp());
        let speed = zd.abs();
        let (new_f, prev_f, sign) = if zd > 0.0 {
            (self.comp, self.ext, 1.0)
        } else {
            (self.ext, self.comp, -1.0)
        };
        let dry = if speed >= self.v_h || z * zd >= 0.0 {
            level(new_f, speed)
        } else {
            let r = speed / self.v_h;
            -level(prev_f, 0.0) + (level(new_f, self.v_h) + level(prev_f, 0.0)) * r
        };
        d.mu_v * zd + sign * dry
    }

    fn gas_volume(&self, y: &[f64; NS]) -> f64 {
        let d = &self.d;
        match self.heat_tau {
            Some(_) => self.v_g0 * (d.p_h0_mpa / y[0]) * y[2],
            None => self.v_g0 * (d.p_h0_mpa / y[0]).powf(1.0 / d.n),
        }
    }

    fn rhs(&self, z: f64, zd: f64, y: &[f64; NS], dy: &mut [f64; NS]) {
        let d = &self.d;
        let pc = y[0];
        let pr = y[1].max(d.floor_mpa);
        let vg = self.gas_volume(y);
        // Eq 5.7 (litres)
        let vc = (self.v_c0 + self.v_g0 - d.a_hc * z * 1e3 - vg).max(1e-9);
        let vr = (self.v_r0 + self.a_ann * z * 1e3).max(1e-9);
        let ec = self.emulsion(pc);
        let er = self.emulsion(pr);
        let rho_bar = if !d.upwind_density {
            0.5 * (ec.rho + er.rho)
        } else if pc >= pr {
            ec.rho
        } else {
            er.rho
        };
        // Eq 5.12 (m^3/s -> L/s)
        let dp_pa = (pc - pr) * 1e6;
        let k = (2.0 / rho_bar).sqrt();
        let q_b = self.cab * k * reg_sqrt_pa(dp_pa, d.sqrt_reg_pa);
        let opening = match self.valve_tau {
            Some(tau) => {
                let target = if dp_pa > 0.0 { 1.0 } else { 0.0 };
                dy[3] = (target - y[3]) / tau;
                y[3].clamp(0.0, 1.0)
            }
            None => {
                dy[3] = 0.0;
                1.0
            }
        };
        let q_c = if dp_pa > 0.0 {
            opening * self.cav * k * reg_sqrt_pa(dp_pa, d.sqrt_reg_pa)
        } else {
            0.0
        };
        let q_l = d.k_l * dp_pa;
        let q = (q_b + q_c + q_l) * 1e3;
        let piston = d.a_hc * zd * 1e3; // L/s swept
                                        // Eqs 5.4 + 5.5 (or the gas energy balance)
        match self.heat_tau {
            Some(tau) => {
                let th = y[2];
                let h = (1.0 - th) / (tau * th);
                let dpc = (piston - q + vg * h / KAPPA) / (vg / (KAPPA * pc) + vc / ec.beta);
                let dvg = q - piston + vc / ec.beta * dpc;
                dy[0] = dpc;
                dy[2] = -(KAPPA - 1.0) * th * dvg / vg + (1.0 - th) / tau;
            }
            None => {
                dy[0] = (piston - q) / (vg / (d.n * pc) + vc / ec.beta);
                dy[2] = 0.0;
            }
        }
        // Eq 5.6
        let mut dpr = er.beta / vr * (ec.rho / er.rho * q - self.a_ann * zd * 1e3);
        if dpr < 0.0 {
            dpr *= ((y[1] - d.floor_mpa) / d.floor_taper_mpa).clamp(0.0, 1.0);
        }
        dy[1] = dpr;
    }

    fn force(&self, z: f64, zd: f64, y: &[f64; NS]) -> f64 {
        let d = &self.d;
        let pr = y[1].max(d.floor_mpa);
        (y[0] * d.a_hc - pr * self.a_ann - P_ATM_MPA * d.a_hr) * 1e6 + self.friction(z, zd)
    }
}

/// Simulate one harmonic bench test (true values, no noise).
pub fn simulate_strut(d: &StrutData, hidden: StrutHidden, test: &BenchTest) -> StrutRun {
    let w = 2.0 * PI * test.freq_hz;
    let a = test.amp_m;
    let v_peak = a * w;
    let s = Strut::new(d, hidden, v_peak);
    let dt = 1.0 / test.sample_hz;
    let sub = (dt / STRUT_MAX_STEP_S).ceil().max(1.0) as usize;
    let h = dt / sub as f64;
    let n_out = (test.cycles / test.freq_hz * test.sample_hz).round() as usize + 1;
    let zz = |t: f64| (a * (w * t).sin(), a * w * (w * t).cos());
    let mut y = [d.p_h0_mpa, d.p_h0_mpa, 1.0, 0.0];
    let mut run = StrutRun::default();
    let (mut k1, mut k2, mut k3, mut k4) = ([0.0; NS], [0.0; NS], [0.0; NS], [0.0; NS]);
    for k in 0..n_out {
        let t = k as f64 * dt;
        let (z, zd) = zz(t);
        run.time_s.push(t);
        run.displacement_m.push(z);
        run.velocity_m_s.push(zd);
        run.force_n.push(s.force(z, zd, &y));
        run.p_piston_pa.push(y[0] * 1e6);
        run.p_rod_pa.push(y[1].max(d.floor_mpa) * 1e6);
        if k + 1 == n_out {
            break;
        }
        for j in 0..sub {
            let ts = t + j as f64 * h;
            let (z0, v0) = zz(ts);
            let (zm, vm) = zz(ts + 0.5 * h);
            let (z1, v1) = zz(ts + h);
            s.rhs(z0, v0, &y, &mut k1);
            let mut yt = [0.0; NS];
            for i in 0..NS {
                yt[i] = y[i] + 0.5 * h * k1[i];
            }
            s.rhs(zm, vm, &yt, &mut k2);
            for i in 0..NS {
                yt[i] = y[i] + 0.5 * h * k2[i];
            }
            s.rhs(zm, vm, &yt, &mut k3);
            for i in 0..NS {
                yt[i] = y[i] + h * k3[i];
            }
            s.rhs(z1, v1, &yt, &mut k4);
            for i in 0..NS {
                y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
            }
            y[1] = y[1].max(d.floor_mpa);
        }
        assert!(
            y.iter().all(|v| v.is_finite()) && y[0] > 0.0,
            "independent strut model diverged at t = {t}: {y:?}"
        );
    }
    run
}

/// Sensor noise of the bench records (standard deviations): LVDT 0.02 mm, velocity
/// 0.5 mm/s, load cell 150 N, pressures 5 kPa.
pub const STRUT_NOISE: [(&str, f64); 5] = [
    ("displacement_m", 2.0e-5),
    ("velocity_m_s", 5.0e-4),
    ("force_n", 150.0),
    ("p_piston_pa", 5.0e3),
    ("p_rod_pa", 5.0e3),
];

/// Peak velocity of the 1-8 Hz tests (m/s).
pub const BENCH_PEAK_VELOCITY: f64 = 0.18;

/// The bench programme: (test, held out?). 0.1 Hz at 25 and 50 mm (50 Hz sampling, 2
/// cycles), then 1, 2, 4, 6, 8 Hz at a constant peak velocity of 0.18 m/s (500 Hz below
/// 4 Hz, 1000 Hz from 4 Hz; 5-10 cycles so the pressures reach a periodic steady state).
/// Held out: 2 Hz and 6 Hz, inside the range the 5 training tests span.
pub fn bench_programme() -> Vec<(BenchTest, bool)> {
    let v = BENCH_PEAK_VELOCITY;
    let hz = |f: f64, cycles: f64, sample_hz: f64| BenchTest {
        freq_hz: f,
        amp_m: ((v / (2.0 * PI * f)) * 1e4).round() / 1e4,
        cycles,
        sample_hz,
    };
    vec![
        (
            BenchTest {
                freq_hz: 0.1,
                amp_m: 0.025,
                cycles: 2.0,
                sample_hz: 50.0,
            },
            false,
        ),
        (
            BenchTest {
                freq_hz: 0.1,
                amp_m: 0.050,
                cycles: 2.0,
                sample_hz: 50.0,
            },
            false,
        ),
        (hz(1.0, 5.0, 500.0), false),
        (hz(2.0, 6.0, 500.0), true),
        (hz(4.0, 8.0, 1000.0), false),
        (hz(6.0, 8.0, 1000.0), true),
        (hz(8.0, 10.0, 1000.0), false),
    ]
}

/// Write the strut record set: `dir/train` (5 records), `dir/holdout` (2) and
/// `dir/truth.json`. Truth model: [`StrutData::perturbed`] plus the hidden effect.
pub fn strut_record_set(dir: &Path, hidden: Option<(&str, f64)>, seed: u64) {
    strut_record_set_of(dir, &StrutData::perturbed(), hidden, seed);
}

/// [`strut_record_set`] with the truth's parameters and choices `d`.
pub fn strut_record_set_of(dir: &Path, d: &StrutData, hidden: Option<(&str, f64)>, seed: u64) {
    let d = *d;
    let effect = match hidden {
        Some((name, size)) => StrutHidden::from_name(name, size),
        None => StrutHidden::None,
    };
    let mut listing = Vec::new();
    for (k, (test, holdout)) in bench_programme().into_iter().enumerate() {
        let run = simulate_strut(&d, effect, &test);
        let mut noise = Noise::new(seed, 0x5354_0000 + k as u64);
        let mut chans: Vec<Vec<f64>> = run.channels().iter().map(|(_, v)| v.to_vec()).collect();
        for (c, (_, sd)) in chans.iter_mut().zip(STRUT_NOISE.iter()) {
            noise.add(c, *sd);
        }
        let decimals = [7, 5, 1, 0, 0];
        let mut cols = vec![Column {
            name: "time_s",
            values: &run.time_s,
            decimals: 4,
        }];
        for (i, (nm, _)) in STRUT_NOISE.iter().enumerate() {
            cols.push(Column {
                name: nm,
                values: &chans[i],
                decimals: decimals[i],
            });
        }
        let name = format!(
            "hps_{k:02}_{}hz_{}mm",
            format!("{}", test.freq_hz).replace('.', "p"),
            format!("{}", (test.amp_m * 1e4).round() / 10.0).replace('.', "p")
        );
        let set = if holdout { "holdout" } else { "train" };
        let sidecar = serde_json::json!({
            "sample_rate_hz": test.sample_hz,
            "excitation": "harmonic",
            "frequency_hz": test.freq_hz,
            "amplitude_m": test.amp_m,
            "cycles": test.cycles,
            "sign_convention": "afsv-v1",
            "source": "independent implementation (tests/independent)",
            "units": {"time_s": "s", "displacement_m": "m", "velocity_m_s": "m/s",
                      "force_n": "N", "p_piston_pa": "Pa", "p_rod_pa": "Pa"},
        });
        write_record(&dir.join(set), &name, &cols, &sidecar);
        listing.push(
            serde_json::json!({"set": set, "name": name, "frequency_hz": test.freq_hz,
            "amplitude_m": test.amp_m, "cycles": test.cycles, "sample_rate_hz": test.sample_hz}),
        );
    }
    let truth = serde_json::json!({
        "model": "hps-strut",
        "source": "independent implementation (tests/independent/strut.rs)",
        "hidden_effect": match hidden {
            Some((name, size)) => serde_json::json!({"name": name, "size": size, "unit": StrutHidden::unit(name)}),
            None => serde_json::Value::Null,
        },
        "note": "truth = Eqs 5.1-5.12 with the gas-oil emulsion (gamma_0 > 0) at the perturbed parameters",
        "perturbations": STRUT_PERTURBATION.iter().map(|(n, v)| (n.to_string(), serde_json::json!(v))).collect::<serde_json::Map<_, _>>(),
        "parameters": d.json(),
        "noise_sd": STRUT_NOISE.iter().map(|(n, v)| (n.to_string(), serde_json::json!(v))).collect::<serde_json::Map<_, _>>(),
        "seed": seed,
        "integrator": {"method": "classic RK4, fixed step", "max_step_s": STRUT_MAX_STEP_S},
        "records": listing,
    });
    write_json(&dir.join("truth.json"), &truth);
}

/// States of one strut in a vehicle's state vector ([`VehicleStrut`]): the table at the
/// top of this file.
pub const STRUT_STATES: usize = NS;

/// The strut of this file as a vehicle drives it (the HPS front axle of
/// `tests/independent/vehicle3d`): the same Eqs 5.1-5.12, its travel `z` (m, compression
/// positive, from the charge position where `P = P_h0`) and rate from the vehicle, its
/// states a slice of the vehicle's. No bench peak velocity: the Eq 5.3 band at its
/// smallest width `v_h = vh_min`. The optional hidden gas heat transfer is the strut's own
/// (state 2, the gas temperature ratio relaxing to the wall's with time constant `tau`,
/// adiabatic with kappa = 1.4 between).
pub struct VehicleStrut {
    s: Strut,
}

impl VehicleStrut {
    /// The strut of `d`, with the gas heat transfer of time constant `gas_heat_tau_s` (s) or
    /// the polytropic gas law of Eq 5.4 (`None`).
    pub fn new(d: &StrutData, gas_heat_tau_s: Option<f64>) -> Self {
        let hidden = match gas_heat_tau_s {
            Some(tau) => StrutHidden::GasHeatTransfer(tau),
            None => StrutHidden::None,
        };
        Self {
            s: Strut::new(d, hidden, 0.0),
        }
    }

    /// The strut's data.
    pub fn data(&self) -> &StrutData {
        &self.s.d
    }

    /// The static travel (m) and states under the compressive force `force_n` (N): both
    /// chambers at `P = F / A_hr + p_atm` (no flow, Eq 5.1 at rest), the travel from the
    /// charge position by integrating the quasi-static compliance of both chambers,
    /// `dz/dP = (V_g / (n P) + V_c / beta_c + V_r / beta_r) / A_hr` (the sum of Eqs 5.5
    /// and 5.6 at equal pressures, 400 RK4 steps in P), with `n` the gas law's slow
    /// exponent: Eq 5.4's `n`, or 1 with the heat transfer (the gas at the wall's
    /// temperature at rest).
    pub fn static_state(&self, force_n: f64) -> (f64, [f64; NS]) {
        let s = &self.s;
        let d = &s.d;
        let p_s = force_n / (d.a_hr * 1e6) + P_ATM_MPA;
        let n_slow = if s.heat_tau.is_some() { 1.0 } else { d.n };
        let slope = |p: f64, z: f64| -> f64 {
            let vg = s.v_g0 * (d.p_h0_mpa / p).powf(1.0 / n_slow);
            let vc = s.v_c0 + s.v_g0 - d.a_hc * z * 1e3 - vg;
            let vr = s.v_r0 + s.a_ann * z * 1e3;
            let b = s.emulsion(p).beta;
            (vg / (n_slow * p) + vc / b + vr / b) / (d.a_hr * 1e3)
        };
        let steps = 400;
        let h = (p_s - d.p_h0_mpa) / steps as f64;
        let mut z = 0.0;
        for k in 0..steps {
            let p = d.p_h0_mpa + k as f64 * h;
            let k1 = slope(p, z);
            let k2 = slope(p + 0.5 * h, z + 0.5 * h * k1);
            let k3 = slope(p + 0.5 * h, z + 0.5 * h * k2);
            let k4 = slope(p + h, z + h * k3);
            z += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        }
        (z, [p_s, p_s, 1.0, 0.0])
    }

    /// State rates at travel `z` (m) and rate `zd` (m/s); `y` and `dy` this strut's
    /// [`STRUT_STATES`] entries (pressures in MPa).
    pub fn rhs(&self, z: f64, zd: f64, y: &[f64], dy: &mut [f64]) {
        let y: &[f64; NS] = y.try_into().expect("strut states");
        let dy: &mut [f64; NS] = dy.try_into().expect("strut state rates");
        self.s.rhs(z, zd, y, dy);
    }

    /// The strut force (N, compressive positive; Eq 5.1 with the friction of Eqs 5.2-5.3).
    pub fn force(&self, z: f64, zd: f64, y: &[f64]) -> f64 {
        let y: &[f64; NS] = y.try_into().expect("strut states");
        self.s.force(z, zd, y)
    }

    /// The rod-side pressure clamped at the cavitation floor after a step, as
    /// [`simulate_strut`] does.
    pub fn clamp(&self, y: &mut [f64]) {
        y[1] = y[1].max(self.s.d.floor_mpa);
    }

    /// The work done on a lossless strut (orifices, leakage and friction off: each chamber
    /// closed, the strut a spring) from travel `z0` at states `y0` to travel `z` (J): its
    /// stored energy. The chamber pressures follow `dy/dz` = the state rates at unit rate
    /// (no flow), the work `integral F dz` (`n` RK4 steps in z). Polytropic gas only.
    pub fn lossless_work(&self, z0: f64, y0: &[f64], z: f64, n: usize) -> f64 {
        let d = &self.s.d;
        assert!(
            d.c_b == 0.0 && d.c_v == 0.0 && d.k_l == 0.0 && self.s.heat_tau.is_none(),
            "the strut's stored energy is the lossless polytropic strut's"
        );
        let mut y: [f64; NS] = y0.try_into().expect("strut states");
        let h = (z - z0) / n as f64;
        let slope = |zz: f64, y: &[f64; NS]| -> ([f64; NS], f64) {
            let mut dy = [0.0; NS];
            self.s.rhs(zz, 1.0, y, &mut dy);
            (dy, self.s.force(zz, 0.0, y))
        };
        let mut work = 0.0;
        let step = |y: &[f64; NS], k: &[f64; NS], f: f64| -> [f64; NS] {
            let mut t = *y;
            for i in 0..NS {
                t[i] += f * k[i];
            }
            t
        };
        for j in 0..n {
            let zj = z0 + j as f64 * h;
            let (k1, f1) = slope(zj, &y);
            let (k2, f2) = slope(zj + 0.5 * h, &step(&y, &k1, 0.5 * h));
            let (k3, f3) = slope(zj + 0.5 * h, &step(&y, &k2, 0.5 * h));
            let (k4, f4) = slope(zj + h, &step(&y, &k3, h));
            for i in 0..NS {
                y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
            }
            work += h / 6.0 * (f1 + 2.0 * f2 + 2.0 * f3 + f4);
        }
        work
    }
}
