//! Errors of the tire crate: every invalid parameter is named.

/// What is wrong with a tire parameter or table.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TireError {
    /// A scalar parameter is out of its valid range (or NaN / infinite).
    #[error("invalid tire parameter `{field}` = {value}: {reason}")]
    InvalidParameter {
        /// Name of the parameter (as in [`crate::TireParams`] or the constructor).
        field: &'static str,
        /// The offending value.
        value: f64,
        /// What the value must satisfy.
        reason: &'static str,
    },
    /// A lookup table is malformed (too short, not increasing, non-finite entries).
    #[error("invalid table `{table}`: {reason}")]
    InvalidTable {
        /// Name of the table.
        table: &'static str,
        /// What is wrong, with the row index where applicable.
        reason: String,
    },
}

/// Require `value` finite and strictly positive.
pub(crate) fn positive(field: &'static str, value: f64) -> Result<f64, TireError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(TireError::InvalidParameter {
            field,
            value,
            reason: "must be finite and > 0",
        })
    }
}

/// Require `value` finite and non-negative.
pub(crate) fn non_negative(field: &'static str, value: f64) -> Result<f64, TireError> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(TireError::InvalidParameter {
            field,
            value,
            reason: "must be finite and >= 0",
        })
    }
}

/// Require `value` finite.
pub(crate) fn finite(field: &'static str, value: f64) -> Result<f64, TireError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(TireError::InvalidParameter {
            field,
            value,
            reason: "must be finite",
        })
    }
}
