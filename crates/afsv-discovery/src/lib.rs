//! Model-discrepancy discovery: find which physical effect a model is missing, add it, and
//! show the gap shrink (see `docs/discovery.md`).
//!
//! The workflow, for any model that implements [`DiscoveryModel`]:
//!
//! 0. **Calibrate** the baseline's uncertain parameters on the training records, so that a
//!    mismatch of nominal values is not mistaken for a missing effect ([`calibrate`]); a
//!    law the paper states ambiguously is calibrated in each of its readings and the better
//!    one kept ([`LawSwitch`]).
//! 1. **Simulate** the calibrated baseline with each record's inputs.
//! 2. **Locate** the disagreement per channel, per phase and by signature ([`signature`]).
//! 3. **Try** every effect of the model's catalogue: fit its parameters (with the baseline's
//!    calibrated parameters freed again) on the training records, score it on held-out records.
//! 4. **Name** an effect only when the improvement is significant ([`stats`]) and it passes
//!    the naming tests that tell a missing effect from a model-form difference (bounds,
//!    [`placebo`] candidates, parameter constancy across condition groups: [`form`]); add it,
//!    repeat.
//! 5. **Report** the outcome ([`Outcome`]: named / model-form discrepancy / nothing
//!    missing), the effects named, fitted parameters with standard errors, before/after
//!    errors and the gap shrink ([`report`]).
//!
//! Two models come with the crate: the hydro-pneumatic strut on a bench ([`hps`]) and the
//! yaw-plane vehicle with hydraulic frame steering ([`yaw`]); [`synth`] writes
//! measurement-like records from them with hidden effects and sensor noise. Progress goes
//! through the [`Progress`] trait (`&()` reports nothing). The crate needs no command-line,
//! plotting or terminal libraries; the cargo feature `plots` (off by default) adds SVG
//! overlays of the held-out records to the report.
//!
//! ```
//! use afsv_discovery::hps::HpsStrutModel;
//! use afsv_discovery::synth::{hps_records, HpsNoise};
//! use afsv_discovery::DiscoveryModel;
//!
//! // Noise-free bench records of the paper's strut, no hidden effect.
//! let model = HpsStrutModel::nominal();
//! let recs = hps_records(&model, &[], HpsNoise::none(), 7, 360.0).unwrap();
//! let first = &recs[0].record;
//! let prepared = model.prepare(first).unwrap();
//! let nominal: Vec<f64> = model.baseline_params().iter().map(|p| p.initial).collect();
//! let predicted = model.simulate(&prepared, &nominal, &[]).unwrap();
//! assert_eq!(predicted.len(), model.channels().len());
//! // The whole workflow: afsv_discovery::discover(&model, &train, &holdout, ..., &()).
//! ```

mod calibration;
mod engine;
mod error;
pub mod evidence;
mod fitting;
pub mod form;
pub mod hps;
mod layout;
#[cfg(feature = "plots")]
mod overlay;
pub mod placebo;
mod readings;
pub mod report;
pub mod signature;
pub mod stats;
pub mod synth;
pub mod vehicle3d;
pub mod vehicle3d_effects;
pub mod yaw;

pub use engine::{
    calibrate, discover, evaluate_errors, ChannelError, Discovery, DiscoveryOptions, EffectChoice,
    EffectParam, FitOutcome, Progress, RecordCondition, Step, SCOUT_ITERATIONS,
};
pub use error::DiscoveryError;
pub use evidence::{Evidence, RecordEvidence};
pub use form::{FormRule, GroupFit, NamingTests, Outcome};
pub use readings::{LawSwitch, ReadingChoice, ReadingScore};

use afsv_records::Record;

/// A parameter the workflow may fit, with its physical range.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ParamSpec {
    /// Name as shown to users (with unit suffix, e.g. `friction_coulomb_n`).
    pub name: String,
    /// Start value (for baseline parameters: the nominal value).
    pub initial: f64,
    /// Lower bound.
    pub lower: f64,
    /// Upper bound.
    pub upper: f64,
    /// Typical magnitude (sets finite-difference steps).
    pub typical: f64,
}

impl ParamSpec {
    /// A parameter with bounds; `typical` defaults to `|initial|` (or the bound span if zero).
    pub fn new(name: &str, initial: f64, lower: f64, upper: f64) -> Self {
        let typical = if initial != 0.0 {
            initial.abs()
        } else {
            (upper - lower).abs().min(1e300) * 0.1
        };
        Self {
            name: name.to_string(),
            initial,
            lower,
            upper,
            typical,
        }
    }
}

/// One candidate model extension of a catalogue: a documented physical mechanism.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct EffectSpec {
    /// Short name used on the command line (`gas-heat-transfer`, `sensor-backlash`, ...).
    pub name: String,
    /// One-sentence physics.
    pub description: String,
    /// Where the mechanism comes from (dissertation section or literature).
    pub citation: String,
    /// Its parameters.
    pub params: Vec<ParamSpec>,
}

/// An effect switched on with parameter values, as passed to [`DiscoveryModel::simulate`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ActiveEffect<'a> {
    /// Index into [`DiscoveryModel::catalogue`].
    pub index: usize,
    /// Values of its parameters, in the order of its [`EffectSpec::params`].
    pub values: &'a [f64],
}

