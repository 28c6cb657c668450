//! Runs on the terrains of Chapter 2 and the parametric studies of section 2.4: every
//! rough-terrain point is a mean ± SD over terrain seeds (the same seeds for every
//! variant of a study), run in parallel with rayon.

use perf_measures::roll::SustainedPeriodParams;
use serde::Serialize;
use terrain_psd::{synthesize, SurfaceParams, TwoTrackSpec, TwoTrackTerrain};

use crate::driver::SteerDirection;
use crate::error::TruckError;
use crate::measures::{level_ground, roll_measures, RollMeasures};
use crate::params::TruckParams;
use crate::simulate::{simulate, RunOptions, RunRecord};
use crate::vehicle::{ModelOptions, TruckVehicle};

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
    let surface = SurfaceParams {
        track_width_m: 0.5 * (p.front_track_m + p.rear_track_m),
        ..SurfaceParams::nominal()
    };
    Ok(TwoTrackTerrain::new(profile, surface)?)
}

/// The truck `p` on `terrain`, each side's tires on its track, the enveloping cache
/// covering `path_length_m` (at most the terrain's length).
pub fn truck_on(
    p: &TruckParams,
    terrain: &TwoTrackTerrain,
    direction: SteerDirection,
    path_length_m: f64,
) -> Result<TruckVehicle, TruckError> {
    let options = ModelOptions {
        direction,
        path_length_m: path_length_m.min(terrain.profile().length_m()),
        ..ModelOptions::default()
    };
    TruckVehicle::new(p, terrain, 0.5 * terrain.params().track_width_m, options)
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
/// and `seed`.
pub fn run_case(
    p: &TruckParams,
    spec: Option<&TwoTrackSpec>,
    seed: u64,
    direction: SteerDirection,
    options: &RunOptions,
    sp: &SustainedPeriodParams,
) -> Result<Run, TruckError> {
    let path_length_m = p.target_speed_m_s * options.t_end_s * 1.1 + 10.0;
    let record = match spec {
        None => {
            let v = TruckVehicle::new(
                p,
                &level_ground(),
                1.0,
                ModelOptions {
                    direction,
                    path_length_m,
                    ..ModelOptions::default()
                },
            )?;
            simulate(&v, options)?
        }
        Some(spec) => {
            let terrain = rough_terrain(p, spec, TERRAIN_LENGTH_M, seed)?;
            simulate(&truck_on(p, &terrain, direction, path_length_m)?, options)?
        }
    };
    let measures = roll_measures(p, &record, sp)?;
    Ok(Run { record, measures })
}
