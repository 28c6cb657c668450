//! Parameter sets of the strut (Eqs 5.1-5.12 / 6.9-6.18): geometry, fluid, gas, flow paths
//! and seal friction, with validation and the two built-in struts.

use crate::error::{non_negative, positive, HpsError};
use crate::lab::{lab_params, LabConfig, LabReported, LAB_GAS_LENGTH_M};
use serde::{Deserialize, Serialize};

/// Seal-friction parameters of Eqs 5.2-5.3.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FrictionParams {
    /// Viscous friction coefficient mu_v (N s/m), Eq 5.2.
    pub mu_v: f64,
    /// Coulomb friction force F_c (N), Eq 5.2.
    pub f_c: f64,
    /// Stiction force F_s (N), Eq 5.2.
    pub f_s: f64,
    /// Stribeck coefficient k_s (s/m), Eq 5.2.
    pub k_s: f64,
    /// Hysteresis transition band as a fraction of the peak strut velocity:
    /// `v_h = max(vh_ratio * v_peak, vh_min)` (section 5.3.1: the band widens with peak
    /// velocity); the strut uses its velocity-amplitude state `u` as `v_peak`.
    pub vh_ratio: f64,
    /// Smallest transition band v_h (m/s).
    pub vh_min: f64,
}

impl FrictionParams {
    /// Transition velocity band v_h for a motion of peak velocity `v_peak` (m/s).
    pub fn v_h(&self, v_peak: f64) -> f64 {
        (self.vh_ratio * v_peak.abs()).max(self.vh_min)
    }

    /// Validate every field (names the field on error).
    pub fn validate(&self) -> Result<(), HpsError> {
        non_negative("friction.mu_v", self.mu_v)?;
        non_negative("friction.f_c", self.f_c)?;
        non_negative("friction.f_s", self.f_s)?;
        non_negative("friction.k_s", self.k_s)?;
        non_negative("friction.vh_ratio", self.vh_ratio)?;
        positive("friction.vh_min", self.vh_min)?;
        Ok(())
    }
}

/// Complete parameter set of one strut. SI units, absolute pressures; the reference state
/// (subscript 0) is the static mid-stroke position `z_s = 0` at pressure `p_h0` in both chambers.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StrutParams {
    /// Effective piston area A_hc (m^2), Eq 5.1.
    pub a_hc: f64,
    /// Effective rod area A_hr (m^2), Eq 5.1; the rod-side annulus is `A_hc - A_hr`.
    pub a_hr: f64,
    /// Number of bleed orifices n_b, Eq 5.12.
    pub n_b: u32,
    /// Opening area of one bleed orifice A_b (m^2).
    pub a_b: f64,
    /// Discharge coefficient of the bleed orifices C_b.
    pub c_b: f64,
    /// Number of check valves n_v, Eq 5.12.
    pub n_v: u32,
    /// Opening area of one check valve A_v (m^2).
    pub a_v: f64,
    /// Discharge coefficient of the check valves C_v.
    pub c_v: f64,
    /// Laminar leakage coefficient k_l (m^3/(Pa s)), Eq 5.12.
    pub k_l: f64,
    /// Bulk modulus of pure oil beta_h (Pa), Eqs 5.8, 5.11.
    pub beta_h: f64,
    /// Mass density of pure oil rho_h (kg/m^3), Eq 5.10.
    pub rho_h: f64,
    /// Gas (and fluid) pressure at the static position P_h0 (Pa, absolute), Eq 5.4.
    pub p_h0: f64,
    /// Free gas volume at the static position V_g0 (m^3), Eq 5.4.
    pub v_g0: f64,
    /// Emulsion volume in the piston-side chamber at the static position V_c0 (m^3), Eq 5.7.
    pub v_c0: f64,
    /// Emulsion volume in the rod-side chamber at the static position V_r0 (m^3), Eq 5.7.
    pub v_r0: f64,
    /// Initial (steady-state) gas volume fraction of the emulsion gamma_0 = V_gi0/V_hi0, Eq 5.9.
    pub gamma0: f64,
    /// Polytropic exponent n, Eqs 5.4, 5.8, 5.11.
    pub n: f64,
    /// Seal friction, Eqs 5.2-5.3.
    pub friction: FrictionParams,
    /// Allowed travel each side of the static position (m); excitations beyond it are refused.
    pub travel: f64,
    /// Ambient pressure on the outer rod end (Pa). Eq 5.1 is written with gauge pressures; with
    /// absolute pressures the rod end sees `-p_amb * A_hr`. Set 0 for Eq 5.1 literally.
    pub p_amb: f64,
    /// Vapour/gas-release pressure (Pa): chamber pressures are kept above it (cavitation guard).
    pub p_vap: f64,
    /// Regularisation pressure of the square-root orifice law near zero pressure difference (Pa).
    pub p_reg: f64,
}

