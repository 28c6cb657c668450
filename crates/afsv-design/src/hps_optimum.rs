//! The chapter-6 HPS design optimisation (section 6.5.2, Eqs 6.19-6.20) on the 3-D vehicle:
//! a real-coded genetic algorithm (`optimize::ga`, Deb's feasibility rules) over
//! chi = [A_hc, A_v, A_b] minimising
//!
//! `F(chi) = a_wz / a_wzn + d_s / d_sn` (Eq 6.19)
//!
//! for the unloaded vehicle at 20 km/h on class E (D1), subject to `a_wz <= 0.85 m/s²` and the
//! lower bounds `chi >= [0.026, 4e-6, 7e-6] m²` (Eq 6.20). `a_wzn` and `d_sn` are the nominal
//! design's values on the same terrain seed. The chapter prints no upper bounds; the defaults
//! (+30 % A_hc, 2 x A_v, 4 x A_b of Table 6.3) are assumptions (note 2.9). During the search
//! every design runs on one fixed terrain seed, its enveloping cache built once; the optimum
//! and the nominal design are then re-evaluated over several seeds, with SP-DRT and omega_z.

use std::sync::Arc;

use optimize::ga::{GaOptions, GeneticAlgorithm, Individual};
use optimize::{Bounds, ConstrainedProblem, Evaluation, Progress};
use serde::{Deserialize, Serialize};
use vehicle_3d::scenarios::{
    ride_on, ride_tracks, roll_over_seeds, yaw, RideSpec, RollSpec, Spread, YawSpec,
};
use vehicle_3d::{FrontAxle, Load, TireTracks, VehicleParams};

use crate::error::DesignError;
use crate::hps_design::HpsDesign;

/// Settings of the optimisation.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HpsGaSettings {
    /// GA population size. Default 20.
    pub population: usize,
    /// GA generations. Default 10 (about 220 vehicle runs).
    pub generations: usize,
    /// Seed of the GA's random numbers.
    pub ga_seed: u64,
    /// The fixed terrain seed of the search.
    pub terrain_seed: u64,
    /// Lower bounds of [A_hc, A_v, A_b] (m²), Eq 6.20.
    pub lower: [f64; 3],
    /// Upper bounds (m²). Assumption: [0.0494, 16e-6, 44e-6].
    pub upper: [f64; 3],
    /// Ride constraint a_wz <= this (m/s²), Eq 6.20.
    pub a_wz_limit_m_s2: f64,
    /// Terrain seeds of the re-evaluation (first = `terrain_seed`).
    pub reevaluation_seeds: usize,
    /// Re-evaluate SP-DRT (D2, the costliest runs); without it SP-DRT is NaN.
    pub reevaluate_roll: bool,
}

impl Default for HpsGaSettings {
    fn default() -> Self {
        Self {
            population: 20,
            generations: 10,
            ga_seed: 1,
            terrain_seed: 1,
            lower: [0.026, 4e-6, 7e-6],
            upper: [0.0494, 16e-6, 44e-6],
            a_wz_limit_m_s2: 0.85,
            reevaluation_seeds: 10,
            reevaluate_roll: true,
        }
    }
}

impl HpsGaSettings {
    /// The sizes a command line may give (`afsv optimize hps`): an even population of 4 to
    /// 1000, 1 to 1000 generations, 1 to 100 re-evaluation seeds; errors name the option.
    pub fn check_options(&self) -> Result<(), String> {
        if !(4..=1000).contains(&self.population) || self.population % 2 == 1 {
            return Err(format!(
                "--population {}: must be even, 4 to 1000",
                self.population
            ));
        }
        if !(1..=1000).contains(&self.generations) {
            return Err(format!(
                "--generations {}: must be 1 to 1000",
                self.generations
            ));
        }
        if !(1..=100).contains(&self.reevaluation_seeds) {
            return Err(format!(
                "--reevaluation-seeds {}: must be 1 to 100",
                self.reevaluation_seeds
            ));
        }
        Ok(())
    }
}

/// a_wz and d_s of one design on the search seed.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RideValues {
    /// a_wz (m/s²).
    pub a_wz_m_s2: f64,
    /// d_s (m).
    pub d_s_m: f64,
}

