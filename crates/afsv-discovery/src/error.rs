//! Why a discovery run, a record replay, a synthesis or a report failed.

use std::path::PathBuf;

/// What went wrong in the discovery workflow. Each message says what is missing or wrong
/// and, where the user can fix it, how (a sidecar field, a command-line option).
#[derive(Debug, thiserror::Error)]
pub enum DiscoveryError {
    /// The workflow was given no training or no held-out record.
    #[error("need at least one training and one held-out record")]
    NoRecords,
    /// An effect asked for is not in the model's catalogue.
    #[error("unknown effect `{effect}` for model {model} (catalogue: {catalogue})")]
    UnknownEffect {
        /// The name given.
        effect: String,
        /// Model name.
        model: String,
        /// The catalogue's effect names, comma-separated.
        catalogue: String,
    },
    /// An active effect's index is outside the model's catalogue.
    #[error("no effect {index} in the {model} catalogue")]
    NoSuchEffect {
        /// The index given.
        index: usize,
        /// Which catalogue (`strut`, `yaw-plane`).
        model: &'static str,
    },
    /// A problem of one record, named by its label.
    #[error("record {record}: {source}")]
    InRecord {
        /// Record label (file stem or position).
        record: String,
        /// What is wrong with it.
        source: Box<DiscoveryError>,
    },
    /// A record lacks a column the model needs.
    #[error("record has no {column} column")]
    MissingColumn {
        /// Column name.
        column: &'static str,
    },
    /// A record is too short to replay.
    #[error("record has fewer than two samples")]
    TooFewSamples,
    /// The strut velocity of a record cannot be derived from its displacement.
    #[error("cannot derive the strut velocity (need at least 9 samples with increasing time_s)")]
    NoStrutVelocity,
    /// A record's sidecar names another strut than the model's.
    #[error(
        "its sidecar names the strut `{record}`, the model is the `{model}` strut; \
         give that strut's parameters with --params"
    )]
    OtherStrut {
        /// Strut named in the sidecar.
        record: String,
        /// Strut of the model.
        model: String,
    },
    /// A sidecar's `load` is not a string.
    #[error("sidecar field `load` must be \"loaded\" or \"unloaded\", got {value}")]
    LoadNotText {
        /// The JSON value found.
        value: String,
    },
    /// A sidecar's `load` names no known load.
    #[error("sidecar field `load` = \"{load}\": expected \"loaded\" or \"unloaded\"")]
    UnknownLoad {
        /// The text found.
        load: String,
    },
    /// A record's load is stated nowhere.
    #[error(
        "its load is unknown: the sidecar has no `load` field. State it there \
         (\"load\": \"loaded\" or \"unloaded\"), or pass --load loaded|unloaded for \
         all such records (with --model yaw-plane also --params-for \
         FILE.csv=params.json for this one)"
    )]
    NoLoad,
    /// A record's forward speed is stated nowhere.
    #[error(
        "its speed is unknown: no speed_m_s column and no speed_m_s or speed_kmh in the sidecar"
    )]
    NoSpeed,
    /// None of the records has a channel the model predicts.
    #[error("no record has any of the channels the model predicts ({channels})")]
    NoChannels {
        /// The model's channels, comma-separated.
        channels: String,
    },
    /// A record lost a channel between layout and replay.
    #[error("record lost the channel `{channel}`")]
    ChannelLost {
        /// Channel name.
        channel: String,
    },
    /// The model stopped predicting a channel it predicted when the records were laid out.
    #[error("model stopped predicting `{channel}`")]
    PredictionMissing {
        /// Channel name.
        channel: String,
    },
    /// A prediction is shorter than its record.
    #[error("prediction of `{channel}` is too short")]
    PredictionTooShort {
        /// Channel name.
        channel: String,
    },
    /// The strut model refused its parameters or failed to simulate.
    #[error(transparent)]
    Strut(#[from] hps_emulsion::HpsError),
    /// The steering system refused its parameters.
    #[error(transparent)]
    Steering(#[from] afs_hydraulics::AfsError),
    /// The vehicle model refused its parameters or failed to simulate.
    #[error(transparent)]
    Vehicle(#[from] afsv_dynamics::DynError),
    /// The 3-D vehicle refused its parameters or failed to simulate.
    #[error(transparent)]
    Vehicle3d(#[from] vehicle_3d::VehicleError),
    /// A sidecar field the model needs is malformed or contradicts the model.
    #[error("sidecar field `{field}`: {reason}")]
    Sidecar {
        /// The field.
        field: &'static str,
        /// What is wrong.
        reason: String,
    },
    /// A calibrated parameter's name is not in its model's registry.
    #[error(transparent)]
    Param(#[from] vehicle_components::ParamError),
    /// A baseline vector of the wrong length was applied.
    #[error("a baseline vector has {got} values, the calibration set has {expected}")]
    BaselineLength {
        /// Size of the calibration set.
        expected: usize,
        /// Values given.
        got: usize,
    },
    /// A calibration switch was set to a reading it does not have.
    #[error("calibration switch `{switch}` has no reading {index}")]
    NoSuchReading {
        /// The switch.
        switch: &'static str,
        /// The reading asked for.
        index: usize,
    },
    /// A least-squares fit could not run.
    #[error(transparent)]
    Fit(#[from] optimize::least_squares::LeastSquaresError),
    /// An effect has no start point to scout.
    #[error("effect `{effect}`: no start point to scout")]
    NoStartPoint {
        /// Effect name.
        effect: String,
    },
    /// A hidden effect of `synth` is not in the catalogue.
    #[error("unknown effect `{effect}` (known: {known})")]
    UnknownHiddenEffect {
        /// The name given.
        effect: String,
        /// The catalogue's effect names, comma-separated.
        known: String,
    },
    /// A hidden effect was given twice.
    #[error("effect `{effect}` given twice")]
    EffectTwice {
        /// Effect name.
        effect: String,
    },
    /// A hidden effect's value is not a number.
    #[error("effect `{effect}`: `{text}` is not a number")]
    NotANumber {
        /// Effect name.
        effect: String,
        /// The text given.
        text: String,
    },
    /// A hidden effect was given the wrong number of values.
    #[error("effect `{effect}` takes {expected} value(s) ({names}), got {got}")]
    WrongValueCount {
        /// Effect name.
        effect: String,
        /// Values it takes.
        expected: usize,
        /// Their names, colon-separated.
        names: String,
        /// Values given.
        got: usize,
    },
    /// A hidden effect's value is outside its parameter's range.
    #[error("effect `{effect}`: {param} = {value} is outside [{lower}, {upper}]")]
    OutOfRange {
        /// Effect name.
        effect: String,
        /// Parameter name.
        param: String,
        /// The value given.
        value: f64,
        /// Lower bound.
        lower: f64,
        /// Upper bound.
        upper: f64,
    },
    /// A record could not be built, read or written (a malformed cell, a refused sign
    /// convention, a file that cannot be opened).
    #[error(transparent)]
    Record(#[from] afsv_records::RecordError),
    /// A file or folder could not be created or written.
    #[error("{path}: {source}")]
    Io {
        /// File or folder involved.
        path: PathBuf,
        /// Underlying error.
        source: std::io::Error,
    },
    /// A result could not be serialised as JSON.
    #[error(transparent)]
    Json(#[from] serde_json::Error),
    /// An SVG plot of the report could not be written (feature `plots`).
    #[error("{0}")]
    Plot(String),
}

impl DiscoveryError {
    /// An I/O error on `path`.
    pub fn io(path: impl Into<PathBuf>, source: std::io::Error) -> Self {
        Self::Io {
            path: path.into(),
            source,
        }
    }

    /// This error, about the record labelled `record`.
    pub fn in_record(self, record: impl Into<String>) -> Self {
        Self::InRecord {
            record: record.into(),
            source: Box::new(self),
        }
    }
}
