//! Named parameters of the AFS set ([`ParamSet`] for [`AfsParams`]): every scalar field by
//! its serde name with SI unit, the range a fit, a sensitivity study or a design may explore,
//! and a typical magnitude. The boolean `inlet_check_valve` is a model switch, not a
//! parameter, and is not listed.

use crate::params::AfsParams;
use vehicle_components::{ParamSet, ParamSpec};

/// The scalar parameters of [`AfsParams`], in field order. Bounds are physical ranges, wider
/// than any design or fit of the dissertation (Tables 3.1, 4.1-4.4); [`AfsParams::validate`]
/// still applies on every set (e.g. A_r < A_c).
pub const AFS_PARAMS: [ParamSpec; 25] = [
    // front strut mount distance l_1 (Table 3.1)
    ParamSpec::new("l1_m", "m", 0.3, 4.0, 1.96),
    // rear strut mount distance l_2
    ParamSpec::new("l2_m", "m", 0.2, 3.0, 0.64),
    // kinematic angle A_0 (10-170 deg)
    ParamSpec::new("a0_rad", "rad", 0.17, 2.97, 1.335),
    // piston area A_c
    ParamSpec::new("piston_area_m2", "m²", 0.0001, 0.1, 9.5e-3),
    // annulus area A_r (< A_c)
    ParamSpec::new("annulus_area_m2", "m²", 0.0001, 0.1, 5.7e-3),
    // chamber-group volume V_0
    ParamSpec::new("dead_volume_m3", "m³", 0.0001, 0.1, 7.6e-3),
    // effective bulk modulus B_eff
    ParamSpec::new("bulk_modulus_pa", "Pa", 100000000.0, 3000000000.0, 1.6e9),
    // seal viscous coefficient mu_v
    ParamSpec::new("seal_viscous_n_s_m", "N·s/m", 0.0, 1000000.0, 6.0e4),
    // constant leakage k_l0 (Eq 3.6)
    ParamSpec::new("leak_const", "m³/(s·Pa)", 0.0, 1.0e-10, 1.3e-13),
    // velocity leakage k_l (Eq 3.6)
    ParamSpec::new("leak_velocity", "m³/(Pa·m)", 0.0, 1.0e-8, 1.8e-10),
    // gerotor displacement k_theta
    ParamSpec::new("gerotor_displacement", "m³/rad", 1.0e-5, 0.01, 4.78e-4),
    // gerotor efficiency eta_g
    ParamSpec::new("gerotor_efficiency", "-", 0.1, 1.0, 0.9),
    // laminar-turbulent coefficient a_0 (<= 0)
    ParamSpec::new("valve_a0_per_pa", "1/Pa", -1.0e-6, 0.0, 7.4e-8),
    // turbulent valve coefficient a_m
    ParamSpec::new("valve_am", "m³/(s·Pa^0.5)", 1.0e-10, 1.0e-5, 4.95e-8),
    // laminar valve coefficient a_v
    ParamSpec::new("valve_av", "m³/(s·Pa)", 0.0, 1.0e-7, 8.0e-10),
    // valve dead band X_0
    ParamSpec::new("dead_band_rad", "rad", 0.0, 0.2, 0.0367),
    // spool pin limit
    ParamSpec::new("spool_limit_rad", "rad", 0.01, 0.5, 0.141),
    // return-path factor k_v
    ParamSpec::new("return_factor", "-", 0.05, 2.0, 0.7),
    // supply pressure P_s
    ParamSpec::new("supply_pressure_pa", "Pa", 1000000.0, 50000000.0, 1.35e7),
    // reservoir pressure P_0
    ParamSpec::new("reservoir_pressure_pa", "Pa", 0.0, 1000000.0, 1.0e5),
    // cavitation pressure
    ParamSpec::new("cavitation_pressure_pa", "Pa", 0.0, 100000.0, 1.0e4),
    // cavitation floor width
    ParamSpec::new("cavitation_band_pa", "Pa", 1.0, 1000000.0, 4.0e4),
    // standby pressure
    ParamSpec::new("standby_pressure_pa", "Pa", 10000.0, 30000000.0, 1.0e6),
    // square-root regularisation width
    ParamSpec::new("sqrt_regularisation_pa", "Pa", 1.0, 1000000.0, 1.0e4),
    // smallest chamber volume / V_0
    ParamSpec::new("min_volume_fraction", "-", 0.0001, 0.5, 0.02),
];

