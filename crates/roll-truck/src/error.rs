//! Errors of the truck model, its runs and its studies.

/// What went wrong building, running or measuring the truck. Every variant names its cause.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TruckError {
    /// A parameter is out of its physical range (the field is named as in
    /// [`crate::TruckParams`] or the options struct it belongs to).
    #[error("invalid truck parameter `{field}` = {value}: {reason}")]
    InvalidParameter {
        /// Field name.
        field: &'static str,
        /// The offending value.
        value: f64,
        /// Why it is rejected.
        reason: &'static str,
    },
    /// The multibody tree could not be built.
    #[error("multibody model: {0}")]
    Model(#[from] multibody::ModelError),
    /// The multibody dynamics failed (e.g. a mass matrix that is not positive definite).
    #[error("multibody dynamics at t = {t:.4} s: {source}")]
    Dynamics {
        /// Simulation time.
        t: f64,
        /// The failure.
        source: multibody::DynamicsError,
    },
    /// The integrator failed (divergence carries time and state).
    #[error("integration failed: {0}")]
    Integration(#[from] odeint::OdeError),
    /// The terrain could not be built.
    #[error("terrain: {0}")]
    Terrain(#[from] terrain_psd::TerrainError),
    /// A tire component could not be built.
    #[error("tire: {0}")]
    Tire(#[from] tire_fiala::TireError),
    /// A roll measure could not be computed from the run.
    #[error("roll measure `{measure}`: {source}")]
    Measure {
        /// Which measure.
        measure: &'static str,
        /// Why.
        source: perf_measures::MeasureError,
    },
}

/// `value` if finite and > 0, else [`TruckError::InvalidParameter`] naming `field`.
pub(crate) fn positive(field: &'static str, value: f64) -> Result<f64, TruckError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(TruckError::InvalidParameter {
            field,
            value,
            reason: "must be finite and > 0",
        })
    }
}

/// `value` if finite and >= 0, else [`TruckError::InvalidParameter`] naming `field`.
pub(crate) fn non_negative(field: &'static str, value: f64) -> Result<f64, TruckError> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(TruckError::InvalidParameter {
            field,
            value,
            reason: "must be finite and >= 0",
        })
    }
}

/// [`TruckError::InvalidParameter`] for a relation between fields.
pub(crate) fn rejected(field: &'static str, value: f64, reason: &'static str) -> TruckError {
    TruckError::InvalidParameter {
        field,
        value,
        reason,
    }
}
