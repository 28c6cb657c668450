//! The component contract, generalised from the yaw-plane model's steering-actuator seam:
//! a subsystem with its own first-order states, evaluated as a pure function
//! `(input, state) -> (d_state, output)` that the vehicle's integrator calls.
//!
//! This is the plain-data counterpart of Chrono::Vehicle's subsystem templates (`ChTire`,
//! `ChSuspension`): instead of `Synchronize` / `Advance` with hidden state, the component
//! declares its states ([`StateInfo`]) and record channels ([`ChannelInfo`]), and the
//! vehicle owns the state vector (see [`crate::StateLayout`]) and the record
//! (see [`crate::Recorder`]).

use crate::error::{check_name, ComponentError};

/// One state of a component: record name ending in its unit (e.g. `p_c_pa`), the SI unit as
/// written in documents (e.g. `Pa`) and a typical magnitude (in that unit, > 0) that sets the
/// absolute tolerance or scaling of the integrated variable.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StateInfo {
    /// Name with unit suffix, `[a-z0-9_]`, starting with a letter.
    pub name: &'static str,
    /// SI unit (`-` for dimensionless).
    pub unit: &'static str,
    /// Typical magnitude (> 0, finite), in `unit`.
    pub typical: f64,
}

impl StateInfo {
    /// A state description (checked by [`StateInfo::check`] when a layout is built).
    pub const fn new(name: &'static str, unit: &'static str, typical: f64) -> Self {
        Self {
            name,
            unit,
            typical,
        }
    }

    /// The name is a valid record name, the unit is not empty, the typical magnitude is
    /// finite and > 0.
    pub fn check(&self) -> Result<(), ComponentError> {
        check_name(self.name)?;
        if self.unit.is_empty() {
            return Err(ComponentError::InvalidName {
                name: self.name.to_string(),
                reason: "the unit must not be empty (use `-` for dimensionless)",
            });
        }
        if !(self.typical.is_finite() && self.typical > 0.0) {
            return Err(ComponentError::InvalidParameter {
                field: "typical",
                value: self.typical,
                reason: "typical magnitude must be finite and > 0",
            });
        }
        Ok(())
    }
}

/// One record channel of a component's output: name ending in its unit (e.g.
/// `torque_n_m`) and the SI unit as written in documents (e.g. `N m`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ChannelInfo {
    /// Name with unit suffix, `[a-z0-9_]`, starting with a letter.
    pub name: &'static str,
    /// SI unit (`-` for dimensionless).
    pub unit: &'static str,
}

impl ChannelInfo {
    /// A channel description.
    pub const fn new(name: &'static str, unit: &'static str) -> Self {
        Self { name, unit }
    }
}

/// A subsystem with first-order states, evaluated without side effects.
///
/// Contract: `states().len()` is fixed for the life of the value; `initial_state` and
/// `evaluate` get slices of exactly that length; `record` gets a row of exactly
/// `channels().len()` values; `evaluate` and `record` do not allocate and return finite
/// numbers for finite inputs and states.
pub trait Component {
    /// What the vehicle gives the component at one instant (positions, rates, commands).
    type Input;
    /// What the component gives back (forces, torques, quantities to record).
    type Output;

    /// The states, in the order of the state slice.
    fn states(&self) -> &[StateInfo];

    /// The output channels [`Component::record`] writes, in order.
    fn channels(&self) -> &[ChannelInfo];

    /// Initial (equilibrium) state for `input`, written into `state`.
    fn initial_state(&self, input: &Self::Input, state: &mut [f64]);

    /// State derivatives into `d_state` and the output, for `input` and `state`.
    fn evaluate(&self, input: &Self::Input, state: &[f64], d_state: &mut [f64]) -> Self::Output;

    /// Write the record channels of `output` into `row`.
    fn record(&self, output: &Self::Output, row: &mut [f64]);

    /// Number of states.
    fn n_states(&self) -> usize {
        self.states().len()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A first-order lag `dx/dt = (u - x) / tau` with output `x`, to exercise the contract.
    struct Lag {
        tau: f64,
    }

    const LAG_STATES: [StateInfo; 1] = [StateInfo::new("x_m", "m", 0.1)];
    const LAG_CHANNELS: [ChannelInfo; 2] = [
        ChannelInfo::new("x_m", "m"),
        ChannelInfo::new("x_rate_m_per_s", "m/s"),
    ];

    impl Component for Lag {
        type Input = f64;
        type Output = (f64, f64);
        fn states(&self) -> &[StateInfo] {
            &LAG_STATES
        }
        fn channels(&self) -> &[ChannelInfo] {
            &LAG_CHANNELS
        }
        fn initial_state(&self, input: &f64, state: &mut [f64]) {
            state[0] = *input;
        }
        fn evaluate(&self, input: &f64, state: &[f64], d_state: &mut [f64]) -> (f64, f64) {
            d_state[0] = (input - state[0]) / self.tau;
            (state[0], d_state[0])
        }
        fn record(&self, output: &(f64, f64), row: &mut [f64]) {
            row[0] = output.0;
            row[1] = output.1;
        }
    }

    #[test]
    fn a_component_is_at_rest_in_its_initial_state() {
        let lag = Lag { tau: 0.5 };
        assert_eq!(lag.n_states(), 1);
        let mut x = [0.0];
        lag.initial_state(&2.0, &mut x);
        let mut dx = [1.0];
        let out = lag.evaluate(&2.0, &x, &mut dx);
        assert_eq!(dx, [0.0]);
        assert_eq!(out, (2.0, 0.0));
        let out = lag.evaluate(&3.0, &x, &mut dx);
        assert_eq!(dx, [2.0]);
        let mut row = [0.0; 2];
        lag.record(&out, &mut row);
        assert_eq!(row, [2.0, 2.0]);
    }

    #[test]
    fn state_info_is_checked() {
        assert!(StateInfo::new("p_c_pa", "Pa", 1e6).check().is_ok());
        assert!(StateInfo::new("", "Pa", 1e6).check().is_err());
        assert!(StateInfo::new("P_c", "Pa", 1e6).check().is_err());
        assert!(StateInfo::new("p c", "Pa", 1e6).check().is_err());
        assert!(StateInfo::new("p_c_pa", "", 1e6).check().is_err());
        assert!(StateInfo::new("p_c_pa", "Pa", 0.0).check().is_err());
        assert!(StateInfo::new("p_c_pa", "Pa", f64::NAN).check().is_err());
    }
}
