//! The error of a multibody vehicle: a parameter out of range, the model or its dynamics, the
//! integration (with time and state), or a subsystem's own error.

/// Why a vehicle could not be built or run.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RunError {
    /// A parameter or run setting is out of range or not finite.
    #[error("invalid vehicle parameter `{field}` = {value}: {reason}")]
    InvalidParameter {
        /// The field's name.
        field: &'static str,
        /// The value given.
        value: f64,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// The multibody tree could not be built.
    #[error("multibody model: {0}")]
    Model(#[from] multibody::ModelError),
    /// Forward dynamics failed (a singular mass matrix).
    #[error("multibody dynamics at t = {t:.4} s: {source}")]
    Dynamics {
        /// Time (s).
        t: f64,
        /// The core's error.
        source: multibody::DynamicsError,
    },
    /// The integration failed: divergence (with time and state), the step budget, a
    /// collapsing step.
    #[error("integration failed: {0}")]
    Integration(#[from] odeint::OdeError),
    /// The step collapsed on one state: a stiff state or absurd parameters.
    #[error("integration failed: the {state} state is stiff or its parameters absurd: {source}")]
    Stiff {
        /// The dominant state's name.
        state: String,
        /// The integrator's error.
        source: odeint::OdeError,
    },
    /// The terrain could not be built.
    #[error("terrain: {0}")]
    Terrain(#[from] terrain_psd::TerrainError),
    /// A tire parameter set is invalid.
    #[error("tire: {0}")]
    Tire(#[from] tire_fiala::TireError),
    /// The steering system's parameters are invalid.
    #[error("steering: {0}")]
    Steering(#[from] afs_hydraulics::AfsError),
    /// A suspension strut's parameters are invalid.
    #[error("front-axle HPS: {0}")]
    Suspension(#[from] hps_emulsion::HpsError),
    /// The steering input is invalid.
    #[error("steering input: {0}")]
    Input(#[from] vehicle_components::InputError),
    /// The state layout could not be built (a component's state description).
    #[error("state layout: {0}")]
    Layout(#[from] vehicle_components::ComponentError),
    /// A measure could not be computed from the run.
    #[error("measure `{measure}`: {reason}")]
    Measure {
        /// The measure.
        measure: &'static str,
        /// Why.
        reason: String,
    },
}

/// `value` if finite and > 0.
pub fn positive(field: &'static str, value: f64) -> Result<f64, RunError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(rejected(field, value, "must be finite and > 0"))
    }
}

/// `value` if finite and >= 0.
pub fn non_negative(field: &'static str, value: f64) -> Result<f64, RunError> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(rejected(field, value, "must be finite and >= 0"))
    }
}

/// `value` if finite.
pub fn finite(field: &'static str, value: f64) -> Result<f64, RunError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(rejected(field, value, "must be finite"))
    }
}

/// The error of `field` = `value`, refused for `reason`.
pub fn rejected(field: &'static str, value: f64, reason: &'static str) -> RunError {
    RunError::InvalidParameter {
        field,
        value,
        reason,
    }
}

/// The error of a measure that could not be computed.
pub fn measure(measure: &'static str, reason: impl std::fmt::Display) -> RunError {
    RunError::Measure {
        measure,
        reason: reason.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_checks_refuse_what_they_say_and_name_the_field() {
        assert_eq!(positive("rtol", 1e-4), Ok(1e-4));
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            let e = positive("rtol", bad).unwrap_err().to_string();
            assert!(e.contains("`rtol`") && e.contains("> 0"), "{e}");
        }
        assert_eq!(non_negative("mass", 0.0), Ok(0.0));
        assert!(non_negative("mass", -1e-9).is_err());
        assert!(non_negative("mass", f64::NAN).is_err());
        assert_eq!(finite("x", -3.0), Ok(-3.0));
        assert!(finite("x", f64::NEG_INFINITY).is_err());
        let m = measure("drt", "no rollover").to_string();
        assert_eq!(m, "measure `drt`: no rollover");
    }
}
