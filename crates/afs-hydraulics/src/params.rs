//! Parameters of the articulated frame steering (AFS) system, Tables 3.1 and 4.1.
//!
//! All fields are SI. The paper's table units (deg, cm², L, mL/deg, MPa, bar, L/min) are
//! converted once, in [`AfsParams::nominal`]; the constants below document the conversions.
//! See `docs/afs-hydraulics.md` for the reasoning behind every unit that the tables leave
//! unstated (mu_v, k_l0, k_l, k_theta, the valve opening X and a_0, a_m, a_v).

use crate::error::{check, AfsError};
use serde::{Deserialize, Serialize};

/// One bar in pascal.
pub const BAR: f64 = 1.0e5;
/// One litre per minute in m³/s.
pub const L_PER_MIN: f64 = 1.0e-3 / 60.0;
/// Unit of the table value of the seal viscous coefficient mu_v (Table 3.1 lists 0.06 with
/// no unit): we read it as kN·s/mm (= MN·s/m), i.e. 0.06 -> 6.0e4 N·s/m. N·s/m or kN·s/m
/// give a friction force of a few newtons, which has no effect on a 100 kN strut, contrary
/// to the paper's sensitivity results (section 3.4.3).
pub const MU_V_TABLE_UNIT: f64 = 1.0e6;
/// Paper's valve coefficient a_0 is per bar (Eq 3.11 with ΔP in bar): SI factor 1/bar.
pub const VALVE_A0_TABLE_UNIT: f64 = 1.0 / BAR;
/// Paper's a_m is in (L/min)/sqrt(bar) per unit normalised opening.
pub const VALVE_AM_TABLE_UNIT: f64 = L_PER_MIN / 316.227_766_016_837_94; // sqrt(1e5)
/// Paper's a_v is in (L/min)/bar per unit normalised opening.
pub const VALVE_AV_TABLE_UNIT: f64 = L_PER_MIN / BAR;

/// Largest accepted dead volume V_0 (m³) of Eq 3.7. A steering circuit holds litres; a
/// volume near `f64::MAX` makes the stored hydraulic energy overflow to infinity.
pub const MAX_DEAD_VOLUME_M3: f64 = 1.0;