/// Default ambient pressure (Pa).
pub const P_ATM: f64 = 101_325.0;
/// Default vapour / gas-release pressure of the oil (Pa).
pub const P_VAPOUR: f64 = 2_000.0;
/// Default regularisation pressure of the orifice square root (Pa).
pub const P_REG: f64 = 100.0;
/// Length of oil left in the rod-side chamber at full extension (m): an assumption, the
/// dissertation does not give the dead volume.
pub const ROD_DEAD_LENGTH: f64 = 0.010;

impl StrutParams {
    /// Front-axle strut of the 35 t articulated dump truck, Table 6.3.
    ///
    /// Table 6.3 gives the geometry, flow paths, oil and gas. Not in the table, chosen here:
    /// - the 11.4 L of oil is split so the rod-side chamber holds `A_ann * (travel + 10 mm)`
    ///   at the static position; emulsion volumes are the oil volumes times `1 + gamma_0`;
    /// - 5.8 MPa is read as absolute (as the chapter 5 pressures, see [`crate::lab`]);
    /// - seal friction is the laboratory strut's (section 5.3.2) scaled by the ratio of the
    ///   piston perimeters `sqrt(A_hc / A_hc,lab)` (seal force grows with seal length);
    ///   `k_s` and the band `v_h` are kept.
    pub fn front_axle() -> Self {
        let a_hc = 0.038;
        let a_hr = 0.0254;
        let travel = 0.120;
        let oil = 11.4e-3;
        let gamma0 = 0.02;
        let oil_r = (a_hc - a_hr) * (travel + ROD_DEAD_LENGTH);
        let oil_c = oil - oil_r;
        let lab = StrutParams::lab(LabConfig::TwoOrifices);
        let scale = (a_hc / lab.a_hc).sqrt();
        let friction = FrictionParams {
            mu_v: lab.friction.mu_v * scale,
            f_c: lab.friction.f_c * scale,
            f_s: lab.friction.f_s * scale,
            ..lab.friction
        };
        Self {
            a_hc,
            a_hr,
            n_b: 4,
            a_b: 11e-6,
            c_b: 0.7,
            n_v: 2,
            a_v: 8e-6,
            c_v: 0.6,
            k_l: 5e-12,
            beta_h: 1700e6,
            rho_h: 850.0,
            p_h0: 5.8e6,
            v_g0: 4.5e-3,
            v_c0: oil_c * (1.0 + gamma0),
            v_r0: oil_r * (1.0 + gamma0),
            gamma0,
            n: 1.4,
            friction,
            travel,
            p_amb: P_ATM,
            p_vap: P_VAPOUR,
            p_reg: P_REG,
        }
    }

    /// Laboratory strut of chapter 5 (one or two bleed orifices), derived from the numbers
    /// the text reports ([`LabReported::paper`]) with the gas-column length
    /// [`LAB_GAS_LENGTH_M`] that [`crate::lab::identify_lab`] fits to them (a constant: nothing
    /// is fitted here); see `docs/hps-emulsion.md`.
    pub fn lab(config: LabConfig) -> Self {
        lab_params(&LabReported::paper(), config, LAB_GAS_LENGTH_M)
    }

    /// Annular rod-side area `A_hc - A_hr` (m^2).
    pub fn a_ann(&self) -> f64 {
        self.a_hc - self.a_hr
    }

    /// Oil volumes (piston side, rod side) at the static position, without entrapped gas (m^3).
    pub fn oil_volumes(&self) -> (f64, f64) {
        (
            self.v_c0 / (1.0 + self.gamma0),
            self.v_r0 / (1.0 + self.gamma0),
        )
    }

    /// Same strut with the emulsion's gas fraction set to `gamma0`, moving gas between the free
    /// gas volume and the emulsion: the oil volumes and the total gas volume (free + entrapped,
    /// at `p_h0`) are kept (section 5.4.3: "gas volume entrapment in the oil reduces the volume
    /// of free gas").
    pub fn with_gamma0(&self, gamma0: f64) -> Result<Self, HpsError> {
        check_gamma0(gamma0)?;
        let (oil_c, oil_r) = self.oil_volumes();
        let total_gas = self.v_g0 + self.gamma0 * (oil_c + oil_r);
        let mut p = *self;
        p.gamma0 = gamma0;
        p.v_g0 = total_gas - gamma0 * (oil_c + oil_r);
        p.v_c0 = oil_c * (1.0 + gamma0);
        p.v_r0 = oil_r * (1.0 + gamma0);
        p.validate()?;
        Ok(p)
    }

