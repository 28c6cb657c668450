//! D4 of section 6.5.2 (Fig 6.16): the ride of one HPS design over forward speeds.
//!
//! At each speed and load the D1 ride run (class E, m_c 0.3, 100 m after the run-in) gives
//! a_wz (W_k, ISO 2631-1), the unweighted vertical RMS and the HPS peak-to-peak travel d_s,
//! each as mean ± SD over common terrain seeds (every speed and load runs on the same
//! terrain realisations). The speed at which the mean a_wz first rises above the 8-hour upper
//! bound of the ISO 2631-1 health guidance caution zone (Annex B, Eq B.1: 6/√48 ≈
//! 0.87 m/s²) is found by linear interpolation between the swept speeds. The dissertation
//! reads it from Fig 6.16 as "approaching 25 km/h" for the optimal HPS.

use crate::error::DesignError;
use perf_measures::iso2631::{health_guidance_zone, HgczRelation};
use serde::Serialize;
use std::sync::Arc;
use vehicle_3d::scenarios::{ride_on, ride_tracks, RideSpec, Spread};
use vehicle_3d::TireTracks;
use vehicle_3d::{FrontAxle, Load, VehicleParams};

/// Largest number of speeds of one sweep.
pub const MAX_SPEEDS: usize = 50;
/// Largest number of terrain seeds of one sweep.
pub const MAX_SEEDS: usize = 100;
/// Lowest speed of a sweep (km/h): one run covers 120 m, so a slower one simulates minutes.
pub const MIN_SPEED_KMH: f64 = 5.0;
/// Highest speed of a sweep (km/h).
pub const MAX_SPEED_KMH: f64 = 100.0;
/// Exposure duration of the caution-zone bound (h), the 8 h of section 6.5.2.
pub const HGCZ_HOURS: f64 = 8.0;

/// The ride at one speed and load.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SpeedPoint {
    /// Forward speed (km/h).
    pub speed_kmh: f64,
    /// Load case.
    pub load: Load,
    /// a_wz (m/s²).
    pub a_wz_m_s2: Spread,
    /// Unweighted vertical RMS acceleration (m/s²).
    pub a_z_rms_m_s2: Spread,
    /// HPS peak-to-peak travel d_s, the larger of the two struts (m).
    pub d_s_m: Spread,
}

/// Where one load case's mean a_wz crosses the caution-zone bound.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Crossing {
    /// Load case.
    pub load: Load,
    /// The first swept speed interval in which the mean a_wz rises above the bound, linearly
    /// interpolated (km/h); `None` when it stays on one side over the whole sweep.
    pub speed_kmh: Option<f64>,
    /// The mean a_wz is above the bound already at the lowest swept speed.
    pub above_at_lowest: bool,
}

/// The sweep.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SpeedSweep {
    /// Terrain seeds.
    pub seeds: Vec<u64>,
    /// The 8-hour upper bound of the caution zone (m/s²).
    pub hgcz_upper_m_s2: f64,
    /// Every point, load by load (unloaded first), speeds in the given order.
    pub points: Vec<SpeedPoint>,
    /// The crossing speed per load (unloaded first).
    pub crossings: Vec<Crossing>,
}

impl SpeedSweep {
    /// The points of `load`, in sweep order.
    pub fn of_load(&self, load: Load) -> impl Iterator<Item = &SpeedPoint> {
        self.points.iter().filter(move |p| p.load == load)
    }
}

/// The first speed at which `values` (over ascending `speeds`) rises from at or below `limit`
/// to above it, linearly interpolated; `None` when no interval crosses upwards.
pub fn first_upward_crossing(speeds: &[f64], values: &[f64], limit: f64) -> Option<f64> {
    speeds
        .windows(2)
        .zip(values.windows(2))
        .find(|(_, v)| v[0] <= limit && v[1] > limit)
        .map(|(s, v)| s[0] + (limit - v[0]) / (v[1] - v[0]) * (s[1] - s[0]))
}

/// The vehicle runs of [`hps_speed_sweep`] over `speeds` speeds and `seeds` seeds (the
/// progress total): both loads at every speed and seed.
pub fn speed_sweep_runs(speeds: usize, seeds: usize) -> usize {
    2 * speeds * seeds
}

