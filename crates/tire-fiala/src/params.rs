//! Tire parameter set (serde), with the 29.5R29 of Table 6.2 as `nominal()`.

use serde::{Deserialize, Serialize};

use crate::cornering::CorneringStiffnessTable;
use crate::error::{non_negative, positive, TireError};
use crate::vertical::LoadDeflectionTable;

/// All parameters of one off-road tire, SI units (field names carry the unit).
///
/// `nominal()` is the radial-ply 29.5R29 of Table 6.2; values the paper does not give
/// (friction, longitudinal stiffness, rolling resistance, longitudinal relaxation length,
/// the Fig 6.4 load-deflection curve) are labelled assumptions in their field docs and in
/// `docs/tire-fiala.md`. Missing fields of a JSON file take their nominal value.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct TireParams {
    /// Free (unloaded) radius R (m). Table 6.2: 1.0.
    pub unloaded_radius_m: f64,
    /// Tire (tread) width b (m); Fiala's R2 is half of it. Table 6.2: 0.7.
    pub width_m: f64,
    /// Charge (inflation) pressure (Pa), informational. Table 6.2: 5 bar.
    pub charge_pressure_pa: f64,
    /// Vertical damping c_t (N s/m), Eq 2.1. Table 6.2: 35 kN s/m.
    pub vertical_damping_n_s_per_m: f64,
    /// Lateral relaxation length sigma_y (m), Eqs 2.7, 3.16. Table 6.2: 1.2.
    pub lateral_relaxation_length_m: f64,
    /// Longitudinal relaxation length (m). Assumption: equal to the lateral one (the paper
    /// uses both in section 6.2.2 but lists one value).
    pub longitudinal_relaxation_length_m: f64,
    /// Constant cornering stiffness C_alpha (N/rad), used when
    /// `cornering_stiffness_table` is empty. Nominal: Table 6.2 front loaded, 6.8 kN/deg.
    pub cornering_stiffness_n_per_rad: f64,
    /// Load-dependent cornering stiffness rows `[F_z (N), C_alpha (N/rad)]` (section 2.2.1);
    /// overrides the constant when non-empty. Nominal: the four Table 6.2 values at the
    /// static loads derived from Table 6.1 ([`CorneringStiffnessTable::table_6_2`]).
    pub cornering_stiffness_table: Vec<[f64; 2]>,
    /// Longitudinal slip stiffness C_slip (N per unit slip ratio). Assumption: 1.0e6 N
    /// (about 7 F_z at the 150 kN loaded front-tire load).
    pub longitudinal_stiffness_n: f64,
    /// Static (peak) friction coefficient U_max. Assumption: 0.8 (dry haul road).
    pub u_max: f64,
    /// Dynamic (sliding) friction coefficient U_min. Assumption: 0.6.
    pub u_min: f64,
    /// Rolling-resistance coefficient f_r (-): M_y = -f_r R F_z. Assumption: 0.03.
    pub rolling_resistance_coefficient: f64,
    /// Load-deflection rows `[deflection (m), load (N)]` replacing Fig 6.4 (not in the
    /// text). Nominal: [`LoadDeflectionTable::default_29_5r29`], an assumption.
    pub load_deflection: Vec<[f64; 2]>,
}

impl Default for TireParams {
    fn default() -> Self {
        Self::nominal()
    }
}

impl TireParams {
    /// The 29.5R29 of Table 6.2 completed by the documented assumptions.
    pub fn nominal() -> Self {
        let deg = std::f64::consts::PI / 180.0;
        Self {
            unloaded_radius_m: 1.0,
            width_m: 0.7,
            charge_pressure_pa: 5.0e5,
            vertical_damping_n_s_per_m: 35.0e3,
            lateral_relaxation_length_m: 1.2,
            longitudinal_relaxation_length_m: 1.2,
            cornering_stiffness_n_per_rad: crate::cornering::C_ALPHA_FRONT_LOADED_N_PER_DEG / deg,
            cornering_stiffness_table: CorneringStiffnessTable::table_6_2().rows(),
            longitudinal_stiffness_n: 1.0e6,
            u_max: 0.8,
            u_min: 0.6,
            rolling_resistance_coefficient: 0.03,
            load_deflection: LoadDeflectionTable::default_29_5r29().rows(),
        }
    }

    /// Check every field; the error names the first bad one.
    pub fn validate(&self) -> Result<(), TireError> {
        positive("unloaded_radius_m", self.unloaded_radius_m)?;
        positive("width_m", self.width_m)?;
        non_negative("charge_pressure_pa", self.charge_pressure_pa)?;
        non_negative(
            "vertical_damping_n_s_per_m",
            self.vertical_damping_n_s_per_m,
        )?;
        positive(
            "lateral_relaxation_length_m",
            self.lateral_relaxation_length_m,
        )?;
        positive(
            "longitudinal_relaxation_length_m",
            self.longitudinal_relaxation_length_m,
        )?;
        positive(
            "cornering_stiffness_n_per_rad",
            self.cornering_stiffness_n_per_rad,
        )?;
        self.cornering_table()?;
        positive("longitudinal_stiffness_n", self.longitudinal_stiffness_n)?;
        positive("u_min", self.u_min)?;
        positive("u_max", self.u_max)?;
        if self.u_max < self.u_min {
            return Err(TireError::InvalidParameter {
                field: "u_max",
                value: self.u_max,
                reason: "must be >= u_min",
            });
        }
        non_negative(
            "rolling_resistance_coefficient",
            self.rolling_resistance_coefficient,
        )?;
        LoadDeflectionTable::new(&self.load_deflection)?;
        Ok(())
    }

    /// The cornering stiffness as a table (a constant when the table field is empty).
    pub fn cornering_table(&self) -> Result<CorneringStiffnessTable, TireError> {
        if self.cornering_stiffness_table.is_empty() {
            CorneringStiffnessTable::constant(self.cornering_stiffness_n_per_rad)
        } else {
            CorneringStiffnessTable::new(&self.cornering_stiffness_table)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nominal_is_valid_and_round_trips_through_json() {
        let p = TireParams::nominal();
        p.validate().unwrap();
        let s = serde_json::to_string(&p).unwrap();
        let q: TireParams = serde_json::from_str(&s).unwrap();
        assert_eq!(p, q);
        let partial: TireParams = serde_json::from_str(r#"{"u_max": 0.9}"#).unwrap();
        assert_eq!(partial.u_max, 0.9);
        assert_eq!(partial.width_m, 0.7);
        assert!(serde_json::from_str::<TireParams>(r#"{"umax": 0.9}"#).is_err());
    }

    #[test]
    fn validation_names_the_field() {
        let mut p = TireParams::nominal();
        p.u_min = 0.9;
        let e = p.validate().unwrap_err().to_string();
        assert!(e.contains("u_max"), "{e}");
        let mut p = TireParams::nominal();
        p.width_m = f64::NAN;
        assert!(p.validate().unwrap_err().to_string().contains("width_m"));
        let mut p = TireParams::nominal();
        p.load_deflection = vec![[0.1, 1.0], [0.05, 2.0]];
        assert!(p.validate().is_err());
    }
}
