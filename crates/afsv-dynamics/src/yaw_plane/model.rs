//! The coupled yaw-plane vehicle + steering-actuator system as an [`odeint::OdeSystem`].
//!
//! State vector (integrated variables; SI unless noted):
//!
//! | index | name | unit | equation |
//! |---|---|---|---|
//! | 0 | articulation angle theta | rad | Eq 3.14 (dtheta/dt = phi_f - phi_r) |
//! | 1 | front lateral velocity v_f | m/s | Eq 3.13 row 1 (solved jointly) |
//! | 2 | front yaw rate phi_f | rad/s | Eq 3.13 row 2 |
//! | 3 | rear yaw rate phi_r | rad/s | Eq 3.13 row 3 |
//! | 4, 5 | ground position of the front cg x, y | m | kinematics |
//! | 6 | front-unit heading psi_f | rad | d(psi_f)/dt = phi_f |
//! | 7..11 | lagged slip angles alpha_1..alpha_4 (only if sigma_y > 0) | rad | Eq 3.16 |
//! | next | steering-wheel angle (only with a path-following driver) | rad | driver law |
//! | rest | actuator states in SI (AFS: p_c, p_r in Pa, theta_h in rad) | | Eqs 3.4-3.12 |
//!
//! Every state is SI; [`YawPlaneModel::state_typical`] gives each one's typical magnitude
//! (1 in rad, m/s, m; the actuator's own, e.g. 1 MPa for a pressure), from which a run
//! builds per-state absolute tolerances.
//!
//! Tire 1/3 are the left tires, 2/4 the right ones; the steady slip angles are Eq 3.17.

use crate::yaw_plane::actuator::{ActuatorOutput, SteeringActuator, MAX_ACTUATOR_STATES};
use crate::yaw_plane::driver::PathDriver;
use crate::yaw_plane::mechanics::{accelerations_with, Accelerations, Loads, Motion, UnitGeometry};
use crate::yaw_plane::params::VehicleParams;
use crate::EquationForm;
use tire_fiala::{slip_lag_rate, LinearCornering};
use vehicle_components::SteerInput;

/// Where the steering-wheel angle comes from.
#[derive(Debug, Clone, PartialEq)]
pub enum SteerSource {
    /// A prescribed time history.
    Open(SteerInput),
    /// A closed-loop path-following driver (its wheel angle is a state).
    Driver(PathDriver),
}

/// Index bookkeeping of the state vector.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Layout {
    /// Number of lagged slip states (0 or 4).
    pub n_slip: usize,
    /// Index of the driver's wheel-angle state.
    pub driver: Option<usize>,
    /// First actuator state.
    pub act0: usize,
    /// Number of actuator states.
    pub n_act: usize,
    /// Total dimension.
    pub dim: usize,
}

/// First slip-angle state.
pub const SLIP0: usize = 7;

/// Everything derived at one (t, y), for the record.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Evaluation {
    /// Steering-wheel angle (rad).
    pub steer_wheel: f64,
    /// Articulation rate (rad/s).
    pub theta_dot: f64,
    /// Slip angles used for the forces (rad).
    pub alpha: [f64; 4],
    /// Actuator outputs.
    pub actuator: ActuatorOutput,
    /// Accelerations and traction force.
    pub acc: Accelerations,
    /// Rear-unit cg velocities (m/s).
    pub u_r: f64,
    /// Rear-unit lateral velocity (m/s).
    pub v_r: f64,
}

/// The coupled system for one manoeuvre.
#[derive(Debug, Clone)]
pub struct YawPlaneModel<'a, A: SteeringActuator> {
    /// Vehicle parameters.
    pub vehicle: &'a VehicleParams,
    /// Articulation actuator.
    pub actuator: &'a A,
    /// Constant forward speed of the front unit u_f (m/s).
    pub speed: f64,
    /// Steering-wheel source.
    pub steer: &'a SteerSource,
    /// Equation form.
    pub form: EquationForm,
    geom: UnitGeometry,
    front_tire: LinearCornering,
    rear_tire: LinearCornering,
    /// Eq 3.16 rate per radian of slip error, |u_f| / sigma_y (speed is constant).
    lag_rate: f64,
    layout: Layout,
}

