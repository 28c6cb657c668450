//! Section 4.3.4: the AHP weights of Eqs 4.12, 4.15 and 4.17 from the printed
//! pairwise-comparison matrices (`afsv_design::AhpHierarchy`).

use super::Ctx;
use crate::fixtures::{matrix, Fixtures};
use crate::Echo;
use afsv_design::{AhpHierarchy, AhpLevels, GoalComparison, Measure};
use serde_json::Value;

/// The chapter-4 hierarchy from the fixtures: M2 (Eq 4.11), the three sub-matrices of
/// Eq 4.14 over (L, omega, zeta), (zeta, Gamma), (Gamma, OS, psi), and W_a (Eq 4.16).
fn hierarchy(fx: &Fixtures) -> Result<AhpHierarchy, String> {
    use Measure::*;
    let rows = |id: &str| -> Result<Vec<Vec<f64>>, String> {
        matrix(&fx.get(id).ok_or(format!("missing fixture {id}"))?.value["rows"])
    };
    let subsets: [(&str, Vec<Measure>); 3] = [
        (
            "s4_ahp_m3_a1",
            vec![StrutLength, YawFrequency, DampingRatio],
        ),
        ("s4_ahp_m3_a2", vec![DampingRatio, SteeringGain]),
        ("s4_ahp_m3_a3", vec![SteeringGain, Overshoot, ResponseRate]),
    ];
    let mut comparisons = Vec::new();
    for (id, measures) in subsets {
        comparisons.push(GoalComparison::new(id, rows(id)?, measures).map_err(|e| e.to_string())?);
    }
    let wa: Vec<f64> = fx
        .get("s4_ahp_wa")
        .and_then(|f| f.value["diagonal"].as_array())
        .ok_or("s4_ahp_wa has no diagonal")?
        .iter()
        .filter_map(Value::as_f64)
        .collect();
    AhpHierarchy::new(rows("s4_ahp_m2")?, comparisons, wa).map_err(|e| e.to_string())
}

/// Weights of every level of the chapter-4 hierarchy.
pub(super) fn ahp_levels(fx: &Fixtures) -> Result<AhpLevels, String> {
    hierarchy(fx)?.weights().map_err(|e| e.to_string())
}

/// AHP weights of Eqs 4.12, 4.15 and 4.17 from the printed matrices.
pub(super) fn check_ahp(ctx: &mut Ctx) -> Result<(), String> {
    let h = hierarchy(ctx.fx())?;
    let levels = h.weights().map_err(|e| e.to_string())?;
    let note = "principal eigenvector (optimize::ahp::weights) of the printed matrix";
    for (i, v) in levels.goals.weights.iter().enumerate() {
        ctx.compare("s4_ahp_w_ii_i", Some(&i.to_string()), None, *v, note);
    }
    for (col, c) in levels.measure_columns.iter().enumerate() {
        for (row, v) in c.iter().enumerate() {
            let key = format!("{row}.{col}");
            if h.relates(col, Measure::ALL[row]) {
                ctx.compare(
                    "s4_ahp_w_iii_ii",
                    Some(&key),
                    None,
                    *v,
                    "sub-matrix eigenvectors embedded per Eq 4.14",
                );
            } else {
                ctx.echo(
                    Echo::ByConstruction,
                    "s4_ahp_w_iii_ii",
                    Some(&key),
                    None,
                    *v,
                    "structural zero of Eq 4.15: the goal does not relate to this measure (optimize::ahp::embed)",
                );
            }
        }
    }
    for (i, v) in levels.composite.iter().enumerate() {
        ctx.compare(
            "s4_ahp_w",
            Some(&i.to_string()),
            None,
            *v,
            "optimize::ahp::compose(W_III/II, W_a, W_II/I), Eq 4.17",
        );
    }
    ctx.cache.ahp_w = Some(levels.composite.to_vec());
    Ok(())
}
