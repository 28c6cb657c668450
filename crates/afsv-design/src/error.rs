//! Errors of the design layer.

/// Why a design, a set of measures or a weighting was rejected. Every variant names the
/// offending field or matrix.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DesignError {
    /// A scalar is out of its range or not finite.
    #[error("invalid `{field}` = {value}: {reason}")]
    Invalid {
        /// Name of the field.
        field: &'static str,
        /// The rejected value.
        value: f64,
        /// What the field must satisfy.
        reason: &'static str,
    },
    /// A vector or matrix has the wrong shape.
    #[error("`{field}`: {reason}")]
    Shape {
        /// Name of the vector or matrix.
        field: &'static str,
        /// What is wrong with its shape.
        reason: String,
    },
    /// The AHP weights of one comparison matrix could not be computed.
    #[error("AHP matrix `{matrix}`: {source}")]
    Ahp {
        /// Which matrix (e.g. `M2`, `M3/A(1)`).
        matrix: String,
        /// Cause.
        source: optimize::ahp::AhpError,
    },
    /// The AFS parameter set a design produced is not valid.
    #[error("design applied to the AFS parameters: {0}")]
    Afs(#[from] afs_hydraulics::AfsError),
    /// A design could not be simulated (the measures could not be computed).
    #[error("simulation: {0}")]
    Simulation(String),
    /// The strut parameter set a design produced is not valid.
    #[error("design applied to the strut parameters: {0}")]
    Hps(#[from] hps_emulsion::HpsError),
}

/// `value` if it is finite and strictly positive, else an error naming `field`.
pub(crate) fn positive(field: &'static str, value: f64) -> Result<f64, DesignError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(DesignError::Invalid {
            field,
            value,
            reason: "must be finite and > 0",
        })
    }
}

/// `value` if it is finite and not negative, else an error naming `field`.
pub(crate) fn non_negative(field: &'static str, value: f64) -> Result<f64, DesignError> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(DesignError::Invalid {
            field,
            value,
            reason: "must be finite and >= 0",
        })
    }
}
