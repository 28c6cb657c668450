//! [`afs_hydraulics::AfsSystem`] as the articulation actuator of the yaw-plane model.
//!
//! States P_c, P_r (Pa) are integrated in MPa (scale 1e-6) and theta_h in rad, so a single
//! absolute tolerance of 1e-8 suits every state of the coupled model. With the valve-lag
//! extension a fourth state, the lagged spool displacement x_v (rad, starts centred), follows.

use crate::yaw_plane::actuator::{ActuatorOutput, SteeringActuator};
use afs_hydraulics::{AfsInput, AfsSystem};

const NAMES: [&str; 4] = ["p_c_pa", "p_r_pa", "theta_h_rad", "valve_spool_rad"];

impl SteeringActuator for AfsSystem {
    fn n_states(&self) -> usize {
        AfsSystem::n_states(self)
    }
    fn state_scale(&self, i: usize) -> f64 {
        AfsSystem::STATE_SCALE.get(i).map_or(1.0, |s| 1.0 / s)
    }
    fn state_name(&self, i: usize) -> &'static str {
        NAMES[i]
    }
    fn initial_state(&self, theta: f64, out: &mut [f64]) {
        out.fill(0.0);
        out[..AfsSystem::N_STATES].copy_from_slice(&AfsSystem::initial_state(self, theta));
    }
    #[inline]
    fn evaluate(
        &self,
        theta: f64,
        theta_dot: f64,
        steer_wheel: f64,
        state: &[f64],
        dstate: &mut [f64],
    ) -> ActuatorOutput {
        let o = self.derivatives(
            &AfsInput {
                theta,
                theta_dot,
                steer_wheel,
            },
            state,
            dstate,
        );
        ActuatorOutput {
            torque: o.torque,
            p_c: o.p_c,
            p_r: o.p_r,
            strut_left_disp: o.strut_left_disp,
            q_supply: o.q_supply,
            supply_power: o.supply_power,
            supply_pressure: o.supply_pressure,
        }
    }
    fn energy(&self, theta: f64, _steer_wheel: f64, state: &[f64]) -> f64 {
        self.hydraulic_energy(theta, state)
    }
    fn supply_pressure(&self) -> f64 {
        self.params().supply_pressure_pa
    }
}
