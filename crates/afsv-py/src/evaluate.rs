//! `afsv.evaluate(vehicle)`: `afsv evaluate --json` on the same library calls: the
//! assessment (`afsv_design::evaluate::assess`: the three design measures of Chapter 6 on
//! the 3-D vehicle over terrain seeds, the yaw-plane steering measures of Chapter 3 per load
//! case, the front-axle strut's summary and the nominal terrain's synthesis summary) and its
//! JSON report (`afsv_design::report::evaluate::to_json`), less the run's provenance.

use crate::value_err;
use afsv_design::evaluate::{assess, MIN_SPEED_KMH};
use pyo3::prelude::*;

/// The assessment of the articulated vehicle `vehicle` (the prototype when `None`) over
/// the terrain seeds `seed..seed + seeds`, with the yaw-plane measures at `speed_kmh`, as
/// the JSON of `afsv evaluate --json` less its provenance (every null with its
/// `*_reason`, as the CLI prints it: `afsv_records::json::annotate_nulls`).
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
    let seed_list = afsv_design::fan_out::seed_range(seed, seeds);
    let out = py.detach(|| assess(&v, speed_kmh, seed, &seed_list, false, &|_| {}));
    let mut json = afsv_design::report::evaluate::to_json(&out.map_err(value_err)?);
    afsv_records::json::annotate_nulls(&mut json);
    Ok(json.to_string())
}

/// Register `evaluate`.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(evaluate, m)?)?;
    Ok(())
}
