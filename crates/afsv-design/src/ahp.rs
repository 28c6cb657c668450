//! The AHP weighting of section 4.3.4 (Eqs 4.11-4.17): level-II goals weighted by a
//! pairwise-comparison matrix (Eqs 4.11-4.12), each goal's related measures weighted by its
//! own matrix (Eq 4.14) and embedded into a column of W_III/II (Eq 4.15, zeros for unrelated
//! measures), then composed with the shares W_a of the incomplete hierarchy (Eq 4.16) into
//! the measure weights W of Eq 4.17. The eigenvector and composition arithmetic is
//! `optimize::ahp`.

use crate::error::{positive, DesignError};
use crate::measures::Measure;
use optimize::ahp::{compose, embed, weights, AhpWeights};
use serde::Serialize;

/// One level-II goal's comparison of its related measures (one block of Eq 4.14).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GoalComparison {
    /// Name used in errors (e.g. `M3/A(1)`).
    pub name: String,
    /// Square pairwise-comparison matrix over `measures`, positive entries.
    pub matrix: Vec<Vec<f64>>,
    /// The measures the goal relates to, in the matrix's order.
    pub measures: Vec<Measure>,
}

impl GoalComparison {
    /// A comparison of `measures` by `matrix` (square, one row per measure, positive finite
    /// entries, distinct measures).
    pub fn new(
        name: impl Into<String>,
        matrix: Vec<Vec<f64>>,
        measures: Vec<Measure>,
    ) -> Result<Self, DesignError> {
        let name = name.into();
        check_matrix(&matrix, measures.len())?;
        for (i, m) in measures.iter().enumerate() {
            if measures[..i].contains(m) {
                return Err(DesignError::Shape {
                    field: "measures",
                    reason: format!("{name} lists {} twice", m.name()),
                });
            }
        }
        Ok(Self {
            name,
            matrix,
            measures,
        })
    }
}

/// The chapter-4 hierarchy: goals (level II) and measures (level III).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AhpHierarchy {
    /// Level-II comparison matrix M2 (Eq 4.11), one row per goal.
    goal_matrix: Vec<Vec<f64>>,
    /// One comparison of related measures per goal, in M2's order (Eq 4.14).
    comparisons: Vec<GoalComparison>,
    /// W_a: the share of the measures related to each goal (Eq 4.16).
    shares: Vec<f64>,
}

/// Weights of every level of an [`AhpHierarchy`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AhpLevels {
    /// W_II/I with the consistency of M2 (Eq 4.12).
    pub goals: AhpWeights,
    /// Each goal's sub-matrix weights with their consistency (Eq 4.14).
    pub comparisons: Vec<AhpWeights>,
    /// Columns of W_III/II (Eq 4.15): one per goal, indexed by [`Measure::index`], zeros
    /// for the measures the goal does not relate to.
    pub measure_columns: Vec<[f64; 6]>,
    /// Composite weights W (Eq 4.17), indexed by [`Measure::index`], summing to 1.
    pub composite: [f64; 6],
}

impl AhpHierarchy {
    /// A hierarchy of `goal_matrix` (square, one row per comparison), one
    /// [`GoalComparison`] per goal and the shares W_a (one positive entry per goal).
    pub fn new(
        goal_matrix: Vec<Vec<f64>>,
        comparisons: Vec<GoalComparison>,
        shares: Vec<f64>,
    ) -> Result<Self, DesignError> {
        check_matrix(&goal_matrix, comparisons.len())?;
        if shares.len() != comparisons.len() {
            return Err(DesignError::Shape {
                field: "shares",
                reason: format!(
                    "one W_a entry per goal: {} goals, {} entries",
                    comparisons.len(),
                    shares.len()
                ),
            });
        }
        for &s in &shares {
            positive("shares", s)?;
        }
        Ok(Self {
            goal_matrix,
            comparisons,
            shares,
        })
    }

