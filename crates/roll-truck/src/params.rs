//! Parameters of the 50-t rigid mining truck of Chapter 2 (Tables 2.1-2.3), loaded, in SI
//! units, with the values the chapter does not give stated as documented assumptions.
//!
//! Assumptions (docs/roll-truck.md gives the reasoning in full):
//! - suspension rates and damping of Table 2.2 are **per wheel station** (a per-axle
//!   reading puts the front static deflection at 238 mm of the 300 mm travel; per station
//!   it is 119 mm, see [`crate::statics`]);
//! - the struts' equivalent lateral spacing is `strut_spacing_ratio` times the axle's
//!   track: the one roll-compliance parameter, calibrated once to the smooth-road DRT of
//!   0.279 g ([`crate::calibration`]);
//! - roll centres (not in chapter 2): the front tires hang from their carriers at
//!   `front_roll_centre_height_m`, the rear axle rolls about a joint at
//!   `rear_roll_centre_height_m`; both default to the static wheel-centre heights
//!   ([`TruckParams::wheel_centre_heights_m`]);
//! - bump stops: clearance springs `bump_stop_ratio` = 10 times the strut rate, travel
//!   symmetric about the static position (note 1.10);
//! - cornering stiffness through the origin, `k_ty = 4.0 kN/deg * F_z / 140 kN` (Table 2.3
//!   gives one point; "kN/mm" is read as kN/deg);
//! - rear-axle pitch and yaw inertias and the front carriers' inertias (not in Table 2.1)
//!   are those of a 2.8 m beam and of a wheel; they barely enter roll;
//! - steering: road-wheel angle = steering-wheel angle / `steering_ratio` (25), ramp
//!   5 deg/s at the steering wheel starting at `ramp_start_s` = 2 s (note 1.5);
//! - PI speed gains 0.5 m g per (m/s) and 0.1 m g per m (note 1.10).

use serde::{Deserialize, Serialize};

use crate::calibration::CALIBRATED_STRUT_SPACING_RATIO;
use crate::error::{non_negative, positive, rejected, TruckError};

/// Strut spacing ratio of the plausible truck ([`TruckParams::plausible`]).
pub const PLAUSIBLE_STRUT_SPACING_RATIO: f64 = 0.5;

/// The built-in trucks: the calibrated one of [`TruckParams::nominal`] and the plausible
/// one of [`TruckParams::plausible`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BuiltinTruck {
    /// Strut spacing ratio calibrated to the smooth-road DRT (0.254).
    Calibrated,
    /// Struts at half the track (0.5).
    Plausible,
}

impl BuiltinTruck {
    /// Its parameters.
    pub fn params(self) -> TruckParams {
        match self {
            BuiltinTruck::Calibrated => TruckParams::nominal(),
            BuiltinTruck::Plausible => TruckParams::plausible(),
        }
    }

    /// Its name as parsed.
    pub fn name(self) -> &'static str {
        match self {
            BuiltinTruck::Calibrated => "calibrated",
            BuiltinTruck::Plausible => "plausible",
        }
    }
}

impl std::str::FromStr for BuiltinTruck {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "calibrated" => Ok(Self::Calibrated),
            "plausible" => Ok(Self::Plausible),
            _ => Err(format!("unknown truck `{s}` (calibrated, plausible)")),
        }
    }
}

