//! Whole-body vibration exposure (ISO 2631-1:1997 clauses 6-7 and Annex B; EU directive
//! 2002/44/EC): weighted RMS per axis, combined `a_v` (Eq 1.1), crest factor, running RMS
//! and MTVV, VDV, daily exposure A(8), the EU action/limit values and the health guidance
//! caution zone.

use super::filter::{weight_time_history, FilterMethod};
use super::weighting::Weighting;
use crate::error::{finite_scalar, finite_series, invalid, positive, MeasureError};
use serde::{Deserialize, Serialize};

/// EU directive 2002/44/EC daily exposure action value, A(8) (m/s^2).
pub const EU_ACTION_VALUE_M_S2: f64 = 0.5;
/// EU directive 2002/44/EC daily exposure limit value, A(8) (m/s^2).
pub const EU_LIMIT_VALUE_M_S2: f64 = 1.15;
/// Reference duration of A(8): 8 h in seconds.
pub const A8_REFERENCE_S: f64 = 8.0 * 3600.0;
/// Integration time of the running RMS for MTVV (ISO 2631-1 6.3.1, 1 s).
pub const MTVV_TAU_S: f64 = 1.0;

/// A translational seat axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Axis {
    /// Fore-aft.
    X,
    /// Lateral.
    Y,
    /// Vertical.
    Z,
}

impl Axis {
    /// ISO 2631-1 weighting for health on the seat pan (Table 1): Wd for x and y, Wk for z.
    pub fn health_weighting(self) -> Weighting {
        match self {
            Axis::X | Axis::Y => Weighting::Wd,
            Axis::Z => Weighting::Wk,
        }
    }
}

/// Multiplying factors `k` of Eq 1.1 (ISO 2631-1 7.2.3 and 8.2.2).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct KFactors {
    /// `k_x`.
    pub x: f64,
    /// `k_y`.
    pub y: f64,
    /// `k_z`.
    pub z: f64,
}

impl KFactors {
    /// Health, seated (ISO 2631-1 7.2.3): `k_x = k_y = 1.4`, `k_z = 1`.
    pub fn health() -> Self {
        KFactors {
            x: 1.4,
            y: 1.4,
            z: 1.0,
        }
    }

    /// Comfort, seat surface (ISO 2631-1 8.2.2.1): all 1.
    pub fn comfort() -> Self {
        KFactors {
            x: 1.0,
            y: 1.0,
            z: 1.0,
        }
    }

    /// The factor of `axis`.
    pub fn of(&self, axis: Axis) -> f64 {
        match axis {
            Axis::X => self.x,
            Axis::Y => self.y,
            Axis::Z => self.z,
        }
    }

    /// Check all three are finite and >= 0.
    pub fn validate(&self) -> Result<(), MeasureError> {
        for (f, v) in [("k_x", self.x), ("k_y", self.y), ("k_z", self.z)] {
            if !(v.is_finite() && v >= 0.0) {
                return Err(invalid(f, format!("{v} must be finite and >= 0")));
            }
        }
        Ok(())
    }
}

impl Default for KFactors {
    fn default() -> Self {
        Self::health()
    }
}

/// Combined vibration total value `a_v = sqrt(sum k_i^2 a_wi^2)` (Eq 1.1; ISO 2631-1
/// 6.5). Pass `0` for an axis that was not measured.
pub fn vibration_total_value(a_w: [f64; 3], k: &KFactors) -> Result<f64, MeasureError> {
    k.validate()?;
    for (f, v) in [("a_wx", a_w[0]), ("a_wy", a_w[1]), ("a_wz", a_w[2])] {
        if !(v.is_finite() && v >= 0.0) {
            return Err(invalid(f, format!("{v} must be finite and >= 0")));
        }
    }
    Ok(((k.x * a_w[0]).powi(2) + (k.y * a_w[1]).powi(2) + (k.z * a_w[2]).powi(2)).sqrt())
}

/// Crest factor: peak `|a_w(t)|` over the weighted RMS (ISO 2631-1 6.2.1).
pub fn crest_factor(weighted: &[f64]) -> Result<f64, MeasureError> {
    finite_series("weighted acceleration", weighted, 1)?;
    let rms = crate::signal::rms(weighted)?;
    if rms == 0.0 {
        return Err(invalid("weighted acceleration", "is identically zero"));
    }
    Ok(weighted.iter().fold(0.0f64, |m, v| m.max(v.abs())) / rms)
}

