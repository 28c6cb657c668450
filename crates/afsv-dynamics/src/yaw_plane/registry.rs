//! Named parameters of the yaw-plane sets: [`ParamSet`] for [`VehicleParams`] (Table 3.1
//! vehicle columns) and for the whole [`YawPlaneParams`] (vehicle + steering). The whole
//! set lists the vehicle's parameters, then the steering system's
//! ([`afs_hydraulics::AFS_PARAMS`]), each by its field name inside `vehicle` or `afs`: the
//! two name lists are disjoint, so one name addresses one parameter.

use crate::yaw_plane::params::{VehicleParams, YawPlaneParams};
use afs_hydraulics::AFS_PARAMS;
use vehicle_components::{ParamSet, ParamSpec};

/// The scalar parameters of [`VehicleParams`], in field order, with the loaded column's
/// sizes as typical magnitudes. [`VehicleParams::validate`] still applies on every set
/// (e.g. the front axle ahead of the joint).
pub const VEHICLE_PARAMS: [ParamSpec; 14] = [
    // front-unit mass m_f
    ParamSpec::new("m_f_kg", "kg", 1000.0, 200000.0, 21_000.0),
    // rear-unit mass m_r
    ParamSpec::new("m_r_kg", "kg", 1000.0, 200000.0, 52_220.0),
    // front-unit yaw inertia I_f
    ParamSpec::new("i_f_kg_m2", "kg·m²", 1000.0, 1000000.0, 42_000.0),
    // rear-unit yaw inertia I_r
    ParamSpec::new("i_r_kg_m2", "kg·m²", 1000.0, 1000000.0, 104_000.0),
    // front cg to front axle L_f1 (either sign)
    ParamSpec::new("l_f1_m", "m", -5.0, 5.0, 0.45),
    // front cg to joint L_f2
    ParamSpec::new("l_f2_m", "m", 0.1, 10.0, 2.13),
    // rear cg to rear axle L_r1 (either sign)
    ParamSpec::new("l_r1_m", "m", -5.0, 5.0, 1.13),
    // rear cg to joint L_r2
    ParamSpec::new("l_r2_m", "m", 0.1, 10.0, 2.31),
    // front cornering stiffness per tire (Eq 3.15)
    ParamSpec::new("c_alpha_f_n_per_rad", "N/rad", 1000.0, 10000000.0, 2.58e5),
    // rear cornering stiffness per tire
    ParamSpec::new("c_alpha_r_n_per_rad", "N/rad", 1000.0, 10000000.0, 2.81e5),
    // front aligning-moment coefficient
    ParamSpec::new("k_mz_f_nm_per_rad", "N·m/rad", 0.0, 10000000.0, 2.18e5),
    // rear aligning-moment coefficient
    ParamSpec::new("k_mz_r_nm_per_rad", "N·m/rad", 0.0, 10000000.0, 2.69e5),
    // tire relaxation length sigma_y (Eq 3.16; 0 = no lag)
    ParamSpec::new("relaxation_length_m", "m", 0.0, 5.0, 0.4),
    // half-track T (Eq 3.17)
    ParamSpec::new("half_track_m", "m", 0.3, 3.0, 1.14),
];

/// Number of parameters of the whole yaw-plane set.
const N_YAW_PLANE: usize = VEHICLE_PARAMS.len() + AFS_PARAMS.len();

/// [`VEHICLE_PARAMS`] followed by [`AFS_PARAMS`].
const fn concat() -> [ParamSpec; N_YAW_PLANE] {
    let mut out = [VEHICLE_PARAMS[0]; N_YAW_PLANE];
    let mut i = 0;
    while i < VEHICLE_PARAMS.len() {
        out[i] = VEHICLE_PARAMS[i];
        i += 1;
    }
    let mut j = 0;
    while j < AFS_PARAMS.len() {
        out[VEHICLE_PARAMS.len() + j] = AFS_PARAMS[j];
        j += 1;
    }
    out
}

/// The scalar parameters of [`YawPlaneParams`]: the vehicle's, then the steering system's.
pub const YAW_PLANE_PARAMS: [ParamSpec; N_YAW_PLANE] = concat();

