//! The chapter-4 objective, Eq 4.8: `F(chi) = V . W`, the weighted sum of the measure
//! ratios of a design to the current design, with the AHP weights W of Eq 4.17.

use crate::error::{non_negative, DesignError};
use crate::measures::{Measure, MeasureRatios};
use serde::Serialize;

/// Eq 4.8 with fixed weights: `F = sum_i W_i V_i`; `F = 1` at the current design when the
/// weights sum to 1, and F falls as the design improves.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Objective {
    /// Weights indexed by [`Measure::index`].
    weights: [f64; 6],
}

impl Objective {
    /// An objective with `weights` in the order of [`Measure::ALL`] (e.g. the composite
    /// AHP weights of Eq 4.17). Weights must be finite and non-negative, not all zero.
    pub fn new(weights: [f64; 6]) -> Result<Self, DesignError> {
        for m in Measure::ALL {
            non_negative(m.name(), weights[m.index()])?;
        }
        let sum: f64 = weights.iter().sum();
        if sum <= 0.0 {
            return Err(DesignError::Invalid {
                field: "weights",
                value: sum,
                reason: "must not all be zero",
            });
        }
        Ok(Self { weights })
    }

    /// [`Objective::new`] from a slice (e.g. [`crate::AhpLevels::composite`]), which must
    /// hold six weights.
    pub fn from_slice(weights: &[f64]) -> Result<Self, DesignError> {
        let w: [f64; 6] = weights.try_into().map_err(|_| DesignError::Shape {
            field: "weights",
            reason: format!("expected 6 weights, got {}", weights.len()),
        })?;
        Self::new(w)
    }

    /// Weight of measure `m`.
    pub fn weight(&self, m: Measure) -> f64 {
        self.weights[m.index()]
    }

    /// `F = W . V` (Eq 4.8) for a design with measure ratios `r` to the current design.
    pub fn value(&self, r: &MeasureRatios) -> f64 {
        self.weights
            .iter()
            .zip(r.objective_vector())
            .map(|(w, v)| w * v)
            .sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::measures::DesignMeasures;

    const CURRENT: [f64; 6] = [1.9146, 5.5, 0.3, 0.2, 12.0, 40.0];
    const W: [f64; 6] = [0.0971, 0.3313, 0.2158, 0.1543, 0.1058, 0.0957];

    fn f_of(design: [f64; 6]) -> f64 {
        let cur = DesignMeasures::new(CURRENT).unwrap();
        let des = DesignMeasures::new(design).unwrap();
        Objective::new(W)
            .unwrap()
            .value(&MeasureRatios::new(&des, &cur).unwrap())
    }

    #[test]
    fn current_design_scores_the_weight_sum() {
        let sum: f64 = W.iter().sum();
        assert!((f_of(CURRENT) - sum).abs() < 1e-15);
    }

    #[test]
    fn hand_computed_value() {
        // Half the strut length and twice the frequency, the rest unchanged:
        // F = 0.0971 * 0.5 + 0.3313 * 0.5 + 0.2158 + 0.1543 + 0.1058 + 0.0957.
        let mut d = CURRENT;
        d[0] *= 0.5;
        d[1] *= 2.0;
        let want = 0.5 * (0.0971 + 0.3313) + 0.2158 + 0.1543 + 0.1058 + 0.0957;
        assert!((f_of(d) - want).abs() < 1e-12);
    }

    #[test]
    fn monotone_in_each_measure_as_eq_4_8_says() {
        let f0 = f_of(CURRENT);
        for m in Measure::ALL {
            let mut up = CURRENT;
            up[m.index()] *= 1.1;
            let f = f_of(up);
            if m.larger_is_better() {
                assert!(f < f0, "{}: F must fall when it grows", m.name());
            } else {
                assert!(f > f0, "{}: F must rise when it grows", m.name());
            }
        }
    }

    #[test]
    fn invalid_weights_are_refused() {
        assert!(Objective::new([0.0; 6]).is_err());
        let e = Objective::new([0.1, -0.1, 0.2, 0.2, 0.2, 0.4]).unwrap_err();
        assert!(e.to_string().contains("yaw_frequency"), "{e}");
        assert!(Objective::from_slice(&[0.5, 0.5]).is_err());
        assert_eq!(
            Objective::from_slice(&W)
                .unwrap()
                .weight(Measure::Overshoot),
            0.1058
        );
    }
}
