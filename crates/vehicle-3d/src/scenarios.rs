//! The design scenarios of section 6.4 and their measures, over terrain seeds:
//!
//! - **D1, ride** ([`ride`]): straight at 20 km/h on 100 m of class E two-track terrain
//!   (m_c 0.3) after a 20 m run-in; `a_wz` is the W_k-weighted RMS vertical acceleration of
//!   the front unit at the cab point (ISO 2631-1, L1837), `d_s` the largest peak-to-peak
//!   front strut travel (Eq 6.19), and the dominant vertical and pitch frequencies of the
//!   Welch PSDs (section 6.3);
//! - **D2, roll** ([`roll`]): ramp steer 5 deg/s from t = 1 s at 50 km/h, loaded, to the rear
//!   unit's absolute rollover; SP-DRT = RMS of the rear unit's lateral acceleration over the
//!   sustained period of |LTR| = 1 of the rear axle (L1843, Eq 2.11 on the rear axle);
//! - **D3, yaw** ([`yaw`]): a 0.2 s half-sine steering-wheel pulse at t = 1 s at 50 km/h,
//!   loaded; the articulation's free oscillation after the pulse is fitted to a single-DOF
//!   response: `omega_z` (Hz) and `zeta` (L1851);
//! - **V3, path change** ([`path_change`]): the field course of Fig 3.6(b) / section 6.3
//!   (4.5 m lateral offset over an 18 m gate after a 20 m approach) at the Table 3.2 mean
//!   speeds (loaded 15.3 km/h, unloaded 19.2 km/h), steered by the yaw-plane model's
//!   pure-pursuit `PathDriver`; the Fig 6.12 channels (articulation, left-strut
//!   displacement, front-unit yaw rate and lateral acceleration), their peaks and the
//!   largest lateral deviation of the front axle from the course.
//!
//! Every rough-terrain number is a mean and SD over seeds ([`Spread`]); variants of one study
//! use the same seeds (common random numbers).

use perf_measures::iso2631::weight_fft;
use perf_measures::roll::{sustained_period, SustainedPeriodParams};
use perf_measures::Weighting;
use rayon::prelude::*;
use serde::Serialize;
use terrain_psd::{
    synthesize, welch_psd, Band, CoherenceModel, IsoClass, PowerLawPsd, SurfaceParams,
    TwoTrackProfile, TwoTrackSpec, TwoTrackTerrain, WelchConfig,
};
use vehicle_components::FlatTerrain;
use vehicle_components::SteerInput;

use crate::error::{measure, positive, VehicleError};
use crate::model::FrontAxle;
use crate::params::{Load, VehicleParams};
use crate::simulate::{simulate, RunOptions, RunRecord};
use crate::tires::TireTracks;
use crate::vehicle::{Vehicle, VehicleOptions};

pub use crate::path_change::{
    path_change, path_change_measures, PathChangeMeasures, PathChangeSpec,
};
use std::sync::Arc;

/// Sample spacing of the synthesized profiles (m).
pub const TERRAIN_DX_M: f64 = 0.05;

/// Output interval of the scenario runs (s): 200 Hz, well above the W_k band of interest.
pub const OUTPUT_DT_S: f64 = 0.005;

/// Run-in before the ride window (m), excluded from a_wz (note 2.10).
pub const RUN_IN_M: f64 = 20.0;

/// The two-track terrain of a run (Eqs 6.4-6.5).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TerrainSpec {
    /// ISO 8608 class of the displacement PSD (Eq 6.4): E for design, C for validation.
    pub class: IsoClass,
    /// Coherence cut-off m_c (cycles/m), Eq 6.5: 0.3.
    pub m_c: f64,
    /// Synthesised band (cycles/m). Assumption: 0.02-5 as in Chapter 2.
    pub band: (f64, f64),
}

impl Default for TerrainSpec {
    fn default() -> Self {
        Self {
            class: IsoClass::E,
            m_c: 0.3,
            band: (0.02, 5.0),
        }
    }
}

