//! The vehicle's parameters: Table 6.1 (dimensions and inertias of the 35 t articulated
//! dump truck), the 29.5R29 tire of Table 6.2, the Table 3.1 frame steering, the Table 6.3
//! front-axle strut, and a documented default for every number Chapter 6 does not give
//! (`docs/vehicle-3d.md`, "Assumptions"). SI units; field names carry the unit.
//!
//! Axes: x forward, y left, z up (right-handed, ISO 8855); every longitudinal position is
//! measured from the articulation joint, positive forward; heights from the ground at the
//! static equilibrium.

use afs_hydraulics::AfsParams;
use hps_emulsion::StrutParams;
use serde::{Deserialize, Serialize};
use tire_fiala::TireParams;

use crate::bogie::BogieParams;
use crate::error::{finite, non_negative, positive, rejected, VehicleError};

/// Mass, cg and inertias of one rigid part (a unit or the payload), Table 6.1.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RigidPart {
    /// Mass (kg).
    pub mass_kg: f64,
    /// Height of the cg above the ground at the static equilibrium (m).
    pub cg_height_m: f64,
    /// Longitudinal distance of the cg from the articulation joint (m), positive: ahead
    /// of it for the front unit, behind it for the rear unit and the payload (as Table 6.1
    /// prints them).
    pub cg_to_joint_m: f64,
    /// Roll moment of inertia about the part's own cg (kg m²).
    pub roll_inertia_kg_m2: f64,
    /// Pitch moment of inertia about the part's own cg (kg m²).
    pub pitch_inertia_kg_m2: f64,
    /// Yaw moment of inertia about the part's own cg (kg m²).
    pub yaw_inertia_kg_m2: f64,
}

/// Whether the rear unit carries its payload (Table 6.1: loaded = with the 33.72 t payload).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Load {
    /// With the payload.
    Loaded,
    /// Without it.
    Unloaded,
}

impl std::str::FromStr for Load {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "loaded" => Ok(Self::Loaded),
            "unloaded" => Ok(Self::Unloaded),
            _ => Err(format!("unknown load `{s}` (use `loaded` or `unloaded`)")),
        }
    }
}

impl std::fmt::Display for Load {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::Loaded => "loaded",
            Self::Unloaded => "unloaded",
        })
    }
}

/// How the units' yaw inertias enter the equations of motion.
///
/// The multibody tree derives its own equations, so the default is the energy-consistent
/// form. `PaperEq313` reproduces the dissertation's printed Eq 3.13 (and Eq 4.1), which adds
/// `m_f L_f2²` and `m_r L_r2²` to the units' yaw inertias although the moments of the cg
/// inertial forces about the joint already hold them: each unit's yaw inertia about its cg
/// grows by its mass times the square of its cg's horizontal distance from the articulation
/// joint (the rear unit's with the payload of the load case). It exists to show the fidelity
/// gap to the paper's 2.81 Hz yaw mode, never for design (docs/vehicle-3d.md).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum YawInertiaForm {
    /// The tree's own, energy-consistent equations (default).
    #[default]
    EnergyConsistent,
    /// The printed Eq 3.13: `m L²` counted twice in the yaw inertias.
    #[serde(rename = "paper_eq_3_13")]
    PaperEq313,
}

impl YawInertiaForm {
    /// Whether this is the default form (a parameter file leaves it out).
    pub fn is_energy_consistent(&self) -> bool {
        *self == Self::EnergyConsistent
    }
}

/// The speed controller: one drive torque for all four wheels (L1576), a PI law on the
/// error of the mean wheel-centre speed, `T = T_rr + k_p e + k_i integral(e)` with the
/// rolling-resistance torque `T_rr` of the static loads as feed-forward.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DriveParams {
    /// Proportional gain (N m per m/s, per wheel). Assumption: 9 kN m/(m/s), a speed loop
    /// of about 0.5 rad/s on the loaded truck.
    pub kp_n_m_per_m_s: f64,
    /// Integral gain (N m per m, per wheel). Assumption: 2 kN m/m.
    pub ki_n_m_per_m: f64,
    /// Largest drive (or braking) torque per wheel (N m). Assumption: 60 kN m.
    pub max_torque_n_m: f64,
}

