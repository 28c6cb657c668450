//! Path-following driver for the field courses of Fig 3.6 (section 3.4.1), shared by the
//! vehicle models (the yaw-plane model of `afsv-dynamics`, the V3 path change of `vehicle-3d`).
//!
//! Pure pursuit on the front-axle centre: the look-ahead point lies on the course a
//! preview distance `L_d = max(min_preview, preview_time * u)` ahead of the projection of
//! the front axle; its bearing `eta` from the front-unit heading gives the path curvature
//! `kappa = 2 sin(eta) / L_d`. The articulation angle that makes the front axle follow
//! curvature `kappa` in a slip-free steady turn solves `sin(theta) = kappa (a cos(theta) + b)`
//! (a = front axle to joint, b = joint to rear axle), i.e.
//! `theta_d = atan(kappa a) + asin(kappa b / sqrt(1 + kappa^2 a^2))`.
//! A volume-regulated steering system integrates the wheel angle into articulation, so the
//! driver turns the wheel at a rate proportional to the articulation error,
//! `d(theta_sw)/dt = clamp(K (theta_d - theta), +-rate_max)`: this also corrects the slow
//! leakage drift (section 3.4.1) the way a driver does.

use crate::inputs::InputError;
use serde::{Deserialize, Serialize};

/// A course, laid out in the ground frame (x along the approach, y to the right): the
/// front axle starts at `(-approach_m, 0)` heading along +x.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Course {
    /// Straight approach, then a circle of `radius_m` tangent at the origin (Fig 3.6a:
    /// 13.5 m). Positive radius turns right, negative left.
    SteadyTurn {
        /// Signed turn radius (m).
        radius_m: f64,
        /// Approach length (m).
        approach_m: f64,
    },
    /// Straight approach, then a lateral offset over a gate length with a half-cosine
    /// transition, then straight (Fig 3.6b: 4.5 m offset, 18 m gate). Positive offset is
    /// to the right.
    PathChange {
        /// Signed lateral offset (m).
        offset_m: f64,
        /// Longitudinal length of the transition (m).
        gate_m: f64,
        /// Approach length (m).
        approach_m: f64,
    },
}

impl Course {
    /// Fig 3.6(a): 13.5 m radius right-hand steady turn after a 20 m approach.
    pub fn steady_turn_fig_3_6() -> Self {
        Course::SteadyTurn {
            radius_m: 13.5,
            approach_m: 20.0,
        }
    }

    /// Fig 3.6(b): 4.5 m offset to the right over an 18 m gate after a 20 m approach.
    pub fn path_change_fig_3_6() -> Self {
        Course::PathChange {
            offset_m: 4.5,
            gate_m: 18.0,
            approach_m: 20.0,
        }
    }

    fn validate(&self) -> Result<(), InputError> {
        let ok = match *self {
            Course::SteadyTurn {
                radius_m,
                approach_m,
            } => {
                radius_m.is_finite()
                    && radius_m.abs() > 0.5
                    && approach_m.is_finite()
                    && approach_m >= 0.0
            }
            Course::PathChange {
                offset_m,
                gate_m,
                approach_m,
            } => {
                offset_m.is_finite()
                    && gate_m.is_finite()
                    && gate_m > 0.0
                    && approach_m.is_finite()
                    && approach_m >= 0.0
            }
        };
        if ok {
            Ok(())
        } else {
            Err(InputError(format!(
                "course {self:?}: radius must exceed 0.5 m, gate be positive, approach >= 0"
            )))
        }
    }

    /// Start position of the front axle (m).
    pub fn start(&self) -> (f64, f64) {
        match *self {
            Course::SteadyTurn { approach_m, .. } | Course::PathChange { approach_m, .. } => {
                (-approach_m, 0.0)
            }
        }
    }

    /// Whether a vehicle at `x` with unwrapped heading `psi` is still on the approach
    /// straight of a steady turn (after the first quarter lap it is on the circle).
    #[inline]
    fn on_approach(x: f64, psi: f64, side: f64) -> bool {
        x < 0.0 && psi * side < std::f64::consts::FRAC_PI_2
    }

    /// Look-ahead point `preview` ahead (along the course) of the point closest to `(x, y)`;
    /// `psi` is the vehicle's unwrapped heading (it tells the approach straight from the
    /// last quarter of each lap).
    #[inline]
    pub fn lookahead(&self, x: f64, y: f64, psi: f64, preview: f64) -> (f64, f64) {
        match *self {
            Course::SteadyTurn { radius_m, .. } => {
                let r = radius_m.abs();
                let side = radius_m.signum();
                // Work in the right-turn frame (mirror y for a left turn).
                let ym = y * side;
                let s = if Self::on_approach(x, psi, side) {
                    x
                } else {
                    let phi = x.atan2(r - ym);
                    let phi = if phi < 0.0 {
                        phi + std::f64::consts::TAU
                    } else {
                        phi
                    };
                    r * phi
                };
                let sl = s + preview;
                let (px, py) = if sl <= 0.0 {
                    (sl, 0.0)
                } else {
                    let phi = sl / r;
                    (r * phi.sin(), r * (1.0 - phi.cos()))
                };
                (px, py * side)
            }
            Course::PathChange {
                offset_m, gate_m, ..
            } => {
                let px = x + preview;
                let py = if px <= 0.0 {
                    0.0
                } else if px >= gate_m {
                    offset_m
                } else {
                    0.5 * offset_m * (1.0 - (std::f64::consts::PI * px / gate_m).cos())
                };
                (px, py)
            }
        }
    }

