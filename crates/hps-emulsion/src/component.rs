//! The strut as a [`Component`] of the component layer: what a vehicle model (Chapter 6)
//! embeds at each suspension corner. Input: the strut deflection and its rate, which the
//! vehicle computes from its mount points; output: the strut force and the quantities a
//! record keeps. States, typical magnitudes and equations are those of [`HpsStrut`].

use crate::strut::{HpsStrut, StrutOutputs};
use vehicle_components::{ChannelInfo, Component, StateInfo};

/// What a vehicle gives the strut at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StrutMotion {
    /// Deflection z_s (m, positive in compression, from the static mid-stroke position).
    pub deflection_m: f64,
    /// Deflection rate z_s' (m/s, positive compressing).
    pub velocity_m_s: f64,
}

/// The record channels [`Component::record`] writes, in the order of the fields of
/// [`StrutOutputs`].
const CHANNELS: [ChannelInfo; 8] = [
    ChannelInfo::new("force_n", "N"),
    ChannelInfo::new("p_piston_pa", "Pa"),
    ChannelInfo::new("p_rod_pa", "Pa"),
    ChannelInfo::new("friction_n", "N"),
    ChannelInfo::new("spring_force_n", "N"),
    ChannelInfo::new("gas_volume_m3", "m³"),
    ChannelInfo::new("flow_m3_s", "m³/s"),
    ChannelInfo::new("velocity_amplitude_m_s", "m/s"),
];

impl Component for HpsStrut {
    type Input = StrutMotion;
    type Output = StrutOutputs;

    fn states(&self) -> &[StateInfo] {
        HpsStrut::states(self)
    }

    fn channels(&self) -> &[ChannelInfo] {
        &CHANNELS
    }

    /// Static equilibrium at the input's deflection (clamped to the travel), with the
    /// velocity amplitude at the input's speed. A deflection within the validated travel
    /// always has an equilibrium (the free gas covers the stroke); should the search still
    /// fail, the reference state (`z_s = 0` at `P_h0`) is written, which is the equilibrium
    /// at mid-stroke.
    fn initial_state(&self, input: &StrutMotion, state: &mut [f64]) {
        let travel = self.params().travel;
        let z = input.deflection_m.clamp(-travel, travel);
        let u0 = input.velocity_m_s.abs();
        let u0 = if u0.is_finite() { u0 } else { 0.0 };
        if self.initial_state_at(z, u0, state).is_err() {
            self.reference_state(state);
        }
    }

    #[inline]
    fn evaluate(&self, input: &StrutMotion, state: &[f64], d_state: &mut [f64]) -> StrutOutputs {
        HpsStrut::evaluate(self, input.deflection_m, input.velocity_m_s, state, d_state)
    }

    fn record(&self, o: &StrutOutputs, row: &mut [f64]) {
        row[0] = o.force;
        row[1] = o.p_piston;
        row[2] = o.p_rod;
        row[3] = o.friction;
        row[4] = o.spring_force;
        row[5] = o.gas_volume;
        row[6] = o.flow;
        row[7] = o.velocity_amplitude;
    }
}