/// Parameters of the hydraulic AFS component (SI units throughout).
///
/// Sources: Table 3.1 (steering model parameters), Table 4.1 (valve coefficients a_0, a_m,
/// a_v), section 3.2.1 (spool limit 8.1 deg, k_v < 1). Fields without a table value are our
/// documented assumptions (standby and cavitation pressures, regularisation widths).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AfsParams {
    /// l_1, distance from the articulation joint to the front strut mounts L_1/R_1 (m). Table 3.1: 1.96.
    pub l1_m: f64,
    /// l_2, distance from the articulation joint to the rear strut mounts L_2/R_2 (m). Table 3.1: 0.64.
    pub l2_m: f64,
    /// A_0, angle L_1-O-L_2 at zero articulation (rad). Table 3.1: 76.5 deg.
    pub a0_rad: f64,
    /// A_c, effective piston area (m²). Table 3.1: 95 cm².
    pub piston_area_m2: f64,
    /// A_r, effective annulus (rod-side) area (m²). Table 3.1: 57 cm².
    pub annulus_area_m2: f64,
    /// V_0, fluid volume of each chamber group (two chambers + pipes) at zero articulation (m³). Table 3.1: 7.6 L.
    pub dead_volume_m3: f64,
    /// B_eff, effective bulk modulus of the fluid (Pa). Table 3.1: 1.6 GPa.
    pub bulk_modulus_pa: f64,
    /// mu_v, viscous seal friction coefficient per strut (N·s/m). Table 3.1: 0.06, read as kN·s/mm -> 6.0e4.
    pub seal_viscous_n_s_m: f64,
    /// k_l0, constant piston-seal leakage coefficient per strut (m³/(s·Pa)), Eq 3.6. Table 3.1: 1.3e-13.
    pub leak_const: f64,
    /// k_l, velocity-dependent leakage coefficient per strut (m³/(Pa·m)): k_lL = k_l0 + k_l·|strut speed|, Eq 3.6. Table 3.1: 1.8e-10.
    pub leak_velocity: f64,
    /// k_theta, gerotor displacement per housing angle (m³/rad), Eq 3.10. Table 3.1: 8.34 mL/deg.
    pub gerotor_displacement: f64,
    /// eta_g, gerotor efficiency (-), Eq 3.10. Table 3.1 ("n"): 0.9.
    pub gerotor_efficiency: f64,
    /// a_0, laminar-turbulent transition coefficient (1/Pa), Eqs 3.11/4.6. Table 4.1: -0.0074 per bar.
    pub valve_a0_per_pa: f64,
    /// a_m, turbulent (square-root) flow coefficient per unit normalised opening (m³/(s·Pa^0.5)).
    /// Table 4.1: 0.94 (L/min)/sqrt(bar).
    pub valve_am: f64,
    /// a_v, laminar flow coefficient per unit normalised opening (m³/(s·Pa)). Table 4.1: 4.8 (L/min)/bar.
    pub valve_av: f64,
    /// X_0, valve dead band of the relative spool angle X (rad), Eq 3.11. Table 3.1: 2.1 deg.
    pub dead_band_rad: f64,
    /// Limit of the relative spool angle |X| set by the pin (rad), section 3.2.1: 8.1 deg.
    /// The valve is fully open at |X| >= this limit.
    pub spool_limit_rad: f64,
    /// k_v, return-path flow area factor (-), Eq 3.12. Table 3.1: 0.7.
    pub return_factor: f64,
    /// P_s, supply (accumulator) pressure, absolute (Pa). Table 3.1: 13.5 MPa (section 4.2.1 says "near 100 bars").
    pub supply_pressure_pa: f64,
    /// P_0, reservoir pressure, absolute (Pa). Table 3.1: 0.1 MPa.
    pub reservoir_pressure_pa: f64,
    /// Cavitation (vapour/air-release) pressure, absolute (Pa): chamber pressures cannot fall below it.
    /// Not in the paper; default 10 kPa.
    pub cavitation_pressure_pa: f64,
    /// Width of the smooth cavitation floor above `cavitation_pressure_pa` (Pa), in which the
    /// fluid's stiffness against further expansion fades to zero. Default 40 kPa.
    pub cavitation_band_pa: f64,
    /// Pressure of both chamber groups at rest (Pa, absolute), used by `initial_state`.
    /// Not in the paper; default 1 MPa.
    pub standby_pressure_pa: f64,
    /// Width of the square-root regularisation of the turbulent valve term (Pa):
    /// sqrt(Δ) is replaced by Δ/(Δ²+δ²)^{1/4}. Default 10 kPa (0.1 bar).
    pub sqrt_regularisation_pa: f64,
    /// Inlet check valve of the steering unit: no back-flow from the struts into the supply
    /// line when the fed chamber pressure exceeds P_s (the printed Eq 3.11 is undefined there).
    pub inlet_check_valve: bool,
    /// Smallest chamber-group volume, as a fraction of V_0: the volumes of Eq 3.7 are clamped
    /// at this value at extreme articulation (fittings and pipes cannot be emptied). Default 0.02.
    pub min_volume_fraction: f64,
}

impl Default for AfsParams {
    fn default() -> Self {
        Self::nominal()
    }
}