impl<'a, A: SteeringActuator> YawPlaneModel<'a, A> {
    /// Assemble the model. Parameters are assumed validated by the caller.
    pub fn new(
        vehicle: &'a VehicleParams,
        actuator: &'a A,
        speed: f64,
        steer: &'a SteerSource,
        form: EquationForm,
    ) -> Self {
        let n_slip = if vehicle.relaxation_length_m > 0.0 {
            4
        } else {
            0
        };
        let driver = match steer {
            SteerSource::Driver(_) => Some(SLIP0 + n_slip),
            SteerSource::Open(_) => None,
        };
        let act0 = SLIP0 + n_slip + usize::from(driver.is_some());
        let n_act = actuator.n_states().min(MAX_ACTUATOR_STATES);
        // Fields are public: zero stiffness ("tires off") is allowed here.
        let front_tire = LinearCornering {
            cornering_stiffness: vehicle.c_alpha_f_n_per_rad,
            aligning_coefficient: vehicle.k_mz_f_nm_per_rad,
        };
        let rear_tire = LinearCornering {
            cornering_stiffness: vehicle.c_alpha_r_n_per_rad,
            aligning_coefficient: vehicle.k_mz_r_nm_per_rad,
        };
        Self {
            vehicle,
            actuator,
            speed,
            steer,
            form,
            geom: UnitGeometry::new(vehicle, form),
            front_tire,
            rear_tire,
            lag_rate: slip_lag_rate(0.0, 1.0, speed, vehicle.relaxation_length_m),
            layout: Layout {
                n_slip,
                driver,
                act0,
                n_act,
                dim: act0 + n_act,
            },
        }
    }

    /// State layout.
    pub fn layout(&self) -> Layout {
        self.layout
    }