    /// Same strut with the rod-side emulsion volume at the static position set to `v_r0`
    /// (m^3), the difference taken from (or given to) the piston side: the chamber split of
    /// the oil, which Table 6.3 gives only in total (11.4 L). Both chambers keep the gas
    /// fraction, so the total oil is kept. The rod-side dead volume (oil left at full
    /// extension) is `v_r0 / (1 + gamma_0) - (a_hc - a_hr) travel`. Errors name the field
    /// ([`StrutParams::validate`]: the rod side must not empty before full extension, the
    /// piston side must keep a non-negative volume).
    pub fn with_rod_volume(&self, v_r0: f64) -> Result<Self, HpsError> {
        if !v_r0.is_finite() {
            return Err(HpsError::InvalidParameter {
                field: "v_r0",
                value: v_r0,
                reason: "rod-side emulsion volume must be finite",
            });
        }
        let mut p = *self;
        p.v_c0 = self.v_c0 + self.v_r0 - v_r0;
        p.v_r0 = v_r0;
        p.validate()?;
        Ok(p)
    }

    /// Validate every field; the error names the first offending field.
    pub fn validate(&self) -> Result<(), HpsError> {
        self.validate_ported(false)
    }

    /// As [`StrutParams::validate`]; with `ported` the chambers also have external ports
    /// (hydraulic lines, [`crate::interconnect`]), so a sealed piston (no bleed orifice, no
    /// leakage) is accepted: the rod-side chamber then discharges through its port.
    pub fn validate_ported(&self, ported: bool) -> Result<(), HpsError> {
        positive("a_hc", self.a_hc)?;
        positive("a_hr", self.a_hr)?;
        if self.a_hr >= self.a_hc {
            return Err(HpsError::InvalidParameter {
                field: "a_hr",
                value: self.a_hr,
                reason: "rod area must be smaller than the piston area a_hc",
            });
        }
        non_negative("a_b", self.a_b)?;
        non_negative("c_b", self.c_b)?;
        non_negative("a_v", self.a_v)?;
        non_negative("c_v", self.c_v)?;
        non_negative("k_l", self.k_l)?;
        if !ported && (self.n_b == 0 || self.a_b == 0.0 || self.c_b == 0.0) && self.k_l == 0.0 {
            return Err(HpsError::InvalidParameter {
                field: "n_b",
                value: self.n_b as f64,
                reason: "no bleed orifice and no leakage (k_l = 0): the rod-side chamber \
                         cannot discharge in extension",
            });
        }
        positive("beta_h", self.beta_h)?;
        positive("rho_h", self.rho_h)?;
        positive("p_h0", self.p_h0)?;
        positive("v_g0", self.v_g0)?;
        non_negative("v_c0", self.v_c0)?;
        positive("v_r0", self.v_r0)?;
        check_gamma0(self.gamma0)?;
        if !(self.n >= 1.0 && self.n <= 1.7) {
            return Err(HpsError::InvalidParameter {
                field: "n",
                value: self.n,
                reason: "polytropic exponent must lie in [1, 1.7] (isothermal to adiabatic)",
            });
        }
        self.friction.validate()?;
        positive("travel", self.travel)?;
        if self.v_r0 - self.a_ann() * self.travel <= 0.0 {
            return Err(HpsError::InvalidParameter {
                field: "v_r0",
                value: self.v_r0,
                reason: "rod-side chamber would be empty before full extension (v_r0 <= (a_hc - a_hr) * travel)",
            });
        }
        if self.v_g0 - self.a_hr * self.travel <= 0.0 {
            return Err(HpsError::InvalidParameter {
                field: "v_g0",
                value: self.v_g0,
                reason: "gas volume would vanish before full compression (v_g0 <= a_hr * travel)",
            });
        }
        non_negative("p_amb", self.p_amb)?;
        non_negative("p_vap", self.p_vap)?;
        if self.p_vap >= self.p_h0 {
            return Err(HpsError::InvalidParameter {
                field: "p_vap",
                value: self.p_vap,
                reason: "vapour pressure must be below p_h0",
            });
        }
        positive("p_reg", self.p_reg)?;
        Ok(())
    }
}

fn check_gamma0(gamma0: f64) -> Result<(), HpsError> {
    if gamma0.is_finite() && (0.0..0.5).contains(&gamma0) {
        Ok(())
    } else {
        Err(HpsError::InvalidParameter {
            field: "gamma0",
            value: gamma0,
            reason: "gas volume fraction must lie in [0, 0.5)",
        })
    }
}
