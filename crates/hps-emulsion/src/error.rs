//! Errors of the strut model.

/// What went wrong building or running a strut model.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum HpsError {
    /// A parameter is out of its physical range (the field is named).
    #[error("invalid strut parameter `{field}` = {value}: {reason}")]
    InvalidParameter {
        /// Field name as in [`crate::StrutParams`] (or the struct it belongs to).
        field: &'static str,
        /// The offending value.
        value: f64,
        /// Why it is rejected.
        reason: &'static str,
    },
    /// The excitation cannot be simulated (empty, unordered, non-finite, beyond the travel).
    #[error("invalid excitation: {0}")]
    InvalidExcitation(String),
    /// The strut left its physical range during a run (a chamber emptied, gas volume vanished).
    #[error("strut left its physical range at t = {t:.4} s: {reason}")]
    OutOfRange {
        /// Simulation time.
        t: f64,
        /// What happened.
        reason: String,
    },
    /// The integrator failed.
    #[error("integration failed: {0}")]
    Integration(#[from] odeint::OdeError),
    /// Identification could not run (bad subset, too few samples, fit failure).
    #[error("identification: {0}")]
    Identification(String),
}

/// Check that `value` is finite and strictly positive.
pub(crate) fn positive(field: &'static str, value: f64) -> Result<(), HpsError> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(HpsError::InvalidParameter {
            field,
            value,
            reason: "must be finite and > 0",
        })
    }
}

/// Check that `value` is finite and not negative.
pub(crate) fn non_negative(field: &'static str, value: f64) -> Result<(), HpsError> {
    if value.is_finite() && value >= 0.0 {
        Ok(())
    } else {
        Err(HpsError::InvalidParameter {
            field,
            value,
            reason: "must be finite and >= 0",
        })
    }
}
