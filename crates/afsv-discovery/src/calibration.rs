//! Whether the final model earned its baseline: the same rule as every fit of the toolkit
//! (a fit that did not converge, a parameter on a bound of its range, is said).

use crate::{FitOutcome, ParamSpec};

/// What keeps the final model `f` (fitted within `specs`) from being an estimate
/// ([`crate::Discovery::calibration_problems`]): a baseline parameter still on a bound of
/// its range, or, when effects were named (so the final fit is a full one), a fit that met
/// no convergence test.
///
/// The calibrated baseline alone is not judged: a missing effect pushes its parameters
/// towards their bounds (a strut without its gas heat transfer calibrates its seal viscosity
/// to 0), which is the evidence discovery works from. Once the effect is named the
/// parameters must come back inside; one that stays on its bound means something the named
/// effects do not explain is still pushing it.
pub(crate) fn problems(f: &FitOutcome, specs: &[ParamSpec]) -> Vec<String> {
    let mut out = Vec::new();
    if !f.effects.is_empty() && !f.converged {
        out.push(
            "the final fit (baseline with the named effects) met no convergence test".to_string(),
        );
    }
    for ((name, value), (spec, on)) in f
        .baseline_names
        .iter()
        .zip(&f.baseline)
        .zip(specs.iter().zip(&f.baseline_at_bound))
    {
        if *on {
            out.push(format!(
                "the baseline's `{name}` = {value:.4e} sits on a bound of its range [{:.4e}, {:.4e}] in the final model: something the named effects do not explain pushes it there (a wrong record scaling or sign, a missing effect, or a model of another form)",
                spec.lower, spec.upper
            ));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn outcome(values: &[f64], at_bound: &[bool], converged: bool) -> FitOutcome {
        FitOutcome {
            effects: Vec::new(),
            baseline_names: vec!["a_b".into(), "k_l".into()],
            baseline: values.to_vec(),
            baseline_se: vec![None; values.len()],
            baseline_at_bound: at_bound.to_vec(),
            effect_params: Vec::new(),
            train_mse: 0.1,
            holdout_mse: 0.1,
            bic: 0.0,
            aic: 0.0,
            k: 2,
            converged,
        }
    }

    #[test]
    fn a_parameter_on_its_bound_and_no_convergence_are_said() {
        let specs = [
            ParamSpec::new("a_b", 1e-5, 1e-7, 1e-3),
            ParamSpec::new("k_l", 1e-12, 0.0, 1e-9),
        ];
        assert!(problems(&outcome(&[1e-5, 1e-12], &[false, false], true), &specs).is_empty());
        // the calibrated baseline alone: a bound is reported, convergence is not judged
        let p = problems(&outcome(&[1e-3, 1e-12], &[true, false], false), &specs);
        assert_eq!(p.len(), 1);
        assert!(p[0].contains("`a_b`") && p[0].contains("bound"), "{}", p[0]);
        // with named effects the final fit must converge
        let mut named = outcome(&[1e-5, 1e-12], &[false, false], false);
        named.effects = vec!["gas-heat-transfer".into()];
        let p = problems(&named, &specs);
        assert_eq!(p.len(), 1);
        assert!(p[0].contains("convergence"));
    }
}