/// The sweep of the module docs for the suspended vehicle `p` (its `hps` is the design) over
/// `speeds_kmh` (strictly ascending, [`MIN_SPEED_KMH`] to [`MAX_SPEED_KMH`]) and `seeds`; `progress` is called once
/// per finished run.
pub fn hps_speed_sweep(
    p: &VehicleParams,
    speeds_kmh: &[f64],
    seeds: &[u64],
    progress: &(dyn Fn(&str) + Sync),
) -> Result<SpeedSweep, DesignError> {
    if speeds_kmh.is_empty() || speeds_kmh.len() > MAX_SPEEDS {
        return Err(DesignError::Shape {
            field: "speeds_kmh",
            reason: format!(
                "between 1 and {MAX_SPEEDS} speeds, got {}",
                speeds_kmh.len()
            ),
        });
    }
    if seeds.is_empty() || seeds.len() > MAX_SEEDS {
        return Err(DesignError::Shape {
            field: "seeds",
            reason: format!("between 1 and {MAX_SEEDS} seeds, got {}", seeds.len()),
        });
    }
    for (i, &v) in speeds_kmh.iter().enumerate() {
        if !(v.is_finite() && (MIN_SPEED_KMH..=MAX_SPEED_KMH).contains(&v)) {
            return Err(DesignError::Invalid {
                field: "speeds_kmh",
                value: v,
                reason: "a speed must lie within 5-100 km/h",
            });
        }
        if i > 0 && v <= speeds_kmh[i - 1] {
            return Err(DesignError::Invalid {
                field: "speeds_kmh",
                value: v,
                reason: "speeds must be strictly ascending",
            });
        }
    }
    let sim = |e: vehicle_3d::VehicleError| DesignError::Simulation(e.to_string());
    let loads = [Load::Unloaded, Load::Loaded];
    let spec = |load, speed_kmh| RideSpec {
        speed_kmh,
        ..RideSpec::d1(load, FrontAxle::Suspended)
    };
    // the enveloping cache depends on the load, the tire and the terrain, not on the speed:
    // built once per load and seed, shared by every speed
    let cases: Vec<(Load, u64)> = loads
        .iter()
        .flat_map(|&load| seeds.iter().map(move |&s| (load, s)))
        .collect();
    // runs load by load, speed by speed, seed by seed (the chunks below rely on it)
    let mut runs = Vec::new();
    for (li, &load) in loads.iter().enumerate() {
        for &v in speeds_kmh {
            for (si, &s) in seeds.iter().enumerate() {
                runs.push((load, v, s, li * seeds.len() + si));
            }
        }
    }
    let measures: Vec<_> = crate::fan_out::cached(
        &cases,
        |&(load, s)| ride_tracks(p, &spec(load, speeds_kmh[0]), s),
        &runs,
        |&(load, v, _, c), tracks: &[Arc<TireTracks>]| {
            ride_on(p, &spec(load, v), Arc::clone(&tracks[c])).map(|(_, m)| m)
        },
        |&(load, v, s, _)| progress(&format!("{load} {v} km/h seed {s}")),
    )
    .map_err(sim)?
    .into_iter()
    .collect::<Result<_, _>>()
    .map_err(sim)?;
    let spread = |v: &[f64]| Spread::of_measured(v).map_err(sim);
    let mut points = Vec::new();
    for (chunk, &(load, v, _, _)) in measures
        .chunks(seeds.len())
        .zip(runs.iter().step_by(seeds.len()))
    {
        let pick = |f: fn(&vehicle_3d::scenarios::RideMeasures) -> f64| {
            spread(&chunk.iter().map(f).collect::<Vec<_>>())
        };
        points.push(SpeedPoint {
            speed_kmh: v,
            load,
            a_wz_m_s2: pick(|m| m.a_wz_m_s2)?,
            a_z_rms_m_s2: pick(|m| m.a_z_rms_m_s2)?,
            d_s_m: pick(|m| m.strut_travel_p2p_m.unwrap_or(f64::NAN))?,
        });
    }
    let upper = health_guidance_zone(HGCZ_HOURS, HgczRelation::SqrtTime)
        .map_err(|e| DesignError::Simulation(e.to_string()))?
        .upper_m_s2;
    let crossings = loads
        .iter()
        .map(|&load| {
            let a: Vec<f64> = points
                .iter()
                .filter(|p| p.load == load)
                .map(|p| p.a_wz_m_s2.mean)
                .collect();
            Crossing {
                load,
                speed_kmh: first_upward_crossing(speeds_kmh, &a, upper),
                above_at_lowest: a[0] > upper,
            }
        })
        .collect();
    Ok(SpeedSweep {
        seeds: seeds.to_vec(),
        hgcz_upper_m_s2: upper,
        points,
        crossings,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crossing_is_interpolated_in_the_first_upward_interval() {
        let s = [10.0, 15.0, 20.0, 25.0, 30.0];
        // 0.6 -> 0.8 -> 1.0: the 0.87 bound is crossed 35 % into 15-20 km/h
        let a = [0.5, 0.6, 0.8, 1.0, 1.2];
        let c = first_upward_crossing(&s, &a, 0.87).unwrap();
        assert!((c - 21.75).abs() < 1e-12, "{c}");
        // a dip below and back: the first upward crossing counts
        let b = [0.9, 0.8, 0.95, 0.7, 1.0];
        assert!(
            (first_upward_crossing(&s, &b, 0.87).unwrap() - (15.0 + 0.07 / 0.15 * 5.0)).abs()
                < 1e-12
        );
        assert_eq!(first_upward_crossing(&s, &[0.1; 5], 0.87), None);
        assert_eq!(first_upward_crossing(&s, &[1.0; 5], 0.87), None);
        assert_eq!(first_upward_crossing(&[10.0], &[0.5], 0.87), None);
    }

    #[test]
    fn bad_sweeps_are_refused_before_any_run() {
        let p = VehicleParams::nominal();
        let none = |_: &str| panic!("no run may start");
        for speeds in [
            &[][..],
            &[20.0, 10.0],
            &[2.0],
            &[101.0],
            &[f64::NAN],
            &[20.0, 20.0],
        ] {
            assert!(
                hps_speed_sweep(&p, speeds, &[1], &none).is_err(),
                "{speeds:?}"
            );
        }
        assert!(hps_speed_sweep(&p, &[20.0], &[], &none).is_err());
        let many: Vec<u64> = (0..=MAX_SEEDS as u64).collect();
        assert!(hps_speed_sweep(&p, &[20.0], &many, &none).is_err());
    }
}
