//! Named parameters of the truck ([`ParamSet`] for [`TruckParams`]): every field by its
//! serde name with SI unit, the range a study may explore and a typical magnitude (the
//! nominal loaded truck). [`TruckParams::validate`] still applies on every set.

use vehicle_components::{ParamSet, ParamSpec};

use crate::params::TruckParams;

/// The parameters of [`TruckParams`], in field order.
pub const TRUCK_PARAMS: [ParamSpec; 36] = [
    ParamSpec::new("wheelbase_m", "m", 1.0, 10.0, 4.02),
    ParamSpec::new("front_track_m", "m", 1.0, 6.0, 3.3),
    ParamSpec::new("rear_track_m", "m", 1.0, 6.0, 2.8),
    ParamSpec::new("dual_spacing_m", "m", 0.1, 2.0, 0.69),
    ParamSpec::new("front_unsprung_mass_kg", "kg", 10.0, 50_000.0, 3_900.0),
    ParamSpec::new("rear_unsprung_mass_kg", "kg", 10.0, 50_000.0, 7_800.0),
    ParamSpec::new(
        "rear_axle_roll_inertia_kg_m2",
        "kg m²",
        1.0,
        1.0e6,
        13_701.0,
    ),
    ParamSpec::new("sprung_mass_kg", "kg", 100.0, 500_000.0, 73_840.0),
    ParamSpec::new("cg_height_m", "m", 0.5, 8.0, 3.15),
    ParamSpec::new("cg_to_front_axle_m", "m", 0.1, 10.0, 2.57),
    ParamSpec::new("sprung_roll_inertia_kg_m2", "kg m²", 1.0, 1.0e7, 119_652.0),
    ParamSpec::new("sprung_pitch_inertia_kg_m2", "kg m²", 1.0, 1.0e7, 286_761.0),
    ParamSpec::new("sprung_yaw_inertia_kg_m2", "kg m²", 1.0, 1.0e7, 194_030.0),
    ParamSpec::new("front_spring_n_per_m", "N/m", 1.0e3, 1.0e8, 1.1e6),
    ParamSpec::new("front_damping_n_s_per_m", "N s/m", 0.0, 1.0e7, 1.0e4),
    ParamSpec::new("front_travel_m", "m", 0.01, 2.0, 0.30),
    ParamSpec::new("rear_spring_n_per_m", "N/m", 1.0e3, 1.0e8, 5.2e6),
    ParamSpec::new("rear_damping_n_s_per_m", "N s/m", 0.0, 1.0e7, 1.5e4),
    ParamSpec::new("rear_travel_m", "m", 0.01, 2.0, 0.22),
    ParamSpec::new("bump_stop_ratio", "-", 0.1, 1000.0, 10.0),
    ParamSpec::new("strut_spacing_ratio", "-", 0.01, 1.0, 0.254),
    ParamSpec::new("front_roll_centre_height_m", "m", 0.0, 3.0, 0.977),
    ParamSpec::new("rear_roll_centre_height_m", "m", 0.0, 3.0, 0.985),
    ParamSpec::new("tire_free_radius_m", "m", 0.1, 3.0, 1.06),
    ParamSpec::new(
        "tire_vertical_stiffness_n_per_m",
        "N/m",
        1.0e4,
        1.0e8,
        1.8e6,
    ),
    ParamSpec::new(
        "tire_vertical_damping_n_s_per_m",
        "N s/m",
        0.0,
        1.0e6,
        6.0e3,
    ),
    ParamSpec::new("cornering_stiffness_n_per_deg", "N/deg", 1.0, 1.0e6, 4.0e3),
    ParamSpec::new("cornering_reference_load_n", "N", 1.0, 1.0e7, 140.0e3),
    ParamSpec::new("relaxation_length_m", "m", 0.01, 100.0, 1.0),
    ParamSpec::new("target_speed_m_s", "m/s", 0.1, 50.0, 11.1),
    ParamSpec::new("speed_kp_n_per_m_s", "N s/m", 0.0, 1.0e8, 4.2e5),
    ParamSpec::new("speed_ki_n_per_m", "N/m", 0.0, 1.0e8, 8.4e4),
    ParamSpec::new("steering_ratio", "-", 1.0, 100.0, 25.0),
    ParamSpec::new("steering_wheel_rate_deg_s", "deg/s", 0.01, 1000.0, 5.0),
    ParamSpec::new("ramp_start_s", "s", 0.0, 1000.0, 2.0),
    ParamSpec::new("gravity_m_s2", "m/s²", 0.1, 100.0, 9.81),
];

