//! Switchable model extensions for the model-discrepancy workflow. Each is a documented
//! physical mechanism with its own parameters; `None` leaves the baseline model of Eqs
//! 5.1-5.12 untouched, bit for bit.

use crate::error::{positive, HpsError};
use serde::{Deserialize, Serialize};

/// Gas heat transfer between isothermal and adiabatic (section 5.4.2 attributes the measured
/// low-frequency pressure hysteresis to it). Replaces the polytropic law of Eq 5.4 by an ideal
/// gas with an energy balance and Newtonian heat exchange with the wall at the static
/// temperature: `T' = -(kappa - 1) T V_g'/V_g + (T_0 - T)/tau`, `P_hc = P_h0 (V_g0/V_g)(T/T_0)`.
/// `tau -> 0` gives an isothermal, `tau -> inf` an adiabatic (`kappa`) gas spring.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct HeatTransfer {
    /// Thermal time constant tau (s).
    pub tau: f64,
    /// Ratio of specific heats of the gas kappa (1.4 for nitrogen).
    pub kappa: f64,
}

/// Growth of the emulsion's gas fraction with strut velocity (Fig 5.4b: the identified mean
/// gamma_0 rises with the peak velocity): `gamma_0,eff = gamma_0 + k_gamma u` on the strut's
/// velocity-amplitude state `u` (a peak detector of the strut speed, [`crate::HpsStrut`]),
/// with the gas taken from the free gas volume at the current pressure (the bookkeeping of
/// [`crate::StrutParams::with_gamma0`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct GasFractionGrowth {
    /// Growth rate k_gamma (s/m).
    pub k_gamma: f64,
}

/// Asymmetric seal friction (section 5.4.2: the model underestimates friction in compression,
/// "structural asymmetry of the strut seals"): Coulomb and stiction levels are multiplied by
/// `compression` while compressing and `extension` while extending.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct AsymmetricFriction {
    /// Factor on F_c, F_s in compression.
    pub compression: f64,
    /// Factor on F_c, F_s in extension.
    pub extension: f64,
}

/// Check-valve opening lag: a first-order valve-opening state `x_v` in [0, 1],
/// `x_v' = (target - x_v)/tau` with target 1 when `P_hc > P_hr` and 0 otherwise; the check
/// flow of Eq 5.12 is multiplied by `x_v` (valve inertia and spring, section 5.3.2 "valve
/// construction and dynamics").
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ValveLag {
    /// Opening/closing time constant (s).
    pub tau: f64,
}

/// The set of switchable extensions. `HpsExtensions::default()` (all `None`) is the baseline.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct HpsExtensions {
    /// Gas heat transfer (adds the gas-temperature state).
    pub heat_transfer: Option<HeatTransfer>,
    /// Gas fraction growing with peak strut velocity.
    pub gas_fraction_growth: Option<GasFractionGrowth>,
    /// Compression/extension friction levels.
    pub asymmetric_friction: Option<AsymmetricFriction>,
    /// Check-valve opening lag (adds the valve-opening state).
    pub valve_lag: Option<ValveLag>,
}

impl HpsExtensions {
    /// The baseline model (no extension).
    pub fn none() -> Self {
        Self::default()
    }

    /// True when no extension is switched on.
    pub fn is_baseline(&self) -> bool {
        *self == Self::default()
    }

    /// Validate the parameters of the extensions that are on.
    pub fn validate(&self) -> Result<(), HpsError> {
        if let Some(h) = self.heat_transfer {
            positive("heat_transfer.tau", h.tau)?;
            if !(h.kappa > 1.0 && h.kappa <= 1.7) {
                return Err(HpsError::InvalidParameter {
                    field: "heat_transfer.kappa",
                    value: h.kappa,
                    reason: "ratio of specific heats must lie in (1, 1.7]",
                });
            }
        }
        if let Some(g) = self.gas_fraction_growth {
            crate::error::non_negative("gas_fraction_growth.k_gamma", g.k_gamma)?;
        }
        if let Some(a) = self.asymmetric_friction {
            crate::error::non_negative("asymmetric_friction.compression", a.compression)?;
            crate::error::non_negative("asymmetric_friction.extension", a.extension)?;
        }
        if let Some(v) = self.valve_lag {
            positive("valve_lag.tau", v.tau)?;
        }
        Ok(())
    }
}