/// Phase labels of a record (e.g. compression/extension) for locating disagreement.
#[derive(Debug, Clone, PartialEq)]
pub struct Phase {
    /// Label (e.g. `compression`).
    pub name: String,
    /// Which samples belong to it.
    pub mask: Vec<bool>,
}

/// A model the discovery workflow can calibrate and extend.
///
/// Implementations live next to the models (strut, yaw-plane vehicle); the workflow only
/// sees records, parameter vectors and predicted channels. Each record is first
/// [prepared](Self::prepare) once: its conditions (load, speed, strut) and invariant inputs
/// (mean speed, smoothed steering angle, strut velocity and its peak) are worked out
/// there, never at every fit evaluation.
pub trait DiscoveryModel: Sync {
    /// A record's conditions and invariant inputs.
    type Prepared: Send + Sync;
    /// Model name (`hps-strut`, `yaw-plane`).
    fn name(&self) -> &str;
    /// Record channels the model predicts and the workflow compares (absent ones are skipped).
    fn channels(&self) -> Vec<String>;
    /// Uncertain baseline parameters calibrated before any effect is considered.
    fn baseline_params(&self) -> Vec<ParamSpec>;
    /// The catalogue of candidate effects.
    fn catalogue(&self) -> Vec<EffectSpec>;
    /// Work out `record`'s conditions and invariant inputs. A condition that cannot be
    /// determined is an error naming the missing field and how to give it.
    fn prepare(&self, record: &Record) -> Result<Self::Prepared, DiscoveryError>;
    /// The conditions a prepared record is replayed under, in words (for the report).
    fn condition(&self, prepared: &Self::Prepared) -> String;
    /// The condition group of a prepared record for the parameter-constancy test of
    /// [`form`] (strut: quasi-static or dynamic test; vehicle: its load). `None` (the
    /// default) leaves the record out of that test.
    fn group(&self, _prepared: &Self::Prepared) -> Option<String> {
        None
    }
    /// Simulate a prepared record with the given baseline parameter values and effects;
    /// returns one predicted series per entry of `channels()`, on the record's time base
    /// (`None` for a channel the model cannot predict for this record).
    fn simulate(
        &self,
        prepared: &Self::Prepared,
        baseline: &[f64],
        effects: &[ActiveEffect<'_>],
    ) -> Result<Vec<Option<Vec<f64>>>, DiscoveryError>;
    /// The experiment kind a prepared record belongs to for the residuals' normalisation
    /// (docs/discovery.md, "Each experiment's own scale"). `None` (the default, every
    /// record): each channel's residual is divided by the channel's standard deviation over
    /// all training records. Where records of one kind are separate experiments whose
    /// channels span very different ranges (the 3-D vehicle's ride runs and V3 path
    /// changes), `Some(kind)` divides each record's channel by the channel's standard
    /// deviation over the training records of the same kind, so that each experiment's
    /// error counts as a normalised error of that experiment (a kind without training
    /// records, or a channel constant over them, keeps the whole set's scale).
    fn scaling_group(&self, _prepared: &Self::Prepared) -> Option<String> {
        None
    }
    /// Laws the paper states ambiguously, each offered in several readings (calibration
    /// switches: step 0 calibrates each reading and keeps the better one, see
    /// [`LawSwitch`]). None by default.
    fn switches(&self) -> Vec<LawSwitch> {
        Vec::new()
    }
    /// As [`Self::simulate`], with reading `readings[i]` of switch `i` of
    /// [`Self::switches`] (a missing entry is the default reading, 0). The default ignores
    /// the readings: a model without switches has nothing to read differently.
    fn simulate_with_readings(
        &self,
        prepared: &Self::Prepared,
        baseline: &[f64],
        effects: &[ActiveEffect<'_>],
        readings: &[usize],
    ) -> Result<Vec<Option<Vec<f64>>>, DiscoveryError> {
        let _ = readings;
        self.simulate(prepared, baseline, effects)
    }
    /// Phases of a record used to locate the disagreement (may be empty).
    fn phases(&self, record: &Record) -> Vec<Phase>;
    /// Leading samples of a record left out of every comparison (start-up transient of a
    /// simulation that starts from static equilibrium).
    fn skip_samples(&self, _record: &Record) -> usize {
        0
    }
    /// A copy of a prepared record that replays faster and less exactly, for scouting: the
    /// ranking of start points and the short scouting fits ([`DiscoveryOptions::starts`]),
    /// which only choose a basin and the round's finalists. Every fit to convergence, every
    /// polish and every score replays the prepared record itself. `None` (the default):
    /// scouting replays as the fits do.
    fn coarse(&self, _prepared: &Self::Prepared) -> Option<Self::Prepared> {
        None
    }
    /// Whether the compared channels carry signal up to the records' sampling rate (ride
    /// vibration), so that the fourth differences of a measured channel read signal as
    /// noise. The noise floor of each record and channel is then the lower of the
    /// fourth-difference estimates on the measured channel and on the calibrated baseline's
    /// residual, which has the signal the model reproduces taken out (docs/discovery.md,
    /// "Statistics"). False by default.
    fn broadband_channels(&self) -> bool {
        false
    }
}