impl TerrainSpec {
    /// A terrain of this spec from `seed`, `length_m` long, with the vehicle's front track.
    pub fn build(
        &self,
        p: &VehicleParams,
        length_m: f64,
        seed: u64,
    ) -> Result<TwoTrackTerrain, VehicleError> {
        let spec = TwoTrackSpec::new(
            PowerLawPsd::iso(self.class),
            Band::new(self.band.0, self.band.1)?,
            CoherenceModel::piecewise(self.m_c)?,
        )?;
        let profile = synthesize(&spec, length_m, TERRAIN_DX_M, seed)?;
        Ok(TwoTrackTerrain::new(profile, surface_of(p))?)
    }
}

/// Mean, SD and count of a measure over seeds.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Spread {
    /// Mean.
    pub mean: f64,
    /// Sample standard deviation (0 for one value).
    pub sd: f64,
    /// Number of values.
    pub n: usize,
}

impl Spread {
    /// The spread of `values` (at least one, all finite).
    pub fn of(values: &[f64]) -> Result<Self, VehicleError> {
        if values.is_empty() || values.iter().any(|v| !v.is_finite()) {
            return Err(measure("spread", "needs at least one finite value"));
        }
        let n = values.len();
        let mean = values.iter().sum::<f64>() / n as f64;
        let sd = if n > 1 {
            (values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1) as f64).sqrt()
        } else {
            0.0
        };
        Ok(Self { mean, sd, n })
    }

    /// The spread of `values`, or NaN mean and SD with `n = 0` when nothing was measured
    /// (a measure a study left out: JSON prints it as null with a reason).
    pub fn of_measured(values: &[f64]) -> Result<Self, VehicleError> {
        if values.is_empty() {
            Ok(Self {
                mean: f64::NAN,
                sd: f64::NAN,
                n: 0,
            })
        } else {
            Self::of(values)
        }
    }
}

/// Measures of one D1 ride run.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RideMeasures {
    /// a_wz: W_k-weighted RMS vertical acceleration at the cab point (m/s²).
    pub a_wz_m_s2: f64,
    /// Unweighted RMS vertical acceleration at the cab point (m/s²).
    pub a_z_rms_m_s2: f64,
    /// d_s: largest peak-to-peak travel of the two front struts (m); None unsuspended.
    pub strut_travel_p2p_m: Option<f64>,
    /// The same of the two rear struts (m); None on a rigid rear axle (and then left out
    /// of the JSON).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rear_strut_travel_p2p_m: Option<f64>,
    /// Frequency of the vertical-acceleration PSD peak, 0.5-10 Hz (Hz).
    pub vertical_peak_hz: f64,
    /// Frequency of the pitch-acceleration PSD peak, 0.5-10 Hz (Hz).
    pub pitch_peak_hz: f64,
}

/// Settings of a ride run.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RideSpec {
    /// Load case.
    pub load: Load,
    /// Front axle.
    pub front_axle: FrontAxle,
    /// Speed (km/h): 20 for D1.
    pub speed_kmh: f64,
    /// Length of the measured window (m): 100 for D1.
    pub length_m: f64,
    /// Terrain.
    pub terrain: TerrainSpec,
}

impl RideSpec {
    /// D1 of section 6.4 for `load` and `front_axle`.
    pub fn d1(load: Load, front_axle: FrontAxle) -> Self {
        Self {
            load,
            front_axle,
            speed_kmh: 20.0,
            length_m: 100.0,
            terrain: TerrainSpec::default(),
        }
    }
}

/// Start of the ride runs' path on the terrain (m).
const RIDE_START_M: f64 = 15.0;

/// The vehicle options of a ride run.
pub(crate) fn ride_options(spec: &RideSpec) -> VehicleOptions {
    VehicleOptions {
        front_axle: spec.front_axle,
        speed_m_s: spec.speed_kmh / 3.6,
        path_length_m: RUN_IN_M + spec.length_m + 5.0,
        start_s_m: RIDE_START_M,
        ..VehicleOptions::default()
    }
}

