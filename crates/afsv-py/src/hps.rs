//! The built-in design problem of Chapter 6 (crate `afsv-design`, module `hps_optimum`): the
//! front-axle HPS design chi = [A_hc, A_v, A_b] of section 6.5.2 found by a real-coded
//! genetic algorithm minimising `F(chi) = a_wz / a_wzn + d_s / d_sn` (Eq 6.19) subject to
//! `a_wz <= 0.85 m/s²` and the lower bounds of Eq 6.20, on the library calls of
//! `afsv optimize hps` (same settings, same numbers); optionally followed by the D4 speed
//! sweep of the optimum (Fig 6.16). The whole run stays in Rust with the GIL released.

use crate::{py_err, to_json, value_err};
use afsv_design::hps_optimum::{optimise_hps, optimum_speed_sweep, optimum_vehicle, HpsGaSettings};
use pyo3::prelude::*;

/// `v` as a count within `lo..=hi`, else the CLI's message with the Python name.
fn count(name: &str, v: i128, lo: usize, hi: usize, even: bool) -> PyResult<usize> {
    match usize::try_from(v) {
        Ok(n) if (lo..=hi).contains(&n) && (!even || n % 2 == 0) => Ok(n),
        _ if even => Err(value_err(format!("{name} {v}: must be even, {lo} to {hi}"))),
        _ => Err(value_err(format!("{name} {v}: must be {lo} to {hi}"))),
    }
}

/// `v` as a seed (0 to 2^64 - 1).
fn seed(name: &str, v: i128) -> PyResult<u64> {
    u64::try_from(v).map_err(|_| value_err(format!("{name} {v}: must be 0 to {}", u64::MAX)))
}

/// The 3-D parameters of the articulated vehicle `vehicle` (the prototype when `None`) with
/// its front-axle strut as `hps` (the nominal design of the search), as the CLI's
/// `--vehicle` of `afsv optimize hps`; an error when the description gives the front axle
/// no strut.
fn with_front_strut(
    vehicle: Option<crate::desc::DescRef<'_>>,
) -> PyResult<vehicle_3d::VehicleParams> {
    let v = crate::desc::articulated(vehicle)?;
    let strut = v.front_strut.ok_or_else(|| {
        value_err(format!(
            "optimize hps: the vehicle description `{}` gives the front axle no strut (add `strut = \"front-axle\"` or a strut file to its front [[axle]])",
            v.name
        ))
    })?;
    Ok(vehicle_3d::VehicleParams {
        hps: strut,
        ..v.params
    })
}

/// The HPS design optimisation of `afsv optimize hps` (module docs): a GA of `population`
/// (even, 4 to 1000) over `generations` (1 to 1000) with seed `seed` on the fixed terrain
/// `terrain_seed`, then the optimum and the nominal re-evaluated over
/// `reevaluation_seeds` (1 to 100) terrain seeds, with SP-DRT (D2) when `roll`; with
/// `speed_sweep`, D4 on the optimum. Returns JSON: the keys of `afsv optimize hps --json`
/// (`afsv_design::hps_optimum::HpsOptimum`, NaN as null) plus `strut_json` (the text
/// `--strut-out` writes) and `speed_sweep` (null unless asked).
#[pyfunction]
#[pyo3(signature = (vehicle, population, generations, seed, terrain_seed, reevaluation_seeds, roll, speed_sweep))]
#[allow(clippy::too_many_arguments)]
fn optimize_hps(
    py: Python<'_>,
    vehicle: Option<crate::desc::DescArg>,
    population: i128,
    generations: i128,
    seed: i128,
    terrain_seed: i128,
    reevaluation_seeds: i128,
    roll: bool,
    speed_sweep: bool,
) -> PyResult<String> {
    let population = count("population", population, 4, 1000, true)?;
    let generations = count("generations", generations, 1, 1000, false)?;
    let reevaluation_seeds = count("reevaluation_seeds", reevaluation_seeds, 1, 100, false)?;
    let settings = HpsGaSettings {
        population,
        generations,
        ga_seed: self::seed("seed", seed)?,
        terrain_seed: self::seed("terrain_seed", terrain_seed)?,
        reevaluation_seeds,
        reevaluate_roll: roll,
        ..HpsGaSettings::default()
    };
    let base = with_front_strut(crate::desc::as_ref(&vehicle))?;
    let (optimum, strut, sweep) = py
        .detach(|| {
            let r = optimise_hps(&base, &settings, &optimize::Silent)?;
            let best = optimum_vehicle(&base, &r)?;
            let sweep = if speed_sweep {
                Some(optimum_speed_sweep(&best, &settings, &|_| {})?)
            } else {
                None
            };
            Ok::<_, afsv_design::DesignError>((r, best.hps, sweep))
        })
        .map_err(|e| py_err(py, &e))?;
    let mut out = to_json(&optimum)?;
    out["strut_json"] = serde_json::Value::String(
        serde_json::to_string_pretty(&strut).map_err(|e| value_err(e.to_string()))? + "\n",
    );
    out["speed_sweep"] = match &sweep {
        Some(s) => to_json(s)?,
        None => serde_json::Value::Null,
    };
    Ok(out.to_string())
}

/// Register the Chapter 6 optimisation.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(optimize_hps, m)?)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::count;

    #[test]
    fn counts_follow_the_cli_ranges() {
        assert_eq!(count("population", 4, 4, 1000, true).unwrap(), 4);
        assert_eq!(count("generations", 1000, 1, 1000, false).unwrap(), 1000);
        for bad in [-2, 0, 3, 5, 1002] {
            assert!(count("population", bad, 4, 1000, true).is_err(), "{bad}");
        }
        assert!(count("generations", 0, 1, 1000, false).is_err());
        assert!(count("generations", 1001, 1, 1000, false).is_err());
    }
}
