//! The 3-D vehicle's parameters by name ([`vehicle_components::ParamSet`] for
//! [`VehicleParams`]): every scalar of Table 6.1 and of the documented assumptions under its
//! serde path (`front_unit.mass_kg`, `cab_point_m[2]`), with the range a design or a user's
//! vehicle may take: from a 10 t forwarder to a 100 t articulated hauler. The nested sets
//! keep their own registries: `tire` (tire-fiala), `steering` (afs-hydraulics), `hps`
//! (hps-emulsion); [`VehicleParams::validate`] applies on every set.

use vehicle_components::{ParamSet, ParamSpec};

use crate::params::VehicleParams;

/// Number of scalar parameters of [`VEHICLE_PARAMS`].
const N: usize = 33;

/// The scalars of [`VehicleParams`], in field order (a rigid part: mass, cg height, cg to
/// joint, roll, pitch and yaw inertia).
pub const VEHICLE_PARAMS: [ParamSpec; N] = [
    ParamSpec::new("gravity_m_s2", "m/s²", 9.7, 9.9, 9.81),
    ParamSpec::new("front_axle_to_joint_m", "m", 0.3, 10.0, 1.68),
    ParamSpec::new("rear_axle_to_joint_m", "m", 0.3, 15.0, 3.44),
    ParamSpec::new("front_track_m", "m", 0.8, 6.0, 2.28),
    ParamSpec::new("rear_track_m", "m", 0.8, 6.0, 2.28),
    ParamSpec::new("front_unit.mass_kg", "kg", 1_000.0, 200_000.0, 21_000.0),
    ParamSpec::new("front_unit.cg_height_m", "m", 0.2, 6.0, 1.36),
    ParamSpec::new("front_unit.cg_to_joint_m", "m", 0.0, 15.0, 2.13),
    ParamSpec::new(
        "front_unit.roll_inertia_kg_m2",
        "kg m²",
        10.0,
        1e7,
        14_000.0,
    ),
    ParamSpec::new(
        "front_unit.pitch_inertia_kg_m2",
        "kg m²",
        10.0,
        1e7,
        41_000.0,
    ),
    ParamSpec::new("front_unit.yaw_inertia_kg_m2", "kg m²", 10.0, 1e7, 42_000.0),
    ParamSpec::new("rear_unit.mass_kg", "kg", 1_000.0, 200_000.0, 18_500.0),
    ParamSpec::new("rear_unit.cg_height_m", "m", 0.2, 6.0, 1.55),
    ParamSpec::new("rear_unit.cg_to_joint_m", "m", 0.0, 15.0, 2.84),
    ParamSpec::new("rear_unit.roll_inertia_kg_m2", "kg m²", 10.0, 1e7, 12_000.0),
    ParamSpec::new(
        "rear_unit.pitch_inertia_kg_m2",
        "kg m²",
        10.0,
        1e7,
        28_000.0,
    ),
    ParamSpec::new("rear_unit.yaw_inertia_kg_m2", "kg m²", 10.0, 1e7, 31_000.0),
    ParamSpec::new("payload.mass_kg", "kg", 1.0, 300_000.0, 33_720.0),
    ParamSpec::new("payload.cg_height_m", "m", 0.2, 8.0, 2.4),
    ParamSpec::new("payload.cg_to_joint_m", "m", 0.0, 15.0, 2.6),
    ParamSpec::new("payload.roll_inertia_kg_m2", "kg m²", 1.0, 1e7, 27_000.0),
    ParamSpec::new("payload.pitch_inertia_kg_m2", "kg m²", 1.0, 1e7, 72_000.0),
    ParamSpec::new("payload.yaw_inertia_kg_m2", "kg m²", 1.0, 1e7, 76_000.0),
    ParamSpec::new("joint_height_m", "m", 0.0, 4.0, 1.0),
    ParamSpec::new("wheel_mass_kg", "kg", 10.0, 20_000.0, 2_000.0),
    ParamSpec::new("wheel_spin_inertia_kg_m2", "kg m²", 0.1, 1e5, 600.0),
    ParamSpec::new("wheel_tilt_inertia_kg_m2", "kg m²", 0.1, 1e5, 350.0),
    ParamSpec::new("cab_point_m[0]", "m", -20.0, 20.0, 1.68),
    ParamSpec::new("cab_point_m[1]", "m", -5.0, 5.0, 1.0),
    ParamSpec::new("cab_point_m[2]", "m", 0.0, 8.0, 2.0),
    ParamSpec::new("drive.kp_n_m_per_m_s", "N s", 1.0, 1e7, 9_000.0),
    ParamSpec::new("drive.ki_n_m_per_m", "N", 0.0, 1e7, 2_000.0),
    ParamSpec::new("drive.max_torque_n_m", "N m", 100.0, 1e7, 60_000.0),
];

