//! Performance measures of articulated frame-steered vehicles (AFSV):
//!
//! * [`iso2631`]: ISO 2631-1:1997 frequency weightings (Annex A) as analog transfer
//!   functions, digital filters and frequency-domain weighting; exposure measures
//!   (weighted RMS, `a_v` of Eq 1.1, crest factor, MTVV, VDV, A(8), EU 2002/44/EC values,
//!   Annex B caution zone) and the weighting check against the standard's tables.
//! * [`roll`]: LTR (Eq 2.11), smooth-road DRT, sustained period and SP-DRT (section 2.3),
//!   SSF.
//! * [`decay`]: free-decay single-DOF fit (yaw-mode frequency and damping, sections 3.3,
//!   4.3.1, 6.4).
//! * [`step`]: step detection in an input record, step-steer gain, 0-100 % rise time,
//!   overshoot (section 3.3).
//! * [`steering`]: steering power efficiency (Eq 4.7).
//! * [`seat`]: the SEAT value of a suspension seat (ISO 10326-1, EN ISO 7096), seat-pan over
//!   floor W_k-weighted RMS.
//!
//! Units are SI throughout; `docs/perf-measures.md` maps every equation to its code.

pub mod decay;
pub mod error;
pub mod iso2631;
pub mod roll;
pub mod seat;
pub mod signal;
pub mod steering;
pub mod step;

pub use decay::{decay_onset, fit_free_decay, not_one_mode, DecayFit, DECAY_RESIDUAL_NOISE_LIMIT};
pub use error::MeasureError;
pub use iso2631::{weighting_check, weighting_check_at, Weighting, WeightingCheck};
pub use roll::{
    ltr, ltr_two_axle, smooth_road_drt, static_stability_factor, sustained_period, RollPoint,
    SustainedPeriod, SustainedPeriodParams,
};
pub use seat::{seat_value, SeatValue};
pub use steering::steering_power_efficiency;
pub use step::{
    step_amplitude, step_metrics, step_metrics_with, step_time, StepMetrics, StepOptions,
};