/// The enveloping cache of a ride run on terrain `seed`: it depends on the load case, the
/// tire and the terrain, not on the suspension, so the rigid and the HPS vehicle and every
/// HPS design share it ([`ride_on`]).
pub fn ride_tracks(
    p: &VehicleParams,
    spec: &RideSpec,
    seed: u64,
) -> Result<Arc<TireTracks>, VehicleError> {
    positive("speed_kmh", spec.speed_kmh)?;
    positive("length_m", spec.length_m)?;
    let terrain = spec
        .terrain
        .build(p, ride_road_needed_m(spec.length_m), seed)?;
    ride_tracks_on(p, spec, &terrain)
}

/// The enveloping cache of a ride run on `terrain` (both tracks under the front track).
fn ride_tracks_on(
    p: &VehicleParams,
    spec: &RideSpec,
    terrain: &TwoTrackTerrain,
) -> Result<Arc<TireTracks>, VehicleError> {
    Ok(Arc::new(TireTracks::build(
        p,
        spec.load,
        &ride_options(spec),
        terrain,
        0.5 * p.front_track_m,
    )?))
}

/// The terrain surface under `p`: the nominal surface with the vehicle's front track.
fn surface_of(p: &VehicleParams) -> SurfaceParams {
    SurfaceParams {
        track_width_m: p.front_track_m,
        ..SurfaceParams::nominal()
    }
}

/// Road a ride run of `length_m` needs (m): 15 m behind the start, the 20 m run-in, the
/// measured window and 30 m beyond (the tire contacts and the enveloping filter look ahead).
pub fn ride_road_needed_m(length_m: f64) -> f64 {
    RIDE_START_M + RUN_IN_M + length_m + 30.0
}

/// The enveloping cache of a ride run on a measured two-track road `profile` (laid out from
/// its first sample, the vehicle's front track between the tracks); the road must be at
/// least [`ride_road_needed_m`] long. The spec's synthesised terrain is not used.
pub fn measured_ride_tracks(
    p: &VehicleParams,
    spec: &RideSpec,
    profile: TwoTrackProfile,
) -> Result<Arc<TireTracks>, VehicleError> {
    positive("speed_kmh", spec.speed_kmh)?;
    positive("length_m", spec.length_m)?;
    let have = profile.dx_m * (profile.len().saturating_sub(1)) as f64;
    let need = ride_road_needed_m(spec.length_m);
    if have < need {
        return Err(VehicleError::Terrain(terrain_psd::TerrainError::Signal(format!(
            "the road is {have:.1} m long; a ride with a {} m window needs {need:.1} m (15 m behind the start, 20 m run-in, the window, 30 m beyond): shorten the window to at most {:.1} m",
            spec.length_m,
            (have - ride_road_needed_m(0.0)).max(0.0)
        ))));
    }
    ride_tracks_on(p, spec, &TwoTrackTerrain::new(profile, surface_of(p))?)
}

/// One ride run on `tracks` ([`ride_tracks`]): the record and its measures.
pub fn ride_on(
    p: &VehicleParams,
    spec: &RideSpec,
    tracks: Arc<TireTracks>,
) -> Result<(RunRecord, RideMeasures), VehicleError> {
    positive("speed_kmh", spec.speed_kmh)?;
    let speed = spec.speed_kmh / 3.6;
    let v = Vehicle::on_tracks(p, spec.load, ride_options(spec), tracks)?;
    let rec = simulate(
        &v,
        &RunOptions {
            t_end_s: (RUN_IN_M + spec.length_m) / speed,
            output_dt_s: OUTPUT_DT_S,
            ..RunOptions::default()
        },
    )?;
    let m = ride_measures(
        &rec,
        RUN_IN_M / speed,
        spec.front_axle,
        p.rear_hps.is_some(),
    )?;
    Ok((rec, m))
}

/// One ride run on terrain `seed`: the record and its measures.
pub fn ride(
    p: &VehicleParams,
    spec: &RideSpec,
    seed: u64,
) -> Result<(RunRecord, RideMeasures), VehicleError> {
    ride_on(p, spec, ride_tracks(p, spec, seed)?)
}

/// The larger peak-to-peak travel of a left and right strut from sample `i0` on (m).
fn largest_p2p(travel: &[Vec<f64>; 2], i0: usize) -> f64 {
    travel
        .iter()
        .map(|z| {
            let w = &z[i0..];
            let hi = w.iter().fold(f64::MIN, |m, v| m.max(*v));
            let lo = w.iter().fold(f64::MAX, |m, v| m.min(*v));
            hi - lo
        })
        .fold(0.0, f64::max)
}

