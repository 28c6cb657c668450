//! Vehicle parameters of the yaw-plane model (Table 3.1, vehicle columns).
//!
//! All fields are SI. Table 3.1 gives the cornering stiffness in kN/deg and the aligning
//! moment coefficient in kN m/deg, **per tire** (Eq 3.15 applies them to each tire i); the
//! constructors convert them here, at the boundary.

use crate::error::DynError;
use serde::{Deserialize, Serialize};

/// Load condition of the 35 t articulated mining truck (Table 3.1 columns).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Load {
    /// Rated payload.
    Loaded,
    /// No payload.
    Unloaded,
}

impl Load {
    /// Both load conditions, loaded first.
    pub const ALL: [Load; 2] = [Load::Loaded, Load::Unloaded];

    /// Lower-case name used in files and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Load::Loaded => "loaded",
            Load::Unloaded => "unloaded",
        }
    }
}

impl std::str::FromStr for Load {
    type Err = DynError;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s {
            "loaded" => Ok(Load::Loaded),
            "unloaded" => Ok(Load::Unloaded),
            other => Err(DynError::InvalidInput(format!(
                "unknown load `{other}` (expected `loaded` or `unloaded`)"
            ))),
        }
    }
}

/// Inertial, geometric and tire parameters of the two vehicle units (Fig 3.5, Table 3.1).
///
/// Distances follow the paper's Eq 3.13/3.17 sign use: the front axle is `l_f1` *ahead* of
/// the front-unit cg (Table 3.1 gives -0.45 m, i.e. 0.45 m behind it), the articulation
/// joint `l_f2` behind the front cg and `l_r2` ahead of the rear cg, the rear axle `l_r1`
/// behind the rear cg.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VehicleParams {
    /// Mass of the front unit m_f (kg).
    pub m_f_kg: f64,
    /// Mass of the rear unit m_r (kg).
    pub m_r_kg: f64,
    /// Yaw moment of inertia of the front unit about its cg, I_f (kg m^2).
    pub i_f_kg_m2: f64,
    /// Yaw moment of inertia of the rear unit about its cg, I_r (kg m^2).
    pub i_r_kg_m2: f64,
    /// Front cg to front axle, positive forward, L_f1 (m).
    pub l_f1_m: f64,
    /// Front cg to articulation joint (rearward), L_f2 (m).
    pub l_f2_m: f64,
    /// Rear cg to rear axle (rearward), L_r1 (m).
    pub l_r1_m: f64,
    /// Rear cg to articulation joint (forward), L_r2 (m).
    pub l_r2_m: f64,
    /// Cornering stiffness of each front tire, C_alpha_f (N/rad).
    pub c_alpha_f_n_per_rad: f64,
    /// Cornering stiffness of each rear tire, C_alpha_r (N/rad).
    pub c_alpha_r_n_per_rad: f64,
    /// Aligning-moment coefficient of each front tire, k_mzf (N m/rad).
    pub k_mz_f_nm_per_rad: f64,
    /// Aligning-moment coefficient of each rear tire, k_mzr (N m/rad).
    pub k_mz_r_nm_per_rad: f64,
    /// Tire lateral relaxation length sigma_y (m), Eq 3.16. `0` switches the lag off:
    /// the slip angles then equal their steady values (Eq 3.17) and carry no state.
    pub relaxation_length_m: f64,
    /// Half-track T (m), Eq 3.17.
    pub half_track_m: f64,
}

const KN_PER_DEG: f64 = 1.0e3 * 180.0 / std::f64::consts::PI;

impl VehicleParams {
    /// Table 3.1, loaded column.
    pub fn loaded() -> Self {
        Self {
            m_f_kg: 21_000.0,
            m_r_kg: 52_220.0,
            i_f_kg_m2: 42_000.0,
            i_r_kg_m2: 104_000.0,
            l_f1_m: -0.45,
            l_f2_m: 2.13,
            l_r1_m: 1.13,
            l_r2_m: 2.31,
            c_alpha_f_n_per_rad: 4.5 * KN_PER_DEG,
            c_alpha_r_n_per_rad: 4.9 * KN_PER_DEG,
            k_mz_f_nm_per_rad: 3.8 * KN_PER_DEG,
            k_mz_r_nm_per_rad: 4.7 * KN_PER_DEG,
            relaxation_length_m: 0.4,
            half_track_m: 1.14,
        }
    }