impl AfsParams {
    /// Nominal parameters of the 35 t mining truck's AFS: Table 3.1, valve coefficients of
    /// Table 4.1, spool limit of section 3.2.1, converted to SI.
    pub fn nominal() -> Self {
        let deg = std::f64::consts::PI / 180.0;
        Self {
            l1_m: 1.96,
            l2_m: 0.64,
            a0_rad: 76.5 * deg,
            piston_area_m2: 95.0e-4,
            annulus_area_m2: 57.0e-4,
            dead_volume_m3: 7.6e-3,
            bulk_modulus_pa: 1.6e9,
            seal_viscous_n_s_m: 0.06 * MU_V_TABLE_UNIT,
            leak_const: 1.3e-13,
            leak_velocity: 1.8e-10,
            gerotor_displacement: 8.34e-6 / deg,
            gerotor_efficiency: 0.9,
            valve_a0_per_pa: -0.0074 * VALVE_A0_TABLE_UNIT,
            valve_am: 0.94 * VALVE_AM_TABLE_UNIT,
            valve_av: 4.8 * VALVE_AV_TABLE_UNIT,
            dead_band_rad: 2.1 * deg,
            spool_limit_rad: 8.1 * deg,
            return_factor: 0.7,
            supply_pressure_pa: 13.5e6,
            reservoir_pressure_pa: 0.1e6,
            cavitation_pressure_pa: 1.0e4,
            cavitation_band_pa: 4.0e4,
            standby_pressure_pa: 1.0e6,
            sqrt_regularisation_pa: 1.0e4,
            inlet_check_valve: true,
            min_volume_fraction: 0.02,
        }
    }

    /// Initial strut length l_0 = sqrt(l_1² + l_2² - 2 l_1 l_2 cos A_0) (m), Eq 3.7.
    pub fn initial_strut_length(&self) -> f64 {
        (self.l1_m * self.l1_m + self.l2_m * self.l2_m
            - 2.0 * self.l1_m * self.l2_m * self.a0_rad.cos())
        .sqrt()
    }

    /// Check every field (finite, physical range) and the cross-field rules
    /// (A_c > A_r, X_0 < spool limit, P_s > P_0 > cavitation pressure, ...).
    pub fn validate(&self) -> Result<(), AfsError> {
        use std::f64::consts::PI;
        check("l1_m", self.l1_m, self.l1_m > 0.0, "must be > 0")?;
        check("l2_m", self.l2_m, self.l2_m > 0.0, "must be > 0")?;
        check(
            "a0_rad",
            self.a0_rad,
            self.a0_rad > 0.0 && self.a0_rad < PI,
            "must lie in (0, pi)",
        )?;
        check(
            "piston_area_m2",
            self.piston_area_m2,
            self.piston_area_m2 > 0.0,
            "must be > 0",
        )?;
        check(
            "annulus_area_m2",
            self.annulus_area_m2,
            self.annulus_area_m2 > 0.0,
            "must be > 0",
        )?;
        if self.piston_area_m2 <= self.annulus_area_m2 {
            return Err(AfsError::Inconsistent {
                field: "annulus_area_m2",
                value: self.annulus_area_m2,
                other: "piston_area_m2",
                other_value: self.piston_area_m2,
                reason: "the annulus area A_r must be smaller than the piston area A_c",
            });
        }
        check(
            "dead_volume_m3",
            self.dead_volume_m3,
            self.dead_volume_m3 > 0.0 && self.dead_volume_m3 <= MAX_DEAD_VOLUME_M3,
            "must be > 0 and at most 1 m³ (a steering circuit holds litres; larger volumes overflow the stored hydraulic energy)",
        )?;
        check(
            "bulk_modulus_pa",
            self.bulk_modulus_pa,
            self.bulk_modulus_pa > 0.0,
            "must be > 0",
        )?;
        check(
            "seal_viscous_n_s_m",
            self.seal_viscous_n_s_m,
            self.seal_viscous_n_s_m >= 0.0,
            "must be >= 0",
        )?;
        check(
            "leak_const",
            self.leak_const,
            self.leak_const >= 0.0,
            "must be >= 0",
        )?;
        check(
            "leak_velocity",
            self.leak_velocity,
            self.leak_velocity >= 0.0,
            "must be >= 0",
        )?;
        self.validate_valve_and_pressures()
    }

