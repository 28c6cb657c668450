//! The constrained problem the design optimisers share: minimise `f(x)` over a box
//! `lower <= x <= upper` subject to `c_j(x) <= 0`. The solvers work on the box scaled to the
//! unit cube (`u = (x - lower) / (upper - lower)`), so that one mesh size, one difference
//! step and one mutation width fit every variable whatever its unit.

use serde::{Deserialize, Serialize};

/// Objective value of a point that could not be evaluated or that violates a constraint in
/// an extreme-barrier method. Finite (unlike infinity) so that states holding it round-trip
/// through JSON.
pub const BARRIER: f64 = f64::MAX;

/// Why a solver could not start or run.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum OptimizeError {
    /// A setting or input is out of its range; names the field.
    #[error("invalid `{field}`: {reason}")]
    Invalid {
        /// Name of the setting or input.
        field: &'static str,
        /// What it must satisfy.
        reason: String,
    },
    /// A checkpoint does not belong to this problem or these settings.
    #[error("checkpoint does not match: {0}")]
    Checkpoint(String),
}

/// `Err(Invalid)` naming `field` unless `ok`.
pub(crate) fn require(ok: bool, field: &'static str, reason: &str) -> Result<(), OptimizeError> {
    if ok {
        Ok(())
    } else {
        Err(OptimizeError::Invalid {
            field,
            reason: reason.to_string(),
        })
    }
}

/// A box of finite bounds with `lower < upper` in every coordinate.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Bounds {
    lower: Vec<f64>,
    upper: Vec<f64>,
}

impl Bounds {
    /// Bounds of equal, non-zero length, finite, with `lower[i] < upper[i]`.
    pub fn new(lower: Vec<f64>, upper: Vec<f64>) -> Result<Self, OptimizeError> {
        require(!lower.is_empty(), "bounds", "at least one variable")?;
        require(
            lower.len() == upper.len(),
            "bounds",
            "lower and upper must have the same length",
        )?;
        for (l, u) in lower.iter().zip(&upper) {
            require(
                l.is_finite() && u.is_finite() && l < u,
                "bounds",
                "every bound finite and lower < upper",
            )?;
        }
        Ok(Self { lower, upper })
    }

    /// Number of variables.
    pub fn dim(&self) -> usize {
        self.lower.len()
    }

    /// Lower bounds.
    pub fn lower(&self) -> &[f64] {
        &self.lower
    }

    /// Upper bounds.
    pub fn upper(&self) -> &[f64] {
        &self.upper
    }

    /// `x` scaled to the unit cube.
    pub fn to_unit(&self, x: &[f64]) -> Vec<f64> {
        x.iter()
            .zip(self.lower.iter().zip(&self.upper))
            .map(|(x, (l, u))| (x - l) / (u - l))
            .collect()
    }

    /// The point of unit coordinates `u` (each clamped to [0, 1] first, so the result lies
    /// inside the bounds).
    pub fn from_unit(&self, u: &[f64]) -> Vec<f64> {
        u.iter()
            .zip(self.lower.iter().zip(&self.upper))
            .map(|(u, (l, h))| l + u.clamp(0.0, 1.0) * (h - l))
            .collect()
    }
}

/// Objective value and constraint values of one point; the point is feasible when every
/// `constraints[j] <= 0`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Evaluation {
    /// Objective value.
    pub f: f64,
    /// Constraint values `c_j(x)`, feasible where `<= 0`.
    pub constraints: Vec<f64>,
}

impl Evaluation {
    /// A point that could not be evaluated (e.g. its simulation diverged): objective and
    /// every constraint at [`BARRIER`], worse than any evaluated point.
    pub fn failed(n_constraints: usize) -> Self {
        Self {
            f: BARRIER,
            constraints: vec![BARRIER; n_constraints],
        }
    }