/// Every parameter of the 3-D vehicle (module docs). `nominal()` is Table 6.1 with the
/// documented assumptions; missing fields of a JSON file take their nominal value.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct VehicleParams {
    /// Gravitational acceleration (m/s²).
    pub gravity_m_s2: f64,
    /// Front axle to articulation joint (m). Table 6.1: 1.68.
    pub front_axle_to_joint_m: f64,
    /// Rear axle to articulation joint (m). Table 6.1: 3.44 (wheel base 5.12 m).
    pub rear_axle_to_joint_m: f64,
    /// Front track (m). Table 6.1: 2.28.
    pub front_track_m: f64,
    /// Rear track (m). Table 6.1: 2.28.
    pub rear_track_m: f64,
    /// Front unit, wheels included. Table 6.1.
    pub front_unit: RigidPart,
    /// Rear unit, wheels included, without the payload. Table 6.1.
    pub rear_unit: RigidPart,
    /// Payload, fixed to the rear unit when loaded. Table 6.1.
    pub payload: RigidPart,
    /// Height of the articulation joint (both revolutes) above the ground (m).
    /// Assumption: 1.0 m, about the wheel radius (note 2.10).
    pub joint_height_m: f64,
    /// Mass of one wheel end: tire, rim, in-wheel drive (kg). Assumption: 2 000 kg. Part
    /// of the Table 6.1 unit masses; with the HPS it is the unsprung mass of a front corner.
    pub wheel_mass_kg: f64,
    /// Spin moment of inertia of one wheel end (kg m²). Assumption: 600.
    pub wheel_spin_inertia_kg_m2: f64,
    /// Moment of inertia of one wheel end about its diameters (kg m²). Assumption: 350.
    pub wheel_tilt_inertia_kg_m2: f64,
    /// Where a_wz is measured: a point of the front unit `[x from the joint, y, height]`
    /// (m). Assumption: above the front axle at cab-floor height, `[1.68, 0, 2.0]`.
    pub cab_point_m: [f64; 3],
    /// The 29.5R29 tire, Table 6.2 (all four tires).
    pub tire: TireParams,
    /// Frame steering, Table 3.1. The strut mounts are its planar layout at the joint
    /// height: the front-unit mount `l_1` from the joint at `90 deg - A_0` from the x axis,
    /// the rear mount on the hitch `l_2` beside the joint (`docs/vehicle-3d.md`).
    pub steering: AfsParams,
    /// The front-axle strut, Table 6.3, used when the vehicle is built with the HPS.
    pub hps: StrutParams,
    /// The rear-axle strut: `Some` suspends the rear axle on one strut per wheel, mounted
    /// as the front's (`docs/layouts.md`, "HPS on any axle"); `None`, the prototype, keeps
    /// it rigid. [`crate::suspension::scaled_strut`] gives the designer's default, the
    /// front strut scaled for the rear static load.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rear_hps: Option<StrutParams>,
    /// The rear walking-beam bogie ([`crate::bogie`]): `Some` replaces the single rear axle
    /// by a tandem, one beam per side pitching about a pivot at `rear_axle_to_joint_m`, the
    /// side's strut (with `rear_hps`) at the pivot; `None`, the prototype, one rear axle.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bogie: Option<BogieParams>,
    /// The speed controller.
    pub drive: DriveParams,
    /// The yaw-inertia form ([`YawInertiaForm`]); left out of a file, energy-consistent.
    #[serde(skip_serializing_if = "YawInertiaForm::is_energy_consistent")]
    pub yaw_inertia_form: YawInertiaForm,
}

impl Default for VehicleParams {
    fn default() -> Self {
        Self::nominal()
    }
}