/// Running RMS with linear integration (ISO 2631-1 6.3.1):
/// `a_w(t0) = sqrt(1/tau * integral_{t0-tau}^{t0} a_w^2 dt)`, one value per sample from the
/// first complete window on (rectangle rule over `round(tau fs)` samples).
pub fn running_rms(weighted: &[f64], fs_hz: f64, tau_s: f64) -> Result<Vec<f64>, MeasureError> {
    positive("fs_hz", fs_hz)?;
    positive("tau_s", tau_s)?;
    let m = (tau_s * fs_hz).round().max(1.0) as usize;
    finite_series("weighted acceleration", weighted, m)?;
    let mut out = Vec::with_capacity(weighted.len() + 1 - m);
    // Sum recomputed exactly every window length to stop round-off drift.
    let mut acc: f64 = weighted[..m].iter().map(|v| v * v).sum();
    out.push((acc.max(0.0) / m as f64).sqrt());
    for i in m..weighted.len() {
        if (i - m + 1) % m == 0 {
            acc = weighted[i + 1 - m..=i].iter().map(|v| v * v).sum();
        } else {
            acc += weighted[i] * weighted[i] - weighted[i - m] * weighted[i - m];
        }
        out.push((acc.max(0.0) / m as f64).sqrt());
    }
    Ok(out)
}

/// Maximum transient vibration value: the largest 1-s running RMS (ISO 2631-1 6.3.1).
pub fn mtvv(weighted: &[f64], fs_hz: f64) -> Result<f64, MeasureError> {
    Ok(running_rms(weighted, fs_hz, MTVV_TAU_S)?
        .into_iter()
        .fold(0.0, f64::max))
}

/// Vibration dose value `VDV = (integral a_w^4 dt)^(1/4)` (ISO 2631-1 6.3.2), m/s^1.75,
/// rectangle rule with `dt = 1/fs`.
pub fn vdv(weighted: &[f64], fs_hz: f64) -> Result<f64, MeasureError> {
    positive("fs_hz", fs_hz)?;
    finite_series("weighted acceleration", weighted, 1)?;
    Ok((weighted.iter().map(|v| v.powi(4)).sum::<f64>() / fs_hz).powf(0.25))
}

/// Daily exposure `A(8) = a * sqrt(T / 8 h)` (2002/44/EC Annex A), with `a` the
/// (k-multiplied) weighted RMS and `T` the daily exposure duration in hours.
pub fn daily_exposure_a8(a_w_k: f64, exposure_hours: f64) -> Result<f64, MeasureError> {
    let a = finite_scalar("a_w", a_w_k)?;
    if a < 0.0 {
        return Err(invalid("a_w", format!("{a} must be >= 0")));
    }
    positive("exposure_hours", exposure_hours)?;
    Ok(a * (exposure_hours * 3600.0 / A8_REFERENCE_S).sqrt())
}

/// Position of A(8) relative to the EU 2002/44/EC values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum EuLevel {
    /// Below the action value 0.5 m/s^2.
    BelowAction,
    /// At or above the action value, below the limit value 1.15 m/s^2.
    AboveAction,
    /// At or above the limit value.
    AboveLimit,
}

/// Classify a daily exposure A(8) against the EU action and limit values.
pub fn eu_level(a8: f64) -> EuLevel {
    if a8 >= EU_LIMIT_VALUE_M_S2 {
        EuLevel::AboveLimit
    } else if a8 >= EU_ACTION_VALUE_M_S2 {
        EuLevel::AboveAction
    } else {
        EuLevel::BelowAction
    }
}

/// Which duration relation of ISO 2631-1 Annex B bounds the caution zone.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum HgczRelation {
    /// Eq B.1, `a_w T^(1/2) = const` (the usual energy-equivalent relation).
    #[default]
    SqrtTime,
    /// Eq B.2, `a_w T^(1/4) = const` (fourth-power, VDV-like relation).
    FourthRootTime,
}

/// Where a weighted RMS lies relative to the caution zone.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum HgczZone {
    /// Below the zone: health effects not clearly documented.
    Below,
    /// In the zone: caution with respect to potential health risks.
    Within,
    /// Above the zone: health risks are likely.
    Above,
}

/// The health guidance caution zone for one duration.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct HealthGuidanceZone {
    /// Exposure duration (h).
    pub duration_h: f64,
    /// Relation used.
    pub relation: HgczRelation,
    /// Lower boundary (m/s^2).
    pub lower_m_s2: f64,
    /// Upper boundary (m/s^2).
    pub upper_m_s2: f64,
    /// Whether the duration lies in the range of ISO 2631-1 Fig B.1 (10 min to 24 h).
    pub within_figure_range: bool,
}

