//! Readings of the laws the dissertation states ambiguously (issue 24): each is an enum
//! whose default is the reading the crate has always used, so a strut built without
//! [`HpsStrut::with_laws`](crate::HpsStrut::with_laws) runs bit for bit as before.
//! `afsv discover` tries the other readings as calibration switches (docs/discovery.md).

use serde::{Deserialize, Serialize};

/// Density `rho_bar` of the orifice laws of Eq 5.12 (bleed orifices and check valves).
/// The text writes one `rho_bar` for flows in both directions without saying whose density
/// it is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum OrificeDensity {
    /// The mean of both chambers' emulsion densities (the bar read as an average; the
    /// crate's reading).
    #[default]
    Mean,
    /// The upstream chamber's density: the piston side's when `P_hc >= P_hr`, else the rod
    /// side's (the orifice equation's own density, that of the fluid entering the orifice).
    Upstream,
}

/// Pressure below which the orifice laws of Eq 5.12 leave the square root ([`crate::flow`]'s
/// regularisation scale, Pa) under [`OrificeTransition::Laminar`]. For the 3.7 mm bleed bore
/// of Table 6.3 (11 mm²) in an ISO VG 32 oil (32 mm²/s) the jet's Reynolds number falls
/// below about 1 000, where a sharp-edged orifice stops being turbulent, at a pressure drop
/// of a few tens of kPa (`850 (1000 * 32e-6 / 3.74e-3)^2 / 2 = 31 kPa`); 20 kPa is the round
/// number below that.
pub const LAMINAR_TRANSITION_PA: f64 = 20_000.0;

/// The orifice laws of Eq 5.12 near zero pressure drop. The text gives the turbulent law
/// only; whether it holds down to small drops is not said.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum OrificeTransition {
    /// Turbulent down to the numerical regularisation `p_reg` of the parameters (100 Pa
    /// for the built-in struts; the crate's reading).
    #[default]
    Turbulent,
    /// Laminar-like below [`LAMINAR_TRANSITION_PA`]: the regularisation scale is
    /// `max(p_reg, LAMINAR_TRANSITION_PA)`, so the flow is linear in the pressure drop
    /// below it and the square-root law holds above.
    Laminar,
}

/// The readings a strut runs with (default: the crate's readings).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct StrutLaws {
    /// Density of the orifice laws (Eq 5.12).
    pub orifice_density: OrificeDensity,
    /// Orifice laws near zero pressure drop (Eq 5.12).
    pub orifice_transition: OrificeTransition,
}

impl StrutLaws {
    /// Regularisation pressure (Pa) of the orifice square root for the parameters' `p_reg`.
    #[inline]
    pub fn orifice_regularisation(&self, p_reg: f64) -> f64 {
        match self.orifice_transition {
            OrificeTransition::Turbulent => p_reg,
            OrificeTransition::Laminar => p_reg.max(LAMINAR_TRANSITION_PA),
        }
    }

    /// Density (kg/m^3) of the orifice laws between the piston side (pressure `p_c`,
    /// density `rho_c`) and the rod side (`p_r`, `rho_r`).
    #[inline]
    pub fn orifice_rho(&self, p_c: f64, rho_c: f64, p_r: f64, rho_r: f64) -> f64 {
        match self.orifice_density {
            OrificeDensity::Mean => 0.5 * (rho_c + rho_r),
            OrificeDensity::Upstream => {
                if p_c >= p_r {
                    rho_c
                } else {
                    rho_r
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_readings_are_the_crates() {
        let l = StrutLaws::default();
        assert_eq!(l.orifice_regularisation(100.0), 100.0);
        assert_eq!(l.orifice_rho(2e6, 840.0, 1e6, 850.0), 0.5 * (840.0 + 850.0));
        let other = StrutLaws {
            orifice_density: OrificeDensity::Upstream,
            orifice_transition: OrificeTransition::Laminar,
        };
        assert_eq!(other.orifice_regularisation(100.0), LAMINAR_TRANSITION_PA);
        assert_eq!(other.orifice_regularisation(5e4), 5e4);
        assert_eq!(other.orifice_rho(2e6, 840.0, 1e6, 850.0), 840.0);
        assert_eq!(other.orifice_rho(1e6, 840.0, 2e6, 850.0), 850.0);
    }
}