impl VehicleParams {
    /// Table 6.1 with the documented assumptions.
    pub fn nominal() -> Self {
        Self {
            gravity_m_s2: 9.81,
            front_axle_to_joint_m: 1.68,
            rear_axle_to_joint_m: 3.44,
            front_track_m: 2.28,
            rear_track_m: 2.28,
            front_unit: RigidPart {
                mass_kg: 21_000.0,
                cg_height_m: 1.36,
                cg_to_joint_m: 2.13,
                roll_inertia_kg_m2: 14_000.0,
                pitch_inertia_kg_m2: 41_000.0,
                yaw_inertia_kg_m2: 42_000.0,
            },
            rear_unit: RigidPart {
                mass_kg: 18_500.0,
                cg_height_m: 1.55,
                cg_to_joint_m: 2.84,
                roll_inertia_kg_m2: 12_000.0,
                pitch_inertia_kg_m2: 28_000.0,
                yaw_inertia_kg_m2: 31_000.0,
            },
            payload: RigidPart {
                mass_kg: 33_720.0,
                cg_height_m: 2.4,
                cg_to_joint_m: 2.6,
                roll_inertia_kg_m2: 27_000.0,
                pitch_inertia_kg_m2: 72_000.0,
                yaw_inertia_kg_m2: 76_000.0,
            },
            joint_height_m: 1.0,
            wheel_mass_kg: 2_000.0,
            wheel_spin_inertia_kg_m2: 600.0,
            wheel_tilt_inertia_kg_m2: 350.0,
            cab_point_m: [1.68, 0.0, 2.0],
            tire: TireParams::nominal(),
            steering: AfsParams::nominal(),
            hps: StrutParams::front_axle(),
            rear_hps: None,
            bogie: None,
            drive: DriveParams {
                kp_n_m_per_m_s: 9_000.0,
                ki_n_m_per_m: 2_000.0,
                max_torque_n_m: 60_000.0,
            },
            yaw_inertia_form: YawInertiaForm::EnergyConsistent,
        }
    }

    /// Wheel base (m): front plus rear axle distance from the joint.
    pub fn wheelbase_m(&self) -> f64 {
        self.front_axle_to_joint_m + self.rear_axle_to_joint_m
    }

    /// Longitudinal position of the front axle ahead of the front unit's cg (m): the joint
    /// lies `front_unit.cg_to_joint_m` behind the cg, the axle `front_axle_to_joint_m` ahead
    /// of the joint (Table 6.1; the wheel centres of [`crate::model`]).
    pub fn front_axle_x_m(&self) -> f64 {
        self.front_axle_to_joint_m - self.front_unit.cg_to_joint_m
    }

    /// The rear-unit parts of a load case: the rear unit, and the payload when loaded.
    pub fn rear_parts(&self, load: Load) -> Vec<RigidPart> {
        match load {
            Load::Loaded => vec![self.rear_unit, self.payload],
            Load::Unloaded => vec![self.rear_unit],
        }
    }

    /// Check every field; the error names the first bad one.
    pub fn validate(&self) -> Result<(), VehicleError> {
        positive("gravity_m_s2", self.gravity_m_s2)?;
        positive("front_axle_to_joint_m", self.front_axle_to_joint_m)?;
        positive("rear_axle_to_joint_m", self.rear_axle_to_joint_m)?;
        positive("front_track_m", self.front_track_m)?;
        positive("rear_track_m", self.rear_track_m)?;
        validate_part(&FRONT_UNIT_FIELDS, &self.front_unit)?;
        validate_part(&REAR_UNIT_FIELDS, &self.rear_unit)?;
        validate_part(&PAYLOAD_FIELDS, &self.payload)?;
        non_negative("joint_height_m", self.joint_height_m)?;
        positive("wheel_mass_kg", self.wheel_mass_kg)?;
        positive("wheel_spin_inertia_kg_m2", self.wheel_spin_inertia_kg_m2)?;
        positive("wheel_tilt_inertia_kg_m2", self.wheel_tilt_inertia_kg_m2)?;
        for (field, v) in ["cab_point_m[0]", "cab_point_m[1]", "cab_point_m[2]"]
            .into_iter()
            .zip(self.cab_point_m)
        {
            finite(field, v)?;
        }
        for (unit, wheels) in [
            ("front_unit.mass_kg", &self.front_unit),
            ("rear_unit.mass_kg", &self.rear_unit),
        ] {
            if wheels.mass_kg <= 2.0 * self.wheel_mass_kg {
                return Err(rejected(
                    unit,
                    wheels.mass_kg,
                    "must exceed the two wheel ends it carries (2 wheel_mass_kg)",
                ));
            }
        }
        if let Some(b) = &self.bogie {
            b.validate()?;
            if self.rear_unit.mass_kg <= 4.0 * self.wheel_mass_kg + 2.0 * b.beam_mass_kg {
                return Err(rejected(
                    "rear_unit.mass_kg",
                    self.rear_unit.mass_kg,
                    "must exceed the bogie it carries (4 wheel_mass_kg + 2 bogie.beam_mass_kg)",
                ));
            }
            if b.spacing_m <= 2.0 * self.tire.unloaded_radius_m {
                return Err(rejected(
                    "bogie.spacing_m",
                    b.spacing_m,
                    "the tandem tires overlap: must exceed the tire diameter (2 tire.unloaded_radius_m)",
                ));
            }
            if b.half_spacing_m() >= self.rear_axle_to_joint_m {
                return Err(rejected(
                    "bogie.spacing_m",
                    b.spacing_m,
                    "the leading tandem axle reaches the articulation joint (spacing / 2 >= rear_axle_to_joint_m)",
                ));
            }
        }
        self.tire.validate()?;
        self.steering.validate()?;
        self.hps.validate()?;
        if let Some(rear) = &self.rear_hps {
            rear.validate().map_err(|e| match e {
                hps_emulsion::HpsError::InvalidParameter { value, reason, .. } => {
                    rejected("rear_hps", value, reason)
                }
                other => VehicleError::from(other),
            })?;
        }
        positive("drive.kp_n_m_per_m_s", self.drive.kp_n_m_per_m_s)?;
        non_negative("drive.ki_n_m_per_m", self.drive.ki_n_m_per_m)?;
        positive("drive.max_torque_n_m", self.drive.max_torque_n_m)?;
        Ok(())
    }
}

