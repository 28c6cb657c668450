//! The tire parameter set by name ([`vehicle_components::ParamSet`]): every scalar field of
//! [`TireParams`] under its serde name, with the physical range a fit or a design may
//! explore. The two tables (`cornering_stiffness_table`, `load_deflection`) are not scalars
//! and are not in the registry; `cornering_stiffness_n_per_rad` only acts when the
//! cornering table is empty.

use vehicle_components::{ParamSet, ParamSpec};

use crate::params::TireParams;

const SPECS: [ParamSpec; 11] = [
    ParamSpec::new("unloaded_radius_m", "m", 0.2, 3.0, 1.0),
    ParamSpec::new("width_m", "m", 0.05, 2.0, 0.7),
    ParamSpec::new("charge_pressure_pa", "Pa", 5e4, 2e6, 5e5),
    ParamSpec::new("vertical_damping_n_s_per_m", "N s/m", 0.0, 5e5, 35e3),
    ParamSpec::new("lateral_relaxation_length_m", "m", 0.01, 10.0, 1.2),
    ParamSpec::new("longitudinal_relaxation_length_m", "m", 0.01, 10.0, 1.2),
    ParamSpec::new("cornering_stiffness_n_per_rad", "N/rad", 1e3, 1e7, 4e5),
    ParamSpec::new("longitudinal_stiffness_n", "N", 1e3, 1e8, 1e6),
    ParamSpec::new("u_max", "-", 0.05, 2.0, 0.8),
    ParamSpec::new("u_min", "-", 0.05, 2.0, 0.6),
    ParamSpec::new("rolling_resistance_coefficient", "-", 0.0, 0.5, 0.03),
];

impl ParamSet for TireParams {
    fn set_name(&self) -> &'static str {
        "tire"
    }

    fn specs(&self) -> &'static [ParamSpec] {
        &SPECS
    }

    fn value(&self, index: usize) -> f64 {
        match index {
            0 => self.unloaded_radius_m,
            1 => self.width_m,
            2 => self.charge_pressure_pa,
            3 => self.vertical_damping_n_s_per_m,
            4 => self.lateral_relaxation_length_m,
            5 => self.longitudinal_relaxation_length_m,
            6 => self.cornering_stiffness_n_per_rad,
            7 => self.longitudinal_stiffness_n,
            8 => self.u_max,
            9 => self.u_min,
            10 => self.rolling_resistance_coefficient,
            _ => panic!("tire parameter index {index} out of range"),
        }
    }

    fn assign(&mut self, index: usize, value: f64) {
        let field = match index {
            0 => &mut self.unloaded_radius_m,
            1 => &mut self.width_m,
            2 => &mut self.charge_pressure_pa,
            3 => &mut self.vertical_damping_n_s_per_m,
            4 => &mut self.lateral_relaxation_length_m,
            5 => &mut self.longitudinal_relaxation_length_m,
            6 => &mut self.cornering_stiffness_n_per_rad,
            7 => &mut self.longitudinal_stiffness_n,
            8 => &mut self.u_max,
            9 => &mut self.u_min,
            10 => &mut self.rolling_resistance_coefficient,
            _ => panic!("tire parameter index {index} out of range"),
        };
        *field = value;
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
    fn names_are_the_serde_fields_and_hold_the_nominal_values() {
        let p = TireParams::nominal();
        check_specs(p.specs()).unwrap();
        let json = serde_json::to_value(&p).unwrap();
        for spec in p.specs() {
            let v = p.get(spec.name).unwrap();
            assert_eq!(json[spec.name].as_f64(), Some(v), "{}", spec.name);
            spec.admit(v).unwrap();
        }
    }

    #[test]
    fn set_reaches_each_field_and_only_it() {
        for (i, spec) in SPECS.iter().enumerate() {
            let mut p = TireParams::nominal();
            // 10 % above the typical size: within bounds, different from the nominal value
            // and keeping u_min (0.66) below u_max (0.8, or 0.88 when u_max is set).
            let v = (1.1 * spec.typical).min(spec.upper);
            assert_ne!(v, p.value(i), "{}", spec.name);
            p.set(spec.name, v).unwrap();
            let q = TireParams::nominal();
            for (j, other) in SPECS.iter().enumerate() {
                let expect = if i == j { v } else { q.value(j) };
                assert_eq!(
                    p.get(other.name).unwrap(),
                    expect,
                    "{} -> {}",
                    spec.name,
                    other.name
                );
            }
        }
    }

    #[test]
    fn typed_errors_leave_the_set_unchanged() {
        let mut p = TireParams::nominal();
        assert!(matches!(
            p.get("umax"),
            Err(ParamError::Unknown { set: "tire", .. })
        ));
        assert!(matches!(
            p.set("width_m", 5.0),
            Err(ParamError::OutOfBounds {
                name: "width_m",
                ..
            })
        ));
        // Within bounds but above u_max: TireParams::validate refuses it.
        let e = p.set("u_min", 0.9).unwrap_err();
        assert!(
            matches!(e, ParamError::Rejected { name: "u_min", .. }),
            "{e}"
        );
        assert_eq!(p, TireParams::nominal());
    }
}
