//! The attribution check of a round's best candidate ([`super::discover`]).

use super::Progress;
use crate::fitting::{Context, Fitted};
use crate::stats;
use crate::{DiscoveryError, DiscoveryModel};

/// Factor on an early-stopped refit's training and held-out errors before the candidate is
/// judged clearly ahead of it ([`attribution_check`]): the candidate must beat the refit as
/// if a full refit halved both of its errors.
const CLEAR_MARGIN: f64 = 0.5;

/// Attribution check: the gain must come from the effect, not from a better optimum of the
/// model as it stands. Refit that model started from the candidate's solution (without the
/// candidate); if it comes as close, returns a note and the better reference.
pub(super) fn attribution_check<M: DiscoveryModel + ?Sized>(
    ctx: &Context<'_, M>,
    current: &Fitted,
    candidate: &Fitted,
    k_ref: usize,
    baseline_gap: f64,
    progress: &dyn Progress,
) -> Result<Option<(String, Fitted)>, DiscoveryError> {
    let mut probe = candidate.1.clone();
    probe.effects.pop();
    let n = ctx.train.n as f64;
    // With a scouting subset the refit first ends on it at the statistical stop. If the
    // candidate is still accepted against that refit with both its errors scaled by
    // `CLEAR_MARGIN`, no refit run to convergence explains the gain either (it lowers the
    // training error by what the records resolve, a few percent): the full refit is skipped.
    if let Some(early) = ctx.fit_scouted(probe.clone(), Some(current.2))? {
        let bic = stats::bic(CLEAR_MARGIN * early.0.train_mse * n, n, current.2, k_ref);
        if ctx.opts.rule.accepts(
            bic,
            candidate.0.bic,
            CLEAR_MARGIN * early.0.holdout_mse,
            candidate.0.holdout_mse,
            baseline_gap,
        ) {
            progress.fit_done("attribution check");
            return Ok(None);
        }
    }
    let refit = ctx.fit(probe, Some(current.2))?;
    progress.fit_done("attribution check");
    let ref_bic_probe = stats::bic(refit.0.train_mse * n, n, current.2, k_ref);
    let explained_without = refit.0.train_mse < current.0.train_mse
        && !ctx.opts.rule.accepts(
            ref_bic_probe,
            candidate.0.bic,
            refit.0.holdout_mse,
            candidate.0.holdout_mse,
            baseline_gap,
        );
    if !explained_without {
        return Ok(None);
    }
    let note = format!(
        "{} failed the attribution check: the model without it, refitted from its solution, reaches train MSE {:.3e} / held-out MSE {:.3e}; round repeated",
        candidate.0.effects.last().map_or("?", String::as_str),
        refit.0.train_mse,
        refit.0.holdout_mse
    );
    Ok(Some((note, refit)))
}