/// Field names of one [`RigidPart`] in error messages: mass, cg height, cg to joint,
/// roll, pitch, yaw.
type PartFields = [&'static str; 6];

const FRONT_UNIT_FIELDS: PartFields = [
    "front_unit.mass_kg",
    "front_unit.cg_height_m",
    "front_unit.cg_to_joint_m",
    "front_unit.roll_inertia_kg_m2",
    "front_unit.pitch_inertia_kg_m2",
    "front_unit.yaw_inertia_kg_m2",
];
const REAR_UNIT_FIELDS: PartFields = [
    "rear_unit.mass_kg",
    "rear_unit.cg_height_m",
    "rear_unit.cg_to_joint_m",
    "rear_unit.roll_inertia_kg_m2",
    "rear_unit.pitch_inertia_kg_m2",
    "rear_unit.yaw_inertia_kg_m2",
];
const PAYLOAD_FIELDS: PartFields = [
    "payload.mass_kg",
    "payload.cg_height_m",
    "payload.cg_to_joint_m",
    "payload.roll_inertia_kg_m2",
    "payload.pitch_inertia_kg_m2",
    "payload.yaw_inertia_kg_m2",
];

fn validate_part(f: &PartFields, p: &RigidPart) -> Result<(), VehicleError> {
    positive(f[0], p.mass_kg)?;
    positive(f[1], p.cg_height_m)?;
    finite(f[2], p.cg_to_joint_m)?;
    positive(f[3], p.roll_inertia_kg_m2)?;
    positive(f[4], p.pitch_inertia_kg_m2)?;
    positive(f[5], p.yaw_inertia_kg_m2)?;
    // principal moments of a real body obey the triangle inequality
    let (a, b, c) = (
        p.roll_inertia_kg_m2,
        p.pitch_inertia_kg_m2,
        p.yaw_inertia_kg_m2,
    );
    if a > b + c || b > a + c || c > a + b {
        return Err(rejected(
            f[3],
            a,
            "the three moments of inertia violate the triangle inequality",
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nominal_is_valid_and_round_trips_through_json() {
        let p = VehicleParams::nominal();
        p.validate().unwrap();
        assert!((p.wheelbase_m() - 5.12).abs() < 1e-12);
        let text = serde_json::to_string(&p).unwrap();
        let back: VehicleParams = serde_json::from_str(&text).unwrap();
        assert_eq!(back, p);
    }

    #[test]
    fn bad_values_name_their_field() {
        let mut p = VehicleParams::nominal();
        p.rear_unit.yaw_inertia_kg_m2 = -1.0;
        let err = p.validate().unwrap_err().to_string();
        assert!(err.contains("rear_unit.yaw_inertia_kg_m2"), "{err}");
        let mut p = VehicleParams::nominal();
        p.wheel_mass_kg = 20_000.0;
        let err = p.validate().unwrap_err().to_string();
        assert!(err.contains("front_unit.mass_kg"), "{err}");
        let mut p = VehicleParams::nominal();
        p.cab_point_m[2] = f64::NAN;
        assert!(p
            .validate()
            .unwrap_err()
            .to_string()
            .contains("cab_point_m[2]"));
    }

    #[test]
    fn unknown_fields_are_refused() {
        let err = serde_json::from_str::<VehicleParams>(r#"{"wheel_base_m": 5.0}"#).unwrap_err();
        assert!(err.to_string().contains("wheel_base_m"), "{err}");
    }
}
