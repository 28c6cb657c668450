//! The roll measures of one run (section 2.3) through `perf_measures::roll`: LTR
//! (Eq 2.11, recorded per sample), the smooth-road DRT (first LTR >= the lift-off level,
//! point A of Fig 2.8), the sustained period of near-unity LTR and its RMS lateral
//! acceleration (SP-DRT, A³ to A⁴ of Fig 2.9), the lateral acceleration at A⁴ and at
//! absolute rollover B′, the peak, and the SSF of the whole truck. Accelerations are
//! magnitudes (a left and a right ramp give the same numbers) reported in g = 9.80665.

use perf_measures::roll::{smooth_road_drt, sustained_period, SustainedPeriodParams};
use serde::Serialize;
use vehicle_components::{FlatTerrain, DEFAULT_FRICTION};

use crate::error::TruckError;
use crate::params::TruckParams;
use crate::simulate::{simulate, RunOptions, RunRecord};
use crate::statics::Statics;
use crate::vehicle::{ModelOptions, TruckVehicle};

/// Standard gravity for reporting in g (the fixtures' convention).
pub const G_REPORT: f64 = 9.80665;

/// LTR level that counts as unity (simulated normal forces reach exactly zero, so LTR
/// reaches 1 exactly; the level guards against rounding).
pub const LIFT_OFF_LTR: f64 = 0.999;

/// Roll measures of one run (module docs); `None` where the run gives none.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RollMeasures {
    /// DRT: |a_y| when the LTR first reaches [`LIFT_OFF_LTR`] (g).
    pub drt_g: Option<f64>,
    /// Time of that first crossing (s).
    pub drt_time_s: Option<f64>,
    /// SP-DRT: RMS |a_y| over the sustained period (g).
    pub sp_drt_g: Option<f64>,
    /// Start of the sustained period A³ (s).
    pub sustained_start_s: Option<f64>,
    /// End of the sustained period A⁴ (s), where the LTR stays at unity to rollover.
    pub sustained_end_s: Option<f64>,
    /// Duration ΔT of the sustained period (s).
    pub sustained_period_s: Option<f64>,
    /// Lowest and highest |a_y| within the sustained period (g).
    pub sustained_range_g: Option<(f64, f64)>,
    /// |a_y| at A⁴ (g).
    pub ay_at_a4_g: Option<f64>,
    /// |a_y| at absolute rollover B′ (g).
    pub ay_at_rollover_g: Option<f64>,
    /// Peak |a_y| over the run (g): the whole-vehicle cg channel of the sum of the tire
    /// forces (the project's a_y).
    pub peak_ay_g: f64,
    /// Peak |a_y| of the sprung-mass cg, horizontal in the heading frame (g); `None`
    /// unless the run recorded the channel (`RunOptions::acceleration_channels`).
    pub peak_sprung_ay_g: Option<f64>,
    /// Peak |reading| of a lateral accelerometer fixed to the sprung mass at its cg (g):
    /// includes `g sin(phi)` of the sprung roll `phi`; `None` as above.
    pub peak_sensor_ay_g: Option<f64>,
    /// Time of the first bump-stop contact of any strut (s).
    pub first_bump_stop_s: Option<f64>,
    /// Time of the first sample with every wheel off the ground (s); the LTR reads 0 there.
    pub first_airborne_s: Option<f64>,
    /// Time spent with every wheel off the ground (s): the sum of the output intervals
    /// that end on an airborne sample.
    pub airborne_time_s: f64,
    /// Peak |a_y| (whole-vehicle channel) before the first bump-stop contact (g); the whole
    /// run's peak if no strut reaches its stop.
    pub peak_ay_before_stop_g: f64,
    /// Time of absolute rollover (s).
    pub rollover_s: Option<f64>,
    /// SSF of the whole truck: mean half track of the axles (weighted by static axle load,
    /// outer duals at the rear) over the whole-vehicle cg height (-).
    pub ssf: f64,
}

/// SSF of the whole truck (section 2.3, L666): load-weighted half track (front track,
/// rear outer duals) over the whole-vehicle cg height, unsprung cg at the wheel centres.
pub fn ssf(p: &TruckParams) -> f64 {
    let s = Statics::of(p);
    let (front, rear) = (2.0 * s.front_tire_load_n, 4.0 * s.rear_tire_load_n);
    let half_track = (front * 0.5 * p.front_track_m
        + rear * 0.5 * (p.rear_track_m + p.dual_spacing_m))
        / (front + rear);
    let wheel_z =
        p.tire_free_radius_m - 0.5 * (s.front_tire_deflection_m + s.rear_tire_deflection_m);
    let unsprung = p.front_unsprung_mass_kg + p.rear_unsprung_mass_kg;
    let h = (p.sprung_mass_kg * p.cg_height_m + unsprung * wheel_z) / p.total_mass_kg();
    half_track / h
}