/// a_wz and d_s of design `x` = [A_hc, A_v, A_b] on the search seed's enveloping cache
/// `tracks` (D1, unloaded, suspended front axle); d_s is NaN when the record has no strut
/// travel.
pub(crate) fn search_ride(
    base: &VehicleParams,
    tracks: Arc<TireTracks>,
    x: &[f64],
) -> Result<RideValues, DesignError> {
    let p = with_design(base, x)?;
    let (_, m) =
        ride_on(&p, &search_spec(), tracks).map_err(|e| DesignError::Simulation(e.to_string()))?;
    Ok(RideValues {
        a_wz_m_s2: m.a_wz_m_s2,
        d_s_m: m.strut_travel_p2p_m.unwrap_or(f64::NAN),
    })
}

/// The ride of the search: D1, unloaded, suspended front axle.
pub(crate) fn search_spec() -> RideSpec {
    RideSpec::d1(Load::Unloaded, FrontAxle::Suspended)
}

/// Eq 6.19 and the constraint of Eq 6.20 of a design's search ride `r` against the
/// nominal's; a failed run or a non-finite measure is a failed evaluation.
pub(crate) fn evaluation(
    r: Result<RideValues, DesignError>,
    nominal: &RideValues,
    limit: f64,
) -> Evaluation {
    match r {
        Ok(r) if r.a_wz_m_s2.is_finite() && r.d_s_m.is_finite() => Evaluation {
            f: r.a_wz_m_s2 / nominal.a_wz_m_s2 + r.d_s_m / nominal.d_s_m,
            constraints: vec![r.a_wz_m_s2 - limit],
        },
        _ => Evaluation::failed(1),
    }
}

/// The problem of the module docs.
struct HpsProblem {
    base: VehicleParams,
    tracks: Arc<TireTracks>,
    nominal: RideValues,
    bounds: Bounds,
    limit: f64,
}

impl HpsProblem {
    fn ride(&self, x: &[f64]) -> Result<RideValues, DesignError> {
        search_ride(&self.base, Arc::clone(&self.tracks), x)
    }
}

impl ConstrainedProblem for HpsProblem {
    fn bounds(&self) -> &Bounds {
        &self.bounds
    }

    fn n_constraints(&self) -> usize {
        1
    }

    fn evaluate(&self, x: &[f64]) -> Evaluation {
        evaluation(self.ride(x), &self.nominal, self.limit)
    }
}

/// A design's measures over the re-evaluation seeds.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct HpsAssessment {
    /// a_wz unloaded (m/s²).
    pub a_wz_m_s2: Spread,
    /// SP-DRT loaded (m/s²); NaN when not re-evaluated.
    pub sp_drt_m_s2: Spread,
    /// omega_z loaded, smooth ground (Hz).
    pub omega_z_hz: f64,
}

/// The result.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HpsOptimum {
    /// The settings.
    pub settings: HpsGaSettings,
    /// The nominal design (Table 6.3).
    pub nominal_design: HpsDesign,
    /// The optimum.
    pub design: HpsDesign,
    /// Eq 6.19 at the optimum (the nominal has F = 2).
    pub objective: f64,
    /// Whether the optimum meets a_wz <= the limit on the search seed.
    pub feasible: bool,
    /// The nominal's a_wz and d_s on the search seed (a_wzn, d_sn).
    pub nominal_ride: RideValues,
    /// The optimum's a_wz and d_s on the search seed.
    pub optimum_ride: RideValues,
    /// Vehicle runs of the search.
    pub evaluations: usize,
    /// The nominal over the re-evaluation seeds.
    pub nominal_over_seeds: HpsAssessment,
    /// The optimum over the re-evaluation seeds.
    pub optimum_over_seeds: HpsAssessment,
}

fn assess(p: &VehicleParams, seeds: &[u64], roll: bool) -> Result<HpsAssessment, DesignError> {
    let sim = |e: vehicle_3d::VehicleError| DesignError::Simulation(e.to_string());
    // the three measures side by side: no core waits for the slowest seed of one of them
    let (ride, (roll, yaw)) = rayon::join(
        || vehicle_3d::scenarios::ride_over_seeds(p, &search_spec(), seeds),
        || {
            rayon::join(
                || match roll {
                    true => roll_over_seeds(p, &RollSpec::d2(FrontAxle::Suspended), seeds),
                    false => Ok(Vec::new()),
                },
                || yaw(p, &YawSpec::d3(FrontAxle::Suspended), 0),
            )
        },
    );
    let (ride, roll, (_, y)) = (ride.map_err(sim)?, roll.map_err(sim)?, yaw.map_err(sim)?);
    assessment(
        &ride.iter().map(|m| m.a_wz_m_s2).collect::<Vec<_>>(),
        &roll.iter().map(|m| m.sp_drt_m_s2).collect::<Vec<_>>(),
        y.omega_z_hz,
    )
}