/// Caution-zone boundaries at 8 h as drawn in ISO 2631-1:1997 Fig B.1 (m/s^2):
/// Eq B.1 lines pass through 3 and 6 m/s^2 at 10 min, i.e. 0.43 and 0.87 m/s^2 at 8 h;
/// Eq B.2 lines through 0.45 and 0.90 m/s^2 at 8 h.
fn hgcz_at_8h(rel: HgczRelation) -> (f64, f64) {
    match rel {
        HgczRelation::SqrtTime => (3.0 / 48f64.sqrt(), 6.0 / 48f64.sqrt()),
        HgczRelation::FourthRootTime => (0.45, 0.90),
    }
}

/// Health guidance caution zone of ISO 2631-1 Annex B (Fig B.1) for `duration_h` hours.
pub fn health_guidance_zone(
    duration_h: f64,
    relation: HgczRelation,
) -> Result<HealthGuidanceZone, MeasureError> {
    positive("duration_h", duration_h)?;
    let (lo8, hi8) = hgcz_at_8h(relation);
    let scale = match relation {
        HgczRelation::SqrtTime => (8.0 / duration_h).sqrt(),
        HgczRelation::FourthRootTime => (8.0 / duration_h).powf(0.25),
    };
    Ok(HealthGuidanceZone {
        duration_h,
        relation,
        lower_m_s2: lo8 * scale,
        upper_m_s2: hi8 * scale,
        within_figure_range: (10.0 / 60.0 - 1e-9..=24.0 + 1e-9).contains(&duration_h),
    })
}

impl HealthGuidanceZone {
    /// Where `a_w` (m/s^2) lies relative to this zone.
    pub fn classify(&self, a_w: f64) -> HgczZone {
        if a_w < self.lower_m_s2 {
            HgczZone::Below
        } else if a_w <= self.upper_m_s2 {
            HgczZone::Within
        } else {
            HgczZone::Above
        }
    }
}

/// ISO 2631-1 6.3.3 ratios above which the basic (RMS) method may underestimate effects.
pub const MTVV_RATIO_LIMIT: f64 = 1.5;
/// See [`MTVV_RATIO_LIMIT`]: VDV / (a_w T^(1/4)).
pub const VDV_RATIO_LIMIT: f64 = 1.75;

/// Exposure measures of one axis.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AxisExposure {
    /// Axis.
    pub axis: Axis,
    /// Weighting applied.
    pub weighting: Weighting,
    /// Multiplying factor `k` of the axis.
    pub k: f64,
    /// Weighted RMS acceleration `a_w` (m/s^2).
    pub a_w: f64,
    /// Crest factor.
    pub crest_factor: f64,
    /// Maximum transient vibration value, 1-s running RMS (m/s^2).
    pub mtvv: f64,
    /// Vibration dose value over the record (m/s^1.75).
    pub vdv: f64,
    /// MTVV / a_w (ISO 2631-1 6.3.3: above 1.5 the basic method may underestimate).
    pub mtvv_ratio: f64,
    /// VDV / (a_w T^(1/4)) (above 1.75 the basic method may underestimate).
    pub vdv_ratio: f64,
}

/// Exposure measures of one axis' unweighted acceleration record `accel` (m/s^2) sampled
/// at `fs_hz`.
pub fn axis_exposure(
    axis: Axis,
    weighting: Weighting,
    k: f64,
    accel: &[f64],
    fs_hz: f64,
    method: FilterMethod,
) -> Result<AxisExposure, MeasureError> {
    let weighted = weight_time_history(weighting, accel, fs_hz, method)?;
    let a_w = crate::signal::rms(&weighted)?;
    let duration = accel.len() as f64 / fs_hz;
    let (cf, mt, v) = if a_w > 0.0 {
        (
            crest_factor(&weighted)?,
            mtvv(&weighted, fs_hz)?,
            vdv(&weighted, fs_hz)?,
        )
    } else {
        (0.0, 0.0, 0.0)
    };
    let ratio = |num: f64, den: f64| if den > 0.0 { num / den } else { 0.0 };
    Ok(AxisExposure {
        axis,
        weighting,
        k,
        a_w,
        crest_factor: cf,
        mtvv: mt,
        vdv: v,
        mtvv_ratio: ratio(mt, a_w),
        vdv_ratio: ratio(v, a_w * duration.powf(0.25)),
    })
}

