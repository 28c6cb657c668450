//! [`afs_hydraulics::AfsSystem`] as the articulation actuator of the yaw-plane model.
//!
//! States P_c, P_r (Pa) and theta_h (rad) are integrated in SI units; their typical
//! magnitudes (1 MPa, 1 MPa, 1 rad, from the AFS component's [`StateInfo`]s) scale the
//! per-state absolute tolerances of the coupled model. With the valve-lag extension a fourth
//! state, the lagged spool displacement x_v (rad, starts centred), follows.
//!
//! [`StateInfo`]: vehicle_components::StateInfo

use crate::yaw_plane::actuator::{ActuatorOutput, SteeringActuator};
use afs_hydraulics::{AfsInput, AfsSystem};
use vehicle_components::Component;

impl SteeringActuator for AfsSystem {
    fn n_states(&self) -> usize {
        AfsSystem::n_states(self)
    }
    fn state_typical(&self, i: usize) -> f64 {
        Component::states(self)[i].typical
    }
    fn state_name(&self, i: usize) -> &'static str {
        Component::states(self)[i].name
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
