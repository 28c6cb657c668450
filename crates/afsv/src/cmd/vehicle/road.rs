//! `afsv vehicle ride --road FILE`: the D1 ride on a measured two-track road instead of
//! synthesised terrain (the file formats: [`super::super::road`]; an OpenCRG road is
//! sampled along the two wheel tracks at plus and minus half the front track).

use afsv_design::report::vehicle::{Ground, NO_STRUT};
use serde_json::{json, Value};
use std::path::Path;
use vehicle_3d::scenarios::{measured_ride_tracks, ride_on, RideMeasures, RideSpec};
use vehicle_3d::{RunRecord, VehicleParams};

/// One D1 ride of `p` on the measured road in `file`: its record, measures and ground.
pub(super) fn ride(
    p: &VehicleParams,
    spec: &RideSpec,
    file: &Path,
    link: Option<&vehicle_3d::interconnect::Link>,
) -> Result<(RunRecord, RideMeasures, Ground), String> {
    let shown = file.display();
    let (profile, format) = super::super::road::read(file, 0.5 * p.front_track_m)?;
    let (dx, n) = (profile.dx_m, profile.len());
    let tracks = measured_ride_tracks(p, spec, profile).map_err(|e| format!("{shown}: {e}"))?;
    let (rec, m) = match link {
        Some(l) => {
            vehicle_3d::interconnect::ride_linked_on(p, spec, tracks, l).map(|(r, m)| (r.record, m))
        }
        None => ride_on(p, spec, tracks),
    }
    .map_err(|e| e.to_string())?;
    let length = dx * (n - 1) as f64;
    let mut road = json!({
        "kind": "measured two-track road",
        "file": file,
        "length_m": length,
        "dx_m": dx,
        "samples": n,
    });
    if let (Value::Object(extra), Some(o)) = (format, road.as_object_mut()) {
        o.extend(extra);
    }
    let ground = Ground {
        json: road,
        text: format!("measured road {shown} ({length:.0} m at {dx} m)"),
        per_run: json!([{
            "road": file,
            "measures": afsv_records::json::explain_nulls(json!(m), NO_STRUT),
        }]),
    };
    Ok((rec, m, ground))
}