impl VehicleParams {
    /// Mutable references to the fields in [`VEHICLE_PARAMS`] order.
    fn slots(&mut self) -> [&mut f64; N] {
        let [cx, cy, cz] = &mut self.cab_point_m;
        [
            &mut self.gravity_m_s2,
            &mut self.front_axle_to_joint_m,
            &mut self.rear_axle_to_joint_m,
            &mut self.front_track_m,
            &mut self.rear_track_m,
            &mut self.front_unit.mass_kg,
            &mut self.front_unit.cg_height_m,
            &mut self.front_unit.cg_to_joint_m,
            &mut self.front_unit.roll_inertia_kg_m2,
            &mut self.front_unit.pitch_inertia_kg_m2,
            &mut self.front_unit.yaw_inertia_kg_m2,
            &mut self.rear_unit.mass_kg,
            &mut self.rear_unit.cg_height_m,
            &mut self.rear_unit.cg_to_joint_m,
            &mut self.rear_unit.roll_inertia_kg_m2,
            &mut self.rear_unit.pitch_inertia_kg_m2,
            &mut self.rear_unit.yaw_inertia_kg_m2,
            &mut self.payload.mass_kg,
            &mut self.payload.cg_height_m,
            &mut self.payload.cg_to_joint_m,
            &mut self.payload.roll_inertia_kg_m2,
            &mut self.payload.pitch_inertia_kg_m2,
            &mut self.payload.yaw_inertia_kg_m2,
            &mut self.joint_height_m,
            &mut self.wheel_mass_kg,
            &mut self.wheel_spin_inertia_kg_m2,
            &mut self.wheel_tilt_inertia_kg_m2,
            cx,
            cy,
            cz,
            &mut self.drive.kp_n_m_per_m_s,
            &mut self.drive.ki_n_m_per_m,
            &mut self.drive.max_torque_n_m,
        ]
    }
}

impl ParamSet for VehicleParams {
    fn set_name(&self) -> &'static str {
        "vehicle-3d"
    }

    fn specs(&self) -> &'static [ParamSpec] {
        &VEHICLE_PARAMS
    }

    fn value(&self, index: usize) -> f64 {
        *self.clone().slots()[index]
    }

    fn assign(&mut self, index: usize, value: f64) {
        *self.slots()[index] = value;
    }

    fn check(&self) -> Result<(), String> {
        self.validate().map_err(|e| e.to_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use vehicle_components::check_specs;

    #[test]
    fn specs_are_well_formed_and_hold_the_nominal_set() {
        check_specs(&VEHICLE_PARAMS).unwrap();
        let p = VehicleParams::nominal();
        for (i, s) in VEHICLE_PARAMS.iter().enumerate() {
            s.admit(p.value(i))
                .unwrap_or_else(|e| panic!("nominal outside its range: {e}"));
        }
    }

    #[test]
    fn every_name_addresses_its_own_field() {
        let nominal = VehicleParams::nominal();
        for (i, s) in VEHICLE_PARAMS.iter().enumerate() {
            let mut p = nominal.clone();
            let v = p.value(i);
            let changed = if s.upper > v {
                (v + s.upper) / 2.0
            } else {
                (v + s.lower) / 2.0
            };
            p.assign(i, changed);
            assert_eq!(p.get(s.name).unwrap(), changed, "{}", s.name);
            for (j, _) in VEHICLE_PARAMS.iter().enumerate().filter(|(j, _)| *j != i) {
                assert_eq!(p.value(j), nominal.value(j), "{} moved {}", s.name, j);
            }
        }
    }

    #[test]
    fn set_refuses_out_of_range_and_inconsistent_values() {
        let mut p = VehicleParams::nominal();
        assert!(p.set("front_unit.mass_kg", -5.0).is_err());
        assert!(
            p.set("wheel_mass_kg", 15_000.0).is_err(),
            "wheels heavier than the unit"
        );
        assert_eq!(p, VehicleParams::nominal());
        p.set("payload.mass_kg", 20_000.0).unwrap();
        assert_eq!(p.payload.mass_kg, 20_000.0);
    }
}
