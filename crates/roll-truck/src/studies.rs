//! Runs on the terrains of Chapter 2 and the parametric studies of section 2.4: every
//! rough-terrain point is a mean ± SD over terrain seeds (the same seeds for every
//! variant of a study), run in parallel with rayon.

use std::sync::Arc;

use perf_measures::roll::SustainedPeriodParams;
use serde::Serialize;
use terrain_psd::{synthesize, SurfaceParams, TwoTrackProfile, TwoTrackSpec, TwoTrackTerrain};

use crate::driver::SteerDirection;
use crate::error::TruckError;
use crate::measures::{level_ground, roll_measures, RollMeasures};
use crate::params::TruckParams;
use crate::simulate::{simulate, RunOptions, RunRecord};
use crate::vehicle::{ModelOptions, TruckVehicle};
use vehicle_run::RunSettings;

/// Sample spacing of the synthesized profiles (m): Nyquist 10 cycles/m, the highest band
/// limit of the study (L682).
pub const TERRAIN_DX_M: f64 = 0.05;

/// Length of the synthesized terrain (m): a 60 s run at 40 km/h (667 m) plus margins.
pub const TERRAIN_LENGTH_M: f64 = 800.0;

/// A two-track terrain of `spec` from `seed`, `length_m` long, for the truck: the track
/// width of the surface is immaterial (the tires read the tracks themselves) and set to
/// the mean of the front and rear tracks.
pub fn rough_terrain(
    p: &TruckParams,
    spec: &TwoTrackSpec,
    length_m: f64,
    seed: u64,
) -> Result<TwoTrackTerrain, TruckError> {
    let profile = synthesize(spec, length_m, TERRAIN_DX_M, seed)?;
    Ok(TwoTrackTerrain::new(profile, truck_surface(p))?)
}

/// The truck's surface over a two-track profile: the track width (immaterial: the tires read
/// the tracks themselves) the mean of the front and rear tracks, the rest nominal.
fn truck_surface(p: &TruckParams) -> SurfaceParams {
    SurfaceParams {
        track_width_m: 2.0 * half_track_m(p),
        ..SurfaceParams::nominal()
    }
}

/// Where the truck's tires read a two-track terrain (m): plus and minus half the mean of the
/// front and rear tracks (an OpenCRG road is sampled there too).
pub fn half_track_m(p: &TruckParams) -> f64 {
    0.25 * (p.front_track_m + p.rear_track_m)
}

/// The truck `p` on `terrain`, each side's tires on its track, the enveloping cache
/// covering `path_length_m` (at most the terrain's length).
pub fn truck_on(
    p: &TruckParams,
    terrain: &TwoTrackTerrain,
    direction: SteerDirection,
    path_length_m: f64,
) -> Result<TruckVehicle, TruckError> {
    let (options, half_width) = placement(terrain, direction, path_length_m);
    TruckVehicle::new(p, terrain, half_width, options)
}

/// How a truck stands on `terrain` for [`truck_on`] and the studies' runs: its options,
/// the cache covering `path_length_m` (at most the terrain's length), and the half width of
/// the terrain's tracks its tires run on.
fn placement(
    terrain: &TwoTrackTerrain,
    direction: SteerDirection,
    path_length_m: f64,
) -> (ModelOptions, f64) {
    let options = ModelOptions {
        direction,
        path_length_m: path_length_m.min(terrain.profile().length_m()),
        ..ModelOptions::default()
    };
    (options, 0.5 * terrain.params().track_width_m)
}

/// One run and its measures.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Run {
    /// The record.
    pub record: RunRecord,
    /// Its roll measures.
    pub measures: RollMeasures,
}

/// A ramp-steer run of `p` on level ground (`spec = None`) or on the terrain of `spec`
/// and `seed`, [`terrain_length_m`] long.
pub fn run_case(
    p: &TruckParams,
    spec: Option<&TwoTrackSpec>,
    seed: u64,
    direction: SteerDirection,
    options: &RunOptions,
    sp: &SustainedPeriodParams,
) -> Result<Run, TruckError> {
    run_case_on(
        p,
        spec,
        seed,
        terrain_length_m(p, options),
        direction,
        options,
        sp,
    )
}

/// Length of the rough terrain of [`run_case`] (m): [`TERRAIN_LENGTH_M`], or longer for a
/// run longer than the default 60 s (the path at the target speed plus 50 m).
pub fn terrain_length_m(p: &TruckParams, options: &RunOptions) -> f64 {
    (p.target_speed_m_s * options.t_end_s * 1.1 + 60.0).max(TERRAIN_LENGTH_M)
}