impl ParamSet for VehicleParams {
    fn set_name(&self) -> &'static str {
        "yaw-plane vehicle"
    }

    fn specs(&self) -> &'static [ParamSpec] {
        &VEHICLE_PARAMS
    }

    fn value(&self, index: usize) -> f64 {
        match index {
            0 => self.m_f_kg,
            1 => self.m_r_kg,
            2 => self.i_f_kg_m2,
            3 => self.i_r_kg_m2,
            4 => self.l_f1_m,
            5 => self.l_f2_m,
            6 => self.l_r1_m,
            7 => self.l_r2_m,
            8 => self.c_alpha_f_n_per_rad,
            9 => self.c_alpha_r_n_per_rad,
            10 => self.k_mz_f_nm_per_rad,
            11 => self.k_mz_r_nm_per_rad,
            12 => self.relaxation_length_m,
            13 => self.half_track_m,
            _ => panic!("vehicle parameter index {index} out of range"),
        }
    }

    fn assign(&mut self, index: usize, value: f64) {
        let slot = match index {
            0 => &mut self.m_f_kg,
            1 => &mut self.m_r_kg,
            2 => &mut self.i_f_kg_m2,
            3 => &mut self.i_r_kg_m2,
            4 => &mut self.l_f1_m,
            5 => &mut self.l_f2_m,
            6 => &mut self.l_r1_m,
            7 => &mut self.l_r2_m,
            8 => &mut self.c_alpha_f_n_per_rad,
            9 => &mut self.c_alpha_r_n_per_rad,
            10 => &mut self.k_mz_f_nm_per_rad,
            11 => &mut self.k_mz_r_nm_per_rad,
            12 => &mut self.relaxation_length_m,
            13 => &mut self.half_track_m,
            _ => panic!("vehicle parameter index {index} out of range"),
        };
        *slot = value;
    }

    fn check(&self) -> Result<(), String> {
        self.validate().map_err(|e| e.to_string())
    }
}

impl ParamSet for YawPlaneParams {
    fn set_name(&self) -> &'static str {
        "yaw-plane"
    }

    fn specs(&self) -> &'static [ParamSpec] {
        &YAW_PLANE_PARAMS
    }

    fn value(&self, index: usize) -> f64 {
        match index.checked_sub(VEHICLE_PARAMS.len()) {
            None => self.vehicle.value(index),
            Some(j) => self.afs.value(j),
        }
    }

    fn assign(&mut self, index: usize, value: f64) {
        match index.checked_sub(VEHICLE_PARAMS.len()) {
            None => self.vehicle.assign(index, value),
            Some(j) => self.afs.assign(j, value),
        }
    }

    fn check(&self) -> Result<(), String> {
        self.validate().map_err(|e| e.to_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::yaw_plane::params::Load;
    use vehicle_components::{check_specs, ParamError};

    #[test]
    fn specs_are_well_formed_disjoint_and_hold_both_loads() {
        check_specs(&VEHICLE_PARAMS).unwrap();
        check_specs(&YAW_PLANE_PARAMS).unwrap(); // names distinct across vehicle and afs
        for load in [Load::Loaded, Load::Unloaded] {
            let p = YawPlaneParams::nominal(load);
            for (i, s) in YAW_PLANE_PARAMS.iter().enumerate() {
                s.admit(p.value(i)).unwrap();
            }
        }
        let p = VehicleParams::loaded();
        for (i, s) in VEHICLE_PARAMS.iter().enumerate() {
            let ratio = p.value(i).abs() / s.typical;
            assert!(ratio > 0.5 && ratio < 2.0, "{}: {ratio}", s.name);
        }
    }

    #[test]
    fn names_are_the_serde_fields_of_vehicle_and_afs() {
        let p = YawPlaneParams::nominal(Load::Loaded);
        let json = serde_json::to_value(&p).unwrap();
        let mut n = 0;
        for part in ["vehicle", "afs"] {
            for (k, v) in json[part].as_object().unwrap() {
                if let Some(x) = v.as_f64() {
                    assert_eq!(p.get(k).unwrap(), x, "{part}.{k}");
                    n += 1;
                }
            }
        }
        assert_eq!(n, YAW_PLANE_PARAMS.len());
    }

    #[test]
    fn set_by_name_reaches_either_part_and_validates() {
        let mut p = YawPlaneParams::nominal(Load::Unloaded);
        p.set("bulk_modulus_pa", 1.1e9).unwrap();
        p.set("relaxation_length_m", 0.8).unwrap();
        assert_eq!(p.afs.bulk_modulus_pa, 1.1e9);
        assert_eq!(p.vehicle.relaxation_length_m, 0.8);
        let before = p.clone();
        // in bounds, but the front axle would lie behind the joint
        let err = p.set("l_f1_m", -3.0).unwrap_err();
        assert!(matches!(err, ParamError::Rejected { .. }), "{err}");
        assert_eq!(p, before);
    }
}
