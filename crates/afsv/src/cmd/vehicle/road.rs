//! `afsv vehicle ride --road FILE`: the D1 ride on a measured two-track road instead of
//! synthesised terrain. The file is either a record (docs/records.md): columns `x_m`
//! (uniformly spaced), `left_m` and `right_m`, other length units (`left_mm`, `x_km`)
//! converted on read and the conversions reported; or an ASAM OpenCRG ASCII file (`.crg`,
//! docs/terrain-psd.md), sampled along the two wheel tracks at plus and minus half the front
//! track.

use afsv::output::OutputGuard;
use afsv_design::report::vehicle::{Ground, NO_STRUT};
use afsv_records::Record;
use serde_json::{json, Value};
use std::path::Path;
use terrain_psd::TwoTrackProfile;
use vehicle_3d::scenarios::{measured_ride_tracks, ride_on, RideMeasures, RideSpec};
use vehicle_3d::{RunRecord, VehicleParams};

/// Largest measured road read (samples per track): 200 km at 2 cm.
const MAX_ROAD_SAMPLES: usize = 10_000_000;

/// Largest OpenCRG file read (bytes): 10 million rows of eight 10-character sections.
const MAX_CRG_BYTES: u64 = 1 << 30;

/// One D1 ride of `p` on the measured road in `file`: its record, measures and ground.
pub(super) fn ride(
    p: &VehicleParams,
    spec: &RideSpec,
    file: &Path,
    link: Option<&vehicle_3d::interconnect::Link>,
) -> Result<(RunRecord, RideMeasures, Ground), String> {
    OutputGuard::new(false).record_input("--road", file)?;
    let shown = file.display();
    let is_crg = file
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("crg"));
    let (profile, format) = if is_crg {
        crg_profile(p, file)?
    } else {
        record_profile(file)?
    };
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

/// The two tracks of a record file, and what its reading converted.
fn record_profile(file: &Path) -> Result<(TwoTrackProfile, Value), String> {
    let shown = file.display();
    let rec = Record::read(file).map_err(|e| e.to_string())?;
    let column = |name: &str| rec.require(name, file).map_err(|e| e.to_string());
    let (x, left, right) = (column("x_m")?, column("left_m")?, column("right_m")?);
    if x.len() > MAX_ROAD_SAMPLES {
        return Err(format!(
            "{shown}: {} samples, more than the {MAX_ROAD_SAMPLES} a road may have",
            x.len()
        ));
    }
    let profile =
        TwoTrackProfile::from_samples(x, left, right).map_err(|e| format!("{shown}: {e}"))?;
    let format = json!({
        "format": "afsv record",
        "unit_conversions": afsv::output::unit_conversions(&rec),
    });
    Ok((profile, format))
}

/// The two tracks of an OpenCRG file at plus and minus half the front track.
fn crg_profile(p: &VehicleParams, file: &Path) -> Result<(TwoTrackProfile, Value), String> {
    let shown = file.display();
    let size = std::fs::metadata(file)
        .map_err(|e| format!("{shown}: {e}"))?
        .len();
    if size > MAX_CRG_BYTES {
        return Err(format!(
            "{shown}: {size} bytes, more than the {MAX_CRG_BYTES} an OpenCRG road may have"
        ));
    }
    let bytes = std::fs::read(file).map_err(|e| format!("{shown}: {e}"))?;
    let half_track = 0.5 * p.front_track_m;
    let road = terrain_psd::read_crg(&bytes, half_track).map_err(|e| format!("{shown}: {e}"))?;
    let format = json!({
        "format": "OpenCRG",
        "track_offsets_m": [half_track, -half_track],
        "start_u_m": road.start_u_m,
        "sections_v_m": road.sections_v_m,
    });
    Ok((road.profile, format))
}
