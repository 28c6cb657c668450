//! The laboratory strut of chapter 5, identified from the numbers the text reports.
//!
//! Table 5.1 (the strut's constant parameters) is missing from the dissertation's text, so the
//! geometry is identified from what the text gives ([`LabReported::paper`], transcribed with
//! section references in `fixtures/reported/hps_lab.json`), in four steps:
//!
//! 1. Gas column: the static pressures 1.43 / 2.05 / 2.74 MPa at 75 / 100 / 115 mm from the
//!    bottom position, charged at 0.68 MPa there (section 5.4.1), follow
//!    `P = P_charge (L / (L - z))^n` with `L = V_g,bottom / A_hr` (quasi-statically the gas is
//!    compressed by the rod volume `A_hr z`). A free fit gives `n` near 1.37 (reported
//!    pressures read as absolute); the dissertation uses n = 1.4 for this strut (section 6.2.5:
//!    "the polytropic exponent ... remain the same as those of the scaled strut"), so `L` is
//!    fitted with n = 1.4.
//! 2. Annulus: in compression the rod-side pressure falls to about 0.5 MPa at most (section
//!    5.4.2) at the peak velocity 0.2356 m/s through one bleed orifice plus the check valves of
//!    the one-orifice strut from its saturation pressure 0.87 MPa; the quasi-steady orifice law
//!    of Eq 5.12 then gives `A_hc - A_hr = (C_b A_b + n_v C_v A_v) sqrt(2 dP / rho_h) / v_peak`.
//! 3. Piston and rod areas: the annulus split with the front-axle strut's ratio
//!    `A_hr / A_hc = 0.0254 / 0.038` (Table 6.3; that strut is "scaled" from this one).
//! 4. Reference state: mid-stroke at 75 mm from the bottom (1.4 MPa at mid-position, section
//!    5.4.1); the free gas volume there is the geometric one, `A_hr (L - 75 mm)`, at the
//!    saturation pressure 0.87 MPa (one orifice) or 1.02 MPa (two orifices); 1 L of oil split
//!    so the rod chamber holds `A_ann (75 mm + 10 mm dead length)`.
//!
//! Orifice and check-valve areas are taken from Table 6.3 (11 mm^2, 8 mm^2, two check valves):
//! the text says the larger strut got *more* bleed orifices, not larger ones. Not reported and
//! assumed: Coulomb and stiction forces (150 N and 100 N), the friction band ratio (10 % of
//! the peak velocity) and gamma_0 (4 % one orifice, 2 % two orifices: the text says only that
//! the one-orifice strut shows the higher gas fraction, Fig 5.4b).

use crate::error::HpsError;
use crate::params::{FrictionParams, StrutParams, P_ATM, P_REG, P_VAPOUR, ROD_DEAD_LENGTH};
use crate::strut::HpsStrut;
use crate::HpsExtensions;
use optimize::least_squares::{fit, FitOptions, Problem};
use serde::{Deserialize, Serialize};

/// Which laboratory configuration (section 5.2: the tests were repeated with one bleed
/// orifice blocked).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum LabConfig {
    /// One bleed orifice open.
    OneOrifice,
    /// Both bleed orifices open.
    TwoOrifices,
}

/// Numbers the dissertation reports about the laboratory strut (SI units).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LabReported {
    /// Oil filled (m^3), section 5.2: 1 L.
    pub oil_volume: f64,
    /// Nitrogen charge pressure at the bottom position (Pa), section 5.2: 0.68 MPa.
    pub charge_pressure: f64,
    /// Static displacements from the bottom (m), section 5.4.1: 75, 100, 115 mm.
    pub static_displacements: [f64; 3],
    /// Pressures reached at those displacements (Pa), section 5.4.1: 1.43, 2.05, 2.74 MPa.
    pub static_pressures: [f64; 3],
    /// Pressure at mid-position before emulsion formed (Pa), section 5.4.1: about 1.4 MPa.
    pub mid_position_pressure: f64,
    /// Saturation pressure, one orifice (Pa), section 5.4.2: 0.87 MPa.
    pub saturation_pressure_one: f64,
    /// Saturation pressure, two orifices (Pa), section 5.4.2: 1.02 MPa.
    pub saturation_pressure_two: f64,
    /// Bleed discharge coefficient, one orifice, section 5.3.2: 0.74.
    pub c_b_one: f64,
    /// Bleed discharge coefficient, two orifices, section 5.3.2: 0.76.
    pub c_b_two: f64,
    /// Check-valve discharge coefficient, section 5.3.2: 0.6.
    pub c_v: f64,
    /// Leakage coefficient (m^3/(Pa s)), section 5.3.2: 5e-12.
    pub k_l: f64,
    /// Stribeck coefficient (s/m), section 5.3.2: 50.
    pub k_s: f64,
    /// Viscous friction coefficient (N s/m), section 5.3.2: 50.
    pub mu_v: f64,
    /// Largest peak velocity of the programme (m/s), sections 5.4.2-5.4.3: 0.2356.
    pub peak_velocity: f64,
    /// Lowest rod-side pressure during compression (Pa), section 5.4.2: about 0.5 MPa.
    pub p_rod_min_compression: f64,
    /// Polytropic exponent of this strut (section 6.2.5 / Table 6.3): 1.4.
    pub n: f64,
}

