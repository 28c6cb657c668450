//! The narrow interface between the vehicle and its articulation actuator.
//!
//! The yaw-plane model only needs, from the steering system: its own states and their
//! derivatives for a given articulation angle/rate and steering-wheel angle, the torque
//! about the joint, and a few outputs for the record. [`afs_hydraulics::AfsSystem`]
//! implements it (module `afs_coupling`); [`EquivalentTorsion`] is the classical
//! torsional spring-damper idealisation the literature uses (section 3.1), handy as a
//! reference and for checking the mechanics alone.

/// Largest number of actuator states the model reserves stack space for.
pub const MAX_ACTUATOR_STATES: usize = 8;

/// What the actuator reports at one instant (SI units).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ActuatorOutput {
    /// Torque about the articulation joint (N m), positive drives theta positive.
    pub torque: f64,
    /// Pressure of the P_c chamber group (Pa, absolute).
    pub p_c: f64,
    /// Pressure of the P_r chamber group (Pa, absolute).
    pub p_r: f64,
    /// Left-strut displacement from its initial length (m), positive extending.
    pub strut_left_disp: f64,
    /// Flow from the supply into the struts (m^3/s).
    pub q_supply: f64,
    /// Supply power P_s q (W).
    pub supply_power: f64,
    /// Supply pressure at the valve inlet (Pa).
    pub supply_pressure: f64,
}

/// An articulation actuator with its own first-order states.
pub trait SteeringActuator {
    /// Number of states (at most [`MAX_ACTUATOR_STATES`]).
    fn n_states(&self) -> usize;
    /// Typical magnitude of state `i` in its SI unit (e.g. `1e6` Pa for a chamber
    /// pressure): the model integrates SI states and gives state `i` the absolute tolerance
    /// `atol * state_typical(i)` (`odeint::Atol::scaled`).
    fn state_typical(&self, i: usize) -> f64;
    /// Record column name of state `i`, ending in its SI unit (e.g. `p_c_pa`).
    fn state_name(&self, i: usize) -> &'static str;
    /// Equilibrium state at articulation angle `theta` with the valve centred (SI).
    fn initial_state(&self, theta: f64, out: &mut [f64]);
    /// Derivatives of the SI state and the outputs. Must not allocate.
    fn evaluate(
        &self,
        theta: f64,
        theta_dot: f64,
        steer_wheel: f64,
        state: &[f64],
        dstate: &mut [f64],
    ) -> ActuatorOutput;
    /// Stored (potential) energy of the actuator (J), for energy checks.
    fn energy(&self, theta: f64, steer_wheel: f64, state: &[f64]) -> f64;
    /// Supply pressure used in the power efficiency, Eq 4.7 (Pa).
    fn supply_pressure(&self) -> f64;
}

/// Equivalent torsional spring and damper at the joint: `T = -k (theta - g delta_sw) - c dtheta/dt`
/// with steering ratio `g` (articulation per steering-wheel angle). No states.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EquivalentTorsion {
    /// Torsional stiffness k (N m/rad).
    pub stiffness: f64,
    /// Torsional damping c (N m s/rad).
    pub damping: f64,
    /// Articulation per steering-wheel angle g (-).
    pub steer_ratio: f64,
}

impl SteeringActuator for EquivalentTorsion {
    fn n_states(&self) -> usize {
        0
    }
    fn state_typical(&self, _i: usize) -> f64 {
        1.0
    }
    fn state_name(&self, _i: usize) -> &'static str {
        ""
    }
    fn initial_state(&self, _theta: f64, _out: &mut [f64]) {}
    fn evaluate(
        &self,
        theta: f64,
        theta_dot: f64,
        steer_wheel: f64,
        _state: &[f64],
        _dstate: &mut [f64],
    ) -> ActuatorOutput {
        ActuatorOutput {
            torque: -self.stiffness * (theta - self.steer_ratio * steer_wheel)
                - self.damping * theta_dot,
            ..ActuatorOutput::default()
        }
    }
    fn energy(&self, theta: f64, steer_wheel: f64, _state: &[f64]) -> f64 {
        let d = theta - self.steer_ratio * steer_wheel;
        0.5 * self.stiffness * d * d
    }
    fn supply_pressure(&self) -> f64 {
        0.0
    }
}
