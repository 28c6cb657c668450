//! A run's record channels in the toolkit's record convention `afsv-v1` (docs/records.md):
//! the one place that names the 3-D vehicle's channels and converts them from the model's
//! signs and units. `afsv vehicle simulate -o`, `afsv vehicle path-change -o`, the Python
//! package's `simulate_vehicle` and discovery's replay all read a [`RunRecord`] through it.
//!
//! Conversions: angles in degrees; the yaw rate right-turn positive (the model's is
//! left-turn positive about +z, module docs of [`mod@crate::simulate`]); everything else as the
//! model records it (SI, body axes of the front unit).

use crate::simulate::RunRecord;

/// The channels of a written record, in column order: a vehicle steering test's channels,
/// then the ride channels.
pub const RECORD_CHANNELS: [&str; 24] = [
    "time_s",
    "steer_wheel_deg",
    "speed_m_s",
    "articulation_deg",
    "strut_left_disp_m",
    "strut_right_disp_m",
    "p_c_pa",
    "p_r_pa",
    "yaw_rate_front_deg_s",
    "cab_accel_x_m_s2",
    "cab_accel_y_m_s2",
    "cab_accel_z_m_s2",
    "front_pitch_accel_rad_s2",
    "front_lateral_accel_m_s2",
    "rear_lateral_accel_m_s2",
    "rear_ltr",
    "rear_roll_deg",
    "hps_travel_left_m",
    "hps_travel_right_m",
    "normal_force_front_left_n",
    "normal_force_front_right_n",
    "normal_force_rear_left_n",
    "normal_force_rear_right_n",
    "drive_torque_n_m",
];

/// The channels of a written record of the vehicle with the rear bogie: those of
/// [`RECORD_CHANNELS`] with the six tires' normal forces ([`crate::model::TANDEM_TIRE_NAMES`]).
pub const TANDEM_RECORD_CHANNELS: [&str; 26] = [
    "time_s",
    "steer_wheel_deg",
    "speed_m_s",
    "articulation_deg",
    "strut_left_disp_m",
    "strut_right_disp_m",
    "p_c_pa",
    "p_r_pa",
    "yaw_rate_front_deg_s",
    "cab_accel_x_m_s2",
    "cab_accel_y_m_s2",
    "cab_accel_z_m_s2",
    "front_pitch_accel_rad_s2",
    "front_lateral_accel_m_s2",
    "rear_lateral_accel_m_s2",
    "rear_ltr",
    "rear_roll_deg",
    "hps_travel_left_m",
    "hps_travel_right_m",
    "normal_force_front_left_n",
    "normal_force_front_right_n",
    "normal_force_rear_left_lead_n",
    "normal_force_rear_right_lead_n",
    "normal_force_rear_left_trail_n",
    "normal_force_rear_right_trail_n",
    "drive_torque_n_m",
];

impl RunRecord {
    /// Channel `name` in the `afsv-v1` convention, or `None` for a name the vehicle does not
    /// record. Besides [`RECORD_CHANNELS`] the front unit's roll and yaw accelerations
    /// (`front_roll_accel_rad_s2`, `front_yaw_accel_rad_s2`) are available, which a
    /// written record leaves out.
    pub fn afsv_v1_channel(&self, name: &str) -> Option<Vec<f64>> {
        let deg = |v: &[f64], sign: f64| v.iter().map(|x| sign * x.to_degrees()).collect();
        let copy = |v: &[f64]| v.to_vec();
        Some(match name {
            "time_s" => copy(&self.t_s),
            "steer_wheel_deg" => deg(&self.steer_wheel_rad, 1.0),
            "speed_m_s" => copy(&self.speed_m_s),
            "articulation_deg" => deg(&self.articulation_rad, 1.0),
            "strut_left_disp_m" => copy(&self.strut_disp_m[0]),
            "strut_right_disp_m" => copy(&self.strut_disp_m[1]),
            "p_c_pa" => copy(&self.pressure_pa[0]),
            "p_r_pa" => copy(&self.pressure_pa[1]),
            // The model's yaw rate is left-turn positive about +z; afsv-v1 is right-turn
            // positive.
            "yaw_rate_front_deg_s" => deg(&self.front_rate_rad_s[2], -1.0),
            "cab_accel_x_m_s2" => copy(&self.cab_accel_m_s2[0]),
            "cab_accel_y_m_s2" => copy(&self.cab_accel_m_s2[1]),
            "cab_accel_z_m_s2" => copy(&self.cab_accel_m_s2[2]),
            "front_roll_accel_rad_s2" => copy(&self.front_angular_accel_rad_s2[0]),
            "front_pitch_accel_rad_s2" => copy(&self.front_angular_accel_rad_s2[1]),
            "front_yaw_accel_rad_s2" => copy(&self.front_angular_accel_rad_s2[2]),
            "front_lateral_accel_m_s2" => copy(&self.front_lateral_accel_m_s2),
            "rear_lateral_accel_m_s2" => copy(&self.rear_lateral_accel_m_s2),
            "rear_ltr" => copy(&self.rear_ltr),
            "rear_roll_deg" => deg(&self.rear_roll_rad, 1.0),
            "hps_travel_left_m" => copy(&self.hps_travel_m[0]),
            "hps_travel_right_m" => copy(&self.hps_travel_m[1]),
            "drive_torque_n_m" => copy(&self.drive_torque_n_m),
            other => {
                let tire = other.strip_prefix("normal_force_")?.strip_suffix("_n")?;
                let k = self.tire_names().iter().position(|&t| t == tire)?;
                copy(self.normal_force_n.get(k)?)
            }
        })
    }

