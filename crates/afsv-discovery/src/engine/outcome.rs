//! What a discovery found: the fits, the rounds and the choices, as the report shows them.

use crate::evidence::Evidence;
use crate::form::{NamingTests, Outcome};
use crate::readings::ReadingChoice;
use crate::signature::ChannelSignature;

/// Error of one channel over a set of records (`None` where it could not be computed).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ChannelError {
    /// Channel name.
    pub channel: String,
    /// RMS error in channel units.
    pub rmse: Option<f64>,
    /// RMS error over the channel's standard deviation (training-set scale; each record by
    /// its experiment kind's for models with scaling groups,
    /// [`DiscoveryModel::scaling_group`](crate::DiscoveryModel::scaling_group)).
    pub nrmse: Option<f64>,
    /// Samples compared (0: no record has the channel).
    pub samples: usize,
}

/// A fitted parameter of an effect.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct EffectParam {
    /// Parameter name with unit suffix.
    pub name: String,
    /// Fitted value.
    pub value: f64,
    /// Standard error from the Jacobian (`None` when the fit could not estimate it).
    pub std_error: Option<f64>,
    /// The value sits on a bound of its range: the data push it there, and the standard
    /// error does not describe its uncertainty.
    pub at_bound: bool,
}

/// A fitted configuration: baseline values plus active effects.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct FitOutcome {
    /// Names of the active effects.
    pub effects: Vec<String>,
    /// Baseline parameter names.
    pub baseline_names: Vec<String>,
    /// Baseline parameter values.
    pub baseline: Vec<f64>,
    /// Their standard errors (`None` for parameters held fixed or not estimable).
    pub baseline_se: Vec<Option<f64>>,
    /// Per baseline parameter: it was fitted and sits on a bound of its range (the data
    /// push it there; its value is not an estimate).
    pub baseline_at_bound: Vec<bool>,
    /// Per active effect: its fitted parameters.
    pub effect_params: Vec<Vec<EffectParam>>,
    /// Normalised residual mean square on the training records.
    pub train_mse: f64,
    /// Normalised residual mean square on the held-out records.
    pub holdout_mse: f64,
    /// Effective-sample BIC on the training records (see [`stats`](crate::stats)).
    pub bic: f64,
    /// Effective-sample AIC on the training records.
    pub aic: f64,
    /// Number of fitted parameters.
    pub k: usize,
    /// Whether the least-squares fit met its convergence test.
    pub converged: bool,
}

/// One candidate tried in one round.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct EffectChoice {
    /// Effect name.
    pub effect: String,
    /// The fitted configuration, or why it failed.
    pub outcome: Result<FitOutcome, String>,
    /// Relative decrease of the held-out error against the round's starting model
    /// (`None` when the fit failed).
    pub holdout_gain: Option<f64>,
    /// BIC decrease against the round's starting model (`None` when the fit failed).
    pub bic_drop: Option<f64>,
}

/// One round of the greedy search.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Step {
    /// Candidates tried, best held-out error first.
    pub candidates: Vec<EffectChoice>,
    /// The effect named in this round, if any was significant.
    pub named: Option<String>,
    /// Set when the best candidate failed the attribution check: refitting the model as it
    /// stood, started from that candidate's solution, explained the same gap, so the round
    /// was repeated against the better-fitted model.
    pub attribution: Option<String>,
    /// The naming tests of the round's best candidate when it was significant.
    pub naming_tests: Option<NamingTests>,
}

/// The conditions one record was replayed under.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct RecordCondition {
    /// Record name.
    pub record: String,
    /// `train` or `holdout`.
    pub set: String,
    /// The conditions, in words (load, speed, manoeuvre; strut).
    pub condition: String,
}

/// Everything the workflow found.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Discovery {
    /// Model name.
    pub model: String,
    /// Channels compared.
    pub channels: Vec<String>,
    /// The conditions each record was replayed under.
    pub conditions: Vec<RecordCondition>,
    /// Nominal (uncalibrated) baseline.
    pub nominal: FitOutcome,
    /// Calibrated baseline.
    pub calibrated: FitOutcome,
    /// The reading each calibration switch took in step 0 (empty for a model without
    /// switches or with [`DiscoveryOptions::switches`](super::DiscoveryOptions::switches) off).
    pub readings: Vec<ReadingChoice>,
    /// Where the calibrated baseline disagrees, per training and held-out record and channel.
    pub signatures: Vec<(String, ChannelSignature)>,
    /// Greedy rounds.
    pub steps: Vec<Step>,
    /// Effects named, in order.
    pub named: Vec<String>,
    /// Per named effect: which held-out records and phases carried its gain.
    pub evidence: Vec<Evidence>,
    /// Final model (calibrated baseline plus named effects).
    pub final_model: FitOutcome,
    /// Per-channel errors: (training before, training after, held-out before, held-out after).
    pub channel_errors: Vec<(ChannelError, ChannelError, ChannelError, ChannelError)>,
    /// Estimated measurement-noise share of the normalised held-out error.
    pub holdout_noise_mse: f64,
    /// Fraction of the reducible held-out error removed by the named effects.
    pub gap_shrink: f64,
    /// When nothing was named: the best candidate's share of the reducible gap.
    pub best_unnamed_shrink: Option<(String, f64)>,
    /// The calibrated baseline's held-out error over the noise floor.
    pub excess_over_noise: f64,
    /// What was found: effects named, a model-form discrepancy, or nothing missing.
    pub outcome: Outcome,
    /// Why the final model's baseline is not an estimate, one sentence each (empty when it
    /// earned its values): a parameter still on its bound, a full final fit that did not
    /// converge (`calibration::problems`).
    pub calibration_problems: Vec<String>,
    /// What the reader should know about the calibration that does not make the result
    /// unearned, one sentence each: a calibrated baseline whose fit met no convergence test
    /// when nothing was named (`calibration::notes`).
    pub calibration_notes: Vec<String>,
}
