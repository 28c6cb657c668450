//! The 3-D calibration set's parameters by registry path: the vehicle-3d registry, and the
//! tire's and the strut's under a `tire.` or `hps.` prefix.

use crate::DiscoveryError;
use vehicle_3d::VehicleParams;
use vehicle_components::ParamSet;

/// Set registry path `name` of `p` (a `tire.` or `hps.` prefix addresses the nested set).
pub fn assign(p: &mut VehicleParams, name: &str, x: f64) -> Result<(), DiscoveryError> {
    let set: &mut dyn ParamSet = if name.starts_with("tire.") {
        &mut p.tire
    } else if name.starts_with("hps.") {
        &mut p.hps
    } else {
        p
    };
    let short = name
        .strip_prefix("tire.")
        .or_else(|| name.strip_prefix("hps."))
        .unwrap_or(name);
    let (i, _) = set.find(short)?;
    set.assign(i, x);
    Ok(())
}

/// Value of registry path `name` of `p`.
pub fn value(p: &VehicleParams, name: &str) -> Result<f64, DiscoveryError> {
    Ok(
        match (name.strip_prefix("tire."), name.strip_prefix("hps.")) {
            (Some(s), _) => p.tire.get(s)?,
            (_, Some(s)) => p.hps.get(s)?,
            _ => p.get(name)?,
        },
    )
}