/// Every parameter of the truck model (module docs for the assumed ones).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct TruckParams {
    /// Wheel base (m), Table 2.1.
    pub wheelbase_m: f64,
    /// Front track (m), Table 2.1.
    pub front_track_m: f64,
    /// Rear track (m) between the centres of the dual pairs, Table 2.1.
    pub rear_track_m: f64,
    /// Lateral spacing of the two tires of a rear dual pair (m), Table 2.1.
    pub dual_spacing_m: f64,
    /// Front unsprung mass, both wheel carriers together (kg), Table 2.1.
    pub front_unsprung_mass_kg: f64,
    /// Rear axle unsprung mass (kg), Table 2.1.
    pub rear_unsprung_mass_kg: f64,
    /// Rear axle roll inertia about its own cg (kg m²), Table 2.1.
    pub rear_axle_roll_inertia_kg_m2: f64,
    /// Sprung mass, loaded (kg), Table 2.1.
    pub sprung_mass_kg: f64,
    /// Sprung-mass cg height above ground at static equilibrium (m), Table 2.1.
    pub cg_height_m: f64,
    /// Longitudinal distance from the sprung cg to the front axle (m), Table 2.1.
    pub cg_to_front_axle_m: f64,
    /// Sprung roll inertia about its cg (kg m²), Table 2.1.
    pub sprung_roll_inertia_kg_m2: f64,
    /// Sprung pitch inertia about its cg (kg m²), Table 2.1.
    pub sprung_pitch_inertia_kg_m2: f64,
    /// Sprung yaw inertia about its cg (kg m²), Table 2.1.
    pub sprung_yaw_inertia_kg_m2: f64,
    /// Front strut rate per wheel station (N/m), Table 2.2 (1.1 kN/mm).
    pub front_spring_n_per_m: f64,
    /// Front strut damping per wheel station (N s/m), Table 2.2.
    pub front_damping_n_s_per_m: f64,
    /// Front strut travel, jounce plus rebound (m), Table 2.2.
    pub front_travel_m: f64,
    /// Rear strut rate per wheel station (N/m), Table 2.2 (5.2 kN/mm).
    pub rear_spring_n_per_m: f64,
    /// Rear strut damping per wheel station (N s/m), Table 2.2.
    pub rear_damping_n_s_per_m: f64,
    /// Rear strut travel, jounce plus rebound (m), Table 2.2.
    pub rear_travel_m: f64,
    /// Bump-stop rate over strut rate (-), assumed 10.
    pub bump_stop_ratio: f64,
    /// Equivalent lateral strut spacing over the axle's track (-), in (0, 1]: the
    /// calibrated roll-compliance parameter.
    pub strut_spacing_ratio: f64,
    /// Front roll-centre height above level ground at static equilibrium (m): the height
    /// of the carrier-fixed point from which each front tire hangs as a vertical column
    /// (its normal and lateral forces act on the carrier along the line through that
    /// point, its slip velocity is that point's). The sprung mass and the carriers tip
    /// over the front tires about this height (docs/roll-truck.md). Nominal: the static
    /// front wheel-centre height (0.977 m, the tire contact under the wheel centre);
    /// 0 puts the contact patch fixed to the tilting carrier (roll centre at the ground).
    pub front_roll_centre_height_m: f64,
    /// Rear roll-centre height above level ground at static equilibrium (m): the height of
    /// the revolute joint about which the rear axle rolls relative to the sprung mass.
    /// Nominal: the static rear wheel-centre height (0.985 m, the axle centre).
    pub rear_roll_centre_height_m: f64,
    /// Tire free radius (m), Table 2.3.
    pub tire_free_radius_m: f64,
    /// Tire vertical rate (N/m), Table 2.3 (1.8 kN/mm).
    pub tire_vertical_stiffness_n_per_m: f64,
    /// Tire vertical damping (N s/m), Table 2.3.
    pub tire_vertical_damping_n_s_per_m: f64,
    /// Tire cornering stiffness at the reference load (N/deg), Table 2.3 (4.0 kN/deg).
    pub cornering_stiffness_n_per_deg: f64,
    /// Reference load of the cornering stiffness (N), Table 2.3 (140 kN).
    pub cornering_reference_load_n: f64,
    /// Lateral relaxation length sigma_y (m), Table 2.3 and Eq 2.7.
    pub relaxation_length_m: f64,
    /// Target forward speed of the PI controller (m/s), 40 km/h (section 2.3).
    pub target_speed_m_s: f64,
    /// Proportional gain of the speed controller (N per m/s), assumed.
    pub speed_kp_n_per_m_s: f64,
    /// Integral gain of the speed controller (N per m), assumed.
    pub speed_ki_n_per_m: f64,
    /// Steering ratio, steering-wheel over road-wheel angle (-), assumed 25.
    pub steering_ratio: f64,
    /// Steering-wheel ramp rate (deg/s), 5 deg/s as in section 6.4.
    pub steering_wheel_rate_deg_s: f64,
    /// Time at which the ramp starts (s), after a settling period.
    pub ramp_start_s: f64,
    /// Gravitational acceleration (m/s²).
    pub gravity_m_s2: f64,
}

impl Default for TruckParams {
    fn default() -> Self {
        Self::nominal()
    }
}