    /// Name (with SI unit) of every state, in order.
    pub fn state_names(&self) -> Vec<String> {
        let mut v: Vec<String> = [
            "articulation_rad",
            "lateral_velocity_front_m_s",
            "yaw_rate_front_rad_s",
            "yaw_rate_rear_rad_s",
            "x_m",
            "y_m",
            "heading_front_rad",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect();
        for i in 0..self.layout.n_slip {
            v.push(format!("slip_{}_rad", i + 1));
        }
        if self.layout.driver.is_some() {
            v.push("driver_steer_wheel_rad".into());
        }
        for i in 0..self.layout.n_act {
            v.push(self.actuator.state_name(i).to_string());
        }
        v
    }

    /// Initial state: straight running at `theta0` with the actuator at equilibrium and
    /// (for a driver course) the front axle at the course start.
    pub fn initial_state(&self, theta0: f64) -> Vec<f64> {
        let mut y = vec![0.0; self.layout.dim];
        y[0] = theta0;
        if let SteerSource::Driver(d) = self.steer {
            let (xa, ya) = d.course.start();
            y[4] = xa - self.vehicle.l_f1_m;
            y[5] = ya;
        }
        let act = self.actuator_range();
        self.actuator.initial_state(theta0, &mut y[act]);
        y
    }

    /// Typical magnitude of state `i` in its SI unit: 1 for the vehicle states (rad, m/s, m)
    /// and the driver's wheel angle, the actuator's [`SteeringActuator::state_typical`] for
    /// its states. A run's absolute tolerance of state `i` is `atol * state_typical(i)`.
    pub fn state_typical(&self, i: usize) -> f64 {
        if i >= self.layout.act0 {
            self.actuator.state_typical(i - self.layout.act0)
        } else {
            1.0
        }
    }

    /// Indices of the actuator states in the state vector.
    #[inline]
    pub fn actuator_range(&self) -> std::ops::Range<usize> {
        self.layout.act0..self.layout.act0 + self.layout.n_act
    }

    /// Steering-wheel angle at (t, y).
    #[inline]
    pub fn steer_wheel(&self, t: f64, y: &[f64]) -> f64 {
        match (self.steer, self.layout.driver) {
            (SteerSource::Open(inp), _) => inp.angle(t),
            (SteerSource::Driver(_), Some(i)) => y[i],
            (SteerSource::Driver(_), None) => 0.0,
        }
    }

    /// Evaluate the right-hand side and everything derived from it.
    #[inline]
    pub fn evaluate(&self, t: f64, y: &[f64], dydt: &mut [f64]) -> Evaluation {
        let v = self.vehicle;
        let u = self.speed;
        let motion = Motion {
            theta: y[0],
            u_f: u,
            v_f: y[1],
            r_f: y[2],
            r_r: y[3],
        };
        let sc = motion.theta.sin_cos();
        let w = motion.v_f - self.geom.l_f2 * motion.r_f;
        let (u_r, v_r) = (
            u * sc.1 - w * sc.0,
            u * sc.0 + w * sc.1 - self.geom.l_r2 * motion.r_r,
        );
        let tr = v.half_track_m;
        // Eq 3.17: steady slip angles (tires 1,3 left: +T phi in the denominator).
        let vy_f = motion.v_f + v.l_f1_m * motion.r_f;
        let vy_r = v_r - v.l_r1_m * motion.r_r;
        let steady = [
            -vy_f.atan2(u + tr * motion.r_f),
            -vy_f.atan2(u - tr * motion.r_f),
            -vy_r.atan2(u_r + tr * motion.r_r),
            -vy_r.atan2(u_r - tr * motion.r_r),
        ];
        let alpha = if self.layout.n_slip == 4 {
            let mut a = [0.0; 4];
            for i in 0..4 {
                a[i] = y[SLIP0 + i];
                // Eq 3.16 with u_f for all tires (as printed): the lag is linear in the
                // slip error, so its rate factor is computed once per model.
                dydt[SLIP0 + i] = (steady[i] - a[i]) * self.lag_rate;
            }
            a
        } else {
            steady
        };
        let theta_dot = motion.r_f - motion.r_r;
        let steer_wheel = self.steer_wheel(t, y);

        // Actuator, on its slice of the (SI) state vector.
        let act = self.actuator_range();
        let out = self.actuator.evaluate(
            motion.theta,
            theta_dot,
            steer_wheel,
            &y[act.clone()],
            &mut dydt[act],
        );

        // Eq 3.15 forces and moments, summed per axle.
        let loads = Loads {
            y_front: self.front_tire.lateral_force(alpha[0] + alpha[1]),
            y_rear: self.rear_tire.lateral_force(alpha[2] + alpha[3]),
            mz_front: self.front_tire.aligning_moment(alpha[0] + alpha[1]),
            mz_rear: self.rear_tire.aligning_moment(alpha[2] + alpha[3]),
            steering_torque: out.torque,
        };
        let acc = accelerations_with(&self.geom, &motion, sc, (u_r, v_r), &loads);
        dydt[0] = theta_dot;
        dydt[1] = acc.dv_f;
        dydt[2] = acc.dr_f;
        dydt[3] = acc.dr_r;
        let (s, c) = y[6].sin_cos();
        dydt[4] = u * c - motion.v_f * s;
        dydt[5] = u * s + motion.v_f * c;
        dydt[6] = motion.r_f;
        if let (SteerSource::Driver(d), Some(i)) = (self.steer, self.layout.driver) {
            let xa = y[4] + v.l_f1_m * c;
            let ya = y[5] + v.l_f1_m * s;
            let td = d.desired_articulation(
                xa,
                ya,
                y[6],
                u,
                v.front_axle_to_joint(),
                v.joint_to_rear_axle(),
            );
            dydt[i] = d.wheel_rate(td, motion.theta);
        }
        Evaluation {
            steer_wheel,
            theta_dot,
            alpha,
            actuator: out,
            acc,
            u_r,
            v_r,
        }
    }
}

impl<A: SteeringActuator> odeint::OdeSystem for YawPlaneModel<'_, A> {
    fn dim(&self) -> usize {
        self.layout.dim
    }
    #[inline]
    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        self.evaluate(t, y, dydt);
    }
}
