//! Calibration switches: laws the paper states ambiguously, offered by a model in several
//! readings ([`DiscoveryModel::switches`]). Step 0 calibrates each reading and keeps the one
//! that fits the training records better *and* lowers the held-out error by at least the
//! significance rule's share of the gap ([`crate::stats::SignificanceRule::min_gap_fraction`]);
//! the report says which reading each switch took (docs/discovery.md, "Calibration
//! switches").

use super::{ActiveEffect, DiscoveryError, DiscoveryModel, EffectSpec, ParamSpec, Phase};
use afsv_records::Record;

/// A law with more than one reading. The first reading is the model's default (what it runs
/// without switches).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct LawSwitch {
    /// Switch name (`orifice-density`).
    pub name: String,
    /// The readings, the model's default first.
    pub readings: Vec<String>,
    /// Where the ambiguity is (equation, section).
    pub citation: String,
}

/// One reading's calibration, as compared by step 0.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ReadingScore {
    /// The reading.
    pub reading: String,
    /// Normalised training MSE of the calibrated baseline under it.
    pub train_mse: f64,
    /// Normalised held-out MSE of the calibrated baseline under it.
    pub holdout_mse: f64,
}

/// Which reading a switch took and what each reading tried scored.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ReadingChoice {
    /// Switch name.
    pub switch: String,
    /// The reading kept.
    pub chosen: String,
    /// Its index in [`LawSwitch::readings`].
    pub index: usize,
    /// Every reading tried, the others' switches at their readings at the time.
    pub tried: Vec<ReadingScore>,
}

/// `inner` with the switches at the readings `choice` (an index per switch): every
/// replay goes through [`DiscoveryModel::simulate_with_readings`].
pub(crate) struct WithReadings<'a, M: DiscoveryModel + ?Sized> {
    pub inner: &'a M,
    pub choice: Vec<usize>,
}

impl<M: DiscoveryModel + ?Sized> DiscoveryModel for WithReadings<'_, M> {
    type Prepared = M::Prepared;

    fn name(&self) -> &str {
        self.inner.name()
    }
    fn channels(&self) -> Vec<String> {
        self.inner.channels()
    }
    fn baseline_params(&self) -> Vec<ParamSpec> {
        self.inner.baseline_params()
    }
    fn catalogue(&self) -> Vec<EffectSpec> {
        self.inner.catalogue()
    }
    fn switches(&self) -> Vec<LawSwitch> {
        self.inner.switches()
    }
    fn prepare(&self, record: &Record) -> Result<Self::Prepared, DiscoveryError> {
        self.inner.prepare(record)
    }
    fn condition(&self, prepared: &Self::Prepared) -> String {
        self.inner.condition(prepared)
    }
    fn group(&self, prepared: &Self::Prepared) -> Option<String> {
        self.inner.group(prepared)
    }
    fn scaling_group(&self, prepared: &Self::Prepared) -> Option<String> {
        self.inner.scaling_group(prepared)
    }
    fn simulate(
        &self,
        prepared: &Self::Prepared,
        baseline: &[f64],
        effects: &[ActiveEffect<'_>],
    ) -> Result<Vec<Option<Vec<f64>>>, DiscoveryError> {
        self.inner
            .simulate_with_readings(prepared, baseline, effects, &self.choice)
    }
    fn simulate_with_readings(
        &self,
        prepared: &Self::Prepared,
        baseline: &[f64],
        effects: &[ActiveEffect<'_>],
        readings: &[usize],
    ) -> Result<Vec<Option<Vec<f64>>>, DiscoveryError> {
        self.inner
            .simulate_with_readings(prepared, baseline, effects, readings)
    }
    fn phases(&self, record: &Record) -> Vec<Phase> {
        self.inner.phases(record)
    }
    fn skip_samples(&self, record: &Record) -> usize {
        self.inner.skip_samples(record)
    }
    fn broadband_channels(&self) -> bool {
        self.inner.broadband_channels()
    }
    fn coarse(&self, prepared: &Self::Prepared) -> Option<Self::Prepared> {
        self.inner.coarse(prepared)
    }
}

/// Whether a reading scoring `(train, holdout)` replaces the current one scoring
/// `(train_ref, holdout_ref)`: a better training fit and a held-out error lower by at least
/// `min_gap_fraction` of the current reading's gap above the noise `noise`.
pub(crate) fn better(
    (train, holdout): (f64, f64),
    (train_ref, holdout_ref): (f64, f64),
    noise: f64,
    min_gap_fraction: f64,
) -> bool {
    let gap = (holdout_ref - noise).max(0.0);
    train < train_ref && holdout_ref - holdout >= min_gap_fraction * gap && holdout < holdout_ref
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_reading_must_win_on_both_sets() {
        // better on both, by more than 2 % of the gap (0.1 - 0.01)
        assert!(better((0.05, 0.08), (0.06, 0.1), 0.01, 0.02));
        // better held out, worse in training
        assert!(!better((0.07, 0.08), (0.06, 0.1), 0.01, 0.02));
        // better in training, held-out gain below 2 % of the gap
        assert!(!better((0.05, 0.0999), (0.06, 0.1), 0.01, 0.02));
        // nothing left to gain
        assert!(!better((0.05, 0.01), (0.06, 0.01), 0.01, 0.02));
    }
}