/// Ride measures of `rec` from `t_start_s` on (module docs), with the front struts' travel
/// on a suspended front axle and the rear struts' with `rear_suspended`.
pub fn ride_measures(
    rec: &RunRecord,
    t_start_s: f64,
    front_axle: FrontAxle,
    rear_suspended: bool,
) -> Result<RideMeasures, VehicleError> {
    let i0 = rec.t_s.partition_point(|&t| t < t_start_s);
    if rec.len() < i0 + 64 {
        return Err(measure(
            "a_wz",
            "the ride window holds fewer than 64 samples",
        ));
    }
    let fs = 1.0 / (rec.t_s[1] - rec.t_s[0]);
    let az = &rec.cab_accel_m_s2[2][i0..];
    let weighted = weight_fft(Weighting::Wk, az, fs).map_err(|e| measure("a_wz", e))?;
    // ISO 2631-1: a_w is the plain RMS of the weighted signal (weight_fft removed the mean)
    let rms = |x: &[f64]| perf_measures::signal::rms(x).map_err(|e| measure("a_wz", e));
    let travel = match front_axle {
        FrontAxle::Rigid => None,
        FrontAxle::Suspended => Some(largest_p2p(&rec.hps_travel_m, i0)),
    };
    Ok(RideMeasures {
        a_wz_m_s2: rms(&weighted)?,
        a_z_rms_m_s2: rms(az)?,
        strut_travel_p2p_m: travel,
        rear_strut_travel_p2p_m: rear_suspended.then(|| largest_p2p(&rec.rear_hps_travel_m, i0)),
        vertical_peak_hz: psd_peak(az, fs)?,
        pitch_peak_hz: psd_peak(&rec.front_angular_accel_rad_s2[1][i0..], fs)?,
    })
}

/// Frequency (Hz) of the largest Welch PSD value of `x` (sampled at `fs`) within 0.5-10 Hz;
/// segments of up to 8 s (at least 4 per record, 50 % overlap, Hann).
pub fn psd_peak(x: &[f64], fs: f64) -> Result<f64, VehicleError> {
    let seg = ((8.0 * fs) as usize).min(x.len() / 2).max(32);
    let s = welch_psd(x, 1.0 / fs, &WelchConfig::new(seg)).map_err(|e| measure("psd", e))?;
    let mut best = (f64::NAN, f64::MIN);
    for (f, p) in s.freq.iter().zip(&s.psd) {
        if (0.5..=10.0).contains(f) && *p > best.1 {
            best = (*f, *p);
        }
    }
    if best.0.is_finite() {
        Ok(best.0)
    } else {
        Err(measure("psd", "no spectral line within 0.5-10 Hz"))
    }
}

/// Ride measures over `seeds` (in parallel), in seed order.
pub fn ride_over_seeds(
    p: &VehicleParams,
    spec: &RideSpec,
    seeds: &[u64],
) -> Result<Vec<RideMeasures>, VehicleError> {
    seeds
        .par_iter()
        .map(|&s| ride(p, spec, s).map(|(_, m)| m))
        .collect()
}

/// Measures of one D3 yaw run.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct YawMeasures {
    /// omega_z: natural frequency of the single-DOF fit (Hz).
    pub omega_z_hz: f64,
    /// Damped frequency of the fit (Hz).
    pub damped_frequency_hz: f64,
    /// Damping ratio zeta of the fit (-).
    pub damping_ratio: f64,
    /// Largest articulation magnitude (deg).
    pub peak_articulation_deg: f64,
    /// Standard error of the fitted damping ratio (-), from the fit covariance.
    pub damping_ratio_std: f64,
    /// RMS residual of the fit over the noise RMS the record shows (floored at 0.1 % of the
    /// articulation's range; `perf_measures::DecayFit::noise_rms`): above
    /// [`perf_measures::DECAY_RESIDUAL_NOISE_LIMIT`] the free response is not one decaying
    /// mode, and omega_z and zeta depend on the fitted window.
    pub fit_residual_to_noise: f64,
}

