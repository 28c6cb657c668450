//! The driver of section 2.3: a ramp steering-wheel input (L648) through a constant
//! steering ratio, and a PI controller on the rear drive force that holds the speed at
//! 40 km/h (L522). The ramp rate and the steering ratio are not given in chapter 2; the
//! defaults (5 deg/s at the steering wheel, ratio 25) follow note 1.5.

use serde::{Deserialize, Serialize};

use crate::params::TruckParams;

/// Which way the ramp steers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SteerDirection {
    /// Positive road-wheel angle: a left turn, rolling to the right.
    Left,
    /// Negative road-wheel angle: a right turn, rolling to the left.
    Right,
    /// No steering (straight run).
    Straight,
}

impl std::fmt::Display for SteerDirection {
    /// `left`, `right` or `straight`, as in a parameter file.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::Left => "left",
            Self::Right => "right",
            Self::Straight => "straight",
        })
    }
}

impl SteerDirection {
    /// +1, -1 or 0.
    pub fn sign(self) -> f64 {
        match self {
            SteerDirection::Left => 1.0,
            SteerDirection::Right => -1.0,
            SteerDirection::Straight => 0.0,
        }
    }
}

impl std::str::FromStr for SteerDirection {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "left" => Ok(Self::Left),
            "right" => Ok(Self::Right),
            "straight" => Ok(Self::Straight),
            _ => Err(format!(
                "unknown steer direction `{s}` (left, right, straight)"
            )),
        }
    }
}

/// Ramp steer: road-wheel angle `delta(t) = sign * rate * max(t - t_0, 0)` (rad).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RampSteer {
    /// Road-wheel rate with its sign (rad/s).
    pub rate_rad_s: f64,
    /// Ramp start t_0 (s), a breakpoint of the run.
    pub start_s: f64,
}

impl RampSteer {
    /// From the parameters and the direction.
    pub fn new(p: &TruckParams, direction: SteerDirection) -> Self {
        Self {
            rate_rad_s: direction.sign() * p.road_wheel_rate_rad_s(),
            start_s: p.ramp_start_s,
        }
    }

    /// Road-wheel angle at `t` (rad), both front wheels alike (no Ackermann).
    #[inline]
    pub fn angle(&self, t: f64) -> f64 {
        self.rate_rad_s * (t - self.start_s).max(0.0)
    }
}

/// PI speed control on the rear drive force: `F = K_p e + K_i integral(e)`,
/// `e = v_target - v_x` (N); the integral is a state of the vehicle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpeedController {
    /// Target speed (m/s).
    pub target_m_s: f64,
    /// K_p (N per m/s).
    pub kp: f64,
    /// K_i (N per m).
    pub ki: f64,
}

impl SpeedController {
    /// From the parameters.
    pub fn new(p: &TruckParams) -> Self {
        Self {
            target_m_s: p.target_speed_m_s,
            kp: p.speed_kp_n_per_m_s,
            ki: p.speed_ki_n_per_m,
        }
    }

    /// Speed error e (m/s) at forward speed `v_x`: the integrator's derivative.
    #[inline]
    pub fn error(&self, v_x: f64) -> f64 {
        self.target_m_s - v_x
    }

    /// Drive force (N) at forward speed `v_x` and error integral `integral` (m).
    #[inline]
    pub fn force(&self, v_x: f64, integral: f64) -> f64 {
        self.kp * self.error(v_x) + self.ki * integral
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn directions_print_as_their_file_names() {
        for d in [
            SteerDirection::Left,
            SteerDirection::Right,
            SteerDirection::Straight,
        ] {
            assert_eq!(serde_json::to_value(d).unwrap(), d.to_string());
        }
    }

    #[test]
    fn ramp_is_zero_before_the_start_and_mirrors() {
        let p = TruckParams::nominal();
        let l = RampSteer::new(&p, SteerDirection::Left);
        let r = RampSteer::new(&p, SteerDirection::Right);
        assert_eq!(l.angle(1.0), 0.0);
        // 5 deg/s at the wheel over ratio 25 is 0.2 deg/s at the road wheel
        assert!((l.angle(12.0).to_degrees() - 2.0).abs() < 1e-12);
        assert_eq!(r.angle(12.0), -l.angle(12.0));
        assert!("sideways".parse::<SteerDirection>().is_err());
    }
}
