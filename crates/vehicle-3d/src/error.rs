//! Errors of the 3-D vehicle, its runs and its measures.

/// What went wrong building, running or measuring the vehicle. Every variant names its cause.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum VehicleError {
    /// A parameter or option is out of its physical range (the field is named as in
    /// [`crate::VehicleParams`] or the options struct it belongs to).
    #[error("invalid vehicle parameter `{field}` = {value}: {reason}")]
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
    /// The multibody dynamics failed (a mass matrix that is not positive definite).
    #[error("multibody dynamics at t = {t:.4} s: {source}")]
    Dynamics {
        /// Simulation time.
        t: f64,
        /// The failure.
        source: multibody::DynamicsError,
    },
    /// The integrator failed (a divergence carries time and state).
    #[error("integration failed: {0}")]
    Integration(#[from] odeint::OdeError),
    /// The step size collapsed early ([`odeint::OdeError::StepSizeCollapsed`]): `state` is
    /// the name of the state that dominates the error, stiff or with absurd parameters.
    #[error("integration failed: the {state} state is stiff or its parameters absurd: {source}")]
    Stiff {
        /// Name of the dominant state ([`crate::Vehicle::state_name`]).
        state: String,
        /// The integrator's error, with time and state vector.
        source: odeint::OdeError,
    },
    /// The terrain could not be built.
    #[error("terrain: {0}")]
    Terrain(#[from] terrain_psd::TerrainError),
    /// A tire component could not be built.
    #[error("tire: {0}")]
    Tire(#[from] tire_fiala::TireError),
    /// The steering hydraulics could not be built.
    #[error("steering: {0}")]
    Steering(#[from] afs_hydraulics::AfsError),
    /// The front-axle strut could not be built or has no static equilibrium.
    #[error("front-axle HPS: {0}")]
    Suspension(#[from] hps_emulsion::HpsError),
    /// The steering-wheel input is invalid.
    #[error("steering input: {0}")]
    Input(#[from] vehicle_components::InputError),
    /// A measure could not be computed from the run.
    #[error("measure `{measure}`: {reason}")]
    Measure {
        /// Which measure.
        measure: &'static str,
        /// Why.
        reason: String,
    },
}

/// `value` if finite and > 0, else [`VehicleError::InvalidParameter`] naming `field`.
pub(crate) fn positive(field: &'static str, value: f64) -> Result<f64, VehicleError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(rejected(field, value, "must be finite and > 0"))
    }
}

/// `value` if finite and >= 0, else [`VehicleError::InvalidParameter`] naming `field`.
pub(crate) fn non_negative(field: &'static str, value: f64) -> Result<f64, VehicleError> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(rejected(field, value, "must be finite and >= 0"))
    }
}

/// `value` if finite, else [`VehicleError::InvalidParameter`] naming `field`.
pub(crate) fn finite(field: &'static str, value: f64) -> Result<f64, VehicleError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(rejected(field, value, "must be finite"))
    }
}

/// [`VehicleError::InvalidParameter`] for a relation between fields.
pub(crate) fn rejected(field: &'static str, value: f64, reason: &'static str) -> VehicleError {
    VehicleError::InvalidParameter {
        field,
        value,
        reason,
    }
}

/// [`VehicleError::Measure`] with a reason.
pub(crate) fn measure(measure: &'static str, reason: impl std::fmt::Display) -> VehicleError {
    VehicleError::Measure {
        measure,
        reason: reason.to_string(),
    }
}
