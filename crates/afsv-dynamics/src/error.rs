//! Errors of the vehicle models.

/// Why a simulation or analysis could not be carried out.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DynError {
    /// A vehicle parameter is out of range or not finite.
    #[error("invalid vehicle parameter `{field}`: {reason}")]
    Param {
        /// Field name as in the parameter file.
        field: &'static str,
        /// What is wrong with it.
        reason: String,
    },
    /// The steering-system parameters were rejected by the AFS component.
    #[error("invalid steering-system parameters: {0}")]
    Steering(String),
    /// A manoeuvre, input or option is not usable.
    #[error("invalid input: {0}")]
    InvalidInput(String),
    /// The run diverged (solver failure, non-finite state, or an articulation/yaw state
    /// beyond physical bounds): when, why and the named state at that time.
    #[error("simulation diverged at t = {t:.4} s: {reason}; state: {state}")]
    Diverged {
        /// Time (s).
        t: f64,
        /// What was detected.
        reason: String,
        /// `name=value` pairs of the last finite state (SI units).
        state: String,
    },
    /// A performance measure could not be computed from the response.
    #[error("measure `{measure}` failed: {reason}")]
    Measure {
        /// Which measure.
        measure: &'static str,
        /// Why.
        reason: String,
    },
}

impl DynError {
    pub(crate) fn param(field: &'static str, reason: impl Into<String>) -> Self {
        DynError::Param {
            field,
            reason: reason.into(),
        }
    }
}

/// A driver input the component layer rejected is an invalid input of the run (same
/// message).
impl From<vehicle_components::InputError> for DynError {
    fn from(e: vehicle_components::InputError) -> Self {
        DynError::InvalidInput(e.0)
    }
}
