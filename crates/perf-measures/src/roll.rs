//! Roll stability measures (section 2.3, section 6.4): lateral load transfer ratio
//! (Eq 2.11), the smooth-road dynamic rollover threshold (DRT), the sustained period of
//! near-unity LTR and the proposed SP-DRT, and the static stability factor.

use crate::error::{finite_series, invalid, positive, same_len, time_series, MeasureError};
use crate::signal::{interp_crossing, trapz_rms};
use serde::{Deserialize, Serialize};

/// Lateral load transfer ratio of one instant (Eq 2.11):
/// `LTR = |sum_j (F_zLj - F_zRj)| / sum_j (F_zLj + F_zRj)` over the axles `j`, with
/// `left[j]`, `right[j]` the tire normal forces (N) of the left and right track. Normal
/// forces are clamped at zero (a lifted tire carries none), so `0 <= LTR <= 1`.
pub fn ltr(left_n: &[f64], right_n: &[f64]) -> Result<f64, MeasureError> {
    same_len("left_n", left_n, "right_n", right_n)?;
    finite_series("left_n", left_n, 1)?;
    finite_series("right_n", right_n, 1)?;
    let l: f64 = left_n.iter().map(|v| v.max(0.0)).sum();
    let r: f64 = right_n.iter().map(|v| v.max(0.0)).sum();
    if l + r <= 0.0 {
        return Err(invalid(
            "normal forces",
            "the total normal load must be > 0",
        ));
    }
    Ok(((l - r) / (l + r)).abs())
}

/// Eq 2.11 for a two-axle vehicle, per sample: front-left, front-right, rear-left,
/// rear-right tire normal forces (N).
pub fn ltr_two_axle(
    fz_lf: &[f64],
    fz_rf: &[f64],
    fz_lr: &[f64],
    fz_rr: &[f64],
) -> Result<Vec<f64>, MeasureError> {
    same_len("fz_lf", fz_lf, "fz_rf", fz_rf)?;
    same_len("fz_lf", fz_lf, "fz_lr", fz_lr)?;
    same_len("fz_lf", fz_lf, "fz_rr", fz_rr)?;
    (0..fz_lf.len())
        .map(|i| ltr(&[fz_lf[i], fz_lr[i]], &[fz_rf[i], fz_rr[i]]))
        .collect()
}

/// Static stability factor `SSF = T / h` (section 2.3): half track `T` over the cg height
/// `h` (both m), the lateral acceleration (in g) at which a rigid vehicle tips over.
pub fn static_stability_factor(half_track_m: f64, cg_height_m: f64) -> Result<f64, MeasureError> {
    positive("half_track_m", half_track_m)?;
    positive("cg_height_m", cg_height_m)?;
    Ok(half_track_m / cg_height_m)
}

/// A point of a roll history.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RollPoint {
    /// Time (s).
    pub time_s: f64,
    /// Lateral acceleration there (m/s^2), linearly interpolated.
    pub lateral_accel_m_s2: f64,
}

fn check_roll(t: &[f64], ltr: &[f64], ay: &[f64]) -> Result<(), MeasureError> {
    time_series(t, 2)?;
    same_len("t", t, "ltr", ltr)?;
    same_len("t", t, "lateral_accel", ay)?;
    finite_series("ltr", ltr, 2)?;
    finite_series("lateral_accel", ay, 2)
}

fn check_threshold(x: f64) -> Result<f64, MeasureError> {
    if x.is_finite() && x > 0.0 && x <= 1.0 {
        Ok(x)
    } else {
        Err(invalid("threshold", format!("{x} must lie in (0, 1]")))
    }
}

/// Smooth-road dynamic rollover threshold (section 2.3, point A of Fig 2.8): the lateral
/// acceleration when the LTR first reaches `threshold` (1 for wheel lift-off; pass e.g.
/// 0.999 for simulated forces that approach 1 asymptotically). Time and acceleration are
/// interpolated linearly at the crossing.
pub fn smooth_road_drt(
    t: &[f64],
    ltr: &[f64],
    lateral_accel: &[f64],
    threshold: f64,
) -> Result<RollPoint, MeasureError> {
    check_roll(t, ltr, lateral_accel)?;
    let thr = check_threshold(threshold)?;
    if ltr[0] >= thr {
        return Ok(RollPoint {
            time_s: t[0],
            lateral_accel_m_s2: lateral_accel[0],
        });
    }
    let i = (1..t.len())
        .find(|&i| ltr[i] >= thr)
        .ok_or_else(|| MeasureError::NotFound(format!("the LTR never reaches {thr}")))?;
    let (time_s, a) = interp_crossing(t, ltr, Some(lateral_accel), i - 1, thr);
    Ok(RollPoint {
        time_s,
        lateral_accel_m_s2: a,
    })
}

/// Definition of the sustained period of near-unity LTR (section 2.3, Fig 2.9(b): A3 to
/// A4; section 6.4, Fig 6.13: A to B). All three criteria are explicit.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SustainedPeriodParams {
    /// LTR at or above this counts as "near unity" (default 0.95).
    pub threshold: f64,
    /// Dips below the threshold lasting at most this long (s) do not break the period
    /// (default 0.5 s).
    pub max_dip_s: f64,
    /// A period must last at least this long (s) to count (default 1 s).
    pub min_duration_s: f64,
    /// If set, a final stretch in which the LTR stays at or above this level without any
    /// dip up to the end of the record is the wheel-lift-off phase leading to absolute
    /// rollover (A4 to B' in Fig 2.9(b), B to C in Fig 6.13); it ends the sustained period
    /// and is excluded from it (default `Some(0.999)`). `None` keeps it.
    pub lift_off_level: Option<f64>,
}