/// [`run_case`] on a synthesized terrain `terrain_length_m` long (the synthesis depends on
/// the length, so equal lengths give equal terrains for a seed).
pub fn run_case_on(
    p: &TruckParams,
    spec: Option<&TwoTrackSpec>,
    seed: u64,
    terrain_length_m: f64,
    direction: SteerDirection,
    options: &RunOptions,
    sp: &SustainedPeriodParams,
) -> Result<Run, TruckError> {
    let Some(spec) = spec else {
        let v = TruckVehicle::new(
            p,
            &level_ground(),
            1.0,
            ModelOptions {
                direction,
                path_length_m: run_path_length_m(p, options),
                ..ModelOptions::default()
            },
        )?;
        let record = simulate(&v, options)?;
        let measures = roll_measures(p, &record, sp)?;
        return Ok(Run { record, measures });
    };
    let terrain = rough_terrain(p, spec, terrain_length_m, seed)?;
    run_on_terrain(p, terrain, direction, options, sp)
}

/// Path length a run of `options` covers (m): the target speed over the run, 10 % over,
/// plus 10 m.
fn run_path_length_m(p: &TruckParams, options: &RunOptions) -> f64 {
    p.target_speed_m_s * options.t_end_s * 1.1 + 10.0
}

/// A run on `terrain` (each side's tires on its track) and its measures. The run stops at
/// rollover, so its enveloping caches are built as it reaches them
/// ([`TruckVehicle::on_demand`]): the prototype's class E run rolls over at 29 s of 60.
fn run_on_terrain(
    p: &TruckParams,
    terrain: TwoTrackTerrain,
    direction: SteerDirection,
    options: &RunOptions,
    sp: &SustainedPeriodParams,
) -> Result<Run, TruckError> {
    let (model, half_width) = placement(&terrain, direction, run_path_length_m(p, options));
    let truck = TruckVehicle::on_demand(p, Arc::new(terrain), half_width, model)?;
    let record = simulate(&truck, options)?;
    let measures = roll_measures(p, &record, sp)?;
    Ok(Run { record, measures })
}

/// Shortest measured road (m) a run of `options` needs: the enveloping cache's end, the
/// start ([`ModelOptions::start_s_m`]) plus the run's path (the target speed over the run,
/// 10 % over, plus 10 m) plus a wheelbase and a tire diameter.
pub fn road_length_needed_m(p: &TruckParams, options: &RunOptions) -> f64 {
    road_beyond_path_m(p) + run_path_length_m(p, options)
}

/// What a road needs besides the run's path (m): the start, a wheelbase and a tire diameter.
fn road_beyond_path_m(p: &TruckParams) -> f64 {
    ModelOptions::default().start_s_m + p.wheelbase_m + 2.0 * p.tire_free_radius_m
}

/// A ramp-steer run of `p` on a measured two-track road `profile` (laid out from its first
/// sample along the path the truck drives, the left tires on its left track; the surface is
/// [`rough_terrain`]'s) and its measures. A road shorter than [`road_length_needed_m`] is
/// refused with the length it needs. A road equal to a synthesized terrain gives that
/// terrain's run bit for bit.
pub fn run_case_on_road(
    p: &TruckParams,
    profile: TwoTrackProfile,
    direction: SteerDirection,
    options: &RunOptions,
    sp: &SustainedPeriodParams,
) -> Result<Run, TruckError> {
    p.validate()?;
    options.validate()?;
    let need = road_length_needed_m(p, options);
    let have = profile.length_m();
    if have < need {
        return Err(TruckError::Terrain(terrain_psd::TerrainError::Signal(format!(
            "the road is {have:.1} m long; a {:.1} s run at {:.1} km/h needs {need:.1} m (the start, the path 10 % over plus 10 m, a wheelbase and a tire diameter): shorten the run to at most {:.1} s",
            options.t_end_s,
            p.target_speed_m_s * 3.6,
            max_duration_on_road_s(p, have)
        ))));
    }
    let terrain = TwoTrackTerrain::new(profile, truck_surface(p))?;
    run_on_terrain(p, terrain, direction, options, sp)
}

/// Longest run (s) a road `length_m` long carries ([`road_length_needed_m`] solved for the
/// run's duration; 0 when the road is too short for any run).
fn max_duration_on_road_s(p: &TruckParams, length_m: f64) -> f64 {
    // run_path_length_m solved for the run's duration
    let path = length_m - road_beyond_path_m(p) - 10.0;
    (path / (1.1 * p.target_speed_m_s)).max(0.0)
}