    /// Lateral deviation of `(x, y)` (unwrapped heading `psi`) from the course (m);
    /// for the steady turn positive towards the centre.
    pub fn deviation(&self, x: f64, y: f64, psi: f64) -> f64 {
        match *self {
            Course::SteadyTurn { radius_m, .. } => {
                let r = radius_m.abs();
                let side = radius_m.signum();
                let ym = y * side;
                if Self::on_approach(x, psi, side) {
                    y
                } else {
                    // Inside the circle (towards the centre) is the turning side.
                    let d = (x * x + (r - ym) * (r - ym)).sqrt();
                    (r - d) * side
                }
            }
            Course::PathChange {
                offset_m, gate_m, ..
            } => {
                let yc = if x <= 0.0 {
                    0.0
                } else if x >= gate_m {
                    offset_m
                } else {
                    0.5 * offset_m * (1.0 - (std::f64::consts::PI * x / gate_m).cos())
                };
                y - yc
            }
        }
    }
}

/// Pure-pursuit driver with a rate-controlled steering wheel.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct PathDriver {
    /// Course to follow.
    pub course: Course,
    /// Preview time (s).
    pub preview_time_s: f64,
    /// Minimum preview distance (m).
    pub min_preview_m: f64,
    /// Wheel-rate gain K (rad/s of steering wheel per rad of articulation error).
    pub rate_gain_per_s: f64,
    /// Steering-wheel rate limit (rad/s).
    pub max_rate_rad_s: f64,
}

impl PathDriver {
    /// Driver with default settings (preview 1.2 s but at least 4 m, K = 40 1/s, rate
    /// limit 2 turns/s) on `course`. The settings were chosen by a sweep over the six
    /// Fig 3.6 / Table 3.2 cases (docs/afs-yaw-plane.md).
    pub fn new(course: Course) -> Self {
        Self {
            course,
            preview_time_s: 1.2,
            min_preview_m: 4.0,
            rate_gain_per_s: 40.0,
            max_rate_rad_s: 4.0 * std::f64::consts::PI,
        }
    }

    /// Check the settings.
    pub fn validate(&self) -> Result<(), InputError> {
        self.course.validate()?;
        for (name, v) in [
            ("preview_time_s", self.preview_time_s),
            ("min_preview_m", self.min_preview_m),
            ("rate_gain_per_s", self.rate_gain_per_s),
            ("max_rate_rad_s", self.max_rate_rad_s),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Err(InputError(format!(
                    "driver `{name}` must be positive and finite, got {v}"
                )));
            }
        }
        Ok(())
    }

    /// Desired articulation angle (rad) for a front axle at `(x, y)` with front-unit
    /// heading `psi`, speed `u`, front axle-to-joint `a` and joint-to-rear-axle `b`.
    #[inline]
    pub fn desired_articulation(&self, x: f64, y: f64, psi: f64, u: f64, a: f64, b: f64) -> f64 {
        let ld = (self.preview_time_s * u).max(self.min_preview_m);
        let (px, py) = self.course.lookahead(x, y, psi, ld);
        let (dx, dy) = (px - x, py - y);
        let eta = dy.atan2(dx) - psi;
        let eta =
            (eta + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI;
        let dist = (dx * dx + dy * dy).sqrt().max(1e-6);
        let kappa = 2.0 * eta.sin() / dist;
        let ka = kappa * a;
        let arg = (kappa * b / (1.0 + ka * ka).sqrt()).clamp(-1.0, 1.0);
        ka.atan() + arg.asin()
    }

    /// Steering-wheel rate (rad/s) for the articulation error.
    #[inline]
    pub fn wheel_rate(&self, theta_desired: f64, theta: f64) -> f64 {
        (self.rate_gain_per_s * (theta_desired - theta))
            .clamp(-self.max_rate_rad_s, self.max_rate_rad_s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kinematic_articulation_matches_turn_radius() {
        // On the circle, heading tangent: desired theta must satisfy R_f = (a cos + b)/sin.
        let d = PathDriver::new(Course::SteadyTurn {
            radius_m: 13.5,
            approach_m: 0.0,
        });
        let (a, b) = (1.68, 3.44);
        let phi: f64 = 1.0;
        let (x, y) = (13.5 * phi.sin(), 13.5 * (1.0 - phi.cos()));
        let th = d.desired_articulation(x, y, phi, 4.0, a, b);
        let r = (a * th.cos() + b) / th.sin();
        assert!(
            (r - 13.5).abs() < 0.05,
            "R = {r}, theta = {}",
            th.to_degrees()
        );
        // Mirror course and pose: mirrored answer.
        let dl = PathDriver::new(Course::SteadyTurn {
            radius_m: -13.5,
            approach_m: 0.0,
        });
        let thl = dl.desired_articulation(x, -y, -phi, 4.0, a, b);
        assert!((th + thl).abs() < 1e-12);
    }

    #[test]
    fn path_change_geometry() {
        let c = Course::path_change_fig_3_6();
        assert_eq!(c.lookahead(-10.0, 0.0, 0.0, 4.0), (-6.0, 0.0));
        let (_, y) = c.lookahead(5.0, 0.0, 0.0, 4.0);
        assert!((y - 2.25).abs() < 1e-12);
        assert!((c.deviation(30.0, 4.0, 0.0) + 0.5).abs() < 1e-12);
        let d = PathDriver::new(c);
        // On the straight, aligned: no articulation demand.
        assert_eq!(
            d.desired_articulation(-30.0, 0.0, 0.0, 5.0, 1.68, 3.44),
            0.0
        );
        assert!(d.wheel_rate(1.0, 0.0) <= d.max_rate_rad_s);
    }
}
