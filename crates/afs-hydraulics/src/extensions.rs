//! Switchable model extensions for the model-discrepancy workflow (issue 6 catalogue).
//!
//! Each extension is a documented physical mechanism with its own parameters. With every
//! field `None`/`false` ([`AfsExtensions::default`]) the model is the baseline of Chapter 3
//! bit for bit: the extension code paths are not entered.

use crate::error::{check, AfsError};
use serde::{Deserialize, Serialize};

/// Supply pressure that drops with the valve flow (pump delivery / relief-valve droop and
/// supply-line loss): P_s,eff = P_s - r · q_1, solved implicitly with the valve law.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SupplyDroop {
    /// Droop r, pressure loss per unit supply flow (Pa per m³/s). E.g. 30 bar at 200 L/min ≈ 9e8.
    pub droop_pa_s_per_m3: f64,
}

/// Coulomb (dry) seal friction per strut, smoothed: F = F_c · tanh(v / v_s), opposing the
/// strut's extension speed v.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CoulombFriction {
    /// F_c, Coulomb friction force level per strut (N).
    pub force_n: f64,
    /// v_s, velocity scale of the tanh smoothing (m/s), e.g. 1e-3.
    pub velocity_scale_m_s: f64,
}

/// Pressure-dependent effective bulk modulus of oil with entrained (undissolved) air
/// (Merritt 1967; Yu, Chen & Lu 1994): with the air volume fraction alpha_0 at atmospheric
/// pressure p_a and a polytropic air process of index n,
/// x(p) = alpha_0/(1-alpha_0) · (p_a/p)^{1/n} (air-to-oil volume ratio) and
/// 1/B_e(p) = (1/B_oil + x/(n p)) / (1 + x), with B_oil = `AfsParams::bulk_modulus_pa`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EntrainedAir {
    /// alpha_0, air volume fraction of the mixture at atmospheric pressure (-), e.g. 0.01.
    pub air_fraction_atm: f64,
    /// n, polytropic index of the air (1 = isothermal, 1.4 = adiabatic).
    pub polytropic_index: f64,
    /// p_a, atmospheric pressure at which alpha_0 is stated (Pa, absolute).
    pub atmospheric_pressure_pa: f64,
}

impl EntrainedAir {
    /// Effective bulk modulus B_e(p) (Pa) of the air-oil mixture at absolute pressure `p`.
    #[inline]
    pub fn bulk_modulus(&self, b_oil: f64, p: f64) -> f64 {
        let r = self.air_fraction_atm / (1.0 - self.air_fraction_atm);
        let x = r * (self.atmospheric_pressure_pa / p).powf(1.0 / self.polytropic_index);
        (1.0 + x) / (1.0 / b_oil + x / (self.polytropic_index * p))
    }
}

/// First-order lag of the steering valve's opening (section 3.4.2 names "delays in the
/// steering valve flows" among the causes of the measured lag): the spool displacement that
/// meters the flows, `x_v`, follows the commanded displacement `X = theta_sw - theta_h`
/// (Eq 3.9) through `dx_v/dt = (X - x_v) / tau` (pilot-stage and spool inertia, flow-force
/// settling). Adds one state (rad) to the steering system.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ValveLag {
    /// tau, time constant of the valve opening (s), e.g. 0.04.
    pub tau_s: f64,
}

/// The set of switchable extensions. `Default` = all off = baseline.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct AfsExtensions {
    /// Supply pressure drop with flow.
    pub supply_droop: Option<SupplyDroop>,
    /// Strut Coulomb friction in addition to the viscous mu_v term.
    pub coulomb_friction: Option<CoulombFriction>,
    /// Pressure-dependent bulk modulus from entrained air (replaces the constant B_eff).
    pub entrained_air: Option<EntrainedAir>,
    /// First-order lag of the valve opening (adds the lagged spool state).
    pub valve_lag: Option<ValveLag>,
    /// Drop the velocity-dependent term of Eq 3.6 and use the constant-coefficient leakage
    /// of Eq 3.5 (k_lL = k_lR = k_l0, the model of refs [10, 12, 19]).
    pub constant_leakage_only: bool,
}

impl AfsExtensions {
    /// Validate the parameters of every enabled extension.
    pub fn validate(&self) -> Result<(), AfsError> {
        if let Some(d) = &self.supply_droop {
            check(
                "supply_droop.droop_pa_s_per_m3",
                d.droop_pa_s_per_m3,
                d.droop_pa_s_per_m3 >= 0.0,
                "must be >= 0",
            )?;
        }
        if let Some(c) = &self.coulomb_friction {
            check(
                "coulomb_friction.force_n",
                c.force_n,
                c.force_n >= 0.0,
                "must be >= 0",
            )?;
            check(
                "coulomb_friction.velocity_scale_m_s",
                c.velocity_scale_m_s,
                c.velocity_scale_m_s > 0.0,
                "must be > 0",
            )?;
        }
        if let Some(v) = &self.valve_lag {
            check(
                "valve_lag.tau_s",
                v.tau_s,
                v.tau_s > 0.0 && v.tau_s <= 10.0,
                "must lie in (0, 10] s",
            )?;
        }
        if let Some(a) = &self.entrained_air {
            check(
                "entrained_air.air_fraction_atm",
                a.air_fraction_atm,
                (0.0..1.0).contains(&a.air_fraction_atm),
                "must lie in [0, 1)",
            )?;
            check(
                "entrained_air.polytropic_index",
                a.polytropic_index,
                (1.0..=1.4).contains(&a.polytropic_index),
                "must lie in [1, 1.4]",
            )?;
            check(
                "entrained_air.atmospheric_pressure_pa",
                a.atmospheric_pressure_pa,
                a.atmospheric_pressure_pa > 0.0,
                "must be > 0",
            )?;
        }
        Ok(())
    }
}
