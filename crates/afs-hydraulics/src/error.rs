//! Error type of the crate.

/// Why a parameter set or extension set was rejected.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum AfsError {
    /// A single field is out of its physical range (or NaN / infinite).
    #[error("invalid AFS parameter `{field}` = {value}: {reason}")]
    InvalidParameter {
        /// Name of the offending field (as in the serde/JSON representation).
        field: &'static str,
        /// The rejected value.
        value: f64,
        /// What the field must satisfy.
        reason: &'static str,
    },
    /// Two fields are individually valid but inconsistent with each other.
    #[error(
        "inconsistent AFS parameters `{field}` = {value} and `{other}` = {other_value}: {reason}"
    )]
    Inconsistent {
        /// The field reported as wrong.
        field: &'static str,
        /// Its value.
        value: f64,
        /// The field it conflicts with.
        other: &'static str,
        /// That field's value.
        other_value: f64,
        /// The rule that is violated.
        reason: &'static str,
    },
}

/// Check that `value` is finite and satisfies `ok`; otherwise name the field.
pub(crate) fn check(
    field: &'static str,
    value: f64,
    ok: bool,
    reason: &'static str,
) -> Result<(), AfsError> {
    if value.is_finite() && ok {
        Ok(())
    } else {
        Err(AfsError::InvalidParameter {
            field,
            value,
            reason: if value.is_finite() {
                reason
            } else {
                "must be a finite number"
            },
        })
    }
}