impl TruckParams {
    /// The loaded truck of Tables 2.1-2.3 with the documented assumptions (module docs).
    pub fn nominal() -> Self {
        let total_mass = 73_840.0 + 3_900.0 + 7_800.0;
        let weight = total_mass * 9.81;
        let mut p = Self {
            wheelbase_m: 4.02,
            front_track_m: 3.3,
            rear_track_m: 2.8,
            dual_spacing_m: 0.69,
            front_unsprung_mass_kg: 3_900.0,
            rear_unsprung_mass_kg: 7_800.0,
            rear_axle_roll_inertia_kg_m2: 13_701.0,
            sprung_mass_kg: 73_840.0,
            cg_height_m: 3.15,
            cg_to_front_axle_m: 2.57,
            sprung_roll_inertia_kg_m2: 119_652.0,
            sprung_pitch_inertia_kg_m2: 286_761.0,
            sprung_yaw_inertia_kg_m2: 194_030.0,
            front_spring_n_per_m: 1.1e6,
            front_damping_n_s_per_m: 10.0e3,
            front_travel_m: 0.30,
            rear_spring_n_per_m: 5.2e6,
            rear_damping_n_s_per_m: 15.0e3,
            rear_travel_m: 0.22,
            bump_stop_ratio: 10.0,
            strut_spacing_ratio: CALIBRATED_STRUT_SPACING_RATIO,
            front_roll_centre_height_m: 0.0,
            rear_roll_centre_height_m: 0.0,
            tire_free_radius_m: 1.06,
            tire_vertical_stiffness_n_per_m: 1.8e6,
            tire_vertical_damping_n_s_per_m: 6.0e3,
            cornering_stiffness_n_per_deg: 4.0e3,
            cornering_reference_load_n: 140.0e3,
            relaxation_length_m: 1.0,
            target_speed_m_s: 40.0 / 3.6,
            speed_kp_n_per_m_s: 0.5 * weight,
            speed_ki_n_per_m: 0.1 * weight,
            steering_ratio: 25.0,
            steering_wheel_rate_deg_s: 5.0,
            ramp_start_s: 2.0,
            gravity_m_s2: 9.81,
        };
        (p.front_roll_centre_height_m, p.rear_roll_centre_height_m) = p.wheel_centre_heights_m();
        p
    }

    /// Static wheel-centre heights `(front, rear)` above level ground (m): the free radius
    /// minus the static tire deflection of [`crate::statics::Statics`] (0.977, 0.985 m for
    /// the nominal truck). The nominal roll-centre heights.
    pub fn wheel_centre_heights_m(&self) -> (f64, f64) {
        let s = crate::statics::Statics::of(self);
        (
            self.tire_free_radius_m - s.front_tire_deflection_m,
            self.tire_free_radius_m - s.rear_tire_deflection_m,
        )
    }

    /// The plausible truck beside the calibrated one: the nominal truck with the struts at
    /// half the track ([`PLAUSIBLE_STRUT_SPACING_RATIO`]: 1.65 m front, 1.40 m rear, as on a
    /// haul truck whose struts sit inboard of the wheels near the frame rails), everything
    /// else as [`TruckParams::nominal`]. Its bump stops engage at the roll angles of
    /// [`TruckParams::bump_stop_roll_angles_deg`] (10.3 deg front, 8.9 deg rear of
    /// suspension roll). docs/roll-truck.md compares the two.
    pub fn plausible() -> Self {
        Self {
            strut_spacing_ratio: PLAUSIBLE_STRUT_SPACING_RATIO,
            ..Self::nominal()
        }
    }

    /// The same truck with its bump stops out of reach: both travels set to 2 m, so a stop
    /// would engage only beyond 1 m of strut compression from static (about 2.4 rad of
    /// suspension roll at the calibrated ratio). For the peak-a_y diagnosis.
    pub fn without_bump_stops(&self) -> Self {
        Self {
            front_travel_m: 2.0,
            rear_travel_m: 2.0,
            ..*self
        }
    }

    /// Suspension roll angles `(front, rear)` (deg, sprung mass relative to the axle line)
    /// at which the struts reach their bump stops: half the travel over the half strut
    /// spacing, `atan(travel / (r T))`.
    pub fn bump_stop_roll_angles_deg(&self) -> (f64, f64) {
        let angle = |travel: f64, track: f64| {
            (travel / (self.strut_spacing_ratio * track))
                .atan()
                .to_degrees()
        };
        (
            angle(self.front_travel_m, self.front_track_m),
            angle(self.rear_travel_m, self.rear_track_m),
        )
    }

