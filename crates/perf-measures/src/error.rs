//! Errors of the performance measures.

/// Why a measure could not be computed. Every variant names the offending input.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MeasureError {
    /// A scalar parameter is out of range or not finite.
    #[error("invalid `{field}`: {reason}")]
    Invalid {
        /// Name of the parameter.
        field: &'static str,
        /// What is wrong with it.
        reason: String,
    },
    /// Two series that must be sample-aligned have different lengths.
    #[error("`{a}` has {len_a} samples but `{b}` has {len_b}")]
    LengthMismatch {
        /// First series.
        a: &'static str,
        /// Its length.
        len_a: usize,
        /// Second series.
        b: &'static str,
        /// Its length.
        len_b: usize,
    },
    /// A series is too short for the measure.
    #[error("`{field}` needs at least {needed} samples, got {got}")]
    TooShort {
        /// Name of the series.
        field: &'static str,
        /// Minimum number of samples.
        needed: usize,
        /// Number given.
        got: usize,
    },
    /// A series holds NaN or an infinity.
    #[error("`{field}` is not finite at sample {index}")]
    NonFinite {
        /// Name of the series.
        field: &'static str,
        /// 0-based sample index.
        index: usize,
    },
    /// The time vector is not strictly increasing.
    #[error("time is not strictly increasing at sample {index}")]
    NonMonotonicTime {
        /// 0-based index of the first offending sample.
        index: usize,
    },
    /// The event a measure is defined by does not occur in the record
    /// (e.g. the LTR never reaches the threshold, the response never reaches its steady value).
    #[error("{0}")]
    NotFound(String),
    /// The free-decay fit could not produce a result.
    #[error("free-decay fit failed: {0}")]
    Fit(String),
}

pub(crate) fn invalid(field: &'static str, reason: impl Into<String>) -> MeasureError {
    MeasureError::Invalid {
        field,
        reason: reason.into(),
    }
}

/// Check that `x` is finite; `field` names it in the error.
pub(crate) fn finite_scalar(field: &'static str, x: f64) -> Result<f64, MeasureError> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(invalid(field, format!("{x} is not finite")))
    }
}

/// Check that `x` is finite and strictly positive.
pub(crate) fn positive(field: &'static str, x: f64) -> Result<f64, MeasureError> {
    if x.is_finite() && x > 0.0 {
        Ok(x)
    } else {
        Err(invalid(field, format!("{x} must be finite and > 0")))
    }
}

/// Check that every sample of `x` is finite and that there are at least `needed`.
pub(crate) fn finite_series(
    field: &'static str,
    x: &[f64],
    needed: usize,
) -> Result<(), MeasureError> {
    if x.len() < needed {
        return Err(MeasureError::TooShort {
            field,
            needed,
            got: x.len(),
        });
    }
    match x.iter().position(|v| !v.is_finite()) {
        Some(index) => Err(MeasureError::NonFinite { field, index }),
        None => Ok(()),
    }
}

/// Check equal lengths.
pub(crate) fn same_len(
    a: &'static str,
    xa: &[f64],
    b: &'static str,
    xb: &[f64],
) -> Result<(), MeasureError> {
    if xa.len() == xb.len() {
        Ok(())
    } else {
        Err(MeasureError::LengthMismatch {
            a,
            len_a: xa.len(),
            b,
            len_b: xb.len(),
        })
    }
}

/// Check a time vector: finite, at least `needed` samples, strictly increasing.
pub(crate) fn time_series(t: &[f64], needed: usize) -> Result<(), MeasureError> {
    finite_series("t", t, needed)?;
    match t.windows(2).position(|w| w[1] <= w[0]) {
        Some(i) => Err(MeasureError::NonMonotonicTime { index: i + 1 }),
        None => Ok(()),
    }
}
