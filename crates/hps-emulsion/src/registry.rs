//! Named parameters of the strut ([`ParamSet`] for [`StrutParams`]): every scalar of
//! Eqs 5.1-5.12 by its serde name (nested friction fields as `friction.mu_v`), with SI unit,
//! the range a fit or a design may explore, and a typical magnitude (the front-axle strut's,
//! Table 6.3). The counts `n_b` and `n_v` are integers, not continuous parameters, and are not
//! listed.

use crate::params::StrutParams;
use vehicle_components::{ParamSet, ParamSpec};

/// The scalar parameters of [`StrutParams`], in field order. [`StrutParams::validate`] still
/// applies on every set (e.g. A_hr < A_hc, a rod chamber that never empties).
pub const STRUT_PARAMS: [ParamSpec; 25] = [
    // piston area A_hc (Eq 5.1)
    ParamSpec::new("a_hc", "m²", 0.0001, 0.2, 0.038),
    // rod area A_hr (< A_hc)
    ParamSpec::new("a_hr", "m²", 1.0e-5, 0.2, 0.0254),
    // one bleed orifice's area A_b (Eq 5.12); the lower bound is a 0.36 mm bore, below
    // which the strut is locked (leakage alone carries the flow) and its runs turn stiff
    ParamSpec::new("a_b", "m²", 1.0e-7, 0.001, 1.1e-5),
    // bleed discharge coefficient C_b (sharp-edged orifices 0.6-0.8; 0 is no orifice)
    ParamSpec::new("c_b", "-", 0.05, 1.0, 0.7),
    // one check valve's area A_v
    ParamSpec::new("a_v", "m²", 0.0, 0.001, 8.0e-6),
    // check-valve discharge coefficient C_v (0 is no valve: use a_v = 0 or n_v = 0)
    ParamSpec::new("c_v", "-", 0.05, 1.0, 0.6),
    // piston leakage k_l
    ParamSpec::new("k_l", "m³/(Pa·s)", 0.0, 1.0e-9, 5.0e-12),
    // oil bulk modulus beta_h (Eqs 5.8, 5.11)
    ParamSpec::new("beta_h", "Pa", 100000000.0, 3000000000.0, 1.7e9),
    // oil density rho_h (Eq 5.10)
    ParamSpec::new("rho_h", "kg/m³", 600.0, 1100.0, 850.0),
    // static gas pressure P_h0 (Eq 5.4)
    ParamSpec::new("p_h0", "Pa", 100000.0, 50000000.0, 5.8e6),
    // static free gas volume V_g0
    ParamSpec::new("v_g0", "m³", 1.0e-6, 0.1, 4.5e-3),
    // static piston-side emulsion volume V_c0 (Eq 5.7)
    ParamSpec::new("v_c0", "m³", 1.0e-6, 0.1, 1.0e-2),
    // static rod-side emulsion volume V_r0
    ParamSpec::new("v_r0", "m³", 1.0e-7, 0.1, 1.7e-3),
    // gas volume fraction gamma_0 (Eq 5.9)
    ParamSpec::new("gamma0", "-", 0.0, 0.49, 0.02),
    // polytropic exponent n
    ParamSpec::new("n", "-", 1.0, 1.7, 1.4),
    // seal viscous coefficient (Eq 5.2)
    ParamSpec::new("friction.mu_v", "N·s/m", 0.0, 1000000.0, 120.0),
    // Coulomb friction F_c
    ParamSpec::new("friction.f_c", "N", 0.0, 100000.0, 360.0),
    // stiction F_s
    ParamSpec::new("friction.f_s", "N", 0.0, 100000.0, 240.0),
    // Stribeck coefficient k_s
    ParamSpec::new("friction.k_s", "s/m", 0.0, 1000.0, 50.0),
    // hysteresis band / peak velocity (Eq 5.3)
    ParamSpec::new("friction.vh_ratio", "-", 0.0, 1.0, 0.1),
    // smallest hysteresis band
    ParamSpec::new("friction.vh_min", "m/s", 1.0e-6, 1.0, 1.0e-3),
    // travel each side of the static position
    ParamSpec::new("travel", "m", 0.001, 1.0, 0.12),
    // ambient pressure on the rod end (50 kPa: about 5 500 m above sea level)
    ParamSpec::new("p_amb", "Pa", 50000.0, 200000.0, 101325.0),
    // vapour / gas-release pressure
    ParamSpec::new("p_vap", "Pa", 0.0, 100000.0, 2000.0),
    // orifice square-root regularisation
    ParamSpec::new("p_reg", "Pa", 0.001, 100000.0, 100.0),
];