    /// Table 3.1, unloaded column.
    pub fn unloaded() -> Self {
        Self {
            m_f_kg: 21_000.0,
            m_r_kg: 18_500.0,
            i_f_kg_m2: 42_000.0,
            i_r_kg_m2: 31_000.0,
            l_f1_m: -0.45,
            l_f2_m: 2.13,
            l_r1_m: 0.60,
            l_r2_m: 2.84,
            c_alpha_f_n_per_rad: 4.1 * KN_PER_DEG,
            c_alpha_r_n_per_rad: 2.54 * KN_PER_DEG,
            k_mz_f_nm_per_rad: 2.35 * KN_PER_DEG,
            k_mz_r_nm_per_rad: 1.43 * KN_PER_DEG,
            relaxation_length_m: 0.4,
            half_track_m: 1.14,
        }
    }

    /// Table 3.1 for the given load condition.
    pub fn nominal(load: Load) -> Self {
        match load {
            Load::Loaded => Self::loaded(),
            Load::Unloaded => Self::unloaded(),
        }
    }

    /// Check every field; the error names the first offending one.
    ///
    /// Masses, inertias and the joint distances must be positive; tire coefficients,
    /// relaxation length and half-track non-negative (zero switches the effect off);
    /// `l_f1` may have either sign but the front axle must lie ahead of the joint
    /// (`l_f1 + l_f2 > 0`) and the rear axle behind it (`l_r1 + l_r2 > 0`).
    pub fn validate(&self) -> Result<(), DynError> {
        let positive = [
            ("m_f_kg", self.m_f_kg),
            ("m_r_kg", self.m_r_kg),
            ("i_f_kg_m2", self.i_f_kg_m2),
            ("i_r_kg_m2", self.i_r_kg_m2),
            ("l_f2_m", self.l_f2_m),
            ("l_r2_m", self.l_r2_m),
        ];
        for (name, v) in positive {
            if !(v.is_finite() && v > 0.0) {
                return Err(DynError::param(
                    name,
                    format!("must be positive and finite, got {v}"),
                ));
            }
        }
        let non_negative = [
            ("c_alpha_f_n_per_rad", self.c_alpha_f_n_per_rad),
            ("c_alpha_r_n_per_rad", self.c_alpha_r_n_per_rad),
            ("k_mz_f_nm_per_rad", self.k_mz_f_nm_per_rad),
            ("k_mz_r_nm_per_rad", self.k_mz_r_nm_per_rad),
            ("relaxation_length_m", self.relaxation_length_m),
            ("half_track_m", self.half_track_m),
        ];
        for (name, v) in non_negative {
            if !(v.is_finite() && v >= 0.0) {
                return Err(DynError::param(
                    name,
                    format!("must be >= 0 and finite, got {v}"),
                ));
            }
        }
        for (name, v) in [("l_f1_m", self.l_f1_m), ("l_r1_m", self.l_r1_m)] {
            if !v.is_finite() {
                return Err(DynError::param(name, format!("must be finite, got {v}")));
            }
        }
        if self.l_f1_m + self.l_f2_m <= 0.0 {
            return Err(DynError::param(
                "l_f1_m",
                format!(
                    "front axle must lie ahead of the joint (l_f1 + l_f2 = {} m)",
                    self.l_f1_m + self.l_f2_m
                ),
            ));
        }
        if self.l_r1_m + self.l_r2_m <= 0.0 {
            return Err(DynError::param(
                "l_r1_m",
                format!(
                    "rear axle must lie behind the joint (l_r1 + l_r2 = {} m)",
                    self.l_r1_m + self.l_r2_m
                ),
            ));
        }
        Ok(())
    }

