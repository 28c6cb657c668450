//! Error tolerances and the weighted RMS error norm of the adaptive methods.

use crate::OdeError;

/// Absolute tolerance: one value for every state, or one per state (in the state's unit).
///
/// Per-state values let a model integrate SI states of very different size (pressures in
/// Pa next to angles in rad): `atol_i = atol * typical_i` with a typical magnitude per state
/// gives the same error norm as integrating `y_i / typical_i` with a scalar `atol`.
#[derive(Debug, Clone, PartialEq)]
pub enum Atol {
    /// The same absolute tolerance for every state.
    Scalar(f64),
    /// One absolute tolerance per state (length must equal the system dimension).
    PerState(Vec<f64>),
}

impl From<f64> for Atol {
    fn from(v: f64) -> Self {
        Atol::Scalar(v)
    }
}

impl From<Vec<f64>> for Atol {
    fn from(v: Vec<f64>) -> Self {
        Atol::PerState(v)
    }
}

impl Atol {
    /// `atol * typical_i` for every state: the tolerance that makes a run on SI states
    /// equivalent to one on the states divided by their typical magnitudes.
    pub fn scaled(atol: f64, typical: impl IntoIterator<Item = f64>) -> Self {
        Atol::PerState(typical.into_iter().map(|s| atol * s).collect())
    }

    /// Write the per-state values for a system of `out.len()` states into `out`, checking
    /// them (positive, finite, right length).
    pub(crate) fn fill(&self, out: &mut [f64]) -> Result<(), OdeError> {
        match self {
            Atol::Scalar(a) => out.fill(*a),
            Atol::PerState(v) => {
                if v.len() != out.len() {
                    return Err(OdeError::InvalidInput(format!(
                        "per-state atol has {} entries, system has {} states",
                        v.len(),
                        out.len()
                    )));
                }
                out.copy_from_slice(v);
            }
        }
        if let Some(i) = out.iter().position(|a| !(a.is_finite() && *a > 0.0)) {
            return Err(OdeError::InvalidInput(format!(
                "atol of state {i} must be positive and finite, got {}",
                out[i]
            )));
        }
        Ok(())
    }
}

/// Weighted RMS norm `sqrt(mean((e_i / (atol_i + rtol*max(|a_i|,|b_i|)))^2))` (HNW I, Eq II.4.11).
#[inline]
pub(crate) fn error_norm(err: &[f64], a: &[f64], b: &[f64], rtol: f64, atol: &[f64]) -> f64 {
    let n = err.len().max(1) as f64;
    let mut s = 0.0;
    for i in 0..err.len() {
        let sk = atol[i] + rtol * a[i].abs().max(b[i].abs());
        let q = err[i] / sk;
        s += q * q;
    }
    (s / n).sqrt()
}
