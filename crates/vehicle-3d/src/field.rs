//! Hooks for mechanisms the paper's 3-D model lacks but section 6.3 suspects behind its field
//! discrepancies, switched on through [`crate::VehicleOptions::field`] (all off by default,
//! which is the paper's model):
//!
//! - a time-varying speed setpoint of the PI drive ([`SpeedSetpoint`]): the driver's throttle
//!   as a longitudinal excitation, where the paper's drive holds one speed;
//! - the HPS strut's extensions ([`hps_emulsion::HpsExtensions`]), e.g. the gas heat
//!   transfer of section 5.4.2 (a gas-temperature state) on the vehicle's struts (front,
//!   and rear when the rear axle is suspended).
//!
//! The discovery adapter of the 3-D vehicle (`afsv_discovery::vehicle3d`) uses them.

use hps_emulsion::HpsExtensions;

use crate::error::{finite, rejected, VehicleError};

/// A speed setpoint over time (m/s), linearly interpolated between its samples and held
/// beyond them. Times must increase.
#[derive(Debug, Clone, PartialEq)]
pub struct SpeedSetpoint {
    time_s: Vec<f64>,
    speed_m_s: Vec<f64>,
}

impl SpeedSetpoint {
    /// A setpoint from samples; refuses empty, mismatched, non-finite or non-increasing
    /// times and non-finite speeds.
    pub fn new(time_s: Vec<f64>, speed_m_s: Vec<f64>) -> Result<Self, VehicleError> {
        if time_s.is_empty() || time_s.len() != speed_m_s.len() {
            return Err(rejected(
                "speed_setpoint",
                time_s.len() as f64,
                "needs as many speeds as times, at least one",
            ));
        }
        for (t, v) in time_s.iter().zip(&speed_m_s) {
            finite("speed_setpoint.time_s", *t)?;
            finite("speed_setpoint.speed_m_s", *v)?;
        }
        if time_s.windows(2).any(|w| w[1] <= w[0]) {
            return Err(rejected(
                "speed_setpoint.time_s",
                f64::NAN,
                "times must increase",
            ));
        }
        Ok(Self { time_s, speed_m_s })
    }

    /// The setpoint at `t` (allocation free: a binary search and one interpolation).
    pub fn at(&self, t: f64) -> f64 {
        let (ts, vs) = (&self.time_s, &self.speed_m_s);
        let i = ts.partition_point(|&x| x <= t);
        if i == 0 {
            return vs[0];
        }
        if i == ts.len() {
            return vs[i - 1];
        }
        let w = (t - ts[i - 1]) / (ts[i] - ts[i - 1]);
        vs[i - 1] + w * (vs[i] - vs[i - 1])
    }
}

/// The switchable field mechanisms of a run (module docs); the default is the paper's model.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct FieldEffects {
    /// Speed setpoint of the PI drive over time; `None` holds `VehicleOptions::speed_m_s`.
    pub speed_setpoint: Option<SpeedSetpoint>,
    /// Extensions of every HPS strut: both front struts (with `FrontAxle::Suspended`) and
    /// both rear struts (with `VehicleParams::rear_hps`).
    pub hps: HpsExtensions,
}

impl FieldEffects {
    /// The PI drive's target at `t`: the setpoint's value, else `hold_m_s`.
    pub fn target_speed(&self, t: f64, hold_m_s: f64) -> f64 {
        self.speed_setpoint.as_ref().map_or(hold_m_s, |s| s.at(t))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_setpoint_interpolates_and_holds_its_ends() {
        let s = SpeedSetpoint::new(vec![0.0, 1.0, 3.0], vec![5.0, 6.0, 4.0]).unwrap();
        assert_eq!(s.at(-1.0), 5.0);
        assert_eq!(s.at(0.5), 5.5);
        assert_eq!(s.at(2.0), 5.0);
        assert_eq!(s.at(9.0), 4.0);
        let f = FieldEffects::default();
        assert_eq!(f.target_speed(1.0, 7.0), 7.0);
        assert!(SpeedSetpoint::new(vec![0.0, 0.0], vec![1.0, 1.0]).is_err());
        assert!(SpeedSetpoint::new(vec![0.0], vec![]).is_err());
        assert!(SpeedSetpoint::new(vec![0.0], vec![f64::NAN]).is_err());
    }
}
