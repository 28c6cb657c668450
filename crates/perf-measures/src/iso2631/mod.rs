//! ISO 2631-1:1997 whole-body vibration: frequency weightings (Annex A), their digital
//! realisations, the tabulated factors, and the exposure measures (clauses 6-7, Annex B,
//! EU directive 2002/44/EC).

pub mod check;
pub mod exposure;
pub mod filter;
pub mod table;
pub mod weighting;

pub use check::{weighting_check, weighting_check_at, WeightingCheck, WeightingCheckEntry};
pub use exposure::{
    assess_whole_body, axis_exposure, crest_factor, daily_exposure_a8, eu_level,
    health_guidance_zone, mtvv, running_rms, vdv, vibration_total_value, Axis, AxisExposure,
    AxisInput, EuLevel, HealthGuidanceZone, HgczRelation, HgczZone, KFactors, WbvAssessment,
    EU_ACTION_VALUE_M_S2, EU_LIMIT_VALUE_M_S2,
};
pub use filter::{weight_fft, weight_iir, weight_time_history, FilterMethod, IirWeighting};
pub use weighting::{Weighting, WeightingParams};