/// The assessment of a design's a_wz and SP-DRT, each in seed order, and omega_z.
pub(crate) fn assessment(
    a_wz: &[f64],
    sp_drt: &[f64],
    omega_z_hz: f64,
) -> Result<HpsAssessment, DesignError> {
    let spread =
        |v: &[f64]| Spread::of_measured(v).map_err(|e| DesignError::Simulation(e.to_string()));
    Ok(HpsAssessment {
        a_wz_m_s2: spread(a_wz)?,
        sp_drt_m_s2: spread(sp_drt)?,
        omega_z_hz,
    })
}

/// The terrain seeds of the re-evaluation: `terrain_seed` and the ones after it.
pub fn reevaluation_seeds(settings: &HpsGaSettings) -> Vec<u64> {
    crate::fan_out::seed_range(settings.terrain_seed, settings.reevaluation_seeds as u64)
}

/// The D4 speeds of section 6.5.2 (km/h): the speed sweep of an optimum (Fig 6.16).
pub const D4_SPEEDS_KMH: [f64; 5] = [10.0, 15.0, 20.0, 25.0, 30.0];

/// The vehicle `base` with the optimum's strut: the Eq 6.19 areas of `r` applied to its
/// strut.
pub fn optimum_vehicle(base: &VehicleParams, r: &HpsOptimum) -> Result<VehicleParams, DesignError> {
    let mut best = base.clone();
    best.hps = r.design.apply(&base.hps)?;
    Ok(best)
}

/// The D4 speed sweep (Fig 6.16) of the optimum vehicle `best` over [`D4_SPEEDS_KMH`] on the
/// re-evaluation seeds of `settings`; `progress` after each run.
pub fn optimum_speed_sweep(
    best: &VehicleParams,
    settings: &HpsGaSettings,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<crate::SpeedSweep, DesignError> {
    let seeds = reevaluation_seeds(settings);
    crate::hps_speed_sweep(best, &D4_SPEEDS_KMH, &seeds, progress)
}

/// Refuses settings the optimisation cannot run: re-evaluation seeds outside 1 to 100.
pub(crate) fn check_settings(settings: &HpsGaSettings) -> Result<(), DesignError> {
    if settings.reevaluation_seeds == 0 || settings.reevaluation_seeds > 100 {
        return Err(DesignError::Shape {
            field: "reevaluation_seeds",
            reason: format!("1 to 100, got {}", settings.reevaluation_seeds),
        });
    }
    Ok(())
}

/// The GA options of `settings`.
pub(crate) fn ga_options(settings: &HpsGaSettings) -> GaOptions {
    GaOptions {
        population: settings.population,
        generations: settings.generations,
        seed: settings.ga_seed,
        ..GaOptions::default()
    }
}

/// The nominal design of `base` as the GA's seed individual (problem units).
pub(crate) fn nominal_x(base: &VehicleParams) -> Vec<f64> {
    let n = HpsDesign::of(&base.hps);
    vec![n.a_hc, n.a_v, n.a_b]
}

/// The bounds of the search (Eq 6.20 and the assumed upper bounds).
pub(crate) fn search_bounds(settings: &HpsGaSettings) -> Result<Bounds, DesignError> {
    Bounds::new(settings.lower.to_vec(), settings.upper.to_vec())
        .map_err(|e| DesignError::Simulation(e.to_string()))
}

/// What a finished search and its re-evaluation found.
pub(crate) struct Found<'a> {
    /// The GA's best individual.
    pub best: &'a Individual,
    /// The GA's evaluations.
    pub evaluations: usize,
    /// The nominal's search ride.
    pub nominal_ride: RideValues,
    /// The optimum's search ride, run once more.
    pub optimum_ride: RideValues,
    /// The nominal over the re-evaluation seeds.
    pub nominal_over_seeds: HpsAssessment,
    /// The optimum over the re-evaluation seeds.
    pub optimum_over_seeds: HpsAssessment,
}