/// One measured axis for [`assess_whole_body`].
#[derive(Debug, Clone, Copy)]
pub struct AxisInput<'a> {
    /// Axis.
    pub axis: Axis,
    /// Weighting (use [`Axis::health_weighting`] for the seat-pan health assessment).
    pub weighting: Weighting,
    /// Unweighted acceleration (m/s^2).
    pub accel: &'a [f64],
}

/// Whole-body vibration assessment of a seat record.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WbvAssessment {
    /// Record duration (s).
    pub record_duration_s: f64,
    /// Sampling rate (Hz).
    pub fs_hz: f64,
    /// Weighting method.
    pub method: FilterMethod,
    /// Per-axis measures.
    pub axes: Vec<AxisExposure>,
    /// `k` factors.
    pub k: KFactors,
    /// Vibration total value `a_v` (Eq 1.1), unmeasured axes count as zero (m/s^2).
    pub a_v: f64,
    /// Highest `k a_w` over the axes (m/s^2), the value the health assessment and A(8) use.
    pub max_k_a_w: f64,
    /// Axis of [`Self::max_k_a_w`].
    pub governing_axis: Axis,
    /// Daily exposure duration (h).
    pub exposure_hours: f64,
    /// Daily exposure A(8) from the governing axis (m/s^2).
    pub a8: f64,
    /// EU 2002/44/EC action value (m/s^2).
    pub eu_action_value: f64,
    /// EU 2002/44/EC limit value (m/s^2).
    pub eu_limit_value: f64,
    /// A(8) relative to the EU values.
    pub eu_level: EuLevel,
    /// Caution zone for the exposure duration (Eq B.1).
    pub hgcz: HealthGuidanceZone,
    /// Where [`Self::max_k_a_w`] lies relative to the caution zone.
    pub hgcz_zone: HgczZone,
}

/// Assess a seat record: per-axis exposure, `a_v` (Eq 1.1), A(8), EU level and caution
/// zone for a daily exposure of `exposure_hours`.
pub fn assess_whole_body(
    inputs: &[AxisInput<'_>],
    fs_hz: f64,
    exposure_hours: f64,
    k: KFactors,
    method: FilterMethod,
) -> Result<WbvAssessment, MeasureError> {
    k.validate()?;
    positive("fs_hz", fs_hz)?;
    positive("exposure_hours", exposure_hours)?;
    if inputs.is_empty() {
        return Err(invalid("axes", "at least one axis is needed"));
    }
    let n = inputs[0].accel.len();
    let mut axes = Vec::with_capacity(inputs.len());
    let mut a_w = [0.0; 3];
    for inp in inputs {
        if inp.accel.len() != n {
            return Err(MeasureError::LengthMismatch {
                a: "first axis",
                len_a: n,
                b: "another axis",
                len_b: inp.accel.len(),
            });
        }
        let idx = inp.axis as usize;
        if axes.iter().any(|a: &AxisExposure| a.axis == inp.axis) {
            return Err(invalid("axes", format!("axis {:?} given twice", inp.axis)));
        }
        let e = axis_exposure(
            inp.axis,
            inp.weighting,
            k.of(inp.axis),
            inp.accel,
            fs_hz,
            method,
        )?;
        a_w[idx] = e.a_w;
        axes.push(e);
    }
    let a_v = vibration_total_value(a_w, &k)?;
    let (governing_axis, max_k_a_w) = axes.iter().map(|a| (a.axis, a.k * a.a_w)).fold(
        (axes[0].axis, f64::NEG_INFINITY),
        |m, v| if v.1 > m.1 { v } else { m },
    );
    let a8 = daily_exposure_a8(max_k_a_w, exposure_hours)?;
    let hgcz = health_guidance_zone(exposure_hours, HgczRelation::SqrtTime)?;
    Ok(WbvAssessment {
        record_duration_s: n as f64 / fs_hz,
        fs_hz,
        method,
        a_v,
        max_k_a_w,
        governing_axis,
        exposure_hours,
        a8,
        eu_action_value: EU_ACTION_VALUE_M_S2,
        eu_limit_value: EU_LIMIT_VALUE_M_S2,
        eu_level: eu_level(a8),
        hgcz_zone: hgcz.classify(max_k_a_w),
        hgcz,
        k,
        axes,
    })
}

/// Validate and return a weighted record's RMS (convenience for callers holding an
/// already-weighted series).
pub fn weighted_rms(weighted: &[f64]) -> Result<f64, MeasureError> {
    finite_series("weighted acceleration", weighted, 1)?;
    crate::signal::rms(weighted)
}