    /// Mass of one front wheel carrier (kg): half the front unsprung mass.
    pub fn front_carrier_mass_kg(&self) -> f64 {
        0.5 * self.front_unsprung_mass_kg
    }

    /// Total mass (kg).
    pub fn total_mass_kg(&self) -> f64 {
        self.sprung_mass_kg + self.front_unsprung_mass_kg + self.rear_unsprung_mass_kg
    }

    /// Distance from the sprung cg back to the rear axle (m).
    pub fn cg_to_rear_axle_m(&self) -> f64 {
        self.wheelbase_m - self.cg_to_front_axle_m
    }

    /// Cornering stiffness per unit load (1/rad): `k_ty / F_z` of Eq 2.5 with the line
    /// through the origin and the Table 2.3 point.
    pub fn cornering_coefficient_per_rad(&self) -> f64 {
        self.cornering_stiffness_n_per_deg.to_degrees() / self.cornering_reference_load_n
    }

    /// Road-wheel steering rate (rad/s) of the ramp.
    pub fn road_wheel_rate_rad_s(&self) -> f64 {
        self.steering_wheel_rate_deg_s.to_radians() / self.steering_ratio
    }

    /// Check every field (the error names it): all finite and positive where physical,
    /// the cg between the axles, the dual pair inside the rear track, the strut spacing
    /// ratio in (0, 1], static tire deflections below the free radius and static strut
    /// deflections of the springs positive.
    pub fn validate(&self) -> Result<(), TruckError> {
        for (field, value) in self.positive_fields() {
            positive(field, value)?;
        }
        for (field, value) in [
            ("front_damping_n_s_per_m", self.front_damping_n_s_per_m),
            ("rear_damping_n_s_per_m", self.rear_damping_n_s_per_m),
            (
                "tire_vertical_damping_n_s_per_m",
                self.tire_vertical_damping_n_s_per_m,
            ),
            ("speed_kp_n_per_m_s", self.speed_kp_n_per_m_s),
            ("speed_ki_n_per_m", self.speed_ki_n_per_m),
            ("ramp_start_s", self.ramp_start_s),
            (
                "front_roll_centre_height_m",
                self.front_roll_centre_height_m,
            ),
            ("rear_roll_centre_height_m", self.rear_roll_centre_height_m),
        ] {
            non_negative(field, value)?;
        }
        self.validate_relations()
    }