/// Largest number of terrain seeds of one study (bounds the work and the output).
pub const MAX_SEEDS: usize = 1000;

/// The studies of section 2.4 (Figs 2.10-2.14).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Study {
    /// Sprung cg height 3.15 m ± 0.15 / ± 0.3 m on the nominal class E terrain and on the
    /// smooth road (Figs 2.10-2.11, L664-L666).
    CgHeight,
    /// ISO classes A-E for m_c = 0.3, 0.6, 0.9 cycles/m (Fig 2.12, L684).
    Roughness,
    /// Waviness w = 1.6-2.4 at alpha_r of class E (Fig 2.13, L688).
    Waviness,
    /// Band limits: upper 1, 3, 5, 10 and lower 0.02, 0.05, 0.15, 0.25 cycles/m
    /// (Fig 2.14, L688, L700).
    Band,
    /// The calibrated and the plausible truck ([`TruckParams::plausible`]), each with its
    /// bump stops and with them out of reach ([`TruckParams::without_bump_stops`]), on the
    /// smooth road and the nominal class E terrain (issue 28).
    Trucks,
}

impl std::str::FromStr for Study {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "cg" => Ok(Self::CgHeight),
            "roughness" => Ok(Self::Roughness),
            "waviness" => Ok(Self::Waviness),
            "band" => Ok(Self::Band),
            "trucks" => Ok(Self::Trucks),
            _ => Err(format!(
                "unknown study `{s}` (cg, roughness, waviness, band, trucks)"
            )),
        }
    }
}

/// One variant of a study: a parameter set, a terrain and where it sits on the plot.
#[derive(Debug, Clone, PartialEq)]
pub struct Variant {
    /// Curve the point belongs to (e.g. `m_c = 0.3`).
    pub group: String,
    /// Abscissa (cg height m, alpha_r, waviness, band limit cycles/m).
    pub x: f64,
    /// The truck.
    pub params: TruckParams,
    /// The rough terrain.
    pub spec: TwoTrackSpec,
    /// Whether the smooth-road run of this truck is part of the study.
    pub with_smooth: bool,
}

fn spec_with(
    alpha_r: f64,
    waviness: f64,
    band: (f64, f64),
    m_c: f64,
) -> Result<TwoTrackSpec, TruckError> {
    Ok(TwoTrackSpec::new(
        terrain_psd::PowerLawPsd::new(alpha_r, waviness)?,
        terrain_psd::Band::new(band.0, band.1)?,
        terrain_psd::CoherenceModel::piecewise(m_c)?,
    )?)
}

impl Study {
    /// Name of the abscissa with its unit.
    pub fn x_label(self) -> &'static str {
        match self {
            Study::CgHeight => "sprung cg height (m)",
            Study::Roughness => "roughness coefficient alpha_r (m^3)",
            Study::Waviness => "waviness w (-)",
            Study::Band => "band limit (cycles/m)",
            Study::Trucks => "truck (0 calibrated, 1 without stops, 2 plausible, 3 without stops)",
        }
    }

    /// The variants, one parameter changed at a time from the nominal truck and terrain
    /// (class E, w = 2, 0.02-5 cycles/m, m_c = 0.3; L680-L682). [`Study::Trucks`] compares
    /// the built-in trucks and ignores `base`.
    pub fn variants(self, base: &TruckParams) -> Result<Vec<Variant>, TruckError> {
        let e = terrain_psd::IsoClass::E.alpha_r();
        let nominal = |x: f64, group: &str, spec: TwoTrackSpec| Variant {
            group: group.into(),
            x,
            params: *base,
            spec,
            with_smooth: false,
        };
        let mut out = Vec::new();
        match self {
            Study::CgHeight => {
                for dh in [-0.3, -0.15, 0.0, 0.15, 0.3] {
                    let mut p = *base;
                    p.cg_height_m += dh;
                    out.push(Variant {
                        params: p,
                        with_smooth: true,
                        ..nominal(
                            p.cg_height_m,
                            "class E",
                            spec_with(e, 2.0, (0.02, 5.0), 0.3)?,
                        )
                    });
                }
            }
            Study::Roughness => {
                for m_c in [0.3, 0.6, 0.9] {
                    for class in ["A", "B", "C", "D", "E"] {
                        let c: terrain_psd::IsoClass =
                            class.parse().map_err(TruckError::Terrain)?;
                        let spec = spec_with(c.alpha_r(), 2.0, (0.02, 5.0), m_c)?;
                        out.push(nominal(c.alpha_r(), &format!("m_c = {m_c}"), spec));
                    }
                }
            }
            Study::Waviness => {
                for w in [1.6, 1.8, 2.0, 2.2, 2.4] {
                    out.push(nominal(
                        w,
                        "class E alpha_r",
                        spec_with(e, w, (0.02, 5.0), 0.3)?,
                    ));
                }
            }
            Study::Band => {
                for hi in [1.0, 3.0, 5.0, 10.0] {
                    let spec = spec_with(e, 2.0, (0.02, hi), 0.3)?;
                    out.push(nominal(hi, "upper limit (0.02-x)", spec));
                }
                for lo in [0.02, 0.05, 0.15, 0.25] {
                    let spec = spec_with(e, 2.0, (lo, 5.0), 0.3)?;
                    out.push(nominal(lo, "lower limit (x-5)", spec));
                }
            }
            Study::Trucks => {
                let trucks = [
                    ("calibrated", TruckParams::nominal()),
                    (
                        "calibrated, no stops",
                        TruckParams::nominal().without_bump_stops(),
                    ),
                    ("plausible", TruckParams::plausible()),
                    (
                        "plausible, no stops",
                        TruckParams::plausible().without_bump_stops(),
                    ),
                ];
                for (i, (group, params)) in trucks.into_iter().enumerate() {
                    out.push(Variant {
                        group: group.into(),
                        x: i as f64,
                        params,
                        spec: spec_with(e, 2.0, (0.02, 5.0), 0.3)?,
                        with_smooth: true,
                    });
                }
            }
        }
        Ok(out)
    }
}

