//! `afsv.evaluate(vehicle)`: the numbers of `afsv evaluate --json` on the same library
//! calls: the three design measures of Chapter 6 on the 3-D vehicle over terrain seeds
//! (`afsv_design::design_3d::assess`: D1 ride a_wz with the 8 h HGCZ verdict, D2 SP-DRT,
//! D3 omega_z and zeta), the yaw-plane steering measures of Chapter 3 per load case
//! (section 3.3), the front-axle strut's summary (Chapter 5) and the nominal terrain's
//! synthesis summary (section 6.2.3).

use crate::value_err;
use afsv_dynamics::{measures_for, Load, MeasureSpec};
use pyo3::prelude::*;
use serde_json::json;

/// Lowest forward speed of the yaw-plane measures (km/h), as the CLI.
const MIN_SPEED_KMH: f64 = 1.0;

/// The assessment of the articulated vehicle `vehicle` (the prototype when `None`) over
/// the terrain seeds `seed..seed + seeds`, with the yaw-plane measures at `speed_kmh`, as
/// JSON (the keys of `afsv evaluate --json` that carry numbers).
#[pyfunction]
#[pyo3(signature = (vehicle, seed, seeds, speed_kmh))]
fn evaluate(
    py: Python<'_>,
    vehicle: Option<crate::desc::DescArg>,
    seed: u64,
    seeds: u64,
    speed_kmh: f64,
) -> PyResult<String> {
    if !(1..=afsv_design::design_3d::MAX_SEEDS).contains(&seeds) {
        return Err(value_err(format!(
            "seeds {seeds}: must be 1 to {}",
            afsv_design::design_3d::MAX_SEEDS
        )));
    }
    if !(speed_kmh.is_finite() && speed_kmh >= MIN_SPEED_KMH) {
        return Err(value_err(format!(
            "speed_kmh must be at least {MIN_SPEED_KMH} km/h (the yaw-plane measures need forward speed), got {speed_kmh}"
        )));
    }
    let v = crate::desc::articulated(crate::desc::as_ref(&vehicle))?;
    let seed_list: Vec<u64> = (0..seeds).map(|i| seed.wrapping_add(i)).collect();
    let speed = speed_kmh / 3.6;
    let out = py.detach(|| -> Result<serde_json::Value, String> {
        let mut p = v.params.clone();
        if let Some(s) = &v.front_strut {
            p.hps = *s;
        }
        let design =
            afsv_design::design_3d::assess(&p, v.front_strut.is_some(), &seed_list, &|_| {})?;
        let yaw = |load: Load| {
            let yp = v.yaw_plane_params(load);
            measures_for(
                &yp.vehicle,
                &yp.afs,
                Some(load),
                speed,
                &MeasureSpec::default(),
            )
            .map_err(|e| format!("yaw-plane measures, {load:?} case: {e}").to_lowercase())
        };
        let (loaded, unloaded) = (yaw(Load::Loaded)?, yaw(Load::Unloaded)?);
        let strut = match &v.front_strut {
            Some(s) => {
                Some(hps_emulsion::characterize::summary(s, 0.025).map_err(|e| e.to_string())?)
            }
            None => None,
        };
        let terrain = terrain_psd::default_terrain_summary(seed);
        let stable =
            |m: &afsv_dynamics::YawMeasures| m.damping_ratio.is_finite() && m.damping_ratio > 0.0;
        let j = |v: serde_json::Result<serde_json::Value>| v.map_err(|e| e.to_string());
        let mut measures = j(serde_json::to_value(&design))?;
        if let Some(c) = hps_changes(&design) {
            measures["hps_change"] = c;
        }
        Ok(json!({
            "vehicle": v.name,
            "design_measures_3d": measures,
            "speed_kmh": speed_kmh,
            "terrain": j(serde_json::to_value(&terrain))?,
            "yaw_plane": {
                "loaded": j(serde_json::to_value(&loaded))?,
                "unloaded": j(serde_json::to_value(&unloaded))?,
                "stable": stable(&loaded) && stable(&unloaded),
            },
            "front_axle_strut": match &strut {
                Some(s) => json!({
                    "source": v.front_strut_source,
                    "static_force_n": s.static_force_n,
                    "static_stiffness_n_m": s.static_stiffness_n_m,
                    "at_1hz": j(serde_json::to_value(s.at_1hz))?,
                }),
                None => serde_json::Value::Null,
            },
        }))
    });
    Ok(out.map_err(value_err)?.to_string())
}

/// The front-axle strut's relative changes (percent) of a_wz and SP-DRT, each with whether
/// it is settled over the seeds (`afsv_design::design_3d::settled`), as `afsv evaluate`
/// reports them; `None` without a strut.
fn hps_changes(d: &afsv_design::design_3d::DesignMeasures) -> Option<serde_json::Value> {
    use afsv_design::design_3d::settled;
    let (h, u) = (d.nominal_hps.as_ref()?, &d.unsuspended);
    let one = |with: &vehicle_3d::scenarios::Spread, base: &vehicle_3d::scenarios::Spread| {
        json!({
            "percent": 100.0 * (with.mean / base.mean - 1.0),
            "settled_over_seeds": settled(with, base),
        })
    };
    Some(json!({
        "a_wz_unloaded": one(&h.ride_unloaded.a_wz_m_s2, &u.ride_unloaded.a_wz_m_s2),
        "a_wz_loaded": one(&h.ride_loaded.a_wz_m_s2, &u.ride_loaded.a_wz_m_s2),
        "sp_drt": one(&h.sp_drt_m_s2, &u.sp_drt_m_s2),
        "rule": "settled: the means differ by at least twice the standard error of the difference over the seeds",
    }))
}

/// Register `evaluate`.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(evaluate, m)?)?;
    Ok(())
}
