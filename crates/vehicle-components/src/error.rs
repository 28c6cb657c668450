//! Errors of the component layer: every invalid value is named.

/// What is wrong with a terrain, a state layout or a recorder.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ComponentError {
    /// A scalar parameter is out of its valid range (or NaN / infinite).
    #[error("invalid parameter `{field}` = {value}: {reason}")]
    InvalidParameter {
        /// Name of the parameter.
        field: &'static str,
        /// The offending value.
        value: f64,
        /// What the value must satisfy.
        reason: &'static str,
    },
    /// A state or channel name is empty, not `[a-z0-9_]`, or used twice.
    #[error("invalid name `{name}`: {reason}")]
    InvalidName {
        /// The offending name.
        name: String,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// A requested size exceeds its bound (checked before anything is allocated).
    #[error("{what} = {requested} exceeds the limit of {limit}")]
    TooLarge {
        /// What was asked for (e.g. `recorder rows`).
        what: &'static str,
        /// The size asked for.
        requested: usize,
        /// The largest size accepted.
        limit: usize,
    },
    /// A row has the wrong number of values for the declared channels.
    #[error("row has {given} values but {expected} channels are declared")]
    RowLength {
        /// Declared channel count.
        expected: usize,
        /// Values given.
        given: usize,
    },
    /// The recorder already holds as many rows as its capacity.
    #[error("recorder is full: capacity of {capacity} rows reached")]
    Full {
        /// The capacity fixed at construction.
        capacity: usize,
    },
}

/// What is wrong with a get or set by name on a parameter set.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ParamError {
    /// The set has no parameter of that name.
    #[error("unknown parameter `{name}` in the {set} set (known: {known})")]
    Unknown {
        /// Name of the parameter set (e.g. `tire`).
        set: &'static str,
        /// The name asked for.
        name: String,
        /// The known names, comma-separated.
        known: String,
    },
    /// The value is NaN or outside the parameter's `[lower, upper]`.
    #[error("parameter `{name}` = {value} is outside [{lower}, {upper}] {unit}")]
    OutOfBounds {
        /// Parameter name.
        name: &'static str,
        /// The value given.
        value: f64,
        /// Lower bound (inclusive).
        lower: f64,
        /// Upper bound (inclusive).
        upper: f64,
        /// Unit of the bounds.
        unit: &'static str,
    },
    /// The value is within bounds but the set's own validation refuses the result (e.g.
    /// a sliding friction above the peak friction); the set is left unchanged.
    #[error("parameter `{name}` = {value} rejected: {reason}")]
    Rejected {
        /// Parameter name.
        name: &'static str,
        /// The value given.
        value: f64,
        /// The set's validation message.
        reason: String,
    },
    /// A parameter specification is malformed (bounds inverted or not finite, typical
    /// magnitude not finite and > 0, duplicate name).
    #[error("invalid specification of parameter `{name}`: {reason}")]
    Spec {
        /// Parameter name.
        name: &'static str,
        /// What is wrong.
        reason: &'static str,
    },
}

/// Require `value` finite and non-negative.
pub(crate) fn non_negative(field: &'static str, value: f64) -> Result<f64, ComponentError> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(ComponentError::InvalidParameter {
            field,
            value,
            reason: "must be finite and >= 0",
        })
    }
}

/// Require `value` finite.
pub(crate) fn finite(field: &'static str, value: f64) -> Result<f64, ComponentError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(ComponentError::InvalidParameter {
            field,
            value,
            reason: "must be finite",
        })
    }
}

/// Check a state or channel name: non-empty, only `[a-z0-9_]`, starting with a letter.
pub(crate) fn check_name(name: &str) -> Result<(), ComponentError> {
    let bad = |reason| {
        Err(ComponentError::InvalidName {
            name: name.to_string(),
            reason,
        })
    };
    match name.chars().next() {
        None => return bad("must not be empty"),
        Some(c) if !c.is_ascii_lowercase() => return bad("must start with a letter a-z"),
        Some(_) => {}
    }
    if !name
        .chars()
        .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
    {
        return bad("may only hold a-z, 0-9 and _");
    }
    Ok(())
}
