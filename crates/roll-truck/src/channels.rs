//! A run's record channels in the toolkit's record convention `afsv-v1` (docs/records.md):
//! the one place that names the truck's channels. `afsv roll simulate -o` and the Python
//! package's `simulate_truck` both read a [`RunRecord`] through it. The truck's channels
//! are recorded in SI and in `afsv-v1`'s signs already; the flags `on_bump_stop` and
//! `airborne` become 0 or 1.

use crate::simulate::RunRecord;

/// The channels of a written record, in column order.
pub const RECORD_CHANNELS: [&str; 18] = [
    "time_s",
    "steer_rad",
    "speed_m_s",
    "lateral_accel_m_s2",
    "ltr",
    "sprung_lateral_accel_m_s2",
    "sprung_sensor_lateral_accel_m_s2",
    "roll_rad",
    "rollover_margin_m",
    "drive_force_n",
    "on_bump_stop",
    "airborne",
    "normal_force_front_left_n",
    "normal_force_front_right_n",
    "normal_force_rear_left_outer_n",
    "normal_force_rear_left_inner_n",
    "normal_force_rear_right_inner_n",
    "normal_force_rear_right_outer_n",
];

impl RunRecord {
    /// Channel `name` of [`RECORD_CHANNELS`], or `None` for a name the truck does not
    /// record.
    pub fn afsv_v1_channel(&self, name: &str) -> Option<Vec<f64>> {
        let copy = |v: &[f64]| v.to_vec();
        let flag = |v: &[bool]| v.iter().map(|b| f64::from(u8::from(*b))).collect();
        Some(match name {
            "time_s" => copy(&self.t_s),
            "steer_rad" => copy(&self.steer_rad),
            "speed_m_s" => copy(&self.speed_m_s),
            "lateral_accel_m_s2" => copy(&self.lateral_accel_m_s2),
            "ltr" => copy(&self.ltr),
            "sprung_lateral_accel_m_s2" => copy(&self.sprung_lateral_accel_m_s2),
            "sprung_sensor_lateral_accel_m_s2" => copy(&self.sprung_sensor_lateral_accel_m_s2),
            "roll_rad" => copy(&self.roll_rad),
            "rollover_margin_m" => copy(&self.rollover_margin_m),
            "drive_force_n" => copy(&self.drive_force_n),
            "on_bump_stop" => flag(&self.on_bump_stop),
            "airborne" => flag(&self.airborne),
            "normal_force_front_left_n" => copy(&self.normal_force_n[0]),
            "normal_force_front_right_n" => copy(&self.normal_force_n[1]),
            "normal_force_rear_left_outer_n" => copy(&self.normal_force_n[2]),
            "normal_force_rear_left_inner_n" => copy(&self.normal_force_n[3]),
            "normal_force_rear_right_inner_n" => copy(&self.normal_force_n[4]),
            "normal_force_rear_right_outer_n" => copy(&self.normal_force_n[5]),
            _ => return None,
        })
    }

    /// Every channel of [`RECORD_CHANNELS`], in order, in the `afsv-v1` convention.
    pub fn afsv_v1_columns(&self) -> Vec<(&'static str, Vec<f64>)> {
        vehicle_run::columns(&RECORD_CHANNELS, |name| self.afsv_v1_channel(name))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::TIRE_NAMES;

    #[test]
    fn every_written_channel_is_recorded_once_in_order_with_flags_as_numbers() {
        let v = |k: f64| vec![k, 2.0 * k];
        let r = RunRecord {
            t_s: v(1.0),
            steer_rad: v(2.0),
            speed_m_s: v(3.0),
            lateral_accel_m_s2: v(4.0),
            ltr: v(5.0),
            airborne: vec![false, true],
            sprung_lateral_accel_m_s2: v(6.0),
            sprung_sensor_lateral_accel_m_s2: v(7.0),
            roll_rad: v(8.0),
            rollover_margin_m: v(9.0),
            drive_force_n: v(10.0),
            on_bump_stop: vec![true, false],
            normal_force_n: [v(11.0), v(12.0), v(13.0), v(14.0), v(15.0), v(16.0)],
            rollover_s: None,
        };
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
        assert_eq!(r.afsv_v1_channel("on_bump_stop").unwrap(), [1.0, 0.0]);
        assert_eq!(r.afsv_v1_channel("airborne").unwrap(), [0.0, 1.0]);
        assert_eq!(r.afsv_v1_channel("roll_deg"), None);
    }
}