impl YawMeasures {
    /// Why the single-mode fit's numbers need a caveat, one sentence (None when the response
    /// is one decaying mode within the record's noise and zeta is determined).
    pub fn fit_caveat(&self) -> Option<String> {
        let mut parts: Vec<String> = perf_measures::not_one_mode(self.fit_residual_to_noise)
            .into_iter()
            .collect();
        if self.damping_ratio_std > 0.5 * self.damping_ratio.abs() {
            parts.push(format!(
                "zeta {:.3} has a standard error of {:.3}",
                self.damping_ratio, self.damping_ratio_std
            ));
        }
        (!parts.is_empty()).then(|| parts.join("; "))
    }
}

/// Settings of a yaw (pulse) run.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct YawSpec {
    /// Load case: loaded for D3.
    pub load: Load,
    /// Front axle.
    pub front_axle: FrontAxle,
    /// Speed (km/h): 50.
    pub speed_kmh: f64,
    /// Steering-wheel pulse peak (deg). Assumption: 30 (not stated in section 6.4).
    pub pulse_deg: f64,
    /// Pulse duration (s): 0.2.
    pub pulse_s: f64,
    /// Pulse start (s): 1.
    pub pulse_start_s: f64,
    /// Run length (s).
    pub t_end_s: f64,
    /// Length of the free-decay window fitted (s).
    pub fit_window_s: f64,
    /// Terrain: None for smooth ground.
    pub terrain: Option<TerrainSpec>,
    /// Lock the rear-unit roll joint (the yaw-mode analysis).
    pub lock_rear_roll: bool,
}

impl YawSpec {
    /// D3 of section 6.4 on smooth ground.
    pub fn d3(front_axle: FrontAxle) -> Self {
        Self {
            load: Load::Loaded,
            front_axle,
            speed_kmh: 50.0,
            pulse_deg: 30.0,
            pulse_s: 0.2,
            pulse_start_s: 1.0,
            t_end_s: 5.0,
            fit_window_s: 3.0,
            terrain: None,
            lock_rear_roll: false,
        }
    }
}

/// The vehicle options of a D3 run: the speed, the steering pulse and the path.
pub(crate) fn yaw_options(spec: &YawSpec) -> Result<VehicleOptions, VehicleError> {
    positive("speed_kmh", spec.speed_kmh)?;
    let speed = spec.speed_kmh / 3.6;
    Ok(VehicleOptions {
        front_axle: spec.front_axle,
        speed_m_s: speed,
        steer: SteerInput::pulse_deg(spec.pulse_deg, spec.pulse_s, spec.pulse_start_s),
        path_length_m: speed * spec.t_end_s + 5.0,
        lock_rear_roll: spec.lock_rear_roll,
        ..VehicleOptions::default()
    })
}

/// One yaw run (on terrain `seed` when the spec has a terrain).
pub fn yaw(
    p: &VehicleParams,
    spec: &YawSpec,
    seed: u64,
) -> Result<(RunRecord, YawMeasures), VehicleError> {
    let options = yaw_options(spec)?;
    let run = RunOptions {
        t_end_s: spec.t_end_s,
        output_dt_s: OUTPUT_DT_S,
        ..RunOptions::default()
    };
    let rec = match &spec.terrain {
        None => {
            let flat = FlatTerrain::new(0.0, vehicle_components::DEFAULT_FRICTION)
                .map_err(|e| measure("terrain", e))?;
            simulate(
                &Vehicle::new(p, spec.load, options, &flat, 0.5 * p.front_track_m)?,
                &run,
            )?
        }
        Some(t) => {
            let terrain = t.build(p, options.path_length_m + 50.0, seed)?;
            simulate(
                &Vehicle::new(p, spec.load, options, &terrain, 0.5 * p.front_track_m)?,
                &run,
            )?
        }
    };
    let m = yaw_measures(&rec, spec.pulse_start_s + spec.pulse_s, spec.fit_window_s)?;
    Ok((rec, m))
}

