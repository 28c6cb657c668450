//! The three design measures of Chapter 6 on the 3-D vehicle (`vehicle-3d`): ride (a_wz,
//! W_k, D1), roll (SP-DRT of the rear unit, D2) and yaw (omega_z after the pulse, D3),
//! unsuspended and with the nominal front-axle HPS, each rough-terrain measure as mean ± SD
//! over common terrain seeds (section 6.4), with the ISO 2631-1 health guidance caution zone
//! (HGCZ, 8 h, Eq B.1) verdict of a_wz. [`measure`] runs them for any parameter set, front
//! axles and ride load cases, all runs in parallel; [`assess`] is the assessment of
//! `afsv evaluate` (and of `afsv.evaluate` in Python), `afsv vehicle measures` uses
//! [`measure`].

use perf_measures::iso2631::{health_guidance_zone, HgczRelation, HgczZone};
use serde::Serialize;
use std::sync::Arc;
use vehicle_3d::interconnect::{
    ride_linked, ride_linked_on, roll_linked, roll_linked_on, yaw_linked, Link,
};
use vehicle_3d::path_change::path_change_linked;
use vehicle_3d::scenarios::{self, PathChangeMeasures, PathChangeSpec, RideMeasures, RollMeasures};
use vehicle_3d::scenarios::{
    ride_on, ride_tracks, roll_on, roll_tracks, yaw, RideSpec, RollSpec, Spread, YawMeasures,
    YawSpec,
};
use vehicle_3d::{FrontAxle, Load, RunRecord, TireTracks, VehicleError, VehicleParams};

/// Largest number of terrain seeds per measure.
pub const MAX_SEEDS: u64 = 100;

/// Ride measures of one load case over the seeds.
#[derive(Debug, Clone, Serialize)]
pub struct RideSummary {
    /// a_wz at the cab point (m/s²).
    pub a_wz_m_s2: Spread,
    /// Peak-to-peak front-strut travel d_s (m), with the HPS only.
    pub strut_travel_m: Option<Spread>,
    /// Verdict of the mean a_wz against the 8 h HGCZ (Eq B.1 of ISO 2631-1).
    pub hgcz_8h: HgczZone,
}

/// The three measures of one front axle.
#[derive(Debug, Clone, Serialize)]
pub struct AxleSummary {
    /// D1 unloaded.
    pub ride_unloaded: RideSummary,
    /// D1 loaded.
    pub ride_loaded: RideSummary,
    /// D2 SP-DRT, loaded (m/s²).
    pub sp_drt_m_s2: Spread,
    /// D3, loaded, smooth ground.
    pub yaw: YawMeasures,
}

/// The assessment: with a rigid front axle and with the vehicle's front-axle HPS.
#[derive(Debug, Clone, Serialize)]
pub struct DesignMeasures {
    /// Terrain seeds used for every rough-terrain measure (the same for both axles).
    pub seeds: Vec<u64>,
    /// The 8 h HGCZ band (m/s²).
    pub hgcz_8h_m_s2: (f64, f64),
    /// The vehicle with a rigid front axle.
    pub unsuspended: AxleSummary,
    /// With the vehicle's front-axle strut (Table 6.3 for the prototype); `None` when its
    /// description gives the front axle no strut.
    pub nominal_hps: Option<AxleSummary>,
    /// The struts' interconnection (`[link]` of the description) in the `nominal_hps` runs;
    /// the rigid-front-axle runs have no front struts to link and run without it.
    pub link: Option<Link>,
}

/// The three measures of one front axle of one parameter set over common seeds: the D1
/// ride of each load case asked for, the D2 SP-DRT and the D3 yaw (both loaded).
#[derive(Debug, Clone, Serialize)]
pub struct ConfigMeasures {
    /// The front axle.
    pub front_axle: FrontAxle,
    /// D1 per load case, in the order asked for.
    pub ride: Vec<(Load, RideSummary)>,
    /// D2 SP-DRT, loaded (m/s²).
    pub sp_drt_m_s2: Spread,
    /// D3, loaded, smooth ground.
    pub yaw: YawMeasures,
}

impl ConfigMeasures {
    /// The ride of `load`, if it was measured.
    pub fn ride_of(&self, load: Load) -> Option<&RideSummary> {
        self.ride.iter().find(|(l, _)| *l == load).map(|(_, r)| r)
    }
}

