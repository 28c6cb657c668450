//! The report of `afsv hps identify`: a strut fit ([`IdentifyResult`], Chapter 5) judged
//! before it is reported. A fit earns its result only when no fitted parameter ends on a
//! bound, no channel ends worse than at the start, the optimiser converged, and the residual
//! and velocity checks pass; otherwise the report names every problem.

use hps_emulsion::IdentifyResult;
use serde_json::json;

/// Reason of a `null` NRMSE.
const NO_CHANNEL: &str = "channel not in the record";

/// The residual of each compared channel against the record's own noise.
fn residual_checks_json(c: &hps_emulsion::fit_checks::ChannelChecks) -> serde_json::Value {
    let one = |c: &Option<hps_emulsion::fit_checks::ChannelCheck>| {
        c.map(|c| {
            json!({
                "residual_rms": c.residual_rms,
                "noise_rms": c.noise_rms,
                "residual_to_noise": afsv_records::json::finite_or_null(c.residual_to_noise()),
                "mean_offset": c.mean_offset,
            })
        })
    };
    afsv_records::json::explain_nulls(
        json!({ "force_n": one(&c.force), "p_piston_pa": one(&c.p_piston), "p_rod_pa": one(&c.p_rod) }),
        NO_CHANNEL,
    )
}

/// The fit `res` of the record `input` from the strut `strut` (named by `strut_source`: the
/// option or the sidecar) as JSON, with the problems that keep it from being earned (empty
/// when it is): a parameter within 0.1 % of the range from a bound, a channel whose NRMSE ends
/// more than 1 % (and 1e-4) above its start, no convergence, and the residual and velocity
/// checks. `accept_poor_fit` is recorded as `accepted_despite_problems`.
pub fn identify_report(
    res: &IdentifyResult,
    input: &str,
    strut: &str,
    strut_source: &str,
    accept_poor_fit: bool,
) -> (serde_json::Value, Vec<String>) {
    let mut at_bound = Vec::new();
    let fitted: Vec<serde_json::Value> = res
        .fitted
        .iter()
        .map(|f| {
            let (lo, hi) = f.param.bounds();
            let tol = 1e-3 * (hi - lo);
            let bound = if f.value <= lo + tol {
                Some("lower")
            } else if f.value >= hi - tol {
                Some("upper")
            } else {
                None
            };
            if bound.is_some() {
                at_bound.push(f.param.name());
            }
            let mut v = serde_json::json!({
                "param": f.param.name(), "initial": f.initial,
                "value": afsv_records::json::finite_or_null(f.value),
                "bounds": [lo, hi],
                "at_bound": bound.unwrap_or("no"),
                "std_error": afsv_records::json::finite_or_null(f.std_error),
            });
            if !f.std_error.is_finite() {
                v["std_error_reason"] = "not determined (singular Jacobian at the solution)".into();
            }
            v
        })
        .collect();
    let channels = |c: &hps_emulsion::ChannelNrmse| {
        [
            ("force", c.force),
            ("p_piston", c.p_piston),
            ("p_rod", c.p_rod),
        ]
    };
    let worse_channels: Vec<&str> = channels(&res.nrmse_initial)
        .into_iter()
        .zip(channels(&res.nrmse))
        .filter_map(|((name, before), (_, after))| match (before, after) {
            // Worse by more than 1 % of the start and 1e-4 (0.01 %) absolute: below that
            // the difference is round-off of an already exact fit, not a worse one.
            (Some(b), Some(a)) if a.is_nan() || a > b * 1.01 + 1e-4 => Some(name),
            _ => None,
        })
        .collect();
    let worse = !worse_channels.is_empty();
    let mut problems = Vec::new();
    if !at_bound.is_empty() {
        problems.push(format!(
            "ended on a bound of {} (the optimum may lie outside the searched range, or the strut/start is wrong)",
            at_bound.join(", ")
        ));
    }
    if worse {
        problems.push(format!(
            "the fit ended worse than its start in {}",
            worse_channels.join(", ")
        ));
    }
    if !res.converged {
        problems.push(format!(
            "no convergence test met in {} iterations",
            res.iterations
        ));
    }
    problems.extend(res.checks.problems());
    problems.extend(res.velocity.problem());
    let converged = res.converged && problems.is_empty();
    let report = json!({
        "input": input,
        "strut": strut,
        "strut_source": strut_source,
        "fitted": fitted,
        "nrmse_initial": afsv_records::json::explain_nulls(json!(res.nrmse_initial), NO_CHANNEL),
        "nrmse": afsv_records::json::explain_nulls(json!(res.nrmse), NO_CHANNEL),
        "nrmse_definition": "RMS(simulated - measured) / (max - min of the measured channel), over the compared samples",
        "iterations": res.iterations,
        "converged": converged,
        "optimizer_converged": res.converged,
        "improved": !worse,
        "residual_checks": residual_checks_json(&res.checks),
        "velocity": res.velocity,
        "problems": problems,
        "accepted_despite_problems": accept_poor_fit && !problems.is_empty(),
    });
    (report, problems)
}