    /// The chapter-4 hierarchy as printed in section 4.3.4: M2 of Eq 4.11 over (yaw
    /// oscillation/stability, steering power efficiency, manoeuvrability), the three
    /// matrices of Eq 4.14 over (L, omega, zeta), (zeta, Gamma), (Gamma, OS, psi), and
    /// W_a = diag(3/6, 2/6, 3/6) of Eq 4.16. Its composite weights are those of Eq 4.17.
    pub fn chapter4() -> Self {
        use Measure::*;
        let c = |name: &str, matrix: Vec<Vec<f64>>, measures: Vec<Measure>| GoalComparison {
            name: name.to_string(),
            matrix,
            measures,
        };
        Self {
            goal_matrix: vec![
                vec![1.0, 3.0, 2.0],
                vec![1.0 / 3.0, 1.0, 0.5],
                vec![0.5, 2.0, 1.0],
            ],
            comparisons: vec![
                c(
                    "M3/A(1)",
                    vec![
                        vec![1.0, 0.2, 1.0],
                        vec![5.0, 1.0, 1.59],
                        vec![1.0, 0.63, 1.0],
                    ],
                    vec![StrutLength, YawFrequency, DampingRatio],
                ),
                c(
                    "M3/A(2)",
                    vec![vec![1.0, 1.76], vec![0.57, 1.0]],
                    vec![DampingRatio, SteeringGain],
                ),
                c(
                    "M3/A(3)",
                    vec![
                        vec![1.0, 1.25, 1.0],
                        vec![0.8, 1.0, 1.3],
                        vec![1.0, 0.77, 1.0],
                    ],
                    vec![SteeringGain, Overshoot, ResponseRate],
                ),
            ],
            shares: vec![0.5, 1.0 / 3.0, 0.5],
        }
    }

    /// The goals' comparisons of their related measures, in M2's order.
    pub fn comparisons(&self) -> &[GoalComparison] {
        &self.comparisons
    }

    /// Whether goal `goal` relates to measure `m`; an unrelated measure holds a structural
    /// zero in that goal's column of W_III/II (Eq 4.15).
    pub fn relates(&self, goal: usize, m: Measure) -> bool {
        self.comparisons
            .get(goal)
            .is_some_and(|c| c.measures.contains(&m))
    }

    /// Weights of every level (Eqs 4.12, 4.14, 4.15, 4.17).
    pub fn weights(&self) -> Result<AhpLevels, DesignError> {
        let ahp = |matrix: &str, m: &[Vec<f64>]| {
            weights(m).map_err(|source| DesignError::Ahp {
                matrix: matrix.to_string(),
                source,
            })
        };
        let goals = ahp("M2", &self.goal_matrix)?;
        let mut comparisons = Vec::with_capacity(self.comparisons.len());
        let mut lower = Vec::with_capacity(self.comparisons.len());
        for c in &self.comparisons {
            let w = ahp(&c.name, &c.matrix)?;
            let idx: Vec<usize> = c.measures.iter().map(|m| m.index()).collect();
            lower.push(embed(&w.weights, &idx, Measure::ALL.len()));
            comparisons.push(w);
        }
        let composite =
            compose(&lower, &self.shares, &goals.weights).map_err(|source| DesignError::Ahp {
                matrix: "W_III/II . W_a . W_II/I".into(),
                source,
            })?;
        let column = |v: &[f64]| -> [f64; 6] { std::array::from_fn(|i| v[i]) };
        Ok(AhpLevels {
            goals,
            comparisons,
            measure_columns: lower.iter().map(|c| column(c)).collect(),
            composite: column(&composite),
        })
    }
}