impl ParamSet for StrutParams {
    fn set_name(&self) -> &'static str {
        "strut (HPS)"
    }

    fn specs(&self) -> &'static [ParamSpec] {
        &STRUT_PARAMS
    }

    fn value(&self, index: usize) -> f64 {
        match index {
            0 => self.a_hc,
            1 => self.a_hr,
            2 => self.a_b,
            3 => self.c_b,
            4 => self.a_v,
            5 => self.c_v,
            6 => self.k_l,
            7 => self.beta_h,
            8 => self.rho_h,
            9 => self.p_h0,
            10 => self.v_g0,
            11 => self.v_c0,
            12 => self.v_r0,
            13 => self.gamma0,
            14 => self.n,
            15 => self.friction.mu_v,
            16 => self.friction.f_c,
            17 => self.friction.f_s,
            18 => self.friction.k_s,
            19 => self.friction.vh_ratio,
            20 => self.friction.vh_min,
            21 => self.travel,
            22 => self.p_amb,
            23 => self.p_vap,
            24 => self.p_reg,
            _ => panic!("strut parameter index {index} out of range"),
        }
    }

    fn assign(&mut self, index: usize, value: f64) {
        let slot = match index {
            0 => &mut self.a_hc,
            1 => &mut self.a_hr,
            2 => &mut self.a_b,
            3 => &mut self.c_b,
            4 => &mut self.a_v,
            5 => &mut self.c_v,
            6 => &mut self.k_l,
            7 => &mut self.beta_h,
            8 => &mut self.rho_h,
            9 => &mut self.p_h0,
            10 => &mut self.v_g0,
            11 => &mut self.v_c0,
            12 => &mut self.v_r0,
            13 => &mut self.gamma0,
            14 => &mut self.n,
            15 => &mut self.friction.mu_v,
            16 => &mut self.friction.f_c,
            17 => &mut self.friction.f_s,
            18 => &mut self.friction.k_s,
            19 => &mut self.friction.vh_ratio,
            20 => &mut self.friction.vh_min,
            21 => &mut self.travel,
            22 => &mut self.p_amb,
            23 => &mut self.p_vap,
            24 => &mut self.p_reg,
            _ => panic!("strut parameter index {index} out of range"),
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
    use crate::lab::LabConfig;
    use vehicle_components::{check_specs, ParamError};

    #[test]
    fn specs_are_well_formed_and_hold_the_built_in_struts() {
        check_specs(&STRUT_PARAMS).unwrap();
        for p in [
            StrutParams::front_axle(),
            StrutParams::lab(LabConfig::OneOrifice),
            StrutParams::lab(LabConfig::TwoOrifices),
        ] {
            for (i, s) in STRUT_PARAMS.iter().enumerate() {
                s.admit(p.value(i)).unwrap();
            }
        }
        let p = StrutParams::front_axle();
        for (i, s) in STRUT_PARAMS.iter().enumerate() {
            let ratio = p.value(i).abs() / s.typical;
            assert!(ratio > 0.5 && ratio < 2.0, "{}: {ratio}", s.name);
        }
    }

    #[test]
    fn names_are_the_serde_fields_and_values_match() {
        let p = StrutParams::front_axle();
        let json = serde_json::to_value(p).unwrap();
        let mut numeric = 0;
        for (key, v) in json.as_object().unwrap() {
            match v {
                serde_json::Value::Object(inner) => {
                    for (k, x) in inner {
                        let name = format!("{key}.{k}");
                        assert_eq!(p.get(&name).unwrap(), x.as_f64().unwrap(), "{name}");
                        numeric += 1;
                    }
                }
                serde_json::Value::Number(x) if key != "n_b" && key != "n_v" => {
                    assert_eq!(p.get(key).unwrap(), x.as_f64().unwrap(), "{key}");
                    numeric += 1;
                }
                _ => {}
            }
        }
        assert_eq!(numeric, STRUT_PARAMS.len());
    }

    #[test]
    fn set_by_name_validates_the_whole_strut() {
        let mut p = StrutParams::front_axle();
        p.set("friction.f_c", 500.0).unwrap();
        assert_eq!(p.friction.f_c, 500.0);
        let before = p;
        let err = p.set("a_hr", 0.05).unwrap_err();
        assert!(matches!(err, ParamError::Rejected { .. }), "{err}");
        assert_eq!(p, before);
        assert!(p.set("gamma0", 0.6).is_err());
        assert!(p.get("n_b").is_err(), "counts are not parameters");
    }
}