/// One run of the assessment.
#[derive(Debug, Clone, Copy)]
enum Job {
    Ride(FrontAxle, Load, u64),
    Roll(FrontAxle, u64),
    Yaw(FrontAxle),
}

/// A job in words for the progress line, e.g. `D1 ride, HPS, unloaded, seed 3`.
fn job_text(j: Job) -> String {
    let axle = |a: FrontAxle| match a {
        FrontAxle::Rigid => "rigid front axle",
        FrontAxle::Suspended => "HPS",
    };
    match j {
        Job::Ride(a, load, seed) => format!("D1 ride, {}, {load}, seed {seed}", axle(a)),
        Job::Roll(a, seed) => format!("D2 roll, {}, seed {seed}", axle(a)),
        Job::Yaw(a) => format!("D3 yaw, {}", axle(a)),
    }
}

/// What one job measured.
enum Outcome {
    Ride(f64, Option<f64>),
    Roll(f64),
    Yaw(YawMeasures),
}

/// The enveloping caches of one seed: the ride of each load case, the roll. They depend on
/// the terrain and the load, not on the front axle, so both axles share them.
struct SeedTracks {
    seed: u64,
    ride: Vec<(Load, Arc<TireTracks>)>,
    roll: Arc<TireTracks>,
}

/// One run of `job`; with the front-axle HPS the struts are interconnected by `link`, when
/// given.
fn run_job(
    p: &VehicleParams,
    job: Job,
    tracks: &[SeedTracks],
    link: Option<Link>,
) -> Result<Outcome, String> {
    let e = |e: vehicle_3d::VehicleError| e.to_string();
    let link_of = |axle: FrontAxle| link.filter(|_| axle == FrontAxle::Suspended);
    let of = |seed: u64| {
        tracks
            .iter()
            .find(|t| t.seed == seed)
            .ok_or_else(|| format!("no tracks for seed {seed}"))
    };
    Ok(match job {
        Job::Ride(axle, load, seed) => {
            let t = of(seed)?
                .ride
                .iter()
                .find(|(l, _)| *l == load)
                .map(|(_, t)| Arc::clone(t))
                .ok_or_else(|| format!("no {load} ride tracks for seed {seed}"))?;
            let spec = RideSpec::d1(load, axle);
            let m = match link_of(axle) {
                Some(l) => ride_linked_on(p, &spec, t, l).map_err(e)?.1,
                None => ride_on(p, &spec, t).map_err(e)?.1,
            };
            Outcome::Ride(m.a_wz_m_s2, m.strut_travel_p2p_m)
        }
        Job::Roll(axle, seed) => {
            let t = Arc::clone(&of(seed)?.roll);
            let spec = RollSpec::d2(axle);
            let m = match link_of(axle) {
                Some(l) => roll_linked_on(p, &spec, t, l).map_err(e)?.1,
                None => roll_on(p, &spec, t).map_err(e)?.1,
            };
            Outcome::Roll(m.sp_drt_m_s2)
        }
        Job::Yaw(axle) => {
            let spec = YawSpec::d3(axle);
            Outcome::Yaw(match link_of(axle) {
                Some(l) => yaw_linked(p, &spec, l).map_err(e)?.1,
                None => yaw(p, &spec, 0).map_err(e)?.1,
            })
        }
    })
}

/// One D1 ride of `p` on terrain `seed`, the struts interconnected by `link` when given
/// (`vehicle_3d::interconnect::ride_linked`, else `vehicle_3d::scenarios::ride`): its
/// record and measures.
pub fn ride_run(
    p: &VehicleParams,
    spec: &RideSpec,
    seed: u64,
    link: Option<&Link>,
) -> Result<(RunRecord, RideMeasures), VehicleError> {
    match link {
        Some(l) => ride_linked(p, spec, seed, l).map(|(r, m)| (r.record, m)),
        None => scenarios::ride(p, spec, seed),
    }
}

/// One D2 roll run of `p` on terrain `seed`, linked as in [`ride_run`]: its record and
/// measures.
pub fn roll_run(
    p: &VehicleParams,
    spec: &RollSpec,
    seed: u64,
    link: Option<&Link>,
) -> Result<(RunRecord, RollMeasures), VehicleError> {
    match link {
        Some(l) => roll_linked(p, spec, seed, l).map(|(r, m)| (r.record, m)),
        None => scenarios::roll(p, spec, seed),
    }
}

