//! Vehicle descriptions (crate `afsv-vehicle`, format `afsv-vehicle-1`, docs/vehicles.md):
//! the same TOML files and built-in names as every `--vehicle` option of the CLI.
//!
//! A description crosses the boundary as a pair `(kind, value)`: `("builtin", NAME)`,
//! `("file", PATH)` or `("text", TOML)` (with the folder that relative strut files are
//! read from as a third element).

use crate::{to_json, value_err};
use afsv_vehicle::{load_builtin, load_file, load_str, ArticulatedVehicle, Described, Vehicle};
use pyo3::prelude::*;
use serde_json::json;
use std::path::Path;

/// A description reference from Python: `(kind, value, folder)`.
pub(crate) type DescRef<'a> = (&'a str, &'a str, &'a str);

/// The owned form of a [`DescRef`], as a Python function argument.
pub(crate) type DescArg = (String, String, String);

/// The borrowed form of an optional [`DescArg`].
pub(crate) fn as_ref(a: &Option<DescArg>) -> Option<DescRef<'_>> {
    a.as_ref()
        .map(|(k, v, f)| (k.as_str(), v.as_str(), f.as_str()))
}

/// The description a reference names, read and checked (the library's errors, with file,
/// line, column and field path, become `ValueError`).
pub(crate) fn load(r: DescRef<'_>) -> PyResult<Described> {
    let (kind, value, folder) = r;
    match kind {
        "builtin" => load_builtin(value),
        "file" => load_file(Path::new(value)),
        "text" => load_str(value, "<text>", Path::new(folder)),
        other => {
            return Err(value_err(format!(
                "vehicle reference `{other}`: expected builtin, file or text"
            )))
        }
    }
    .map_err(|e| value_err(e.to_string()))
}

/// The articulated vehicle a reference names (the built-in prototype when `None`).
pub(crate) fn articulated(r: Option<DescRef<'_>>) -> PyResult<ArticulatedVehicle> {
    match load(r.unwrap_or(("builtin", "prototype", ".")))?.vehicle {
        Vehicle::Articulated(a) => Ok(a),
        Vehicle::RigidTruck(t) => Err(value_err(format!(
            "vehicle: `{}` is a rigid truck; this model runs an articulated vehicle (the rigid truck runs with model=\"truck\")",
            t.name
        ))),
    }
}

/// The description as JSON: name, kind, the commented TOML text (what `save` writes) and
/// the model parameter sets it converts to.
#[pyfunction]
#[pyo3(signature = (kind, value, folder))]
fn describe_vehicle(kind: &str, value: &str, folder: &str) -> PyResult<String> {
    let d = load((kind, value, folder))?;
    let toml = match kind {
        "text" => value.to_string(),
        "file" => std::fs::read_to_string(value).map_err(|e| value_err(format!("{value}: {e}")))?,
        _ => afsv_vehicle::to_commented_toml(&d.description).map_err(value_err)?,
    };
    let out = match &d.vehicle {
        Vehicle::Articulated(a) => json!({
            "name": a.name,
            "kind": "articulated",
            "toml": toml,
            "params": {
                "vehicle_3d": to_json(&a.params)?,
                "front_suspension": to_json(&a.front_suspension)?,
                "front_strut": to_json(&a.front_strut)?,
                "yaw_plane_loaded": to_json(a.yaw_plane(vehicle_3d::Load::Loaded))?,
                "yaw_plane_unloaded": to_json(a.yaw_plane(vehicle_3d::Load::Unloaded))?,
                "yaw_plane_derived": a.yaw_plane_derived,
                "steering": to_json(a.steering())?,
            },
        }),
        Vehicle::RigidTruck(t) => json!({
            "name": t.name,
            "kind": "rigid-truck",
            "toml": toml,
            "params": { "truck": to_json(&t.params)? },
        }),
    };
    Ok(out.to_string())
}

/// The built-in descriptions: `[(name, what it is)]`.
#[pyfunction]
fn builtin_vehicles() -> Vec<(&'static str, &'static str)> {
    afsv_vehicle::BUILTIN.to_vec()
}

/// Register the description functions.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(describe_vehicle, m)?)?;
    m.add_function(wrap_pyfunction!(builtin_vehicles, m)?)?;
    Ok(())
}