    /// Total constraint violation `sum_j max(0, c_j)` (0 when feasible; [`BARRIER`] for a
    /// failed point or a non-finite value).
    pub fn violation(&self) -> f64 {
        let mut v = 0.0;
        for c in &self.constraints {
            if !c.is_finite() || *c >= BARRIER {
                return BARRIER;
            }
            v += c.max(0.0);
        }
        if self.f.is_finite() && self.f < BARRIER {
            v
        } else {
            BARRIER
        }
    }

    /// Whether every constraint holds and the objective is finite.
    pub fn is_feasible(&self) -> bool {
        self.violation() == 0.0
    }

    /// The objective under an extreme barrier: `f` if feasible, else [`BARRIER`].
    pub fn barrier_value(&self) -> f64 {
        if self.is_feasible() {
            self.f
        } else {
            BARRIER
        }
    }

    /// Deb's feasibility rules (Deb 2000): a feasible point beats an infeasible one, two
    /// feasible points compare by objective, two infeasible ones by total violation.
    /// `Less` means `self` is better.
    pub fn deb_cmp(&self, other: &Evaluation) -> std::cmp::Ordering {
        let (va, vb) = (self.violation(), other.violation());
        match (va == 0.0, vb == 0.0) {
            (true, true) => self.f.total_cmp(&other.f),
            (true, false) => std::cmp::Ordering::Less,
            (false, true) => std::cmp::Ordering::Greater,
            (false, false) => va.total_cmp(&vb),
        }
    }
}

/// A box-constrained problem with inequality constraints `c_j(x) <= 0`. `evaluate` must be
/// a pure function of `x` (the solvers evaluate in parallel and rely on the same point
/// giving the same bytes).
pub trait ConstrainedProblem: Sync {
    /// The box.
    fn bounds(&self) -> &Bounds;
    /// Number of inequality constraints.
    fn n_constraints(&self) -> usize;
    /// Objective and constraints at `x` (inside the bounds), a function of `x`: the same
    /// point gives the same evaluation, and the genetic algorithm reuses a known design's
    /// ([`crate::ga::GeneticAlgorithm::step`]). A point that cannot be evaluated returns
    /// [`Evaluation::failed`].
    fn evaluate(&self, x: &[f64]) -> Evaluation;
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cmp::Ordering;

    #[test]
    fn bounds_scale_and_validate() {
        let b = Bounds::new(vec![0.0, -2.0], vec![10.0, 2.0]).unwrap();
        assert_eq!(b.to_unit(&[5.0, 1.0]), vec![0.5, 0.75]);
        assert_eq!(b.from_unit(&[0.5, 0.75]), vec![5.0, 1.0]);
        assert_eq!(b.from_unit(&[1.5, -0.1]), vec![10.0, -2.0]);
        assert!(Bounds::new(vec![1.0], vec![1.0]).is_err());
        assert!(Bounds::new(vec![0.0, 0.0], vec![1.0]).is_err());
        assert!(Bounds::new(vec![f64::NAN], vec![1.0]).is_err());
        assert!(Bounds::new(vec![], vec![]).is_err());
    }

    #[test]
    fn deb_rules_order_points() {
        let e = |f: f64, c: f64| Evaluation {
            f,
            constraints: vec![c],
        };
        assert_eq!(e(5.0, -1.0).deb_cmp(&e(1.0, 0.1)), Ordering::Less);
        assert_eq!(e(1.0, 0.1).deb_cmp(&e(5.0, -1.0)), Ordering::Greater);
        assert_eq!(e(1.0, -1.0).deb_cmp(&e(2.0, 0.0)), Ordering::Less);
        assert_eq!(e(9.0, 0.1).deb_cmp(&e(1.0, 0.2)), Ordering::Less);
        let failed = Evaluation::failed(1);
        assert_eq!(e(1e300, 1e300).deb_cmp(&failed), Ordering::Less);
        assert_eq!(failed.barrier_value(), BARRIER);
        assert_eq!(e(3.0, -1.0).barrier_value(), 3.0);
        assert_eq!(e(3.0, 1.0).barrier_value(), BARRIER);
        assert!(!e(f64::NAN, -1.0).is_feasible());
    }
}
