//! Errors of the terrain-psd crate. Every invalid input is reported as a value of
//! [`TerrainError`] naming the offending field; nothing in this crate panics on bad input.

/// What went wrong building a model, synthesizing a profile or estimating a spectrum.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TerrainError {
    /// A numeric parameter is NaN, infinite or out of its range.
    #[error("{name} = {value} is invalid: {requirement}")]
    Parameter {
        /// Field or argument name (e.g. `alpha_r`, `band.n_min`).
        name: &'static str,
        /// Value given.
        value: f64,
        /// What the value must satisfy.
        requirement: String,
    },
    /// The spatial band is empty or inverted.
    #[error(
        "band [{n_min}, {n_max}] cycles/m is invalid: n_min must be positive and less than n_max"
    )]
    Band {
        /// Lower spatial frequency (cycles/m).
        n_min: f64,
        /// Upper spatial frequency (cycles/m).
        n_max: f64,
    },
    /// A name (ISO class, terrain, coherence model, ...) is not recognised.
    #[error("unknown {what} `{given}` (expected one of: {expected})")]
    Unknown {
        /// Kind of name.
        what: &'static str,
        /// Text given.
        given: String,
        /// Accepted values.
        expected: &'static str,
    },
    /// A text could not be read as the value asked for.
    #[error("cannot read {what} from `{given}`: expected {expected}")]
    Syntax {
        /// Kind of value.
        what: &'static str,
        /// Text given.
        given: String,
        /// Accepted form.
        expected: &'static str,
    },
    /// A value a model needs was not given.
    #[error("{what} needs {needs}")]
    Missing {
        /// Model or operation.
        what: &'static str,
        /// What must be supplied.
        needs: &'static str,
    },
    /// A signal given to an estimator is unusable (too short, lengths differ, non-finite).
    #[error("{0}")]
    Signal(String),
    /// A text file (an OpenCRG road) is malformed or asks for what is not supported, at a
    /// line and column counted from 1.
    #[error("line {line} column {column}: {message}")]
    File {
        /// Line of the file (from 1).
        line: usize,
        /// Column of the line (from 1).
        column: usize,
        /// What is wrong there.
        message: String,
    },
}

/// Result alias of this crate.
pub type Result<T> = std::result::Result<T, TerrainError>;

/// Check that `value` is finite and strictly positive.
pub(crate) fn positive(name: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(TerrainError::Parameter {
            name,
            value,
            requirement: "must be a finite number > 0".into(),
        })
    }
}

/// Check that `value` is finite and non-negative.
pub(crate) fn non_negative(name: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(TerrainError::Parameter {
            name,
            value,
            requirement: "must be a finite number >= 0".into(),
        })
    }
}
