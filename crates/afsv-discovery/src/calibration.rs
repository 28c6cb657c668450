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

/// What a reader of the outcome should know about the calibration `f` that does not make
/// the result unearned ([`crate::Discovery::calibration_notes`]): when nothing was named
/// and the calibrated baseline's fit met no convergence test. A baseline short of its
/// optimum can only leave more error than the converged one, so the excess over noise
/// (`excess`, held-out MSE over the noise floor) is an upper bound and "nothing missing" stays
/// true; but a "model-form discrepancy" may then be a calibration the records did not
/// finish, and a rerun with more iterations (`DiscoveryOptions::max_iter`) can tell.
pub(crate) fn notes(f: &FitOutcome, excess: f64) -> Vec<String> {
    if f.effects.is_empty() && !f.converged {
        vec![format!(
            "the calibrated baseline's fit met no convergence test within its iterations: its {excess:.2}x the noise floor is an upper bound of what it leaves (a converged baseline leaves no more)"
        )]
    } else {
        Vec::new()
    }
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

    #[test]
    fn an_unconverged_calibration_is_noted_only_when_nothing_was_named() {
        let plain = outcome(&[1e-5, 1e-12], &[false, false], false);
        let n = notes(&plain, 3.5);
        assert_eq!(n.len(), 1);
        assert!(
            n[0].contains("3.50x") && n[0].contains("upper bound"),
            "{}",
            n[0]
        );
        assert!(notes(&outcome(&[1e-5, 1e-12], &[false, false], true), 3.5).is_empty());
        // with effects named the same fit is a problem, not a note
        let mut named = plain;
        named.effects = vec!["gas-heat-transfer".into()];
        assert!(notes(&named, 3.5).is_empty());
    }
}