/// `m` is an `n` x `n` matrix of positive finite entries.
fn check_matrix(m: &[Vec<f64>], n: usize) -> Result<(), DesignError> {
    if n == 0 || m.len() != n || m.iter().any(|r| r.len() != n) {
        return Err(DesignError::Shape {
            field: "matrix",
            reason: format!("expected {n} x {n}, got {} rows", m.len()),
        });
    }
    for &v in m.iter().flatten() {
        positive("matrix entry", v)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chapter4_hierarchy_gives_the_weights_of_eq_4_17() {
        // Exact weights of the printed matrices (reading notes, section 3.5).
        let w = AhpHierarchy::chapter4().weights().unwrap().composite;
        let want = [0.0971, 0.3313, 0.2158, 0.1543, 0.1058, 0.0957];
        for (a, b) in w.iter().zip(want) {
            assert!((a - b).abs() < 6e-5, "{w:?}");
        }
    }
    use Measure::*;

    /// A consistent 3 x 3 matrix: weights 4/7, 2/7, 1/7.
    fn consistent() -> Vec<Vec<f64>> {
        vec![
            vec![1.0, 2.0, 4.0],
            vec![0.5, 1.0, 2.0],
            vec![0.25, 0.5, 1.0],
        ]
    }

    fn equal(n: usize) -> Vec<Vec<f64>> {
        vec![vec![1.0; n]; n]
    }

    #[test]
    fn consistent_hierarchy_has_hand_computed_weights() {
        // Goal 1 relates to (L, omega), goal 2 to (zeta, Gamma), goal 3 to (OS, psi), each
        // with equal judgements (0.5, 0.5) and equal shares: W = goal weight / 2.
        let h = AhpHierarchy::new(
            consistent(),
            vec![
                GoalComparison::new("g1", equal(2), vec![StrutLength, YawFrequency]).unwrap(),
                GoalComparison::new("g2", equal(2), vec![DampingRatio, SteeringGain]).unwrap(),
                GoalComparison::new("g3", equal(2), vec![Overshoot, ResponseRate]).unwrap(),
            ],
            vec![1.0, 1.0, 1.0],
        )
        .unwrap();
        let l = h.weights().unwrap();
        let want_goals = [4.0 / 7.0, 2.0 / 7.0, 1.0 / 7.0];
        for (g, w) in l.goals.weights.iter().zip(want_goals) {
            assert!((g - w).abs() < 1e-12);
        }
        assert!(l.goals.consistency_ratio.abs() < 1e-12);
        assert_eq!(l.measure_columns[0], [0.5, 0.5, 0.0, 0.0, 0.0, 0.0]);
        assert!(h.relates(0, YawFrequency) && !h.relates(0, DampingRatio));
        assert!(!h.relates(3, StrutLength));
        assert_eq!(h.comparisons()[2].name, "g3");
        let want = [2.0, 2.0, 1.0, 1.0, 0.5, 0.5].map(|v| v / 7.0);
        for (c, w) in l.composite.iter().zip(want) {
            assert!((c - w).abs() < 1e-12, "{:?}", l.composite);
        }
    }

    #[test]
    fn shares_weight_the_goals() {
        // Two goals of equal weight over disjoint single measures; shares 3:1 give 0.75/0.25.
        let h = AhpHierarchy::new(
            equal(2),
            vec![
                GoalComparison::new("a", equal(1), vec![StrutLength]).unwrap(),
                GoalComparison::new("b", equal(1), vec![Overshoot]).unwrap(),
            ],
            vec![3.0, 1.0],
        )
        .unwrap();
        let w = h.weights().unwrap().composite;
        assert!((w[0] - 0.75).abs() < 1e-12 && (w[4] - 0.25).abs() < 1e-12);
        assert_eq!(w[1], 0.0);
    }

    #[test]
    fn bad_shapes_and_entries_are_refused() {
        let g = || GoalComparison::new("a", equal(1), vec![StrutLength]).unwrap();
        assert!(GoalComparison::new("a", equal(2), vec![StrutLength]).is_err());
        assert!(GoalComparison::new("a", equal(2), vec![Overshoot, Overshoot]).is_err());
        assert!(GoalComparison::new(
            "a",
            vec![vec![1.0, -2.0], vec![0.5, 1.0]],
            vec![StrutLength, Overshoot]
        )
        .is_err());
        assert!(AhpHierarchy::new(equal(2), vec![g()], vec![1.0]).is_err());
        assert!(AhpHierarchy::new(equal(1), vec![g()], vec![1.0, 1.0]).is_err());
        let e = AhpHierarchy::new(equal(1), vec![g()], vec![f64::NAN]).unwrap_err();
        assert!(e.to_string().contains("shares"), "{e}");
    }
}