/// One D3 yaw run of `p` (on terrain `seed` when the spec has one), linked as in
/// [`ride_run`] (a linked run is on smooth ground): its record and measures.
pub fn yaw_run(
    p: &VehicleParams,
    spec: &YawSpec,
    seed: u64,
    link: Option<&Link>,
) -> Result<(RunRecord, YawMeasures), VehicleError> {
    match link {
        Some(l) => yaw_linked(p, spec, l).map(|(r, m)| (r.record, m)),
        None => yaw(p, spec, seed),
    }
}

/// One V3 path change of `p` (on terrain `seed` when the spec has one), linked as in
/// [`ride_run`]: its record and measures.
pub fn path_change_run(
    p: &VehicleParams,
    spec: &PathChangeSpec,
    seed: u64,
    link: Option<&Link>,
) -> Result<(RunRecord, PathChangeMeasures), VehicleError> {
    match link {
        Some(l) => path_change_linked(p, spec, seed, l).map(|(r, m)| (r.record, m)),
        None => scenarios::path_change(p, spec, seed),
    }
}

/// The design measures D1 (a_wz and d_s for each of `ride_loads`), D2 (SP-DRT) and D3
/// (omega_z, zeta) of the vehicle `p` with each of `axles`, over common terrain `seeds`
/// (section 6.4), all runs in parallel; with the front-axle HPS the struts are
/// interconnected by `link` (the description's `[link]`), when given. `progress` is called
/// once per finished run with a short description. One entry per axle, in order.
pub fn measure(
    p: &VehicleParams,
    axles: &[FrontAxle],
    ride_loads: &[Load],
    seeds: &[u64],
    link: Option<Link>,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<Vec<ConfigMeasures>, String> {
    if seeds.is_empty() || seeds.len() as u64 > MAX_SEEDS {
        return Err(format!(
            "between 1 and {MAX_SEEDS} terrain seeds, got {}",
            seeds.len()
        ));
    }
    if axles.is_empty() || ride_loads.is_empty() {
        return Err("at least one front axle and one ride load case".into());
    }
    let mut jobs = Vec::new();
    for &axle in axles {
        jobs.push(Job::Yaw(axle));
        for &s in seeds {
            jobs.push(Job::Roll(axle, s));
            for &load in ride_loads {
                jobs.push(Job::Ride(axle, load, s));
            }
        }
    }
    let e = |e: vehicle_3d::VehicleError| e.to_string();
    let outcomes: Vec<Outcome> = crate::fan_out::cached(
        seeds,
        |&seed| {
            let ride = ride_loads
                .iter()
                .map(|&load| {
                    ride_tracks(p, &RideSpec::d1(load, FrontAxle::Rigid), seed)
                        .map(|t| (load, t))
                        .map_err(e)
                })
                .collect::<Result<_, String>>()?;
            Ok::<_, String>(SeedTracks {
                seed,
                ride,
                roll: roll_tracks(p, &RollSpec::d2(FrontAxle::Rigid), seed).map_err(e)?,
            })
        },
        &jobs,
        |&j, tracks| run_job(p, j, tracks, link),
        |&j| progress(&job_text(j)),
    )?
    .into_iter()
    .collect::<Result<_, _>>()?;
    let zone = health_guidance_zone(8.0, HgczRelation::SqrtTime).map_err(|e| e.to_string())?;
    let summary = |axle: FrontAxle| -> Result<ConfigMeasures, String> {
        let mut awz = vec![Vec::new(); ride_loads.len()];
        let mut ds = vec![Vec::new(); ride_loads.len()];
        let mut sp = Vec::new();
        let mut wz = None;
        for (job, out) in jobs.iter().zip(&outcomes) {
            match (job, out) {
                (Job::Ride(a, load, _), Outcome::Ride(w, d)) if *a == axle => {
                    if let Some(i) = ride_loads.iter().position(|l| l == load) {
                        awz[i].push(*w);
                        ds[i].extend(*d);
                    }
                }
                (Job::Roll(a, _), Outcome::Roll(s)) if *a == axle => sp.push(*s),
                (Job::Yaw(a), Outcome::Yaw(m)) if *a == axle => wz = Some(*m),
                _ => {}
            }
        }
        let spread = |v: &[f64]| Spread::of(v).map_err(|e| e.to_string());
        let ride = ride_loads
            .iter()
            .enumerate()
            .map(|(i, &load)| -> Result<(Load, RideSummary), String> {
                let a = spread(&awz[i])?;
                Ok((
                    load,
                    RideSummary {
                        a_wz_m_s2: a,
                        strut_travel_m: if ds[i].is_empty() {
                            None
                        } else {
                            Some(spread(&ds[i])?)
                        },
                        hgcz_8h: zone.classify(a.mean),
                    },
                ))
            })
            .collect::<Result<_, _>>()?;
        Ok(ConfigMeasures {
            front_axle: axle,
            ride,
            sp_drt_m_s2: spread(&sp)?,
            yaw: wz.ok_or("the yaw run is missing")?,
        })
    };
    axles.iter().map(|&a| summary(a)).collect()
}

/// The 8 h HGCZ band of ISO 2631-1 (Eq B.1, m/s²).
pub fn hgcz_8h_band() -> Result<(f64, f64), String> {
    let zone = health_guidance_zone(8.0, HgczRelation::SqrtTime).map_err(|e| e.to_string())?;
    Ok((zone.lower_m_s2, zone.upper_m_s2))
}

/// Run the assessment of the vehicle `p` over `seeds` (in parallel): [`measure`] with a
/// rigid front axle and, when `with_hps`, with its front-axle strut `p.hps` (interconnected
/// by `link`, when given), both load cases; `progress` is called once per finished run with
/// a short description.
pub fn assess(
    p: &VehicleParams,
    with_hps: bool,
    seeds: &[u64],
    link: Option<Link>,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<DesignMeasures, String> {
    if link.is_some() && !with_hps {
        return Err(
            "a [link] interconnects the front-axle struts: the vehicle needs its front-axle HPS"
                .into(),
        );
    }
    let axles: &[FrontAxle] = if with_hps {
        &[FrontAxle::Rigid, FrontAxle::Suspended]
    } else {
        &[FrontAxle::Rigid]
    };
    let configs = measure(
        p,
        axles,
        &[Load::Unloaded, Load::Loaded],
        seeds,
        link,
        progress,
    )?;
    let axle = |c: &ConfigMeasures| -> Result<AxleSummary, String> {
        let ride = |load| {
            c.ride_of(load)
                .cloned()
                .ok_or_else(|| format!("the {load} ride is missing"))
        };
        Ok(AxleSummary {
            ride_unloaded: ride(Load::Unloaded)?,
            ride_loaded: ride(Load::Loaded)?,
            sp_drt_m_s2: c.sp_drt_m_s2,
            yaw: c.yaw,
        })
    };
    Ok(DesignMeasures {
        seeds: seeds.to_vec(),
        hgcz_8h_m_s2: hgcz_8h_band()?,
        unsuspended: axle(&configs[0])?,
        nominal_hps: configs.get(1).map(axle).transpose()?,
        link,
    })
}

/// Runs per [`assess`]: one yaw and, per seed, two rides and a roll, for each axle.
pub fn assess_runs(with_hps: bool, seeds: usize) -> usize {
    (1 + usize::from(with_hps)) * (1 + 3 * seeds)
}

/// The HPS's relative changes (percent) with whether each is settled over the seeds
/// ([`settled`]), as JSON; `None` without an HPS.
pub fn hps_changes(d: &DesignMeasures) -> Option<serde_json::Value> {
    let h = d.nominal_hps.as_ref()?;
    let u = &d.unsuspended;
    let one = |with: &Spread, base: &Spread| {
        serde_json::json!({
            "percent": 100.0 * (with.mean / base.mean - 1.0),
            "settled_over_seeds": settled(with, base),
        })
    };
    Some(serde_json::json!({
        "a_wz_unloaded": one(&h.ride_unloaded.a_wz_m_s2, &u.ride_unloaded.a_wz_m_s2),
        "a_wz_loaded": one(&h.ride_loaded.a_wz_m_s2, &u.ride_loaded.a_wz_m_s2),
        "sp_drt": one(&h.sp_drt_m_s2, &u.sp_drt_m_s2),
        "rule": "settled: the means differ by at least twice the standard error of the difference over the seeds",
    }))
}

/// Whether the means of `a` and `b` differ by at least twice the standard error of their
/// difference over the seeds (`sqrt(sd_a²/n_a + sd_b²/n_b)`); with one seed nothing is
/// settled.
pub fn settled(a: &Spread, b: &Spread) -> bool {
    let se = (a.sd * a.sd / a.n as f64 + b.sd * b.sd / b.n as f64).sqrt();
    a.n > 1 && b.n > 1 && (a.mean - b.mean).abs() >= 2.0 * se
}