impl Default for SustainedPeriodParams {
    fn default() -> Self {
        SustainedPeriodParams {
            threshold: 0.95,
            max_dip_s: 0.5,
            min_duration_s: 1.0,
            lift_off_level: Some(0.999),
        }
    }
}

impl SustainedPeriodParams {
    /// Check the parameters.
    pub fn validate(&self) -> Result<(), MeasureError> {
        check_threshold(self.threshold)?;
        if !(self.max_dip_s.is_finite() && self.max_dip_s >= 0.0) {
            return Err(invalid(
                "max_dip_s",
                format!("{} must be finite and >= 0", self.max_dip_s),
            ));
        }
        if !(self.min_duration_s.is_finite() && self.min_duration_s >= 0.0) {
            return Err(invalid(
                "min_duration_s",
                format!("{} must be finite and >= 0", self.min_duration_s),
            ));
        }
        if let Some(l) = self.lift_off_level {
            if !(l.is_finite() && l >= self.threshold && l <= 1.0) {
                return Err(invalid(
                    "lift_off_level",
                    format!("{l} must lie in [threshold, 1]"),
                ));
            }
        }
        Ok(())
    }
}

/// The sustained period and the SP-DRT.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SustainedPeriod {
    /// Start of the period (s), point A3 / A.
    pub start_s: f64,
    /// End of the period (s), point A4 / B.
    pub end_s: f64,
    /// Duration `Delta T` (s).
    pub duration_s: f64,
    /// SP-DRT: RMS lateral acceleration over the period (m/s^2, trapezoidal in time).
    pub sp_drt_m_s2: f64,
    /// Lowest and highest lateral acceleration within the period (m/s^2).
    pub lateral_accel_range_m_s2: (f64, f64),
    /// Fraction of the period with LTR at or above the threshold.
    pub fraction_above_threshold: f64,
    /// Number of tolerated dips inside the period.
    pub dips: usize,
    /// Start of the excluded final lift-off phase (s), if one was found.
    pub lift_off_start_s: Option<f64>,
    /// Sample indices `[first, last]` of the period.
    pub sample_range: (usize, usize),
}

/// Find the sustained period of near-unity LTR before absolute rollover and its SP-DRT
/// (section 2.3: "the RMS lateral acceleration response over the sustained period of unity
/// LTR value"; section 6.4). The record should end at (or shortly after) absolute
/// rollover. Runs of `ltr >= threshold` are merged across dips no longer than `max_dip_s`;
/// the final lift-off phase is cut off (see [`SustainedPeriodParams::lift_off_level`]); the
/// last merged run lasting at least `min_duration_s` is the sustained period.
pub fn sustained_period(
    t: &[f64],
    ltr: &[f64],
    lateral_accel: &[f64],
    params: &SustainedPeriodParams,
) -> Result<SustainedPeriod, MeasureError> {
    check_roll(t, ltr, lateral_accel)?;
    params.validate()?;
    let n = t.len();
    // Cut off the final lift-off phase.
    let mut end = n; // exclusive
    let mut lift_off_start_s = None;
    if let Some(level) = params.lift_off_level {
        let mut k = n;
        while k > 0 && ltr[k - 1] >= level {
            k -= 1;
        }
        if k < n {
            lift_off_start_s = Some(t[k]);
            end = k + 1; // the period may run up to the lift-off instant
        }
    }
    // Runs of ltr >= threshold as [first, last] sample indices.
    let thr = params.threshold;
    let mut runs: Vec<(usize, usize)> = Vec::new();
    let mut i = 0;
    while i < end {
        if ltr[i] >= thr {
            let s = i;
            while i + 1 < end && ltr[i + 1] >= thr {
                i += 1;
            }
            runs.push((s, i));
        }
        i += 1;
    }
    // Merge across short dips (the dip lasts from the last sample above to the next one).
    let mut merged: Vec<(usize, usize, usize)> = Vec::new(); // (first, last, dips)
    for (s, e) in runs {
        match merged.last_mut() {
            Some(last) if t[s] - t[last.1] <= params.max_dip_s + 1e-12 => {
                last.1 = e;
                last.2 += 1;
            }
            _ => merged.push((s, e, 0)),
        }
    }
    let (first, last, dips) = merged
        .into_iter()
        .rev()
        .find(|&(s, e, _)| t[e] - t[s] >= params.min_duration_s && e > s)
        .ok_or_else(|| {
            MeasureError::NotFound(format!(
                "no period with LTR >= {thr} lasting >= {} s (dips <= {} s tolerated) before the lift-off phase",
                params.min_duration_s, params.max_dip_s
            ))
        })?;
    let duration = t[last] - t[first];
    let above: f64 = (first..last)
        .map(|k| {
            let (a, b) = (ltr[k] >= thr, ltr[k + 1] >= thr);
            let dt = t[k + 1] - t[k];
            match (a, b) {
                (true, true) => dt,
                (false, false) => 0.0,
                _ => 0.5 * dt,
            }
        })
        .sum();
    let seg = &lateral_accel[first..=last];
    Ok(SustainedPeriod {
        start_s: t[first],
        end_s: t[last],
        duration_s: duration,
        sp_drt_m_s2: trapz_rms(t, lateral_accel, first, last),
        lateral_accel_range_m_s2: (
            seg.iter().copied().fold(f64::INFINITY, f64::min),
            seg.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        ),
        fraction_above_threshold: above / duration,
        dips,
        lift_off_start_s,
        sample_range: (first, last),
    })
}
