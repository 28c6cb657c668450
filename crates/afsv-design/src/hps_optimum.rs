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

use optimize::ga::{GaOptions, GeneticAlgorithm};
use optimize::{Bounds, ConstrainedProblem, Evaluation, Progress};
use serde::Serialize;
use vehicle_3d::scenarios::{
    ride_on, ride_tracks, roll_over_seeds, yaw, RideSpec, RollSpec, Spread, YawSpec,
};
use vehicle_3d::{FrontAxle, Load, TireTracks, VehicleParams};

use crate::error::DesignError;
use crate::hps_design::HpsDesign;

/// Settings of the optimisation.
#[derive(Debug, Clone, PartialEq, Serialize)]
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

/// a_wz and d_s of one design on the search seed.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RideValues {
    /// a_wz (m/s²).
    pub a_wz_m_s2: f64,
    /// d_s (m).
    pub d_s_m: f64,
}

/// The problem of the module docs.
struct HpsProblem {
    base: VehicleParams,
    spec: RideSpec,
    tracks: Arc<TireTracks>,
    nominal: RideValues,
    bounds: Bounds,
    limit: f64,
}

impl HpsProblem {
    fn ride(&self, x: &[f64]) -> Result<RideValues, DesignError> {
        let mut p = self.base.clone();
        p.hps = HpsDesign::new(x[0], x[1], x[2])?.apply(&self.base.hps)?;
        let (_, m) = ride_on(&p, &self.spec, Arc::clone(&self.tracks))
            .map_err(|e| DesignError::Simulation(e.to_string()))?;
        Ok(RideValues {
            a_wz_m_s2: m.a_wz_m_s2,
            d_s_m: m.strut_travel_p2p_m.unwrap_or(f64::NAN),
        })
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
        match self.ride(x) {
            Ok(r) if r.a_wz_m_s2.is_finite() && r.d_s_m.is_finite() => Evaluation {
                f: r.a_wz_m_s2 / self.nominal.a_wz_m_s2 + r.d_s_m / self.nominal.d_s_m,
                constraints: vec![r.a_wz_m_s2 - self.limit],
            },
            _ => Evaluation::failed(1),
        }
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
    let ride = vehicle_3d::scenarios::ride_over_seeds(
        p,
        &RideSpec::d1(Load::Unloaded, FrontAxle::Suspended),
        seeds,
    )
    .map_err(sim)?;
    let roll = if roll {
        roll_over_seeds(p, &RollSpec::d2(FrontAxle::Suspended), seeds).map_err(sim)?
    } else {
        Vec::new()
    };
    let (_, y) = yaw(p, &YawSpec::d3(FrontAxle::Suspended), 0).map_err(sim)?;
    let spread = |v: Vec<f64>| Spread::of_measured(&v).map_err(sim);
    Ok(HpsAssessment {
        a_wz_m_s2: spread(ride.iter().map(|m| m.a_wz_m_s2).collect())?,
        sp_drt_m_s2: spread(roll.iter().map(|m| m.sp_drt_m_s2).collect())?,
        omega_z_hz: y.omega_z_hz,
    })
}

/// The optimisation of the module docs for `base` (its `hps` is the nominal design).
pub fn optimise_hps(
    base: &VehicleParams,
    settings: &HpsGaSettings,
    progress: &dyn Progress,
) -> Result<HpsOptimum, DesignError> {
    let sim = |e: vehicle_3d::VehicleError| DesignError::Simulation(e.to_string());
    if settings.reevaluation_seeds == 0 || settings.reevaluation_seeds > 100 {
        return Err(DesignError::Shape {
            field: "reevaluation_seeds",
            reason: format!("1 to 100, got {}", settings.reevaluation_seeds),
        });
    }
    let spec = RideSpec::d1(Load::Unloaded, FrontAxle::Suspended);
    let tracks = ride_tracks(base, &spec, settings.terrain_seed).map_err(sim)?;
    let nominal_design = HpsDesign::of(&base.hps);
    let bounds = Bounds::new(settings.lower.to_vec(), settings.upper.to_vec())
        .map_err(|e| DesignError::Simulation(e.to_string()))?;
    let mut problem = HpsProblem {
        base: base.clone(),
        spec,
        tracks,
        nominal: RideValues {
            a_wz_m_s2: 1.0,
            d_s_m: 1.0,
        },
        bounds,
        limit: settings.a_wz_limit_m_s2,
    };
    problem.nominal =
        problem.ride(&[nominal_design.a_hc, nominal_design.a_v, nominal_design.a_b])?;
    let options = GaOptions {
        population: settings.population,
        generations: settings.generations,
        seed: settings.ga_seed,
        ..GaOptions::default()
    };
    let opt = |e: optimize::OptimizeError| DesignError::Simulation(e.to_string());
    let ga = GeneticAlgorithm::new(&problem, options).map_err(opt)?;
    // the nominal design is one of the initial individuals (in problem units)
    let start = ga
        .start(&[vec![
            nominal_design.a_hc,
            nominal_design.a_v,
            nominal_design.a_b,
        ]])
        .map_err(opt)?;
    let end = ga.run(start, progress, &mut |_| Ok(())).map_err(opt)?;
    let best = end.best().clone();
    let design = HpsDesign::new(best.x[0], best.x[1], best.x[2])?;
    let optimum_ride = problem.ride(&best.x)?;
    let seeds: Vec<u64> = (0..settings.reevaluation_seeds as u64)
        .map(|i| settings.terrain_seed.wrapping_add(i))
        .collect();
    let mut optimum_params = base.clone();
    optimum_params.hps = design.apply(&base.hps)?;
    Ok(HpsOptimum {
        settings: settings.clone(),
        nominal_design,
        design,
        objective: best.eval.f,
        feasible: best.eval.is_feasible(),
        nominal_ride: problem.nominal,
        optimum_ride,
        evaluations: end.evaluations + 2,
        nominal_over_seeds: assess(base, &seeds, settings.reevaluate_roll)?,
        optimum_over_seeds: assess(&optimum_params, &seeds, settings.reevaluate_roll)?,
    })
}
