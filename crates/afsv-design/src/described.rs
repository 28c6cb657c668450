//! The vehicle a command's `--vehicle` names: a vehicle description file (TOML,
//! `docs/vehicles.md`) or the name of a built-in one (`prototype`, the default, and
//! `chapter2-truck`); a file of that name wins over the built-in. Read and resolved by
//! `afsv-vehicle`; here the choice between file and built-in, the kind of vehicle a command
//! runs, and the front strut the strut studies need.

use afsv_records::guard::OutputGuard;
use afsv_vehicle::{load_builtin, load_file, ArticulatedVehicle, Described, TruckVehicle, Vehicle};
use std::path::Path;

/// The description `arg` names, read and checked (the built-in prototype when `None`).
pub fn load(arg: Option<&Path>) -> Result<Described, String> {
    let Some(path) = arg else {
        return load_builtin("prototype").map_err(|e| e.to_string());
    };
    let name = path.to_string_lossy();
    if !path.exists() && afsv_vehicle::builtin(&name).is_some() {
        return load_builtin(&name).map_err(|e| e.to_string());
    }
    load_file(path).map_err(|e| e.to_string())
}

/// The articulated vehicle `arg` names (the prototype when `None`).
pub fn articulated(arg: Option<&Path>) -> Result<ArticulatedVehicle, String> {
    match load(arg)?.vehicle {
        Vehicle::Articulated(a) => Ok(a),
        Vehicle::RigidTruck(t) => Err(format!(
            "--vehicle: `{}` is a rigid truck; this command runs an articulated vehicle (the rigid truck runs with `afsv roll`)",
            t.name
        )),
    }
}

/// The rigid truck `arg` names (a file or `chapter2-truck`).
pub fn truck(arg: &Path) -> Result<TruckVehicle, String> {
    match load(Some(arg))?.vehicle {
        Vehicle::RigidTruck(t) => Ok(t),
        Vehicle::Articulated(a) => Err(format!(
            "--vehicle: `{}` is articulated; `afsv roll` runs a rigid truck (articulated vehicles run with `afsv vehicle` and `afsv evaluate`)",
            a.name
        )),
    }
}

/// Whether `arg` is a file the command reads (not a built-in name).
pub fn is_file(arg: &Path) -> bool {
    arg.exists() || afsv_vehicle::builtin(&arg.to_string_lossy()).is_none()
}

/// Declare `--vehicle` to `guard` as an input when it names a file (not a built-in).
pub fn declare(guard: &mut OutputGuard, arg: Option<&Path>) -> Result<(), String> {
    guard.input_if("--vehicle", arg.filter(|v| is_file(v)))?;
    Ok(())
}

/// The 3-D parameters of the articulated vehicle `arg` names, with its front-axle strut as
/// `hps`, for a command (`what`) that designs or varies that strut; an error when the
/// description gives the front axle no strut, or interconnects its struts (`[link]`: these
/// commands run the strut unlinked, so they would answer for another vehicle).
pub fn with_front_strut(
    arg: Option<&Path>,
    what: &str,
) -> Result<vehicle_3d::VehicleParams, String> {
    let v = articulated(arg)?;
    refuse_link(&v, what)?;
    let strut = v.front_strut.ok_or_else(|| {
        format!(
            "{what}: the vehicle description `{}` gives the front axle no strut (add `strut = \"front-axle\"` or a strut file to its front [[axle]])",
            v.name
        )
    })?;
    Ok(vehicle_3d::VehicleParams {
        hps: strut,
        ..v.params
    })
}

/// Refuses a description whose struts are interconnected (`[link]`) in a command (`what`)
/// that runs the front strut alone, unlinked: its answer would be for another vehicle.
pub fn refuse_link(v: &ArticulatedVehicle, what: &str) -> Result<(), String> {
    match v.link {
        None => Ok(()),
        Some(_) => Err(format!(
            "{what}: the vehicle description `{}` interconnects its struts ([link]); this study varies the front strut alone, unlinked (use `afsv optimize layout` for a linked layout, or remove the [link])",
            v.name
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builtin_names_resolve_and_kinds_are_checked() {
        let prototype = articulated(Some(Path::new("prototype"))).unwrap();
        assert_eq!(articulated(None).unwrap().name, prototype.name);
        let truck_name = Path::new("chapter2-truck");
        assert!(!is_file(truck_name) && is_file(Path::new("no-such-vehicle.toml")));
        assert!(truck(truck_name).is_ok());
        assert!(articulated(Some(truck_name))
            .unwrap_err()
            .contains("is a rigid truck"));
        assert!(truck(Path::new("prototype"))
            .unwrap_err()
            .contains("is articulated"));
        let p = with_front_strut(None, "study").unwrap();
        assert_eq!(p.hps, articulated(None).unwrap().front_strut.unwrap());
    }
}