impl ParamSet for AfsParams {
    fn set_name(&self) -> &'static str {
        "steering (AFS)"
    }

    fn specs(&self) -> &'static [ParamSpec] {
        &AFS_PARAMS
    }

    fn value(&self, index: usize) -> f64 {
        match index {
            0 => self.l1_m,
            1 => self.l2_m,
            2 => self.a0_rad,
            3 => self.piston_area_m2,
            4 => self.annulus_area_m2,
            5 => self.dead_volume_m3,
            6 => self.bulk_modulus_pa,
            7 => self.seal_viscous_n_s_m,
            8 => self.leak_const,
            9 => self.leak_velocity,
            10 => self.gerotor_displacement,
            11 => self.gerotor_efficiency,
            12 => self.valve_a0_per_pa,
            13 => self.valve_am,
            14 => self.valve_av,
            15 => self.dead_band_rad,
            16 => self.spool_limit_rad,
            17 => self.return_factor,
            18 => self.supply_pressure_pa,
            19 => self.reservoir_pressure_pa,
            20 => self.cavitation_pressure_pa,
            21 => self.cavitation_band_pa,
            22 => self.standby_pressure_pa,
            23 => self.sqrt_regularisation_pa,
            24 => self.min_volume_fraction,
            _ => panic!("AFS parameter index {index} out of range"),
        }
    }

    fn assign(&mut self, index: usize, value: f64) {
        let slot = match index {
            0 => &mut self.l1_m,
            1 => &mut self.l2_m,
            2 => &mut self.a0_rad,
            3 => &mut self.piston_area_m2,
            4 => &mut self.annulus_area_m2,
            5 => &mut self.dead_volume_m3,
            6 => &mut self.bulk_modulus_pa,
            7 => &mut self.seal_viscous_n_s_m,
            8 => &mut self.leak_const,
            9 => &mut self.leak_velocity,
            10 => &mut self.gerotor_displacement,
            11 => &mut self.gerotor_efficiency,
            12 => &mut self.valve_a0_per_pa,
            13 => &mut self.valve_am,
            14 => &mut self.valve_av,
            15 => &mut self.dead_band_rad,
            16 => &mut self.spool_limit_rad,
            17 => &mut self.return_factor,
            18 => &mut self.supply_pressure_pa,
            19 => &mut self.reservoir_pressure_pa,
            20 => &mut self.cavitation_pressure_pa,
            21 => &mut self.cavitation_band_pa,
            22 => &mut self.standby_pressure_pa,
            23 => &mut self.sqrt_regularisation_pa,
            24 => &mut self.min_volume_fraction,
            _ => panic!("AFS parameter index {index} out of range"),
        };
        *slot = value;
    }

    fn check(&self) -> Result<(), String> {
        self.validate().map_err(|e| e.to_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use vehicle_components::{check_specs, ParamError};

    #[test]
    fn specs_are_well_formed_and_hold_the_nominal_set() {
        check_specs(&AFS_PARAMS).unwrap();
        let p = AfsParams::nominal();
        for (i, s) in AFS_PARAMS.iter().enumerate() {
            s.admit(p.value(i)).unwrap();
            // the typical magnitude is the nominal size, within a factor of 2
            let v = p.value(i).abs();
            assert!(
                v == 0.0 || (v / s.typical > 0.5 && v / s.typical < 2.0),
                "{}",
                s.name
            );
        }
    }

    #[test]
    fn names_are_the_serde_fields_and_values_match() {
        let p = AfsParams::nominal();
        let json = serde_json::to_value(&p).unwrap();
        let obj = json.as_object().unwrap();
        for (i, s) in AFS_PARAMS.iter().enumerate() {
            assert_eq!(obj[s.name].as_f64(), Some(p.value(i)), "{}", s.name);
        }
        // every numeric field is listed
        let numeric = obj.values().filter(|v| v.is_number()).count();
        assert_eq!(numeric, AFS_PARAMS.len());
    }

    #[test]
    fn set_by_name_round_trips_and_refuses_what_validate_refuses() {
        let mut p = AfsParams::nominal();
        p.set("bulk_modulus_pa", 1.2e9).unwrap();
        assert_eq!(p.get("bulk_modulus_pa").unwrap(), 1.2e9);
        assert_eq!(p.bulk_modulus_pa, 1.2e9);
        // within bounds, but A_r >= A_c is inconsistent: refused, set unchanged
        let before = p.clone();
        let err = p.set("annulus_area_m2", 0.02).unwrap_err();
        assert!(matches!(err, ParamError::Rejected { .. }), "{err}");
        assert_eq!(p, before);
        assert!(matches!(
            p.set("leak_const", f64::NAN),
            Err(ParamError::OutOfBounds { .. })
        ));
        let unknown = p.get("bulk_modulus").unwrap_err().to_string();
        assert!(unknown.contains("bulk_modulus_pa"), "{unknown}");
    }
}