impl LabReported {
    /// The values as printed in the dissertation.
    pub fn paper() -> Self {
        Self {
            oil_volume: 1.0e-3,
            charge_pressure: 0.68e6,
            static_displacements: [0.075, 0.100, 0.115],
            static_pressures: [1.43e6, 2.05e6, 2.74e6],
            mid_position_pressure: 1.4e6,
            saturation_pressure_one: 0.87e6,
            saturation_pressure_two: 1.02e6,
            c_b_one: 0.74,
            c_b_two: 0.76,
            c_v: 0.6,
            k_l: 5e-12,
            k_s: 50.0,
            mu_v: 50.0,
            peak_velocity: 0.2356,
            p_rod_min_compression: 0.5e6,
            n: 1.4,
        }
    }
}

/// Result of [`identify_lab`]: the strut and the intermediate numbers.
#[derive(Debug, Clone, PartialEq)]
pub struct LabIdentification {
    /// The identified strut.
    pub params: StrutParams,
    /// Gas-column length `V_g,bottom / A_hr` fitted with `n = reported.n` (m).
    pub gas_length: f64,
    /// Gas-column length and exponent of the free two-parameter fit (m, -).
    pub free_fit: (f64, f64),
    /// The identified strut when fresh: no emulsion yet (gamma_0 = 0, the oil volumes
    /// without gas), charged at the bottom, so P_h0 is the charge pressure compressed to
    /// mid-stroke along the fitted gas column (section 5.4.1).
    pub fresh: StrutParams,
    /// Static pressures of the identified fresh strut (no emulsion) at the reported
    /// displacements (Pa).
    pub static_pressures: [f64; 3],
    /// Mid-stroke position measured from the bottom (m).
    pub mid_stroke: f64,
}

struct StaticFit<'a> {
    rep: &'a LabReported,
    fixed_n: Option<f64>,
}

impl Problem for StaticFit<'_> {
    fn n_params(&self) -> usize {
        if self.fixed_n.is_some() {
            1
        } else {
            2
        }
    }
    fn n_residuals(&self) -> usize {
        3
    }
    fn residuals(&self, p: &[f64], r: &mut [f64]) -> Result<(), String> {
        let l = p[0];
        let n = self.fixed_n.unwrap_or_else(|| p[1]);
        for i in 0..3 {
            let z = self.rep.static_displacements[i];
            if l <= z {
                return Err("gas column shorter than the displacement".into());
            }
            let model = self.rep.charge_pressure * (l / (l - z)).powf(n);
            r[i] = (model - self.rep.static_pressures[i]) / self.rep.static_pressures[i];
        }
        Ok(())
    }
}

/// Ratio A_hr / A_hc of the front-axle strut (Table 6.3), used for the laboratory strut.
pub const AREA_RATIO: f64 = 0.0254 / 0.038;

/// Gas-column length L of the laboratory strut (m): step 1's fit with n = 1.4 to the reported
/// static pressures ([`LabReported::paper`]). A constant, so that building the nominal lab
/// strut fits nothing; `tests/lab.rs` checks that [`identify_lab`] still gives it.
pub const LAB_GAS_LENGTH_M: f64 = 0.182_667_631_447_125_97;