    /// The gerotor, valve (Eqs 3.9-3.12) and circuit-pressure part of [`Self::validate`].
    fn validate_valve_and_pressures(&self) -> Result<(), AfsError> {
        check(
            "gerotor_displacement",
            self.gerotor_displacement,
            self.gerotor_displacement > 0.0,
            "must be > 0",
        )?;
        check(
            "gerotor_efficiency",
            self.gerotor_efficiency,
            self.gerotor_efficiency > 0.0 && self.gerotor_efficiency <= 1.0,
            "must lie in (0, 1]",
        )?;
        check(
            "valve_a0_per_pa",
            self.valve_a0_per_pa,
            self.valve_a0_per_pa <= 0.0,
            "must be <= 0 (a positive value makes the valve flow grow exponentially)",
        )?;
        check(
            "valve_am",
            self.valve_am,
            self.valve_am >= 0.0,
            "must be >= 0",
        )?;
        check(
            "valve_av",
            self.valve_av,
            self.valve_av >= 0.0,
            "must be >= 0",
        )?;
        if self.valve_am == 0.0 && self.valve_av == 0.0 {
            return Err(AfsError::Inconsistent {
                field: "valve_am",
                value: self.valve_am,
                other: "valve_av",
                other_value: self.valve_av,
                reason: "at least one valve flow coefficient must be positive",
            });
        }
        check(
            "dead_band_rad",
            self.dead_band_rad,
            self.dead_band_rad >= 0.0,
            "must be >= 0",
        )?;
        check(
            "spool_limit_rad",
            self.spool_limit_rad,
            self.spool_limit_rad > 0.0,
            "must be > 0",
        )?;
        if self.dead_band_rad >= self.spool_limit_rad {
            return Err(AfsError::Inconsistent {
                field: "dead_band_rad",
                value: self.dead_band_rad,
                other: "spool_limit_rad",
                other_value: self.spool_limit_rad,
                reason: "the valve dead band X_0 must be smaller than the spool travel limit",
            });
        }
        check(
            "return_factor",
            self.return_factor,
            self.return_factor > 0.0,
            "must be > 0",
        )?;
        check(
            "cavitation_pressure_pa",
            self.cavitation_pressure_pa,
            self.cavitation_pressure_pa >= 0.0,
            "must be >= 0 (absolute pressure)",
        )?;
        check(
            "cavitation_band_pa",
            self.cavitation_band_pa,
            self.cavitation_band_pa > 0.0,
            "must be > 0",
        )?;
        check(
            "reservoir_pressure_pa",
            self.reservoir_pressure_pa,
            self.reservoir_pressure_pa > 0.0,
            "must be > 0 (absolute pressure)",
        )?;
        check(
            "supply_pressure_pa",
            self.supply_pressure_pa,
            self.supply_pressure_pa > 0.0,
            "must be > 0 (absolute pressure)",
        )?;
        if self.reservoir_pressure_pa <= self.cavitation_pressure_pa {
            return Err(AfsError::Inconsistent {
                field: "reservoir_pressure_pa",
                value: self.reservoir_pressure_pa,
                other: "cavitation_pressure_pa",
                other_value: self.cavitation_pressure_pa,
                reason: "the reservoir pressure must exceed the cavitation pressure",
            });
        }
        if self.supply_pressure_pa <= self.reservoir_pressure_pa {
            return Err(AfsError::Inconsistent {
                field: "supply_pressure_pa",
                value: self.supply_pressure_pa,
                other: "reservoir_pressure_pa",
                other_value: self.reservoir_pressure_pa,
                reason: "the supply pressure must exceed the reservoir pressure",
            });
        }
        check(
            "standby_pressure_pa",
            self.standby_pressure_pa,
            self.standby_pressure_pa > self.cavitation_pressure_pa + self.cavitation_band_pa,
            "must exceed cavitation_pressure_pa + cavitation_band_pa",
        )?;
        check(
            "sqrt_regularisation_pa",
            self.sqrt_regularisation_pa,
            self.sqrt_regularisation_pa > 0.0,
            "must be > 0",
        )?;
        check(
            "min_volume_fraction",
            self.min_volume_fraction,
            self.min_volume_fraction > 0.0 && self.min_volume_fraction < 1.0,
            "must lie in (0, 1)",
        )?;
        Ok(())
    }
}