    fn positive_fields(&self) -> [(&'static str, f64); 28] {
        [
            ("wheelbase_m", self.wheelbase_m),
            ("front_track_m", self.front_track_m),
            ("rear_track_m", self.rear_track_m),
            ("dual_spacing_m", self.dual_spacing_m),
            ("front_unsprung_mass_kg", self.front_unsprung_mass_kg),
            ("rear_unsprung_mass_kg", self.rear_unsprung_mass_kg),
            (
                "rear_axle_roll_inertia_kg_m2",
                self.rear_axle_roll_inertia_kg_m2,
            ),
            ("sprung_mass_kg", self.sprung_mass_kg),
            ("cg_height_m", self.cg_height_m),
            ("cg_to_front_axle_m", self.cg_to_front_axle_m),
            ("sprung_roll_inertia_kg_m2", self.sprung_roll_inertia_kg_m2),
            (
                "sprung_pitch_inertia_kg_m2",
                self.sprung_pitch_inertia_kg_m2,
            ),
            ("sprung_yaw_inertia_kg_m2", self.sprung_yaw_inertia_kg_m2),
            ("front_spring_n_per_m", self.front_spring_n_per_m),
            ("front_travel_m", self.front_travel_m),
            ("rear_spring_n_per_m", self.rear_spring_n_per_m),
            ("rear_travel_m", self.rear_travel_m),
            ("bump_stop_ratio", self.bump_stop_ratio),
            ("strut_spacing_ratio", self.strut_spacing_ratio),
            ("tire_free_radius_m", self.tire_free_radius_m),
            (
                "tire_vertical_stiffness_n_per_m",
                self.tire_vertical_stiffness_n_per_m,
            ),
            (
                "cornering_stiffness_n_per_deg",
                self.cornering_stiffness_n_per_deg,
            ),
            (
                "cornering_reference_load_n",
                self.cornering_reference_load_n,
            ),
            ("relaxation_length_m", self.relaxation_length_m),
            ("target_speed_m_s", self.target_speed_m_s),
            ("steering_ratio", self.steering_ratio),
            ("steering_wheel_rate_deg_s", self.steering_wheel_rate_deg_s),
            ("gravity_m_s2", self.gravity_m_s2),
        ]
    }

    fn validate_relations(&self) -> Result<(), TruckError> {
        if self.cg_to_front_axle_m >= self.wheelbase_m {
            return Err(rejected(
                "cg_to_front_axle_m",
                self.cg_to_front_axle_m,
                "the sprung cg must lie between the axles (below wheelbase_m)",
            ));
        }
        if self.dual_spacing_m >= self.rear_track_m {
            return Err(rejected(
                "dual_spacing_m",
                self.dual_spacing_m,
                "the inner duals must not cross the centre line (below rear_track_m)",
            ));
        }
        if self.strut_spacing_ratio > 1.0 {
            return Err(rejected(
                "strut_spacing_ratio",
                self.strut_spacing_ratio,
                "the struts cannot sit outside the wheels (at most 1)",
            ));
        }
        let statics = crate::statics::Statics::of(self);
        let deflection = statics
            .front_tire_deflection_m
            .max(statics.rear_tire_deflection_m);
        if deflection >= 0.5 * self.tire_free_radius_m {
            return Err(rejected(
                "tire_vertical_stiffness_n_per_m",
                self.tire_vertical_stiffness_n_per_m,
                "static tire deflection would exceed half the free radius",
            ));
        }
        for (field, value) in [
            (
                "front_roll_centre_height_m",
                self.front_roll_centre_height_m,
            ),
            ("rear_roll_centre_height_m", self.rear_roll_centre_height_m),
        ] {
            if value >= self.cg_height_m {
                return Err(rejected(
                    field,
                    value,
                    "the roll centre must lie below the sprung cg (below cg_height_m)",
                ));
            }
        }
        if self.cg_height_m <= self.tire_free_radius_m {
            return Err(rejected(
                "cg_height_m",
                self.cg_height_m,
                "the sprung cg must lie above the wheel centres",
            ));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nominal_is_valid_and_rejections_name_the_field() {
        TruckParams::nominal().validate().expect("nominal valid");
        let mut p = TruckParams::nominal();
        p.sprung_mass_kg = f64::NAN;
        let e = p.validate().unwrap_err();
        assert!(e.to_string().contains("sprung_mass_kg"), "{e}");
        let mut p = TruckParams::nominal();
        p.cg_to_front_axle_m = 5.0;
        assert!(p
            .validate()
            .unwrap_err()
            .to_string()
            .contains("cg_to_front_axle_m"));
        let mut p = TruckParams::nominal();
        p.strut_spacing_ratio = 1.5;
        assert!(p
            .validate()
            .unwrap_err()
            .to_string()
            .contains("strut_spacing_ratio"));
        let mut p = TruckParams::nominal();
        p.front_damping_n_s_per_m = -1.0;
        assert!(p
            .validate()
            .unwrap_err()
            .to_string()
            .contains("front_damping"));
    }

    #[test]
    fn unknown_fields_are_refused_and_missing_fields_are_nominal() {
        let e = serde_json::from_str::<TruckParams>(r#"{"wheel_base": 4.0}"#).unwrap_err();
        assert!(e.to_string().contains("wheel_base"), "{e}");
        let p: TruckParams = serde_json::from_str(r#"{"cg_height_m": 3.3}"#).unwrap();
        assert_eq!(p.cg_height_m, 3.3);
        assert_eq!(p.wheelbase_m, 4.02);
    }

    #[test]
    fn cornering_coefficient_matches_table_2_3() {
        let p = TruckParams::nominal();
        // 4.0 kN/deg at 140 kN, in N/rad per N
        let k = p.cornering_coefficient_per_rad() * 140.0e3;
        assert!((k - 4.0e3 * 180.0 / std::f64::consts::PI).abs() < 1e-6);
    }
}