/// The result of `found` for `base` (the nominal design and the optimum's runs: two more
/// than the GA's evaluations).
pub(crate) fn result(
    base: &VehicleParams,
    settings: &HpsGaSettings,
    found: Found,
) -> Result<HpsOptimum, DesignError> {
    let x = &found.best.x;
    Ok(HpsOptimum {
        settings: settings.clone(),
        nominal_design: HpsDesign::of(&base.hps),
        design: HpsDesign::new(x[0], x[1], x[2])?,
        objective: found.best.eval.f,
        feasible: found.best.eval.is_feasible(),
        nominal_ride: found.nominal_ride,
        optimum_ride: found.optimum_ride,
        evaluations: found.evaluations + 2,
        nominal_over_seeds: found.nominal_over_seeds,
        optimum_over_seeds: found.optimum_over_seeds,
    })
}

/// `base` with the HPS design `x` = [A_hc, A_v, A_b].
pub(crate) fn with_design(base: &VehicleParams, x: &[f64]) -> Result<VehicleParams, DesignError> {
    let mut p = base.clone();
    p.hps = HpsDesign::new(x[0], x[1], x[2])?.apply(&base.hps)?;
    Ok(p)
}

/// The optimisation of the module docs for `base` (its `hps` is the nominal design).
pub fn optimise_hps(
    base: &VehicleParams,
    settings: &HpsGaSettings,
    progress: &dyn Progress,
) -> Result<HpsOptimum, DesignError> {
    let sim = |e: vehicle_3d::VehicleError| DesignError::Simulation(e.to_string());
    check_settings(settings)?;
    let tracks = ride_tracks(base, &search_spec(), settings.terrain_seed).map_err(sim)?;
    let mut problem = HpsProblem {
        base: base.clone(),
        tracks,
        nominal: RideValues {
            a_wz_m_s2: 1.0,
            d_s_m: 1.0,
        },
        bounds: search_bounds(settings)?,
        limit: settings.a_wz_limit_m_s2,
    };
    problem.nominal = problem.ride(&nominal_x(base))?;
    let opt = |e: optimize::OptimizeError| DesignError::Simulation(e.to_string());
    let ga = GeneticAlgorithm::new(&problem, ga_options(settings)).map_err(opt)?;
    // the nominal design is one of the initial individuals (in problem units)
    let start = ga.start(&[nominal_x(base)]).map_err(opt)?;
    let end = ga.run(start, progress, &mut |_| Ok(())).map_err(opt)?;
    let best = end.best();
    let seeds = reevaluation_seeds(settings);
    let optimum_params = with_design(base, &best.x)?;
    // the optimum's ride and both re-evaluations side by side
    let (optimum_ride, (nominal_over_seeds, optimum_over_seeds)) = rayon::join(
        || problem.ride(&best.x),
        || {
            rayon::join(
                || assess(base, &seeds, settings.reevaluate_roll),
                || assess(&optimum_params, &seeds, settings.reevaluate_roll),
            )
        },
    );
    result(
        base,
        settings,
        Found {
            best,
            evaluations: end.evaluations,
            nominal_ride: problem.nominal,
            optimum_ride: optimum_ride?,
            nominal_over_seeds: nominal_over_seeds?,
            optimum_over_seeds: optimum_over_seeds?,
        },
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn command_line_sizes_are_bounded_and_named() {
        assert!(HpsGaSettings::default().check_options().is_ok());
        let with = |population, generations, reevaluation_seeds| HpsGaSettings {
            population,
            generations,
            reevaluation_seeds,
            ..HpsGaSettings::default()
        };
        assert!(with(4, 1, 1).check_options().is_ok());
        assert!(with(1000, 1000, 100).check_options().is_ok());
        let e = with(5, 1, 1).check_options().unwrap_err();
        assert_eq!(e, "--population 5: must be even, 4 to 1000");
        assert!(with(2, 1, 1).check_options().is_err());
        let e = with(4, 0, 1).check_options().unwrap_err();
        assert_eq!(e, "--generations 0: must be 1 to 1000");
        let e = with(4, 1, 101).check_options().unwrap_err();
        assert_eq!(e, "--reevaluation-seeds 101: must be 1 to 100");
    }
}