/// Mean, sample standard deviation and count of the seeds that gave a value.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Stat {
    /// Mean (NaN if `n == 0`; printed as null).
    pub mean: f64,
    /// Sample standard deviation (0 for one value).
    pub sd: f64,
    /// Number of values.
    pub n: usize,
}

impl Stat {
    /// Of the `Some` values.
    pub fn of(values: impl Iterator<Item = Option<f64>>) -> Self {
        let v: Vec<f64> = values.flatten().filter(|x| x.is_finite()).collect();
        let n = v.len();
        if n == 0 {
            return Self {
                mean: f64::NAN,
                sd: f64::NAN,
                n,
            };
        }
        let mean = v.iter().sum::<f64>() / n as f64;
        let var = if n > 1 {
            v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1) as f64
        } else {
            0.0
        };
        Self {
            mean,
            sd: var.sqrt(),
            n,
        }
    }
}

/// One point of a study: the smooth-road measures (if part of the study) and the
/// rough-terrain measures as mean ± SD over the seeds.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StudyPoint {
    /// Curve.
    pub group: String,
    /// Abscissa.
    pub x: f64,
    /// Smooth-road DRT (g).
    pub smooth_drt_g: Option<f64>,
    /// SSF of the truck (-).
    pub ssf: f64,
    /// Rough-terrain SP-DRT (g).
    pub sp_drt_g: Stat,
    /// Sustained period ΔT (s).
    pub sustained_period_s: Stat,
    /// Lowest |a_y| within the sustained period (g).
    pub sustained_min_g: Stat,
    /// Highest |a_y| within the sustained period (g).
    pub sustained_max_g: Stat,
    /// End of the sustained period A⁴ (s).
    pub sustained_end_s: Stat,
    /// |a_y| at A⁴ (g).
    pub ay_at_a4_g: Stat,
    /// |a_y| at absolute rollover B′ (g).
    pub ay_at_rollover_g: Stat,
    /// Peak |a_y| (g), whole-vehicle channel.
    pub peak_ay_g: Stat,
    /// Peak |a_y| of the sprung cg, horizontal (g).
    pub peak_sprung_ay_g: Stat,
    /// Peak |reading| of a lateral accelerometer on the sprung cg (g).
    pub peak_sensor_ay_g: Stat,
    /// Peak |a_y| before the first bump-stop contact (g).
    pub peak_ay_before_stop_g: Stat,
    /// Smooth-road peak |a_y| (g), whole-vehicle channel.
    pub smooth_peak_ay_g: Option<f64>,
    /// Time of absolute rollover (s).
    pub rollover_s: Stat,
    /// Seeds whose run failed or gave no sustained period.
    pub seeds_without_period: usize,
}

/// A study's points, its seeds and its derived numbers.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StudyResult {
    /// Which study.
    pub study: Study,
    /// The terrain seeds (common to every variant).
    pub seeds: Vec<u64>,
    /// The points in variant order.
    pub points: Vec<StudyPoint>,
}