impl TruckParams {
    /// Mutable references to the fields in [`TRUCK_PARAMS`] order.
    fn slots(&mut self) -> [&mut f64; 36] {
        [
            &mut self.wheelbase_m,
            &mut self.front_track_m,
            &mut self.rear_track_m,
            &mut self.dual_spacing_m,
            &mut self.front_unsprung_mass_kg,
            &mut self.rear_unsprung_mass_kg,
            &mut self.rear_axle_roll_inertia_kg_m2,
            &mut self.sprung_mass_kg,
            &mut self.cg_height_m,
            &mut self.cg_to_front_axle_m,
            &mut self.sprung_roll_inertia_kg_m2,
            &mut self.sprung_pitch_inertia_kg_m2,
            &mut self.sprung_yaw_inertia_kg_m2,
            &mut self.front_spring_n_per_m,
            &mut self.front_damping_n_s_per_m,
            &mut self.front_travel_m,
            &mut self.rear_spring_n_per_m,
            &mut self.rear_damping_n_s_per_m,
            &mut self.rear_travel_m,
            &mut self.bump_stop_ratio,
            &mut self.strut_spacing_ratio,
            &mut self.front_roll_centre_height_m,
            &mut self.rear_roll_centre_height_m,
            &mut self.tire_free_radius_m,
            &mut self.tire_vertical_stiffness_n_per_m,
            &mut self.tire_vertical_damping_n_s_per_m,
            &mut self.cornering_stiffness_n_per_deg,
            &mut self.cornering_reference_load_n,
            &mut self.relaxation_length_m,
            &mut self.target_speed_m_s,
            &mut self.speed_kp_n_per_m_s,
            &mut self.speed_ki_n_per_m,
            &mut self.steering_ratio,
            &mut self.steering_wheel_rate_deg_s,
            &mut self.ramp_start_s,
            &mut self.gravity_m_s2,
        ]
    }
}

impl ParamSet for TruckParams {
    fn set_name(&self) -> &'static str {
        "truck (chapter 2)"
    }

    fn specs(&self) -> &'static [ParamSpec] {
        &TRUCK_PARAMS
    }

    fn value(&self, index: usize) -> f64 {
        let mut copy = *self;
        *copy.slots()[index]
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
    use vehicle_components::params::check_specs;

    #[test]
    fn specs_are_consistent_and_cover_every_serde_field() {
        check_specs(&TRUCK_PARAMS).unwrap();
        let p = TruckParams::nominal();
        let json = serde_json::to_value(p).unwrap();
        let fields = json.as_object().unwrap();
        assert_eq!(fields.len(), TRUCK_PARAMS.len());
        for (i, spec) in TRUCK_PARAMS.iter().enumerate() {
            let v = fields[spec.name].as_f64().unwrap();
            assert_eq!(p.value(i), v, "{}", spec.name);
            assert!(
                spec.lower <= v && v <= spec.upper,
                "{} nominal out of bounds",
                spec.name
            );
        }
    }

    #[test]
    fn set_by_name_and_rejections_leave_the_set_unchanged() {
        let mut p = TruckParams::nominal();
        p.set("cg_height_m", 3.45).unwrap();
        assert_eq!(p.cg_height_m, 3.45);
        let before = p;
        assert!(p.set("cg_to_front_axle_m", 9.0).is_err());
        assert!(p.set("no_such", 1.0).is_err());
        assert_eq!(p, before);
    }
}
