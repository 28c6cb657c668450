//! Fixtures no model can reproduce, listed with the reason: they need the measured records
//! of the field tests, which the dissertation only shows as figures.

use super::Ctx;

/// The section 6.3 comparisons of model and measurement.
pub(super) fn list_not_reproducible(ctx: &mut Ctx) -> Result<(), String> {
    ctx.not_reproducible(
        "s6_validation_discrepancies",
        None,
        "model-vs-measurement gaps of section 6.3: they need the measured PSDs (Figs 6.9/6.10) and path-change records (Fig 6.12), which are absent",
    );
    Ok(())
}
