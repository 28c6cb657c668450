//! The strut-space AFS as a [`Component`] of the component layer: the view a 3-D vehicle
//! has (Chapter 6), which computes both struts' lengths from its mount points.
//!
//! States are SI with the typical magnitudes that set their absolute tolerances: P_c and
//! P_r about 1 MPa, theta_h and (with [`crate::ValveLag`]) the lagged spool x_v about 1 rad.

use crate::strut_space::{StrutInput, StrutOutput};
use crate::system::AfsSystem;
use vehicle_components::{ChannelInfo, Component, StateInfo};

/// The states in order; the fourth only with the valve-lag extension. The typical
/// magnitudes of the first three are [`AfsSystem::STATE_TYPICAL`].
const STATES: [StateInfo; 4] = [
    StateInfo::new("p_c_pa", "Pa", AfsSystem::STATE_TYPICAL[0]),
    StateInfo::new("p_r_pa", "Pa", AfsSystem::STATE_TYPICAL[1]),
    StateInfo::new("theta_h_rad", "rad", AfsSystem::STATE_TYPICAL[2]),
    StateInfo::new("valve_spool_rad", "rad", 1.0),
];

/// The record channels [`Component::record`] writes.
const CHANNELS: [ChannelInfo; 10] = [
    ChannelInfo::new("strut_left_force_n", "N"),
    ChannelInfo::new("strut_right_force_n", "N"),
    ChannelInfo::new("p_c_pa", "Pa"),
    ChannelInfo::new("p_r_pa", "Pa"),
    ChannelInfo::new("supply_pressure_pa", "Pa"),
    ChannelInfo::new("q_supply_m3_s", "m³/s"),
    ChannelInfo::new("q_leak_m3_s", "m³/s"),
    ChannelInfo::new("valve_opening", "-"),
    ChannelInfo::new("supply_power_w", "W"),
    ChannelInfo::new("strut_power_w", "W"),
];

impl Component for AfsSystem {
    type Input = StrutInput;
    type Output = StrutOutput;

    fn states(&self) -> &[StateInfo] {
        &STATES[..self.n_states()]
    }

    fn channels(&self) -> &[ChannelInfo] {
        &CHANNELS
    }

    /// Both chamber groups at the standby pressure, valve housing and spool centred. In
    /// strut space there is no joint to balance: the vehicle's statics settle the rest.
    fn initial_state(&self, _input: &StrutInput, state: &mut [f64]) {
        state.fill(0.0);
        state[0] = self.params().standby_pressure_pa;
        state[1] = self.params().standby_pressure_pa;
    }

    #[inline]
    fn evaluate(&self, input: &StrutInput, state: &[f64], d_state: &mut [f64]) -> StrutOutput {
        self.strut_derivatives(input, state, d_state)
    }

    fn record(&self, o: &StrutOutput, row: &mut [f64]) {
        row[0] = o.force_left;
        row[1] = o.force_right;
        row[2] = o.p_c;
        row[3] = o.p_r;
        row[4] = o.supply_pressure;
        row[5] = o.q_supply;
        row[6] = o.q_leak;
        row[7] = o.valve_opening;
        row[8] = o.supply_power;
        row[9] = o.strut_power;
    }
}