/// The articulation of `rec` in degrees and the sample range `i0..i1` of its free decay
/// after `pulse_end_s`: from its second extremum on (the first swing is driven by the
/// input), `window_s` long. [`yaw_measures`] fits it.
pub fn yaw_decay_window(
    rec: &RunRecord,
    pulse_end_s: f64,
    window_s: f64,
) -> Result<(Vec<f64>, std::ops::Range<usize>), VehicleError> {
    let deg: Vec<f64> = rec
        .articulation_rad
        .iter()
        .map(|a| a.to_degrees())
        .collect();
    let t = &rec.t_s;
    let i0 = perf_measures::decay_onset(t, &deg, pulse_end_s)
        .ok_or_else(|| measure("omega_z", "no free oscillation after the pulse"))?;
    let i1 = t.partition_point(|&x| x < t[i0] + window_s);
    Ok((deg, i0..i1))
}

/// Yaw measures of `rec`: the articulation's free decay after `pulse_end_s`
/// ([`yaw_decay_window`]), fitted over `window_s`.
pub fn yaw_measures(
    rec: &RunRecord,
    pulse_end_s: f64,
    window_s: f64,
) -> Result<YawMeasures, VehicleError> {
    let (deg, window) = yaw_decay_window(rec, pulse_end_s, window_s)?;
    let (t, i0, i1) = (&rec.t_s, window.start, window.end);
    let fit = perf_measures::fit_free_decay(&t[i0..i1], &deg[i0..i1])
        .map_err(|e| measure("omega_z", e))?;
    Ok(YawMeasures {
        omega_z_hz: fit.natural_frequency_hz,
        damped_frequency_hz: fit.damped_frequency_hz,
        damping_ratio: fit.damping_ratio,
        peak_articulation_deg: deg.iter().fold(0.0, |m, v| m.max(v.abs())),
        damping_ratio_std: fit.damping_ratio_std,
        fit_residual_to_noise: fit.rmse / fit.noise_rms,
    })
}

/// Measures of one D2 roll run.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RollMeasures {
    /// SP-DRT: RMS |a_y| of the rear unit over the sustained period of |LTR| = 1 (m/s²).
    pub sp_drt_m_s2: f64,
    /// Lowest and highest |a_y| in the sustained period (m/s²).
    pub sustained_range_m_s2: (f64, f64),
    /// Start and end of the sustained period (s).
    pub sustained_s: (f64, f64),
    /// Time of the rear unit's absolute rollover (s), if reached.
    pub rollover_s: Option<f64>,
    /// Largest |a_y| of the rear unit (m/s²).
    pub peak_ay_m_s2: f64,
}

/// Settings of a roll (ramp-steer) run.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RollSpec {
    /// Load case: loaded for D2.
    pub load: Load,
    /// Front axle.
    pub front_axle: FrontAxle,
    /// Speed (km/h): 50.
    pub speed_kmh: f64,
    /// Steering-wheel rate (deg/s): 5.
    pub ramp_deg_s: f64,
    /// Ramp start (s). Assumption: 1.
    pub ramp_start_s: f64,
    /// Longest run (s).
    pub t_end_s: f64,
    /// Terrain: class E for D2 (None: smooth ground).
    pub terrain: Option<TerrainSpec>,
}

impl RollSpec {
    /// D2 of section 6.4.
    pub fn d2(front_axle: FrontAxle) -> Self {
        Self {
            load: Load::Loaded,
            front_axle,
            speed_kmh: 50.0,
            ramp_deg_s: 5.0,
            ramp_start_s: 1.0,
            t_end_s: D2_DURATION_S,
            terrain: Some(TerrainSpec::default()),
        }
    }
}

/// The longest D2 run (s), when the rear unit does not roll over: rollover comes at 25-30 s
/// on class E. The terrain is synthesised over the path of the whole run, so a seed's
/// terrain depends on this length (and the speed): a run of another duration reads another
/// realisation under the same seed. The enveloping cache covers that path too, so a longer
/// limit also costs in proportion.
pub const D2_DURATION_S: f64 = 45.0;