/// Run `study` for the truck `base` over `seeds` (common to every variant), in parallel
/// with rayon; `progress(done, total)` is called after every run. A run that fails
/// counts against its point's `seeds_without_period` (the error is not lost: a study in
/// which every run of a point fails returns the first error).
pub fn run_study(
    study: Study,
    base: &TruckParams,
    seeds: &[u64],
    options: &RunOptions,
    sp: &SustainedPeriodParams,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<StudyResult, TruckError> {
    run_variants(study, &study.variants(base)?, seeds, options, sp, progress)
}

/// [`run_study`] for a chosen subset of `study`'s variants (e.g. one curve of Fig 2.12).
pub fn run_variants(
    study: Study,
    variants: &[Variant],
    seeds: &[u64],
    options: &RunOptions,
    sp: &SustainedPeriodParams,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<StudyResult, TruckError> {
    use rayon::prelude::*;
    use std::sync::atomic::{AtomicUsize, Ordering};
    if seeds.is_empty() || seeds.len() > MAX_SEEDS {
        return Err(crate::error::rejected(
            "seeds",
            seeds.len() as f64,
            "a study needs 1 to 1000 terrain seeds",
        ));
    }
    options.validate()?;
    sp.validate()
        .map_err(|e| vehicle_run::measure("sustained period", e))?;
    let mut jobs: Vec<(usize, Option<u64>)> = Vec::new();
    for (i, v) in variants.iter().enumerate() {
        if v.with_smooth {
            jobs.push((i, None));
        }
        jobs.extend(seeds.iter().map(|s| (i, Some(*s))));
    }
    let done = AtomicUsize::new(0);
    let total = jobs.len();
    let results: Vec<(usize, Option<u64>, Result<RollMeasures, TruckError>)> = jobs
        .par_iter()
        .map(|&(i, seed)| {
            let v = &variants[i];
            let spec = seed.map(|_| &v.spec);
            let r = run_case(
                &v.params,
                spec,
                seed.unwrap_or(0),
                SteerDirection::Left,
                options,
                sp,
            )
            .map(|run| run.measures);
            progress(done.fetch_add(1, Ordering::Relaxed) + 1, total);
            (i, seed, r)
        })
        .collect();
    let points = variants
        .iter()
        .enumerate()
        .map(|(i, v)| point(v, i, &results))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(StudyResult {
        study,
        seeds: seeds.to_vec(),
        points,
    })
}

type JobResult = (usize, Option<u64>, Result<RollMeasures, TruckError>);

fn point(v: &Variant, i: usize, results: &[JobResult]) -> Result<StudyPoint, TruckError> {
    let smooth = results
        .iter()
        .find(|(j, seed, _)| *j == i && seed.is_none())
        .map(|(_, _, r)| r.clone())
        .transpose()?;
    let rough: Vec<&Result<RollMeasures, TruckError>> = results
        .iter()
        .filter(|(j, seed, _)| *j == i && seed.is_some())
        .map(|(_, _, r)| r)
        .collect();
    if let Some(Err(e)) = rough.first().filter(|_| rough.iter().all(|r| r.is_err())) {
        return Err(e.clone());
    }
    let ok: Vec<&RollMeasures> = rough.iter().filter_map(|r| r.as_ref().ok()).collect();
    let stat = |f: &dyn Fn(&RollMeasures) -> Option<f64>| Stat::of(ok.iter().map(|m| f(m)));
    let sp_drt_g = stat(&|m| m.sp_drt_g);
    Ok(StudyPoint {
        group: v.group.clone(),
        x: v.x,
        smooth_drt_g: smooth.as_ref().and_then(|m| m.drt_g),
        ssf: crate::measures::ssf(&v.params),
        sustained_period_s: stat(&|m| m.sustained_period_s),
        sustained_min_g: stat(&|m| m.sustained_range_g.map(|r| r.0)),
        sustained_max_g: stat(&|m| m.sustained_range_g.map(|r| r.1)),
        sustained_end_s: stat(&|m| m.sustained_end_s),
        ay_at_a4_g: stat(&|m| m.ay_at_a4_g),
        ay_at_rollover_g: stat(&|m| m.ay_at_rollover_g),
        peak_ay_g: stat(&|m| Some(m.peak_ay_g)),
        peak_sprung_ay_g: stat(&|m| m.peak_sprung_ay_g),
        peak_sensor_ay_g: stat(&|m| m.peak_sensor_ay_g),
        peak_ay_before_stop_g: stat(&|m| Some(m.peak_ay_before_stop_g)),
        smooth_peak_ay_g: smooth.as_ref().map(|m| m.peak_ay_g),
        rollover_s: stat(&|m| m.rollover_s),
        seeds_without_period: rough.len() - sp_drt_g.n,
        sp_drt_g,
    })
}