/// Largest |x| of a recorded channel, `None` if it was not recorded (empty).
fn recorded_peak(x: &[f64]) -> Option<f64> {
    (!x.is_empty()).then(|| x.iter().fold(0.0_f64, |m, a| m.max(a.abs())))
}

/// Interpolated |a_y| at time `t` of the record.
fn ay_at(rec: &RunRecord, t: f64) -> Option<f64> {
    let i = rec.t_s.iter().position(|&x| x >= t)?;
    if i == 0 {
        return Some(rec.lateral_accel_m_s2[0].abs());
    }
    let (t0, t1) = (rec.t_s[i - 1], rec.t_s[i]);
    let w = if t1 > t0 { (t - t0) / (t1 - t0) } else { 1.0 };
    let (a0, a1) = (rec.lateral_accel_m_s2[i - 1], rec.lateral_accel_m_s2[i]);
    Some((a0 + w * (a1 - a0)).abs())
}

/// The measures of `rec` for the truck `p` with the sustained-period definition `sp`.
pub fn roll_measures(
    p: &TruckParams,
    rec: &RunRecord,
    sp: &SustainedPeriodParams,
) -> Result<RollMeasures, TruckError> {
    let ay: Vec<f64> = rec.lateral_accel_m_s2.iter().map(|a| a.abs()).collect();
    let g = |x: f64| x / G_REPORT;
    let first = smooth_road_drt(&rec.t_s, &rec.ltr, &ay, LIFT_OFF_LTR).ok();
    let period = sustained_period(&rec.t_s, &rec.ltr, &ay, sp).ok();
    let peak_of = |x: &[f64]| x.iter().fold(0.0_f64, |m, a| m.max(a.abs()));
    let peak = peak_of(&ay);
    let stop = rec.on_bump_stop.iter().position(|b| *b);
    // a fold from +0: `sum` of no terms is -0, which a report would print as "-0.0"
    let airborne_time_s = (1..rec.t_s.len())
        .filter(|&i| rec.airborne[i])
        .map(|i| rec.t_s[i] - rec.t_s[i - 1])
        .fold(0.0, |total, dt| total + dt);
    Ok(RollMeasures {
        drt_g: first.map(|a| g(a.lateral_accel_m_s2)),
        drt_time_s: first.map(|a| a.time_s),
        sp_drt_g: period.as_ref().map(|s| g(s.sp_drt_m_s2)),
        sustained_start_s: period.as_ref().map(|s| s.start_s),
        sustained_end_s: period.as_ref().map(|s| s.end_s),
        sustained_period_s: period.as_ref().map(|s| s.duration_s),
        sustained_range_g: period.as_ref().map(|s| {
            let (lo, hi) = s.lateral_accel_range_m_s2;
            (g(lo), g(hi))
        }),
        ay_at_a4_g: period.as_ref().and_then(|s| ay_at(rec, s.end_s)).map(g),
        ay_at_rollover_g: rec.rollover_s.and_then(|t| ay_at(rec, t)).map(g),
        peak_ay_g: g(peak),
        peak_sprung_ay_g: recorded_peak(&rec.sprung_lateral_accel_m_s2).map(g),
        peak_sensor_ay_g: recorded_peak(&rec.sprung_sensor_lateral_accel_m_s2).map(g),
        first_bump_stop_s: stop.map(|i| rec.t_s[i]),
        first_airborne_s: rec.airborne.iter().position(|b| *b).map(|i| rec.t_s[i]),
        airborne_time_s,
        peak_ay_before_stop_g: g(peak_of(&ay[..stop.unwrap_or(ay.len())])),
        rollover_s: rec.rollover_s,
        ssf: ssf(p),
    })
}

/// Level ground at zero elevation with the default friction.
pub fn level_ground() -> FlatTerrain {
    FlatTerrain::new(0.0, DEFAULT_FRICTION).expect("zero height and the default friction are valid")
}

/// Smooth-road DRT (g) of the truck `p`: a left ramp on level ground to rollover.
pub fn smooth_drt_g(p: &TruckParams) -> Result<f64, TruckError> {
    let vehicle = TruckVehicle::new(p, &level_ground(), 1.0, ModelOptions::default())?;
    let rec = simulate(&vehicle, &RunOptions::default())?;
    let m = roll_measures(p, &rec, &SustainedPeriodParams::default())?;
    m.drt_g
        .ok_or_else(|| vehicle_run::measure("drt", "the LTR never reaches unity"))
}