/// The vehicle options of a roll run.
pub(crate) fn roll_options(spec: &RollSpec) -> VehicleOptions {
    let speed = spec.speed_kmh / 3.6;
    VehicleOptions {
        front_axle: spec.front_axle,
        speed_m_s: speed,
        steer: SteerInput::Ramp {
            rate_rad_s: spec.ramp_deg_s.to_radians(),
            start_s: spec.ramp_start_s,
            limit_rad: 50f64.to_radians() * 20.0,
        },
        path_length_m: speed * spec.t_end_s + 5.0,
        ..VehicleOptions::default()
    }
}

/// The enveloping cache of a roll run on terrain `seed` (smooth ground without a terrain),
/// shared by every suspension and HPS design of the load case ([`roll_on`]). Built as the
/// runs reach it ([`TireTracks::on_demand`]): a run stops at rollover, the prototype's
/// after about 25 of the 45 s the cache could cover, and building the whole path took twice
/// the rigid run's own time.
pub fn roll_tracks(
    p: &VehicleParams,
    spec: &RollSpec,
    seed: u64,
) -> Result<Arc<TireTracks>, VehicleError> {
    positive("speed_kmh", spec.speed_kmh)?;
    positive("ramp_deg_s", spec.ramp_deg_s)?;
    let options = roll_options(spec);
    let half = 0.5 * p.front_track_m;
    let tracks = match &spec.terrain {
        None => {
            let flat = FlatTerrain::new(0.0, vehicle_components::DEFAULT_FRICTION)
                .map_err(|e| measure("terrain", e))?;
            TireTracks::on_demand(p, spec.load, &options, Arc::new(flat), half)?
        }
        Some(t) => {
            let terrain = t.build(p, options.path_length_m + 50.0, seed)?;
            TireTracks::on_demand(p, spec.load, &options, Arc::new(terrain), half)?
        }
    };
    Ok(Arc::new(tracks))
}

/// One roll run to rollover on `tracks` ([`roll_tracks`]).
pub fn roll_on(
    p: &VehicleParams,
    spec: &RollSpec,
    tracks: Arc<TireTracks>,
) -> Result<(RunRecord, RollMeasures), VehicleError> {
    let v = Vehicle::on_tracks(p, spec.load, roll_options(spec), tracks)?;
    let rec = simulate(
        &v,
        &RunOptions {
            t_end_s: spec.t_end_s,
            output_dt_s: 0.01,
            stop_at_rollover: true,
            ..RunOptions::default()
        },
    )?;
    let m = roll_measures(&rec)?;
    Ok((rec, m))
}

/// One roll run to rollover (on terrain `seed` when the spec has a terrain).
pub fn roll(
    p: &VehicleParams,
    spec: &RollSpec,
    seed: u64,
) -> Result<(RunRecord, RollMeasures), VehicleError> {
    roll_on(p, spec, roll_tracks(p, spec, seed)?)
}

/// Roll measures over `seeds` (in parallel), in seed order.
pub fn roll_over_seeds(
    p: &VehicleParams,
    spec: &RollSpec,
    seeds: &[u64],
) -> Result<Vec<RollMeasures>, VehicleError> {
    seeds
        .par_iter()
        .map(|&s| roll(p, spec, s).map(|(_, m)| m))
        .collect()
}

/// Roll measures of `rec` (module docs).
pub fn roll_measures(rec: &RunRecord) -> Result<RollMeasures, VehicleError> {
    let ltr: Vec<f64> = rec.rear_ltr.iter().map(|x| x.abs()).collect();
    let ay: Vec<f64> = rec
        .rear_lateral_accel_m_s2
        .iter()
        .map(|x| x.abs())
        .collect();
    let s = sustained_period(&rec.t_s, &ltr, &ay, &SustainedPeriodParams::default())
        .map_err(|e| measure("SP-DRT", e))?;
    Ok(RollMeasures {
        sp_drt_m_s2: s.sp_drt_m_s2,
        sustained_range_m_s2: s.lateral_accel_range_m_s2,
        sustained_s: (s.start_s, s.end_s),
        rollover_s: rec.rollover_s,
        peak_ay_m_s2: ay.iter().fold(0.0, |m, v| m.max(*v)),
    })
}