/// Identify the laboratory strut from the reported numbers (steps in the module docs).
pub fn identify_lab(rep: &LabReported, config: LabConfig) -> LabIdentification {
    let zmax = rep.static_displacements[2];
    let opts = FitOptions {
        lower: Some(vec![zmax * 1.01, 1.0]),
        upper: Some(vec![1.0, 1.7]),
        ..FitOptions::default()
    };
    let free = fit(&StaticFit { rep, fixed_n: None }, &[0.2, 1.3], &opts)
        .map(|f| (f.params[0], f.params[1]))
        .unwrap_or((f64::NAN, f64::NAN));
    let opts1 = FitOptions {
        lower: Some(vec![zmax * 1.01]),
        upper: Some(vec![1.0]),
        ..FitOptions::default()
    };
    let gas_length = fit(
        &StaticFit {
            rep,
            fixed_n: Some(rep.n),
        },
        &[0.2],
        &opts1,
    )
    .map(|f| f.params[0])
    .unwrap_or(f64::NAN);

    let params = lab_params(rep, config, gas_length);
    let mid = rep.static_displacements[0];
    let (oil_c, oil_r) = params.oil_volumes();
    // Fresh strut (no emulsion yet, charged at the bottom): reproduce the static pressures.
    let mut fresh = params;
    fresh.gamma0 = 0.0;
    fresh.v_c0 = oil_c;
    fresh.v_r0 = oil_r;
    fresh.p_h0 = rep.charge_pressure * (gas_length / (gas_length - mid)).powf(rep.n);
    let mut static_pressures = [f64::NAN; 3];
    if let Ok(s) = HpsStrut::new(&fresh, &HpsExtensions::none()) {
        for i in 0..3 {
            static_pressures[i] = s
                .static_pressure(rep.static_displacements[i] - mid)
                .unwrap_or(f64::NAN);
        }
    }
    LabIdentification {
        params,
        gas_length,
        free_fit: free,
        fresh,
        static_pressures,
        mid_stroke: mid,
    }
}

/// The laboratory strut from the reported numbers and the gas-column length `gas_length`
/// (m, step 1): steps 2-4 of the module docs, no fitting. [`StrutParams::lab`] calls it with
/// [`LAB_GAS_LENGTH_M`].
pub fn lab_params(rep: &LabReported, config: LabConfig, gas_length: f64) -> StrutParams {
    // Step 2: annulus from the lowest rod pressure in compression (one-orifice strut).
    let a_b = 11e-6;
    let a_v = 8e-6;
    let n_v = 2u32;
    let ca_comp = rep.c_b_one * a_b + rep.c_v * n_v as f64 * a_v;
    let dp = rep.saturation_pressure_one - rep.p_rod_min_compression;
    let rho_h = 850.0;
    let a_ann = ca_comp * (2.0 * dp / rho_h).sqrt() / rep.peak_velocity;
    // Step 3.
    let a_hc = a_ann / (1.0 - AREA_RATIO);
    let a_hr = a_hc * AREA_RATIO;
    // Step 4.
    let mid = rep.static_displacements[0];
    let (n_b, c_b, p_h0, gamma0) = match config {
        LabConfig::OneOrifice => (1, rep.c_b_one, rep.saturation_pressure_one, 0.04),
        LabConfig::TwoOrifices => (2, rep.c_b_two, rep.saturation_pressure_two, 0.02),
    };
    let oil_r = a_ann * (mid + ROD_DEAD_LENGTH);
    let oil_c = rep.oil_volume - oil_r;
    StrutParams {
        a_hc,
        a_hr,
        n_b,
        a_b,
        c_b,
        n_v,
        a_v,
        c_v: rep.c_v,
        k_l: rep.k_l,
        beta_h: 1700e6,
        rho_h,
        p_h0,
        v_g0: a_hr * (gas_length - mid),
        v_c0: oil_c * (1.0 + gamma0),
        v_r0: oil_r * (1.0 + gamma0),
        gamma0,
        n: rep.n,
        friction: FrictionParams {
            mu_v: rep.mu_v,
            f_c: 150.0,
            f_s: 100.0,
            k_s: rep.k_s,
            vh_ratio: 0.1,
            vh_min: 1e-3,
        },
        travel: mid,
        p_amb: P_ATM,
        p_vap: P_VAPOUR,
        p_reg: P_REG,
    }
}

/// Check that reported numbers are usable (positive, ordered); used before [`identify_lab`]
/// on user-supplied values.
pub fn validate_reported(rep: &LabReported) -> Result<(), HpsError> {
    use crate::error::positive;
    positive("oil_volume", rep.oil_volume)?;
    positive("charge_pressure", rep.charge_pressure)?;
    for i in 0..3 {
        positive("static_displacements", rep.static_displacements[i])?;
        positive("static_pressures", rep.static_pressures[i])?;
    }
    positive("saturation_pressure_one", rep.saturation_pressure_one)?;
    positive("saturation_pressure_two", rep.saturation_pressure_two)?;
    positive("peak_velocity", rep.peak_velocity)?;
    if rep.p_rod_min_compression >= rep.saturation_pressure_one {
        return Err(HpsError::InvalidParameter {
            field: "p_rod_min_compression",
            value: rep.p_rod_min_compression,
            reason: "must be below the one-orifice saturation pressure",
        });
    }
    Ok(())
}