    /// The tire names of the record's normal forces: six with the rear bogie, else four.
    fn tire_names(&self) -> &'static [&'static str] {
        crate::model::tire_names(self.normal_force_n.len() == crate::model::MAX_TIRES)
    }

    /// The written channels: [`RECORD_CHANNELS`], or [`TANDEM_RECORD_CHANNELS`] for a run
    /// with the rear bogie.
    pub fn record_channels(&self) -> &'static [&'static str] {
        if self.normal_force_n.len() == crate::model::MAX_TIRES {
            &TANDEM_RECORD_CHANNELS
        } else {
            &RECORD_CHANNELS
        }
    }

    /// Every channel of [`RunRecord::record_channels`], in order, in the `afsv-v1`
    /// convention.
    pub fn afsv_v1_columns(&self) -> Vec<(&'static str, Vec<f64>)> {
        vehicle_run::columns(self.record_channels(), |name| self.afsv_v1_channel(name))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::TIRE_NAMES;

    /// A record whose every channel holds its own distinct value.
    fn record() -> RunRecord {
        let mut k = 0.0;
        let mut next = || {
            k += 1.0;
            vec![k, 2.0 * k]
        };
        RunRecord {
            t_s: next(),
            steer_wheel_rad: next(),
            speed_m_s: next(),
            articulation_rad: next(),
            rear_roll_rad: next(),
            front_rate_rad_s: [next(), next(), next()],
            front_angular_accel_rad_s2: [next(), next(), next()],
            cab_accel_m_s2: [next(), next(), next()],
            front_lateral_accel_m_s2: next(),
            rear_lateral_accel_m_s2: next(),
            rear_ltr: next(),
            rollover_margin_m: next(),
            strut_disp_m: [next(), next()],
            pressure_pa: [next(), next()],
            hps_travel_m: [next(), next()],
            rear_hps_travel_m: [next(), next()],
            normal_force_n: vec![next(), next(), next(), next()],
            drive_torque_n_m: next(),
            position_m: [next(), next()],
            front_axle_m: [next(), next()],
            heading_rad: next(),
            rollover_s: None,
        }
    }

    #[test]
    fn every_written_channel_is_recorded_once_and_in_order() {
        let r = record();
        let columns = r.afsv_v1_columns();
        assert_eq!(columns.len(), RECORD_CHANNELS.len());
        for (k, (name, _)) in columns.iter().enumerate() {
            assert_eq!(*name, RECORD_CHANNELS[k]);
            assert!(!RECORD_CHANNELS[..k].contains(name), "{name} twice");
        }
        for (k, tire) in TIRE_NAMES.iter().enumerate() {
            let name = format!("normal_force_{tire}_n");
            assert_eq!(r.afsv_v1_channel(&name).unwrap(), r.normal_force_n[k]);
        }
        assert_eq!(r.afsv_v1_channel("no_such_channel_m"), None);
    }

    #[test]
    fn angles_are_degrees_and_the_yaw_rate_is_right_turn_positive() {
        let r = record();
        let yaw = r.afsv_v1_channel("yaw_rate_front_deg_s").unwrap();
        assert_eq!(yaw[1], -r.front_rate_rad_s[2][1].to_degrees());
        let theta = r.afsv_v1_channel("articulation_deg").unwrap();
        assert_eq!(theta[0], r.articulation_rad[0].to_degrees());
        let roll = r.afsv_v1_channel("front_roll_accel_rad_s2").unwrap();
        assert_eq!(roll, r.front_angular_accel_rad_s2[0]);
        assert_eq!(
            r.afsv_v1_channel("cab_accel_z_m_s2").unwrap(),
            r.cab_accel_m_s2[2]
        );
    }
}