    /// Front axle to joint distance L_f1 + L_f2 (m).
    pub fn front_axle_to_joint(&self) -> f64 {
        self.l_f1_m + self.l_f2_m
    }

    /// Joint to rear axle distance L_r1 + L_r2 (m).
    pub fn joint_to_rear_axle(&self) -> f64 {
        self.l_r1_m + self.l_r2_m
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_3_1_conversions() {
        let p = VehicleParams::loaded();
        // 4.5 kN/deg = 257.83 kN/rad
        assert!((p.c_alpha_f_n_per_rad - 257_831.0).abs() < 1.0);
        assert!((VehicleParams::unloaded().k_mz_r_nm_per_rad - 81_933.0).abs() < 1.0);
        p.validate().unwrap();
        VehicleParams::unloaded().validate().unwrap();
    }

    #[test]
    fn rejects_bad_fields_by_name() {
        let mut p = VehicleParams::loaded();
        p.m_r_kg = f64::NAN;
        assert!(p.validate().unwrap_err().to_string().contains("m_r_kg"));
        let mut p = VehicleParams::loaded();
        p.relaxation_length_m = -0.1;
        assert!(p
            .validate()
            .unwrap_err()
            .to_string()
            .contains("relaxation_length_m"));
        let mut p = VehicleParams::loaded();
        p.l_f1_m = -3.0;
        assert!(p.validate().unwrap_err().to_string().contains("l_f1_m"));
    }

    #[test]
    fn load_parses() {
        assert_eq!("loaded".parse::<Load>().unwrap(), Load::Loaded);
        assert!("heavy".parse::<Load>().is_err());
    }
}

/// Complete parameter set of the yaw-plane model: vehicle (Table 3.1, vehicle columns)
/// and frame steering (Table 3.1 steering column / Table 4.1, see `docs/afs-hydraulics.md`
/// for its units). This is the file format of `afsv params dump yaw-plane`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct YawPlaneParams {
    /// Load condition the vehicle column belongs to (informative; `None` for a user set).
    #[serde(default)]
    pub load: Option<Load>,
    /// Vehicle parameters.
    pub vehicle: VehicleParams,
    /// Steering-system parameters.
    pub afs: afs_hydraulics::AfsParams,
}

impl YawPlaneParams {
    /// Table 3.1 for the given load with the nominal steering system.
    pub fn nominal(load: Load) -> Self {
        Self {
            load: Some(load),
            vehicle: VehicleParams::nominal(load),
            afs: afs_hydraulics::AfsParams::nominal(),
        }
    }

    /// Validate both parts; the error names the offending field.
    pub fn validate(&self) -> Result<(), DynError> {
        self.vehicle.validate()?;
        self.afs
            .validate()
            .map_err(|e| DynError::Steering(e.to_string()))
    }

    /// Build the steering component (validates the steering parameters).
    pub fn afs_system(&self) -> Result<afs_hydraulics::AfsSystem, DynError> {
        afs_hydraulics::AfsSystem::new(self.afs.clone())
            .map_err(|e| DynError::Steering(e.to_string()))
    }
}

#[cfg(test)]
mod set_tests {
    use super::*;

    #[test]
    fn yaw_plane_set_round_trips_through_json_and_validates() {
        let p = YawPlaneParams::nominal(Load::Unloaded);
        let s = serde_json::to_string(&p).unwrap();
        let q: YawPlaneParams = serde_json::from_str(&s).unwrap();
        // serde_json's default float parser may differ in the last bit.
        assert_eq!(p.vehicle, q.vehicle);
        assert!((p.afs.gerotor_displacement / q.afs.gerotor_displacement - 1.0).abs() < 1e-14);
        q.validate().unwrap();
        let mut bad = q.clone();
        bad.afs.l1_m = 0.0;
        assert!(bad.validate().unwrap_err().to_string().contains("l1"));
        let unknown = s.replacen("\"vehicle\"", "\"vehicel\"", 1);
        assert!(serde_json::from_str::<YawPlaneParams>(&unknown).is_err());
    }
}
