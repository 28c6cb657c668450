//! Which held-out records and phases carried the gain of each named effect.

use super::fitting::{Config, Context};
use super::{DiscoveryError, DiscoveryModel};

/// One held-out record's part in an effect's gain.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct RecordEvidence {
    /// Record name.
    pub record: String,
    /// Conditions the record was replayed under.
    pub condition: String,
    /// Normalised mean squared error of the record before the effect was added.
    pub mse_before: f64,
    /// The same with the effect.
    pub mse_after: f64,
    /// Share of the effect's held-out gain (sum of squared errors removed) that this
    /// record carries; negative where the effect made the record worse.
    pub share: f64,
}

/// The evidence for one named effect.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Evidence {
    /// The effect.
    pub effect: String,
    /// Held-out records, largest share first.
    pub records: Vec<RecordEvidence>,
    /// Share of the gain per phase of the records (e.g. steering / free, compression /
    /// extension), largest first.
    pub phases: Vec<(String, f64)>,
}

/// Evidence for each named effect: held-out squared error before and after, per record and
/// per phase. `chain[k]` is the model before and after the k-th named effect.
pub(crate) fn of_named<M: DiscoveryModel + ?Sized>(
    ctx: &Context<'_, M>,
    named: &[String],
    chain: &[(Config, Config)],
    holdout_names: &[String],
) -> Result<Vec<Evidence>, DiscoveryError> {
    let set = &ctx.holdout;
    let phases: Vec<_> = set.records.iter().map(|r| ctx.model.phases(r)).collect();
    let mut out = Vec::new();
    for (name, (before, after)) in named.iter().zip(chain) {
        let rb = set.residual_vec(ctx.model, &before.baseline, &before.active())?;
        let ra = set.residual_vec(ctx.model, &after.baseline, &after.active())?;
        let sb = set.per_record_sse(&rb);
        let sa = set.per_record_sse(&ra);
        let total: f64 = sb.iter().sum::<f64>() - sa.iter().sum::<f64>();
        let denom = if total.abs() > 0.0 { total } else { 1.0 };
        let mut records: Vec<RecordEvidence> = (0..set.records.len())
            .map(|i| {
                let n = set.segments[i].iter().map(|s| s.len).sum::<usize>().max(1) as f64;
                RecordEvidence {
                    record: holdout_names.get(i).cloned().unwrap_or_default(),
                    condition: ctx.model.condition(set.prepared[i]),
                    mse_before: sb[i] / n,
                    mse_after: sa[i] / n,
                    share: (sb[i] - sa[i]) / denom,
                }
            })
            .collect();
        records.sort_by(|a, b| b.share.total_cmp(&a.share));
        let mut by_phase: Vec<(String, f64)> = Vec::new();
        for (i, segs) in set.segments.iter().enumerate() {
            for ph in &phases[i] {
                let mut gain = 0.0;
                for s in segs {
                    for k in 0..s.len {
                        if ph.mask.get(s.skip + k).copied().unwrap_or(false) {
                            let (b, a) = (rb[s.offset + k], ra[s.offset + k]);
                            gain += b * b - a * a;
                        }
                    }
                }
                match by_phase.iter_mut().find(|(n, _)| *n == ph.name) {
                    Some(entry) => entry.1 += gain / denom,
                    None => by_phase.push((ph.name.clone(), gain / denom)),
                }
            }
        }
        by_phase.sort_by(|a, b| b.1.total_cmp(&a.1));
        out.push(Evidence {
            effect: name.clone(),
            records,
            phases: by_phase,
        });
    }
    Ok(out)
}
